#include "ImprovementSweep.h"

#include "ParallelFor.h"
#include "Coloring/PartitionColoring.h"

#include <algorithm>
#include <chrono>
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
      PartitionMesh& target = boxes[box];
      target.tets.push_back(partition.tets[t]);
      target.parentCells.push_back(partition.parentCells[t]);
      if (!partition.regions.empty())
      {
        target.regions.push_back(partition.regions[t]);
      }
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

// One improvement sweep over box partitions of the given layout.
Status improveOverBoxes(const ColorLoopSetup& refinementSetup, const AdaptationOptions& options,
  int cells, double shift, AdaptationState& state, AdaptationResult& result)
{
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
  return runColorLoop(sweep, options, state, result);
}

} // namespace

Status improveAcrossFormerInterfaces(const ColorLoopSetup& refinementSetup,
  const AdaptationOptions& options, int boxes, AdaptationState& state, AdaptationResult& result)
{
  if (result.poorTets == 0)
  {
    return Status::success(); // nothing was below the target: no seam to work on
  }
  const auto start = std::chrono::steady_clock::now();
  const double improveBefore = result.seconds.improve;
  const int cells = std::max(1, static_cast<int>(std::lround(std::cbrt(std::max(1, boxes)))));
  // Box faces freeze vertices in their turn: a second layout shifted by half a box frees them.
  Status status = Status::success();
  for (double shift : { 0.0, 0.5 })
  {
    status = improveOverBoxes(refinementSetup, options, cells, shift, state, result);
    if (!status.ok() || result.aborted)
    {
      break;
    }
  }
  // The sweeps count as improvement, regrouping and colouring included.
  result.seconds.improve =
    improveBefore + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return status;
}

} // namespace cgmesh
