#include "RemeshSweep.h"

#include "BoxSweep.h"
#include "Core/TetQuality.h"

#include <algorithm>
#include <atomic>

namespace cgmesh
{
namespace
{

// Flags the corners of the tets at former interface vertices (at any vertex without
// `formerInterface`) under SweepSliverDegrees, then grows the flags SweepRings times by the
// corners of every tet touching one. Flags nothing unless the tets there under
// RemeshSliverDegrees are more than RemeshSliverShare of all tets, the rule a partition is meshed
// anew by: improvement mends a few slivers at a fraction of the cost.
Status flagAroundSlivers(int threads, const std::vector<char>* formerInterface,
  const AdaptationState& state, std::vector<char>& flagged, bool& found)
{
  const std::vector<double>& xyz = state.coordinates;
  flagged.assign(xyz.size() / 3, 0);
  std::atomic<std::int64_t> severe(0);
  Status status = Status::success();
  flagCornersOfSelectedTets(
    threads, state, state.partitions.size(),
    [&](const Tet& tet)
    {
      if (formerInterface && !touchesFlaggedPoint(tet, *formerInterface))
      {
        return false;
      }
      const double angle = minimumDihedralAngle(xyz.data() + 3 * tet[0], xyz.data() + 3 * tet[1],
        xyz.data() + 3 * tet[2], xyz.data() + 3 * tet[3]);
      if (angle < RemeshSliverDegrees)
      {
        ++severe;
      }
      return angle < SweepSliverDegrees;
    },
    flagged, status);
  std::size_t tets = 0;
  for (const PartitionMesh& partition : state.partitions)
  {
    tets += partition.tets.size();
  }
  found = exceedsSliverShare(severe.load(), tets);
  if (!found)
  {
    flagged.clear();
  }
  for (int ring = 0; ring < SweepRings && status.ok() && found; ++ring)
  {
    const std::vector<char> before = flagged;
    flagCornersOfSelectedTets(
      threads, state, state.partitions.size(),
      [&](const Tet& tet) { return touchesFlaggedPoint(tet, before); }, flagged, status);
  }
  return status;
}

// Meshes the clusters around the flagged slivers anew with `sweep`, each whole in one box.
Status remeshAroundSlivers(const ColorLoopSetup& sweep, const AdaptationOptions& options,
  int boxesPerAxis, const std::vector<char>* formerInterface, AdaptationState& state,
  AdaptationSummary& summary, PhaseReporter& reporter, bool& found)
{
  reporter.enter(Phase::Adapt);
  std::vector<char> moving;
  Status status = flagAroundSlivers(sweep.threads, formerInterface, state, moving, found);
  if (!status.ok() || !found)
  {
    return status;
  }
  const BoxLayout layout =
    layBoxes(state.coordinates, boxesPerAxis, 0, parallelForOn(sweep.threads));
  const std::vector<std::size_t> boxOfPoint = boxOfClusters(state, moving, layout);
  std::size_t boxes = 0;
  return runSweepOverBoxes(
    sweep, options, layout, moving, state, summary, reporter, boxes, &boxOfPoint);
}

ColorLoopSetup remeshingSweep(const ColorLoopSetup& setup)
{
  ColorLoopSetup sweep = setup;
  sweep.refine = true;
  sweep.remeshSweep = true;
  sweep.improve = false;
  return sweep;
}

} // namespace

Status remeshAcrossFormerInterfaces(const ColorLoopSetup& setup, const AdaptationOptions& options,
  int boxesPerAxis, const std::vector<char>& formerInterface, AdaptationState& state,
  AdaptationSummary& summary, PhaseReporter& reporter)
{
  bool found = false;
  return remeshAroundSlivers(remeshingSweep(setup), options, boxesPerAxis, &formerInterface, state,
    summary, reporter, found);
}

Status countSlivers(int threads, const AdaptationState& state, SliverCount& count)
{
  std::vector<std::int64_t> slivers(state.partitions.size(), 0);
  const std::vector<double>& xyz = state.coordinates;
  const double ceiling = meanRatioCeiling(RemeshSliverDegrees);
  const Status status = runParallel(threads, static_cast<std::int64_t>(state.partitions.size()),
    [&](std::int64_t p)
    {
      for (const Tet& tet : state.partitions[p].tets)
      {
        slivers[p] +=
          minimumDihedralAngleBelow(xyz.data() + 3 * tet[0], xyz.data() + 3 * tet[1],
            xyz.data() + 3 * tet[2], xyz.data() + 3 * tet[3], RemeshSliverDegrees, ceiling)
          ? 1
          : 0;
      }
    });
  count = SliverCount();
  for (std::size_t p = 0; p < slivers.size(); ++p)
  {
    count.slivers += slivers[p];
    count.tets += static_cast<std::int64_t>(state.partitions[p].tets.size());
  }
  return status;
}

Status remeshSliverClusters(const ColorLoopSetup& setup, const AdaptationOptions& options,
  int boxesPerAxis, AdaptationState& state, AdaptationSummary& summary, PhaseReporter& reporter,
  bool& remeshed)
{
  ColorLoopSetup sweep = remeshingSweep(setup);
  sweep.numberOfIterations = 1;
  sweep.delaunay.shapesOnly = true;
  remeshed = false;
  return remeshAroundSlivers(
    sweep, options, boxesPerAxis, nullptr, state, summary, reporter, remeshed);
}

} // namespace cgmesh
