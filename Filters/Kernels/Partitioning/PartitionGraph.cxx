#include "Partitioning/PartitionGraph.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <utility>

namespace cgmesh
{
namespace
{

// Consecutive tets scanned in turn, so partitions need not be copied into one array: their
// partition is `partitionOfTet[t]`, or `partition` for all of them when `partitionOfTet` is null.
struct TetRun
{
  const Tet* tets = nullptr;
  std::size_t count = 0;
  const int* partitionOfTet = nullptr;
  int partition = -1;
};

// Partitions whose neighbour rows one task gathers, at least.
constexpr std::int64_t PartitionsPerRowRange = 4096;

// Tets one task of the membership scan reads, at most.
constexpr std::size_t TetsPerScanChunk = 16384;

// Per point, a partition + 1 (0: none yet), written concurrently. Which partition a racing
// claim records depends on the schedule; the set of partitions each point ends up with does not.
using PartitionSlots = std::vector<std::atomic<int>>;

// The partitions of every point that lies in tets of more than one: group g lists those of the
// g-th such point in id order, sorted, as members[memberStart[g]] to members[memberStart[g + 1]];
// `interfaceVertex` flags those points.
// The tets are scanned by chunks concurrently: the first tet to reach a point claims it for its
// partition, and every other partition met there is kept by the chunk as a (point, partition)
// pair. The pairs are then counted and placed per point through atomic cursors, and each point's
// few partitions sorted, so the groups are the same for any schedule.
Status collectInterfaceGroups(const std::vector<TetRun>& runs, PointId numberOfPoints,
  const ParallelFor& parallelFor, std::vector<std::int64_t>& memberStart, std::vector<int>& members,
  std::vector<char>& interfaceVertex)
{
  struct Chunk
  {
    const TetRun* run;
    std::size_t begin, end;
  };
  std::vector<Chunk> chunks;
  for (const TetRun& run : runs)
  {
    for (std::size_t begin = 0; begin < run.count; begin += TetsPerScanChunk)
    {
      chunks.push_back({ &run, begin, std::min(run.count, begin + TetsPerScanChunk) });
    }
  }
  const std::int64_t numberOfChunks = static_cast<std::int64_t>(chunks.size());
  const std::size_t points = static_cast<std::size_t>(numberOfPoints);

  // The two partitions last recorded as extra ones per point (the latest in the low half): a
  // point's tets come from a few partitions in turn, so this keeps most repeats out of the lists.
  // On a 65,536-partition cube (1.05 M tets), remembering one let 1.9 M pairs through for 1.0 M
  // distinct, two 1.39 M, and the groups took 0.039-0.042 s instead of 0.046-0.052 (2 threads).
  // A race only lets a repeat through, which the sort drops.
  std::vector<std::atomic<std::uint64_t>> lastExtras(points);
  PartitionSlots claim(points);
  std::vector<std::vector<std::pair<PointId, int>>> extraOfChunk(chunks.size());
  Status status = parallelFor(numberOfChunks,
    [&](std::int64_t c)
    {
      const Chunk& chunk = chunks[c];
      std::vector<std::pair<PointId, int>>& found = extraOfChunk[c];
      for (std::size_t t = chunk.begin; t < chunk.end; ++t)
      {
        const int mine =
          (chunk.run->partitionOfTet ? chunk.run->partitionOfTet[t] : chunk.run->partition) + 1;
        for (PointId p : chunk.run->tets[t])
        {
          // A failed claim leaves the recorded partition in `seen`.
          int seen = claim[p].load(std::memory_order_relaxed);
          if (seen == mine ||
            (seen == 0 && claim[p].compare_exchange_strong(seen, mine, std::memory_order_relaxed)))
          {
            continue;
          }
          const std::uint64_t recorded = lastExtras[p].load(std::memory_order_relaxed);
          const std::uint64_t latest = recorded & 0xffffffffu;
          const std::uint64_t partition = static_cast<std::uint32_t>(mine);
          if (seen != mine && latest != partition && (recorded >> 32) != partition)
          {
            lastExtras[p].store(latest << 32 | partition, std::memory_order_relaxed);
            found.emplace_back(p, mine - 1);
          }
        }
      }
    });
  if (!status.ok())
  {
    return status;
  }

  // A counting sort by point: counts, their prefix sums by ranges of points, then every pair
  // placed at its point's cursor. `cursor` holds the counts first, then the next free slot.
  PartitionSlots cursor(points);
  status = forEachRange(parallelFor, numberOfPoints, IndicesPerCopyRange,
    [&](std::int64_t begin, std::int64_t end)
    {
      for (std::int64_t p = begin; p < end; ++p)
      {
        cursor[p].store(0, std::memory_order_relaxed);
      }
    });
  if (!status.ok())
  {
    return status;
  }
  status = parallelFor(numberOfChunks,
    [&](std::int64_t c)
    {
      for (const auto& pair : extraOfChunk[c])
      {
        cursor[pair.first].fetch_add(1, std::memory_order_relaxed);
      }
    });
  if (!status.ok())
  {
    return status;
  }
  std::vector<std::int64_t> rangeStart; // never empty: one entry per range, then the total
  status = offsetsOfAtomicCounts(cursor, parallelFor, rangeStart);
  const std::int64_t pointRanges = static_cast<std::int64_t>(rangeStart.size()) - 1;
  std::vector<std::int64_t> start(points + 1, 0);
  if (status.ok())
  {
    status = forEachRange(parallelFor, numberOfPoints, IndicesPerCopyRange,
      [&](std::int64_t begin, std::int64_t end)
      {
        std::int64_t next = rangeStart[begin / IndicesPerCopyRange];
        for (std::int64_t p = begin; p < end; ++p)
        {
          start[p] = next;
          next += cursor[p].load(std::memory_order_relaxed);
          cursor[p].store(static_cast<int>(start[p] - rangeStart[begin / IndicesPerCopyRange]),
            std::memory_order_relaxed);
        }
        start[end] = next;
      });
  }
  // Only the partitions are placed: the point of a slot follows from `start`. The cursors count
  // from their range's start so that they fit an int.
  std::vector<int> partitions(static_cast<std::size_t>(rangeStart.back()));
  if (status.ok())
  {
    status = parallelFor(numberOfChunks,
      [&](std::int64_t c)
      {
        for (const auto& pair : extraOfChunk[c])
        {
          const std::int64_t slot = rangeStart[pair.first / IndicesPerCopyRange] +
            cursor[pair.first].fetch_add(1, std::memory_order_relaxed);
          partitions[static_cast<std::size_t>(slot)] = pair.second;
        }
        extraOfChunk[c] = {};
      });
  }
  if (!status.ok())
  {
    return status;
  }

  // Each point's few other partitions sorted in place (insertion sort) and repeats dropped; then
  // the groups are written by ranges of points at their range's offsets, the claimed partition
  // put in its place among the others.
  std::vector<std::int64_t> groupsOfRange(static_cast<std::size_t>(pointRanges) + 1, 0);
  std::vector<std::int64_t> membersOfRange(static_cast<std::size_t>(pointRanges) + 1, 0);
  std::vector<int> others(points, 0);
  interfaceVertex.resize(points);
  status = forEachRange(parallelFor, numberOfPoints, IndicesPerCopyRange,
    [&](std::int64_t begin, std::int64_t end)
    {
      std::int64_t groups = 0, memberCount = 0;
      for (std::int64_t p = begin; p < end; ++p)
      {
        int* const first = partitions.data() + start[p];
        int* const last = partitions.data() + start[p + 1];
        for (int* it = first + 1; it < last; ++it)
        {
          const int value = *it;
          int* hole = it;
          for (; hole > first && hole[-1] > value; --hole)
          {
            *hole = hole[-1];
          }
          *hole = value;
        }
        others[p] = static_cast<int>(std::unique(first, last) - first);
        interfaceVertex[p] = others[p] > 0;
        groups += others[p] > 0;
        memberCount += others[p] > 0 ? others[p] + 1 : 0;
      }
      groupsOfRange[begin / IndicesPerCopyRange + 1] = groups;
      membersOfRange[begin / IndicesPerCopyRange + 1] = memberCount;
    });
  if (!status.ok())
  {
    return status;
  }
  for (std::int64_t r = 0; r < pointRanges; ++r)
  {
    groupsOfRange[r + 1] += groupsOfRange[r];
    membersOfRange[r + 1] += membersOfRange[r];
  }
  memberStart.assign(static_cast<std::size_t>(groupsOfRange.back()) + 1, 0);
  memberStart.back() = membersOfRange.back();
  members.resize(static_cast<std::size_t>(membersOfRange.back()));
  return forEachRange(parallelFor, numberOfPoints, IndicesPerCopyRange,
    [&](std::int64_t begin, std::int64_t end)
    {
      std::int64_t group = groupsOfRange[begin / IndicesPerCopyRange];
      std::int64_t out = membersOfRange[begin / IndicesPerCopyRange];
      for (std::int64_t p = begin; p < end; ++p)
      {
        if (others[p] == 0)
        {
          continue;
        }
        memberStart[static_cast<std::size_t>(group++)] = out;
        const int claimed = claim[p].load(std::memory_order_relaxed) - 1;
        const int* it = partitions.data() + start[p];
        const int* const last = it + others[p];
        for (; it != last && *it < claimed; ++it)
        {
          members[static_cast<std::size_t>(out++)] = *it;
        }
        members[static_cast<std::size_t>(out++)] = claimed;
        for (; it != last; ++it)
        {
          members[static_cast<std::size_t>(out++)] = *it;
        }
      }
    });
}

// The graph of the partitions the runs' tets belong to.
Status buildGraphOfRuns(const std::vector<TetRun>& runs, int numberOfPartitions,
  PointId numberOfPoints, const ParallelFor& parallelFor, PartitionGraph& graph)
{
  std::vector<std::int64_t> memberStart;
  std::vector<int> members;
  std::vector<char> interfaceVertex;
  Status status = collectInterfaceGroups(
    runs, numberOfPoints, parallelFor, memberStart, members, interfaceVertex);
  if (!status.ok())
  {
    return status;
  }

  // Per partition, the groups it belongs to (compressed rows); its neighbours are the other
  // members of those groups, gathered with a stamp per partition. No global sort of the pairs:
  // with many small partitions every point is shared by several, and sorting their pairs took
  // most of the graph's time (65,536 parts of a 1.05 M-tet cube).
  const std::size_t groups = memberStart.size() - 1;
  auto forEachMember = [&](std::size_t g, auto&& visit)
  {
    for (std::int64_t i = memberStart[g]; i < memberStart[g + 1]; ++i)
    {
      visit(members[static_cast<std::size_t>(i)]);
    }
  };
  std::vector<std::int64_t> groupsOfPartition(static_cast<std::size_t>(numberOfPartitions) + 1, 0);
  for (std::size_t g = 0; g < groups; ++g)
  {
    forEachMember(g, [&](int q) { ++groupsOfPartition[q + 1]; });
  }
  for (int q = 0; q < numberOfPartitions; ++q)
  {
    groupsOfPartition[q + 1] += groupsOfPartition[q];
  }
  std::vector<std::size_t> groupList(static_cast<std::size_t>(groupsOfPartition.back()));
  {
    std::vector<std::int64_t> next(groupsOfPartition.begin(), groupsOfPartition.end() - 1);
    for (std::size_t g = 0; g < groups; ++g)
    {
      forEachMember(g, [&](int q) { groupList[next[q]++] = g; });
    }
  }

  // Rows are gathered by ranges of partitions concurrently, each range with its own stamps (at
  // most 64 ranges, so the stamps cost at most 64 entries per partition): at 65,536 partitions
  // the serial gathering was half the graph. They come out unsorted; as the relation is
  // symmetric, each row is then written sorted by handing every pair (q, r) to row r in
  // ascending q, range of rows by range of rows: sorting the 65,536 rows took 0.015 of the
  // graph's 0.09 s at 2 threads.
  const std::int64_t rangeSize =
    std::max<std::int64_t>(PartitionsPerRowRange, (numberOfPartitions + 63) / 64);
  const std::int64_t ranges = (numberOfPartitions + rangeSize - 1) / rangeSize;
  // pairsTo[source range * ranges + target range]: (r, q) with q in the first, r in the second,
  // in ascending q.
  std::vector<std::vector<std::pair<int, int>>> pairsTo(static_cast<std::size_t>(ranges * ranges));
  std::vector<std::int64_t> rowLength(static_cast<std::size_t>(numberOfPartitions), 0);
  status = forEachRange(parallelFor, numberOfPartitions, rangeSize,
    [&](std::int64_t begin, std::int64_t end)
    {
      std::vector<std::pair<int, int>>* pairs = pairsTo.data() + begin / rangeSize * ranges;
      std::vector<int> stamp(numberOfPartitions, -1);
      for (int q = static_cast<int>(begin); q < end; ++q)
      {
        stamp[q] = q;
        std::int64_t length = 0;
        for (std::int64_t k = groupsOfPartition[q]; k < groupsOfPartition[q + 1]; ++k)
        {
          forEachMember(groupList[k],
            [&](int r)
            {
              if (stamp[r] != q)
              {
                stamp[r] = q;
                pairs[r / rangeSize].emplace_back(r, q);
                ++length;
              }
            });
        }
        rowLength[q] = length;
      }
    });
  if (!status.ok())
  {
    return status;
  }
  graph = PartitionGraph();
  graph.numberOfPartitions = numberOfPartitions;
  graph.interfacePoints = static_cast<std::int64_t>(groups);
  graph.interfaceVertex = std::move(interfaceVertex);
  graph.offsets.assign(static_cast<std::size_t>(numberOfPartitions) + 1, 0);
  for (int q = 0; q < numberOfPartitions; ++q)
  {
    graph.offsets[q + 1] = graph.offsets[q] + rowLength[q];
  }
  graph.neighbours.resize(static_cast<std::size_t>(graph.offsets.back()));
  return forEachRange(parallelFor, numberOfPartitions, rangeSize,
    [&](std::int64_t begin, std::int64_t end)
    {
      std::vector<std::int64_t> next(graph.offsets.begin() + begin, graph.offsets.begin() + end);
      const std::int64_t target = begin / rangeSize;
      for (std::int64_t source = 0; source < ranges; ++source)
      {
        for (const auto& [r, q] : pairsTo[static_cast<std::size_t>(source * ranges + target)])
        {
          graph.neighbours[static_cast<std::size_t>(next[r - begin]++)] = q;
        }
      }
    });
}

} // namespace

Status buildPartitionGraph(const TetList& tets, const std::vector<int>& partitionOfCell,
  int numberOfPartitions, PointId numberOfPoints, const ParallelFor& parallelFor,
  PartitionGraph& graph)
{
  const std::vector<TetRun> runs = { { tets.data(), tets.size(), partitionOfCell.data(), -1 } };
  return buildGraphOfRuns(runs, numberOfPartitions, numberOfPoints, parallelFor, graph);
}

Status buildPartitionGraph(const std::vector<PartitionMesh>& partitions, PointId numberOfPoints,
  const ParallelFor& parallelFor, PartitionGraph& graph)
{
  std::vector<TetRun> runs;
  for (std::size_t p = 0; p < partitions.size(); ++p)
  {
    runs.push_back(
      { partitions[p].tets.data(), partitions[p].tets.size(), nullptr, static_cast<int>(p) });
  }
  return buildGraphOfRuns(
    runs, static_cast<int>(partitions.size()), numberOfPoints, parallelFor, graph);
}

PartitionGraph makePartitionGraph(int numberOfPartitions, std::vector<std::pair<int, int>> edges)
{
  std::vector<std::pair<int, int>> directed;
  directed.reserve(2 * edges.size());
  for (const auto& edge : edges)
  {
    if (edge.first != edge.second)
    {
      directed.emplace_back(edge.first, edge.second);
      directed.emplace_back(edge.second, edge.first);
    }
  }
  std::sort(directed.begin(), directed.end());
  directed.erase(std::unique(directed.begin(), directed.end()), directed.end());

  PartitionGraph graph;
  graph.numberOfPartitions = numberOfPartitions;
  graph.offsets.assign(numberOfPartitions + 1, 0);
  graph.neighbours.reserve(directed.size());
  for (const auto& edge : directed)
  {
    ++graph.offsets[edge.first + 1];
    graph.neighbours.push_back(edge.second);
  }
  for (int p = 0; p < numberOfPartitions; ++p)
  {
    graph.offsets[p + 1] += graph.offsets[p];
  }
  return graph;
}

} // namespace cgmesh
