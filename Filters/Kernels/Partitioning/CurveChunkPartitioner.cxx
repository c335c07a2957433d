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
  const ParallelFor& parallelFor)
{
  const CellId tetCount = mesh.numberOfTets();
  partitionOfCell.assign(tetCount, 0);
  const Status count = checkPartitionCount(tetCount, numberOfPartitions);
  if (!count.ok() || numberOfPartitions == 1)
  {
    return count;
  }
  chunks = std::clamp(chunks, 1, numberOfPartitions);
  DualGraph graph;
  Status status = buildDualGraph(mesh.tets, graph, parallelFor);
  if (status.ok() && chunks == 1)
  {
    return partitionGraph(graph, numberOfPartitions, partitionOfCell);
  }
  std::vector<CellId> order, positionOf(tetCount);
  if (status.ok())
  {
    // Chunks of many thousand tets need no fine curve: 2^10 cells a side cost half the steps.
    status = orderTetsAlongHilbertCurve(mesh, order, parallelFor, 10);
  }
  if (status.ok())
  {
    status = forEachRange(parallelFor, tetCount, IndicesPerCopyRange,
      [&](std::int64_t begin, std::int64_t end)
      {
        for (CellId position = begin; position < end; ++position)
        {
          positionOf[order[position]] = position;
        }
      });
  }
  if (!status.ok())
  {
    return status;
  }
  std::vector<Status> statusOfChunk(chunks, Status::success());
  status = parallelFor(chunks,
    [&](std::int64_t c)
    {
      const CellId begin = c * tetCount / chunks;
      const CellId end = (c + 1) * tetCount / chunks;
      const int firstPartition = static_cast<int>(c * numberOfPartitions / chunks);
      const int parts = static_cast<int>((c + 1) * numberOfPartitions / chunks) - firstPartition;
      std::vector<int> local(static_cast<std::size_t>(end - begin), 0);
      if (parts > 1)
      {
        const DualGraph chunkGraph = subgraphOfPositions(graph, order, positionOf, begin, end);
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
