#include "Refinement/TetGenRefiner.h"

#include "Refinement/ConstrainedEdgeSplits.h"
#include "Refinement/EnclosedPieces.h"

#include "Core/ConstrainedFaces.h"
#include "Core/FaceKey.h"
#include "Core/Geometry.h"
#include "Core/TetLocator.h"
#include "Core/TetQuality.h"

#define TETLIBRARY
#include <tetgen.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <new>
#include <numeric>
#include <unordered_map>

namespace cgmesh
{
namespace
{

// An order of a partition's n tets: the t-th tet handed to TetGen is tet sourceOf(t).
struct TetOrder
{
  std::size_t count = 0;
  std::size_t step = 1; // coprime to count: t -> (start + t * step) mod count is a permutation
  std::size_t start = 0;

  std::size_t sourceOf(std::size_t t) const { return (this->start + t * this->step) % this->count; }

  static TetOrder forward(std::size_t n) { return { n, 1, 0 }; }
  static TetOrder reversed(std::size_t n) { return { n, n - 1, n - 1 }; }
  // Neighbouring tets far apart in the sequence: a step near n / golden ratio, made coprime.
  static TetOrder strided(std::size_t n)
  {
    std::size_t step = std::max<std::size_t>(1, static_cast<std::size_t>(0.618 * n));
    while (std::gcd(step, n) != 1)
    {
      ++step;
    }
    return { n, step, 0 };
  }
};

// What TetGen receives of a partition.
enum class TetGenInput
{
  Tets,                  // its tets, to refine (switch r)
  KeptFacesAndPoints,    // its kept faces and all its points, to mesh anew (switch p)
  KeptFacesAndOwnPoints, // the same without the interior points refinement made (see
                         // remeshPartitionDelaunay)
};

// The partition renumbered 0..n-1 for TetGen, and the way back. Only the first `passed` points
// go to TetGen: the others are interior points it meshes without (and that the partition loses).
struct LocalNumbering
{
  std::vector<PointId> idOfLocal;
  std::unordered_map<PointId, int> localOfId;
  std::vector<std::size_t> tetOfLocal; // a partition tet with that point: where walks start
  std::size_t passed = 0;
};

class TetGenSession
{
public:
  TetGenSession(const PartitionMesh& partition, const RefinementContext& context,
    const PartitionRefinement& refinement)
    : Partition(partition)
    , Context(context)
    , Refinement(refinement)
  {
  }

  const double* coordinatesOf(PointId id) const
  {
    return pointCoordinates(*this->Context.coordinates, this->Refinement.newCoordinates, id);
  }

  double sizeOf(PointId id) const
  {
    return pointSize(*this->Context.sizes, this->Refinement.newSizes, id);
  }

