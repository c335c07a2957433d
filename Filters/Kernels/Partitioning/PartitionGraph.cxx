#include "Partitioning/PartitionGraph.h"

#include <algorithm>

namespace cgmesh
{
namespace
{

// (point, partition) pairs for every point that lies in more than one partition, beyond the first
// partition recorded in `firstPartition`.
std::vector<std::pair<PointId, int>> collectExtraMemberships(const std::vector<Tet>& tets,
  const std::vector<int>& partitionOfCell, std::vector<int>& firstPartition)
{
  std::vector<std::pair<PointId, int>> extra;
  // The partition last recorded as an extra one per point: a point's tets in one partition mostly
  // come one after another, so this keeps most repeats out of the sort below.
  std::vector<int> lastExtra(firstPartition.size(), -1);
  for (std::size_t t = 0; t < tets.size(); ++t)
  {
    const int partition = partitionOfCell[t];
    for (PointId p : tets[t])
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
  std::sort(extra.begin(), extra.end());
  extra.erase(std::unique(extra.begin(), extra.end()), extra.end());
  return extra;
}

} // namespace

PartitionGraph buildPartitionGraph(const std::vector<Tet>& tets,
  const std::vector<int>& partitionOfCell, int numberOfPartitions, PointId numberOfPoints)
{
  std::vector<int> firstPartition(numberOfPoints, -1);
  const auto extra = collectExtraMemberships(tets, partitionOfCell, firstPartition);
  std::vector<std::pair<int, int>> edges;
  std::vector<int> members;
  std::int64_t interfacePoints = 0;
  for (std::size_t begin = 0; begin < extra.size(); ++interfacePoints)
  {
    const PointId point = extra[begin].first;
    members.assign(1, firstPartition[point]);
    std::size_t end = begin;
    for (; end < extra.size() && extra[end].first == point; ++end)
    {
      members.push_back(extra[end].second);
    }
    for (std::size_t i = 0; i < members.size(); ++i)
    {
      for (std::size_t j = i + 1; j < members.size(); ++j)
      {
        edges.emplace_back(members[i], members[j]);
      }
    }
    begin = end;
  }
  PartitionGraph graph = makePartitionGraph(numberOfPartitions, std::move(edges));
  graph.interfacePoints = interfacePoints;
  return graph;
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
