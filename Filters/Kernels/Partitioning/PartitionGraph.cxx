#include "Partitioning/PartitionGraph.h"

#include <algorithm>

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

// Sorts (point, partition) pairs and drops repeats. Points are dense ids, so a counting sort by
// point (stable) groups them, and each point's few partitions are sorted in place: the order a
// comparison sort of all pairs gives, which took half of the graph's time at 65,536 partitions
// of a 1.05 M-tet cube.
void sortByPointThenPartition(std::vector<std::pair<PointId, int>>& pairs, PointId numberOfPoints)
{
  std::vector<std::int64_t> start(static_cast<std::size_t>(numberOfPoints) + 1, 0);
  for (const auto& pair : pairs)
  {
    ++start[pair.first + 1];
  }
  for (PointId p = 0; p < numberOfPoints; ++p)
  {
    start[p + 1] += start[p];
  }
  // Only the partitions are placed: the point of a slot follows from `start`.
  std::vector<int> partitions(pairs.size());
  {
    std::vector<std::int64_t> next(start.begin(), start.end() - 1);
    for (const auto& pair : pairs)
    {
      partitions[next[pair.first]++] = pair.second;
    }
  }
  std::size_t kept = 0;
  for (PointId p = 0; p < numberOfPoints; ++p)
  {
    int* const first = partitions.data() + start[p];
    int* const last = partitions.data() + start[p + 1];
    for (int* it = first + 1; it < last; ++it) // a few entries: insertion sort
    {
      const int value = *it;
      int* hole = it;
      for (; hole > first && hole[-1] > value; --hole)
      {
        *hole = hole[-1];
      }
      *hole = value;
    }
    for (int* it = first; it != last; ++it)
    {
      if (it == first || *it != it[-1])
      {
        pairs[kept++] = { p, *it };
      }
    }
  }
  pairs.resize(kept);
}

// (point, partition) pairs for every point that lies in more than one partition, beyond the first
// partition recorded in `firstPartition` (the partition of its first tet in run order), sorted.
// The scan is serial: split by tets, threads race to claim points, and split by points, every
// thread reads all tets; both measured slower than this one scan on the 844k-tet FinFET (0.28
// against 0.14 s for its two graphs on one thread, no gain on two).
void collectExtraMemberships(const std::vector<TetRun>& runs, PointId numberOfPoints,
  std::vector<int>& firstPartition, std::vector<std::pair<PointId, int>>& extra)
{
  firstPartition.assign(numberOfPoints, -1);
  extra.clear();
  // The partition last recorded as an extra one per point: a point's tets in one partition mostly
  // come one after another, so this keeps most repeats out of the sort below.
  std::vector<int> lastExtra(numberOfPoints, -1);
  for (const TetRun& run : runs)
  {
    for (std::size_t t = 0; t < run.count; ++t)
    {
      const int partition = run.partitionOfTet ? run.partitionOfTet[t] : run.partition;
      for (PointId p : run.tets[t])
      {
        if (firstPartition[p] < 0)
        {
          firstPartition[p] = partition;
        }
        else if (firstPartition[p] != partition && lastExtra[p] != partition)
        {
          extra.emplace_back(p, partition);
          lastExtra[p] = partition;
        }
      }
    }
  }
  sortByPointThenPartition(extra, numberOfPoints);
}

// The graph of the partitions the runs' tets belong to.
Status buildGraphOfRuns(const std::vector<TetRun>& runs, int numberOfPartitions,
  PointId numberOfPoints, const ParallelFor& parallelFor, PartitionGraph& graph)
{
  std::vector<int> firstPartition;
  std::vector<std::pair<PointId, int>> extra;
  collectExtraMemberships(runs, numberOfPoints, firstPartition, extra);

  // One group per interface point: its first partition and its run of `extra`. Then, per
  // partition, the groups it belongs to (compressed rows), and its neighbours are the other
  // members of those groups, gathered with a stamp per partition. No global sort of the pairs:
  // with many small partitions every point is shared by several, and sorting their pairs took
  // most of the graph's time (65,536 parts of a 1.05 M-tet cube).
  std::vector<std::size_t> groupStart;
  for (std::size_t i = 0; i < extra.size(); ++i)
  {
    if (i == 0 || extra[i].first != extra[i - 1].first)
    {
      groupStart.push_back(i);
    }
  }
  const std::size_t groups = groupStart.size();
  groupStart.push_back(extra.size());
  auto forEachMember = [&](std::size_t g, auto&& visit)
  {
    visit(firstPartition[extra[groupStart[g]].first]);
    for (std::size_t i = groupStart[g]; i < groupStart[g + 1]; ++i)
    {
      visit(extra[i].second);
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
  // most 64 ranges, so the stamps cost at most 64 entries per partition), and joined in partition
  // order: at 65,536 partitions the serial gathering was half the graph.
  const std::int64_t rangeSize =
    std::max<std::int64_t>(PartitionsPerRowRange, (numberOfPartitions + 63) / 64);
  const std::int64_t ranges = (numberOfPartitions + rangeSize - 1) / rangeSize;
  std::vector<std::vector<int>> rowsOfRange(ranges);
  std::vector<std::int64_t> rowLength(static_cast<std::size_t>(numberOfPartitions), 0);
  const Status status = forEachRange(parallelFor, numberOfPartitions, rangeSize,
    [&](std::int64_t begin, std::int64_t end)
    {
      std::vector<int>& rows = rowsOfRange[begin / rangeSize];
      std::vector<int> stamp(numberOfPartitions, -1);
      for (int q = static_cast<int>(begin); q < end; ++q)
      {
        stamp[q] = q;
        const std::size_t rowStart = rows.size();
        for (std::int64_t k = groupsOfPartition[q]; k < groupsOfPartition[q + 1]; ++k)
        {
          forEachMember(groupList[k],
            [&](int r)
            {
              if (stamp[r] != q)
              {
                stamp[r] = q;
                rows.push_back(r);
              }
            });
        }
        std::sort(rows.begin() + rowStart, rows.end());
        rowLength[q] = static_cast<std::int64_t>(rows.size() - rowStart);
      }
    });
  if (!status.ok())
  {
    return status;
  }
  graph = PartitionGraph();
  graph.numberOfPartitions = numberOfPartitions;
  graph.interfacePoints = static_cast<std::int64_t>(groups);
  graph.offsets.assign(static_cast<std::size_t>(numberOfPartitions) + 1, 0);
  for (int q = 0; q < numberOfPartitions; ++q)
  {
    graph.offsets[q + 1] = graph.offsets[q] + rowLength[q];
  }
  graph.neighbours.reserve(static_cast<std::size_t>(graph.offsets.back()));
  for (const std::vector<int>& rows : rowsOfRange)
  {
    graph.neighbours.insert(graph.neighbours.end(), rows.begin(), rows.end());
  }
  return Status::success();
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
