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
  TetList tets;
  std::vector<int> regions; // empty when the input has no regions
  std::vector<CellId> parentCells;
};

// Whether a corner of `tet` is flagged (points beyond the flags' end are not).
inline bool touchesFlaggedPoint(const Tet& tet, const std::vector<char>& flagged)
{
  for (PointId p : tet)
  {
    if (p < static_cast<PointId>(flagged.size()) && flagged[p])
    {
      return true;
    }
  }
  return false;
}

// Appends tet `t` of `from`, with its region and parent, to `to`.
inline void appendTetOf(const PartitionMesh& from, std::size_t t, PartitionMesh& to)
{
  to.tets.push_back(from.tets[t]);
  to.parentCells.push_back(from.parentCells[t]);
  if (!from.regions.empty())
  {
    to.regions.push_back(from.regions[t]);
  }
}

} // namespace cgmesh

#endif
