#include "ColorLoop.h"

#include "Coloring/ColoringSupport.h"
#include "Coloring/PartitionColoring.h"
#include "Core/Geometry.h"
#include "Core/Stopwatch.h"
#include "ParallelFor.h"

#include <algorithm>
#include <functional>
#include <limits>

namespace cgmesh
{
namespace
{

std::vector<std::vector<int>> partitionsByColor(
  const std::vector<int>& colorOfPartition, int colors)
{
  std::vector<std::vector<int>> members(colors);
  for (std::size_t p = 0; p < colorOfPartition.size(); ++p)
  {
    members[colorOfPartition[p]].push_back(static_cast<int>(p));
  }
  return members;
}

// What one partition's task reports back to the serial part of the loop.
struct TaskReport
{
  Status status = Status::success();
  DelaunayOutcome delaunay;
  double seconds = 0;
  bool skipped = false; // not read: nothing to split in it (refineMembers)
};

// Everything one iteration's partition tasks share.
struct IterationContext
{
  const ColorLoopSetup& setup;
  const AdaptationOptions& options;
  RefinementContext refinement;
  std::vector<PartitionRefinement> refinements;
  // Refinement loops: the partitions changed since their last improvement (see improvesNow).
  std::vector<char>* awaitingImprovement = nullptr;
  // Template refinement loops: the partitions unchanged since a pass found no edge to split in
  // them (see refineMembers).
  std::vector<char>* nothingToSplit = nullptr;
  // Template refinement loops: per partition, which of its tets came through the last pass
  // unsplit, unchanged since (refinePartition's `passedUnsplit`); empty where not known.
  std::vector<std::vector<char>>* passedUnsplit = nullptr;
  // Every interface split the colours before the current one made in this iteration, by edge: a
  // partition heals from it what its processed neighbours split (see postSplitsOfColor).
  PostedSplits splitsOfEarlierColors = PostedSplits();
};

TaskReport refineOnePartition(
  IterationContext& iteration, AdaptationState& state, int partition, const PostedSplits& received)
{
  TaskReport report;
  const Stopwatch stopwatch;
  PartitionRefinement& refinement = iteration.refinements[partition];
  if (iteration.setup.method == RefinementMethod::Template)
  {
    std::vector<char>* unsplit = iteration.passedUnsplit && iteration.options.skipSettledPartitions
      ? &(*iteration.passedUnsplit)[partition]
      : nullptr;
    report.status = refinePartition(state.partitions[partition], iteration.refinement, received,
      refinement, EdgeFilter(), nullptr, nullptr, unsplit);
  }
  else
  {
    DelaunayParameters parameters = iteration.setup.delaunay;
    const auto& failing = iteration.options.simulateTetGenFailureIn;
    parameters.simulateFailure = !iteration.setup.remeshSweep && // names refinement partitions
      std::find(failing.begin(), failing.end(), partition) != failing.end();
    const PartitionTetGenRunner& runner = iteration.setup.runTetGen;
    const TetGenRunner runTetGen = [&runner, partition](
                                     const tetgenio& in, const std::string& switches, tetgenio& out)
    {
      return runner(partition, in, switches, out);
    };
    report.status = iteration.setup.remeshSweep
      ? remeshPartitionDelaunay(state.partitions[partition], iteration.refinement, parameters,
          state.inputPointCount, runTetGen, refinement, report.delaunay)
      : refinePartitionDelaunay(state.partitions[partition], iteration.refinement, received,
          parameters, runTetGen, refinement, report.delaunay);
  }
  report.seconds = stopwatch.seconds();
  return report;
}

// Boxes meshed anew, by the sweep across former interfaces or, before refinement, around the
// input's slivers: how many, the points they dropped, and why the others failed (they stay as
// they were).
void recordRemeshReports(
  const std::vector<TaskReport>& reports, bool beforeRefinement, AdaptationSummary& summary)
{
  std::int64_t& boxes = beforeRefinement ? summary.inputRemeshedBoxes : summary.sweepRemeshedBoxes;
  std::int64_t& dropped =
    beforeRefinement ? summary.inputDroppedPoints : summary.sweepDroppedPoints;
  std::int64_t& failures =
    beforeRefinement ? summary.inputRemeshFailures : summary.sweepRemeshFailures;
  for (const TaskReport& report : reports)
  {
    const DelaunayOutcome& outcome = report.delaunay;
    summary.tetgenPoints += outcome.tetgenPoints;
    boxes += outcome.remeshed ? 1 : 0;
    dropped += outcome.droppedPoints;
    if (!outcome.fellBack || outcome.reason == WorkerCallAbortedReason)
    {
      continue; // an aborted run's result is dropped: its calls cut short are no failures
    }
    ++failures;
    if (beforeRefinement)
    {
      summary.warnings.push_back({ WarningKind::InputRemeshFailed, -1,
        "a cluster of slivers in the input could not be meshed anew (" + outcome.reason +
          "); its tets are refined as they were" });
    }
    else
    {
      summary.warnings.push_back({ WarningKind::SweepRemeshFailed, -1,
        "a box across former interfaces could not be meshed anew (" + outcome.reason +
          "); its tets stay as refined" });
    }
  }
}

void recordReports(const std::vector<int>& members, const std::vector<TaskReport>& reports,
  int iteration, AdaptationSummary& summary)
{
  const std::size_t partitions = summary.plan.partitions;
  for (std::size_t i = 0; i < members.size(); ++i)
  {
    const TaskReport& report = reports[i];
    summary.partitionTaskSeconds[iteration * partitions + members[i]] += report.seconds;
    summary.skippedPartitionReads += report.skipped ? 1 : 0;
    summary.tetgenPoints += report.delaunay.tetgenPoints;
    summary.tetgenRetries += report.delaunay.retried ? 1 : 0;
    summary.tetgenWithoutQualityBound += report.delaunay.withoutQualityBound ? 1 : 0;
    summary.tetgenRemeshed += report.delaunay.remeshed ? 1 : 0;
    if (report.delaunay.fellBack && report.delaunay.reason != WorkerCallAbortedReason)
    {
      ++summary.delaunayFallbacks;
      summary.fallbackPartitions.push_back(members[i]);
      summary.warnings.push_back({ WarningKind::DelaunayFallback, members[i],
        "partition " + std::to_string(members[i]) + ": Delaunay refinement failed (" +
          report.delaunay.reason + "); refined by templates instead" });
    }
  }
}

// Gives the colour's new points global ids: prefix sums in partition order (the same for any
// thread count), then each partition rewrites its own references in parallel.
Status numberNewPoints(
  IterationContext& iteration, const std::vector<int>& members, AdaptationState& state)
{
  std::vector<PointId> firstId(members.size());
  PointId next = static_cast<PointId>(state.coordinates.size() / 3);
  for (std::size_t i = 0; i < members.size(); ++i)
  {
    firstId[i] = next;
    next += static_cast<PointId>(iteration.refinements[members[i]].newPointSources.size());
  }
  // The global arrays grow once; each partition then copies its points into its own range. The
  // sources of new points only serve point-data provenance: without it they are not gathered.
  const bool keepSources = iteration.options.pointProvenance;
  state.coordinates.resize(3 * next);
  const bool withSizes = std::any_of(members.begin(), members.end(),
    [&](int p) { return !iteration.refinements[p].newSizes.empty(); });
  if (withSizes)
  {
    state.sizes.resize(next); // new points carry sizes only where every point has one
  }
  if (keepSources)
  {
    state.newPointSources.resize(next - state.inputPointCount);
  }
  Status status = runParallel(iteration.setup.threads, static_cast<std::int64_t>(members.size()),
    [&](std::int64_t i)
    {
      const int p = members[i];
      PartitionRefinement& refinement = iteration.refinements[p];
      finalizeNewPoints(state.partitions[p], refinement, firstId[i]);
      std::copy(refinement.newCoordinates.begin(), refinement.newCoordinates.end(),
        state.coordinates.begin() + 3 * firstId[i]);
      if (withSizes)
      {
        std::copy(
          refinement.newSizes.begin(), refinement.newSizes.end(), state.sizes.begin() + firstId[i]);
      }
      if (keepSources)
      {
        std::copy(refinement.newPointSources.begin(), refinement.newPointSources.end(),
          state.newPointSources.begin() + (firstId[i] - state.inputPointCount));
      }
      refinement.newCoordinates = std::vector<double>();
      refinement.newSizes = std::vector<double>();
      refinement.newPointSources = std::vector<PointSource>();
    });
  for (int p : members)
  {
    PartitionRefinement& refinement = iteration.refinements[p];
    state.movedPoints.insert(
      state.movedPoints.end(), refinement.movedPoints.begin(), refinement.movedPoints.end());
    refinement.movedPoints.clear();
  }
  return status;
}

// Adds the colour's interface splits, now in global ids, to those later colours heal from. Each
// split goes in once; gathering every processed neighbour's whole outbox into a map per partition
// instead inserted each split once per neighbour: at 65,536 partitions of 16 tets, most of the
// healing time.
Status postSplitsOfColor(IterationContext& iteration, const std::vector<int>& members)
{
  std::vector<const Outbox*> outboxes;
  for (int p : members)
  {
    outboxes.push_back(&iteration.refinements[p].outbox);
  }
  const Status status =
    iteration.splitsOfEarlierColors.post(outboxes, parallelForOn(iteration.setup.threads));
  for (int p : members)
  {
    iteration.refinements[p].outbox = Outbox();
  }
  return status;
}

// The adapt loop of one colour.
Status refineMembers(IterationContext& iteration, const std::vector<int>& members,
  int iterationIndex, AdaptationState& state, AdaptationSummary& summary, PhaseReporter& reporter)
{
  const ColorLoopSetup& setup = iteration.setup;
  const std::int64_t count = static_cast<std::int64_t>(members.size());
  reporter.enter(Phase::Adapt);
  std::vector<TaskReport> reports(members.size());
  // TetGen calls can take minutes: the calling thread, its own done, keeps polling the abort
  // hook (which also reports progress again) until the others end, and an abort cuts their
  // calls short (WorkerPool::setAbortCheck).
  std::function<void()> whileWaiting;
  if (setup.runTetGen && iteration.options.abortRequested)
  {
    whileWaiting = [&iteration]
    {
      iteration.options.abortRequested();
    };
  }
  Status status = runParallel(
    setup.threads, count,
    [&](std::int64_t i)
    {
      const int p = members[i];
      // A partition whose tets a template pass found no edge to split in, and which nothing has
      // changed since, has none now: its neighbours split no edge it shares with them either (the
      // same lengths and sizes decide on both sides, and improvement never moves interface
      // vertices), so it would make no point and heal none. Reading it again is skipped. On the
      // FinFET with its size field (six passes, 1,024 partitions) 1,152 of the 6,144 reads,
      // most of them in the last pass: adapt 1.90 to 1.70 s at one thread, same output.
      char& nothingToSplit = (*iteration.nothingToSplit)[p];
      if (nothingToSplit && iteration.options.skipSettledPartitions) // templates alone set it
      {
        reports[i] = TaskReport();
        reports[i].skipped = true;
        return;
      }
      reports[i] = refineOnePartition(iteration, state, p, iteration.splitsOfEarlierColors);
      // What its improvement left is still known where templates neither split nor healed
      // (a partition settled in an earlier pass); TetGen may change tets without a new point.
      const PartitionRefinement& refinement = iteration.refinements[p];
      const bool changed = setup.method != RefinementMethod::Template ||
        !refinement.newPointSources.empty() || refinement.healedSplits != 0;
      if (changed)
      {
        state.improvementLeft[p] = ImprovementLeft();
      }
      nothingToSplit = !changed;
    },
    whileWaiting);
  const bool beforeRefinement = setup.stage == Stage::ImproveInput;
  if (setup.remeshSweep)
  {
    recordRemeshReports(reports, beforeRefinement, summary);
  }
  else if (!beforeRefinement) // the interface rounds before meshing the input anew report nothing
  {
    recordReports(members, reports, iterationIndex, summary);
  }
  for (const TaskReport& report : reports)
  {
    if (!report.status.ok())
    {
      return report.status;
    }
  }
  return status;
}

// Whether partition p is improved in this pass. Refinement passes leave a partition's improvement
// to the pass that finds it settled (no point made in it, no split healed) or to the last pass
// allowed: improving it while later passes still split its tets repeats the work on their
// children. On the FinFET with a size field (5 passes, 1,024 partitions, 2 threads) improvement
// took 12.0 s instead of 15.9, for the same quality (minimum dihedral p1 21.7 against 21.9
// degrees, 93.8% of edges within the field's bounds against 93.9%). Sweeps always improve.
bool improvesNow(IterationContext& iteration, int iterationIndex, int p)
{
  if (!iteration.setup.refine)
  {
    return true;
  }
  const PartitionRefinement& refinement = iteration.refinements[p];
  const bool changed = !refinement.newPointSources.empty() || refinement.healedSplits != 0;
  const bool lastPass = iterationIndex == iteration.setup.numberOfIterations - 1;
  char& awaiting = (*iteration.awaitingImprovement)[p];
  awaiting = awaiting || changed;
  if (!awaiting || (changed && !lastPass))
  {
    return false;
  }
  awaiting = 0;
  return true;
}

Status improveMembers(IterationContext& iteration, const std::vector<int>& members,
  int iterationIndex, AdaptationState& state, AdaptationSummary& summary)
{
  std::vector<ImprovementStatistics> statistics(members.size());
  std::vector<Status> outcomes(members.size(), Status::success());
  Status status = runParallel(iteration.setup.threads, static_cast<std::int64_t>(members.size()),
    [&](std::int64_t i)
    {
      const int p = members[i];
      PartitionRefinement& refinement = iteration.refinements[p];
      if (!improvesNow(iteration, iterationIndex, p))
      {
        return;
      }
      (*iteration.nothingToSplit)[p] = 0; // improvement may make long edges
      if (iteration.passedUnsplit)
      {
        (*iteration.passedUnsplit)[p].clear(); // and moves and renews tets
      }
      PartitionPoints points{ &state.coordinates, &refinement.newCoordinates };
      if (iteration.setup.sizeField)
      {
        points.globalSizes = &state.sizes;
        points.provisionalSizes = &refinement.newSizes;
      }
      ImprovementLeft& left = state.improvementLeft[p];
      const bool listed = iteration.refinement.improvementTarget > 0;
      outcomes[i] =
        improvePartition(state.partitions[p], points, iteration.setup.improvement, statistics[i],
          refinement.movedPoints, &left.tets, listed ? &refinement.tetsToScreen : nullptr);
      left.known = outcomes[i].ok();
      left.tetCount = state.partitions[p].tets.size();
    });
  for (std::size_t i = 0; i < members.size(); ++i)
  {
    summary.edgeRemovals += statistics[i].edgeRemovals;
    summary.faceSwaps += statistics[i].faceSwaps;
    summary.vertexMoves += statistics[i].vertexMoves;
    summary.edgeCollapses += statistics[i].edgeCollapses;
    summary.poorTets += statistics[i].poorTets;
    if (!outcomes[i].ok())
    {
      return outcomes[i];
    }
  }
  return status;
}

Status processColor(IterationContext& iteration, const std::vector<int>& members,
  int iterationIndex, AdaptationState& state, AdaptationSummary& summary, PhaseReporter& reporter)
{
  const ColorLoopSetup& setup = iteration.setup;
  Status status = Status::success();
  if (setup.refine)
  {
    status = refineMembers(iteration, members, iterationIndex, state, summary, reporter);
    if (!status.ok())
    {
      return status;
    }
  }

  if (setup.improve)
  {
    reporter.enter(Phase::Improve);
    status = improveMembers(iteration, members, iterationIndex, state, summary);
    if (!status.ok())
    {
      return status;
    }
  }

  // A sweep's numbering only gathers moved points: it counts as improvement.
  reporter.enter(setup.refine ? Phase::Post : Phase::Improve);
  status = numberNewPoints(iteration, members, state);
  if (!status.ok() || !setup.refine)
  {
    return status;
  }
  reporter.enter(Phase::Heal);
  return postSplitsOfColor(iteration, members);
}

std::int64_t countTets(const AdaptationState& state)
{
  std::int64_t tets = 0;
  for (const PartitionMesh& partition : state.partitions)
  {
    tets += static_cast<std::int64_t>(partition.tets.size());
  }
  return tets;
}

// Room in the point arrays for the points an iteration forecast to make `forecastTets` tets from
// `tets` will add (a tet mesh holds about one point per six tets), so that the colours'
// numbering, which runs on one thread, appends without moving the arrays again and again.
void reserveForNewPoints(std::int64_t forecastTets, std::int64_t tets, AdaptationState& state)
{
  if (forecastTets <= tets)
  {
    return;
  }
  const std::size_t points = state.coordinates.size() / 3 + (forecastTets - tets) / 5;
  state.coordinates.reserve(3 * points);
  if (!state.sizes.empty())
  {
    state.sizes.reserve(points);
  }
}

// Refuses an iteration whose forecast size exceeds the guard, before it allocates anything big.
// Sets `forecastTets` to the forecast, or 0 when there is no guard. `tetsNow` and `tetsBefore`
// count the tets at the start of this pass and of the one before (0 in the first).
Status checkForecastSize(const ColorLoopSetup& setup, const RefinementContext& context,
  const AdaptationState& state, std::int64_t tetsNow, std::int64_t tetsBefore,
  std::int64_t& forecastTets)
{
  forecastTets = 0;
  if (!setup.refine || setup.remeshSweep || setup.maximumNumberOfCells <= 0)
  {
    return Status::success();
  }
  // A template pass gives a tet 8 children at most: where even that stays within the guard, the
  // forecast only sizes the room for new points, and after the first pass the last pass's growth
  // does that well enough without reading every tet. On the FinFET with its size field (six
  // passes) the forecasts took 4% of the run.
  if (setup.method == RefinementMethod::Template && tetsBefore > 0 &&
    tetsNow <= setup.maximumNumberOfCells / 8)
  {
    forecastTets = static_cast<std::int64_t>(static_cast<double>(tetsNow) *
      static_cast<double>(tetsNow) / static_cast<double>(tetsBefore));
    return Status::success();
  }
  const std::int64_t partitions = static_cast<std::int64_t>(state.partitions.size());
  std::vector<std::int64_t> forecast(state.partitions.size(), 0);
  Status status = runParallel(setup.threads, partitions,
    [&](std::int64_t p)
    {
      const PartitionMesh& partition = state.partitions[p];
      if (setup.method == RefinementMethod::Template)
      {
        forecast[p] = predictTemplateTetCount(partition, context);
        return;
      }
      // What TetGen will make, plus what is there.
      double added = 0;
      if (context.sizes)
      {
        added = forecastDelaunayTetsForSizes(partition.tets, state.coordinates, *context.sizes);
      }
      else
      {
        double volume = 0;
        for (const Tet& tet : partition.tets)
        {
          volume += signedVolume6(state.coordinates.data() + 3 * tet[0],
                      state.coordinates.data() + 3 * tet[1], state.coordinates.data() + 3 * tet[2],
                      state.coordinates.data() + 3 * tet[3]) /
            6.0;
        }
        // A bound of rounding-noise size (or an overflowing volume) forecasts no finite count:
        // that is more than any guard allows, not a number to convert.
        added = forecastDelaunayTets(volume, setup.delaunay.maximumVolume);
      }
      const std::int64_t most = std::numeric_limits<std::int64_t>::max() / (partitions + 1);
      forecast[p] = static_cast<std::int64_t>(partition.tets.size()) +
        (added < static_cast<double>(most) ? static_cast<std::int64_t>(added) : most);
    });
  std::int64_t total = 0;
  for (std::int64_t count : forecast)
  {
    total += count;
  }
  forecastTets = total;
  if (status.ok() && total > setup.maximumNumberOfCells)
  {
    return Status::failure(ErrorKind::SizeLimit,
      "refining would produce about " + std::to_string(total) +
        " tetrahedra, more than the limit of " + std::to_string(setup.maximumNumberOfCells) +
        " (MaximumNumberOfCells); raise the limit or refine less");
  }
  return status;
}

// The interface points after a refinement pass, from those before it. A pass moves no tet from
// one partition to another, and a partition keeps every vertex it had on its boundary (children
// keep their parents' corners; improvement and TetGen keep the partition's boundary), so an old
// point is shared as before, and a point the pass made is shared exactly when a second partition
// took it from the posted splits: no scan of the refined tets is needed. On the FinFET and the Big
// cube the scan was half of the heal phase.
void keepInterfaceVertices(const std::vector<PartitionRefinement>& refinements,
  const AdaptationState& state, std::vector<char>& interfaceVertex)
{
  interfaceVertex.resize(state.coordinates.size() / 3, 0);
  for (const PartitionRefinement& refinement : refinements)
  {
    for (PointId point : refinement.receivedPoints)
    {
      interfaceVertex[point] = 1;
    }
  }
}

} // namespace

Status colorPartitions(const PartitionGraph& graph, const std::string& coloringName, int threads,
  std::vector<int>& colorOfPartition)
{
  const auto coloring = makeColoring(coloringName);
  if (!coloring)
  {
    return Status::failure(ErrorKind::InvalidOption, "unknown colouring '" + coloringName + "'");
  }
  Status status = coloring->color(graph, parallelForOn(threads), colorOfPartition);
  if (status.ok() && !isProperColoring(graph, colorOfPartition))
  {
    return Status::failure(ErrorKind::Internal,
      std::string("colouring '") + coloring->name() +
        "' gave two adjacent partitions the same colour");
  }
  return status;
}

void summarizeColoring(AdaptationSummary& summary)
{
  summary.numberOfColors = countColors(summary.colorOfPartition);
  summary.partitionsPerColor = colorSizes(summary.colorOfPartition, summary.numberOfColors);
  summary.colorBalance = 0;
  if (summary.numberOfColors > 0)
  {
    const double mean =
      static_cast<double>(summary.colorOfPartition.size()) / summary.numberOfColors;
    summary.colorBalance =
      *std::max_element(summary.partitionsPerColor.begin(), summary.partitionsPerColor.end()) /
      mean;
  }
}

Status runColorLoop(const ColorLoopSetup& setup, const AdaptationOptions& options,
  AdaptationState& state, AdaptationSummary& summary, PhaseReporter& reporter)
{
  const auto members = partitionsByColor(*setup.colorOfPartition, setup.numberOfColors);
  const int steps = setup.numberOfIterations * setup.numberOfColors;
  std::size_t pointsAtLastPass = 0;
  std::vector<char> awaitingImprovement(state.partitions.size(), 1); // none improved yet
  std::vector<char> nothingToSplit(state.partitions.size(), 0);
  std::vector<std::vector<char>> passedUnsplit(
    setup.method == RefinementMethod::Template ? state.partitions.size() : 0);
  state.improvementLeft.assign(state.partitions.size(), ImprovementLeft());
  // Its figures per partition, but not those of the interface rounds before the input's slivers
  // are meshed anew.
  const bool refinesPartitions =
    setup.refine && !setup.remeshSweep && setup.stage != Stage::ImproveInput;
  if (refinesPartitions)
  {
    summary.partitionTaskSeconds.assign(
      static_cast<std::size_t>(setup.numberOfIterations) * summary.plan.partitions, 0.0);
  }
  std::vector<char> interfaceVertex; // refinement: per point, in tets of two or more partitions
  std::int64_t tetsNow = 0, tetsBefore = 0; // at the start of this pass and of the last
  for (int iteration = 0; iteration < setup.numberOfIterations; ++iteration)
  {
    if (setup.refine && iteration > 0 && state.coordinates.size() == pointsAtLastPass)
    {
      summary.refinementConverged = true; // a pass that adds no point changes nothing after it
      break;
    }
    pointsAtLastPass = state.coordinates.size();
    // Only refinement reads the interface points (improvement freezes each partition's boundary
    // itself); each pass keeps them up to date for the next (keepInterfaceVertices).
    reporter.enter(setup.refine ? Phase::Heal : Phase::Improve);
    if (setup.refine && iteration == 0 && setup.interfaceVertexAtStart)
    {
      interfaceVertex = *setup.interfaceVertexAtStart;
    }
    else if (setup.refine && iteration == 0)
    {
      const Status found =
        findInterfaceVertices(state.partitions, static_cast<PointId>(state.coordinates.size() / 3),
          parallelForOn(setup.threads), interfaceVertex);
      if (!found.ok())
      {
        return found;
      }
    }
    IterationContext context{ setup, options, RefinementContext(),
      std::vector<PartitionRefinement>(state.partitions.size()), &awaitingImprovement,
      &nothingToSplit, passedUnsplit.empty() ? nullptr : &passedUnsplit };
    context.refinement.coordinates = &state.coordinates;
    context.refinement.interfaceVertex = &interfaceVertex;
    context.refinement.squaredThreshold = setup.squaredThreshold;
    context.refinement.sizes = state.sizes.empty() ? nullptr : &state.sizes;
    context.refinement.templates = setup.templates;
    context.refinement.orderCornersByCoordinates = setup.orderCornersByCoordinates;
    context.refinement.locateTetGenOutput = options.pointProvenance || options.cellDataByParent;
    // Template children of good parents are good (FullSplitChildQuality): refinement measures the
    // others as it makes them and lists the poor ones, and improvement screens those alone. Short
    // edges have no such bound.
    if (setup.refine && setup.improve && setup.method == RefinementMethod::Template &&
      setup.improvement.improve && !setup.improvement.coarsen)
    {
      context.refinement.improvementTarget = setup.improvement.targetQuality;
    }
    tetsBefore = tetsNow;
    tetsNow = countTets(state);
    std::int64_t forecastTets = 0;
    Status forecast =
      checkForecastSize(setup, context.refinement, state, tetsNow, tetsBefore, forecastTets);
    if (!forecast.ok())
    {
      return forecast;
    }
    reserveForNewPoints(forecastTets, tetsNow, state);

    for (int color = 0; color < setup.numberOfColors; ++color)
    {
      if (options.abortRequested && options.abortRequested())
      {
        summary.aborted = true;
        return Status::success();
      }
      Status status = processColor(context, members[color], iteration, state, summary, reporter);
      if (!status.ok())
      {
        return status;
      }
      if (setup.runTetGen && options.abortRequested && options.abortRequested())
      {
        summary.aborted = true; // seen while the colour's TetGen calls ran, which it cut short
        return Status::success();
      }
      const double done = static_cast<double>(iteration * setup.numberOfColors + color + 1) / steps;
      reporter.progress(
        setup.stage, setup.progressStart + (setup.progressEnd - setup.progressStart) * done);
    }
    if (setup.refine)
    {
      keepInterfaceVertices(context.refinements, state, interfaceVertex);
    }
    if (refinesPartitions)
    {
      summary.iterationsRun = iteration + 1;
    }
  }
  if (setup.refine && setup.interfaceVertexAtEnd)
  {
    *setup.interfaceVertexAtEnd = std::move(interfaceVertex);
  }
  if (refinesPartitions && state.coordinates.size() == pointsAtLastPass)
  {
    summary.refinementConverged = true; // the last pass allowed added no point either
  }
  return Status::success();
}

} // namespace cgmesh
