#include "Partitioning/MeshPartitioner.h"

#include <metis.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <utility>

namespace cgmesh
{

namespace
{

bool isConnected(const DualGraph& graph)
{
  const std::size_t count = graph.offsets.size() - 1;
  std::vector<char> reached(count, 0);
  std::vector<std::size_t> stack = { 0 };
  reached[0] = 1;
  std::size_t visited = 0;
  while (!stack.empty())
  {
    const std::size_t v = stack.back();
    stack.pop_back();
    ++visited;
    for (std::int64_t k = graph.offsets[v]; k < graph.offsets[v + 1]; ++k)
    {
      const std::size_t w = static_cast<std::size_t>(graph.neighbours[k]);
      if (!reached[w])
      {
        reached[w] = 1;
        stack.push_back(w);
      }
    }
  }
  return visited == count;
}

} // namespace

Status partitionGraphWithMetis(
  const DualGraph& graph, int parts, std::vector<int>& partOfVertex, bool contiguous)
{
  const std::int64_t vertexTotal = static_cast<std::int64_t>(graph.offsets.size()) - 1;
  partOfVertex.assign(vertexTotal, 0);
  if (parts <= 1 || vertexTotal == 0)
  {
    return Status::success();
  }
  if (graph.neighbours.size() >= static_cast<std::size_t>(std::numeric_limits<idx_t>::max()))
  {
    return Status::failure(ErrorKind::InvalidInput, "mesh too large for METIS' 32-bit indices");
  }
  std::vector<idx_t> offsets(graph.offsets.begin(), graph.offsets.end());
  std::vector<idx_t> neighbours(graph.neighbours.begin(), graph.neighbours.end());
  std::vector<idx_t> weights(graph.vertexWeights.begin(), graph.vertexWeights.end());
  if (!weights.empty() &&
    std::accumulate(graph.vertexWeights.begin(), graph.vertexWeights.end(), std::int64_t{ 0 }) >=
      std::numeric_limits<idx_t>::max())
  {
    return Status::failure(ErrorKind::InvalidInput, "tet weights too large for METIS' indices");
  }
  std::vector<idx_t> partition(vertexTotal, 0);
  idx_t vertexCount = static_cast<idx_t>(vertexTotal);
  idx_t constraintCount = 1;
  idx_t partCount = parts;
  idx_t edgeCut = 0;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_NUMBERING] = 0;
  options[METIS_OPTION_SEED] = 1;
  // Contiguity is only possible for a connected graph (asking anyway makes METIS complain).
  options[METIS_OPTION_CONTIG] = contiguous && isConnected(graph) ? 1 : 0;
  // Parts of a few dozen tets make k-way slow: it coarsens only down to 30 vertices per part
  // and cuts that graph by recursive bisection before refining. Bisecting directly is faster
  // there and cuts about as well (Delaunay on the Kuhn cube N=25, 2 threads: 1,024 parts 0.76 ->
  // 0.32 s of partitioning, 1.4% more tets; 4,096 parts, whose second level asks for 64 parts of
  // about 1,465 tets at a time, 1.38 -> 0.45 s, 3.4% fewer tets; from about 180 tets per part on
  // k-way is as fast and makes fewer tets). Below 16 parts k-way is quick anyway and its parts
  // are kept (8 bisected parts of a 750-tet graded cube made TetGen abort on one of them).
  // Bisection cannot promise connected parts, so it serves only where they are not asked for.
  constexpr std::int64_t BisectBelowVerticesPerPart = 128;
  constexpr int BisectFromParts = 16;
  const bool bisect = options[METIS_OPTION_CONTIG] == 0 && parts >= BisectFromParts &&
    vertexTotal < BisectBelowVerticesPerPart * static_cast<std::int64_t>(parts);
  auto run = [&]()
  {
    if (bisect)
    {
      return METIS_PartGraphRecursive(&vertexCount, &constraintCount, offsets.data(),
        neighbours.data(), weights.empty() ? nullptr : weights.data(), nullptr, nullptr, &partCount,
        nullptr, nullptr, options, &edgeCut, partition.data());
    }
    return METIS_PartGraphKway(&vertexCount, &constraintCount, offsets.data(), neighbours.data(),
      weights.empty() ? nullptr : weights.data(), nullptr, nullptr, &partCount, nullptr, nullptr,
      options, &edgeCut, partition.data());
  };
  int result = run();
  if (result != METIS_OK && options[METIS_OPTION_CONTIG] == 1)
  {
    options[METIS_OPTION_CONTIG] = 0;
    result = run();
  }
  if (result != METIS_OK)
  {
    return Status::failure(
      "METIS failed to partition the mesh (code " + std::to_string(result) + ")");
  }
  std::copy(partition.begin(), partition.end(), partOfVertex.begin());
  return Status::success();
}

