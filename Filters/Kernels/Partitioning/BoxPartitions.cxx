#include "Partitioning/BoxPartitions.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace cgmesh
{

std::size_t BoxLayout::numberOfBoxes() const
{
  const std::size_t n = static_cast<std::size_t>(this->boxesPerAxis());
  return n * n * n;
}

std::array<int, 3> BoxLayout::indexOf(const double* point) const
{
  std::array<int, 3> index;
  for (int axis = 0; axis < 3; ++axis)
  {
    index[axis] = std::max(0,
      std::min(this->cells,
        static_cast<int>(std::floor((point[axis] - this->low[axis]) / this->size[axis]))));
  }
  return index;
}

std::size_t BoxLayout::boxAt(const std::array<int, 3>& index) const
{
  const std::size_t n = static_cast<std::size_t>(this->boxesPerAxis());
  return (static_cast<std::size_t>(index[2]) * n + static_cast<std::size_t>(index[1])) * n +
    static_cast<std::size_t>(index[0]);
}

std::array<int, 3> BoxLayout::indexOfBox(std::size_t box) const
{
  const std::size_t n = static_cast<std::size_t>(this->boxesPerAxis());
  return { static_cast<int>(box % n), static_cast<int>(box / n % n),
    static_cast<int>(box / n / n) };
}

std::size_t BoxLayout::boxOf(const Tet& tet, const std::vector<double>& coordinates) const
{
  double centroid[3] = { 0, 0, 0 };
  for (int axis = 0; axis < 3; ++axis)
  {
    for (PointId p : tet)
    {
      centroid[axis] += 0.25 * coordinates[3 * p + axis];
    }
  }
  return this->boxAt(this->indexOf(centroid));
}

BoxLayout layBoxes(
  const std::vector<double>& coordinates, int cells, double shift, const ParallelFor& parallelFor)
{
  // Each range of points keeps its own bounds; min and max do not care how they are joined.
  using Bounds = std::array<double, 6>; // low x, y, z, high x, y, z
  constexpr double Largest = std::numeric_limits<double>::max();
  const std::int64_t points = static_cast<std::int64_t>(coordinates.size() / 3);
  std::vector<Bounds> boundsOfRange(
    static_cast<std::size_t>((points + IndicesPerCopyRange - 1) / IndicesPerCopyRange),
    Bounds{ Largest, Largest, Largest, -Largest, -Largest, -Largest });
  // The body neither allocates nor throws, so the runner has no failure to report.
  forEachRange(parallelFor, points, IndicesPerCopyRange,
    [&](std::int64_t begin, std::int64_t end)
    {
      Bounds& bounds = boundsOfRange[begin / IndicesPerCopyRange];
      for (std::int64_t p = begin; p < end; ++p)
      {
        for (int axis = 0; axis < 3; ++axis)
        {
          bounds[axis] = std::min(bounds[axis], coordinates[3 * p + axis]);
          bounds[3 + axis] = std::max(bounds[3 + axis], coordinates[3 * p + axis]);
        }
      }
    });
  BoxLayout layout;
  layout.cells = std::max(1, cells);
  for (int axis = 0; axis < 3; ++axis)
  {
    double lowest = Largest, highest = -Largest;
    for (const Bounds& bounds : boundsOfRange)
    {
      lowest = std::min(lowest, bounds[axis]);
      highest = std::max(highest, bounds[3 + axis]);
    }
    layout.size[axis] = highest > lowest ? (highest - lowest) / layout.cells : 1.0;
    layout.low[axis] = lowest - shift * layout.size[axis];
  }
  return layout;
}

namespace
{

// A partition's tets for the boxes, sorted by (box, tet) as (box << 32 | tet) keys, with the runs
// of one box among them.
struct MovingTets
{
  std::vector<std::uint64_t> keys;
  struct Run
  {
    std::size_t box;
    std::size_t begin, end; // in keys
  };
  std::vector<Run> runs;
};

bool moves(const Tet& tet, const std::vector<char>* movingIfFlagged)
{
  return !movingIfFlagged || touchesFlaggedPoint(tet, *movingIfFlagged);
}

// The box a moving tet goes to: its centroid's, or with `boxOfFlaggedPoint` the entry of its
// first flagged corner.
std::size_t boxOfMovingTet(const Tet& tet, const std::vector<double>& coordinates,
  const BoxLayout& layout, const std::vector<char>* movingIfFlagged,
  const std::vector<std::size_t>* boxOfFlaggedPoint)
{
  if (boxOfFlaggedPoint)
  {
    for (PointId p : tet)
    {
      if ((*movingIfFlagged)[p])
      {
        return (*boxOfFlaggedPoint)[p];
      }
    }
  }
  return layout.boxOf(tet, coordinates);
}

MovingTets sortMovingTets(const PartitionMesh& partition, const std::vector<double>& coordinates,
  const BoxLayout& layout, const std::vector<char>* movingIfFlagged,
  const std::vector<std::size_t>* boxOfFlaggedPoint)
{
  MovingTets moving;
  for (std::size_t t = 0; t < partition.tets.size(); ++t)
  {
    const Tet& tet = partition.tets[t];
    if (moves(tet, movingIfFlagged))
    {
      const std::size_t box =
        boxOfMovingTet(tet, coordinates, layout, movingIfFlagged, boxOfFlaggedPoint);
      moving.keys.push_back((static_cast<std::uint64_t>(box) << 32) | t);
    }
  }
  std::sort(moving.keys.begin(), moving.keys.end());
  for (std::size_t i = 0; i < moving.keys.size(); ++i)
  {
    const std::size_t box = static_cast<std::size_t>(moving.keys[i] >> 32);
    if (moving.runs.empty() || moving.runs.back().box != box)
    {
      moving.runs.push_back({ box, i, i });
    }
    moving.runs.back().end = i + 1;
  }
  return moving;
}

std::size_t tetOfKey(std::uint64_t key)
{
  return static_cast<std::size_t>(key & 0xffffffffu);
}

// Copies tet `t` of `from` to position `at` of `to`, which is sized for it.
void copyTetTo(const PartitionMesh& from, std::size_t t, PartitionMesh& to, std::size_t at)
{
  to.tets[at] = from.tets[t];
  to.parentCells[at] = from.parentCells[t];
  if (!from.regions.empty())
  {
    to.regions[at] = from.regions[t];
  }
}

void resizeMesh(PartitionMesh& mesh, std::size_t tets, bool withRegions)
{
  mesh.tets.resize(tets);
  mesh.parentCells.resize(tets);
  mesh.regions.resize(withRegions ? tets : 0);
}

// Keeps, in place, the tets of `partition` that do not move (removeTetsAt: compacting in order
// wrote every tet after the first that moved, 0.014 s of the FinFET's first sweep at one thread).
void keepStaying(PartitionMesh& partition, const MovingTets& moving)
{
  if (moving.keys.empty())
  {
    return; // nothing leaves: no copy
  }
  if (moving.keys.size() == partition.tets.size())
  {
    partition = PartitionMesh();
    return;
  }
  std::vector<std::size_t> leaving;
  leaving.reserve(moving.keys.size());
  for (std::uint64_t key : moving.keys)
  {
    leaving.push_back(tetOfKey(key));
  }
  std::sort(leaving.begin(), leaving.end());
  removeTetsAt(partition, leaving);
  if (2 * partition.tets.size() < partition.tets.capacity())
  {
    partition.tets.shrink_to_fit(); // most tets moved out: give their memory back
    partition.parentCells.shrink_to_fit();
    partition.regions.shrink_to_fit();
  }
}

} // namespace

Status regroupIntoBoxes(std::vector<PartitionMesh>& partitions,
  const std::vector<double>& coordinates, const BoxLayout& layout, const ParallelFor& parallelFor,
  std::vector<PartitionMesh>& boxes, const std::vector<char>* movingIfFlagged,
  const std::vector<std::size_t>* boxOfFlaggedPoint)
{
  if (std::any_of(partitions.begin(), partitions.end(),
        [](const PartitionMesh& partition) { return partition.tets.size() >> 32 != 0; }))
  {
    return Status::failure(
      ErrorKind::SizeLimit, "a partition of 2^32 tets or more cannot be regrouped into boxes");
  }
  const bool withRegions = std::any_of(partitions.begin(), partitions.end(),
    [](const PartitionMesh& partition) { return !partition.regions.empty(); });
  const std::int64_t partitionCount = static_cast<std::int64_t>(partitions.size());
  std::vector<MovingTets> moving(partitions.size());
  Status status = parallelFor(partitionCount,
    [&](std::int64_t p)
    {
      moving[p] =
        sortMovingTets(partitions[p], coordinates, layout, movingIfFlagged, boxOfFlaggedPoint);
    });
  if (!status.ok())
  {
    return status;
  }

  // Per box, the runs that go there, in partition order: counted, then filled (compressed rows).
  struct Source
  {
    int partition;
    std::size_t run;
  };
  const std::size_t boxCount = layout.numberOfBoxes();
  std::vector<std::size_t> firstSource(boxCount + 1, 0), boxSize(boxCount, 0);
  for (std::size_t p = 0; p < moving.size(); ++p)
  {
    for (const MovingTets::Run& run : moving[p].runs)
    {
      ++firstSource[run.box + 1];
      boxSize[run.box] += run.end - run.begin;
    }
  }
  for (std::size_t b = 0; b < boxCount; ++b)
  {
    firstSource[b + 1] += firstSource[b];
  }
  std::vector<Source> sources(firstSource.back());
  {
    std::vector<std::size_t> next(firstSource.begin(), firstSource.end() - 1);
    for (std::size_t p = 0; p < moving.size(); ++p)
    {
      for (std::size_t r = 0; r < moving[p].runs.size(); ++r)
      {
        sources[next[moving[p].runs[r].box]++] = { static_cast<int>(p), r };
      }
    }
  }

  boxes.assign(boxCount, PartitionMesh());
  status = parallelFor(static_cast<std::int64_t>(boxCount),
    [&](std::int64_t b)
    {
      PartitionMesh& box = boxes[b];
      resizeMesh(box, boxSize[b], withRegions);
      std::size_t at = 0;
      for (std::size_t s = firstSource[b]; s < firstSource[b + 1]; ++s)
      {
        const MovingTets& tetsOfSource = moving[sources[s].partition];
        const MovingTets::Run& run = tetsOfSource.runs[sources[s].run];
        for (std::size_t i = run.begin; i < run.end; ++i)
        {
          copyTetTo(partitions[sources[s].partition], tetOfKey(tetsOfSource.keys[i]), box, at++);
        }
      }
    });
  if (!status.ok())
  {
    return status;
  }
  return parallelFor(partitionCount,
    [&](std::int64_t p)
    {
      keepStaying(partitions[p], moving[p]);
      moving[p] = MovingTets();
    });
}

Status regroupByCellPartition(std::vector<PartitionMesh>& partitions,
  const std::vector<int>& partitionOfCell, int numberOfPartitions, const ParallelFor& parallelFor,
  std::vector<PartitionMesh>& regrouped)
{
  const bool withRegions = std::any_of(partitions.begin(), partitions.end(),
    [](const PartitionMesh& partition) { return !partition.regions.empty(); });
  const std::size_t destinations = static_cast<std::size_t>(numberOfPartitions);
  regrouped.assign(destinations, PartitionMesh());
  // A partition whose tets all go to one destination is taken over whole when it is the first
  // such for its destination: after a sweep those are the partitions the boxes left, nearly all
  // the tets, and the copy below sees only the boxes' tets (on the FinFET 0.045 s at one thread
  // for the copy of all 844,000 input tets).
  std::vector<int> wholeTo(partitions.size(), -1);
  Status status = parallelFor(static_cast<std::int64_t>(partitions.size()),
    [&](std::int64_t p)
    {
      const PartitionMesh& partition = partitions[p];
      if (partition.tets.empty())
      {
        return;
      }
      const int to = partitionOfCell[partition.parentCells.front()];
      for (CellId parent : partition.parentCells)
      {
        if (partitionOfCell[parent] != to)
        {
          return;
        }
      }
      wholeTo[p] = to;
    });
  if (!status.ok())
  {
    return status;
  }
  std::vector<char> taken(destinations, 0);
  for (std::size_t p = 0; p < partitions.size(); ++p)
  {
    if (wholeTo[p] >= 0 && !taken[wholeTo[p]] && partitions[p].regions.empty() != withRegions)
    {
      taken[wholeTo[p]] = 1;
      regrouped[wholeTo[p]] = std::move(partitions[p]);
      partitions[p] = PartitionMesh();
    }
  }

  // The other tets, one after another, in ranges of IndicesPerCopyRange: a range counts its tets
  // per destination, the counts' running sums in range order give each range its place in every
  // destination after the tets taken over, and the ranges copy concurrently (a stable counting
  // sort).
  std::vector<std::int64_t> firstTet(partitions.size() + 1, 0);
  for (std::size_t p = 0; p < partitions.size(); ++p)
  {
    firstTet[p + 1] = firstTet[p] + static_cast<std::int64_t>(partitions[p].tets.size());
  }
  const std::int64_t tets = firstTet.back();
  const std::int64_t ranges = (tets + IndicesPerCopyRange - 1) / IndicesPerCopyRange;
  // Calls visit(partition, tet) for the tets of range `range`, in order.
  auto forEachTetOfRange = [&](std::int64_t range, auto&& visit)
  {
    const std::int64_t begin = range * IndicesPerCopyRange;
    const std::int64_t end = std::min(tets, begin + IndicesPerCopyRange);
    std::size_t p = static_cast<std::size_t>(
      std::upper_bound(firstTet.begin(), firstTet.end(), begin) - firstTet.begin() - 1);
    for (std::int64_t i = begin; i < end; ++i)
    {
      while (i == firstTet[p + 1])
      {
        ++p;
      }
      visit(partitions[p], static_cast<std::size_t>(i - firstTet[p]));
    }
  };
  std::vector<std::int64_t> place(static_cast<std::size_t>(ranges) * destinations, 0);
  status = parallelFor(ranges,
    [&](std::int64_t range)
    {
      std::int64_t* const count = place.data() + range * numberOfPartitions;
      forEachTetOfRange(range,
        [&](const PartitionMesh& from, std::size_t t)
        { ++count[partitionOfCell[from.parentCells[t]]]; });
    });
  if (!status.ok())
  {
    return status;
  }
  std::vector<std::int64_t> size(destinations, 0);
  for (std::size_t d = 0; d < destinations; ++d)
  {
    size[d] = static_cast<std::int64_t>(regrouped[d].tets.size());
  }
  for (std::int64_t range = 0; range < ranges; ++range)
  {
    for (std::size_t d = 0; d < destinations; ++d)
    {
      const std::int64_t count = place[range * numberOfPartitions + d];
      place[range * numberOfPartitions + d] = size[d];
      size[d] += count;
    }
  }
  status = parallelFor(numberOfPartitions,
    [&](std::int64_t d)
    { resizeMesh(regrouped[d], static_cast<std::size_t>(size[d]), withRegions); });
  if (status.ok())
  {
    status = parallelFor(ranges,
      [&](std::int64_t range)
      {
        std::int64_t* const next = place.data() + range * numberOfPartitions;
        forEachTetOfRange(range,
          [&](const PartitionMesh& from, std::size_t t)
          {
            const int d = partitionOfCell[from.parentCells[t]];
            copyTetTo(from, t, regrouped[d], static_cast<std::size_t>(next[d]++));
          });
      });
  }
  if (!status.ok())
  {
    return status;
  }
  return parallelFor(static_cast<std::int64_t>(partitions.size()),
    [&](std::int64_t p) { partitions[p] = PartitionMesh(); });
}

namespace
{

// The axis-aligned bounding box of a box's tet corners; empty when the box has no tet.
struct CornerBounds
{
  double low[3] = { std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
    std::numeric_limits<double>::max() };
  double high[3] = { -std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
    -std::numeric_limits<double>::max() };
  bool empty() const { return this->low[0] > this->high[0]; }
  bool meets(const CornerBounds& other) const
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      if (this->high[axis] < other.low[axis] || other.high[axis] < this->low[axis])
      {
        return false;
      }
    }
    return true;
  }
};

