#include "GreedyColoring.h"

#include "ColoringSupport.h"

namespace cgmesh
{

Status GreedyColoring::color(
  const PartitionGraph& graph, const ParallelFor&, std::vector<int>& colorOfPartition) const
{
  colorOfPartition.assign(graph.numberOfPartitions, -1);
  ForbiddenColors forbidden;
  for (int p = 0; p < graph.numberOfPartitions; ++p)
  {
    forbidden.clear();
    const int* neighbours = graph.neighboursOf(p);
    for (int i = 0; i < graph.degree(p); ++i)
    {
      forbidden.forbid(colorOfPartition[neighbours[i]]);
    }
    colorOfPartition[p] = forbidden.firstAllowed();
  }
  return Status::success();
}

} // namespace cgmesh
