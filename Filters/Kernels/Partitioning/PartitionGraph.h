// The partition graph: two partitions are adjacent when they share at least one vertex (smoothing
// moves vertices and an edge split touches both end points, so sharing an edge is not enough).
#ifndef cgmesh_PartitionGraph_h
#define cgmesh_PartitionGraph_h

#include "Core/PartitionMesh.h"
#include "Core/Status.h"
#include "Core/Tasks.h"
#include "Core/TetMesh.h"

#include <vector>

namespace cgmesh
{

struct PartitionGraph
{
  int numberOfPartitions = 0;
  std::vector<std::int64_t> offsets; // size numberOfPartitions + 1
  std::vector<int> neighbours;       // sorted within each row
  std::int64_t interfacePoints = 0;  // points in tets of two or more partitions
  // Per point of the partitioned mesh, 1 for those interface points (graphs built from tets).
  std::vector<char> interfaceVertex;

  int degree(int partition) const
  {
    return static_cast<int>(offsets[partition + 1] - offsets[partition]);
  }
  const int* neighboursOf(int partition) const { return neighbours.data() + offsets[partition]; }
  std::int64_t numberOfEdges() const { return static_cast<std::int64_t>(neighbours.size()) / 2; }
};

// The graph of the partition of `tets` given by `partitionOfCell`. The tets are scanned on the
// calling thread; `parallelFor` gathers the partitions' neighbour rows. The graph does not
// depend on it.
Status buildPartitionGraph(const TetList& tets, const std::vector<int>& partitionOfCell,
  int numberOfPartitions, PointId numberOfPoints, const ParallelFor& parallelFor,
  PartitionGraph& graph);

// The same for partitions held as meshes: partition p owns the tets of partitions[p].
Status buildPartitionGraph(const std::vector<PartitionMesh>& partitions, PointId numberOfPoints,
  const ParallelFor& parallelFor, PartitionGraph& graph);

// Builds a graph from an explicit undirected edge list (tests and colouring benchmarks).
PartitionGraph makePartitionGraph(int numberOfPartitions, std::vector<std::pair<int, int>> edges);

} // namespace cgmesh

#endif
