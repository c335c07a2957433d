#include "ImprovementSweep.h"

#include "ParallelFor.h"
#include "PartitionColoring.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace cgmesh
{
namespace
{

// Splits the bounding box into cells x cells x cells boxes; a tet goes to the box of its centroid.
std::vector<PartitionMesh> regroupIntoBoxes(
  std::vector<PartitionMesh>& partitions, const std::vector<double>& coordinates, int cells)
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
    low[axis] = lowest;
    size[axis] = highest > lowest ? (highest - lowest) / cells : 1.0;
  }
  std::vector<PartitionMesh> boxes(static_cast<std::size_t>(cells) * cells * cells);
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
        const int index = std::max(0,
          std::min(cells - 1, static_cast<int>(std::floor((centroid - low[axis]) / size[axis]))));
        box = box * cells + index;
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

} // namespace

Status improveAcrossFormerInterfaces(const ColorLoopSetup& refinementSetup,
  const AdaptationOptions& options, int boxes, AdaptationState& state, AdaptationResult& result)
{
  const auto start = std::chrono::steady_clock::now();
  const int cells = std::max(1, static_cast<int>(std::lround(std::cbrt(std::max(1, boxes)))));
  state.partitions = regroupIntoBoxes(state.partitions, state.coordinates, cells);
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
  const double improveBefore = result.seconds.improve;
  status = runColorLoop(sweep, options, state, result);
  // The whole sweep counts as improvement (regrouping and colouring included).
  result.seconds.improve =
    improveBefore + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return status;
}

} // namespace cgmesh
