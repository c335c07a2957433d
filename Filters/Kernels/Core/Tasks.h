// How kernels with independent pieces of work (parallel colouring rounds, hierarchical
// partitioning) run them without a threading library: the driver supplies the runner.
#ifndef cgmesh_Tasks_h
#define cgmesh_Tasks_h

#include "Core/Status.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

namespace cgmesh
{

// Runs body(i) for every i in [0, count), possibly concurrently, and returns a failure when a call
// threw. The result must not depend on how the calls are scheduled.
using ParallelFor =
  std::function<Status(std::int64_t count, const std::function<void(std::int64_t)>& body)>;

// The runner for serial use: every call in order, on the calling thread.
inline Status runSerially(std::int64_t count, const std::function<void(std::int64_t)>& body)
{
  for (std::int64_t i = 0; i < count; ++i)
  {
    body(i);
  }
  return Status::success();
}

// A range size for loops that only copy or fill a few values per index.
constexpr std::int64_t IndicesPerCopyRange = 65536;

// Runs body(begin, end) over consecutive ranges of at most `rangeSize` indices that cover
// [0, count), through `parallelFor`: loops over millions of cells or points whose per-index work
// is too small to be scheduled one index at a time.
inline Status forEachRange(const ParallelFor& parallelFor, std::int64_t count,
  std::int64_t rangeSize, const std::function<void(std::int64_t, std::int64_t)>& body)
{
  const std::int64_t ranges = (count + rangeSize - 1) / rangeSize;
  return parallelFor(ranges,
    [&](std::int64_t range) { body(range * rangeSize, std::min(count, (range + 1) * rangeSize)); });
}

// Where consecutive ranges of `rangeSize` indices over [0, count) place their items, when
// countIn(begin, end) tells how many [begin, end) has: the ranges are counted through
// `parallelFor` and summed in range order, so the offsets do not depend on the schedule. One
// entry per range, then the total.
inline Status offsetsOfRanges(const ParallelFor& parallelFor, std::int64_t count,
  std::int64_t rangeSize, const std::function<std::int64_t(std::int64_t, std::int64_t)>& countIn,
  std::vector<std::int64_t>& offsets)
{
  const std::int64_t ranges = (count + rangeSize - 1) / rangeSize;
  offsets.assign(static_cast<std::size_t>(ranges) + 1, 0);
  const Status status = forEachRange(parallelFor, count, rangeSize,
    [&](std::int64_t begin, std::int64_t end)
    { offsets[static_cast<std::size_t>(begin / rangeSize) + 1] = countIn(begin, end); });
  for (std::size_t r = 1; r < offsets.size(); ++r)
  {
    offsets[r] += offsets[r - 1];
  }
  return status;
}

// Where each range of IndicesPerCopyRange indices puts its items when counts[i] holds index i's
// (atomic, as the loops that filled them ran concurrently): offsetsOfRanges over the counts.
template <typename Count>
Status offsetsOfAtomicCounts(const std::vector<std::atomic<Count>>& counts,
  const ParallelFor& parallelFor, std::vector<std::int64_t>& offsets)
{
  return offsetsOfRanges(
    parallelFor, static_cast<std::int64_t>(counts.size()), IndicesPerCopyRange,
    [&](std::int64_t begin, std::int64_t end)
    {
      std::int64_t sum = 0;
      for (std::int64_t i = begin; i < end; ++i)
      {
        sum += counts[i].load(std::memory_order_relaxed);
      }
      return sum;
    },
    offsets);
}

} // namespace cgmesh

#endif
