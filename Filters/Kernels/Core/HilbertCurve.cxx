#include "Core/HilbertCurve.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace cgmesh
{

namespace
{

// The low 21 bits of `value` moved to every third bit (bit i to bit 3 i).
std::uint64_t spreadToEveryThirdBit(std::uint32_t value)
{
  std::uint64_t x = value & 0x1fffffu;
  x = (x | (x << 32)) & 0x1f00000000ffffull;
  x = (x | (x << 16)) & 0x1f0000ff0000ffull;
  x = (x | (x << 8)) & 0x100f00f00f00f00full;
  x = (x | (x << 4)) & 0x10c30c30c30c30c3ull;
  x = (x | (x << 2)) & 0x1249249249249249ull;
  return x;
}

} // namespace

std::uint64_t hilbertIndex(std::array<std::uint32_t, 3> cell, int bits)
{
  // Walk the levels from the coarsest: at each level the lower bits are reflected or swapped so
  // that the sub-cube reached is entered the way the curve enters it (Skilling's "transpose"
  // form of the Hilbert index), then the three coordinates are Gray-decoded into one index.
  // Masks instead of branches: the bits tested are the data's, and mispredicted branches made
  // this the partitioner's largest cost.
  const std::uint32_t top = 1u << (bits - 1);
  for (std::uint32_t level = top; level > 1; level >>= 1)
  {
    const std::uint32_t lower = level - 1;
    for (int axis = 0; axis < 3; ++axis)
    {
      const std::uint32_t set = 0u - ((cell[axis] & level) != 0 ? 1u : 0u);
      const std::uint32_t swapped = (cell[0] ^ cell[axis]) & lower & ~set;
      cell[0] ^= (lower & set) | swapped;
      cell[axis] ^= swapped;
    }
  }
  cell[1] ^= cell[0];
  cell[2] ^= cell[1];
  std::uint32_t flip = 0;
  for (std::uint32_t level = top; level > 1; level >>= 1)
  {
    flip ^= (level - 1) & (0u - ((cell[2] & level) != 0 ? 1u : 0u));
  }
  const std::uint32_t used = bits >= 32 ? ~0u : (1u << bits) - 1;
  return (spreadToEveryThirdBit((cell[0] ^ flip) & used) << 2) |
    (spreadToEveryThirdBit((cell[1] ^ flip) & used) << 1) |
    spreadToEveryThirdBit((cell[2] ^ flip) & used);
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
