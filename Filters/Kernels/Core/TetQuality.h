// Shape measures of a single tetrahedron.
#ifndef cgmesh_TetQuality_h
#define cgmesh_TetQuality_h

#include "Core/Geometry.h"

#include <algorithm>
#include <cmath>

namespace cgmesh
{

// What the mean ratio is made of: the signed volume V and the sum S of squared edge lengths.
struct MeanRatioTerms
{
  double volume;
  double sumSquared;
};

inline MeanRatioTerms meanRatioTerms(
  const double* p0, const double* p1, const double* p2, const double* p3)
{
  return { signedVolume6(p0, p1, p2, p3) / 6.0,
    squaredDistance(p0, p1) + squaredDistance(p0, p2) + squaredDistance(p0, p3) +
      squaredDistance(p1, p2) + squaredDistance(p1, p3) + squaredDistance(p2, p3) };
}

// Mean ratio: 12 (3 V)^(2/3) / (sum of squared edge lengths). 1 for the regular tet, tending to 0
// for degenerate ones, negative for inverted ones. Smooth and cheap, which suits optimisation;
// it is the measure the quality improvement maximises (the worst tet of each local change).
inline double meanRatio(const double* p0, const double* p1, const double* p2, const double* p3)
{
  const auto [volume, sumSquared] = meanRatioTerms(p0, p1, p2, p3);
  if (!(sumSquared > 0))
  {
    return -1;
  }
  if (volume <= 0)
  {
    return volume < 0 ? -1 : 0;
  }
  return 12.0 * std::cbrt(9.0 * volume * volume) / sumSquared;
}

// meanRatio(...) cubed, 15552 V^2 / S^3 with the sign of V (0 or -1 as meanRatio gives them),
// without the cube root: it orders tets as the mean ratio does, and comparing tets is what the
// improvement's inner loops do.
inline double cubedMeanRatio(const double* p0, const double* p1, const double* p2, const double* p3)
{
  const auto [volume, sumSquared] = meanRatioTerms(p0, p1, p2, p3);
  if (!(sumSquared > 0))
  {
    return -1;
  }
  if (volume <= 0)
  {
    return volume < 0 ? -1 : 0;
  }
  return 1728.0 * 9.0 * volume * volume / (sumSquared * sumSquared * sumSquared);
}

// meanRatio(...) < target for a target in (0, 1], without the cube root: for a positive volume
// the ratio is below the target exactly when 12^3 (9 V^2) < (target S)^3. Screening every tet
// of a partition for poor ones is the improver's most frequent question.
inline bool meanRatioBelow(
  const double* p0, const double* p1, const double* p2, const double* p3, double target)
{
  const auto [volume, sumSquared] = meanRatioTerms(p0, p1, p2, p3);
  if (!(sumSquared > 0) || volume <= 0)
  {
    return true;
  }
  const double scaled = target * sumSquared;
  return 1728.0 * 9.0 * volume * volume < scaled * scaled * scaled;
}

// The six edge vectors of a tet, corner b minus corner a for the edges of TetEdgeCorners: (0,1),
// (0,2), (0,3), (1,2), (1,3), (2,3). Both measures below are made of them, so a caller wanting
// both computes them once.
struct TetEdgeVectors
{
  double edge[6][3];
};

inline TetEdgeVectors tetEdgeVectors(
  const double* p0, const double* p1, const double* p2, const double* p3)
{
  const double* p[4] = { p0, p1, p2, p3 };
  TetEdgeVectors vectors;
  for (int e = 0; e < 6; ++e)
  {
    const double* a = p[TetEdgeCorners[e][0]];
    const double* b = p[TetEdgeCorners[e][1]];
    for (int k = 0; k < 3; ++k)
    {
      vectors.edge[e][k] = b[k] - a[k];
    }
  }
  return vectors;
}

// The normal of the face opposite corner f is edge [f][0] cross edge [f][1] of TetEdgeVectors:
// (c - b) x (d - b), (d - a) x (c - a), (b - a) x (d - a), (c - a) x (b - a) for corners a, b, c,
// d. All point outward for a positive tet and all inward for an inverted one: the products of
// pairs of normals do not see the difference, so no face needs its own orientation test.
constexpr int FaceNormalEdges[4][2] = { { 3, 4 }, { 2, 1 }, { 0, 2 }, { 1, 0 } };

// Smallest dihedral angle in degrees (70.53 for the regular tet; 180 when every face is
// degenerate).
inline double minimumDihedralAngle(const TetEdgeVectors& vectors)
{
  const auto& e = vectors.edge;
  double normal[4][3];
  for (int f = 0; f < 4; ++f)
  {
    crossProduct(e[FaceNormalEdges[f][0]], e[FaceNormalEdges[f][1]], normal[f]);
  }
  double inverseLength[4];
  bool hasArea[4];
  for (int f = 0; f < 4; ++f)
  {
    const double* n = normal[f];
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    hasArea[f] = length > 0;
    inverseLength[f] = hasArea[f] ? 1.0 / length : 0.0;
  }
  // The dihedral angle at an edge is the angle between the two faces holding it, pi minus the
  // angle between their outward normals. The smallest angle has the largest cosine: one acos.
  double largestCosine = -1;
  bool any = false;
  for (int i = 0; i < 4; ++i)
  {
    for (int j = i + 1; j < 4; ++j)
    {
      if (hasArea[i] && hasArea[j])
      {
        const double dot =
          normal[i][0] * normal[j][0] + normal[i][1] * normal[j][1] + normal[i][2] * normal[j][2];
        largestCosine = std::max(largestCosine, -dot * inverseLength[i] * inverseLength[j]);
        any = true;
      }
    }
  }
  return any ? std::acos(std::min(1.0, largestCosine)) * (180.0 / M_PI) : 180.0;
}

inline double minimumDihedralAngle(
  const double* p0, const double* p1, const double* p2, const double* p3)
{
  return minimumDihedralAngle(tetEdgeVectors(p0, p1, p2, p3));
}

// The largest mean ratio a tet whose smallest dihedral angle is below `degrees` (in (0, 90)) can
// have, with a margin for rounding. At the edge of length l where that angle θ lies, between
// faces of areas A1 and A2 (each at most l L / 2, L the longest edge), the volume
// 2 A1 A2 sin θ / (3 l) is at most L^3 sin θ / 6, and the squared edge lengths add up to at least
// L^2: the mean ratio is at most 12 (sin θ / 2)^(2/3), 0.509 for one degree.
inline double meanRatioCeiling(double degrees)
{
  const double halfSine = std::sin(degrees * (M_PI / 180.0)) / 2.0;
  return 12.0 * std::cbrt(halfSine * halfSine) * (1.0 + 1e-6);
}

// Whether the smallest dihedral angle is below `degrees`, `ceiling` being
// meanRatioCeiling(degrees): a tet whose mean ratio reaches the ceiling is passed over without the
// angle's four square roots and arc cosine. Counting the slivers of the 844k-tet FinFET so took
// 0.010 s instead of 0.029 at 2 threads.
inline bool minimumDihedralAngleBelow(const double* p0, const double* p1, const double* p2,
  const double* p3, double degrees, double ceiling)
{
  return meanRatioBelow(p0, p1, p2, p3, ceiling) && minimumDihedralAngle(p0, p1, p2, p3) < degrees;
}

// Longest edge over shortest edge (1 for the regular tet); infinite when an edge has no length.
inline double edgeRatio(const TetEdgeVectors& vectors)
{
  double shortest = HUGE_VAL;
  double longest = 0;
  for (const double* v : vectors.edge)
  {
    const double squared = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    shortest = std::min(shortest, squared);
    longest = std::max(longest, squared);
  }
  return shortest > 0 ? std::sqrt(longest / shortest) : HUGE_VAL;
}

inline double edgeRatio(const double* p0, const double* p1, const double* p2, const double* p3)
{
  return edgeRatio(tetEdgeVectors(p0, p1, p2, p3));
}

// Both measures above for Lanes tets at once, the coordinates lane by lane (corner, coordinate,
// lane): the whole-mesh quality arrays call this. Each lane does exactly the operations of
// minimumDihedralAngle() and edgeRatio(), in their order, so the values are the same bits (the
// compiler may not reorder IEEE arithmetic), while the loops over the lanes become vector
// instructions. Only the final acos is taken lane by lane.
template <int Lanes>
struct TetLanes
{
  double corner[4][3][Lanes];
};

template <int Lanes>
inline void dihedralAndEdgeRatioLanes(
  const TetLanes<Lanes>& tets, double* minDihedralAngle, double* edgeRatio)
{
  // Branches become selects between values computed in every lane (a quotient by zero in a lane
  // that does not use it is harmless), with the flags held as doubles: that is what lets the
  // compiler vectorize the loops.
  double edge[6][3][Lanes];
  for (int e = 0; e < 6; ++e)
  {
    for (int k = 0; k < 3; ++k)
    {
      for (int l = 0; l < Lanes; ++l)
      {
        edge[e][k][l] =
          tets.corner[TetEdgeCorners[e][1]][k][l] - tets.corner[TetEdgeCorners[e][0]][k][l];
      }
    }
  }
  double normal[4][3][Lanes]; // as crossProduct() makes them
  double inverseLength[4][Lanes];
  double hasArea[4][Lanes]; // 1 or 0
  for (int f = 0; f < 4; ++f)
  {
    const auto& u = edge[FaceNormalEdges[f][0]];
    const auto& v = edge[FaceNormalEdges[f][1]];
    for (int l = 0; l < Lanes; ++l)
    {
      normal[f][0][l] = u[1][l] * v[2][l] - u[2][l] * v[1][l];
      normal[f][1][l] = u[2][l] * v[0][l] - u[0][l] * v[2][l];
      normal[f][2][l] = u[0][l] * v[1][l] - u[1][l] * v[0][l];
      const double length = std::sqrt(normal[f][0][l] * normal[f][0][l] +
        normal[f][1][l] * normal[f][1][l] + normal[f][2][l] * normal[f][2][l]);
      const double inverse = 1.0 / length;
      hasArea[f][l] = length > 0 ? 1.0 : 0.0;
      inverseLength[f][l] = length > 0 ? inverse : 0.0;
    }
  }
  double largestCosine[Lanes];
  double any[Lanes]; // 1 when some pair of faces has area
  for (int l = 0; l < Lanes; ++l)
  {
    largestCosine[l] = -1;
    any[l] = 0;
  }
  // The pairs of faces in the scalar function's order: (0, 1), (0, 2), (0, 3), (1, 2), ...
  for (const auto& pair : TetEdgeCorners)
  {
    const int i = pair[0], j = pair[1];
    for (int l = 0; l < Lanes; ++l)
    {
      const double dot = normal[i][0][l] * normal[j][0][l] + normal[i][1][l] * normal[j][1][l] +
        normal[i][2][l] * normal[j][2][l];
      const double cosine = -dot * inverseLength[i][l] * inverseLength[j][l];
      const double both = hasArea[i][l] * hasArea[j][l];
      // A pair without area leaves the largest as it is, as the scalar function skips it.
      const bool larger = both != 0 && largestCosine[l] < cosine;
      largestCosine[l] = larger ? cosine : largestCosine[l];
      any[l] = std::max(any[l], both);
    }
  }
  double shortest[Lanes], longest[Lanes];
  for (int l = 0; l < Lanes; ++l)
  {
    shortest[l] = HUGE_VAL;
    longest[l] = 0;
  }
  for (int e = 0; e < 6; ++e)
  {
    for (int l = 0; l < Lanes; ++l)
    {
      const double squared = edge[e][0][l] * edge[e][0][l] + edge[e][1][l] * edge[e][1][l] +
        edge[e][2][l] * edge[e][2][l];
      shortest[l] = std::min(shortest[l], squared);
      longest[l] = std::max(longest[l], squared);
    }
  }
  for (int l = 0; l < Lanes; ++l)
  {
    const double ratio = std::sqrt(longest[l] / shortest[l]);
    edgeRatio[l] = shortest[l] > 0 ? ratio : HUGE_VAL;
  }
  for (int l = 0; l < Lanes; ++l)
  {
    minDihedralAngle[l] =
      any[l] != 0 ? std::acos(std::min(1.0, largestCosine[l])) * (180.0 / M_PI) : 180.0;
  }
}

} // namespace cgmesh

#endif
