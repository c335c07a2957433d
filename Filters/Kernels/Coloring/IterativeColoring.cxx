#include "Coloring/IterativeColoring.h"

#include "Coloring/ColoringSupport.h"

#include <algorithm>

namespace cgmesh
{

Status IterativeColoring::color(const PartitionGraph& graph, const ParallelFor& parallelFor,
  std::vector<int>& colorOfPartition) const
{
  const int count = graph.numberOfPartitions;
  const int blockSize = std::max(1, this->BlockSize);
  const int blockCount = (count + blockSize - 1) / blockSize;
  auto blockOf = [blockSize](int p)
  {
    return p / blockSize;
  };

  colorOfPartition.assign(count, -1);
  std::vector<char> pending(count, 1);
  std::vector<int> snapshot;
  // Each round fixes at least the smallest pending id, so `count` rounds always suffice.
  for (int round = 0; round < count + 1; ++round)
  {
    snapshot = colorOfPartition;
    Status status = parallelFor(blockCount,
      [&](std::int64_t block)
      {
        ForbiddenColors forbidden;
        const int begin = static_cast<int>(block) * blockSize;
        const int end = std::min(count, begin + blockSize);
        for (int p = begin; p < end; ++p)
        {
          if (!pending[p])
          {
            continue;
          }
          forbidden.clear();
          const int* neighbours = graph.neighboursOf(p);
          for (int i = 0; i < graph.degree(p); ++i)
          {
            const int q = neighbours[i];
            forbidden.forbid(blockOf(q) == block ? colorOfPartition[q] : snapshot[q]);
          }
          colorOfPartition[p] = forbidden.firstAllowed();
        }
      });
    if (!status.ok())
    {
      return status;
    }

    // Conflict detection reads the finished round and writes only the next round's flags.
    std::vector<char> nextPending(count, 0);
    status = parallelFor(count,
      [&](std::int64_t index)
      {
        const int p = static_cast<int>(index);
        if (!pending[p])
        {
          return;
        }
        const int* neighbours = graph.neighboursOf(p);
        for (int i = 0; i < graph.degree(p); ++i)
        {
          const int q = neighbours[i];
          if (q < p && colorOfPartition[q] == colorOfPartition[p])
          {
            nextPending[p] = 1;
            return;
          }
        }
      });
    if (!status.ok())
    {
      return status;
    }
    pending.swap(nextPending);
    if (std::find(pending.begin(), pending.end(), 1) == pending.end())
    {
      return Status::success();
    }
  }
  return Status::failure("iterative colouring did not converge");
}

} // namespace cgmesh