// How many boxes beyond its own box `bounds` reaches along any axis.
int reachInBoxes(
  const CornerBounds& bounds, const std::array<int, 3>& index, const BoxLayout& layout)
{
  int reach = 0;
  for (int axis = 0; axis < 3; ++axis)
  {
    const double boxLow = layout.low[axis] + index[axis] * layout.size[axis];
    const double below = (boxLow - bounds.low[axis]) / layout.size[axis];
    const double above = (bounds.high[axis] - boxLow) / layout.size[axis] - 1.0;
    reach = std::max(reach, static_cast<int>(std::ceil(std::max({ below, above, 0.0 }))));
  }
  return reach;
}

} // namespace

Status buildBoxGraph(const std::vector<PartitionMesh>& boxes,
  const std::vector<double>& coordinates, const BoxLayout& layout, const ParallelFor& parallelFor,
  PartitionGraph& graph)
{
  const std::int64_t boxCount = static_cast<std::int64_t>(boxes.size());
  std::vector<CornerBounds> bounds(boxes.size());
  std::vector<int> reach(boxes.size(), 0);
  const int n = layout.boxesPerAxis();
  Status status = parallelFor(boxCount,
    [&](std::int64_t b)
    {
      CornerBounds& box = bounds[b];
      for (const Tet& tet : boxes[b].tets)
      {
        for (PointId p : tet)
        {
          for (int axis = 0; axis < 3; ++axis)
          {
            box.low[axis] = std::min(box.low[axis], coordinates[3 * p + axis]);
            box.high[axis] = std::max(box.high[axis], coordinates[3 * p + axis]);
          }
        }
      }
      reach[b] = box.empty() ? 0 : reachInBoxes(box, layout.indexOfBox(b), layout);
    });
  if (!status.ok())
  {
    return status;
  }
  const int farthest = reach.empty() ? 0 : *std::max_element(reach.begin(), reach.end());
  if (farthest > 3)
  {
    return buildPartitionGraph(
      boxes, static_cast<PointId>(coordinates.size() / 3), parallelFor, graph);
  }

  // Corners' bounds reach `farthest` boxes beyond their own box at most, so two that meet lie at
  // most 2 * farthest + 1 boxes apart along every axis.
  std::vector<std::vector<int>> rows(boxes.size());
  status = parallelFor(boxCount,
    [&](std::int64_t b)
    {
      if (bounds[b].empty())
      {
        return;
      }
      const std::array<int, 3> at = layout.indexOfBox(b);
      const int span = 2 * farthest + 1;
      std::array<int, 3> from, to;
      for (int axis = 0; axis < 3; ++axis)
      {
        from[axis] = std::max(0, at[axis] - span);
        to[axis] = std::min(n - 1, at[axis] + span);
      }
      for (int z = from[2]; z <= to[2]; ++z)
      {
        for (int y = from[1]; y <= to[1]; ++y)
        {
          for (int x = from[0]; x <= to[0]; ++x)
          {
            const std::size_t other = layout.boxAt({ x, y, z });
            if (static_cast<std::int64_t>(other) != b && !bounds[other].empty() &&
              bounds[b].meets(bounds[other]))
            {
              rows[b].push_back(static_cast<int>(other)); // ascending: x fastest
            }
          }
        }
      }
    });
  if (!status.ok())
  {
    return status;
  }
  graph = PartitionGraph();
  graph.numberOfPartitions = static_cast<int>(boxes.size());
  graph.offsets.assign(boxes.size() + 1, 0);
  for (std::size_t b = 0; b < boxes.size(); ++b)
  {
    graph.offsets[b + 1] = graph.offsets[b] + static_cast<std::int64_t>(rows[b].size());
  }
  graph.neighbours.reserve(static_cast<std::size_t>(graph.offsets.back()));
  for (const std::vector<int>& row : rows)
  {
    graph.neighbours.insert(graph.neighbours.end(), row.begin(), row.end());
  }
  return Status::success();
}

} // namespace cgmesh
