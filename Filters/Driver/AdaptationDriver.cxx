#include "AdaptationDriver.h"

#include "ColorLoop.h"
#include "Coloring/ColoringSupport.h"
#include "Core/Geometry.h"
#include "ImprovementSweep.h"
#include "Validation/InputPreparation.h"
#include "Partitioning/MeshPartitioner.h"
#include "ParallelFor.h"
#include "Coloring/PartitionColoring.h"
#include "TetGenWorkers.h"

#include <memory>
#include <mutex>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <new>
#include <string>

namespace cgmesh
{
namespace
{

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

Status validateInput(const TetMesh& input, const AdaptationOptions& options)
{
  if (input.coordinates.size() % 3 != 0)
  {
    return Status::failure("point coordinates are not a multiple of three values");
  }
  if (input.hasRegions() && input.regions.size() != input.tets.size())
  {
    return Status::failure("the region array does not have one value per tet");
  }
  const PointId pointCount = input.numberOfPoints();
  for (const Tet& tet : input.tets)
  {
    for (PointId p : tet)
    {
      if (p < 0 || p >= pointCount)
      {
        return Status::failure("a tet references point " + std::to_string(p) +
          " but the mesh has " + std::to_string(pointCount) + " points");
      }
    }
  }
  if (options.numberOfIterations < 0)
  {
    return Status::failure("the number of iterations must not be negative");
  }
  if (!options.partitionByRegion && options.numberOfPartitions < 1)
  {
    return Status::failure("the number of partitions must be at least 1");
  }
  if (options.partitionByRegion && !input.hasRegions() && !input.tets.empty())
  {
    return Status::failure("partitioning by region needs a region array");
  }
  if (options.method == RefinementMethod::Template && !(options.maximumEdgeLength > 0) &&
    !(options.edgeLengthFactor > 0))
  {
    return Status::failure("set a positive maximum edge length or edge length factor");
  }
  if (options.method == RefinementMethod::Delaunay)
  {
    if (!(options.maximumVolume > 0) && !(options.volumeFactor > 0))
    {
      return Status::failure("set a positive maximum volume or volume factor");
    }
    if (!(options.radiusEdgeRatio >= 1.0))
    {
      return Status::failure("the radius-edge ratio bound must be at least 1");
    }
  }
  return Status::success();
}

// Mean over the six edges of every tet (shared edges count once per tet, which weighs edges by
// how many tets use them and needs no edge list).
double meanTetEdgeLength(const TetMesh& mesh)
{
  double sum = 0;
  for (const Tet& tet : mesh.tets)
  {
    for (const auto& edge : TetEdgeCorners)
    {
      sum += std::sqrt(squaredEdgeLength(mesh, tet[edge[0]], tet[edge[1]]));
    }
  }
  return mesh.tets.empty() ? 0 : sum / (6.0 * static_cast<double>(mesh.tets.size()));
}

double meanTetVolume(const TetMesh& mesh)
{
  double sum = 0;
  for (const Tet& tet : mesh.tets)
  {
    sum += std::abs(signedVolume6(mesh, tet)) / 6.0;
  }
  return mesh.tets.empty() ? 0 : sum / static_cast<double>(mesh.tets.size());
}

// Flags output tets (in merge order: partition by partition) that touch a former interface vertex.
void markNearFormerInterface(const std::vector<PartitionMesh>& partitions,
  const std::vector<char>& formerInterface, AdaptationResult& result)
{
  result.nearFormerInterface.clear();
  for (const PartitionMesh& partition : partitions)
  {
    for (const Tet& tet : partition.tets)
    {
      bool near = false;
      for (PointId p : tet)
      {
        near = near || (p < static_cast<PointId>(formerInterface.size()) && formerInterface[p]);
      }
      result.nearFormerInterface.push_back(near ? 1 : 0);
    }
  }
}

void distributeTets(
  const TetMesh& input, const std::vector<int>& partitionOfCell, AdaptationState& state)
{
  for (CellId t = 0; t < input.numberOfTets(); ++t)
  {
    PartitionMesh& partition = state.partitions[partitionOfCell[t]];
    partition.tets.push_back(input.tets[t]);
    partition.parentCells.push_back(t);
    if (input.hasRegions())
    {
      partition.regions.push_back(input.regions[t]);
    }
  }
  state.coordinates = input.coordinates;
  state.inputPointCount = input.numberOfPoints();
}

Status partitionAndColor(const TetMesh& input, const AdaptationOptions& options,
  std::vector<int>& partitionOfCell, PartitionGraph& graph, std::vector<int>& colorOfPartition,
  AdaptationResult& result)
{
  auto start = Clock::now();
  Status status = options.partitionByRegion
    ? partitionByRegion(
        input, options.partitionsPerRegion, partitionOfCell, result.numberOfPartitions)
    : partitionMesh(input, result.numberOfPartitions, partitionOfCell);
  result.seconds.partition = secondsSince(start);
  if (!status.ok())
  {
    return status;
  }

  start = Clock::now();
  graph = buildPartitionGraph(
    input.tets, partitionOfCell, result.numberOfPartitions, input.numberOfPoints());
  result.seconds.graph = secondsSince(start);

  start = Clock::now();
  status = colorPartitions(graph, options.coloring, result.numberOfThreads, colorOfPartition);
  result.seconds.color = secondsSince(start);
  result.numberOfColors = countColors(colorOfPartition);
  result.colorOfPartition = colorOfPartition;
  result.partitionsPerColor = colorSizes(colorOfPartition, result.numberOfColors);
  if (result.numberOfColors > 0)
  {
    const double mean = static_cast<double>(result.numberOfPartitions) / result.numberOfColors;
    result.colorBalance =
      *std::max_element(result.partitionsPerColor.begin(), result.partitionsPerColor.end()) / mean;
  }
  return status;
}

// The colour loop's set-up for refinement (the template table is built once per process, about
// 30 ms, and never changed afterwards).
ColorLoopSetup refinementSetup(const AdaptationOptions& options, const AdaptationResult& result,
  const PartitionGraph& graph, const std::vector<int>& colorOfPartition)
{
  static const TemplateTable templates;
  ColorLoopSetup setup;
  setup.graph = &graph;
  setup.colorOfPartition = &colorOfPartition;
  setup.numberOfColors = result.numberOfColors;
  setup.numberOfIterations = options.numberOfIterations;
  setup.threads = result.numberOfThreads;
  setup.squaredThreshold = result.edgeLengthThreshold * result.edgeLengthThreshold;
  setup.templates = &templates;
  setup.method = options.method;
  setup.delaunay.maximumVolume = result.volumeBound;
  setup.delaunay.radiusEdgeRatio = options.radiusEdgeRatio;
  setup.maximumNumberOfCells = options.maximumNumberOfCells;
  setup.improve = options.improveQuality;
  setup.improvement.passes = options.improvementPasses;
  // Improvement must not undo Delaunay refinement's volume bound.
  setup.improvement.maximumVolume =
    options.method == RefinementMethod::Delaunay ? result.volumeBound : 0.0;
  return setup;
}

// TetGen calls go to one worker process per thread (or one, serialised, on request).
void attachTetGen(const AdaptationOptions& options, ColorLoopSetup& setup, AdaptationResult& result,
  std::unique_ptr<TetGenWorkerPool>& workers, std::mutex& serialTetGen)
{
  const bool serialize = options.serializeTetGen;
  workers = std::make_unique<TetGenWorkerPool>(serialize ? 1 : result.numberOfThreads);
  result.concurrentTetGen = !serialize && result.numberOfThreads > 1;
  TetGenWorkerPool* pool = workers.get();
  setup.runTetGen = [pool, serialize, &serialTetGen](
                      const tetgenio& in, const std::string& switches, tetgenio& out)
  {
    if (serialize)
    {
      std::lock_guard<std::mutex> lock(serialTetGen);
      return pool->run(0, in, switches, out);
    }
    return pool->run(currentThreadIndex(), in, switches, out);
  };
}

void adoptMergedMesh(MergedMesh& merged, const std::vector<int>& partitionOfInputCell,
  const std::vector<int>& colorOfPartition, AdaptationResult& result)
{
  result.mesh = std::move(merged.mesh);
  result.parentCell = std::move(merged.parentCell);
  result.provenance = std::move(merged.provenance);
  // A tet was refined by the partition of the input tet it comes from (the improvement sweep
  // regroups tets but refines nothing).
  result.partitionOfCell.resize(result.parentCell.size());
  result.colorOfCell.resize(result.parentCell.size());
  result.cellsPerColor.assign(result.numberOfColors, 0);
  for (std::size_t t = 0; t < result.partitionOfCell.size(); ++t)
  {
    result.partitionOfCell[t] = partitionOfInputCell[result.parentCell[t]];
    result.colorOfCell[t] = colorOfPartition[result.partitionOfCell[t]];
    ++result.cellsPerColor[result.colorOfCell[t]];
  }
  if (merged.removedPoints > 0)
  {
    result.warnings.push_back(
      "removed " + std::to_string(merged.removedPoints) + " points that no tetrahedron uses");
  }
}

Status runPipeline(const TetMesh& input, const AdaptationOptions& options, AdaptationResult& result)
{
  std::vector<int> partitionOfCell;
  PartitionGraph graph;
  std::vector<int> colorOfPartition;
  Status status =
    partitionAndColor(input, options, partitionOfCell, graph, colorOfPartition, result);
  if (!status.ok())
  {
    return status;
  }
  if (options.progress)
  {
    options.progress(0.1, "partitioned");
  }

  AdaptationState state;
  state.partitions.resize(result.numberOfPartitions);
  distributeTets(input, partitionOfCell, state);
  ColorLoopSetup setup = refinementSetup(options, result, graph, colorOfPartition);
  std::unique_ptr<TetGenWorkerPool> tetgenWorkers;
  std::mutex serialTetGen;
  if (options.method == RefinementMethod::Delaunay)
  {
    attachTetGen(options, setup, result, tetgenWorkers, serialTetGen);
  }
  status = runColorLoop(setup, options, state, result);
  tetgenWorkers.reset();
  if (!status.ok() || result.aborted)
  {
    return status;
  }
  const std::vector<char> formerInterface =
    findInterfaceVertices(state.partitions, static_cast<PointId>(state.coordinates.size() / 3));
  if (options.improveQuality)
  {
    status =
      improveAcrossFormerInterfaces(setup, options, result.numberOfPartitions, state, result);
    if (!status.ok() || result.aborted)
    {
      return status;
    }
  }
  markNearFormerInterface(state.partitions, formerInterface, result);

  const auto start = Clock::now();
  MergedMesh merged;
  status = mergePartitions(state.partitions, state.coordinates, state.inputPointCount,
    state.newPointSources, merged, RelocationInput{ &input, &state.movedPoints });
  state = AdaptationState();
  result.seconds.merge = secondsSince(start);
  if (!status.ok())
  {
    return status;
  }
  adoptMergedMesh(merged, partitionOfCell, colorOfPartition, result);
  return Status::success();
}

void reportRepairs(const InputRepairs& repairs, AdaptationResult& result)
{
  result.reorientedTets = repairs.reorientedTets;
  result.mergedPoints = repairs.mergedPoints;
  if (repairs.reorientedTets > 0)
  {
    result.warnings.push_back("turned around " + std::to_string(repairs.reorientedTets) +
      " inverted tetrahedra: the output is consistently positively oriented");
  }
  if (repairs.mergedPoints > 0)
  {
    result.warnings.push_back("merged " + std::to_string(repairs.mergedPoints) +
      " points that repeat another point's coordinates: parts touching without shared nodes are "
      "joined");
  }
}

} // namespace

Status adaptMesh(
  const TetMesh& rawInput, const AdaptationOptions& options, AdaptationResult& result)
{
  const auto start = Clock::now();
  result = AdaptationResult();
  Status status = validateInput(rawInput, options);
  if (!status.ok())
  {
    return status;
  }
  TetMesh input;
  InputRepairs repairs;
  status = prepareInput(rawInput, input, repairs);
  if (!status.ok())
  {
    return status;
  }
  reportRepairs(repairs, result);
  result.numberOfThreads = resolveThreadCount(options.numberOfThreads);
  if (options.method == RefinementMethod::Delaunay)
  {
    result.volumeBound = options.maximumVolume > 0 ? options.maximumVolume
                                                   : options.volumeFactor * meanTetVolume(input);
    result.edgeLengthThreshold = interfaceEdgeLengthForVolume(result.volumeBound);
  }
  else
  {
    result.edgeLengthThreshold = options.maximumEdgeLength > 0
      ? options.maximumEdgeLength
      : options.edgeLengthFactor * meanTetEdgeLength(input);
  }
  result.numberOfPartitions = options.numberOfPartitions;
  if (!options.partitionByRegion && input.numberOfTets() > 0 &&
    options.numberOfPartitions > input.numberOfTets())
  {
    result.numberOfPartitions = static_cast<int>(input.numberOfTets());
    result.warnings.push_back("requested " + std::to_string(options.numberOfPartitions) +
      " partitions for " + std::to_string(input.numberOfTets()) + " tetrahedra; using " +
      std::to_string(result.numberOfPartitions));
  }
  else if (input.numberOfTets() == 0)
  {
    result.numberOfPartitions = 1;
  }

  try
  {
    status = runPipeline(input, options, result);
  }
  catch (const std::bad_alloc&)
  {
    status = Status::failure("out of memory");
  }
  catch (const std::exception& error)
  {
    status = Status::failure(error.what());
  }
  if (!status.ok() || result.aborted)
  {
    const bool aborted = result.aborted;
    auto warnings = std::move(result.warnings);
    result = AdaptationResult();
    result.aborted = aborted;
    result.warnings = std::move(warnings);
  }
  result.seconds.total = secondsSince(start);
  if (options.progress)
  {
    options.progress(1.0, "done");
  }
  return status;
}

} // namespace cgmesh
