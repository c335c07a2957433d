// The points a mesh's tets use, found by ranges of tets on a ParallelFor: input checks and the
// contact search look only at those, and at millions of tets a serial scan of them was a fixed
// cost of every run whatever the thread count.
#ifndef cgmesh_UsedPoints_h
#define cgmesh_UsedPoints_h

#include "Core/Tasks.h"
#include "Core/TetMesh.h"

#include <atomic>
#include <vector>

namespace cgmesh
{

// The ids of the used points in ascending order. Ranges of tets mark the points concurrently
// (every order of the stores gives the same marks); the marks are counted by ranges of points,
// then the ids written at their range's offset.
inline Status listUsedPoints(
  const TetMesh& mesh, const ParallelFor& parallelFor, std::vector<PointId>& ids)
{
  std::vector<std::atomic<unsigned char>> used(static_cast<std::size_t>(mesh.numberOfPoints()));
  Status status = forEachRange(parallelFor, mesh.numberOfTets(), IndicesPerCopyRange,
    [&](std::int64_t begin, std::int64_t end)
    {
      for (std::int64_t t = begin; t < end; ++t)
      {
        for (PointId p : mesh.tets[t])
        {
          used[p].store(1, std::memory_order_relaxed);
        }
      }
    });
  const std::int64_t points = mesh.numberOfPoints();
  std::vector<std::int64_t> firstOfRange;
  if (status.ok())
  {
    status = offsetsOfAtomicCounts(used, parallelFor, firstOfRange);
  }
  if (!status.ok())
  {
    return status;
  }
  ids.resize(static_cast<std::size_t>(firstOfRange.back()));
  return forEachRange(parallelFor, points, IndicesPerCopyRange,
    [&](std::int64_t begin, std::int64_t end)
    {
      std::int64_t next = firstOfRange[begin / IndicesPerCopyRange];
      for (std::int64_t p = begin; p < end; ++p)
      {
        if (used[p].load(std::memory_order_relaxed))
        {
          ids[static_cast<std::size_t>(next++)] = p;
        }
      }
    });
}

} // namespace cgmesh

#endif
