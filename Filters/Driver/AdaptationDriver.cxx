#include "AdaptationDriver.h"

#include "AbortWatch.h"
#include "ColorLoop.h"
#include "Coloring/ColoringSupport.h"
#include "Coloring/PartitionColoring.h"
#include "ImprovementSweep.h"
#include "InputImprovement.h"
#include "ParallelFor.h"
#include "Partitioning/CurveChunkPartitioner.h"
#include "Partitioning/HilbertPartitioner.h"
#include "Partitioning/MeshPartitioner.h"
#include "Refinement/SizeField.h"
#include "RemeshSweep.h"
#include "Validation/InputPreparation.h"
#include "WorkerPool.h"

#include <algorithm>
#include <iomanip>
#include <memory>
#include <mutex>
#include <new>
#include <sstream>
#include <string>

namespace cgmesh
{
namespace
{

// Flags output tets (in merge order: partition by partition) that touch a former interface vertex.
Status markNearFormerInterface(const std::vector<PartitionMesh>& partitions,
  const std::vector<char>& formerInterface, int threads, std::vector<char>& near)
{
  std::vector<std::size_t> first(partitions.size() + 1, 0);
  for (std::size_t p = 0; p < partitions.size(); ++p)
  {
    first[p + 1] = first[p] + partitions[p].tets.size();
  }
  near.assign(first.back(), 0);
  return runParallel(threads, static_cast<std::int64_t>(partitions.size()),
    [&](std::int64_t p)
    {
      for (std::size_t t = 0; t < partitions[p].tets.size(); ++t)
      {
        near[first[p] + t] = touchesFlaggedPoint(partitions[p].tets[t], formerInterface) ? 1 : 0;
      }
    });
}

// Every input tet to its partition, in input order: a counting sort of the tet ids by partition,
// then each partition copies its own tets.
Status distributeTets(const TetMesh& input, const std::vector<int>& partitionOfCell, int threads,
  AdaptationState& state)
{
  const std::size_t partitions = state.partitions.size();
  std::vector<CellId> first(partitions + 1, 0);
  for (const int p : partitionOfCell)
  {
    ++first[p + 1];
  }
  for (std::size_t p = 0; p < partitions; ++p)
  {
    first[p + 1] += first[p];
  }
  std::vector<CellId> tetsByPartition(partitionOfCell.size());
  {
    std::vector<CellId> next(first.begin(), first.end() - 1);
    for (CellId t = 0; t < input.numberOfTets(); ++t)
    {
      tetsByPartition[next[partitionOfCell[t]]++] = t;
    }
  }
  state.coordinates = input.coordinates;
  state.sizes = input.sizes;
  state.inputPointCount = input.numberOfPoints();
  return runParallel(threads, static_cast<std::int64_t>(partitions),
    [&](std::int64_t p)
    {
      PartitionMesh& partition = state.partitions[p];
      const std::size_t count = static_cast<std::size_t>(first[p + 1] - first[p]);
      partition.tets.resize(count);
      partition.parentCells.assign(
        tetsByPartition.begin() + first[p], tetsByPartition.begin() + first[p + 1]);
      partition.regions.resize(input.hasRegions() ? count : 0);
      for (std::size_t k = 0; k < count; ++k)
      {
        const CellId t = partition.parentCells[k];
        partition.tets[k] = input.tets[t];
        if (input.hasRegions())
        {
          partition.regions[k] = input.regions[t];
        }
      }
    });
}

// METIS for the chunks of the curve-chunk partitioner: in worker processes when there are any
// (METIS' random draws are process-wide), else here, one call at a time. A chunk whose worker
// failed is cut here: the same result.
GraphPartitioner metisForChunks(WorkerPool* workers)
{
  return [workers](const DualGraph& graph, int parts, std::vector<int>& partOfVertex)
  {
    if (workers &&
      workers->partitionGraph(currentThreadIndex(), graph, parts, false, partOfVertex).empty())
    {
      return Status::success();
    }
    static std::mutex oneCallAtATime;
    std::lock_guard<std::mutex> lock(oneCallAtATime);
    return partitionGraphWithMetis(graph, parts, partOfVertex, false);
  };
}

Status partitionAndColor(const TetMesh& input, const AdaptationOptions& options,
  WorkerPool* workers, std::vector<int>& partitionOfCell, PartitionGraph& graph,
  AdaptationSummary& summary, PhaseReporter& reporter)
{
  const AdaptationPlan& plan = summary.plan;
  reporter.enter(Phase::Partition);
  int partitions = plan.partitions;
  // A size field, refinement regions or a box make some tets' output many times others': the
  // partitions balance the forecast work then, not the input tets.
  const TetWeights weights = input.hasSizes() ? forecastWeights(input) : TetWeights();
  const TetWeights* balance = weights.empty() ? nullptr : &weights;
  PartitioningOptions partitioning;
  partitioning.tetWeights = balance;
  // Connected parts cost METIS about half its time for nothing measurable: 0.03% more tets on
  // the Delaunay Big cube without them, 1.3 s less partitioning on the 844k-tet FinFET.
  partitioning.contiguous = false;
  Status status = Status::success();
  if (options.partitionByRegion)
  {
    status = partitionByRegion(
      input, options.partitionsPerRegion, partitionOfCell, partitions, parallelForOn(plan.threads));
  }
  else if (plan.partitioner == PartitionerKind::Hilbert)
  {
    status = partitionAlongHilbertCurve(
      input, plan.partitions, partitionOfCell, parallelForOn(plan.threads), balance);
  }
  else if (plan.partitioner == PartitionerKind::CurveChunks &&
    curveChunkCount(input.numberOfTets(), plan.partitions) > 1)
  {
    const int chunks = curveChunkCount(input.numberOfTets(), plan.partitions);
    status = partitionInCurveChunks(input, plan.partitions, chunks, metisForChunks(workers),
      partitionOfCell, parallelForOn(plan.threads), balance);
  }
  else
  {
    status = partitionMesh(
      input, plan.partitions, partitionOfCell, partitioning, parallelForOn(plan.threads));
  }
  if (!status.ok())
  {
    return status;
  }
  if (partitions != plan.partitions)
  {
    return Status::failure(ErrorKind::Internal,
      "partitioning made " + std::to_string(partitions) + " partitions, the plan " +
        std::to_string(plan.partitions));
  }
  reporter.progress(Stage::Partition, 0.8);

  reporter.enter(Phase::Graph);
  status = buildPartitionGraph(input.tets, partitionOfCell, plan.partitions, input.numberOfPoints(),
    parallelForOn(plan.threads), graph);
  if (!status.ok())
  {
    return status;
  }
  summary.interfacePoints = graph.interfacePoints;
  reporter.progress(Stage::Partition, 0.9);

  reporter.enter(Phase::Color);
  status = colorPartitions(graph, options.coloring, plan.threads, summary.colorOfPartition);
  if (!status.ok())
  {
    return status;
  }
  summarizeColoring(summary);
  reporter.progress(Stage::Partition, 1.0);
  return Status::success();
}

// The template table is read once per process from the templates compiled in, and checked, and
// never changed afterwards.
const TemplateTable& templateTable()
{
  static const TemplateTable templates(compiledTemplateData());
  return templates;
}

ColorLoopSetup refinementSetup(const AdaptationOptions& options, const AdaptationSummary& summary)
{
  const AdaptationPlan& plan = summary.plan;
  ColorLoopSetup setup;
  setup.colorOfPartition = &summary.colorOfPartition;
  setup.numberOfColors = summary.numberOfColors;
  // TetGen meets a size field inside each partition in one call, and the interface edges are
  // split to it before: a second pass added 0.2% of the points of the first on the graded Big
  // cube, at 1.4 times its cost.
  const bool delaunayToSizes = options.method == RefinementMethod::Delaunay && plan.sizeField;
  setup.numberOfIterations = delaunayToSizes ? 1 : options.numberOfIterations;
  setup.threads = plan.threads;
  setup.squaredThreshold = plan.edgeLengthThreshold * plan.edgeLengthThreshold;
  setup.templates = &templateTable();
  setup.orderCornersByCoordinates = options.orderCornersByCoordinates;
  setup.method = options.method;
  setup.delaunay.maximumVolume = plan.volumeBound;
  setup.delaunay.radiusEdgeRatio = options.radiusEdgeRatio;
  setup.maximumNumberOfCells = options.maximumNumberOfCells;
  // Delaunay partitions under a volume bound are not improved on their own: TetGen's interiors
  // are good and their poor tets lie on the frozen interfaces, which the box sweeps reach anyway.
  // Measured on the Big cube (94 partitions, 2 threads): the same quality (minimum dihedral p1
  // 21.0 against 20.8 degrees, edge ratio p99 3.00 against 2.98) in 19% less time. With a size
  // field TetGen refuses quality splits inside its points' size balls, so its interiors are
  // poorer and are improved (and coarsened) as templates' are: on the graded Big cube, minimum
  // dihedral p1 15.7 degrees without, 22.3 with, and 92.0% of edges within the field's bounds
  // instead of 90.1%.
  const bool templates = options.method == RefinementMethod::Template;
  setup.improvement.improve = options.improveQuality;
  setup.improvement.coarsen = options.coarsen && plan.sizeField;
  setup.sizeField = plan.sizeField;
  setup.improve =
    (options.improveQuality || setup.improvement.coarsen) && (templates || plan.sizeField);
  setup.improvement.passes = options.improvementPasses;
  setup.improvement.maximumVolume = plan.improvementVolumeBound;
  return setup;
}

// The pool's TetGen calls end early when the run is aborted (options.abortRequested is the
// run's AbortWatch, safe on any thread).
void cutShortOnAbort(WorkerPool& pool, const AdaptationOptions& options)
{
  if (options.abortRequested)
  {
    pool.setAbortCheck([abortRequested = options.abortRequested] { return !abortRequested(); });
  }
}

// Worker processes, forked before any parallel loop of the run: one per thread for the Delaunay
// method's TetGen calls (or one, serialised, on request), and for the curve-chunk partitioner's
// METIS calls when there are chunks and threads to run them at once. None otherwise.
std::unique_ptr<WorkerPool> startWorkers(
  const TetMesh& input, const AdaptationOptions& options, const AdaptationPlan& plan)
{
  if (options.method == RefinementMethod::Delaunay)
  {
    auto pool = std::make_unique<WorkerPool>(options.serializeTetGen ? 1 : plan.threads);
    cutShortOnAbort(*pool, options);
    return pool;
  }
  if (plan.partitioner == PartitionerKind::CurveChunks && !options.partitionByRegion &&
    plan.threads > 1 && curveChunkCount(input.numberOfTets(), plan.partitions) > 1)
  {
    return std::make_unique<WorkerPool>(plan.threads);
  }
  return nullptr;
}

// TetGen calls go to the worker of the calling thread (or to the first, serialised, on request
// or when the pool has one worker): a worker serves one call at a time, the others waiting for
// their turn (WorkerPool).
void attachTetGen(const AdaptationOptions& options, ColorLoopSetup& setup,
  AdaptationSummary& summary, WorkerPool* pool, bool oneWorker = false)
{
  const bool serialize = options.serializeTetGen || oneWorker;
  summary.concurrentTetGen = !serialize && summary.plan.threads > 1;
  setup.runTetGen = [pool, serialize](
                      int partition, const tetgenio& in, const std::string& switches, tetgenio& out)
  {
    return pool->runTetGen(serialize ? 0 : currentThreadIndex(), in, switches, out, partition);
  };
}

Status adoptMergedMesh(
  MergedMesh& merged, const std::vector<int>& partitionOfInputCell, AdaptationResult& result)
{
  AdaptationSummary& summary = result.summary;
  result.mesh = std::move(merged.mesh);
  result.parentCell = std::move(merged.parentCell);
  result.provenance = std::move(merged.provenance);
  // A tet was refined by the partition of the input tet it comes from (the improvement sweep
  // regroups tets but refines nothing). Cells per colour are counted per range, then summed.
  const std::int64_t tets = static_cast<std::int64_t>(result.parentCell.size());
  result.partitionOfCell.resize(tets);
  result.colorOfCell.resize(tets);
  const std::int64_t ranges = (tets + IndicesPerCopyRange - 1) / IndicesPerCopyRange;
  std::vector<std::vector<std::int64_t>> cellsPerColorOfRange(
    ranges, std::vector<std::int64_t>(summary.numberOfColors, 0));
  const Status status = forEachRange(parallelForOn(summary.plan.threads), tets, IndicesPerCopyRange,
    [&](std::int64_t begin, std::int64_t end)
    {
      std::vector<std::int64_t>& cellsPerColor = cellsPerColorOfRange[begin / IndicesPerCopyRange];
      for (std::int64_t t = begin; t < end; ++t)
      {
        result.partitionOfCell[t] = partitionOfInputCell[result.parentCell[t]];
        result.colorOfCell[t] = summary.colorOfPartition[result.partitionOfCell[t]];
        ++cellsPerColor[result.colorOfCell[t]];
      }
    });
  summary.cellsPerColor.assign(summary.numberOfColors, 0);
  for (const std::vector<std::int64_t>& cellsPerColor : cellsPerColorOfRange)
  {
    for (int color = 0; color < summary.numberOfColors; ++color)
    {
      summary.cellsPerColor[color] += cellsPerColor[color];
    }
  }
  // Each collapse leaves exactly one vertex unused, and so does each point the Delaunay sweep, or
  // meshing a sliver-laden input anew, dropped: those are the run's own, not the input's fault.
  const PointId unused = merged.removedPoints -
    static_cast<PointId>(
      summary.edgeCollapses + summary.sweepDroppedPoints + summary.inputDroppedPoints);
  if (unused > 0)
  {
    summary.warnings.push_back({ WarningKind::UnusedPointsRemoved, -1,
      "removed " + std::to_string(unused) + " points that no tetrahedron uses" });
  }
  return status;
}

// Why a run refines a sliver-laden input as given; empty when it meshes it anew. Delaunay runs
// mesh it anew (as a whole, or its clusters where the boundary triangulation is kept) unless one
// of the first two holds.
std::string whySliversAreKept(const AdaptationOptions& options, const AdaptationPlan& plan)
{
  if (!options.improveQuality)
  {
    return "ImproveQuality is off";
  }
  if (!options.improveInput)
  {
    return "ImproveInput is off";
  }
  if (plan.restricted())
  {
    return "RefinementRegions or RefinementBox leaves the other tets as they are";
  }
  if (options.keepBoundaryTriangulation)
  {
    return "the pieces of a mesh across processes keep their boundary's triangles";
  }
  return std::string();
}

// What refining slivers as given costs, by method.
const char* costOfKeptSlivers(RefinementMethod method)
{
  if (method == RefinementMethod::Template)
  {
    return "templates cut each sliver into slivers";
  }
  // Measured on the benchmarks' sliver-laden block and fin (26,269 tets, V = 0.64 x the mean
  // volume, 2 threads): 68 s and 4 fallbacks as given, 1.6 s meshed anew first.
  return "TetGen refines each sliver-laden partition against the slivers' faces on its boundary, "
         "which can take it far longer than meshing the input anew and fail (the partition is "
         "then refined by templates)";
}

// Meshes a sliver-laden input anew first (remeshInputFirst); any other input is left as it is.
// Template runs start their TetGen worker only here, for such an input: one, as there is one
// call. A run that may not mesh it anew warns, with the reason and what it costs.
Status remeshIfSliverLaden(const AdaptationOptions& options,
  const std::vector<int>& partitionOfCell, PartitionGraph& graph, ColorLoopSetup& setup,
  AdaptationState& state, AdaptationSummary& summary, PhaseReporter& reporter,
  std::unique_ptr<WorkerPool>& workers, bool& remeshed, bool& refined)
{
  const bool remeshes = remeshesInputFirst(options, summary.plan);
  SliverCount count;
  const Status status = countSlivers(setup.threads, state, count);
  if (!status.ok() || !count.many())
  {
    return status;
  }
  if (!remeshes)
  {
    std::ostringstream text;
    text << count.slivers << " of " << count.tets << " input tets (" << std::setprecision(3)
         << 100.0 * static_cast<double>(count.slivers) / static_cast<double>(count.tets)
         << "%) have a dihedral angle under " << RemeshSliverDegrees
         << " degree; they are refined as given (" << whySliversAreKept(options, summary.plan)
         << ") and " << costOfKeptSlivers(options.method)
         << ". Such an input is meshed anew by TetGen first with ImproveQuality and ImproveInput "
            "on, over the whole mesh, its boundary free to change";
    summary.warnings.push_back({ WarningKind::SliverLadenInputKept, -1, text.str() });
    return status;
  }
  if (!setup.runTetGen)
  {
    const bool started = workers != nullptr; // the curve chunks' METIS workers, one per thread
    if (!started)
    {
      workers = std::make_unique<WorkerPool>(1);
    }
    cutShortOnAbort(*workers, options);
    attachTetGen(options, setup, summary, workers.get(), !started);
  }
  return remeshInputFirst(
    options, partitionOfCell, graph, setup, state, summary, reporter, remeshed, refined);
}

// Refinement (and improvement inside partitions), then the sweeps across former interfaces.
// `formerInterface` flags the vertices shared by two refinement partitions.
Status refineAndImprove(const AdaptationOptions& options, const ColorLoopSetup& setup,
  AdaptationState& state, AdaptationSummary& summary, PhaseReporter& reporter,
  std::vector<char>& formerInterface)
{
  const std::int64_t poorBefore = summary.poorTets;
  ColorLoopSetup refinement = setup;
  refinement.interfaceVertexAtEnd = &formerInterface;
  Status status = runColorLoop(refinement, options, state, summary, reporter);
  if (!status.ok() || summary.aborted)
  {
    return status;
  }
  ColorLoopSetup sweeps = setup;
  sweeps.stage = Stage::Sweep;
  sweeps.progressStart = 0;
  sweeps.progressEnd = 1;
  if (setup.method == RefinementMethod::Delaunay && options.remeshAcrossFormerInterfaces)
  {
    sweeps.progressEnd = 0.5;
    status = remeshAcrossFormerInterfaces(
      sweeps, options, summary.plan.boxesPerAxis, formerInterface, state, summary, reporter);
    if (!status.ok() || summary.aborted)
    {
      return status;
    }
    sweeps.progressStart = 0.5;
    sweeps.progressEnd = 1;
  }
  if (!options.improveQuality && !setup.improvement.coarsen)
  {
    return status;
  }
  if (setup.improve && summary.poorTets == poorBefore && !setup.improvement.coarsen)
  {
    return status; // improvement in partitions saw no poor tet: no seam to work on
  }
  return improveAcrossFormerInterfaces(
    sweeps, options, summary.plan.boxesPerAxis, formerInterface, state, summary, reporter);
}

Status runPipeline(const TetMesh& input, const AdaptationOptions& options, AdaptationResult& result,
  PhaseReporter& reporter)
{
  AdaptationSummary& summary = result.summary;
  std::vector<int> partitionOfCell;
  PartitionGraph graph;
  std::unique_ptr<WorkerPool> workers = startWorkers(input, options, summary.plan);
  Status status =
    partitionAndColor(input, options, workers.get(), partitionOfCell, graph, summary, reporter);
  if (!status.ok())
  {
    return status;
  }
  reporter.enter(Phase::Prepare);
  status = templateTable().status();
  if (!status.ok())
  {
    return status;
  }
  AdaptationState state;
  state.partitions.resize(summary.plan.partitions);
  status = distributeTets(input, partitionOfCell, summary.plan.threads, state);
  if (!status.ok())
  {
    return status;
  }
  ColorLoopSetup setup = refinementSetup(options, summary);
  // A selection promises that the tets outside change only by refinement's closure: improvement
  // leaves every tet with a corner outside it as it is.
  std::vector<char> keptPoints;
  if (summary.plan.restricted())
  {
    keptPoints = pointsOutsideSelection(input.sizes);
    setup.improvement.keptPoints = &keptPoints;
  }
  if (options.method == RefinementMethod::Delaunay)
  {
    attachTetGen(options, setup, summary, workers.get());
  }
  bool remeshedInput = false, refinedInput = false;
  status = remeshIfSliverLaden(options, partitionOfCell, graph, setup, state, summary, reporter,
    workers, remeshedInput, refinedInput);
  if (!status.ok() || summary.aborted)
  {
    return status;
  }
  if (!remeshedInput && improvesInputFirst(options, summary.plan))
  {
    status = improveInputFirst(options, partitionOfCell, graph, setup, state, summary, reporter);
    if (!status.ok() || summary.aborted)
    {
      return status;
    }
  }
  // `graph` was built for the partitions as they are now, except after Delaunay interface rounds
  // that were not followed by a rebuild (remeshInputFirst when TetGen found no sliver cluster to
  // mesh): those split edges, so the points are more than the graph's.
  if (graph.interfaceVertex.size() == state.coordinates.size() / 3)
  {
    setup.interfaceVertexAtStart = &graph.interfaceVertex;
  }
  std::vector<char> formerInterface;
  if (refinedInput)
  {
    // TetGen met the bounds in its one call over the input: the passes only improve, inside the
    // partitions and then across their interfaces, which stand for the former interfaces.
    setup.refine = false;
    setup.numberOfIterations = 1;
    summary.iterationsRun = 1;
    summary.refinementConverged = true;
    formerInterface = graph.interfaceVertex;
  }
  status = refineAndImprove(options, setup, state, summary, reporter, formerInterface);
  workers.reset();
  if (!status.ok() || summary.aborted)
  {
    return status;
  }

  reporter.enter(Phase::Merge);
  status = markNearFormerInterface(
    state.partitions, formerInterface, summary.plan.threads, result.nearFormerInterface);
  MergedMesh merged;
  if (status.ok())
  {
    status = mergePartitions(state.partitions, std::move(state.coordinates), state.inputPointCount,
      state.newPointSources, merged, RelocationInput{ &input, &state.movedPoints },
      options.pointProvenance,
      summary.plan.sizeField ? std::move(state.sizes) : std::vector<double>(),
      parallelForOn(summary.plan.threads));
  }
  if (!status.ok())
  {
    return status;
  }
  state = AdaptationState(); // the partitions are in `merged` now
  status = adoptMergedMesh(merged, partitionOfCell, result);
  if (!status.ok())
  {
    return status;
  }
  if (result.mesh.hasSizes())
  {
    const ParallelFor parallelFor = parallelForOn(summary.plan.threads);
    status = edgeLengthRatios(result.mesh, parallelFor, result.edgeLengthRatio);
    if (status.ok())
    {
      status = measureEdgeSizes(result.mesh, parallelFor, summary.edgeSizes);
    }
    if (!status.ok())
    {
      return status;
    }
  }
  reporter.progress(Stage::Merge, 1.0);
  return Status::success();
}

void reportRepairs(const TetMesh& input, const InputRepairs& repairs, AdaptationSummary& summary)
{
  summary.reorientedTets = repairs.reorientedTets;
  summary.gluedPoints = repairs.gluedPoints;
  summary.keptApartPoints = repairs.keptApartPoints;
  if (repairs.reorientedTets > 0)
  {
    summary.warnings.push_back({ WarningKind::InvertedTetsReoriented, -1,
      "turned around " + std::to_string(repairs.reorientedTets) +
        " inverted tetrahedra: the output is consistently positively oriented" });
  }
  if (repairs.gluedPoints > 0)
  {
    summary.warnings.push_back({ WarningKind::CoincidentPointsMerged, -1,
      "merged " + std::to_string(repairs.gluedPoints) +
        " points that repeat the corners of matching faces: touching parts are glued where "
        "their faces match" });
  }
  if (repairs.keptApartPoints > 0)
  {
    const double* x = input.point(repairs.firstKeptApartPoint);
    std::ostringstream text;
    text << "kept " << repairs.keptApartPoints << " coincident points apart (the first is point "
         << repairs.firstKeptApartPoint << " at (" << x[0] << ", " << x[1] << ", " << x[2]
         << ")): they are not corners of faces that match across the contact, so the parts "
            "touching there are refined separately and stay unconnected";
    summary.warnings.push_back({ WarningKind::CoincidentPointsKeptApart, -1, text.str() });
  }
}

} // namespace

Status adaptMesh(
  const TetMesh& rawInput, const AdaptationOptions& options, AdaptationResult& result)
{
  result = AdaptationResult();
  AdaptationSummary& summary = result.summary;
  PhaseReporter reporter(options.progress);
  reporter.enter(Phase::Prepare);
  Status status = checkOptionsAndInput(rawInput, options);
  TetMesh input;
  if (status.ok())
  {
    InputRepairs repairs;
    status = prepareInput(
      rawInput, input, repairs, parallelForOn(resolveThreadCount(options.numberOfThreads)));
    reportRepairs(rawInput, repairs, summary);
  }
  if (status.ok() && input.hasSizes())
  {
    limitSizeGradation(input, options.sizeGradation, input.sizes);
  }
  if (status.ok())
  {
    summary.plan = resolvePlan(input, options, summary.warnings);
    if (summary.plan.restricted())
    {
      const std::array<double, 6>* box =
        summary.plan.hasRefinementBox ? &summary.plan.refinementBox : nullptr;
      restrictToSelection(input, selectTets(input, summary.plan.refinementRegions, box),
        summary.plan.edgeLengthThreshold, input.sizes);
    }
    reporter.progress(Stage::Prepare, 1.0);
    // The front end's abort hook, asked on this thread only, behind a watch that any thread may
    // poll while TetGen runs (AbortWatch.h).
    AbortWatch watch(options.abortRequested, reporter);
    AdaptationOptions watched = options;
    if (options.abortRequested)
    {
      watched.abortRequested = [&watch]
      {
        return !watch.keepGoing();
      };
    }
    try
    {
      status = runPipeline(input, watched, result, reporter);
      summary.aborted = summary.aborted || watch.aborted();
    }
    catch (const std::bad_alloc&)
    {
      status = Status::failure(ErrorKind::OutOfMemory, "out of memory");
    }
    catch (const std::exception& error)
    {
      status = Status::failure(ErrorKind::Internal, error.what());
    }
  }
  reporter.stop();
  if (!status.ok() || summary.aborted)
  {
    // No partial mesh: keep only the summary (plan, warnings, counts, seconds).
    AdaptationSummary kept = std::move(summary);
    result = AdaptationResult();
    result.summary = std::move(kept);
  }
  result.summary.seconds = reporter.seconds();
  result.summary.totalSeconds = reporter.seconds().total();
  reporter.progress(Stage::Merge, 1.0);
  return status;
}

} // namespace cgmesh
