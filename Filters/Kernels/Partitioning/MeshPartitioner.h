// Splits a tet mesh into contiguous partitions: METIS k-way on the dual graph (tets adjacent when
// they share a face).
#ifndef cgmesh_MeshPartitioner_h
#define cgmesh_MeshPartitioner_h

#include "Core/Status.h"
#include "Core/Tasks.h"
#include "Core/TetMesh.h"
#include "Partitioning/DualGraph.h"

#include <vector>

namespace cgmesh
{

// METIS k-way on `graph` into `parts` parts, or its recursive bisection into 16 or more parts of
// fewer than 128 vertices when connected parts are not asked for; with `contiguous`, connected
// parts when the graph is connected. Deterministic for a given graph (fixed seed), but METIS
// draws from the C library's process-wide random generator: two calls must never overlap in one
// process.
Status partitionGraphWithMetis(
  const DualGraph& graph, int parts, std::vector<int>& partOfVertex, bool contiguous = true);

struct PartitioningOptions
{
  // Ask METIS for connected parts (when the mesh is connected). It costs METIS about half its
  // time and gains little (a 200k-tet FinFET, templates, 1024 parts: 0.1% more tets near
  // interfaces without it; Delaunay on the Big cube: 0.03% more tets), so the filter does not.
  bool contiguous = true;
  // From this many partitions on, METIS' initial partitioning of its coarsest graph dominates:
  // the mesh is first cut into about sqrt(k) parts, then each into its share of the k. The
  // second level runs one METIS call after another: METIS seeds a process-wide random generator,
  // so overlapping calls would make the partitions depend on thread timing.
  int hierarchicalFrom = 4096;
  // When set: the work each tet stands for (TetWeights), which the parts balance instead of
  // their tet counts.
  const std::vector<std::int64_t>* tetWeights = nullptr;
};

// A partition count a mesh of `tetCount` tets can be cut into: at least 1, at most one per tet.
Status checkPartitionCount(CellId tetCount, int numberOfPartitions);

// Assigns every tet a partition in [0, numberOfPartitions). Deterministic: METIS runs with a
// fixed seed on graphs built in a fixed order.
Status partitionMesh(const TetMesh& mesh, int numberOfPartitions, std::vector<int>& partitionOfCell,
  const PartitioningOptions& options = PartitioningOptions(),
  const ParallelFor& parallelFor = ParallelFor(runSerially));

// Cuts along material regions: each region (in increasing region id order) becomes
// `partitionsPerRegion` partitions (fewer when it has fewer tets), split by METIS on the region's
// own dual graph. Sets `numberOfPartitions` to the total. Requires mesh.regions.
Status partitionByRegion(const TetMesh& mesh, int partitionsPerRegion,
  std::vector<int>& partitionOfCell, int& numberOfPartitions,
  const ParallelFor& parallelFor = ParallelFor(runSerially));

} // namespace cgmesh

#endif
