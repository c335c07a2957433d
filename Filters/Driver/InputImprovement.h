// The input's tets made better before they are refined. Template: a child has its parent's shape
// or one close to it, so a poor input tet becomes eight poor tets per pass: improving the input
// works on a fraction of the tets that improving the refined mesh does, and leaves that step
// little to do. Delaunay: TetGen keeps every partition's boundary, and where those faces are a
// sliver-laden input's, it refines slowly and leaves slivers. Templates cut slivers into slivers,
// and improvement cannot mend what they then make (a size field's passes on the benchmark's poor
// input: 1.9 M tets in 43-49 s at 2 threads, minimum dihedral p1 0.03 degrees). So a sliver-laden
// input is meshed anew by TetGen first, for either method, then improved.
#ifndef cgmesh_InputImprovement_h
#define cgmesh_InputImprovement_h

#include "ColorLoop.h"

namespace cgmesh
{

// Whether the run improves its input first: template refinement with ImproveQuality and
// ImproveInput, over the whole mesh (a RefinementRegions or RefinementBox selection promises to
// leave the other tets as they are).
bool improvesInputFirst(const AdaptationOptions& options, const AdaptationPlan& plan);

// Improves the tets of the refinement partitions in `state` as the refined mesh is improved:
// inside each partition on the colour loop, then in the box sweeps across the partitions'
// interfaces, which `graph` (built for those partitions) gives. Then every tet goes back to the
// partition of its input cell (`partitionOfCell`), and `graph` and the colouring (summary and
// `setup`) are rebuilt: a tet made across an interface can give its partition a vertex of another.
Status improveInputFirst(const AdaptationOptions& options, const std::vector<int>& partitionOfCell,
  PartitionGraph& graph, ColorLoopSetup& setup, AdaptationState& state, AdaptationSummary& summary,
  PhaseReporter& reporter);

// Whether the run meshes a sliver-laden input anew first: ImproveInput and ImproveQuality, and
// for templates only where the boundary triangulation may change (no tagged triangles, no pieces
// across processes) and over the whole mesh (no RefinementRegions or RefinementBox).
bool remeshesInputFirst(const AdaptationOptions& options, const AdaptationPlan& plan);

// For an input whose tets under RemeshSliverDegrees are more than RemeshSliverShare of all
// (countSlivers), with TetGen attached to `setup`. Where the boundary triangulation may change,
// the whole input is meshed anew in one TetGen call with the radius-edge bound alone, its
// boundary and material-interface faces free to split. Otherwise, and for Delaunay when that call
// fails: the interface rounds of Delaunay refinement (boundary, material-interface and partition-
// interface edges split down to the interface length), then the clusters around the slivers
// meshed anew (remeshSliverClusters). Then every tet goes back to its input cell's partition with
// `graph` and the colouring rebuilt, and the tets are improved as by improveInputFirst.
// `remeshed` says whether TetGen meshed any of it anew, and so whether the tets were improved.
// Refinement then cuts its partitions through TetGen's tets instead of slivers. `refined`: the
// whole input was meshed anew and refined to the volume bound in the same call
// (AdaptationPlan::wholeInputCallRefines); its tets are not improved here, and the refinement
// passes have only to improve them.
Status remeshInputFirst(const AdaptationOptions& options, const std::vector<int>& partitionOfCell,
  PartitionGraph& graph, ColorLoopSetup& setup, AdaptationState& state, AdaptationSummary& summary,
  PhaseReporter& reporter, bool& remeshed, bool& refined);

// improveInputFirst, its progress going from `progressStart` to `progressEnd` of its stage.
Status improveInputBetween(double progressStart, double progressEnd,
  const AdaptationOptions& options, const std::vector<int>& partitionOfCell, PartitionGraph& graph,
  ColorLoopSetup& setup, AdaptationState& state, AdaptationSummary& summary,
  PhaseReporter& reporter);

// Every tet to the partition of its input cell (`partitionOfCell`), then `graph` and the
// colouring (summary and `setup`) rebuilt for them; reports `progress` of the ImproveInput stage.
Status returnToInputPartitions(const AdaptationOptions& options,
  const std::vector<int>& partitionOfCell, PartitionGraph& graph, ColorLoopSetup& setup,
  AdaptationState& state, AdaptationSummary& summary, PhaseReporter& reporter, double progress);

} // namespace cgmesh

#endif
