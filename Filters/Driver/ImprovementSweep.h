// The second quality sweep. During refinement every vertex on an interface between partitions is
// frozen, so the tets around interfaces keep their template shapes. This sweep regroups the mesh
// into box-shaped partitions that cut across the refinement partitions, so that most former
// interfaces lie inside a partition, and runs quality improvement once more over a new colouring;
// then again over boxes shifted by half a box, whose insides hold the first layout's box faces.
#ifndef cgmesh_ImprovementSweep_h
#define cgmesh_ImprovementSweep_h

#include "ColorLoop.h"

namespace cgmesh
{

// `setup` is the set-up the partitions were improved with (threads, improvement parameters), and
// its stage and progress range are the sweeps'; `boxesPerAxis` the boxes along each axis of the
// first layout; `formerInterface` flags the vertices shared by two partitions. Only the tets that
// touch one and need work, and the tets sharing a vertex with those, move into boxes; the others
// stay in their partitions. All its time is improvement.
Status improveAcrossFormerInterfaces(const ColorLoopSetup& setup, const AdaptationOptions& options,
  int boxesPerAxis, const std::vector<char>& formerInterface, AdaptationState& state,
  AdaptationSummary& summary, PhaseReporter& reporter);

} // namespace cgmesh

#endif
