// Joins the refined partitions into one conforming mesh: drops points no tet uses, numbers the
// rest in their global order (each interface point appears once: partitions share global ids),
// and expresses every output point as a weighted sum of input points for data interpolation.
#ifndef cgmesh_MeshMerge_h
#define cgmesh_MeshMerge_h

#include "Core/EdgeSplits.h"
#include "Core/PartitionMesh.h"
#include "Core/Status.h"
#include "Core/Tasks.h"
#include "Core/TetMesh.h"

#include <vector>

namespace cgmesh
{

// Output point i is the weighted sum of input points
// sources[offsets[i] .. offsets[i + 1]) with the matching weights: linear interpolation of point
// data. Input points that survive have a single source with weight 1, unless improvement moved
// them; `inputPoints` tells them apart either way.
struct PointProvenance
{
  std::vector<std::int64_t> offsets;
  std::vector<PointId> sources;
  std::vector<double> weights;
  std::vector<PointId> inputPoints; // per output point: the input point it is, or -1 if new
};

// A source whose weight is at most this in magnitude is one in name only: a point TetGen puts on
// a face or an edge of the tet it lies in gets rounding noise (1e-17 to 1e-14) as the weight of
// the corners off that face or edge. Such a source neither shares its labels nor passes on that
// it moved.
constexpr double NegligibleSourceWeight = 1e-12;

struct MergedMesh
{
  TetMesh mesh;
  UnfilledVector<CellId> parentCell; // per output tet: the input tet it came from
  PointProvenance provenance;        // per output point, over input point ids
  PointId removedPoints = 0;         // points no tet uses (unused input points)
};

// `coordinates` holds all global points; points from `inputPointCount` on were created by
// refinement at the locations in `newPointSources` (one entry per created point, in id order).
// Points quality improvement moved, and points whose location derives from one (a midpoint of a
// moved point, ...), no longer lie where their recorded sources say: those get their provenance
// from the input tet that contains their final position (`input` is the unrefined mesh).
struct RelocationInput
{
  const TetMesh* input = nullptr;
  const std::vector<PointId>* movedPoints = nullptr;
};

// `withProvenance` false leaves merged.provenance empty (nothing to interpolate); then
// `newPointSources` is not read and may be empty. `pointSizes` (one size per global point, or
// empty) gives merged.mesh.sizes. `coordinates` and `pointSizes` are taken: when every point is
// used, as after any refinement that removed none, they become the merged mesh's own arrays
// without a copy. `parallelFor` runs the marking and numbering of the used points and the copies
// of points and tets; the output does not depend on it. The provenance expansion is serial: it is
// only built when there is point data to carry.
Status mergePartitions(const std::vector<PartitionMesh>& partitions,
  std::vector<double> coordinates, PointId inputPointCount,
  const std::vector<PointSource>& newPointSources, MergedMesh& merged,
  const RelocationInput& relocation = RelocationInput(), bool withProvenance = true,
  std::vector<double> pointSizes = std::vector<double>(),
  const ParallelFor& parallelFor = ParallelFor(runSerially));

} // namespace cgmesh

#endif
