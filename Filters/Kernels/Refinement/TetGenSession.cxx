#include "Refinement/TetGenSession.h"

#include "Refinement/EnclosedPieces.h"

#include "Core/Geometry.h"
#include "Core/HilbertCurve.h"
#include "Core/TetLocator.h"

#define TETLIBRARY
#include <tetgen.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

namespace cgmesh
{
namespace
{

// A tet's region attribute: TetGen's last one, the one it compares to find material interfaces.
inline double regionAttribute(const tetgenio& io, int t)
{
  const int count = io.numberoftetrahedronattributes;
  return io.tetrahedronattributelist[static_cast<std::size_t>(t) * count + count - 1];
}

// Whether `v` is one of the four entries at `four`: written out, as std::find over them stayed a
// call per corner, 20 per tet, a third of the validation of a Delaunay partition.
inline bool amongFour(const int* four, int v)
{
  return (four[0] == v) | (four[1] == v) | (four[2] == v) | (four[3] == v);
}

// The hull faces and the faces between two attributes of TetGen's output, sorted, from the face
// neighbours it returned (switch n), each checked rather than trusted: a neighbour must be another
// tet sharing exactly one face with this one, through no face claimed twice, and must name this
// tet back. False when a check fails. Linear in the output and free of hashing, which matters:
// the output is 20 times the size of the faces it is compared against.
bool keptFacesOfOutput(const tetgenio& io, std::vector<std::array<int, 3>>& kept)
{
  if (io.neighborlist == nullptr)
  {
    return false;
  }
  kept.clear();
  const int count = io.numberoftetrahedra;
  for (int t = 0; t < count; ++t)
  {
    const int* corners = io.tetrahedronlist + 4 * t;
    const int* neighbours = io.neighborlist + 4 * t;
    int sharedFaces = 0; // bit k: the face opposite corner k has a neighbour
    for (int slot = 0; slot < 4; ++slot)
    {
      const int n = neighbours[slot];
      if (n == -1)
      {
        continue;
      }
      if (n < 0 || n >= count || n == t)
      {
        return false;
      }
      const int* other = io.tetrahedronlist + 4 * n;
      int missing = -1, common = 0;
      for (int k = 0; k < 4; ++k)
      {
        if (amongFour(other, corners[k]))
        {
          ++common;
        }
        else
        {
          missing = k;
        }
      }
      const int* back = io.neighborlist + 4 * n;
      if (common != 3 || (sharedFaces & (1 << missing)) || !amongFour(back, t))
      {
        return false;
      }
      sharedFaces |= 1 << missing;
      if (t < n && regionAttribute(io, t) != regionAttribute(io, n))
      {
        kept.push_back(sortedFace(corners, missing));
      }
    }
    for (int k = 0; k < 4; ++k)
    {
      if (!(sharedFaces & (1 << k)))
      {
        kept.push_back(sortedFace(corners, k));
      }
    }
  }
  std::sort(kept.begin(), kept.end());
  return true;
}

// Whether two sets of faces (corner indices into the output's points) cover the same area, to
// 1e-9 relative: split kept faces still cover what was kept, region volumes being checked too.
bool sameArea(const tetgenio& io, const std::vector<std::array<int, 3>>& faces,
  const std::vector<std::array<int, 3>>& others)
{
  auto total = [&](const std::vector<std::array<int, 3>>& list)
  {
    double area = 0;
    for (const auto& face : list)
    {
      area += triangleArea(
        io.pointlist + 3 * face[0], io.pointlist + 3 * face[1], io.pointlist + 3 * face[2]);
    }
    return area;
  };
  const double expected = total(others);
  return std::abs(total(faces) - expected) <= 1e-9 * expected;
}

// Replaces `weights` (x's barycentric coordinates in the tet of `corners`) by x's coordinates in
// the face it lies on, if it lies on one: within 1e-10 of that face's longest edge of its plane,
// the corner off the face gets exactly 0. TetGen meshing anew puts points on the kept faces it
// splits, and in a flat tet, as on a sliver-laden boundary, the corner off the face came out of
// rounding at 1e-12 and more: labels the face's corners share were lost (on TetGen's
// tetrahedralisation of 4,000 random points meshed anew, 27 of 20,215 hull points; the last 3
// were located anew for noise on a moved corner's weight, see NegligibleSourceWeight).
void weightsOnFace(const double* x, const double* corners[4], std::array<double, 4>& weights)
{
  int best = -1;
  double bestDistance = HUGE_VAL;
  double bestNormal[3] = { 0, 0, 0 };
  for (int off = 0; off < 4; ++off)
  {
    const double* a = corners[(off + 1) % 4];
    const double* b = corners[(off + 2) % 4];
    const double* c = corners[(off + 3) % 4];
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    const double n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
      u[0] * v[1] - u[1] * v[0] };
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const double longest =
      std::sqrt(std::max({ squaredDistance(a, b), squaredDistance(b, c), squaredDistance(c, a) }));
    if (!(length > 0))
    {
      continue;
    }
    const double distance =
      std::abs((x[0] - a[0]) * n[0] + (x[1] - a[1]) * n[1] + (x[2] - a[2]) * n[2]) / length;
    if (distance <= 1e-10 * longest && distance / longest < bestDistance)
    {
      best = off;
      bestDistance = distance / longest;
      std::copy_n(n, 3, bestNormal);
    }
  }
  if (best < 0)
  {
    return;
  }
  const double squaredLength =
    bestNormal[0] * bestNormal[0] + bestNormal[1] * bestNormal[1] + bestNormal[2] * bestNormal[2];
  // Each face corner's weight: the signed area of the sub-triangle x makes with the other two.
  for (int k = 1; k < 4; ++k)
  {
    const double* p = corners[(best + k % 3 + 1) % 4];
    const double* q = corners[(best + (k + 1) % 3 + 1) % 4];
    const double e[3] = { p[0] - x[0], p[1] - x[1], p[2] - x[2] };
    const double f[3] = { q[0] - x[0], q[1] - x[1], q[2] - x[2] };
    const double cross[3] = { e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2],
      e[0] * f[1] - e[1] * f[0] };
    weights[(best + k) % 4] =
      (cross[0] * bestNormal[0] + cross[1] * bestNormal[1] + cross[2] * bestNormal[2]) /
      squaredLength;
  }
  weights[best] = 0;
}

} // namespace

