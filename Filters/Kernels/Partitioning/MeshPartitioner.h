// Splits a tet mesh into contiguous partitions: METIS k-way on the dual graph (tets adjacent when
// they share a face).
#ifndef cgmesh_MeshPartitioner_h
#define cgmesh_MeshPartitioner_h

#include "Core/Status.h"
#include "Core/TetMesh.h"

#include <vector>

namespace cgmesh
{

// Face-adjacency graph of the tets in compressed rows.
struct DualGraph
{
  std::vector<std::int64_t> offsets; // size numberOfTets + 1
  std::vector<CellId> neighbours;
};

DualGraph buildDualGraph(const TetMesh& mesh);

// Assigns every tet a partition in [0, numberOfPartitions). Deterministic: METIS runs with a
// fixed seed on a graph built in a fixed order.
Status partitionMesh(
  const TetMesh& mesh, int numberOfPartitions, std::vector<int>& partitionOfCell);

// Cuts along material regions: each region (in increasing region id order) becomes
// `partitionsPerRegion` partitions (fewer when it has fewer tets), split by METIS on the region's
// own dual graph. Sets `numberOfPartitions` to the total. Requires mesh.regions.
Status partitionByRegion(const TetMesh& mesh, int partitionsPerRegion,
  std::vector<int>& partitionOfCell, int& numberOfPartitions);

} // namespace cgmesh

#endif
