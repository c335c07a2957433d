#include "Partitioning/HilbertPartitioner.h"

#include "Partitioning/MeshPartitioner.h"

#include "Core/HilbertCurve.h"
#include "Core/ParallelSort.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace cgmesh
{

Status orderTetsAlongHilbertCurve(
  const TetMesh& mesh, std::vector<CellId>& order, const ParallelFor& parallelFor, int bits)
{
  const CellId tetCount = mesh.numberOfTets();
  order.clear();
  if (tetCount == 0)
  {
    return Status::success();
  }

  // Centroids (times 4) on one cubic grid over the tets' bounding box, so that the curve keeps
  // the same resolution along every axis. Each range keeps its own box; min and max do not care
  // in which order the ranges are joined.
  using Box = std::array<std::array<double, 3>, 2>;
  constexpr double Infinity = std::numeric_limits<double>::infinity();
  const std::int64_t rangeSize = IndicesPerCopyRange;
  std::vector<Box> boxOfRange((tetCount + rangeSize - 1) / rangeSize,
    Box{ { { Infinity, Infinity, Infinity }, { -Infinity, -Infinity, -Infinity } } });
  std::vector<std::array<double, 3>> centroids(tetCount);
  Status status = forEachRange(parallelFor, tetCount, rangeSize,
    [&](std::int64_t begin, std::int64_t end)
    {
      Box& box = boxOfRange[begin / rangeSize];
      for (CellId t = begin; t < end; ++t)
      {
        for (int axis = 0; axis < 3; ++axis)
        {
          double sum = 0;
          for (PointId corner : mesh.tets[t])
          {
            sum += mesh.point(corner)[axis];
          }
          centroids[t][axis] = sum;
          box[0][axis] = std::min(box[0][axis], sum);
          box[1][axis] = std::max(box[1][axis], sum);
        }
      }
    });
  std::array<double, 3> low = boxOfRange[0][0], high = boxOfRange[0][1];
  for (const Box& box : boxOfRange)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      low[axis] = std::min(low[axis], box[0][axis]);
      high[axis] = std::max(high[axis], box[1][axis]);
    }
  }
  const double lastCell = (1u << bits) - 1;
  const double extent = std::max({ high[0] - low[0], high[1] - low[1], high[2] - low[2], 1e-300 });
  std::vector<std::pair<std::uint64_t, CellId>> keyed(tetCount);
  if (status.ok())
  {
    status = forEachRange(parallelFor, tetCount, rangeSize,
      [&](std::int64_t begin, std::int64_t end)
      {
        for (CellId t = begin; t < end; ++t)
        {
          std::array<std::uint32_t, 3> cell;
          for (int axis = 0; axis < 3; ++axis)
          {
            const double scaled = (centroids[t][axis] - low[axis]) / extent * lastCell;
            cell[axis] = static_cast<std::uint32_t>(std::clamp(scaled, 0.0, lastCell));
          }
          keyed[t] = { hilbertIndex(cell, bits), t };
        }
      });
  }
  if (status.ok())
  {
    status = sortKeyedInParallel(keyed, parallelFor);
  }
  if (!status.ok())
  {
    return status;
  }
  order.resize(tetCount);
  return forEachRange(parallelFor, tetCount, rangeSize,
    [&](std::int64_t begin, std::int64_t end)
    {
      for (CellId position = begin; position < end; ++position)
      {
        order[position] = keyed[position].second;
      }
    });
}

std::vector<CellId> weightedRunStarts(
  const std::vector<CellId>& order, const TetWeights& weights, const std::vector<CellId>& least)
{
  const CellId count = static_cast<CellId>(order.size());
  const std::size_t pieces = least.size();
  std::int64_t total = 0;
  for (CellId id : order)
  {
    total += weights[id];
  }
  std::vector<CellId> start(pieces + 1, count);
  // The weight before each position against r / pieces of the total, in integers.
  std::int64_t before = 0;
  std::size_t run = 0;
  for (CellId position = 0; position < count && run < pieces; ++position)
  {
    while (run < pieces &&
      static_cast<__int128>(before) * static_cast<__int128>(pieces) >=
        static_cast<__int128>(run) * static_cast<__int128>(total))
    {
      start[run++] = position;
    }
    before += weights[order[position]];
  }
  // Each start within [tets the runs before need, tets left for the runs from it on], then at
  // least least[r - 1] after the one before: a start clamped so cannot pass its upper bound.
  std::vector<CellId> neededBefore(pieces + 1, 0);
  for (std::size_t r = 0; r < pieces; ++r)
  {
    neededBefore[r + 1] = neededBefore[r] + least[r];
  }
  const CellId needed = neededBefore[pieces];
  for (std::size_t r = 0; r < pieces; ++r)
  {
    start[r] = std::clamp(start[r], neededBefore[r], count - (needed - neededBefore[r]));
    if (r > 0)
    {
      start[r] = std::max(start[r], start[r - 1] + least[r - 1]);
    }
  }
  start[0] = 0;
  start[pieces] = count;
  return start;
}

Status partitionAlongHilbertCurve(const TetMesh& mesh, int numberOfPartitions,
  std::vector<int>& partitionOfCell, const ParallelFor& parallelFor, const TetWeights* weights)
{
  const CellId tetCount = mesh.numberOfTets();
  partitionOfCell.assign(tetCount, 0);
  const Status count = checkPartitionCount(tetCount, numberOfPartitions);
  if (!count.ok() || numberOfPartitions == 1)
  {
    return count;
  }
  std::vector<CellId> order;
  const Status status = orderTetsAlongHilbertCurve(mesh, order, parallelFor);
  if (!status.ok())
  {
    return status;
  }
  if (weights)
  {
    const std::vector<CellId> start = weightedRunStarts(
      order, *weights, std::vector<CellId>(static_cast<std::size_t>(numberOfPartitions), 1));
    return parallelFor(numberOfPartitions,
      [&](std::int64_t run)
      {
        for (CellId position = start[run]; position < start[run + 1]; ++position)
        {
          partitionOfCell[order[position]] = static_cast<int>(run);
        }
      });
  }
  // Run r holds the tets at positions [r n / k, (r + 1) n / k).
  return forEachRange(parallelFor, tetCount, IndicesPerCopyRange,
    [&](std::int64_t begin, std::int64_t end)
    {
      for (CellId position = begin; position < end; ++position)
      {
        partitionOfCell[order[position]] =
          static_cast<int>(position * numberOfPartitions / tetCount);
      }
    });
}

} // namespace cgmesh
