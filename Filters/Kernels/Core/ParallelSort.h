// A sort of millions of keys on the driver's ParallelFor: fixed ranges sorted concurrently, then
// merged pairwise in rounds. The ranges do not depend on the thread count, and with a strict total
// order (no two values equal) the result is std::sort's.
#ifndef cgmesh_ParallelSort_h
#define cgmesh_ParallelSort_h

#include "Core/Tasks.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace cgmesh
{

template <typename T>
Status sortInParallel(std::vector<T>& values, const ParallelFor& parallelFor)
{
  // Eight ranges keep both cores of a small machine busy in the sorts and cost three merge
  // rounds, the last one of them on a single thread.
  constexpr std::int64_t Ranges = 8;
  const std::int64_t count = static_cast<std::int64_t>(values.size());
  const std::int64_t width = (count + Ranges - 1) / Ranges;
  if (count < 2 * IndicesPerCopyRange)
  {
    std::sort(values.begin(), values.end());
    return Status::success();
  }
  Status status = forEachRange(parallelFor, count, width,
    [&](std::int64_t begin, std::int64_t end)
    { std::sort(values.begin() + begin, values.begin() + end); });
  std::vector<T> merged(values.size());
  for (std::int64_t sorted = width; sorted < count && status.ok(); sorted *= 2)
  {
    // Runs [begin, begin + sorted) and [begin + sorted, begin + 2 sorted) become one.
    status = forEachRange(parallelFor, count, 2 * sorted,
      [&](std::int64_t begin, std::int64_t end)
      {
        const std::int64_t middle = std::min(end, begin + sorted);
        std::merge(values.begin() + begin, values.begin() + middle, values.begin() + middle,
          values.begin() + end, merged.begin() + begin);
      });
    values.swap(merged);
  }
  return status;
}

} // namespace cgmesh

#endif