void TetGenSession::prepareInput(tetgenio& in, const std::vector<Face>& keptFaces, TetOrder order,
  TetGenInput input, PointId firstDroppablePoint)
{
  this->Remesh = input != TetGenInput::Tets;
  this->TetsInSpace = this->Remesh ? std::vector<std::size_t>()
                                   : tetsAlongHilbertCurve(this->Partition.tets,
                                       [this](PointId id) { return this->coordinatesOf(id); });
  this->numberPoints();
  this->DropsPoints = input == TetGenInput::KeptFacesAndOwnPoints;
  if (input == TetGenInput::KeptFacesAndOwnPoints)
  {
    this->passOnlyKeptPoints(keptFaces, firstDroppablePoint);
  }
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(this->Numbering.passed);
  in.pointlist = new REAL[3 * in.numberofpoints];
  for (int i = 0; i < in.numberofpoints; ++i)
  {
    std::copy_n(this->coordinatesOf(this->Numbering.idOfLocal[i]), 3, in.pointlist + 3 * i);
  }
  if (this->Context.sizes)
  {
    // TetGen's sizing input (switch m): it splits a tet whose circumradius exceeds the size at
    // one of its corners, and interpolates sizes at the points it inserts.
    in.numberofpointmtrs = 1;
    in.pointmtrlist = new REAL[in.numberofpoints];
    for (int i = 0; i < in.numberofpoints; ++i)
    {
      in.pointmtrlist[i] = TetGenRadiusPerSize * this->sizeOf(this->Numbering.idOfLocal[i]);
    }
  }
  this->KeptFaces.clear();
  for (const Face& face : keptFaces)
  {
    std::array<int, 3> local;
    for (int k = 0; k < 3; ++k)
    {
      local[k] = this->Numbering.localOf(face[k]);
    }
    std::sort(local.begin(), local.end());
    this->KeptFaces.push_back(local);
  }
  std::sort(this->KeptFaces.begin(), this->KeptFaces.end());
  if (this->Remesh)
  {
    this->fillFacetsAndRegions(in, keptFaces, order);
  }
  else
  {
    this->fillTetsAndFaces(in, keptFaces, order);
  }
}

