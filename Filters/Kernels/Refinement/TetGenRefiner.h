// Delaunay refinement of one partition: its interface and material-interface edges are first split
// by templates (so neighbours can heal them through the outbox), then TetGen refines the interior
// with every boundary and material-interface face kept as it is (switches r, Y, q, and a for a
// volume bound or m for a size field: RefinementContext::sizes). A partition full of slivers is
// first meshed anew from its kept faces and points instead (switch p for r; see
// RemeshSliverDegrees), and refined as any other where that fails.
// A TetGen failure (a thrown int, or output that does not validate) never loses the partition: it
// falls back to template refinement of the interior edges.
#ifndef cgmesh_TetGenRefiner_h
#define cgmesh_TetGenRefiner_h

#include "Core/FaceKey.h"
#include "Refinement/PartitionRefiner.h"

#include <functional>
#include <string>

class tetgenio;

namespace cgmesh
{

// Surface classes of kept faces: (sorted corners, class) pairs sorted by corners. Faces of one
// class carry the same tags (the filter's triangle cells with equal cell data).
using SurfaceClasses = std::vector<std::pair<Face, int>>;

struct DelaunayParameters
{
  double maximumVolume = 0;     // TetGen's volume bound (switch a)
  double radiusEdgeRatio = 2;   // TetGen's radius-edge quality bound (switch q)
  bool simulateFailure = false; // behave as if TetGen had failed (tests of the fallback)
  // Before a sliver-laden input is meshed anew (Driver/InputImprovement.h): only the interface
  // rounds, no TetGen call; then TetGen with the radius-edge bound alone, neither the volume
  // bound nor the sizes.
  bool constrainedEdgesOnly = false;
  bool shapesOnly = false;
  // Meshing anew only: TetGen may split the kept faces (no switch Y), as it splits a boundary it
  // meshes on its own, and triangulate coplanar neighbouring ones anew (no switch M). Only for a
  // partition that holds the whole mesh, whose kept faces are the domain boundary and the
  // material interfaces alone, shared with no other partition.
  bool keptFacesMaySplit = false;
  // With keptFacesMaySplit: the classes of the tagged kept faces (null: none tagged). TetGen
  // merges coplanar neighbours of one class only, untagged ones among themselves, so no face it
  // makes straddles two classes, and each stays a child of triangles of one class.
  const SurfaceClasses* surfaceClasses = nullptr;
};

// The edge length up to which templates refine interfaces for a volume bound: the edge of the
// regular tetrahedron of that volume, (6 sqrt(2) V)^(1/3).
double interfaceEdgeLengthForVolume(double maximumVolume);

// With a size field, TetGen gets this times h per point: it splits a tet whose circumradius
// exceeds its corners' value, and a regular tet of edge h has circumradius 0.61 h. Chosen by
// measurement on the Big cube with a graded field (benchmarks/size-field): edges within
// [h / sqrt(2), sqrt(2) h] peak near this value (see docs/design.md).
constexpr double TetGenRadiusPerSize = 0.7;
// A partition whose share of tets with a minimum dihedral angle below RemeshSliverDegrees exceeds
// RemeshSliverShare (after its interface edges are split) is meshed anew by TetGen from its kept
// faces and points instead of refined (see refinePartitionDelaunay).
constexpr double RemeshSliverDegrees = 1.0;
constexpr double RemeshSliverShare = 0.001;
// Whether `slivers` (tets under RemeshSliverDegrees) are more than RemeshSliverShare of `tets`: the
// rule for a partition, the sweep across former interfaces and a sliver-laden input alike.
inline bool exceedsSliverShare(std::int64_t slivers, std::size_t tets)
{
  return static_cast<double>(slivers) > RemeshSliverShare * static_cast<double>(tets);
}
// About how many tets TetGen makes of `volume` under the bound: its tets average about a third
// of the bound (measured on cubes and FinFETs). Used by the size guard and the partition count.
double forecastDelaunayTets(double volume, double maximumVolume);
// The same for a size field (`sizes` per point of `coordinates`): tet by tet, at the mean size of
// its corners.
double forecastDelaunayTetsForSizes(
  const TetList& tets, const std::vector<double>& coordinates, const std::vector<double>& sizes);

// TetGen's output tets forecast for refining the tets given in `in` to `maximumVolume`: the tets
// given plus four per bound of their volume (generous: its tets average about a third of the
// bound). Sizes the time limit of a call and the points it may add.
double forecastRefinedTets(const tetgenio& in, double maximumVolume);

// Gives `io` `count` facets of one triangle each, their corners 3 per facet in `corners`: the PLC
// of a partition meshed anew (switch p).
void setTriangleFacets(tetgenio& io, const int* corners, int count);

// Runs TetGen with the given switches on `in`, filling `out`; returns an empty string on success,
// else why it failed. The driver runs the calls in worker processes (see WorkerPool.h). A
// call stopped for taking too long returns a reason that starts with TetGenTimeLimitReason: no
// further attempt is made on that partition.
constexpr const char* TetGenTimeLimitReason = "TetGen took longer than";
// A call that refines given tets to a volume bound may add at most twice its forecast output tets
// (forecastRefinedTets) in points, at least SteinerCapFloor; one that adds more than half the cap
// fails with a reason starting with TetGenRunawayReason, and no further attempt is made either.
constexpr int SteinerCapFloor = 1000;
constexpr const char* TetGenRunawayReason = "TetGen kept inserting points";
// A call ended because the run was aborted: no further attempt is made, and the partition's
// outcome counts as no failure (the run's result is dropped).
constexpr const char* WorkerCallAbortedReason = "the run was aborted";
using TetGenRunner =
  std::function<std::string(const tetgenio& in, const std::string& switches, tetgenio& out)>;

struct DelaunayOutcome
{
  bool fellBack = false;            // TetGen failed; the partition was template-refined instead
  bool retried = false;             // the first TetGen call failed, a second attempt was made
  bool withoutQualityBound = false; // refined by the last attempt, without the radius-edge bound
  bool remeshed = false;            // meshed anew from its kept faces and points (switch p)
  std::int64_t droppedPoints = 0;   // interior points meshed without (remeshPartitionDelaunay)
  std::string reason;               // why, when it fell back
  std::int64_t tetgenPoints = 0;    // Steiner points TetGen inserted
};

// `context.squaredThreshold` must hold the squared interface edge length.
Status refinePartitionDelaunay(PartitionMesh& partition, const RefinementContext& context,
  const PostedSplits& received, const DelaunayParameters& parameters, const TetGenRunner& runTetGen,
  PartitionRefinement& refinement, DelaunayOutcome& outcome);

// The Delaunay sweep across former interfaces: meshes the partition anew (switch p) from its
// boundary and material-interface faces as they are (no edge is split, so no neighbour has
// anything to heal) and from its points, but for the interior ones from `firstDroppablePoint` on
// (those an earlier pass made), which the partition loses. Where partitions of the first pass
// met, those points crowd the former interface and TetGen, bound to keep them, leaves the slivers
// they make. On failure the partition stays as it was, and `outcome` says why (fellBack, reason).
Status remeshPartitionDelaunay(PartitionMesh& partition, const RefinementContext& context,
  const DelaunayParameters& parameters, PointId firstDroppablePoint, const TetGenRunner& runTetGen,
  PartitionRefinement& refinement, DelaunayOutcome& outcome);

} // namespace cgmesh

#endif
