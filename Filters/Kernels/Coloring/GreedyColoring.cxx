#include "Coloring/GreedyColoring.h"

#include "Coloring/ColoringSupport.h"

namespace cgmesh
{

Status GreedyColoring::color(
  const PartitionGraph& graph, const ParallelFor&, std::vector<int>& colorOfPartition) const
{
  colorOfPartition.assign(graph.numberOfPartitions, -1);
  ForbiddenColors forbidden;
  for (int p = 0; p < graph.numberOfPartitions; ++p)
  {
    forbidNeighbourColors(graph, p, colorOfPartition, forbidden);
    colorOfPartition[p] = forbidden.firstAllowed();
  }
  return Status::success();
}

} // namespace cgmesh
