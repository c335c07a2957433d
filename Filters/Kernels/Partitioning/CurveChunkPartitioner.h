// Splits a tet mesh in two levels, so that the graph partitioner runs on pieces at once: the
// Hilbert curve through the tets' centroids cuts the mesh into a few chunks of equal tet counts,
// then each chunk's own dual graph is cut into its share of the partitions. The chunk borders are
// Hilbert cuts (longer than METIS' own), everything inside a chunk is cut by the graph
// partitioner; a few chunks add a few percent of interface points (the 837k-tet FinFET into 84
// parts: 27,942 interface points in one piece, 29,502 in four chunks) and make the graph work
// smaller (METIS' cost grows with the graph, the coarsening of a chunk's graph is a quarter
// of the whole's).
#ifndef cgmesh_CurveChunkPartitioner_h
#define cgmesh_CurveChunkPartitioner_h

#include "Partitioning/HilbertPartitioner.h"
#include "Partitioning/MeshPartitioner.h"

#include "Core/Status.h"
#include "Core/Tasks.h"
#include "Core/TetMesh.h"

#include <functional>
#include <vector>

namespace cgmesh
{

// Cuts `graph` into `parts` parts (partOfVertex[v] in [0, parts)); the result must depend on the
// graph and `parts` alone. Called through `parallelFor`, so possibly from several threads at once.
using GraphPartitioner =
  std::function<Status(const DualGraph& graph, int parts, std::vector<int>& partOfVertex)>;

// How many chunks a mesh of `tetCount` tets is cut into for `numberOfPartitions` partitions:
// one per TetsPerChunk tets and at most one per PartitionsPerChunk partitions, at least one, at
// most MaximumChunks. Below 400,000 tets METIS is cheap and the chunk borders' extra interface
// costs more than it saves: one chunk, plain METIS. A function of the mesh and the count alone,
// so that the partitions do not depend on the thread count.
int curveChunkCount(CellId tetCount, int numberOfPartitions);

// Assigns every tet a partition in [0, numberOfPartitions): chunk c holds the tets at positions
// [c n / C, (c + 1) n / C) along the curve (with `weights`, runs of equal weight,
// weightedRunStarts) and the partitions [c k / C, (c + 1) k / C), which `partitionGraph` assigns
// inside it, on the chunk's graph with the tets' weights. Chunks are handled through
// `parallelFor`; the result does not depend on it.
Status partitionInCurveChunks(const TetMesh& mesh, int numberOfPartitions, int chunks,
  const GraphPartitioner& partitionGraph, std::vector<int>& partitionOfCell,
  const ParallelFor& parallelFor = ParallelFor(runSerially), const TetWeights* weights = nullptr);

} // namespace cgmesh

#endif
