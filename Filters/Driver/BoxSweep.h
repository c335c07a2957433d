// A sweep over box partitions: the tets that need work move into a grid of boxes that cuts across
// the refinement partitions, so that most former interfaces lie inside a box, and the colour loop
// runs once more over a colouring of the boxes. Both sweeps across former interfaces use it: the
// improvement sweep (ImprovementSweep.h) and the Delaunay sweep that meshes boxes anew
// (RemeshSweep.h).
#ifndef cgmesh_BoxSweep_h
#define cgmesh_BoxSweep_h

#include "ColorLoop.h"
#include "Partitioning/BoxPartitions.h"

#include <cstddef>
#include <vector>

namespace cgmesh
{

// Moves the tets that touch a point flagged in `moving` into the boxes of `layout` and runs
// `sweep` over them (its graph, colouring and colour count are the boxes'). The other tets stay
// in their partitions, which follow the boxes in `state.partitions` afterwards (emptied ones
// left out). `boxCount` becomes the number of boxes: the sweep's partitions are the first
// `boxCount` ones of `state.partitions`. `boxOfMovingPoint`, when given, names the box of each
// moving tet by its flagged corners (see regroupIntoBoxes).
Status runSweepOverBoxes(ColorLoopSetup sweep, const AdaptationOptions& options,
  const BoxLayout& layout, const std::vector<char>& moving, AdaptationState& state,
  AdaptationSummary& summary, PhaseReporter& reporter, std::size_t& boxCount,
  const std::vector<std::size_t>* boxOfMovingPoint = nullptr);

} // namespace cgmesh

#endif
