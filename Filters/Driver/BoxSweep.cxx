#include "BoxSweep.h"

#include "Coloring/PartitionColoring.h"
#include "ParallelFor.h"

#include <iterator>

namespace cgmesh
{

Status runSweepOverBoxes(ColorLoopSetup sweep, const AdaptationOptions& options,
  const BoxLayout& layout, const std::vector<char>& moving, AdaptationState& state,
  AdaptationSummary& summary, PhaseReporter& reporter, std::size_t& boxCount,
  const std::vector<std::size_t>* boxOfMovingPoint)
{
  const ParallelFor parallelFor = parallelForOn(sweep.threads);
  std::vector<PartitionMesh> boxes;
  Status status = regroupIntoBoxes(
    state.partitions, state.coordinates, layout, parallelFor, boxes, &moving, boxOfMovingPoint);
  if (!status.ok())
  {
    return status;
  }
  std::vector<PartitionMesh> staying = std::move(state.partitions);
  state.partitions = std::move(boxes);
  state.improvementLeft.assign(state.partitions.size(), ImprovementLeft());
  boxCount = state.partitions.size();
  PartitionGraph graph;
  status = buildBoxGraph(state.partitions, state.coordinates, layout, parallelFor, graph);
  std::vector<int> colorOfBox;
  if (status.ok())
  {
    status = colorPartitions(graph, options.coloring, sweep.threads, colorOfBox);
  }
  if (status.ok())
  {
    sweep.colorOfPartition = &colorOfBox;
    sweep.numberOfColors = countColors(colorOfBox);
    sweep.numberOfIterations = 1;
    status = runColorLoop(sweep, options, state, summary, reporter);
  }
  std::copy_if(std::make_move_iterator(staying.begin()), std::make_move_iterator(staying.end()),
    std::back_inserter(state.partitions),
    [](const PartitionMesh& partition) { return !partition.tets.empty(); });
  state.improvementLeft.resize(state.partitions.size()); // the staying ones: unknown
  return status;
}

} // namespace cgmesh
