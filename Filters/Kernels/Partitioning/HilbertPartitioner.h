// Splits a tet mesh into partitions of equal tet counts along a Hilbert curve through the tets'
// centroids. It needs no dual graph and no graph partitioner: a key per tet and one sort, so it
// costs the same for 64 or 65,536 partitions. The price is a longer interface than METIS' and
// parts that may be disconnected where the domain is not convex.
#ifndef cgmesh_HilbertPartitioner_h
#define cgmesh_HilbertPartitioner_h

#include "Core/Status.h"
#include "Core/Tasks.h"
#include "Core/TetMesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace cgmesh
{

// The tets' ids ordered by the Hilbert index of their centroid on a grid of 2^bits cells a side
// (bits in [1, 21]) over the mesh's bounding cube, ties by tet id. The index costs a step per
// bit. The same for any `parallelFor`.
Status orderTetsAlongHilbertCurve(const TetMesh& mesh, std::vector<CellId>& order,
  const ParallelFor& parallelFor = ParallelFor(runSerially), int bits = 21);

// The work each tet stands for, by tet id, when partitions are to balance it instead of their
// tet counts: positive integers (the filter makes them from the forecast output of each tet when
// a size field, refinement regions or a box make the output uneven).
using TetWeights = std::vector<std::int64_t>;

// Where `pieces` runs of the tets at positions [0, order.size()) of `order` start (pieces + 1
// entries, the last order.size()): run r starts at the first position where the weight before it
// reaches r / pieces of the total, moved only as far as it takes for every run r to hold at least
// least[r] tets (their sum must not exceed the tets).
std::vector<CellId> weightedRunStarts(
  const std::vector<CellId>& order, const TetWeights& weights, const std::vector<CellId>& least);

// Assigns every tet a partition in [0, numberOfPartitions): the tets ordered by the Hilbert index
// of their centroid (ties by tet id) are cut into runs of equal size, or of equal weight with
// `weights` (each run at least one tet). Deterministic: `parallelFor` runs the keys and the sort in
// ranges, and the result does not depend on it.
Status partitionAlongHilbertCurve(const TetMesh& mesh, int numberOfPartitions,
  std::vector<int>& partitionOfCell, const ParallelFor& parallelFor = ParallelFor(runSerially),
  const TetWeights* weights = nullptr);

} // namespace cgmesh

#endif