  // Fills TetGen's input from the partition and the faces it must keep (see TetGenInput).
  // `order` says in which order TetGen receives the tets, or the faces when remeshing (the
  // attempts of refineWithTetGen). With KeptFacesAndOwnPoints, the points from
  // `firstDroppablePoint` on that lie on no kept face are left out.
  void prepareInput(tetgenio& in, const std::vector<Face>& keptFaces, TetOrder order,
    TetGenInput input, PointId firstDroppablePoint = 0)
  {
    this->numberPoints();
    this->Remesh = input != TetGenInput::Tets;
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
        local[k] = this->Numbering.localOfId.at(face[k]);
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

  // The volume of each region, six times over: of the partition as TetGen received it, and of
  // TetGen's output (cavities of other partitions left out).
  std::map<int, double> regionVolumesOfInput() const;
  std::map<int, double> regionVolumesOfOutput(const tetgenio& out) const;

  // Checks what TetGen returned: input points kept in place, positive tets, the same boundary
  // and region interfaces, the same volume per region. Empty when valid.
  std::string validate(const tetgenio& in, const tetgenio& out) const;

  // The partition's points TetGen meshed without.
  std::int64_t droppedPoints() const
  {
    return static_cast<std::int64_t>(this->Numbering.idOfLocal.size() - this->Numbering.passed);
  }

  // Replaces the partition by TetGen's output; new points are placed in the old tets.
  void adoptOutput(const tetgenio& out, PartitionMesh& partition, PartitionRefinement& refinement,
    DelaunayOutcome& outcome) const;

private:
  // Local numbers in the order the partition's tets first reach the points.
  void numberPoints()
  {
    for (const Tet& tet : this->Partition.tets)
    {
      for (PointId p : tet)
      {
        if (this->Numbering.localOfId.emplace(p, static_cast<int>(this->Numbering.idOfLocal.size()))
              .second)
        {
          this->Numbering.idOfLocal.push_back(p);
          this->Numbering.tetOfLocal.push_back(
            static_cast<std::size_t>(&tet - this->Partition.tets.data()));
        }
      }
    }
    this->Numbering.passed = this->Numbering.idOfLocal.size();
  }

  // Renumbers the points so that those TetGen receives come first, in their order, and the
  // dropped ones after them: the points from `firstDroppablePoint` on that lie on no kept face.
  // Such a point is used by this partition's tets alone (any other tet at it would leave a kept
  // face of this partition at it), so no other partition loses it.
  void passOnlyKeptPoints(const std::vector<Face>& keptFaces, PointId firstDroppablePoint)
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
        keep[static_cast<std::size_t>(numbering.localOfId.at(p))] = 1;
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

  std::vector<int> localCorners() const
  {
    std::vector<int> corners;
    corners.reserve(4 * this->Partition.tets.size());
    for (const Tet& tet : this->Partition.tets)
    {
      for (PointId p : tet)
      {
        corners.push_back(this->Numbering.localOfId.at(p));
      }
    }
    return corners;
  }

  int regionOfTet(std::size_t t) const
  {
    return this->Partition.regions.empty() ? 0 : this->Partition.regions[t];
  }

  // Switch r: the tets with their regions as attributes, and the kept faces.
  void fillTetsAndFaces(tetgenio& in, const std::vector<Face>& keptFaces, TetOrder order) const
  {
    const std::vector<int> corners = this->localCorners();
    in.numberoftetrahedra = static_cast<int>(this->Partition.tets.size());
    in.numberofcorners = 4;
    in.tetrahedronlist = new int[4 * in.numberoftetrahedra];
    in.numberoftetrahedronattributes = 1;
    in.tetrahedronattributelist = new REAL[in.numberoftetrahedra];
    for (int t = 0; t < in.numberoftetrahedra; ++t)
    {
      const std::size_t source = order.sourceOf(static_cast<std::size_t>(t));
      std::copy_n(corners.data() + 4 * source, 4, in.tetrahedronlist + 4 * t);
      in.tetrahedronattributelist[t] = this->regionOfTet(source);
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
        in.trifacelist[3 * f + k] = this->Numbering.localOfId.at(keptFaces[f][k]);
      }
      in.trifacemarkerlist[f] = static_cast<int>(f) + 1;
    }
  }

