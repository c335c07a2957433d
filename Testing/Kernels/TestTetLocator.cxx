// The locator behind Delaunay point placement and parent cells: on a Kuhn cube whose inner points
// are jittered (no tet axis-aligned, no two alike), every query point is found in a tet whose
// barycentric coordinates are those four volume ratios give, sum to 1 and rebuild the point,
// by the grid search and by walks from any tet, around a concave corner too; a point outside gets
// the tet it is nearest in that sense, with one coordinate negative.
#include "Core/Geometry.h"
#include "Core/TetLocator.h"
#include "CubeGenerator.h"
#include "TestHarness.h"

#include <array>
#include <cstdint>

using namespace cgmesh;

namespace
{

constexpr int Side = 8;

TetMesh jitteredCube()
{
  TetMesh mesh;
  CHECK(generateKuhnCube(Side, mesh).ok());
  std::uint64_t state = 7;
  auto uniform = [&state]()
  {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 9007199254740992.0; // [0, 1)
  };
  const double cell = 1.0 / Side;
  for (PointId p = 0; p < mesh.numberOfPoints(); ++p)
  {
    double* x = mesh.coordinates.data() + 3 * p;
    const bool inner = x[0] > 0 && x[0] < 1 && x[1] > 0 && x[1] < 1 && x[2] > 0 && x[2] < 1;
    for (int axis = 0; inner && axis < 3; ++axis)
    {
      x[axis] += 0.25 * cell * (uniform() - 0.5);
    }
  }
  return mesh;
}

// The four coordinates as ratios of signed volumes, the definition the locator must agree with.
std::array<double, 4> volumeRatios(const TetMesh& mesh, const Tet& tet, const double* point)
{
  const double* c[4] = { mesh.point(tet[0]), mesh.point(tet[1]), mesh.point(tet[2]),
    mesh.point(tet[3]) };
  const double whole = signedVolume6(c[0], c[1], c[2], c[3]);
  std::array<double, 4> ratios;
  for (int k = 0; k < 4; ++k)
  {
    const double* q[4] = { c[0], c[1], c[2], c[3] };
    q[k] = point;
    ratios[k] = signedVolume6(q[0], q[1], q[2], q[3]) / whole;
  }
  return ratios;
}

void checkLocation(
  const TetMesh& mesh, const double* point, const TetLocator::Location& where, bool inside)
{
  CHECK(where.tet < mesh.tets.size());
  const Tet& tet = mesh.tets[where.tet];
  const std::array<double, 4> expected = volumeRatios(mesh, tet, point);
  double sum = 0, lowest = 1;
  double rebuilt[3] = { 0, 0, 0 };
  for (int k = 0; k < 4; ++k)
  {
    CHECK(std::abs(where.barycentric[k] - expected[k]) <= 1e-12);
    sum += where.barycentric[k];
    lowest = std::min(lowest, where.barycentric[k]);
    for (int axis = 0; axis < 3; ++axis)
    {
      rebuilt[axis] += where.barycentric[k] * mesh.point(tet[k])[axis];
    }
  }
  CHECK(std::abs(sum - 1) <= 1e-12);
  for (int axis = 0; axis < 3; ++axis)
  {
    CHECK(std::abs(rebuilt[axis] - point[axis]) <= 1e-12);
  }
  CHECK(inside ? lowest >= -1e-12 : lowest < 0);
}

void test_points_inside_are_found_by_grid_and_walks()
{
  const TetMesh mesh = jitteredCube();
  TetLocator locator(mesh.tets, [&mesh](PointId p) { return mesh.point(p); });
  locator.buildFaceNeighbours(mesh.tets);
  std::uint64_t state = 11;
  auto next = [&state]()
  {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return state >> 11;
  };
  for (int query = 0; query < 2000; ++query)
  {
    // A point well inside a tet, at weights drawn at random: the expected tet is known.
    const std::size_t tet = next() % mesh.tets.size();
    double weights[4], total = 0;
    for (double& w : weights)
    {
      w = 0.05 + static_cast<double>(next() % 1000) / 1000.0;
      total += w;
    }
    double point[3] = { 0, 0, 0 };
    for (int k = 0; k < 4; ++k)
    {
      for (int axis = 0; axis < 3; ++axis)
      {
        point[axis] += weights[k] / total * mesh.point(mesh.tets[tet][k])[axis];
      }
    }
    const TetLocator::Location byGrid = locator.locate(point);
    CHECK_EQUAL(byGrid.tet, tet);
    checkLocation(mesh, point, byGrid, true);
    const TetLocator::Location byWalk = locator.locateFrom(point, next() % mesh.tets.size());
    CHECK_EQUAL(byWalk.tet, tet);
    checkLocation(mesh, point, byWalk, true);
  }
}

// An L-shaped mesh (the cube without the tets of the quarter x, y > 1/2): walks from one arm to
// the other run into the missing quarter's faces and must go around; a point in the missing
// quarter is outside and gets the nearest tet.
void test_walks_go_around_a_concave_corner()
{
  TetMesh cube = jitteredCube();
  TetMesh mesh;
  mesh.coordinates = cube.coordinates;
  auto centroidAt = [&cube](const Tet& tet, int axis)
  {
    double sum = 0;
    for (PointId p : tet)
    {
      sum += 0.25 * cube.point(p)[axis];
    }
    return sum;
  };
  for (const Tet& tet : cube.tets)
  {
    if (!(centroidAt(tet, 0) > 0.5 && centroidAt(tet, 1) > 0.5))
    {
      mesh.tets.push_back(tet);
    }
  }
  TetLocator locator(mesh.tets, [&mesh](PointId p) { return mesh.point(p); });
  locator.buildFaceNeighbours(mesh.tets);
  std::size_t start = 0; // a tet at the far end of the arm x < 1/2, y > 1/2, next to the corner
  while (!(centroidAt(mesh.tets[start], 0) > 0.35 && centroidAt(mesh.tets[start], 0) < 0.5 &&
    centroidAt(mesh.tets[start], 1) > 0.85))
  {
    ++start;
  }
  for (const double z : { 0.1, 0.5, 0.9 })
  {
    // At the far end of the other arm (x > 1/2, y < 1/2): the straight way crosses the quarter.
    const double point[3] = { 0.95, 0.4, z };
    checkLocation(mesh, point, locator.locateFrom(point, start), true);
  }
  const double missing[3] = { 0.8, 0.8, 0.5 };
  checkLocation(mesh, missing, locator.locateFrom(missing, start), false);
}

// A walk across a fine cube from corner to corner takes more steps than a walk may: the search
// goes on breadth first from where the walk stopped.
void test_long_walks_go_on_breadth_first()
{
  TetMesh mesh;
  CHECK(generateKuhnCube(24, mesh).ok());
  TetLocator locator(mesh.tets, [&mesh](PointId p) { return mesh.point(p); });
  locator.buildFaceNeighbours(mesh.tets);
  const double point[3] = { 0.97, 0.03, 0.98 };
  checkLocation(mesh, point, locator.locateFrom(point, 0), true);
}

void test_point_outside_gets_the_nearest_tet()
{
  const TetMesh mesh = jitteredCube();
  TetLocator locator(mesh.tets, [&mesh](PointId p) { return mesh.point(p); });
  locator.buildFaceNeighbours(mesh.tets);
  const double outside[3] = { 0.5, 0.5, 1.0 + 1e-3 };
  checkLocation(mesh, outside, locator.locate(outside), false);
  checkLocation(mesh, outside, locator.locateFrom(outside, 0), false);
}

} // namespace

int main()
{
  test_points_inside_are_found_by_grid_and_walks();
  test_walks_go_around_a_concave_corner();
  test_long_walks_go_on_breadth_first();
  test_point_outside_gets_the_nearest_tet();
  return cgmesh_test::finish("TestTetLocator");
}
