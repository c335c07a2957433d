#include "Core/TetLocator.h"

#include "Core/Geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cgmesh
{

TetLocator::TetLocator(const std::vector<Tet>& tets, CoordinatesOf coordinatesOf)
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
  // About one tet per grid cell, or fewer: a tet's bounding box spans several cells.
  this->Resolution = std::max(1, std::min(96, static_cast<int>(1.5 * std::cbrt(count))));
  for (int axis = 0; axis < 3; ++axis)
  {
    const double extent = high[axis] - this->Low[axis];
    this->CellSize[axis] = extent > 0 ? extent / this->Resolution : 1.0;
  }
  this->Buckets.resize(
    static_cast<std::size_t>(this->Resolution) * this->Resolution * this->Resolution);
  auto clampIndex = [this](double value)
  {
    return std::max(0, std::min(this->Resolution - 1, static_cast<int>(std::floor(value))));
  };
  for (std::size_t t = 0; t < count; ++t)
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
          this->Buckets[(static_cast<std::size_t>(k) * this->Resolution + j) * this->Resolution + i]
            .push_back(t);
        }
      }
    }
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
  const double* point, const std::vector<std::size_t>& candidates) const
{
  Location best;
  double bestMinimum = -std::numeric_limits<double>::max();
  for (std::size_t tet : candidates)
  {
    if (bestMinimum > -1e-12 && !this->mayContain(tet, point))
    {
      continue; // cheap rejection once a near-containing tet is known
    }
    const auto weights = this->barycentric(tet, point);
    const double minimum = *std::min_element(weights.begin(), weights.end());
    if (minimum > bestMinimum)
    {
      bestMinimum = minimum;
      best.tet = tet;
      best.barycentric = weights;
      if (minimum >= 0)
      {
        break; // inside (or on the boundary of) this tet: no other can do better than tie
      }
    }
  }
  return best;
}

TetLocator::Location TetLocator::locate(const double* point) const
{
  const auto& candidates = this->Buckets[this->cellIndex(point)];
  Location location = this->bestAmong(point, candidates);
  const double minimum =
    *std::min_element(location.barycentric.begin(), location.barycentric.end());
  if (candidates.empty() || minimum < -1e-9)
  {
    std::vector<std::size_t> all(this->Volumes6.size());
    for (std::size_t t = 0; t < all.size(); ++t)
    {
      all[t] = t;
    }
    location = this->bestAmong(point, all);
  }
  return location;
}

} // namespace cgmesh
