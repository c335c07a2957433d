#include "InputImprovement.h"

#include "ImprovementSweep.h"
#include "ParallelFor.h"
#include "Partitioning/BoxPartitions.h"
#include "Refinement/PartitionRefiner.h"
#include "RemeshSweep.h"

#include <atomic>

namespace cgmesh
{
namespace
{

// Every tet to the partition of the input cell it comes from, in (box, tet) order.
Status returnTetsToPartitions(
  AdaptationState& state, const std::vector<int>& partitionOfCell, int partitions, int threads)
{
  std::vector<PartitionMesh> returned;
  const Status status = regroupByCellPartition(
    state.partitions, partitionOfCell, partitions, parallelForOn(threads), returned);
  state.partitions = std::move(returned);
  return status;
}

// Meshes the whole input anew in one TetGen call (pAMQnq): from its boundary and material
// interface faces, which TetGen may split as it splits a boundary it meshes on its own, and all
// its points. Kept triangles are what leaves slivers on such an input: a tet resting on a large
// kept triangle stays poor whatever TetGen inserts (see docs/design.md, section 5). With the
// plan's wholeInputCallRefines the call also has the volume bound (a). Afterwards the whole mesh
// is one partition; `remeshed` says whether TetGen succeeded.
Status remeshWholeInput(const ColorLoopSetup& setup, const AdaptationOptions& options,
  AdaptationState& state, AdaptationSummary& summary, PhaseReporter& reporter, bool& remeshed)
{
  PartitionMesh whole;
  for (PartitionMesh& partition : state.partitions)
  {
    appendTetsOf(partition, whole);
    partition = PartitionMesh();
  }
  state.partitions.assign(1, std::move(whole));
  ColorLoopSetup sweep = setup;
  sweep.refine = true;
  sweep.remeshSweep = true;
  sweep.method = RefinementMethod::Delaunay; // also before template refinement
  sweep.improve = false;
  sweep.numberOfIterations = 1;
  sweep.delaunay.shapesOnly = !summary.plan.wholeInputCallRefines;
  sweep.delaunay.keptFacesMaySplit = true;
  sweep.delaunay.surfaceClasses =
    options.surfaceClasses.empty() ? nullptr : &options.surfaceClasses;
  sweep.stage = Stage::ImproveInput;
  sweep.progressStart = 0;
  sweep.progressEnd = 0.6;
  const std::vector<int> oneColor(1, 0);
  sweep.colorOfPartition = &oneColor;
  sweep.numberOfColors = 1;
  const std::int64_t before = summary.inputRemeshedBoxes;
  const Status status = runColorLoop(sweep, options, state, summary, reporter);
  remeshed = summary.inputRemeshedBoxes > before;
  summary.boundaryRetriangulated = remeshed && !options.surfaceClasses.empty();
  return status;
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
  return improveInputBetween(
    0, 1, options, partitionOfCell, graph, setup, state, summary, reporter);
}

namespace
{

// Whether a tet below the improvement target (and not kept) lies in the partitions: the only tets
// the input's improvement starts from, as it never coarsens. The partitions are read in their
// order, which follows the mesh, where the colour loop reads each colour's partitions scattered
// over it: on the Kuhn cube N=56 (no poor tet) with 65,536 partitions, improvement took
// 0.086-0.102 s at 2 threads with that loop finding nothing, 0.027-0.032 s with this pass first.
bool holdsPoorTet(const ColorLoopSetup& setup, AdaptationState& state, Status& status)
{
  std::vector<double> noProvisionalPoints;
  const PartitionPoints points{ &state.coordinates, &noProvisionalPoints };
  std::atomic<bool> found(false);
  status = runParallel(setup.threads, static_cast<std::int64_t>(state.partitions.size()),
    [&](std::int64_t p)
    {
      if (found.load(std::memory_order_relaxed))
      {
        return; // the answer is known
      }
      for (const Tet& tet : state.partitions[static_cast<std::size_t>(p)].tets)
      {
        if (needsImprovement(tet, points, setup.improvement))
        {
          found.store(true, std::memory_order_relaxed);
          return;
        }
      }
    });
  return found.load();
}

// improveInputBetween, without counting its operations apart.
Status improveInputTets(double progressStart, double progressEnd, const AdaptationOptions& options,
  const std::vector<int>& partitionOfCell, PartitionGraph& graph, ColorLoopSetup& setup,
  AdaptationState& state, AdaptationSummary& summary, PhaseReporter& reporter)
{
  const double progressMiddle = 0.5 * (progressStart + progressEnd);
  ColorLoopSetup improveOnly = setup;
  improveOnly.refine = false;
  improveOnly.improve = true;
  // A size field is for the refined mesh: it neither coarsens the input nor bars a change that
  // makes an edge longer than sqrt(2) h (refinement splits those anyway). Measured on the FinFET
  // with the size-field benchmark's field (h a quarter of the edge length in the channel), it
  // barred most edge removals there: the input kept poorer tets, which refinement multiplied,
  // and the run took 12-16% longer for a minimum dihedral p1 of 21.72 against 21.95 degrees.
  improveOnly.improvement.coarsen = false;
  improveOnly.sizeField = false;
  improveOnly.numberOfIterations = 1;
  improveOnly.stage = Stage::ImproveInput;
  improveOnly.progressStart = progressStart;
  improveOnly.progressEnd = progressMiddle;
  reporter.enter(Phase::Improve);
  Status status = Status::success();
  if (!holdsPoorTet(improveOnly, state, status))
  {
    return status; // the loops below would change nothing
  }
  const std::int64_t poorBefore = summary.poorTets;
  status = runColorLoop(improveOnly, options, state, summary, reporter);
  if (!status.ok() || summary.aborted)
  {
    return status;
  }
  if (summary.poorTets == poorBefore)
  {
    return Status::success(); // no tet below the target: nothing changed
  }
  // Improvement inside partitions leaves each partition's vertices as they were, so the graph's
  // interface points are still those of the partitions.
  improveOnly.progressStart = progressMiddle;
  improveOnly.progressEnd = progressEnd;
  status = improveAcrossFormerInterfaces(improveOnly, options, summary.plan.boxesPerAxis,
    graph.interfaceVertex, state, summary, reporter);
  if (!status.ok() || summary.aborted)
  {
    return status;
  }
  return returnToInputPartitions(
    options, partitionOfCell, graph, setup, state, summary, reporter, progressEnd);
}

} // namespace

Status improveInputBetween(double progressStart, double progressEnd,
  const AdaptationOptions& options, const std::vector<int>& partitionOfCell, PartitionGraph& graph,
  ColorLoopSetup& setup, AdaptationState& state, AdaptationSummary& summary,
  PhaseReporter& reporter)
{
  const std::int64_t removals = summary.edgeRemovals, swaps = summary.faceSwaps,
                     moves = summary.vertexMoves;
  const Status status = improveInputTets(
    progressStart, progressEnd, options, partitionOfCell, graph, setup, state, summary, reporter);
  summary.inputEdgeRemovals += summary.edgeRemovals - removals;
  summary.inputFaceSwaps += summary.faceSwaps - swaps;
  summary.inputVertexMoves += summary.vertexMoves - moves;
  return status;
}

bool remeshesInputFirst(const AdaptationOptions& options, const AdaptationPlan& plan)
{
  if (!options.improveInput || !options.improveQuality)
  {
    return false;
  }
  if (options.method == RefinementMethod::Delaunay)
  {
    return true;
  }
  // Templates have no interface length for the rounds the clusters need, so only the whole
  // input, over every tet (a selection promises to leave the others as they are).
  return !options.keepBoundaryTriangulation && !plan.restricted();
}

Status remeshInputFirst(const AdaptationOptions& options, const std::vector<int>& partitionOfCell,
  PartitionGraph& graph, ColorLoopSetup& setup, AdaptationState& state, AdaptationSummary& summary,
  PhaseReporter& reporter, bool& remeshed, bool& refined)
{
  remeshed = false;
  refined = false;
  Status status = Status::success();
  if (!options.keepBoundaryTriangulation)
  {
    status = remeshWholeInput(setup, options, state, summary, reporter, remeshed);
    if (!status.ok() || summary.aborted)
    {
      return status;
    }
    if (remeshed)
    {
      status = returnToInputPartitions(
        options, partitionOfCell, graph, setup, state, summary, reporter, 0.6);
      refined = summary.plan.wholeInputCallRefines;
      if (!status.ok() || refined)
      {
        return status; // refined: the refinement passes improve it
      }
      return improveInputBetween(
        0.6, 1, options, partitionOfCell, graph, setup, state, summary, reporter);
    }
    // TetGen failed on the whole input: its tets went back unchanged. Templates refine them as
    // they are (after improveInputFirst); Delaunay meshes the clusters around the slivers below.
    status = returnTetsToPartitions(state, partitionOfCell, summary.plan.partitions, setup.threads);
    if (!status.ok() || options.method == RefinementMethod::Template)
    {
      return status;
    }
  }
  // The interface rounds first, as refinement makes them: TetGen keeps the boundary and material
  // interface triangles it is given, and tets resting on the input's large ones stay slivers
  // whatever it inserts (see docs/design.md, section 5).
  ColorLoopSetup rounds = setup;
  rounds.improve = false;
  rounds.numberOfIterations = 1;
  rounds.delaunay.constrainedEdgesOnly = true;
  rounds.stage = Stage::ImproveInput;
  rounds.progressStart = 0;
  rounds.progressEnd = 0.1;
  status = runColorLoop(rounds, options, state, summary, reporter);
  if (!status.ok() || summary.aborted)
  {
    return status;
  }
  ColorLoopSetup sweep = setup;
  sweep.stage = Stage::ImproveInput;
  sweep.progressStart = 0.1;
  sweep.progressEnd = 0.6;
  status = remeshSliverClusters(
    sweep, options, summary.plan.boxesPerAxis, state, summary, reporter, remeshed);
  if (!status.ok() || summary.aborted || !remeshed)
  {
    return status;
  }
  status =
    returnToInputPartitions(options, partitionOfCell, graph, setup, state, summary, reporter, 0.6);
  if (!status.ok())
  {
    return status;
  }
  // TetGen's tets against the kept triangles can still be slivers (on the benchmark's poor input
  // 22 of 95,702 under 1 degree): improved as a template run's input is, no partition of the
  // refinement is sliver-laden (3 were without it) and the output's minimum dihedral angle is
  // 0.98 degrees instead of 0.62.
  return improveInputBetween(
    0.6, 1, options, partitionOfCell, graph, setup, state, summary, reporter);
}

Status returnToInputPartitions(const AdaptationOptions& options,
  const std::vector<int>& partitionOfCell, PartitionGraph& graph, ColorLoopSetup& setup,
  AdaptationState& state, AdaptationSummary& summary, PhaseReporter& reporter, double progress)
{
  Status status =
    returnTetsToPartitions(state, partitionOfCell, summary.plan.partitions, setup.threads);
  if (!status.ok())
  {
    return status;
  }

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
  reporter.progress(Stage::ImproveInput, progress);
  return Status::success();
}

} // namespace cgmesh
