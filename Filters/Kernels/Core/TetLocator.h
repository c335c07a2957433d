// Finds the tet of a small mesh that contains a point, with its barycentric coordinates: used to
// place Delaunay Steiner points (for point data) and to find a new tet's parent (for cell data).
#ifndef cgmesh_TetLocator_h
#define cgmesh_TetLocator_h

#include "Core/TetMesh.h"

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace cgmesh
{

// Searches change cached state (the grid, built on first need): one thread at a time.
class TetLocator
{
public:
  using CoordinatesOf = std::function<const double*(PointId)>;

  // `tets` and the coordinates must outlive the locator.
  TetLocator(const TetList& tets, CoordinatesOf coordinatesOf);

  struct Location
  {
    std::size_t tet = 0;
    std::array<double, 4> barycentric = { 0, 0, 0, 0 };
  };

  // The tet whose smallest barycentric coordinate for `point` is largest: the containing tet, or
  // for a point a rounding error outside every tet, the nearest one in that sense.
  Location locate(const double* point) const;

  // Face neighbours for locateFrom(): one hashing pass over `tets`, those of the constructor.
  void buildFaceNeighbours(const TetList& tets);

  // A tet containing `point`, found by walking from tet `start` towards it across the face the
  // point lies furthest beyond: a few steps for a point near `start`, where a graded mesh fills
  // the grid buckets with large tets. A walk stopped by the mesh's boundary or going on too long
  // goes on breadth first from where it stopped; only a point outside that connected piece of
  // the mesh ends in locate(). Needs buildFaceNeighbours().
  Location locateFrom(const double* point, std::size_t start) const;

private:
  Location bestAmong(const double* point, const std::size_t* first, const std::size_t* last) const;
  std::array<double, 4> barycentric(std::size_t tet, const double* point) const;
  bool mayContain(std::size_t tet, const double* point) const; // bounding-box test
  std::size_t cellIndex(const double* point) const;
  void buildGrid() const;
  Location searchAround(const double* point, std::size_t start) const;

  // Per tet, once: barycentric coordinate k is gradients[k] . (x - anchor), the anchor being
  // corner 1 for k = 0 and corner 0 otherwise (both lie on the face opposite corner k). Four dot
  // products per candidate instead of four volumes and divisions.
  struct FacePlanes
  {
    std::array<std::array<double, 3>, 2> anchors;
    std::array<std::array<double, 3>, 4> gradients;
  };
  const TetList* Tets;
  CoordinatesOf Coordinates;
  std::vector<FacePlanes> Faces;
  std::vector<std::int64_t> FaceNeighbours; // 4 per tet, across the face opposite corner k; -1

  // The grid for locate(): per tet its bounding box (low xyz, high xyz), and the tets whose box
  // meets grid cell c in BucketTets[BucketOffsets[c] .. [c + 1]).
  mutable std::vector<double> Boxes;
  mutable double Low[3], CellSize[3];
  mutable int Resolution = 1;
  mutable std::vector<std::size_t> BucketOffsets;
  mutable std::vector<std::size_t> BucketTets;
  // searchAround(): tets marked with the current stamp were reached, and the queue.
  mutable std::vector<unsigned> Visited;
  mutable unsigned VisitStamp = 0;
  mutable std::vector<std::size_t> Queue;
};

} // namespace cgmesh

#endif