void TetGenSession::numberPoints()
{
  const std::size_t count = this->Partition.tets.size();
  this->Numbering.localOfId.reserve(count / 4 + 16); // a mesh has a fifth to a sixth as many points
  for (std::size_t i = 0; i < count; ++i)
  {
    const std::size_t t = this->TetsInSpace.empty() ? i : this->TetsInSpace[i];
    for (PointId p : this->Partition.tets[t])
    {
      if (this->Numbering.localOfId.emplace(p, static_cast<int>(this->Numbering.idOfLocal.size())))
      {
        this->Numbering.idOfLocal.push_back(p);
        this->Numbering.tetOfLocal.push_back(t);
      }
    }
  }
  this->Numbering.passed = this->Numbering.idOfLocal.size();
}

void TetGenSession::passOnlyKeptPoints(
  const std::vector<Face>& keptFaces, PointId firstDroppablePoint)
{
  LocalNumbering& numbering = this->Numbering;
  std::vector<char> keep(numbering.idOfLocal.size(), 0);
  for (std::size_t i = 0; i < keep.size(); ++i)
  {
    const PointId id = numbering.idOfLocal[i];
    keep[i] = id >= 0 && id < firstDroppablePoint; // provisional (negative) ids are new points
  }
  for (const Face& face : keptFaces)
  {
    for (PointId p : face)
    {
      keep[static_cast<std::size_t>(numbering.localOf(p))] = 1;
    }
  }
  std::vector<std::size_t> order(keep.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_partition(order.begin(), order.end(), [&](std::size_t i) { return keep[i] != 0; });
  LocalNumbering renumbered;
  for (std::size_t old : order)
  {
    renumbered.localOfId.emplace(
      numbering.idOfLocal[old], static_cast<int>(renumbered.idOfLocal.size()));
    renumbered.idOfLocal.push_back(numbering.idOfLocal[old]);
    renumbered.tetOfLocal.push_back(numbering.tetOfLocal[old]);
    renumbered.passed += keep[old] ? 1 : 0;
  }
  numbering = std::move(renumbered);
}

std::vector<int> TetGenSession::localCorners() const
{
  std::vector<int> corners;
  corners.reserve(4 * this->Partition.tets.size());
  for (const Tet& tet : this->Partition.tets)
  {
    for (PointId p : tet)
    {
      corners.push_back(this->Numbering.localOf(p));
    }
  }
  return corners;
}

void TetGenSession::fillTetsAndFaces(
  tetgenio& in, const std::vector<Face>& keptFaces, TetOrder order) const
{
  const std::vector<int> corners = this->localCorners();
  in.numberoftetrahedra = static_cast<int>(this->Partition.tets.size());
  in.numberofcorners = 4;
  in.tetrahedronlist = new int[4 * in.numberoftetrahedra];
  // Two attributes: the tet's index in the partition, then its region, which TetGen compares
  // (the last attribute) to find the material interfaces. A tet TetGen creates takes the
  // attributes of a tet it replaces, so the first names an old tet beside the new one: where
  // adoptOutput's walk to the old tet holding the new tet's centroid starts.
  in.numberoftetrahedronattributes = TetAttributes;
  in.tetrahedronattributelist =
    new REAL[TetAttributes * static_cast<std::size_t>(in.numberoftetrahedra)];
  for (int t = 0; t < in.numberoftetrahedra; ++t)
  {
    const std::size_t source = this->TetsInSpace[order.sourceOf(static_cast<std::size_t>(t))];
    std::copy_n(corners.data() + 4 * source, 4, in.tetrahedronlist + 4 * t);
    in.tetrahedronattributelist[TetAttributes * t] = static_cast<double>(source);
    in.tetrahedronattributelist[TetAttributes * t + 1] = this->regionOfTet(source);
  }
  // The faces to keep, each its own facet (a distinct marker): TetGen merges coplanar
  // neighbouring boundary triangles otherwise and may flip their shared edge, which the
  // partition across would not see.
  in.numberoftrifaces = static_cast<int>(keptFaces.size());
  in.trifacelist = new int[3 * keptFaces.size()];
  in.trifacemarkerlist = new int[keptFaces.size()];
  for (std::size_t f = 0; f < keptFaces.size(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      in.trifacelist[3 * f + k] = this->Numbering.localOf(keptFaces[f][k]);
    }
    in.trifacemarkerlist[f] = static_cast<int>(f) + 1;
  }
}

void TetGenSession::fillFacetsAndRegions(
  tetgenio& in, const std::vector<Face>& keptFaces, TetOrder order)
{
  std::vector<int> faceCorners;
  faceCorners.reserve(3 * keptFaces.size());
  in.facetmarkerlist = new int[keptFaces.size()];
  for (std::size_t f = 0; f < keptFaces.size(); ++f)
  {
    const std::size_t source = order.sourceOf(f);
    for (PointId p : keptFaces[source])
    {
      faceCorners.push_back(this->Numbering.localOf(p));
    }
    in.facetmarkerlist[f] = static_cast<int>(source) + 1;
  }
  setTriangleFacets(in, faceCorners.data(), static_cast<int>(keptFaces.size()));
  const std::vector<int> corners = this->localCorners();
  const std::vector<int> pieceOfTet = enclosedPieces(corners, this->KeptFaces);
  const int pieceCount =
    pieceOfTet.empty() ? 0 : *std::max_element(pieceOfTet.begin(), pieceOfTet.end()) + 1;
  std::vector<double> localCoordinates; // of every local point, dropped ones too
  localCoordinates.reserve(3 * this->Numbering.idOfLocal.size());
  for (PointId id : this->Numbering.idOfLocal)
  {
    const double* xyz = this->coordinatesOf(id);
    localCoordinates.insert(localCoordinates.end(), xyz, xyz + 3);
  }
  const std::vector<std::array<double, 3>> inside =
    pointInsideEachPiece(corners, pieceOfTet, pieceCount, localCoordinates.data());
  this->RegionOfAttribute.assign(this->Partition.regions.begin(), this->Partition.regions.end());
  if (this->RegionOfAttribute.empty())
  {
    this->RegionOfAttribute.push_back(0);
  }
  std::sort(this->RegionOfAttribute.begin(), this->RegionOfAttribute.end());
  this->RegionOfAttribute.erase(
    std::unique(this->RegionOfAttribute.begin(), this->RegionOfAttribute.end()),
    this->RegionOfAttribute.end());
  std::vector<int> regionOfPiece(static_cast<std::size_t>(pieceCount));
  for (std::size_t t = 0; t < pieceOfTet.size(); ++t)
  {
    regionOfPiece[static_cast<std::size_t>(pieceOfTet[t])] = this->regionOfTet(t);
  }
  in.numberofregions = pieceCount;
  in.regionlist = new REAL[5 * static_cast<std::size_t>(pieceCount)];
  for (int piece = 0; piece < pieceCount; ++piece)
  {
    REAL* entry = in.regionlist + 5 * piece;
    std::copy_n(inside[static_cast<std::size_t>(piece)].data(), 3, entry);
    const auto rank = std::lower_bound(this->RegionOfAttribute.begin(),
      this->RegionOfAttribute.end(), regionOfPiece[static_cast<std::size_t>(piece)]);
    entry[3] = 1.0 + static_cast<double>(rank - this->RegionOfAttribute.begin());
    entry[4] = -1.0; // no volume bound of its own
  }
}

bool TetGenSession::regionOfOutputTet(const tetgenio& out, int t, int& region) const
{
  const long attribute = std::lround(regionAttribute(out, t));
  if (!this->Remesh)
  {
    region = static_cast<int>(attribute);
    return true;
  }
  if (attribute < 1 || attribute > static_cast<long>(this->RegionOfAttribute.size()))
  {
    return false;
  }
  region = this->RegionOfAttribute[static_cast<std::size_t>(attribute - 1)];
  return true;
}

std::map<int, double> TetGenSession::regionVolumesOfInput() const
{
  std::map<int, double> volumes;
  for (std::size_t t = 0; t < this->Partition.tets.size(); ++t)
  {
    const Tet& tet = this->Partition.tets[t];
    volumes[this->regionOfTet(t)] += signedVolume6(this->coordinatesOf(tet[0]),
      this->coordinatesOf(tet[1]), this->coordinatesOf(tet[2]), this->coordinatesOf(tet[3]));
  }
  return volumes;
}

std::map<int, double> TetGenSession::regionVolumesOfOutput(const tetgenio& out) const
{
  std::map<int, double> volumes;
  for (int t = 0; t < out.numberoftetrahedra; ++t)
  {
    int region = 0;
    if (this->regionOfOutputTet(out, t, region))
    {
      const int* c = out.tetrahedronlist + 4 * t;
      volumes[region] += signedVolume6(out.pointlist + 3 * c[0], out.pointlist + 3 * c[1],
        out.pointlist + 3 * c[2], out.pointlist + 3 * c[3]);
    }
  }
  return volumes;
}

std::string TetGenSession::validate(
  const tetgenio& in, const tetgenio& out, bool keptFacesMaySplit) const
{
  // Refining, the tets' own attributes come back; meshing anew, the one of switch A.
  const int attributes = this->Remesh ? 1 : TetAttributes;
  if (out.numberofpoints < in.numberofpoints || out.numberoftetrahedra < 1 ||
    out.numberofcorners != 4 || out.numberoftetrahedronattributes != attributes ||
    out.firstnumber != 0)
  {
    return "TetGen returned an incomplete mesh";
  }
  if (!std::equal(in.pointlist, in.pointlist + 3 * in.numberofpoints, out.pointlist))
  {
    return "TetGen moved or renumbered input points";
  }
  // Edges this much shorter than the partition are rounding noise, not refinement: TetGen can
  // leave clusters of such points on some inputs.
  double low[3] = { in.pointlist[0], in.pointlist[1], in.pointlist[2] };
  double high[3] = { low[0], low[1], low[2] };
  for (int p = 0; p < in.numberofpoints; ++p)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      low[axis] = std::min(low[axis], in.pointlist[3 * p + axis]);
      high[axis] = std::max(high[axis], in.pointlist[3 * p + axis]);
    }
  }
  const double shortestAllowed = 1e-8 * std::sqrt(squaredDistance(low, high));
  // Corners of kept faces (input points: TetGen numbers them as given): improvement never moves
  // them, so a flat tet of four such corners would stay flat. Flagged only once a flat tet needs
  // them, which few calls return.
  std::vector<char> onKeptFace;
  const auto allOnKeptFaces = [&](const int* corners)
  {
    if (onKeptFace.empty())
    {
      onKeptFace.assign(static_cast<std::size_t>(out.numberofpoints), 0);
      for (const auto& face : this->KeptFaces)
      {
        for (int p : face)
        {
          if (p >= 0 && p < out.numberofpoints)
          {
            onKeptFace[static_cast<std::size_t>(p)] = 1;
          }
        }
      }
    }
    return std::all_of(
      corners, corners + 4, [&](int p) { return onKeptFace[static_cast<std::size_t>(p)] != 0; });
  };
  for (int t = 0; t < out.numberoftetrahedra; ++t)
  {
    const int* c = out.tetrahedronlist + 4 * t;
    if (*std::min_element(c, c + 4) < 0 || *std::max_element(c, c + 4) >= out.numberofpoints)
    {
      return "TetGen returned an invalid or inverted tetrahedron";
    }
    const double volume6 = signedVolume6(out.pointlist + 3 * c[0], out.pointlist + 3 * c[1],
      out.pointlist + 3 * c[2], out.pointlist + 3 * c[3]);
    if (!(volume6 > 0))
    {
      return "TetGen returned an invalid or inverted tetrahedron";
    }
    double shortest = HUGE_VAL, longest = 0;
    for (const auto& edge : TetEdgeCorners)
    {
      const double squared =
        squaredDistance(out.pointlist + 3 * c[edge[0]], out.pointlist + 3 * c[edge[1]]);
      shortest = std::min(shortest, squared);
      longest = std::max(longest, squared);
    }
    if (std::sqrt(shortest) < shortestAllowed)
    {
      return "TetGen returned a tetrahedron with an edge of rounding-noise length";
    }
    // Flat within rounding, as the mesh checks count a degenerate tet. TetGen leaves such tets
    // among coplanar grid points; refinement's are mended by the improvement that follows, but
    // the sweep's boxes, meshed anew without their interior points, are improved only at former
    // interface vertices. Nor is a flat tet on four corners of kept faces, which improvement
    // never moves: TetGen, meshing anew a partition of a random point cloud's tetrahedralisation,
    // laid one on a flat patch of the hull, its outer faces the kept ones.
    const bool flat = volume6 <= 1e-12 * longest * std::sqrt(longest);
    if (flat && (this->DropsPoints || allOnKeptFaces(c)))
    {
      return "TetGen returned a flat tetrahedron";
    }
  }
  std::vector<std::array<int, 3>> keptInOutput;
  if (!keptFacesOfOutput(out, keptInOutput))
  {
    return "TetGen returned inconsistent face neighbours";
  }
  if (keptFacesMaySplit ? !sameArea(out, keptInOutput, this->KeptFaces)
                        : keptInOutput != this->KeptFaces)
  {
    return "TetGen changed the partition boundary or a material interface";
  }
  const auto before = this->regionVolumesOfInput();
  const auto after = this->regionVolumesOfOutput(out);
  if (before.size() != after.size())
  {
    return "TetGen changed the set of regions";
  }
  for (const auto& region : before)
  {
    const auto found = after.find(region.first);
    if (found == after.end() ||
      std::abs(found->second - region.second) > 1e-9 * std::abs(region.second))
    {
      return "TetGen changed a region's volume";
    }
  }
  return std::string();
}

