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

class TetLocator
{
public:
  using CoordinatesOf = std::function<const double*(PointId)>;

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

  // A tet containing `point`, found by walking from tet `start` towards it across the face
  // opposite the most negative barycentric coordinate: a few steps for a point near `start`,
  // where a graded mesh fills the grid buckets with large tets. A walk that leaves the mesh or
  // goes on too long ends in locate(). Needs buildFaceNeighbours().
  Location locateFrom(const double* point, std::size_t start) const;

private:
  Location bestAmong(const double* point, const std::size_t* first, const std::size_t* last) const;
  std::array<double, 4> barycentric(std::size_t tet, const double* point) const;
  bool mayContain(std::size_t tet, const double* point) const; // bounding-box test
  std::size_t cellIndex(const double* point) const;

  // Per tet, copied once: the corners' coordinates (12 values), the bounding box (low xyz, high
  // xyz) and six times the signed volume. Queries then touch one contiguous record per candidate.
  std::vector<double> Corners;
  std::vector<double> Boxes;
  std::vector<double> Volumes6;
  double Low[3], CellSize[3];
  int Resolution = 1;
  // The tets whose bounding box meets grid cell c: BucketTets[BucketOffsets[c] .. [c + 1]).
  std::vector<std::size_t> BucketOffsets;
  std::vector<std::size_t> BucketTets;
  std::vector<std::int64_t> FaceNeighbours; // 4 per tet, across the face opposite corner k; -1
};

} // namespace cgmesh

#endif
