#include "Refinement/SizeField.h"

#include "Core/Geometry.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <queue>
#include <string>
#include <utility>

namespace cgmesh
{
namespace
{

// The edges of a mesh by their lower end: the higher ends met from point p are
// ends[offsets[p]] to ends[offsets[p + 1] - 1], an edge once per tet that holds it, in the order
// of a walk over the tets; the gradation and the measurement then read each point's ends in
// order. Gathering the tets around each point instead cost a cache miss per tet: the merge phase,
// which holds the measurement, took 0.34 s instead of 0.43 on the graded Big cube (1.7 M tets, 2
// threads) and 1.2 s instead of 1.47 on the FinFET with its size field (5.9 M tets).
template <typename End>
struct HigherEnds
{
  std::vector<std::int64_t> offsets;
  // Not zeroed on allocation: every entry is written, by the threads that build the lists.
  std::unique_ptr<End[]> ends;
};

// Lower ends go in ranges of this many points, each sorted on its own: an end's place in its
// range fits 16 bits.
constexpr std::int64_t PointsPerEdgeRange = 8192;

// HigherEnds built concurrently, the same lists as one walk over the tets makes. Blocks of
// consecutive tets count their edge copies per range of lower ends, which places every (block,
// range) group: a range's stretch holds its blocks' copies in block order. Each block then writes
// its copies (the higher end, and the lower end's place in its range) to its groups, and each
// range sorts its stretch by lower end with a stable counting sort. Done in one walk on one
// thread, this was the serial 0.10-0.14 s of the graded Big cube's edge measure (0.30 s at 2
// threads in all).
template <typename End>
Status higherEnds(const TetMesh& mesh, const ParallelFor& parallelFor, HigherEnds<End>& edges)
{
  const std::int64_t pointCount = mesh.numberOfPoints();
  const std::int64_t tetCount = static_cast<std::int64_t>(mesh.tets.size());
  const std::int64_t ranges =
    std::max<std::int64_t>(1, (pointCount + PointsPerEdgeRange - 1) / PointsPerEdgeRange);
  // At most 256 blocks: the counts per (block, range) stay a few MB on a 10^9-tet mesh.
  const std::int64_t tetsPerBlock =
    std::max<std::int64_t>(IndicesPerCopyRange, (tetCount + 255) / 256);
  const std::int64_t blocks =
    std::max<std::int64_t>(1, (tetCount + tetsPerBlock - 1) / tetsPerBlock);
  const auto rangeOf = [](PointId p)
  {
    return static_cast<std::int64_t>(p) / PointsPerEdgeRange;
  };
  const auto forEachCopy = [&](std::int64_t block, const auto& visit)
  {
    const std::int64_t end = std::min(tetCount, (block + 1) * tetsPerBlock);
    for (std::int64_t t = block * tetsPerBlock; t < end; ++t)
    {
      const Tet& tet = mesh.tets[static_cast<std::size_t>(t)];
      for (const auto& corners : TetEdgeCorners)
      {
        const PointId a = tet[corners[0]], b = tet[corners[1]];
        visit(std::min(a, b), std::max(a, b));
      }
    }
  };

  // place[block * ranges + range]: the group's size, then where it starts.
  std::vector<std::int64_t> place(static_cast<std::size_t>(blocks * ranges), 0);
  Status status = parallelFor(blocks,
    [&](std::int64_t block)
    {
      std::int64_t* row = place.data() + block * ranges;
      forEachCopy(block, [&](PointId low, PointId) { ++row[rangeOf(low)]; });
    });
  if (!status.ok())
  {
    return status;
  }
  std::vector<std::int64_t> rangeStart(static_cast<std::size_t>(ranges) + 1, 0);
  std::int64_t total = 0;
  for (std::int64_t range = 0; range < ranges; ++range)
  {
    rangeStart[range] = total;
    for (std::int64_t block = 0; block < blocks; ++block)
    {
      std::int64_t& group = place[block * ranges + range];
      const std::int64_t size = group;
      group = total;
      total += size;
    }
  }
  rangeStart[ranges] = total;

  edges.ends.reset(new End[static_cast<std::size_t>(total)]);
  const std::unique_ptr<std::uint16_t[]> placeInRange(
    new std::uint16_t[static_cast<std::size_t>(total)]);
  status = parallelFor(blocks,
    [&](std::int64_t block)
    {
      std::int64_t* next = place.data() + block * ranges;
      forEachCopy(block,
        [&](PointId low, PointId high)
        {
          const std::int64_t position = next[rangeOf(low)]++;
          edges.ends[position] = static_cast<End>(high);
          placeInRange[position] = static_cast<std::uint16_t>(low % PointsPerEdgeRange);
        });
    });
  if (!status.ok())
  {
    return status;
  }

  edges.offsets.assign(static_cast<std::size_t>(pointCount) + 1, total);
  return parallelFor(ranges,
    [&](std::int64_t range)
    {
      const std::int64_t begin = rangeStart[range], end = rangeStart[range + 1];
      const std::int64_t firstPoint = range * PointsPerEdgeRange;
      const std::int64_t points = std::min(PointsPerEdgeRange, pointCount - firstPoint);
      std::vector<std::int64_t> next(static_cast<std::size_t>(points) + 1, 0);
      for (std::int64_t k = begin; k < end; ++k)
      {
        ++next[placeInRange[k] + 1];
      }
      for (std::int64_t p = 0; p < points; ++p)
      {
        next[p + 1] += next[p];
        edges.offsets[firstPoint + p] = begin + next[p];
      }
      std::vector<End> sorted(static_cast<std::size_t>(end - begin));
      for (std::int64_t k = begin; k < end; ++k)
      {
        sorted[next[placeInRange[k]]++] = edges.ends[k];
      }
      std::copy(sorted.begin(), sorted.end(), edges.ends.get() + begin);
    });
}

// Every edge of the mesh once, as (low id, high id): by low id, each low id's partners in the
// order its tets meet them, repeats dropped with one mark per partner. Sorting all 6n edge copies
// instead took 1.2 s on a 2 M-tet mesh.
std::vector<std::pair<PointId, PointId>> uniqueEdges(const TetMesh& mesh)
{
  const std::size_t pointCount = static_cast<std::size_t>(mesh.numberOfPoints());
  HigherEnds<PointId> higher;
  // On the calling thread, where a failure can only be a thrown exception, which goes on up.
  higherEnds(mesh, ParallelFor(runSerially), higher);
  std::vector<std::pair<PointId, PointId>> edges;
  edges.reserve(pointCount * 7);
  std::vector<PointId> lastPartnerOf(pointCount, -1); // b was met as a's partner when a
  for (std::size_t a = 0; a < pointCount; ++a)
  {
    const PointId low = static_cast<PointId>(a);
    for (std::int64_t k = higher.offsets[a]; k < higher.offsets[a + 1]; ++k)
    {
      const PointId b = higher.ends[k];
      if (lastPartnerOf[b] != low)
      {
        lastPartnerOf[b] = low;
        edges.emplace_back(low, b);
      }
    }
  }
  return edges;
}

// Points per task of the edge measurement: each reads about 35 higher ends.
constexpr std::int64_t PointsPerMeasuringRange = 8192;

// measureEdgeSizes() over the edges by lower end: ranges of points run concurrently, each
// counting its points' distinct higher ends, and their counts are summed (the same for any
// schedule).
template <typename End>
Status measureEdgeSizesOf(const TetMesh& mesh, const HigherEnds<End>& edges,
  const ParallelFor& parallelFor, EdgeSizeReport& report)
{
  const std::int64_t pointCount = mesh.numberOfPoints();
  const std::int64_t ranges = (pointCount + PointsPerMeasuringRange - 1) / PointsPerMeasuringRange;
  std::vector<EdgeSizeReport> reports(ranges);
  std::vector<std::int64_t> withinOfRange(ranges, 0);
  const double bounds[5] = { 0.5, std::sqrt(0.5), 1.0, std::sqrt(2.0), 2.0 };
  const Status status = forEachRange(parallelFor, pointCount, PointsPerMeasuringRange,
    [&](std::int64_t begin, std::int64_t end)
    {
      EdgeSizeReport& counts = reports[begin / PointsPerMeasuringRange];
      std::int64_t& within = withinOfRange[begin / PointsPerMeasuringRange];
      std::vector<End> distinct;
      for (PointId a = static_cast<PointId>(begin); a < end; ++a)
      {
        // A dozen or so distinct ends, each met several times: a linear search of those found
        // so far is cheaper than sorting.
        distinct.clear();
        for (std::int64_t k = edges.offsets[a]; k < edges.offsets[a + 1]; ++k)
        {
          if (std::find(distinct.begin(), distinct.end(), edges.ends[k]) == distinct.end())
          {
            distinct.push_back(edges.ends[k]);
          }
        }
        for (const End end : distinct)
        {
          const PointId b = static_cast<PointId>(end);
          if (!std::isfinite(mesh.sizes[a]) || !std::isfinite(mesh.sizes[b]))
          {
            continue; // outside a refinement selection: the field does not apply there
          }
          const double length = std::sqrt(squaredEdgeLength(mesh, a, b));
          const double ratio = length / (0.5 * (mesh.sizes[a] + mesh.sizes[b]));
          const int bin = static_cast<int>(std::upper_bound(bounds, bounds + 5, ratio) - bounds);
          ++counts.histogram[bin];
          ++counts.edges;
          // Both ends belong to the interval; an edge of exactly sqrt(2) h is not split.
          within += ratio >= bounds[1] * (1 - 1e-12) && ratio <= bounds[3] * (1 + 1e-12);
        }
      }
    });
  report = EdgeSizeReport();
  std::int64_t within = 0;
  for (std::int64_t range = 0; range < ranges; ++range)
  {
    report.edges += reports[range].edges;
    within += withinOfRange[range];
    for (std::size_t bin = 0; bin < report.histogram.size(); ++bin)
    {
      report.histogram[bin] += reports[range].histogram[bin];
    }
  }
  report.shareWithinBounds =
    report.edges > 0 ? static_cast<double>(within) / static_cast<double>(report.edges) : 0;
  return status;
}

} // namespace

Status checkSizeField(const TetMesh& mesh)
{
  if (mesh.sizes.size() != static_cast<std::size_t>(mesh.numberOfPoints()))
  {
    return Status::failure(ErrorKind::InvalidInput,
      "the size field has " + std::to_string(mesh.sizes.size()) + " values for " +
        std::to_string(mesh.numberOfPoints()) + " points");
  }
  for (const Tet& tet : mesh.tets)
  {
    for (PointId p : tet)
    {
      const double h = mesh.sizes[p];
      if (!(h > 0) || !std::isfinite(h))
      {
        return Status::failure(ErrorKind::InvalidInput,
          "the size field's value at point " + std::to_string(p) + " is " + std::to_string(h) +
            "; sizes must be positive and finite");
      }
    }
  }
  return Status::success();
}

void limitSizeGradation(const TetMesh& mesh, double gradation, std::vector<double>& sizes)
{
  // Dijkstra on the edge graph with multiplicative path costs: points leave the queue smallest
  // size first (ties by id), and each lowers its neighbours to at most its size times gradation.
  const auto edges = uniqueEdges(mesh);
  const std::size_t pointCount = sizes.size();
  std::vector<std::int64_t> offsets(pointCount + 1, 0);
  for (const auto& edge : edges)
  {
    ++offsets[edge.first + 1];
    ++offsets[edge.second + 1];
  }
  for (std::size_t p = 0; p < pointCount; ++p)
  {
    offsets[p + 1] += offsets[p];
  }
  std::vector<PointId> neighbours(offsets.back());
  std::vector<std::int64_t> fill(offsets.begin(), offsets.end() - 1);
  for (const auto& edge : edges)
  {
    neighbours[fill[edge.first]++] = edge.second;
    neighbours[fill[edge.second]++] = edge.first;
  }

  using Entry = std::pair<double, PointId>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (std::size_t p = 0; p < pointCount; ++p)
  {
    if (offsets[p + 1] > offsets[p])
    {
      queue.emplace(sizes[p], static_cast<PointId>(p));
    }
  }
  std::vector<char> settled(pointCount, 0);
  while (!queue.empty())
  {
    const auto [size, p] = queue.top();
    queue.pop();
    if (settled[p] || size != sizes[p])
    {
      continue;
    }
    settled[p] = 1;
    const double bound = size * gradation;
    for (std::int64_t k = offsets[p]; k < offsets[p + 1]; ++k)
    {
      const PointId q = neighbours[k];
      if (!settled[q] && sizes[q] > bound)
      {
        sizes[q] = bound;
        queue.emplace(bound, q);
      }
    }
  }
}

Status measureEdgeSizes(const TetMesh& mesh, const ParallelFor& parallelFor, EdgeSizeReport& report)
{
  // Point ids fit 32 bits on any mesh this machine holds; the wider list is for the rest.
  const auto measure = [&](auto edges)
  {
    const Status listed = higherEnds(mesh, parallelFor, edges);
    return listed.ok() ? measureEdgeSizesOf(mesh, edges, parallelFor, report) : listed;
  };
  if (mesh.numberOfPoints() <= static_cast<PointId>(std::numeric_limits<std::uint32_t>::max()))
  {
    return measure(HigherEnds<std::uint32_t>());
  }
  return measure(HigherEnds<PointId>());
}

Status edgeLengthRatios(
  const TetMesh& mesh, const ParallelFor& parallelFor, std::vector<double>& ratios)
{
  ratios.assign(mesh.tets.size(), 0.0);
  return forEachRange(parallelFor, static_cast<std::int64_t>(mesh.tets.size()), IndicesPerCopyRange,
    [&](std::int64_t begin, std::int64_t end)
    {
      for (std::int64_t t = begin; t < end; ++t)
      {
        const Tet& tet = mesh.tets[t];
        double longest = 0;
        for (const auto& corners : TetEdgeCorners)
        {
          longest = std::max(longest, squaredEdgeLength(mesh, tet[corners[0]], tet[corners[1]]));
        }
        const double meanSize = 0.25 *
          (mesh.sizes[tet[0]] + mesh.sizes[tet[1]] + mesh.sizes[tet[2]] + mesh.sizes[tet[3]]);
        ratios[t] = std::isfinite(meanSize) ? std::sqrt(longest) / meanSize : 0.0;
      }
    });
}

double regularTetsFilling(
  const Tet& tet, const std::vector<double>& coordinates, const std::vector<double>& sizes)
{
  const double volume =
    signedVolume6(coordinates.data() + 3 * tet[0], coordinates.data() + 3 * tet[1],
      coordinates.data() + 3 * tet[2], coordinates.data() + 3 * tet[3]) /
    6.0;
  const double size = 0.25 * (sizes[tet[0]] + sizes[tet[1]] + sizes[tet[2]] + sizes[tet[3]]);
  return volume / (size * size * size / (6.0 * std::sqrt(2.0))); // the regular tet's volume
}

std::vector<std::int64_t> forecastWeights(const TetMesh& mesh)
{
  const std::size_t count = mesh.tets.size();
  std::vector<double> forecast(count, 0.0);
  double total = 0;
  for (std::size_t t = 0; t < count; ++t)
  {
    forecast[t] = regularTetsFilling(mesh.tets[t], mesh.coordinates, mesh.sizes);
    total += forecast[t];
  }
  const double mean = std::min(16.0, std::ldexp(1.0, 30) / std::max<double>(1.0, count));
  const double scale = total > 0 ? mean * static_cast<double>(count) / total : 0.0;
  std::vector<std::int64_t> weights(count);
  for (std::size_t t = 0; t < count; ++t)
  {
    weights[t] = 1 + std::llround(scale * forecast[t]);
  }
  return weights;
}

std::vector<char> selectTets(
  const TetMesh& mesh, const std::vector<int>& regions, const std::array<double, 6>* box)
{
  std::vector<char> selected(mesh.tets.size(), 1);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
  {
    if (!regions.empty() &&
      std::find(regions.begin(), regions.end(), mesh.hasRegions() ? mesh.regions[t] : 0) ==
        regions.end())
    {
      selected[t] = 0;
      continue;
    }
    if (box)
    {
      for (int axis = 0; axis < 3 && selected[t]; ++axis)
      {
        double low = mesh.point(mesh.tets[t][0])[axis], high = low;
        for (PointId p : mesh.tets[t])
        {
          low = std::min(low, mesh.point(p)[axis]);
          high = std::max(high, mesh.point(p)[axis]);
        }
        selected[t] = high >= (*box)[axis] && low <= (*box)[axis + 3];
      }
    }
  }
  return selected;
}

void restrictToSelection(const TetMesh& mesh, const std::vector<char>& selectedTets,
  double threshold, std::vector<double>& sizes)
{
  std::vector<char> selectedPoint(static_cast<std::size_t>(mesh.numberOfPoints()), 0);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
  {
    if (selectedTets[t])
    {
      for (PointId p : mesh.tets[t])
      {
        selectedPoint[p] = 1;
      }
    }
  }
  if (sizes.empty())
  {
    sizes.assign(selectedPoint.size(), threshold / std::sqrt(2.0));
  }
  for (std::size_t p = 0; p < selectedPoint.size(); ++p)
  {
    if (!selectedPoint[p])
    {
      sizes[p] = std::numeric_limits<double>::infinity();
    }
  }
}

std::vector<char> pointsOutsideSelection(const std::vector<double>& sizes)
{
  std::vector<char> outside(sizes.size(), 0);
  for (std::size_t p = 0; p < sizes.size(); ++p)
  {
    outside[p] = std::isinf(sizes[p]) ? 1 : 0;
  }
  return outside;
}

} // namespace cgmesh
