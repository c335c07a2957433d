// A sort of millions of keys on the driver's ParallelFor: fixed ranges sorted concurrently, then
// merged pairwise in rounds. The ranges do not depend on the thread count, and with a strict total
// order (no two values equal) the result is std::sort's.
#ifndef cgmesh_ParallelSort_h
#define cgmesh_ParallelSort_h

#include "Core/DefaultInitAllocator.h"
#include "Core/Tasks.h"

#include <algorithm>
#include <cstdint>
#include <utility>
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

// The same for (key, value) pairs by a bucket sort: ranges of pairs are counted and scattered
// concurrently into buckets of the keys' top bits (between the smallest and the largest key), in
// pair order within each bucket, then the buckets are sorted concurrently. Every step is a
// parallel loop, where sortInParallel ends in merges of halves, the last one on a single thread
// (it sorted the FinFET's 844k Hilbert keys in 59 ms at one thread). The result is std::sort's
// for any `parallelFor`.
template <typename Value>
Status sortKeyedInParallel(
  std::vector<std::pair<std::uint64_t, Value>>& values, const ParallelFor& parallelFor)
{
  using Pair = std::pair<std::uint64_t, Value>;
  const std::int64_t count = static_cast<std::int64_t>(values.size());
  if (count < 2 * IndicesPerCopyRange)
  {
    std::sort(values.begin(), values.end());
    return Status::success();
  }
  const std::int64_t rangeSize = IndicesPerCopyRange / 4;
  const std::int64_t ranges = (count + rangeSize - 1) / rangeSize;
  std::vector<std::pair<std::uint64_t, std::uint64_t>> boundsOfRange(
    static_cast<std::size_t>(ranges));
  Status status = forEachRange(parallelFor, count, rangeSize,
    [&](std::int64_t begin, std::int64_t end)
    {
      const auto [low, high] = std::minmax_element(values.begin() + begin, values.begin() + end,
        [](const Pair& a, const Pair& b) { return a.first < b.first; });
      boundsOfRange[begin / rangeSize] = { low->first, high->first };
    });
  std::uint64_t low = boundsOfRange[0].first, high = boundsOfRange[0].second;
  for (const auto& bounds : boundsOfRange)
  {
    low = std::min(low, bounds.first);
    high = std::max(high, bounds.second);
  }
  // About a thousand pairs a bucket, at most 4,096 buckets: each sorts in cache.
  int bucketBits = 1;
  while (bucketBits < 12 && (std::int64_t(1) << bucketBits) * 1024 < count)
  {
    ++bucketBits;
  }
  int spanBits = 0;
  while (spanBits < 64 && ((high - low) >> spanBits) != 0)
  {
    ++spanBits;
  }
  const int shift = std::max(0, spanBits - bucketBits);
  const std::int64_t buckets = std::int64_t(1) << bucketBits;
  const auto bucketOf = [low, shift](std::uint64_t key)
  {
    return static_cast<std::int64_t>((key - low) >> shift);
  };
  // slot[b * ranges + r]: where range r writes its pairs of bucket b (first their count).
  std::vector<std::int64_t> slot(static_cast<std::size_t>(buckets * ranges), 0);
  if (status.ok())
  {
    status = forEachRange(parallelFor, count, rangeSize,
      [&](std::int64_t begin, std::int64_t end)
      {
        std::int64_t* counts = slot.data() + begin / rangeSize;
        for (std::int64_t i = begin; i < end; ++i)
        {
          ++counts[bucketOf(values[i].first) * ranges];
        }
      });
  }
  std::vector<std::int64_t> bucketStart(static_cast<std::size_t>(buckets) + 1, 0);
  for (std::int64_t b = 0, next = 0; b < buckets; ++b)
  {
    bucketStart[b] = next;
    for (std::int64_t r = 0; r < ranges; ++r)
    {
      const std::int64_t counted = slot[b * ranges + r];
      slot[b * ranges + r] = next;
      next += counted;
    }
    bucketStart[b + 1] = next;
  }
  UnfilledVector<Pair> scattered(values.size());
  if (status.ok())
  {
    status = forEachRange(parallelFor, count, rangeSize,
      [&](std::int64_t begin, std::int64_t end)
      {
        std::int64_t* next = slot.data() + begin / rangeSize;
        for (std::int64_t i = begin; i < end; ++i)
        {
          scattered[next[bucketOf(values[i].first) * ranges]++] = values[i];
        }
      });
  }
  if (status.ok())
  {
    status = parallelFor(buckets,
      [&](std::int64_t b)
      {
        std::sort(scattered.begin() + bucketStart[b], scattered.begin() + bucketStart[b + 1]);
        std::copy(scattered.begin() + bucketStart[b], scattered.begin() + bucketStart[b + 1],
          values.begin() + bucketStart[b]);
      });
  }
  return status;
}

} // namespace cgmesh

#endif