std::int64_t TetGenSession::ancestorOf(const tetgenio& out, int t) const
{
  if (this->Remesh)
  {
    return -1; // no old tets behind the new ones
  }
  const double ancestor = out.tetrahedronattributelist[static_cast<std::size_t>(t) * TetAttributes];
  return ancestor >= 0 && ancestor < static_cast<double>(this->Partition.tets.size())
    ? static_cast<std::int64_t>(ancestor)
    : -1;
}

template <typename LocatorOf>
std::size_t TetGenSession::parentTet(const tetgenio& out, int t, int region, std::size_t cornerTet,
  bool locating, const LocatorOf& locatorOfOldTets) const
{
  // Without cell data to carry, the old tet TetGen's tet descends from will do: it lies in the
  // same partition, so the PartitionId and ColorId it gives are the located one's, and in the
  // same region (TetGen's cavities stop at the kept faces, region interfaces among them), which
  // is checked.
  const std::int64_t ancestor = this->ancestorOf(out, t);
  if (!locating && ancestor >= 0 && this->regionOfTet(static_cast<std::size_t>(ancestor)) == region)
  {
    return static_cast<std::size_t>(ancestor);
  }
  const int* c = out.tetrahedronlist + 4 * t;
  double centroid[3] = { 0, 0, 0 };
  for (int k = 0; k < 4; ++k)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      centroid[axis] += 0.25 * out.pointlist[3 * c[k] + axis];
    }
  }
  // The walk starts at the old tet TetGen's tet descends from: in the FinFET's partitions it
  // holds the centroid for 63% of the output tets, against a walk of 4.3 steps on average from
  // the first corner's tet, where it starts when meshing anew.
  const std::size_t start = ancestor >= 0 ? static_cast<std::size_t>(ancestor) : cornerTet;
  return locatorOfOldTets().locateFrom(centroid, start).tet;
}

