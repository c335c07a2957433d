// Orders by position along a 3D Hilbert curve: cells close on the curve are close in space, so
// tets taken in this order touch memory, and meet their face neighbours, a few steps apart.
#ifndef cgmesh_HilbertCurve_h
#define cgmesh_HilbertCurve_h

#include "Core/TetMesh.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace cgmesh
{

// Position along the 3D Hilbert curve of order `bits` (at most 21) of a point on the integer grid
// [0, 2^bits)^3.
std::uint64_t hilbertIndex(std::array<std::uint32_t, 3> cell, int bits);

// The positions of `tets` ordered by the Hilbert index of their centroids on a grid over their
// bounding cube with about 500 cells per tet (8 times finer a side than one cell per tet), ties
// by position.
std::vector<std::size_t> tetsAlongHilbertCurve(
  const TetList& tets, const std::function<const double*(PointId)>& coordinatesOf);

} // namespace cgmesh

#endif
