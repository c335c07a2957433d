// One TetGen call on a partition: what TetGen receives of it (its tets, or its kept faces and
// points as a PLC, with or without the interior points refinement made), the check of what it
// returns, and the adoption of the result. The attempts and the switches are TetGenRefiner's.
#ifndef cgmesh_TetGenSession_h
#define cgmesh_TetGenSession_h

#include "Core/FaceKey.h"
#include "Refinement/PartitionRefiner.h"
#include "Refinement/TetGenRefiner.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

class tetgenio;

namespace cgmesh
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
  PointIdMap<int> localOfId;
  std::vector<std::size_t> tetOfLocal; // a partition tet with that point: where walks start
  std::size_t passed = 0;

  // The local number of a point of the partition; throws std::out_of_range for any other.
  int localOf(PointId id) const
  {
    const int* local = this->localOfId.find(id);
    if (!local)
    {
      throw std::out_of_range("a point outside the partition");
    }
    return *local;
  }
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
    TetGenInput input, PointId firstDroppablePoint = 0);

  // The volume of each region, six times over: of the partition as TetGen received it, and of
  // TetGen's output (cavities of other partitions left out).
  std::map<int, double> regionVolumesOfInput() const;
  std::map<int, double> regionVolumesOfOutput(const tetgenio& out) const;

  // Checks what TetGen returned: input points kept in place, positive tets, the same boundary
  // and region interfaces, the same volume per region. Empty when valid.
  // With `keptFacesMaySplit`, the kept faces may come back split: then their total area, not the
  // faces themselves, must be what was given.
  std::string validate(const tetgenio& in, const tetgenio& out, bool keptFacesMaySplit) const;

  // The partition's points TetGen meshed without.
  std::int64_t droppedPoints() const
  {
    return static_cast<std::int64_t>(this->Numbering.idOfLocal.size() - this->Numbering.passed);
  }

  // Replaces the partition by TetGen's output; new points are placed in the old tets.
  void adoptOutput(const tetgenio& out, PartitionMesh& partition, PartitionRefinement& refinement,
    DelaunayOutcome& outcome) const;

private:
  // Local numbers in the order the tets TetGen receives (TetsInSpace for switch r, else the
  // partition's own order) first reach the points.
  void numberPoints();

  // Renumbers the points so that those TetGen receives come first, in their order, and the
  // dropped ones after them: the points from `firstDroppablePoint` on that lie on no kept face.
  // Such a point is used by this partition's tets alone (any other tet at it would leave a kept
  // face of this partition at it), so no other partition loses it.
  void passOnlyKeptPoints(const std::vector<Face>& keptFaces, PointId firstDroppablePoint);

  std::vector<int> localCorners() const;

  int regionOfTet(std::size_t t) const
  {
    return this->Partition.regions.empty() ? 0 : this->Partition.regions[t];
  }

  // Switch r: the tets with their regions as attributes, and the kept faces.
  void fillTetsAndFaces(tetgenio& in, const std::vector<Face>& keptFaces, TetOrder order) const;

  // Switch p: each kept face its own facet, and a point inside each piece of the partition with
  // the piece's region as its attribute (switch A). Attributes are 1 + the region's rank among
  // the partition's regions: TetGen numbers the pockets that receive no point upwards from the
  // largest attribute given, so any other attribute marks a cavity of other partitions.
  void fillFacetsAndRegions(tetgenio& in, const std::vector<Face>& keptFaces, TetOrder order);

  // Switch r: per tet, its index in the partition and its region.
  static constexpr int TetAttributes = 2;

  // The old tet output tet t descends from (the first attribute TetGen carried over), or -1 when
  // meshing anew or when the attribute names no old tet.
  std::int64_t ancestorOf(const tetgenio& out, int t) const;
  // The old tet whose cell data output tet t (of `region`) takes: the one holding its centroid,
  // found by a walk from the old tet it descends from (meshing anew, from `cornerTet`, an old
  // tet at its first corner); or, when not `locating`, the old tet it descends from if that is
  // of its region. `locatorOfOldTets()` gives the locator, built on first need.
  template <typename LocatorOf>
  std::size_t parentTet(const tetgenio& out, int t, int region, std::size_t cornerTet,
    bool locating, const LocatorOf& locatorOfOldTets) const;

  // The region of output tet t; false for a tet in a cavity of other partitions (remeshing only).
  bool regionOfOutputTet(const tetgenio& out, int t, int& region) const;

  const PartitionMesh& Partition;
  const RefinementContext& Context;
  const PartitionRefinement& Refinement;
  LocalNumbering Numbering;
  // Switch r: the partition's tets along a Hilbert curve, the order TetGen receives them in (the
  // attempt's order applies to this sequence).
  std::vector<std::size_t> TetsInSpace;
  std::vector<std::array<int, 3>> KeptFaces; // in local numbers, sorted
  bool Remesh = false;
  bool DropsPoints = false;           // KeptFacesAndOwnPoints: the sweep across former interfaces
  std::vector<int> RegionOfAttribute; // remeshing: the region of TetGen's attribute a at a - 1
};

} // namespace cgmesh

#endif