  // Switch p: each kept face its own facet, and a point inside each piece of the partition with
  // the piece's region as its attribute (switch A). Attributes are 1 + the region's rank among
  // the partition's regions: TetGen numbers the pockets that receive no point upwards from the
  // largest attribute given, so any other attribute marks a cavity of other partitions.
  void fillFacetsAndRegions(tetgenio& in, const std::vector<Face>& keptFaces, TetOrder order)
  {
    std::vector<int> faceCorners;
    faceCorners.reserve(3 * keptFaces.size());
    in.facetmarkerlist = new int[keptFaces.size()];
    for (std::size_t f = 0; f < keptFaces.size(); ++f)
    {
      const std::size_t source = order.sourceOf(f);
      for (PointId p : keptFaces[source])
      {
        faceCorners.push_back(this->Numbering.localOfId.at(p));
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

  // The region of output tet t; false for a tet in a cavity of other partitions (remeshing only).
  bool regionOfOutputTet(const tetgenio& out, int t, int& region) const
  {
    const long attribute = std::lround(out.tetrahedronattributelist[t]);
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

  const PartitionMesh& Partition;
  const RefinementContext& Context;
  const PartitionRefinement& Refinement;
  LocalNumbering Numbering;
  std::vector<std::array<int, 3>> KeptFaces; // in local numbers, sorted
  bool Remesh = false;
  bool DropsPoints = false;           // KeptFacesAndOwnPoints: the sweep across former interfaces
  std::vector<int> RegionOfAttribute; // remeshing: the region of TetGen's attribute a at a - 1
};

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
        if (std::find(other, other + 4, corners[k]) != other + 4)
        {
          ++common;
        }
        else
        {
          missing = k;
        }
      }
      const int* back = io.neighborlist + 4 * n;
      if (common != 3 || (sharedFaces & (1 << missing)) || std::find(back, back + 4, t) == back + 4)
      {
        return false;
      }
      sharedFaces |= 1 << missing;
      if (t < n && io.tetrahedronattributelist[t] != io.tetrahedronattributelist[n])
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

std::string TetGenSession::validate(const tetgenio& in, const tetgenio& out) const
{
  if (out.numberofpoints < in.numberofpoints || out.numberoftetrahedra < 1 ||
    out.numberofcorners != 4 || out.numberoftetrahedronattributes < 1 || out.firstnumber != 0)
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
  for (int t = 0; t < out.numberoftetrahedra; ++t)
  {
    const int* c = out.tetrahedronlist + 4 * t;
    if (*std::min_element(c, c + 4) < 0 || *std::max_element(c, c + 4) >= out.numberofpoints ||
      !(signedVolume6(out.pointlist + 3 * c[0], out.pointlist + 3 * c[1], out.pointlist + 3 * c[2],
          out.pointlist + 3 * c[3]) > 0))
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
    // interface vertices.
    if (this->DropsPoints &&
      signedVolume6(out.pointlist + 3 * c[0], out.pointlist + 3 * c[1], out.pointlist + 3 * c[2],
        out.pointlist + 3 * c[3]) <= 1e-12 * longest * std::sqrt(longest))
    {
      return "TetGen returned a flat tetrahedron";
    }
  }
  std::vector<std::array<int, 3>> keptInOutput;
  if (!keptFacesOfOutput(out, keptInOutput))
  {
    return "TetGen returned inconsistent face neighbours";
  }
  if (keptInOutput != this->KeptFaces)
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

void TetGenSession::adoptOutput(const tetgenio& out, PartitionMesh& partition,
  PartitionRefinement& refinement, DelaunayOutcome& outcome) const
{
  const int inputPointCount = static_cast<int>(this->Numbering.passed);
  TetLocator locator(this->Partition.tets, [this](PointId id) { return this->coordinatesOf(id); });
  locator.buildFaceNeighbours(this->Partition.tets);

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
    // TetGen inserts points near the ones before them, often in the same old tet.
    const TetLocator::Location where =
      locator.locateFrom(out.pointlist + 3 * i, tetOfOutput.back());
    PointSource source;
    for (int k = 0; k < 4; ++k)
    {
      source.points[k] = this->Partition.tets[where.tet][k];
      source.weights[k] = where.barycentric[k];
    }
    sources.push_back(source);
    coordinates.insert(coordinates.end(), out.pointlist + 3 * i, out.pointlist + 3 * i + 3);
    if (this->Context.sizes)
    {
      double size = 0; // interpolated like the point's data
      for (int k = 0; k < 4; ++k)
      {
        size += source.weights[k] * this->sizeOf(source.points[k]);
      }
      sizes.push_back(size);
    }
    idOfOutput.push_back(-static_cast<PointId>(refinement.newPointSources.size() + sources.size()));
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
    double centroid[3] = { 0, 0, 0 };
    for (int k = 0; k < 4; ++k)
    {
      for (int axis = 0; axis < 3; ++axis)
      {
        centroid[axis] += 0.25 * out.pointlist[3 * c[k] + axis];
      }
    }
    refined.tets.push_back(
      { idOfOutput[c[0]], idOfOutput[c[1]], idOfOutput[c[2]], idOfOutput[c[3]] });
    // The centroid lies a step or two from the old tet that holds the tet's first corner.
    refined.parentCells.push_back(
      this->Partition.parentCells[locator.locateFrom(centroid, tetOfOutput[c[0]]).tet]);
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

std::string tetgenSwitches(
  const DelaunayParameters& parameters, bool qualityBound, bool sizeField, bool remesh)
{
  // r: refine the given mesh, or p: mesh the kept faces and the points anew, with A: the region
  // attributes from the region list; Y: keep the given boundary and interface faces; M: do not
  // merge coplanar facets; Q: quiet; n: return the face neighbours (for validation); q: the
  // radius-edge bound, when asked; a: the volume bound, when there is one; m: the sizes given
  // per point, with a size field.
  std::string switches = remesh ? "pAYMQn" : "rYMQn";
  char bound[64];
  if (qualityBound)
  {
    std::snprintf(bound, sizeof(bound), "q%.17g", parameters.radiusEdgeRatio);
    switches += bound;
  }
  else if (sizeField)
  {
    // TetGen refines only with q; a radius-edge bound no tet reaches leaves the shapes alone.
    switches += "q1000";
  }
  if (parameters.maximumVolume > 0)
  {
    std::snprintf(bound, sizeof(bound), "a%.17g", parameters.maximumVolume);
    switches += bound;
  }
  return sizeField ? switches + "m" : switches;
}

// Whether TetGen should mesh the partition anew from its kept faces and points rather than refine
// its tets: when its tets hold many slivers. TetGen cannot split a kept face, and refining a mesh
// whose slivers rest on kept faces costs it minutes and leaves worse slivers (a partition of the
// TetGen mesh of random points in a block: 116 s and min dihedral p1 0.005 degrees when refined,
// 0.9 s and 7.6 degrees when meshed anew). Meshing anew costs about 1.5 times refining on good
// partitions, so it is kept for those that need it.
bool holdsManySlivers(const PartitionMesh& partition, const RefinementContext& context,
  const PartitionRefinement& refinement)
{
  std::size_t slivers = 0;
  for (const Tet& tet : partition.tets)
  {
    const double* p[4];
    for (int k = 0; k < 4; ++k)
    {
      p[k] = pointCoordinates(*context.coordinates, refinement.newCoordinates, tet[k]);
    }
    if (minimumDihedralAngle(p[0], p[1], p[2], p[3]) < RemeshSliverDegrees)
    {
      ++slivers;
    }
  }
  return static_cast<double>(slivers) >
    RemeshSliverShare * static_cast<double>(partition.tets.size());
}

// One TetGen call of a partition: the order the tets (or when remeshing, the kept faces) are
// handed over in, whether the radius-edge bound applies, and whether the partition is meshed anew.
struct TetGenAttempt
{
  TetOrder order;
  bool qualityBound;
  TetGenInput input;
};

// Runs the attempts in turn until one gives a valid mesh, which the partition adopts; returns
// the last failure, empty on success. A call stopped at the time limit while refining (switch r)
// ends the attempts.
std::string runAttempts(const std::vector<TetGenAttempt>& attempts, PartitionMesh& partition,
  const std::vector<Face>& keptFaces, const RefinementContext& context,
  const DelaunayParameters& parameters, PointId firstDroppablePoint, const TetGenRunner& runTetGen,
  PartitionRefinement& refinement, DelaunayOutcome& outcome)
{
  std::string failure;
  for (const TetGenAttempt& attempt : attempts)
  {
    TetGenSession session(partition, context, refinement);
    tetgenio in, out;
    session.prepareInput(in, keptFaces, attempt.order, attempt.input, firstDroppablePoint);
    const bool remesh = attempt.input != TetGenInput::Tets;
    failure = runTetGen(
      in, tetgenSwitches(parameters, attempt.qualityBound, context.sizes != nullptr, remesh), out);
    if (failure.empty())
    {
      failure = session.validate(in, out);
    }
    if (failure.empty())
    {
      session.adoptOutput(out, partition, refinement, outcome);
      outcome.withoutQualityBound = !attempt.qualityBound;
      outcome.remeshed = remesh;
      outcome.droppedPoints = session.droppedPoints();
      return failure;
    }
    outcome.retried = true;
    if (!remesh && failure.rfind(TetGenTimeLimitReason, 0) == 0)
    {
      break;
    }
  }
  return failure;
}

// Runs TetGen on the partition; an empty string means the partition now holds TetGen's mesh.
std::string refineWithTetGen(PartitionMesh& partition, const std::vector<Face>& keptFaces,
  const RefinementContext& context, const DelaunayParameters& parameters,
  const TetGenRunner& runTetGen, PartitionRefinement& refinement, DelaunayOutcome& outcome)
{
  if (parameters.simulateFailure)
  {
    return "simulated TetGen failure";
  }
  // TetGen 1.5 aborts on some inputs with many coplanar and cospherical points (its symbolic
  // perturbation asserts in insphere_s), or flips a kept face among coplanar ones; the same tets
  // in another order take other insertion paths, so a failed call is tried again with the tets
  // reversed, then strided. On sliver-laden partitions the flips come from the radius-edge
  // refinement itself, in every order, and never from the volume bound alone: the last attempt
  // drops q and leaves the shapes to the improvement sweeps, before the partition falls back. A
  // call stopped at the time limit ends the attempts: on the partitions measured, TetGen loops on
  // the same kept faces in every order and without q too, and each attempt costs the whole limit.
  // A sliver-laden partition is first meshed anew; where TetGen fails on that too (it can loop
  // on kept faces that are slivers' faces), the partition is refined as any other.
  std::vector<TetGenAttempt> attempts;
  if (holdsManySlivers(partition, context, refinement))
  {
    attempts.push_back(
      { TetOrder::forward(keptFaces.size()), true, TetGenInput::KeptFacesAndPoints });
  }
  const std::size_t count = partition.tets.size();
  attempts.push_back({ TetOrder::forward(count), true, TetGenInput::Tets });
  attempts.push_back({ TetOrder::reversed(count), true, TetGenInput::Tets });
  attempts.push_back({ TetOrder::strided(count), true, TetGenInput::Tets });
  attempts.push_back({ TetOrder::forward(count), false, TetGenInput::Tets });
  return runAttempts(
    attempts, partition, keptFaces, context, parameters, 0, runTetGen, refinement, outcome);
}

// TetGen's output tets per regular tet of edge h that fills the same volume: 1.68 M tets on the
// Big cube with h = 0.01 + 0.08 |x - 0.5|, whose volume holds 1.02 M regular tets.
constexpr double SizeFieldTetsPerRegularTet = 1.65;

double regularTetVolume(double edge)
{
  return edge * edge * edge / (6.0 * std::sqrt(2.0));
}

} // namespace

void setTriangleFacets(tetgenio& io, const int* corners, int count)
{
  io.numberoffacets = count;
  io.facetlist = new tetgenio::facet[static_cast<std::size_t>(count)];
  for (int f = 0; f < count; ++f)
  {
    tetgenio::facet& facet = io.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(facet.polygonlist);
    facet.polygonlist[0].numberofvertices = 3;
    facet.polygonlist[0].vertexlist = new int[3];
    std::copy_n(corners + 3 * f, 3, facet.polygonlist[0].vertexlist);
  }
}

double forecastDelaunayTets(double volume, double maximumVolume)
{
  return 3.0 * volume / maximumVolume;
}

double forecastDelaunayTetsForSizes(const std::vector<Tet>& tets,
  const std::vector<double>& coordinates, const std::vector<double>& sizes)
{
  double total = 0;
  for (const Tet& tet : tets)
  {
    const double volume =
      signedVolume6(coordinates.data() + 3 * tet[0], coordinates.data() + 3 * tet[1],
        coordinates.data() + 3 * tet[2], coordinates.data() + 3 * tet[3]) /
      6.0;
    const double size = 0.25 * (sizes[tet[0]] + sizes[tet[1]] + sizes[tet[2]] + sizes[tet[3]]);
    total += SizeFieldTetsPerRegularTet * volume / regularTetVolume(size);
  }
  return total;
}

double interfaceEdgeLengthForVolume(double maximumVolume)
{
  return std::cbrt(6.0 * std::sqrt(2.0) * maximumVolume);
}

Status remeshPartitionDelaunay(PartitionMesh& partition, const RefinementContext& context,
  const DelaunayParameters& parameters, PointId firstDroppablePoint, const TetGenRunner& runTetGen,
  PartitionRefinement& refinement, DelaunayOutcome& outcome)
{
  if (partition.tets.empty())
  {
    return Status::success();
  }
  std::vector<Face> keptFaces, regionInterfaceFaces;
  findConstrainedFaces(partition, keptFaces, regionInterfaceFaces);
  keptFaces.insert(keptFaces.end(), regionInterfaceFaces.begin(), regionInterfaceFaces.end());
  // A second order of the faces where TetGen fails on the first (see refineWithTetGen).
  const std::vector<TetGenAttempt> attempts{
    { TetOrder::forward(keptFaces.size()), true, TetGenInput::KeptFacesAndOwnPoints },
    { TetOrder::strided(keptFaces.size()), true, TetGenInput::KeptFacesAndOwnPoints },
  };
  outcome.reason = parameters.simulateFailure
    ? std::string("simulated TetGen failure")
    : runAttempts(attempts, partition, keptFaces, context, parameters, firstDroppablePoint,
        runTetGen, refinement, outcome);
  outcome.fellBack = !outcome.reason.empty();
  return Status::success();
}

Status refinePartitionDelaunay(PartitionMesh& partition, const RefinementContext& context,
  const EdgeMidpointMap& received, const DelaunayParameters& parameters,
  const TetGenRunner& runTetGen, PartitionRefinement& refinement, DelaunayOutcome& outcome)
{
  if (partition.tets.empty())
  {
    return Status::success();
  }
  std::vector<Face> boundaryFaces, regionInterfaceFaces;
  Status status = splitConstrainedEdges(
    partition, context, received, refinement, boundaryFaces, regionInterfaceFaces);
  if (!status.ok())
  {
    return status;
  }
  const std::size_t boundaryCount = boundaryFaces.size();
  std::vector<Face> keptFaces = boundaryFaces;
  keptFaces.insert(keptFaces.end(), regionInterfaceFaces.begin(), regionInterfaceFaces.end());

  const std::string failure =
    refineWithTetGen(partition, keptFaces, context, parameters, runTetGen, refinement, outcome);
  if (failure.empty())
  {
    return Status::success();
  }
  // Fallback: template-split the interior. The boundary stays frozen: its splits are already
  // posted, and neighbours will heal exactly those.
  outcome.fellBack = true;
  outcome.reason = failure;
  keptFaces.resize(boundaryCount); // the partition is as TetGen received it
  EdgeSet frozenEdges;
  addFaceEdges(keptFaces, frozenEdges);
  return refinePartition(
    partition, context, EdgeMidpointMap(), refinement, EdgeFilter{ &frozenEdges, false });
}

} // namespace cgmesh
