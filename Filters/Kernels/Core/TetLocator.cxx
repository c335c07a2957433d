#include "Core/TetLocator.h"

#include "Core/FaceKey.h"
#include "Core/Geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace cgmesh
{

TetLocator::TetLocator(const TetList& tets, CoordinatesOf coordinatesOf)
  : Tets(&tets)
  , Coordinates(std::move(coordinatesOf))
{
  const std::size_t count = tets.size();
  this->Faces.resize(count);
  for (std::size_t t = 0; t < count; ++t)
  {
    const double* c[4];
    for (int i = 0; i < 4; ++i)
    {
      c[i] = this->Coordinates(tets[t][i]);
    }
    FacePlanes& planes = this->Faces[t];
    std::copy_n(c[0], 3, planes.anchors[0].data());
    std::copy_n(c[1], 3, planes.anchors[1].data());
    // Weight k is the affine function that is 0 on the face opposite corner k and 1 at corner k:
    // the face's normal divided by the corner's height over it, taken from a corner of that face.
    for (int k = 0; k < 4; ++k)
    {
      const double* a = k == 0 ? c[1] : c[0];
      const double* b = c[k <= 1 ? 2 : 1];
      const double* d = c[k == 3 ? 2 : 3];
      const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
      const double v[3] = { d[0] - a[0], d[1] - a[1], d[2] - a[2] };
      double normal[3];
      crossProduct(u, v, normal);
      const double height =
        normal[0] * (c[k][0] - a[0]) + normal[1] * (c[k][1] - a[1]) + normal[2] * (c[k][2] - a[2]);
      for (int axis = 0; axis < 3; ++axis)
      {
        planes.gradients[k][axis] = normal[axis] / height;
      }
    }
  }
}

// About one tet per grid cell, or fewer: a tet's bounding box spans several cells. Built on the
// first search that needs it: walks from a nearby tet, the common case, do without.
void TetLocator::buildGrid() const
{
  const TetList& tets = *this->Tets;
  const std::size_t count = tets.size();
  this->Boxes.resize(6 * count);
  double high[3];
  for (int axis = 0; axis < 3; ++axis)
  {
    this->Low[axis] = std::numeric_limits<double>::max();
    high[axis] = -std::numeric_limits<double>::max();
  }
  for (std::size_t t = 0; t < count; ++t)
  {
    double* box = this->Boxes.data() + 6 * t;
    for (int axis = 0; axis < 3; ++axis)
    {
      box[axis] = std::numeric_limits<double>::max();
      box[3 + axis] = -std::numeric_limits<double>::max();
    }
    for (int i = 0; i < 4; ++i)
    {
      const double* x = this->Coordinates(tets[t][i]);
      for (int axis = 0; axis < 3; ++axis)
      {
        box[axis] = std::min(box[axis], x[axis]);
        box[3 + axis] = std::max(box[3 + axis], x[axis]);
      }
    }
    for (int axis = 0; axis < 3; ++axis)
    {
      this->Low[axis] = std::min(this->Low[axis], box[axis]);
      high[axis] = std::max(high[axis], box[3 + axis]);
    }
  }
  // Where tets are long against the mesh (a sliver-laden one, a coarse one around a fine part),
  // the grid is made coarser until the buckets hold at most 16 entries per tet, so building them
  // stays linear (the benchmark's poor input, meshed anew as one cluster: adapt 2.8 to 2.55 s at
  // 2 threads).
  auto cellsSpanned = [&](int resolution)
  {
    double entries = 0;
    for (std::size_t t = 0; t < count; ++t)
    {
      const double* box = this->Boxes.data() + 6 * t;
      double cells = 1;
      for (int axis = 0; axis < 3; ++axis)
      {
        const double extent = high[axis] - this->Low[axis];
        cells *= extent > 0 ? std::min<double>(resolution,
                                std::floor((box[3 + axis] - box[axis]) / extent * resolution) + 2)
                            : 1;
      }
      entries += cells;
    }
    return entries;
  };
  this->Resolution = std::max(1, std::min(96, static_cast<int>(1.5 * std::cbrt(count))));
  while (this->Resolution > 1 && cellsSpanned(this->Resolution) > 16.0 * static_cast<double>(count))
  {
    this->Resolution = std::max(1, this->Resolution * 3 / 4);
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    const double extent = high[axis] - this->Low[axis];
    this->CellSize[axis] = extent > 0 ? extent / this->Resolution : 1.0;
  }
  auto clampIndex = [this](double value)
  {
    return std::max(0, std::min(this->Resolution - 1, static_cast<int>(std::floor(value))));
  };
  // Buckets in compressed rows (count, then fill): one allocation instead of one per grid cell.
  const std::size_t cellCount =
    static_cast<std::size_t>(this->Resolution) * this->Resolution * this->Resolution;
  this->BucketOffsets.assign(cellCount + 1, 0);
  auto forEachCellOf = [&](std::size_t t, auto&& visit)
  {
    const double* box = this->Boxes.data() + 6 * t;
    int first[3], last[3];
    for (int axis = 0; axis < 3; ++axis)
    {
      first[axis] = clampIndex((box[axis] - this->Low[axis]) / this->CellSize[axis]);
      last[axis] = clampIndex((box[3 + axis] - this->Low[axis]) / this->CellSize[axis]);
    }
    for (int k = first[2]; k <= last[2]; ++k)
    {
      for (int j = first[1]; j <= last[1]; ++j)
      {
        for (int i = first[0]; i <= last[0]; ++i)
        {
          visit((static_cast<std::size_t>(k) * this->Resolution + j) * this->Resolution + i);
        }
      }
    }
  };
  for (std::size_t t = 0; t < count; ++t)
  {
    forEachCellOf(t, [this](std::size_t cell) { ++this->BucketOffsets[cell + 1]; });
  }
  for (std::size_t cell = 0; cell < cellCount; ++cell)
  {
    this->BucketOffsets[cell + 1] += this->BucketOffsets[cell];
  }
  this->BucketTets.resize(this->BucketOffsets[cellCount]);
  std::vector<std::size_t> next(this->BucketOffsets.begin(), this->BucketOffsets.end() - 1);
  for (std::size_t t = 0; t < count; ++t)
  {
    forEachCellOf(t, [&](std::size_t cell) { this->BucketTets[next[cell]++] = t; });
  }
}

std::size_t TetLocator::cellIndex(const double* point) const
{
  int index[3];
  for (int axis = 0; axis < 3; ++axis)
  {
    const double scaled = std::floor((point[axis] - this->Low[axis]) / this->CellSize[axis]);
    index[axis] = static_cast<int>(std::max(0.0, std::min<double>(this->Resolution - 1, scaled)));
  }
  return (static_cast<std::size_t>(index[2]) * this->Resolution + index[1]) * this->Resolution +
    index[0];
}

bool TetLocator::mayContain(std::size_t tet, const double* point) const
{
  const double* box = this->Boxes.data() + 6 * tet;
  for (int axis = 0; axis < 3; ++axis)
  {
    if (point[axis] < box[axis] || point[axis] > box[3 + axis])
    {
      return false;
    }
  }
  return true;
}

std::array<double, 4> TetLocator::barycentric(std::size_t tet, const double* point) const
{
  const FacePlanes& planes = this->Faces[tet];
  std::array<double, 4> weights;
  for (int k = 0; k < 4; ++k)
  {
    const double* anchor = planes.anchors[k == 0 ? 1 : 0].data();
    const double* gradient = planes.gradients[k].data();
    weights[k] = gradient[0] * (point[0] - anchor[0]) + gradient[1] * (point[1] - anchor[1]) +
      gradient[2] * (point[2] - anchor[2]);
  }
  return weights;
}

TetLocator::Location TetLocator::bestAmong(
  const double* point, const std::size_t* first, const std::size_t* last) const
{
  Location best;
  double bestMinimum = -std::numeric_limits<double>::max();
  auto consider = [&](std::size_t tet)
  {
    const auto weights = this->barycentric(tet, point);
    const double minimum = *std::min_element(weights.begin(), weights.end());
    if (minimum > bestMinimum)
    {
      bestMinimum = minimum;
      best.tet = tet;
      best.barycentric = weights;
    }
    return minimum >= 0; // inside (or on the boundary of) this tet: no other can do better
  };
  // A containing tet's bounding box holds the point, so the cheap box test leaves the few
  // candidates worth the four volumes; only a point a rounding error outside every tet needs
  // all of them.
  for (const std::size_t* tet = first; tet != last; ++tet)
  {
    if (this->mayContain(*tet, point) && consider(*tet))
    {
      return best;
    }
  }
  for (const std::size_t* tet = first; tet != last; ++tet)
  {
    if (!this->mayContain(*tet, point) && consider(*tet))
    {
      return best;
    }
  }
  return best;
}

TetLocator::Location TetLocator::locate(const double* point) const
{
  if (this->BucketOffsets.empty())
  {
    this->buildGrid();
  }
  const std::size_t cell = this->cellIndex(point);
  const std::size_t* first = this->BucketTets.data() + this->BucketOffsets[cell];
  const std::size_t* last = this->BucketTets.data() + this->BucketOffsets[cell + 1];
  Location location = this->bestAmong(point, first, last);
  const double minimum =
    *std::min_element(location.barycentric.begin(), location.barycentric.end());
  if (first == last || minimum < -1e-9)
  {
    std::vector<std::size_t> all(this->Faces.size());
    for (std::size_t t = 0; t < all.size(); ++t)
    {
      all[t] = t;
    }
    location = this->bestAmong(point, all.data(), all.data() + all.size());
  }
  return location;
}

void TetLocator::buildFaceNeighbours(const TetList& tets)
{
  this->FaceNeighbours.assign(4 * tets.size(), -1);
  forEachDistinctFace(tets.empty() ? nullptr : tets[0].data(), tets.size(),
    [&](
      const std::array<PointId, 3>& face, std::size_t first, std::size_t second, std::size_t count)
    {
      if (count == 2)
      {
        this->FaceNeighbours[4 * first + cornerOpposite(tets[first], face)] =
          static_cast<std::int64_t>(second);
        this->FaceNeighbours[4 * second + cornerOpposite(tets[second], face)] =
          static_cast<std::int64_t>(first);
      }
    });
}

TetLocator::Location TetLocator::locateFrom(const double* point, std::size_t start) const
{
  // Enough for a point a few tets away; a visibility walk can also circle on degenerate input.
  constexpr int MaximumSteps = 64;
  std::size_t tet = start;
  for (int step = 0; step < MaximumSteps; ++step)
  {
    const auto weights = this->barycentric(tet, point);
    // Across the face the point is furthest beyond, or where that face is on the mesh's
    // boundary (a concave partition), the next furthest one with a tet behind it: on the
    // FinFET's partitions 11,000 walks a run stopped at the boundary with the furthest face
    // alone, 4,600 with this rule.
    std::int64_t next = -1;
    double furthest = 0;
    for (int k = 0; k < 4; ++k)
    {
      const std::int64_t across = this->FaceNeighbours[4 * tet + k];
      if (weights[k] < furthest && across >= 0)
      {
        furthest = weights[k];
        next = across;
      }
    }
    if (next < 0)
    {
      if (*std::min_element(weights.begin(), weights.end()) >= 0)
      {
        Location location;
        location.tet = tet;
        location.barycentric = weights;
        return location;
      }
      return this->searchAround(point, tet);
    }
    tet = static_cast<std::size_t>(next);
  }
  return this->searchAround(point, tet);
}

TetLocator::Location TetLocator::searchAround(const double* point, std::size_t start) const
{
  // Breadth first through face neighbours: a walk stops where the point lies behind the mesh's
  // boundary from where it stands (around a concave corner of a partition, 4,600 times in a
  // FinFET Delaunay run), or goes on too long, yet the tet holding the point is a few dozen tets
  // away, or a few hundred: nearer than a grid that would have to be built for it. Beyond 2,048
  // tets the grid is built, and from then on it answers: on a sliver-laden input meshed anew in
  // one piece, walks fail often, and searching the whole piece each time made adapt 40% slower.
  constexpr std::size_t MaximumVisits = 2048;
  if (!this->BucketOffsets.empty())
  {
    return this->locate(point); // the grid, once built, answers at once
  }
  if (this->Visited.size() != this->Faces.size())
  {
    this->Visited.assign(this->Faces.size(), 0);
  }
  if (++this->VisitStamp == 0) // wrapped: no old mark may match
  {
    std::fill(this->Visited.begin(), this->Visited.end(), 0);
    this->VisitStamp = 1;
  }
  std::vector<std::size_t>& queue = this->Queue;
  queue.assign(1, start);
  this->Visited[start] = this->VisitStamp;
  for (std::size_t head = 0; head < queue.size() && head < MaximumVisits; ++head)
  {
    const std::size_t tet = queue[head];
    const auto weights = this->barycentric(tet, point);
    if (*std::min_element(weights.begin(), weights.end()) >= 0)
    {
      Location location;
      location.tet = tet;
      location.barycentric = weights;
      return location;
    }
    for (int k = 0; k < 4; ++k)
    {
      const std::int64_t across = this->FaceNeighbours[4 * tet + k];
      if (across >= 0 && this->Visited[static_cast<std::size_t>(across)] != this->VisitStamp)
      {
        this->Visited[static_cast<std::size_t>(across)] = this->VisitStamp;
        queue.push_back(static_cast<std::size_t>(across));
      }
    }
  }
  return this->locate(point);
}

} // namespace cgmesh
