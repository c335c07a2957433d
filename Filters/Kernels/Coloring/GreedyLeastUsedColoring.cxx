#include "Coloring/GreedyLeastUsedColoring.h"

#include "Coloring/ColoringSupport.h"
#include "Coloring/GreedyColoring.h"

namespace cgmesh
{

Status GreedyLeastUsedColoring::color(const PartitionGraph& graph, const ParallelFor& parallelFor,
  std::vector<int>& colorOfPartition) const
{
  Status status = GreedyColoring().color(graph, parallelFor, colorOfPartition);
  if (!status.ok())
  {
    return status;
  }
  const int palette = countColors(colorOfPartition);
  std::vector<std::int64_t> used(palette, 0);
  colorOfPartition.assign(graph.numberOfPartitions, -1);
  ForbiddenColors forbidden;
  for (int p = 0; p < graph.numberOfPartitions; ++p)
  {
    forbidNeighbourColors(graph, p, colorOfPartition, forbidden);
    int chosen = -1;
    for (int c = 0; c < static_cast<int>(used.size()); ++c)
    {
      if (!forbidden.isForbidden(c) && (chosen < 0 || used[c] < used[chosen]))
      {
        chosen = c;
      }
    }
    if (chosen < 0)
    {
      // Every colour of the palette is taken around p: the second pass may need one more.
      chosen = static_cast<int>(used.size());
      used.push_back(0);
    }
    colorOfPartition[p] = chosen;
    ++used[chosen];
  }
  return Status::success();
}

} // namespace cgmesh