void TetGenSession::adoptOutput(const tetgenio& out, PartitionMesh& partition,
  PartitionRefinement& refinement, DelaunayOutcome& outcome) const
{
  const int inputPointCount = static_cast<int>(this->Numbering.passed);
  // Meshing anew leaves no old tet behind a new one, and sizes are interpolated like point data:
  // then, or where the run carries point or cell data, everything new is located in the old tets.
  const bool locating = this->Remesh || this->Context.sizes || this->Context.locateTetGenOutput;
  std::unique_ptr<TetLocator> locator;
  const auto locatorOfOldTets = [&]() -> const TetLocator&
  {
    if (!locator)
    {
      locator = std::make_unique<TetLocator>(
        this->Partition.tets, [this](PointId id) { return this->coordinatesOf(id); });
      locator->buildFaceNeighbours(this->Partition.tets);
    }
    return *locator;
  };

  // The partition's tets: all of them, but for the cavities of other partitions that remeshing
  // fills too (and the points TetGen inserted there).
  std::vector<int> regionOfOutput(static_cast<std::size_t>(out.numberoftetrahedra));
  std::vector<char> kept(static_cast<std::size_t>(out.numberoftetrahedra), 0);
  std::vector<char> used(static_cast<std::size_t>(out.numberofpoints), 0);
  for (int t = 0; t < out.numberoftetrahedra; ++t)
  {
    if (this->regionOfOutputTet(out, t, regionOfOutput[static_cast<std::size_t>(t)]))
    {
      kept[static_cast<std::size_t>(t)] = 1;
      for (int k = 0; k < 4; ++k)
      {
        used[static_cast<std::size_t>(out.tetrahedronlist[4 * t + k])] = 1;
      }
    }
  }

  // New points first: their ids are needed for the tets. Placing reads the old tets, whose
  // coordinates live in refinement.newCoordinates, so collect the additions before appending.
  std::vector<PointId> idOfOutput(
    this->Numbering.idOfLocal.begin(), this->Numbering.idOfLocal.begin() + inputPointCount);
  std::vector<std::size_t> tetOfOutput(
    this->Numbering.tetOfLocal.begin(), this->Numbering.tetOfLocal.begin() + inputPointCount);
  std::vector<double> coordinates;
  std::vector<PointSource> sources;
  std::vector<double> sizes;
  for (int i = inputPointCount; i < out.numberofpoints; ++i)
  {
    if (!used[static_cast<std::size_t>(i)])
    {
      idOfOutput.push_back(-1); // named by no kept tet
      tetOfOutput.push_back(tetOfOutput.back());
      continue;
    }
    coordinates.insert(coordinates.end(), out.pointlist + 3 * i, out.pointlist + 3 * i + 3);
    idOfOutput.push_back(
      -static_cast<PointId>(refinement.newPointSources.size() + sources.size() + 1));
    if (!locating)
    {
      sources.push_back(PointSource{}); // read by nothing: the run carries no point data
      tetOfOutput.push_back(tetOfOutput.back());
      continue;
    }
    // TetGen inserts points near the ones before them, often in the same old tet.
    const TetLocator::Location where =
      locatorOfOldTets().locateFrom(out.pointlist + 3 * i, tetOfOutput.back());
    std::array<double, 4> weights = where.barycentric;
    if (this->Remesh)
    {
      const double* corners[4];
      for (int k = 0; k < 4; ++k)
      {
        corners[k] = this->coordinatesOf(this->Partition.tets[where.tet][k]);
      }
      weightsOnFace(out.pointlist + 3 * i, corners, weights);
    }
    PointSource source;
    for (int k = 0; k < 4; ++k)
    {
      source.points[k] = this->Partition.tets[where.tet][k];
      source.weights[k] = weights[k];
    }
    sources.push_back(source);
    if (this->Context.sizes)
    {
      double size = 0; // interpolated like the point's data
      for (int k = 0; k < 4; ++k)
      {
        size += source.weights[k] * this->sizeOf(source.points[k]);
      }
      sizes.push_back(size);
    }
    tetOfOutput.push_back(where.tet);
  }

  PartitionMesh refined;
  refined.tets.reserve(out.numberoftetrahedra);
  for (int t = 0; t < out.numberoftetrahedra; ++t)
  {
    if (!kept[static_cast<std::size_t>(t)])
    {
      continue;
    }
    const int* c = out.tetrahedronlist + 4 * t;
    refined.tets.push_back(
      { idOfOutput[c[0]], idOfOutput[c[1]], idOfOutput[c[2]], idOfOutput[c[3]] });
    refined.parentCells.push_back(this->Partition.parentCells[this->parentTet(out, t,
      regionOfOutput[static_cast<std::size_t>(t)], tetOfOutput[c[0]], locating, locatorOfOldTets)]);
    if (!this->Partition.regions.empty())
    {
      refined.regions.push_back(regionOfOutput[static_cast<std::size_t>(t)]);
    }
  }
  refinement.newCoordinates.insert(
    refinement.newCoordinates.end(), coordinates.begin(), coordinates.end());
  refinement.newPointSources.insert(
    refinement.newPointSources.end(), sources.begin(), sources.end());
  refinement.newSizes.insert(refinement.newSizes.end(), sizes.begin(), sizes.end());
  outcome.tetgenPoints = static_cast<std::int64_t>(sources.size());
  partition = std::move(refined);
}

} // namespace cgmesh