namespace
{

// Shares of `total` for parts of the given sizes: proportional, at most the size, at least 1 for
// a non-empty part (largest remainders first, ties to the lower index). Needs total <= sum.
std::vector<int> proportionalShares(const std::vector<std::int64_t>& sizes, int total)
{
  std::int64_t sum = 0;
  for (std::int64_t size : sizes)
  {
    sum += size;
  }
  std::vector<int> shares(sizes.size(), 0);
  std::vector<std::pair<double, std::size_t>> remainders;
  int given = 0;
  for (std::size_t i = 0; i < sizes.size(); ++i)
  {
    const double exact = static_cast<double>(total) * sizes[i] / sum;
    shares[i] = static_cast<int>(
      std::min<double>(sizes[i], std::max(sizes[i] > 0 ? 1.0 : 0.0, std::floor(exact))));
    given += shares[i];
    remainders.emplace_back(-(exact - std::floor(exact)), i);
  }
  std::sort(remainders.begin(), remainders.end());
  // Hand out what is missing (or take back what the minimum of 1 overspent), round robin.
  for (std::size_t k = 0; given != total; k = (k + 1) % remainders.size())
  {
    const std::size_t i = remainders[k].second;
    if (given < total && shares[i] < sizes[i])
    {
      ++shares[i];
      ++given;
    }
    else if (given > total && shares[i] > 1)
    {
      --shares[i];
      --given;
    }
  }
  return shares;
}

// Two levels: METIS cuts the graph into about sqrt(parts) parts, then each of those into its
// share of `parts`, one METIS call after another (see PartitioningOptions).
Status partitionHierarchically(const DualGraph& graph, int parts,
  const PartitioningOptions& options, std::vector<int>& partOfVertex)
{
  const std::size_t vertexCount = graph.offsets.size() - 1;
  const int coarseCount = std::max(2, static_cast<int>(std::lround(std::sqrt(parts))));
  std::vector<int> coarsePart;
  Status status = partitionGraphWithMetis(graph, coarseCount, coarsePart, options.contiguous);
  if (!status.ok())
  {
    return status;
  }
  const VertexGroups coarse = groupVertices(coarsePart, coarseCount);
  std::vector<std::int64_t> sizes(coarseCount); // weights, or counts
  for (int c = 0; c < coarseCount; ++c)
  {
    for (CellId position = coarse.groupStart[c]; position < coarse.groupStart[c + 1]; ++position)
    {
      sizes[c] += graph.vertexWeights.empty() ? 1 : graph.vertexWeights[coarse.order[position]];
    }
  }
  const std::vector<int> shares = proportionalShares(sizes, parts);
  partOfVertex.assign(vertexCount, 0);
  int first = 0;
  for (int c = 0; c < coarseCount; ++c)
  {
    const CellId begin = coarse.groupStart[c], end = coarse.groupStart[c + 1];
    std::vector<int> local;
    status = partitionGraphWithMetis(
      subgraphOfPositions(graph, coarse.order, coarse.positionOf, begin, end), shares[c], local,
      options.contiguous);
    if (!status.ok())
    {
      return status;
    }
    for (CellId position = begin; position < end; ++position)
    {
      partOfVertex[coarse.order[position]] = first + local[position - begin];
    }
    first += shares[c];
  }
  return Status::success();
}

} // namespace

