// Quality improvement of the input before template refinement. A template child has its parent's
// shape or one close to it, so a poor input tet becomes eight poor tets per pass: improving the
// input works on a fraction of the tets that improving the refined mesh does, and leaves that
// step little to do.
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
// interfaces. Then every tet goes back to the partition of its input cell (`partitionOfCell`),
// and `graph` and the colouring (summary and `setup`) are rebuilt: a tet made across an interface
// can give its partition a vertex of another.
Status improveInputFirst(const AdaptationOptions& options, const std::vector<int>& partitionOfCell,
  PartitionGraph& graph, ColorLoopSetup& setup, AdaptationState& state, AdaptationSummary& summary,
  PhaseReporter& reporter);

} // namespace cgmesh

#endif
