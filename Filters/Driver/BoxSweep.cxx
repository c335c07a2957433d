#include "BoxSweep.h"

#include "Coloring/PartitionColoring.h"
#include "Core/LowestRootSets.h"
#include "ParallelFor.h"

#include <iterator>

namespace cgmesh
{

std::vector<std::size_t> boxOfClusters(const AdaptationState& state, std::vector<char>& flagged,
  const BoxLayout& layout, std::size_t largestCluster, std::size_t holding)
{
  // Union-find with each set's root its lowest point id, so the result does not depend on the
  // order of the unions.
  LowestRootSets<PointId> clusters(flagged.size());
  const std::size_t looked = std::min(holding, state.partitions.size());
  for (std::size_t p = 0; p < looked; ++p)
  {
    const PartitionMesh& partition = state.partitions[p];
    for (const Tet& tet : partition.tets)
    {
      PointId first = -1;
      for (PointId p : tet)
      {
        if (flagged[p])
        {
          first = first < 0 ? clusters.root(p) : clusters.join(first, p);
        }
      }
    }
  }
  std::vector<std::size_t> pointsOfRoot(flagged.size(), 0);
  for (std::size_t p = 0; p < flagged.size(); ++p)
  {
    if (flagged[p])
    {
      ++pointsOfRoot[clusters.root(p)];
    }
  }
  std::vector<std::size_t> box(flagged.size(), 0);
  for (std::size_t p = 0; p < flagged.size(); ++p)
  {
    if (!flagged[p])
    {
      continue;
    }
    const PointId root = clusters.root(p);
    if (pointsOfRoot[root] > largestCluster)
    {
      flagged[p] = 0;
      continue;
    }
    box[p] = layout.boxAt(layout.indexOf(state.coordinates.data() + 3 * root));
  }
  return box;
}

Status runSweepOverBoxes(ColorLoopSetup sweep, const AdaptationOptions& options,
  const BoxLayout& layout, const std::vector<char>& moving, AdaptationState& state,
  AdaptationSummary& summary, PhaseReporter& reporter, std::size_t& boxCount,
  const std::vector<std::size_t>* boxOfMovingPoint, std::size_t holding)
{
  const ParallelFor parallelFor = parallelForOn(sweep.threads);
  // The partitions past `holding` hold no moving tet: set aside unread, put back in order.
  std::vector<PartitionMesh> unread;
  if (holding < state.partitions.size())
  {
    unread.assign(std::make_move_iterator(state.partitions.begin() + holding),
      std::make_move_iterator(state.partitions.end()));
    state.partitions.resize(holding);
  }
  std::vector<PartitionMesh> boxes;
  Status status = regroupIntoBoxes(
    state.partitions, state.coordinates, layout, parallelFor, boxes, &moving, boxOfMovingPoint);
  if (!status.ok())
  {
    std::move(unread.begin(), unread.end(), std::back_inserter(state.partitions));
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
    // Interface points known for the partitions before are not the boxes'.
    sweep.interfaceVertexAtStart = nullptr;
    sweep.interfaceVertexAtEnd = nullptr;
    status = runColorLoop(sweep, options, state, summary, reporter);
  }
  for (std::vector<PartitionMesh>* rest : { &staying, &unread })
  {
    std::copy_if(std::make_move_iterator(rest->begin()), std::make_move_iterator(rest->end()),
      std::back_inserter(state.partitions),
      [](const PartitionMesh& partition) { return !partition.tets.empty(); });
  }
  state.improvementLeft.resize(state.partitions.size()); // the staying ones: unknown
  return status;
}

} // namespace cgmesh
