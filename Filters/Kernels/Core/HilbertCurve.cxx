#include "Core/HilbertCurve.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace cgmesh
{

std::uint64_t hilbertIndex(std::array<std::uint32_t, 3> cell, int bits)
{
  // Walk the levels from the coarsest: at each level the lower bits are reflected or swapped so
  // that the sub-cube reached is entered the way the curve enters it (Skilling's "transpose"
  // form of the Hilbert index), then the three coordinates are Gray-decoded into one index.
  const std::uint32_t top = 1u << (bits - 1);
  for (std::uint32_t level = top; level > 1; level >>= 1)
  {
    const std::uint32_t lower = level - 1;
    for (int axis = 0; axis < 3; ++axis)
    {
      if (cell[axis] & level)
      {
        cell[0] ^= lower;
      }
      else
      {
        const std::uint32_t swapped = (cell[0] ^ cell[axis]) & lower;
        cell[0] ^= swapped;
        cell[axis] ^= swapped;
      }
    }
  }
  cell[1] ^= cell[0];
  cell[2] ^= cell[1];
  std::uint32_t flip = 0;
  for (std::uint32_t level = top; level > 1; level >>= 1)
  {
    if (cell[2] & level)
    {
      flip ^= level - 1;
    }
  }
  std::uint64_t index = 0;
  for (int bit = bits - 1; bit >= 0; --bit)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      index = (index << 1) | (((cell[axis] ^ flip) >> bit) & 1u);
    }
  }
  return index;
}

std::vector<std::size_t> tetsAlongHilbertCurve(
  const TetList& tets, const std::function<const double*(PointId)>& coordinatesOf)
{
  const std::size_t count = tets.size();
  // The index costs a step per bit: no more bits than the tets need.
  int bits = 4;
  while (bits < 21 && std::ldexp(1.0, bits) < 8.0 * std::cbrt(static_cast<double>(count)))
  {
    ++bits;
  }
  std::vector<std::array<double, 3>> centroids(count, { 0, 0, 0 });
  std::array<double, 3> low, high;
  low.fill(std::numeric_limits<double>::infinity());
  high.fill(-std::numeric_limits<double>::infinity());
  for (std::size_t t = 0; t < count; ++t)
  {
    for (PointId p : tets[t])
    {
      const double* x = coordinatesOf(p);
      for (int axis = 0; axis < 3; ++axis)
      {
        centroids[t][axis] += 0.25 * x[axis];
      }
    }
    for (int axis = 0; axis < 3; ++axis)
    {
      low[axis] = std::min(low[axis], centroids[t][axis]);
      high[axis] = std::max(high[axis], centroids[t][axis]);
    }
  }
  double extent = 0;
  for (int axis = 0; axis < 3; ++axis)
  {
    extent = std::max(extent, high[axis] - low[axis]);
  }
  const double cellsPerUnit = extent > 0 ? ((1u << bits) - 1) / extent : 0;
  std::vector<std::pair<std::uint64_t, std::size_t>> keyed(count);
  for (std::size_t t = 0; t < count; ++t)
  {
    std::array<std::uint32_t, 3> cell;
    for (int axis = 0; axis < 3; ++axis)
    {
      cell[axis] = static_cast<std::uint32_t>((centroids[t][axis] - low[axis]) * cellsPerUnit);
    }
    keyed[t] = { hilbertIndex(cell, bits), t };
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::size_t> order(count);
  for (std::size_t t = 0; t < count; ++t)
  {
    order[t] = keyed[t].second;
  }
  return order;
}

} // namespace cgmesh
