// Box partitions for the improvement sweeps: a grid of boxes over the mesh's bounding box, each tet
// in the box of its centroid, and the graph of the boxes. Regrouping and the graph run on a
// ParallelFor and give the same result for any schedule: a box holds its tets in (source
// partition, tet) order, as a serial pass would put them.
#ifndef cgmesh_BoxPartitions_h
#define cgmesh_BoxPartitions_h

#include "Core/PartitionMesh.h"
#include "Core/Status.h"
#include "Core/Tasks.h"
#include "Partitioning/PartitionGraph.h"

#include <array>
#include <cstddef>
#include <vector>

namespace cgmesh
{

struct BoxLayout
{
  int cells = 1;       // boxes along each axis of the bounding box
  double low[3] = {};  // the corner of box (0, 0, 0)
  double size[3] = {}; // a box's edge lengths
  // One box more per axis than `cells`: a layout shifted by a fraction of a box needs it at the
  // far ends.
  int boxesPerAxis() const { return this->cells + 1; }
  std::size_t numberOfBoxes() const;
  // The grid index, per axis, of the box holding `point` (clamped to the grid).
  std::array<int, 3> indexOf(const double* point) const;
  // Box number of a grid index: x fastest.
  std::size_t boxAt(const std::array<int, 3>& index) const;
  // The grid index of a box number (the inverse of boxAt).
  std::array<int, 3> indexOfBox(std::size_t box) const;
  // The box of the tet's centroid.
  std::size_t boxOf(const Tet& tet, const std::vector<double>& coordinates) const;
};

// `cells` boxes per axis over the bounding box of `coordinates`, moved back by `shift` boxes (0:
// from the bounding box's corner; 0.5: by half a box, so that the first layout's box faces lie
// inside boxes). The bounding box is found by ranges of points on `parallelFor`.
BoxLayout layBoxes(const std::vector<double>& coordinates, int cells, double shift,
  const ParallelFor& parallelFor = runSerially);

// Moves the tets of `partitions` into the boxes of `layout` (`boxes`), each into the box of its
// centroid. With `movingIfFlagged`, only the tets that touch a flagged point move, and the others
// stay in their partition (nothing is allocated for them): in order, but for those past the
// partition's new end, which fill the places the moving ones left, in order. Without it every
// tet moves and the partitions are emptied. With `boxOfFlaggedPoint` as well (an entry per flagged
// point), a moving tet goes into the box its first flagged corner names instead: tets that must
// stay together go into one box.
Status regroupIntoBoxes(std::vector<PartitionMesh>& partitions,
  const std::vector<double>& coordinates, const BoxLayout& layout, const ParallelFor& parallelFor,
  std::vector<PartitionMesh>& boxes, const std::vector<char>* movingIfFlagged = nullptr,
  const std::vector<std::size_t>* boxOfFlaggedPoint = nullptr);

// Moves every tet of `partitions` into `regrouped[partitionOfCell[parentCell]]` and empties
// `partitions`: the way back from boxes to the partitions of the input cells. The first source
// partition whose tets all go to one destination becomes that destination as it is; the other
// tets follow in (source partition, tet) order, as a serial pass would append them, counted and
// copied by ranges of the tets.
Status regroupByCellPartition(std::vector<PartitionMesh>& partitions,
  const std::vector<int>& partitionOfCell, int numberOfPartitions, const ParallelFor& parallelFor,
  std::vector<PartitionMesh>& regrouped);

// The boxes' partition graph, for colouring: two boxes are neighbours when the bounding boxes of
// their tets' corners meet. Boxes that share a point always do, so the graph holds every edge of
// the exact one (buildPartitionGraph), possibly more: any colouring of it keeps same-coloured
// boxes vertex-disjoint. Linear in the tets; when a box's tets reach further than 3 boxes beyond
// it (a mesh coarse for its layout) it falls back to the exact graph.
Status buildBoxGraph(const std::vector<PartitionMesh>& boxes,
  const std::vector<double>& coordinates, const BoxLayout& layout, const ParallelFor& parallelFor,
  PartitionGraph& graph);

} // namespace cgmesh

#endif
