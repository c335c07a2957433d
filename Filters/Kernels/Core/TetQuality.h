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

// Smallest dihedral angle in degrees (70.53 for the regular tet).
inline double minimumDihedralAngle(
  const double* p0, const double* p1, const double* p2, const double* p3)
{
  const double* p[4] = { p0, p1, p2, p3 };
  // Face normals (unnormalised) of the faces opposite each corner, pointing outward.
  double normal[4][3];
  for (int skip = 0; skip < 4; ++skip)
  {
    const double* a = p[(skip + 1) % 4];
    const double* b = p[(skip + 2) % 4];
    const double* c = p[(skip + 3) % 4];
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    double* n = normal[skip];
    n[0] = u[1] * v[2] - u[2] * v[1];
    n[1] = u[2] * v[0] - u[0] * v[2];
    n[2] = u[0] * v[1] - u[1] * v[0];
    const double* opposite = p[skip];
    const double toOpposite =
      n[0] * (opposite[0] - a[0]) + n[1] * (opposite[1] - a[1]) + n[2] * (opposite[2] - a[2]);
    if (toOpposite > 0)
    {
      n[0] = -n[0];
      n[1] = -n[1];
      n[2] = -n[2];
    }
  }
  // The smallest angle has the largest cosine: one acos instead of six.
  double largestCosine = -1;
  bool any = false;
  for (int i = 0; i < 4; ++i)
  {
    for (int j = i + 1; j < 4; ++j)
    {
      const double dot =
        normal[i][0] * normal[j][0] + normal[i][1] * normal[j][1] + normal[i][2] * normal[j][2];
      const double lengths = std::sqrt(
        (normal[i][0] * normal[i][0] + normal[i][1] * normal[i][1] + normal[i][2] * normal[i][2]) *
        (normal[j][0] * normal[j][0] + normal[j][1] * normal[j][1] + normal[j][2] * normal[j][2]));
      if (lengths > 0)
      {
        largestCosine = std::max(largestCosine, std::min(1.0, -dot / lengths));
        any = true;
      }
    }
  }
  return any ? std::acos(largestCosine) * 180.0 / M_PI : 180.0;
}

// Longest edge over shortest edge (1 for the regular tet); infinite when an edge has no length.
inline double edgeRatio(const double* p0, const double* p1, const double* p2, const double* p3)
{
  const double squared[6] = { squaredDistance(p0, p1), squaredDistance(p0, p2),
    squaredDistance(p0, p3), squaredDistance(p1, p2), squaredDistance(p1, p3),
    squaredDistance(p2, p3) };
  const auto range = std::minmax_element(squared, squared + 6);
  return *range.first > 0 ? std::sqrt(*range.second / *range.first) : HUGE_VAL;
}

} // namespace cgmesh

#endif
