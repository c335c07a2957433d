// The Delaunay sweep across former interfaces. Refinement keeps every partition's boundary as it
// is, so where the partitions of a sliver-laden input meet, TetGen fills both sides against the
// same poor faces and crowds points along them; improvement (swaps and smoothing) cannot undo
// that. This sweep gathers the slivers at former interfaces, with the tets around them, into
// clusters of tets that share a corner, puts each cluster whole into one box (a box face through
// a cluster would be a poor face to keep, on which TetGen fails), and lets TetGen mesh each box
// anew without the interior points refinement made (remeshPartitionDelaunay), boxes of one
// colour at once. The same machinery meshes a sliver-laden input's clusters anew before it is
// refined (remeshSliverClusters).
#ifndef cgmesh_RemeshSweep_h
#define cgmesh_RemeshSweep_h

#include "ColorLoop.h"

#include <cstdint>

namespace cgmesh
{

// A tet at a former interface vertex with a minimum dihedral angle below this goes into the
// sweep's boxes, with the tets up to SweepRings vertex rings around it.
constexpr double SweepSliverDegrees = 5.0;
constexpr int SweepRings = 2;

// `setup` is the Delaunay refinement's (threads, TetGen runner, bounds); `boxesPerAxis` the boxes
// along each axis of the grid; `formerInterface` flags the vertices shared by two
// refinement partitions. Does nothing unless the tets at former interfaces under
// RemeshSliverDegrees are more than RemeshSliverShare of all tets. Its time is heal, adapt and
// post, as refinement's is.
Status remeshAcrossFormerInterfaces(const ColorLoopSetup& setup, const AdaptationOptions& options,
  int boxesPerAxis, const std::vector<char>& formerInterface, AdaptationState& state,
  AdaptationSummary& summary, PhaseReporter& reporter);

// The tets under RemeshSliverDegrees among all.
struct SliverCount
{
  std::int64_t slivers = 0;
  std::int64_t tets = 0;

  // Whether they are more than RemeshSliverShare of all.
  bool many() const { return exceedsSliverShare(slivers, static_cast<std::size_t>(tets)); }
};

// Counts the slivers of every partition (a scan of every tet, on `threads` threads).
Status countSlivers(int threads, const AdaptationState& state, SliverCount& count);

// Meshes the clusters around every sliver anew as the sweep does (not only at former
// interfaces), with the radius-edge bound alone (DelaunayParameters::shapesOnly), when the tets
// under RemeshSliverDegrees are more than RemeshSliverShare of all tets; `remeshed` says whether
// it did. For a sliver-laden input before it is refined (InputImprovement.h).
Status remeshSliverClusters(const ColorLoopSetup& setup, const AdaptationOptions& options,
  int boxesPerAxis, AdaptationState& state, AdaptationSummary& summary, PhaseReporter& reporter,
  bool& remeshed);

} // namespace cgmesh

#endif
