// The faces of a partition that must stay as they are: its boundary (partition interfaces and the
// domain boundary: faces in one of its tets only) and the faces between two regions inside it.
#ifndef cgmesh_ConstrainedFaces_h
#define cgmesh_ConstrainedFaces_h

#include "Core/FaceKey.h"
#include "Core/PartitionMesh.h"

#include <cstdint>
#include <vector>

namespace cgmesh
{

// Per tet, which of its faces are constrained: bit k when the face opposite corner k is a
// boundary face, bit InterfaceMarkShift + k when it lies between two regions. Template refinement
// hands them on to the children (refinePartition()), so that the interface rounds of the Delaunay
// method know the faces after each round without looking for them again.
using ConstrainedFaceMarks = std::vector<std::uint8_t>;
constexpr int InterfaceMarkShift = 4;

// Appends the constrained faces to the two lists and sorts what it appended (in corner order,
// whatever the order of the tets: TetGen receives them in this order).
void findConstrainedFaces(const PartitionMesh& partition, std::vector<Face>& boundaryFaces,
  std::vector<Face>& regionInterfaceFaces);

// The marks of the partition's tets: one hashing pass over their faces.
void markConstrainedFaces(const PartitionMesh& partition, ConstrainedFaceMarks& marks);

// The faces the marks name, as findConstrainedFaces() lists them.
void appendMarkedFaces(const PartitionMesh& partition, const ConstrainedFaceMarks& marks,
  std::vector<Face>& boundaryFaces, std::vector<Face>& regionInterfaceFaces);

} // namespace cgmesh

#endif
