// The second quality sweep. During refinement every vertex on an interface between partitions is
// frozen, so the tets around interfaces keep their template shapes. This sweep regroups the mesh
// into box-shaped partitions that cut across the refinement partitions, so that most former
// interfaces lie inside a partition, and runs quality improvement once more over a new colouring;
// then again over boxes shifted by half a box, whose insides hold the first layout's box faces.
// Skipped when improvement inside the partitions (templates) saw no tet below the target.
#ifndef cgmesh_ImprovementSweep_h
#define cgmesh_ImprovementSweep_h

#include "ColorLoop.h"

namespace cgmesh
{

// `refinementSetup` is the set-up the refinement ran with (threads, improvement parameters);
// `boxesPerAxis` the boxes along each axis of the first layout; `formerInterface` flags the
// vertices shared by two refinement partitions: only the tets touching one take part, the others
// end up in one last partition of their own. All its time is improvement.
Status improveAcrossFormerInterfaces(const ColorLoopSetup& refinementSetup,
  const AdaptationOptions& options, int boxesPerAxis, const std::vector<char>& formerInterface,
  AdaptationState& state, AdaptationSummary& summary, PhaseReporter& reporter);

} // namespace cgmesh

#endif
