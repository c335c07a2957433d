// A plain tetrahedral mesh: the exchange format between the kernels, the driver and the VTK
// adapter.
#ifndef cgmesh_TetMesh_h
#define cgmesh_TetMesh_h

#include "Core/DefaultInitAllocator.h"

#include <array>
#include <cstdint>
#include <vector>

namespace cgmesh
{

using PointId = std::int64_t;
using CellId = std::int64_t;
using Tet = std::array<PointId, 4>;
// Tets are always written after the array is sized: resize() leaves them unwritten.
using TetList = UnfilledVector<Tet>;

struct TetMesh
{
  std::vector<double> coordinates; // x, y, z per point
  TetList tets;                    // four point ids per tetrahedron
  std::vector<int> regions;        // one material/region id per tet, or empty
  std::vector<double> sizes;       // target edge length h per point (a size field), or empty

  PointId numberOfPoints() const { return static_cast<PointId>(coordinates.size() / 3); }
  CellId numberOfTets() const { return static_cast<CellId>(tets.size()); }
  bool hasRegions() const { return !regions.empty(); }
  bool hasSizes() const { return !sizes.empty(); }
  const double* point(PointId id) const { return coordinates.data() + 3 * id; }
};

} // namespace cgmesh

#endif