Status checkPartitionCount(CellId tetCount, int numberOfPartitions)
{
  if (numberOfPartitions < 1)
  {
    return Status::failure(ErrorKind::InvalidOption, "the number of partitions must be at least 1");
  }
  if (numberOfPartitions > 1 && numberOfPartitions > tetCount)
  {
    return Status::failure(ErrorKind::InvalidOption, "more partitions than tets");
  }
  return Status::success();
}

Status partitionMesh(const TetMesh& mesh, int numberOfPartitions, std::vector<int>& partitionOfCell,
  const PartitioningOptions& options, const ParallelFor& parallelFor)
{
  const CellId tetCount = mesh.numberOfTets();
  partitionOfCell.assign(tetCount, 0);
  const Status count = checkPartitionCount(tetCount, numberOfPartitions);
  if (!count.ok() || numberOfPartitions == 1)
  {
    return count;
  }
  DualGraph graph;
  const Status built = buildDualGraph(mesh.tets, graph, parallelFor);
  if (!built.ok())
  {
    return built;
  }
  if (options.tetWeights)
  {
    graph.vertexWeights = *options.tetWeights;
  }
  if (numberOfPartitions >= options.hierarchicalFrom)
  {
    return partitionHierarchically(graph, numberOfPartitions, options, partitionOfCell);
  }
  return partitionGraphWithMetis(graph, numberOfPartitions, partitionOfCell, options.contiguous);
}

Status partitionByRegion(const TetMesh& mesh, int partitionsPerRegion,
  std::vector<int>& partitionOfCell, int& numberOfPartitions, const ParallelFor& parallelFor)
{
  if (!mesh.hasRegions())
  {
    return Status::failure(ErrorKind::InvalidOption, "partitioning by region needs a region array");
  }
  if (partitionsPerRegion < 1)
  {
    return Status::failure(
      ErrorKind::InvalidOption, "the number of partitions per region must be at least 1");
  }
  std::vector<int> regionIds = mesh.regions;
  std::sort(regionIds.begin(), regionIds.end());
  regionIds.erase(std::unique(regionIds.begin(), regionIds.end()), regionIds.end());
  std::vector<int> regionIndexOf(mesh.tets.size());
  for (CellId t = 0; t < mesh.numberOfTets(); ++t)
  {
    regionIndexOf[t] = static_cast<int>(
      std::lower_bound(regionIds.begin(), regionIds.end(), mesh.regions[t]) - regionIds.begin());
  }
  const VertexGroups regions = groupVertices(regionIndexOf, static_cast<int>(regionIds.size()));

  DualGraph graph;
  if (partitionsPerRegion > 1)
  {
    const Status built = buildDualGraph(mesh.tets, graph, parallelFor);
    if (!built.ok())
    {
      return built;
    }
  }
  partitionOfCell.assign(mesh.tets.size(), 0);
  numberOfPartitions = 0;
  for (std::size_t r = 0; r < regionIds.size(); ++r)
  {
    const CellId begin = regions.groupStart[r], end = regions.groupStart[r + 1];
    const int parts = static_cast<int>(std::min<std::int64_t>(partitionsPerRegion, end - begin));
    std::vector<int> local(static_cast<std::size_t>(end - begin), 0);
    if (parts > 1)
    {
      Status status = partitionGraphWithMetis(
        subgraphOfPositions(graph, regions.order, regions.positionOf, begin, end), parts, local);
      if (!status.ok())
      {
        return status;
      }
    }
    for (CellId position = begin; position < end; ++position)
    {
      partitionOfCell[regions.order[position]] = numberOfPartitions + local[position - begin];
    }
    numberOfPartitions += parts;
  }
  return Status::success();
}

} // namespace cgmesh
