#include "InputImprovement.h"

#include "ImprovementSweep.h"
#include "ParallelFor.h"
#include "Refinement/PartitionRefiner.h"

namespace cgmesh
{
namespace
{

// Every tet to the partition of the input cell it comes from, in (box, tet) order.
void returnTetsToPartitions(
  AdaptationState& state, const std::vector<int>& partitionOfCell, int partitions)
{
  std::vector<PartitionMesh> returned(static_cast<std::size_t>(partitions));
  for (PartitionMesh& from : state.partitions)
  {
    for (std::size_t t = 0; t < from.tets.size(); ++t)
    {
      appendTetOf(from, t, returned[partitionOfCell[from.parentCells[t]]]);
    }
    from = PartitionMesh();
  }
  state.partitions = std::move(returned);
}

} // namespace

bool improvesInputFirst(const AdaptationOptions& options, const AdaptationPlan& plan)
{
  return options.improveInput && options.improveQuality &&
    options.method == RefinementMethod::Template && !plan.restricted();
}

Status improveInputFirst(const AdaptationOptions& options, const std::vector<int>& partitionOfCell,
  PartitionGraph& graph, ColorLoopSetup& setup, AdaptationState& state, AdaptationSummary& summary,
  PhaseReporter& reporter)
{
  ColorLoopSetup improveOnly = setup;
  improveOnly.refine = false;
  improveOnly.improve = true;
  improveOnly.improvement.coarsen = false; // sizes are for the refined mesh
  improveOnly.numberOfIterations = 1;
  improveOnly.stage = Stage::ImproveInput;
  improveOnly.progressStart = 0;
  improveOnly.progressEnd = 0.5;
  const std::int64_t poorBefore = summary.poorTets;
  Status status = runColorLoop(improveOnly, options, state, summary, reporter);
  if (!status.ok() || summary.aborted)
  {
    return status;
  }
  if (summary.poorTets == poorBefore)
  {
    return Status::success(); // no tet below the target: nothing changed
  }
  std::vector<char> formerInterface;
  status =
    findInterfaceVertices(state.partitions, static_cast<PointId>(state.coordinates.size() / 3),
      parallelForOn(setup.threads), formerInterface);
  if (!status.ok())
  {
    return status;
  }
  improveOnly.progressStart = 0.5;
  improveOnly.progressEnd = 1;
  status = improveAcrossFormerInterfaces(
    improveOnly, options, summary.plan.boxesPerAxis, formerInterface, state, summary, reporter);
  if (!status.ok() || summary.aborted)
  {
    return status;
  }
  returnTetsToPartitions(state, partitionOfCell, summary.plan.partitions);

  reporter.enter(Phase::Graph);
  status = buildPartitionGraph(state.partitions, static_cast<PointId>(state.coordinates.size() / 3),
    parallelForOn(setup.threads), graph);
  if (!status.ok())
  {
    return status;
  }
  summary.interfacePoints = graph.interfacePoints;
  reporter.enter(Phase::Color);
  status = colorPartitions(graph, options.coloring, setup.threads, summary.colorOfPartition);
  if (!status.ok())
  {
    return status;
  }
  summarizeColoring(summary);
  setup.numberOfColors = summary.numberOfColors;
  reporter.progress(Stage::ImproveInput, 1.0);
  return Status::success();
}

} // namespace cgmesh
