#include "Core/TetLocator.h"

#include "Core/FaceKey.h"
#include "Core/Geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cgmesh
{

TetLocator::TetLocator(const TetList& tets, CoordinatesOf coordinatesOf)
{
  const std::size_t count = tets.size();
  this->Corners.resize(12 * count);
  this->Boxes.resize(6 * count);
  this->Volumes6.resize(count);
  double high[3];
  for (int axis = 0; axis < 3; ++axis)
  {
    this->Low[axis] = std::numeric_limits<double>::max();
    high[axis] = -std::numeric_limits<double>::max();
  }
  for (std::size_t t = 0; t < count; ++t)
  {
    double* corners = this->Corners.data() + 12 * t;
    double* box = this->Boxes.data() + 6 * t;
    for (int axis = 0; axis < 3; ++axis)
    {
      box[axis] = std::numeric_limits<double>::max();
      box[3 + axis] = -std::numeric_limits<double>::max();
    }
    for (int i = 0; i < 4; ++i)
    {
      const double* x = coordinatesOf(tets[t][i]);
      for (int axis = 0; axis < 3; ++axis)
      {
        corners[3 * i + axis] = x[axis];
        box[axis] = std::min(box[axis], x[axis]);
        box[3 + axis] = std::max(box[3 + axis], x[axis]);
      }
    }
    this->Volumes6[t] = signedVolume6(corners, corners + 3, corners + 6, corners + 9);
    for (int axis = 0; axis < 3; ++axis)
    {
      this->Low[axis] = std::min(this->Low[axis], box[axis]);
      high[axis] = std::max(high[axis], box[3 + axis]);
    }
  }
  // About one tet per grid cell, or fewer: a tet's bounding box spans several cells. Where tets
  // are long against the mesh (a sliver-laden one, a coarse one around a fine part), the grid is
  // made coarser until the buckets hold at most 16 entries per tet, so building them stays linear
  // (the benchmark's poor input, meshed anew as one cluster: adapt 2.8 to 2.55 s at 2 threads).
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
  const double* corners = this->Corners.data() + 12 * tet;
  const double* p[4] = { corners, corners + 3, corners + 6, corners + 9 };
  const double volume = this->Volumes6[tet];
  std::array<double, 4> weights;
  for (int i = 0; i < 4; ++i)
  {
    const double* q[4] = { p[0], p[1], p[2], p[3] };
    q[i] = point;
    weights[i] = signedVolume6(q[0], q[1], q[2], q[3]) / volume;
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
  const std::size_t cell = this->cellIndex(point);
  const std::size_t* first = this->BucketTets.data() + this->BucketOffsets[cell];
  const std::size_t* last = this->BucketTets.data() + this->BucketOffsets[cell + 1];
  Location location = this->bestAmong(point, first, last);
  const double minimum =
    *std::min_element(location.barycentric.begin(), location.barycentric.end());
  if (first == last || minimum < -1e-9)
  {
    std::vector<std::size_t> all(this->Volumes6.size());
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
  auto opposite = [&tets](std::size_t tet, const std::array<PointId, 3>& face)
  {
    int corner = 0;
    while (std::find(face.begin(), face.end(), tets[tet][corner]) != face.end())
    {
      ++corner;
    }
    return corner;
  };
  forEachDistinctFace(tets.empty() ? nullptr : tets[0].data(), tets.size(),
    [&](
      const std::array<PointId, 3>& face, std::size_t first, std::size_t second, std::size_t count)
    {
      if (count == 2)
      {
        this->FaceNeighbours[4 * first + opposite(first, face)] = static_cast<std::int64_t>(second);
        this->FaceNeighbours[4 * second + opposite(second, face)] =
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
    const auto lowest = std::min_element(weights.begin(), weights.end());
    if (*lowest >= 0)
    {
      Location location;
      location.tet = tet;
      location.barycentric = weights;
      return location;
    }
    const std::int64_t next = this->FaceNeighbours[4 * tet + (lowest - weights.begin())];
    if (next < 0)
    {
      break;
    }
    tet = static_cast<std::size_t>(next);
  }
  return this->locate(point);
}

} // namespace cgmesh
