#include "GreedyColoring.h"

namespace cgmesh
{

Status GreedyColoring::color(const PartitionGraph& graph,
  const ParallelFor&,
  std::vector<int>& colorOfPartition) const
{
  const int count = graph.numberOfPartitions;
  colorOfPartition.assign(count, -1);
  // usedBy[c] == p marks colour c as taken by a neighbour of partition p.
  std::vector<int> usedBy;
  for (int p = 0; p < count; ++p)
  {
    const int* neighbours = graph.neighboursOf(p);
    for (int i = 0; i < graph.degree(p); ++i)
    {
      const int c = colorOfPartition[neighbours[i]];
      if (c >= 0)
      {
        usedBy[c] = p;
      }
    }
    int chosen = 0;
    while (chosen < static_cast<int>(usedBy.size()) && usedBy[chosen] == p)
    {
      ++chosen;
    }
    if (chosen == static_cast<int>(usedBy.size()))
    {
      usedBy.push_back(-1);
    }
    colorOfPartition[p] = chosen;
  }
  return Status::success();
}

} // namespace cgmesh
