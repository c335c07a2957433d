// Local quality improvement of one partition after refinement: edge removal (a ring of 3 to 7
// tets around an edge re-triangulated without it: 3->2, 4->4, 5->6, ...), face swaps (2->3) and
// Laplacian smoothing with rollback; and, with a size field, coarsening: edges shorter than
// h / sqrt(2) collapsed at their free end (EdgeCollapse.cxx).
//
// Only what the partition owns alone is touched: vertices on its boundary (partition interfaces
// and the domain boundary) and on material interfaces never move, and the edges and faces changed
// are interior to the partition and to one material, so neighbours keep matching faces. A change
// is kept only when it raises the smallest mean ratio (TetQuality.h) of the tets it replaces and
// inverts nothing. Serial and deterministic: the same input gives the same output.
#ifndef cgmesh_QualityImprover_h
#define cgmesh_QualityImprover_h

#include "Core/PartitionMesh.h"
#include "Core/ProvisionalIds.h"
#include "Core/Status.h"

#include <limits>
#include <vector>

namespace cgmesh
{

struct ImprovementParameters
{
  int passes = 2;      // sweeps of edge removal, face swaps and smoothing (and of coarsening)
  bool improve = true; // edge removal, face swaps and smoothing
  // Collapse edges shorter than h / sqrt(2) (h from PartitionPoints::sizeAt), each at an end that
  // is free to go: a vertex on no boundary, interface or material interface face. A collapse is
  // kept when it inverts nothing, makes no edge longer than sqrt(2) h (which refinement would
  // split again), and leaves the worst mean ratio of the affected tets at least
  // min(collapseQualityFloor, their worst before).
  bool coarsen = false;
  double collapseQualityFloor = 0.3;
  // With coarsening, when set: only the vertices flagged here (by global point id) may be
  // collapsed, and only short edges with a flagged end are work. The sweeps across former
  // interfaces pass the former interface vertices: every other vertex was free in its partition,
  // whose improvement tried its short edges already.
  const std::vector<char>* collapsibleVertices = nullptr;
  // When set (to the same flags as collapsibleVertices), the improver clears the flag of every
  // vertex it could not collapse while it was free: that vertex had its chance, as every vertex
  // inside a partition had, and a later sweep leaves it be. Only free vertices' flags are
  // written, and a free vertex lies in the tets of one improver alone, so improvers running at
  // once never share one.
  std::vector<char>* settledVertices = nullptr;
  // Only tets whose mean ratio is below this are worked on: good tets are left alone, which is
  // where most of the time would go.
  double targetQuality = 0.5;
  // When positive, no change may create a tet larger than this (nor than the largest it replaces):
  // Delaunay refinement's volume bound survives the improvement.
  double maximumVolume = 0;
  // When set: flags, by global point id, the input points outside a RefinementRegions or
  // RefinementBox selection (pointsOutsideSelection()). A tet with such a corner is neither work
  // nor handed to an improver, so it stays exactly as it is: the tets outside a selection change
  // only where refinement's closure templates split them. Points past the flags' end, and
  // provisional ones, are new, made inside the selection.
  const std::vector<char>* keptPoints = nullptr;
};

struct ImprovementStatistics
{
  std::int64_t edgeRemovals = 0;
  std::int64_t faceSwaps = 0;
  std::int64_t vertexMoves = 0;
  std::int64_t edgeCollapses = 0;
  std::int64_t poorTets = 0; // tets below the target when the partition was taken up
};

// Where a partition's points live: global ids in `global`, provisional ids (see
// PartitionRefinement) in `provisional`. Improvement writes only the partition's free vertices.
struct PartitionPoints
{
  std::vector<double>* global = nullptr;
  std::vector<double>* provisional = nullptr;
  // The size field at the same points; null without one. With it, coarsening may run, and no
  // collapse, and no other change but one that mends a sliver (Improver::SliverMeanRatio), makes
  // an edge longer than sqrt(2) h.
  const std::vector<double>* globalSizes = nullptr;
  const std::vector<double>* provisionalSizes = nullptr;

  double* at(PointId id) const
  {
    return const_cast<double*>(pointCoordinates(*global, *provisional, id));
  }
  // Infinite where there is no size: no edge there counts as short.
  double sizeAt(PointId id) const
  {
    if (!globalSizes)
    {
      return std::numeric_limits<double>::infinity();
    }
    return pointSize(*globalSizes, *provisionalSizes, id);
  }
};

// Whether `tet` has a corner improvement must leave where it is
// (ImprovementParameters::keptPoints).
inline bool isKept(const Tet& tet, const ImprovementParameters& parameters)
{
  const std::vector<char>* kept = parameters.keptPoints;
  if (!kept)
  {
    return false;
  }
  for (PointId id : tet)
  {
    if (!isProvisional(id) && static_cast<std::size_t>(id) < kept->size() && (*kept)[id])
    {
      return true;
    }
  }
  return false;
}

// Whether vertex `id` may be collapsed (ImprovementParameters::collapsibleVertices).
inline bool mayCollapse(PointId id, const ImprovementParameters& parameters)
{
  const std::vector<char>* flags = parameters.collapsibleVertices;
  return !flags ||
    (!isProvisional(id) && static_cast<std::size_t>(id) < flags->size() && (*flags)[id]);
}

// Whether improvePartition() works on `tet`: its mean ratio is below the target (with
// `improve`), or an edge is shorter than the size field asks with an end that may be collapsed
// (with `coarsen`). The operations stay
// among the tets that share a vertex with such a tet.
bool needsImprovement(
  const Tet& tet, const PartitionPoints& points, const ImprovementParameters& parameters);

// Improves `partition` in place; appends the ids of the vertices it moved to `movedPoints`.
// `tetsLeft`, when given, becomes the indices (ascending) of the partition's tets that still need
// improvement (needsImprovement() with `parameters`) afterwards: every other tet passes it, so a
// later search for work may look at these alone while the partition stays as it is.
// `tetsToScreen`, when given, are the indices of the only tets that may need improvement (as
// refinement lists them, PartitionRefinement::tetsToScreen): work is looked for among them alone.
Status improvePartition(PartitionMesh& partition, const PartitionPoints& points,
  const ImprovementParameters& parameters, ImprovementStatistics& statistics,
  std::vector<PointId>& movedPoints, std::vector<std::size_t>* tetsLeft = nullptr,
  const std::vector<std::size_t>* tetsToScreen = nullptr);

} // namespace cgmesh

#endif
