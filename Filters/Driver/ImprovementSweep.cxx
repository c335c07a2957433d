#include "ImprovementSweep.h"

#include "Coloring/PartitionColoring.h"
#include "ParallelFor.h"
#include "Partitioning/BoxPartitions.h"

namespace cgmesh
{
namespace
{

// One improvement sweep over box partitions; `sweepIndex` 0 lays the boxes from the bounding
// box's corner, 1 shifts them by half a box. With `formerInterface` (the first sweep), the tets
// that touch no flagged vertex go to `settled` instead: the sweeps have nothing to do there
// (refinement already improved them, or TetGen met its bound), and leaving them out halves what
// the sweeps build.
Status improveOverBoxes(const ColorLoopSetup& refinementSetup, const AdaptationOptions& options,
  int cells, int sweepIndex, const std::vector<char>* formerInterface, PartitionMesh& settled,
  AdaptationState& state, AdaptationSummary& summary, PhaseReporter& reporter)
{
  reporter.enter(Phase::Improve);
  const ParallelFor parallelFor = parallelForOn(refinementSetup.threads);
  const BoxLayout layout = layBoxes(state.coordinates, cells, 0.5 * sweepIndex);
  std::vector<PartitionMesh> boxes;
  Status status = regroupIntoBoxes(
    state.partitions, state.coordinates, layout, parallelFor, boxes, formerInterface, &settled);
  if (!status.ok())
  {
    return status;
  }
  state.partitions = std::move(boxes);
  PartitionGraph graph;
  status = buildBoxGraph(state.partitions, state.coordinates, layout, parallelFor, graph);
  std::vector<int> colorOfBox;
  if (status.ok())
  {
    status = colorPartitions(graph, options.coloring, refinementSetup.threads, colorOfBox);
  }
  if (!status.ok())
  {
    return status;
  }
  ColorLoopSetup sweep = refinementSetup;
  sweep.graph = &graph;
  sweep.colorOfPartition = &colorOfBox;
  sweep.numberOfColors = countColors(colorOfBox);
  sweep.numberOfIterations = 1;
  sweep.refine = false;
  sweep.improve = true;
  sweep.stage = Stage::Sweep;
  sweep.progressStart = 0.5 * sweepIndex;
  sweep.progressEnd = 0.5 * (sweepIndex + 1);
  return runColorLoop(sweep, options, state, summary, reporter);
}

} // namespace

Status improveAcrossFormerInterfaces(const ColorLoopSetup& refinementSetup,
  const AdaptationOptions& options, int boxesPerAxis, const std::vector<char>& formerInterface,
  AdaptationState& state, AdaptationSummary& summary, PhaseReporter& reporter)
{
  if (refinementSetup.improve && summary.poorTets == 0 && !refinementSetup.improvement.coarsen)
  {
    return Status::success(); // improvement in partitions saw no poor tet: no seam to work on
  }
  // Box faces freeze vertices in their turn: a second layout shifted by half a box frees them.
  PartitionMesh settled;
  for (int sweepIndex = 0; sweepIndex < 2; ++sweepIndex)
  {
    Status status = improveOverBoxes(refinementSetup, options, boxesPerAxis, sweepIndex,
      sweepIndex == 0 ? &formerInterface : nullptr, settled, state, summary, reporter);
    if (!status.ok() || summary.aborted)
    {
      return status;
    }
  }
  state.partitions.push_back(std::move(settled));
  return Status::success();
}

} // namespace cgmesh
