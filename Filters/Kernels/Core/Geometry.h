// Small geometric helpers shared by the kernels.
#ifndef cgmesh_Geometry_h
#define cgmesh_Geometry_h

#include "Core/TetMesh.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace cgmesh
{

inline double squaredDistance(const double* a, const double* b)
{
  const double dx = b[0] - a[0];
  const double dy = b[1] - a[1];
  const double dz = b[2] - a[2];
  return dx * dx + dy * dy + dz * dz;
}

// Squared length of edge (a, b) computed in a canonical order (smaller id first), so that every
// partition holding the edge gets the bit-identical value and takes the same split decision.
inline double squaredEdgeLength(const TetMesh& mesh, PointId a, PointId b)
{
  return a < b ? squaredDistance(mesh.point(a), mesh.point(b))
               : squaredDistance(mesh.point(b), mesh.point(a));
}

// Six times the signed volume: det[p1 - p0, p2 - p0, p3 - p0].
inline double signedVolume6(const double* p0, const double* p1, const double* p2, const double* p3)
{
  const double a[3] = { p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2] };
  const double b[3] = { p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2] };
  const double c[3] = { p3[0] - p0[0], p3[1] - p0[1], p3[2] - p0[2] };
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
    a[2] * (b[0] * c[1] - b[1] * c[0]);
}

inline double signedVolume6(const TetMesh& mesh, const Tet& tet)
{
  return signedVolume6(
    mesh.point(tet[0]), mesh.point(tet[1]), mesh.point(tet[2]), mesh.point(tet[3]));
}

// n = u x v.
inline void crossProduct(const double* u, const double* v, double* n)
{
  n[0] = u[1] * v[2] - u[2] * v[1];
  n[1] = u[2] * v[0] - u[0] * v[2];
  n[2] = u[0] * v[1] - u[1] * v[0];
}

inline double triangleArea(const double* p0, const double* p1, const double* p2)
{
  const double a[3] = { p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2] };
  const double b[3] = { p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2] };
  double c[3];
  crossProduct(a, b, c);
  return 0.5 * std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
}

// The six edges of a tet as pairs of local corner indices; the order is part of the template
// tables' contract.
constexpr int TetEdgeCorners[6][2] = { { 0, 1 }, { 0, 2 }, { 0, 3 }, { 1, 2 }, { 1, 3 }, { 2, 3 } };

} // namespace cgmesh

#endif
