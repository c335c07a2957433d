#include "ImprovementSweep.h"

#include "Coloring/PartitionColoring.h"
#include "ParallelFor.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cgmesh
{
namespace
{

// Splits the bounding box into cells x cells x cells boxes; a tet goes to the box of its centroid.
std::vector<PartitionMesh> regroupIntoBoxes(std::vector<PartitionMesh>& partitions,
  const std::vector<double>& coordinates, int cells, double shift)
{
  double low[3], size[3];
  for (int axis = 0; axis < 3; ++axis)
  {
    double lowest = std::numeric_limits<double>::max(), highest = -lowest;
    for (std::size_t p = axis; p < coordinates.size(); p += 3)
    {
      lowest = std::min(lowest, coordinates[p]);
      highest = std::max(highest, coordinates[p]);
    }
    size[axis] = highest > lowest ? (highest - lowest) / cells : 1.0;
    low[axis] = lowest - shift * size[axis];
  }
  // One more box per axis than cells, for the shifted layout's far ends.
  std::vector<PartitionMesh> boxes(static_cast<std::size_t>(cells + 1) * (cells + 1) * (cells + 1));
  for (PartitionMesh& partition : partitions)
  {
    for (std::size_t t = 0; t < partition.tets.size(); ++t)
    {
      std::size_t box = 0;
      for (int axis = 2; axis >= 0; --axis)
      {
        double centroid = 0;
        for (PointId p : partition.tets[t])
        {
          centroid += 0.25 * coordinates[3 * p + axis];
        }
        const int index = std::max(
          0, std::min(cells, static_cast<int>(std::floor((centroid - low[axis]) / size[axis]))));
        box = box * (cells + 1) + index;
      }
      appendTetOf(partition, t, boxes[box]);
    }
    partition = PartitionMesh();
  }
  return boxes;
}

PartitionGraph graphOfPartitions(const std::vector<PartitionMesh>& partitions, PointId points)
{
  std::vector<Tet> tets;
  std::vector<int> partitionOfCell;
  for (std::size_t p = 0; p < partitions.size(); ++p)
  {
    tets.insert(tets.end(), partitions[p].tets.begin(), partitions[p].tets.end());
    partitionOfCell.insert(partitionOfCell.end(), partitions[p].tets.size(), static_cast<int>(p));
  }
  return buildPartitionGraph(tets, partitionOfCell, static_cast<int>(partitions.size()), points);
}

// One improvement sweep over box partitions; `sweepIndex` 0 lays the boxes from the bounding
// box's corner, 1 shifts them by half a box.
Status improveOverBoxes(const ColorLoopSetup& refinementSetup, const AdaptationOptions& options,
  int cells, int sweepIndex, AdaptationState& state, AdaptationSummary& summary,
  PhaseReporter& reporter)
{
  reporter.enter(Phase::Improve);
  const double shift = 0.5 * sweepIndex;
  state.partitions = regroupIntoBoxes(state.partitions, state.coordinates, cells, shift);
  const PartitionGraph graph =
    graphOfPartitions(state.partitions, static_cast<PointId>(state.coordinates.size() / 3));
  std::vector<int> colorOfBox;
  Status status = colorPartitions(graph, options.coloring, refinementSetup.threads, colorOfBox);
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

// Moves the tets that touch no former interface vertex out of the partitions, into one mesh of
// their own: the sweeps have nothing to do there (refinement already improved them, or TetGen
// met its bound), and leaving them out halves what the sweeps build.
PartitionMesh setAsideSettledTets(
  std::vector<PartitionMesh>& partitions, const std::vector<char>& formerInterface)
{
  PartitionMesh settled;
  for (PartitionMesh& partition : partitions)
  {
    PartitionMesh seam;
    for (std::size_t t = 0; t < partition.tets.size(); ++t)
    {
      appendTetOf(
        partition, t, touchesFlaggedPoint(partition.tets[t], formerInterface) ? seam : settled);
    }
    partition = std::move(seam);
  }
  return settled;
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
  reporter.enter(Phase::Improve);
  PartitionMesh settled = setAsideSettledTets(state.partitions, formerInterface);
  // Box faces freeze vertices in their turn: a second layout shifted by half a box frees them.
  for (int sweepIndex = 0; sweepIndex < 2; ++sweepIndex)
  {
    Status status = improveOverBoxes(
      refinementSetup, options, boxesPerAxis, sweepIndex, state, summary, reporter);
    if (!status.ok() || summary.aborted)
    {
      return status;
    }
  }
  state.partitions.push_back(std::move(settled));
  return Status::success();
}

} // namespace cgmesh
