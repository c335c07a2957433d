// The tets one partition owns: the unit every stage after partitioning works on.
#ifndef cgmesh_PartitionMesh_h
#define cgmesh_PartitionMesh_h

#include "Core/TetMesh.h"

#include <algorithm>
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

// Appends every tet of `from`, in order, as appendTetOf() does one.
inline void appendTetsOf(const PartitionMesh& from, PartitionMesh& to)
{
  to.tets.insert(to.tets.end(), from.tets.begin(), from.tets.end());
  to.parentCells.insert(to.parentCells.end(), from.parentCells.begin(), from.parentCells.end());
  to.regions.insert(to.regions.end(), from.regions.begin(), from.regions.end());
}

// Removes the tets at the ascending, distinct positions `leaving`. Each place one leaves below the
// new end takes the next staying tet from past it, so only as many tets are written as leave
// (compacting in order writes every tet after the first that leaves). The staying tets keep
// their order but for those moved down.
inline void removeTetsAt(PartitionMesh& partition, const std::vector<std::size_t>& leaving)
{
  const std::size_t kept = partition.tets.size() - leaving.size();
  auto leavingPastEnd = std::lower_bound(leaving.begin(), leaving.end(), kept);
  std::size_t source = kept;
  const bool hasRegions = !partition.regions.empty();
  for (auto hole = leaving.begin(); hole != leaving.end() && *hole < kept; ++hole, ++source)
  {
    for (; leavingPastEnd != leaving.end() && *leavingPastEnd == source; ++leavingPastEnd)
    {
      ++source; // a tet past the end that leaves as well
    }
    partition.tets[*hole] = partition.tets[source];
    partition.parentCells[*hole] = partition.parentCells[source];
    if (hasRegions)
    {
      partition.regions[*hole] = partition.regions[source];
    }
  }
  partition.tets.resize(kept);
  partition.parentCells.resize(kept);
  partition.regions.resize(hasRegions ? kept : 0);
}

} // namespace cgmesh

#endif
