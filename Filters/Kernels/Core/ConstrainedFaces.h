// The faces of a partition that must stay as they are: its boundary (partition interfaces and the
// domain boundary: faces in one of its tets only) and the faces between two regions inside it.
#ifndef cgmesh_ConstrainedFaces_h
#define cgmesh_ConstrainedFaces_h

#include "Core/FaceKey.h"
#include "Core/PartitionMesh.h"

#include <vector>

namespace cgmesh
{

void findConstrainedFaces(const PartitionMesh& partition, std::vector<Face>& boundaryFaces,
  std::vector<Face>& regionInterfaceFaces);

} // namespace cgmesh

#endif
