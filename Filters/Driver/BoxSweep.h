// A sweep over box partitions: the tets that need work move into a grid of boxes that cuts across
// the refinement partitions, so that most former interfaces lie inside a box, and the colour loop
// runs once more over a colouring of the boxes. Both sweeps across former interfaces use it: the
// improvement sweep (ImprovementSweep.h) and the Delaunay sweep that meshes boxes anew
// (RemeshSweep.h).
#ifndef cgmesh_BoxSweep_h
#define cgmesh_BoxSweep_h

#include "ColorLoop.h"
#include "ParallelFor.h"
#include "Partitioning/BoxPartitions.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace cgmesh
{

// Flags, in `flagged` (sized to every point), the corners of the tets of the first `candidates`
// partitions that pass `selects`, looked at in parallel; returns how many tets passed. The tets
// a sweep works on: only those touching a flagged point go into its boxes. With `onlyLeft`, a
// partition whose improvement left is known is looked at in the tets it names alone (`selects`
// must then pass no tet that improvement would not work on).
template <typename Selects>
std::int64_t flagCornersOfSelectedTets(int threads, const AdaptationState& state,
  std::size_t candidates, const Selects& selects, std::vector<char>& flagged, Status& status,
  bool onlyLeft = false)
{
  std::vector<std::vector<PointId>> corners(candidates);
  status = runParallel(threads, static_cast<std::int64_t>(candidates),
    [&](std::int64_t p)
    {
      const TetList& tets = state.partitions[p].tets;
      const auto select = [&](const Tet& tet)
      {
        if (selects(tet))
        {
          corners[p].insert(corners[p].end(), tet.begin(), tet.end());
        }
      };
      const bool known = onlyLeft && static_cast<std::size_t>(p) < state.improvementLeft.size() &&
        state.improvementLeft[p].known && state.improvementLeft[p].tetCount == tets.size();
      if (known)
      {
        for (std::size_t t : state.improvementLeft[p].tets)
        {
          select(tets[t]);
        }
        return;
      }
      for (const Tet& tet : tets)
      {
        select(tet);
      }
    });
  flagged.resize(state.coordinates.size() / 3, 0);
  std::int64_t selected = 0;
  for (const std::vector<PointId>& list : corners)
  {
    selected += static_cast<std::int64_t>(list.size() / 4);
    for (PointId p : list)
    {
      flagged[p] = 1;
    }
  }
  return selected;
}

// Every tet that touches a flagged point lies in the first `holding` partitions of the state: a
// sweep looks for them there only. Such a bound comes from an earlier sweep, whose boxes took
// every tet around the points it flagged.
constexpr std::size_t AllPartitions = static_cast<std::size_t>(-1);

// Joins the flagged points that are corners of one tet into clusters and names, for each flagged
// point, the box of `layout` that holds its cluster's lowest point: given to runSweepOverBoxes,
// a cluster's tets go into one box, never cut by a box face. The points of a cluster of more
// than `largestCluster` points are unflagged instead: one box would hold it all, a serial task.
// The tets touching flagged points are looked for in the first `holding` partitions.
std::vector<std::size_t> boxOfClusters(const AdaptationState& state, std::vector<char>& flagged,
  const BoxLayout& layout, std::size_t largestCluster = static_cast<std::size_t>(-1),
  std::size_t holding = AllPartitions);

// Moves the tets that touch a point flagged in `moving` into the boxes of `layout` and runs
// `sweep` over them (its graph, colouring and colour count are the boxes'). The other tets stay
// in their partitions, which follow the boxes in `state.partitions` afterwards (emptied ones
// left out). `boxCount` becomes the number of boxes: the sweep's partitions are the first
// `boxCount` ones of `state.partitions`. `boxOfMovingPoint`, when given, names the box of each
// moving tet by its flagged corners (see regroupIntoBoxes). The moving tets are looked for in
// the first `holding` partitions only; the others are not read.
Status runSweepOverBoxes(ColorLoopSetup sweep, const AdaptationOptions& options,
  const BoxLayout& layout, const std::vector<char>& moving, AdaptationState& state,
  AdaptationSummary& summary, PhaseReporter& reporter, std::size_t& boxCount,
  const std::vector<std::size_t>* boxOfMovingPoint = nullptr, std::size_t holding = AllPartitions);

} // namespace cgmesh

#endif
