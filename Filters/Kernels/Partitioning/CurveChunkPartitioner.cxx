#include "Partitioning/CurveChunkPartitioner.h"

#include "Partitioning/DualGraph.h"
#include "Partitioning/HilbertPartitioner.h"

#include <algorithm>

namespace cgmesh
{

int curveChunkCount(CellId tetCount, int numberOfPartitions)
{
  constexpr CellId TetsPerChunk = 200000;
  constexpr int PartitionsPerChunk = 16;
  constexpr int MaximumChunks = 64;
  const CellId bySize = tetCount / TetsPerChunk;
  const int byCount = numberOfPartitions / PartitionsPerChunk;
  return static_cast<int>(std::clamp<CellId>(std::min<CellId>(bySize, byCount), 1, MaximumChunks));
}

Status partitionInCurveChunks(const TetMesh& mesh, int numberOfPartitions, int chunks,
  const GraphPartitioner& partitionGraph, std::vector<int>& partitionOfCell,
  const ParallelFor& parallelFor, const TetWeights* weights)
{
  const CellId tetCount = mesh.numberOfTets();
  partitionOfCell.assign(tetCount, 0);
  const Status count = checkPartitionCount(tetCount, numberOfPartitions);
  if (!count.ok() || numberOfPartitions == 1)
  {
    return count;
  }
  chunks = std::clamp(chunks, 1, numberOfPartitions);
  if (chunks == 1)
  {
    DualGraph graph;
    const Status status = buildDualGraph(mesh.tets, graph, parallelFor);
    if (weights)
    {
      graph.vertexWeights = *weights;
    }
    return status.ok() ? partitionGraph(graph, numberOfPartitions, partitionOfCell) : status;
  }
  std::vector<CellId> order;
  // Chunks of many thousand tets need no fine curve: 2^10 cells a side cost half the steps.
  Status status = orderTetsAlongHilbertCurve(mesh, order, parallelFor, 10);
  if (!status.ok())
  {
    return status;
  }
  const auto firstPartitionOf = [&](std::int64_t c)
  {
    return static_cast<int>(c * numberOfPartitions / chunks);
  };
  std::vector<CellId> chunkStart(static_cast<std::size_t>(chunks) + 1);
  if (weights)
  {
    std::vector<CellId> least(static_cast<std::size_t>(chunks));
    for (int c = 0; c < chunks; ++c)
    {
      least[c] = firstPartitionOf(c + 1) - firstPartitionOf(c);
    }
    chunkStart = weightedRunStarts(order, *weights, least);
  }
  else
  {
    for (int c = 0; c <= chunks; ++c)
    {
      chunkStart[c] = c * tetCount / chunks;
    }
  }
  std::vector<Status> statusOfChunk(chunks, Status::success());
  status = parallelFor(chunks,
    [&](std::int64_t c)
    {
      const CellId begin = chunkStart[c];
      const CellId end = chunkStart[c + 1];
      const int firstPartition = firstPartitionOf(c);
      const int parts = firstPartitionOf(c + 1) - firstPartition;
      std::vector<int> local(static_cast<std::size_t>(end - begin), 0);
      if (parts > 1)
      {
        // Each chunk's graph from its own tets' faces: building the whole mesh's graph and
        // taking the chunks' out of it, through scattered reads of its rows, took 0.42 s of the
        // FinFET's 0.91 s of partitioning at one thread (its four chunks 0.12 s).
        DualGraph chunkGraph = dualGraphOfPositions(mesh.tets, order, begin, end);
        if (weights)
        {
          chunkGraph.vertexWeights.reserve(static_cast<std::size_t>(end - begin));
          for (CellId position = begin; position < end; ++position)
          {
            chunkGraph.vertexWeights.push_back((*weights)[order[position]]);
          }
        }
        statusOfChunk[c] = partitionGraph(chunkGraph, parts, local);
      }
      for (CellId position = begin; position < end; ++position)
      {
        partitionOfCell[order[position]] = firstPartition + local[position - begin];
      }
    });
  if (!status.ok())
  {
    return status;
  }
  for (const Status& chunkStatus : statusOfChunk)
  {
    if (!chunkStatus.ok())
    {
      return chunkStatus;
    }
  }
  return Status::success();
}

} // namespace cgmesh
