#include "Coloring/RecoloringBalance.h"

#include "Coloring/ColoringSupport.h"
#include "Coloring/GreedyColoring.h"

namespace cgmesh
{
namespace
{

// For each member of one colour class: the colours none of its neighbours carries (palette-sized
// flag rows, one per member).
Status allowedColorsOfClass(const PartitionGraph& graph, const std::vector<int>& members,
  const std::vector<int>& colorOfPartition, int palette, const ParallelFor& parallelFor,
  std::vector<char>& allowed)
{
  allowed.assign(members.size() * palette, 1);
  return parallelFor(static_cast<std::int64_t>(members.size()),
    [&](std::int64_t i)
    {
      char* row = allowed.data() + i * palette;
      const int p = members[i];
      const int* neighbours = graph.neighboursOf(p);
      for (int k = 0; k < graph.degree(p); ++k)
      {
        row[colorOfPartition[neighbours[k]]] = 0;
      }
    });
}

} // namespace

Status RecoloringBalance::color(const PartitionGraph& graph, const ParallelFor& parallelFor,
  std::vector<int>& colorOfPartition) const
{
  Status status = GreedyColoring().color(graph, parallelFor, colorOfPartition);
  if (!status.ok() || graph.numberOfPartitions == 0)
  {
    return status;
  }
  const int palette = countColors(colorOfPartition);
  std::vector<std::int64_t> sizes = colorSizes(colorOfPartition, palette);
  const std::int64_t target = (graph.numberOfPartitions + palette - 1) / palette;

  std::vector<std::vector<int>> members(palette);
  for (int p = 0; p < graph.numberOfPartitions; ++p)
  {
    members[colorOfPartition[p]].push_back(p);
  }
  for (int source = palette - 1; source >= 0; --source)
  {
    std::vector<char> allowed;
    status =
      allowedColorsOfClass(graph, members[source], colorOfPartition, palette, parallelFor, allowed);
    if (!status.ok())
    {
      return status;
    }
    for (std::size_t i = 0; i < members[source].size() && sizes[source] > target; ++i)
    {
      const char* row = allowed.data() + i * palette;
      int best = -1;
      for (int c = 0; c < palette; ++c)
      {
        if (c != source && row[c] && sizes[c] < target && (best < 0 || sizes[c] < sizes[best]))
        {
          best = c;
        }
      }
      if (best >= 0)
      {
        colorOfPartition[members[source][i]] = best;
        --sizes[source];
        ++sizes[best];
      }
    }
  }
  return Status::success();
}

} // namespace cgmesh
