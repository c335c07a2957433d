// The faces of a partition that must stay as they are: its boundary (partition interfaces and the
// domain boundary: faces in one of its tets only) and the faces between two regions inside it.
#ifndef cgmesh_ConstrainedFaces_h
#define cgmesh_ConstrainedFaces_h

#include "PartitionRefiner.h"

#include <array>
#include <vector>

namespace cgmesh
{

using Face = std::array<PointId, 3>; // corners in ascending order

void findConstrainedFaces(const PartitionMesh& partition, std::vector<Face>& boundaryFaces,
  std::vector<Face>& regionInterfaceFaces);

} // namespace cgmesh

#endif
