// Unstructured meshes made without a quality bound, full of slivers, for the tests of both
// methods on such inputs: TetGen fills a polyhedron with pseudo-random points (the same on every
// machine).
#ifndef cgmesh_SliverLadenMeshes_h
#define cgmesh_SliverLadenMeshes_h

#include "Core/Geometry.h"
#include "Core/TetMesh.h"
#include "Core/TetQuality.h"

#ifndef TETLIBRARY
#define TETLIBRARY
#endif
#include <tetgen.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace cgmesh_test
{
using namespace cgmesh;

// Pseudo-random numbers in [0, 1), the same on every machine.
class UnitRandom
{
public:
  double next()
  {
    this->State = this->State * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(this->State >> 11) / 9007199254740992.0;
  }

private:
  std::uint64_t State = 12345;
};

// `in`'s facets: one polygon each, of the given point indices.
inline void setPolygonFacets(tetgenio& in, const std::vector<std::vector<int>>& polygons)
{
  in.numberoffacets = static_cast<int>(polygons.size());
  in.facetlist = new tetgenio::facet[polygons.size()];
  for (std::size_t f = 0; f < polygons.size(); ++f)
  {
    tetgenio::facet& facet = in.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(facet.polygonlist);
    facet.polygonlist[0].numberofvertices = static_cast<int>(polygons[f].size());
    facet.polygonlist[0].vertexlist = new int[polygons[f].size()];
    std::copy(polygons[f].begin(), polygons[f].end(), facet.polygonlist[0].vertexlist);
  }
}

// TetGen's mesh of the piecewise linear complex `in` with its regions and no quality bound.
inline TetMesh meshWithoutQualityBound(tetgenio& in)
{
  tetgenio out;
  tetgenbehavior behaviour;
  behaviour.parse_commandline(const_cast<char*>("pAQ"));
  tetrahedralize(&behaviour, &in, &out);
  TetMesh mesh;
  mesh.coordinates.assign(out.pointlist, out.pointlist + 3 * out.numberofpoints);
  for (int t = 0; t < out.numberoftetrahedra; ++t)
  {
    Tet tet;
    std::copy_n(out.tetrahedronlist + 4 * t, 4, tet.begin());
    if (signedVolume6(mesh, tet) < 0)
    {
      std::swap(tet[0], tet[1]);
    }
    mesh.tets.push_back(tet);
    mesh.regions.push_back(static_cast<int>(std::lround(out.tetrahedronattributelist[t])));
  }
  return mesh;
}

// A block with a cube inside, both materials filled by TetGen with pseudo-random points and no
// quality bound: full of slivers, as unstructured meshes made without one are, while the faces of
// both cubes are good triangles. Region 1 is the block around the inner cube, region 2 the cube.
inline TetMesh sliverLadenBlock(int pointCount)
{
  tetgenio in;
  in.numberofpoints = 16 + pointCount;
  in.pointlist = new REAL[3 * in.numberofpoints];
  UnitRandom random;
  for (int i = 0; i < in.numberofpoints; ++i)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      const int corner = (i >> axis) & 1;
      const double value = random.next();
      in.pointlist[3 * i + axis] = i < 8 ? corner : i < 16 ? 0.35 + 0.3 * corner : value;
    }
  }
  // The six faces of each cube, as quadrilaterals of corner indices.
  const int faces[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 },
    { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
  std::vector<std::vector<int>> polygons;
  for (int f = 0; f < 12; ++f)
  {
    polygons.emplace_back();
    for (int k = 0; k < 4; ++k)
    {
      polygons.back().push_back(faces[f % 6][k] + (f < 6 ? 0 : 8));
    }
  }
  setPolygonFacets(in, polygons);
  in.numberofregions = 2;
  in.regionlist = new REAL[10]{ 0.1, 0.1, 0.1, 1, -1, 0.5, 0.5, 0.5, 2, -1 };
  return meshWithoutQualityBound(in);
}

// A thin fin [0.45, 0.55] x [0, 1] x [0.5, 0.75] (region 2) on a block [0, 2] x [0, 1] x [0, 0.5]
// (region 1), filled by TetGen with pseudo-random points and no quality bound. The block's front
// and back faces run around the fin's footprint, and their triangulation holds needles: thin
// triangles that no point placed off the face can make good tets on.
inline TetMesh sliverLadenFinOnBlock(int pointCount)
{
  const double corners[16][3] = { { 0, 0, 0 }, { 2, 0, 0 }, { 2, 1, 0 }, { 0, 1, 0 }, { 0, 0, 0.5 },
    { 0.45, 0, 0.5 }, { 0.55, 0, 0.5 }, { 2, 0, 0.5 }, { 0, 1, 0.5 }, { 0.45, 1, 0.5 },
    { 0.55, 1, 0.5 }, { 2, 1, 0.5 }, { 0.45, 0, 0.75 }, { 0.55, 0, 0.75 }, { 0.45, 1, 0.75 },
    { 0.55, 1, 0.75 } };
  tetgenio in;
  in.numberofpoints = 16 + pointCount;
  in.pointlist = new REAL[3 * in.numberofpoints];
  std::copy_n(&corners[0][0], 48, in.pointlist);
  UnitRandom random;
  for (int i = 16; i < in.numberofpoints; ++i)
  {
    const bool inFin = i % 8 == 0; // an eighth of the points, in a fortieth of the volume
    const double x = random.next(), y = random.next(), z = random.next();
    in.pointlist[3 * i] = inFin ? 0.45 + 0.1 * x : 2 * x;
    in.pointlist[3 * i + 1] = y;
    in.pointlist[3 * i + 2] = inFin ? 0.5 + 0.25 * z : 0.5 * z;
  }
  setPolygonFacets(in,
    { { 0, 1, 2, 3 }, { 0, 1, 7, 6, 5, 4 }, { 5, 6, 13, 12 }, { 3, 2, 11, 10, 9, 8 },
      { 9, 10, 15, 14 }, { 0, 3, 8, 4 }, { 1, 2, 11, 7 }, { 4, 5, 9, 8 }, { 6, 7, 11, 10 },
      { 5, 6, 10, 9 }, { 5, 12, 14, 9 }, { 6, 13, 15, 10 }, { 12, 13, 15, 14 } });
  in.numberofregions = 2;
  in.regionlist = new REAL[10]{ 1, 0.5, 0.25, 1, -1, 0.5, 0.5, 0.6, 2, -1 };
  return meshWithoutQualityBound(in);
}

// The share of tets whose smallest dihedral angle is below `degrees`.
inline double shareBelow(
  const TetList& tets, const std::vector<double>& coordinates, double degrees)
{
  std::size_t below = 0;
  for (const Tet& tet : tets)
  {
    below += minimumDihedralAngle(coordinates.data() + 3 * tet[0], coordinates.data() + 3 * tet[1],
               coordinates.data() + 3 * tet[2], coordinates.data() + 3 * tet[3]) < degrees;
  }
  return static_cast<double>(below) / static_cast<double>(tets.size());
}

} // namespace cgmesh_test

#endif
