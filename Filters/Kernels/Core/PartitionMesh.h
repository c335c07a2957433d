// The tets one partition owns: the unit every stage after partitioning works on.
#ifndef cgmesh_PartitionMesh_h
#define cgmesh_PartitionMesh_h

#include "Core/TetMesh.h"

#include <vector>

namespace cgmesh
{

// The tets one partition owns, with their region and input cell of origin.
struct PartitionMesh
{
  std::vector<Tet> tets;
  std::vector<int> regions; // empty when the input has no regions
  std::vector<CellId> parentCells;
};

} // namespace cgmesh

#endif
