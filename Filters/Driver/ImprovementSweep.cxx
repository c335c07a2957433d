#include "ImprovementSweep.h"

#include "BoxSweep.h"

#include <algorithm>

namespace cgmesh
{
namespace
{

// Flags the corners of the tets the sweep works on: those that touch a former interface vertex
// and need improvement (poor, or short-edged when coarsening). Every operation stays among the
// tets that share a vertex with them, so only those go into boxes. Only the first `candidates`
// partitions are looked at, and in each only the tets its improvement left, where known: on the
// FinFET (6.5 M tets after refinement) 3,000 instead of 4 M tets at former interfaces.
// Returns how many were found.
std::int64_t flagCornersOfWork(const ColorLoopSetup& setup, const ImprovementParameters& work,
  const std::vector<char>& formerInterface, std::size_t candidates, AdaptationState& state,
  std::vector<char>& flagged, Status& status)
{
  std::vector<double> noProvisionalPoints, noProvisionalSizes;
  PartitionPoints points{ &state.coordinates, &noProvisionalPoints };
  if (setup.sizeField)
  {
    points.globalSizes = &state.sizes;
    points.provisionalSizes = &noProvisionalSizes;
  }
  flagged.assign(state.coordinates.size() / 3, 0);
  return flagCornersOfSelectedTets(
    setup.threads, state, candidates,
    [&](const Tet& tet)
    { return touchesFlaggedPoint(tet, formerInterface) && needsImprovement(tet, points, work); },
    flagged, status, true);
}

// The improvement sweeps: boxes from the bounding box's corner, then shifted by half a box, then
// whole clusters of the poorest tets left.
constexpr int SweepCount = 3;
// The third sweep's work: tets still under this mean ratio. With every tet under the improvement
// target (0.5) it took the FinFET template run's improvement from 0.55 to 0.63 s for no
// measurable gain; with this bar, 0.02 s.
constexpr double ClusterSweepQuality = 0.3;
// The third sweep's largest cluster, in corners of work: one box holds a cluster and one task
// improves a box, so a cluster that grew along a whole interface would be a serial task. None
// came near it: the Big cube's largest (Delaunay, 1,024 partitions, two passes) held 17 corners.
constexpr std::size_t LargestCluster = 1000;

// Keeps flagged only the points `earlier` flagged as well, and says whether any is left.
bool keepFlaggedBefore(std::vector<char>& flagged, const std::vector<char>& earlier)
{
  bool any = false;
  for (std::size_t p = 0; p < flagged.size(); ++p)
  {
    flagged[p] = flagged[p] && earlier[p];
    any = any || flagged[p];
  }
  return any;
}

// One improvement sweep over box partitions; `sweepIndex` 0 lays the boxes from the bounding
// box's corner, 1 shifts them by half a box, 2 puts each cluster of the work left (its tets'
// corners joined through the tets around them) into one box. Only the tets that share a vertex
// with a tet to work on move into the boxes; the others stay in their partitions, which follow
// the boxes. Work is looked for in the first `candidates` partitions; `candidates` becomes the
// number of boxes, or 0 when there was no work.
//
// After the first sweep, `cornersOfWork` holds the points the sweep before flagged, and a sweep
// moves only the tets around those of them it flags again. All of their tets went into that
// sweep's boxes, the first `candidates` partitions, and stayed there (a box's changes stay
// inside it), so the rest of the mesh is not read: on the FinFET's 6.5 M refined tets a full
// pass took 0.04 s of 0.05 s a sweep. Work at a corner flagged for the first time, a few per
// cent of a sweep's (on the FinFET 74 of 2,733 points), waits at the box faces, frozen.
//
// After Delaunay refinement the second sweep reads the whole mesh again, as the first does:
// there the corners flagged for the first time carry slivers, which frozen stay (the Big cube's
// minimum dihedral angle 3.01 degrees restricted, 4.66 whole; the FinFET's p1 16.70 against
// 16.72), and the full pass costs little: 0.02-0.04 s of the Big cube's 0.4 s of improvement at
// 2 threads, on the FinFET less than the runs' noise (the mesh is a third of a Template run's).
// After templates it cost the FinFET 0.1 s of improvement for the same quality.
Status improveOverBoxes(const ColorLoopSetup& setup, const AdaptationOptions& options, int cells,
  int sweepIndex, const std::vector<char>& formerInterface, std::size_t& candidates,
  std::vector<char>& cornersOfWork, AdaptationState& state, AdaptationSummary& summary,
  PhaseReporter& reporter)
{
  reporter.enter(Phase::Improve);
  const bool restricted =
    sweepIndex > 0 && !(sweepIndex == 1 && setup.method == RefinementMethod::Delaunay);
  if (!restricted)
  {
    candidates = state.partitions.size();
  }
  std::vector<char> flaggedBefore;
  std::swap(flaggedBefore, cornersOfWork);
  Status status = Status::success();
  const bool clustered = sweepIndex == 2;
  ImprovementParameters work = setup.improvement;
  if (clustered)
  {
    work.targetQuality = std::min(work.targetQuality, ClusterSweepQuality);
    work.coarsen = false;
  }
  if (flagCornersOfWork(setup, work, formerInterface, candidates, state, cornersOfWork, status) ==
      0 ||
    !status.ok() || (restricted && !keepFlaggedBefore(cornersOfWork, flaggedBefore)))
  {
    candidates = 0;
    return status; // nothing near a former interface needs work
  }
  const std::size_t holding = restricted ? candidates : AllPartitions;
  const BoxLayout layout = layBoxes(
    state.coordinates, cells, clustered ? 0 : 0.5 * sweepIndex, parallelForOn(setup.threads));
  ColorLoopSetup sweep = setup;
  sweep.refine = false;
  sweep.improve = true;
  const double share = (setup.progressEnd - setup.progressStart) / SweepCount;
  sweep.progressStart = setup.progressStart + share * sweepIndex;
  sweep.progressEnd = sweep.progressStart + share;
  if (!clustered)
  {
    return runSweepOverBoxes(sweep, options, layout, cornersOfWork, state, summary, reporter,
      candidates, nullptr, holding);
  }
  const std::vector<std::size_t> boxOfPoint =
    boxOfClusters(state, cornersOfWork, layout, LargestCluster, holding);
  if (std::find(cornersOfWork.begin(), cornersOfWork.end(), 1) == cornersOfWork.end())
  {
    candidates = 0;
    return status; // only clusters too large for one box
  }
  return runSweepOverBoxes(sweep, options, layout, cornersOfWork, state, summary, reporter,
    candidates, &boxOfPoint, holding);
}

} // namespace

Status improveAcrossFormerInterfaces(const ColorLoopSetup& setup, const AdaptationOptions& options,
  int boxesPerAxis, const std::vector<char>& formerInterface, AdaptationState& state,
  AdaptationSummary& summary, PhaseReporter& reporter)
{
  // Only former interface vertices are collapsed: the others were free in their partitions,
  // whose coarsening tried their short edges. With every short edge counted, the sweeps of the
  // FinFET with a size field built improvers over 7.1 M tets (of 5.8 M output tets), 4.9 M now.
  // Likewise a vertex a sweep tried while free is settled for the next (settledVertices): the
  // shifted layout tries those the first layout's box faces froze.
  ColorLoopSetup sweeps = setup;
  std::vector<char> collapsible = formerInterface;
  sweeps.improvement.collapsibleVertices = &collapsible;
  sweeps.improvement.settledVertices = &collapsible;
  // Box faces freeze vertices in their turn: a second layout shifted by half a box frees most of
  // them. Not all: a vertex near a face of the first layout along one axis and near a face of the
  // second along another is cut by both (on the FinFET, three slivers of 0.6 to 1.0 degrees
  // survived that way). The third sweep takes the work left in whole clusters, each in one box.
  // The tets that stayed out of a layout's boxes are as they were, so the next looks for work in
  // those boxes only.
  std::size_t candidates = state.partitions.size();
  std::vector<char> cornersOfWork;
  for (int sweepIndex = 0; sweepIndex < SweepCount && candidates > 0; ++sweepIndex)
  {
    Status status = improveOverBoxes(sweeps, options, boxesPerAxis, sweepIndex, formerInterface,
      candidates, cornersOfWork, state, summary, reporter);
    if (!status.ok() || summary.aborted)
    {
      return status;
    }
  }
  return Status::success();
}

} // namespace cgmesh
