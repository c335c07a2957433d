// Tagged triangles found by position (findTriangleChildrenByPosition), as after an input meshed
// anew: a Kuhn cube N=2 of two regions (x below or above 1/2) tags its bottom (z = 0) and the
// interface between the regions (x = 1/2), one bottom triangle twice (a face in two tag sets);
// the output is a Kuhn cube N=6 of the same regions, whose faces lie across the input's. Every
// output face on the bottom or the interface is a child, of a triangle that holds its centroid,
// oriented as it; the duplicated triangle's faces have two parents; no other face is a child;
// the children cover each tagged surface's area; and the result is sorted by parent.
#include "Core/FaceKey.h"
#include "CubeGenerator.h"
#include "Merge/TaggedTriangles.h"
#include "TestHarness.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

using namespace cgmesh;

namespace
{

TetMesh twoRegionCube(int n)
{
  TetMesh mesh;
  CHECK(generateKuhnCube(n, mesh).ok());
  for (const Tet& tet : mesh.tets)
  {
    double x = 0;
    for (PointId p : tet)
    {
      x += 0.25 * mesh.point(p)[0];
    }
    mesh.regions.push_back(x < 0.5 ? 1 : 2);
  }
  return mesh;
}

bool allOn(const TetMesh& mesh, const Face& face, int axis, double value)
{
  return std::all_of(face.begin(), face.end(),
    [&](PointId p) { return std::abs(mesh.point(p)[axis] - value) < 1e-12; });
}

std::array<double, 3> normalOf(const TetMesh& mesh, const Triangle& corners)
{
  const double* a = mesh.point(corners[0]);
  const double* b = mesh.point(corners[1]);
  const double* c = mesh.point(corners[2]);
  const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  return { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0] };
}

double areaOf(const TetMesh& mesh, const Triangle& corners)
{
  const std::array<double, 3> n = normalOf(mesh, corners);
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

// Whether the centroid of `face` (in `output`) lies in `triangle` (in `input`), both in the plane
// `axis` = const: 2D barycentric signs over the other two axes.
bool holdsCentroid(const TetMesh& input, const Triangle& triangle, const TetMesh& output,
  const Triangle& face, int axis)
{
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  double c[2] = { 0, 0 };
  for (PointId p : face)
  {
    c[0] += output.point(p)[i] / 3;
    c[1] += output.point(p)[j] / 3;
  }
  double signs[3];
  for (int k = 0; k < 3; ++k)
  {
    const double* a = input.point(triangle[k]);
    const double* b = input.point(triangle[(k + 1) % 3]);
    signs[k] = (b[i] - a[i]) * (c[1] - a[j]) - (b[j] - a[j]) * (c[0] - a[i]);
  }
  return (signs[0] >= 0 && signs[1] >= 0 && signs[2] >= 0) ||
    (signs[0] <= 0 && signs[1] <= 0 && signs[2] <= 0);
}

void test_children_found_by_position()
{
  const TetMesh input = twoRegionCube(2);
  const TetMesh output = twoRegionCube(6);

  // The input's bottom faces (oriented out of their tet) and interface faces, as tagged.
  std::vector<Triangle> triangles;
  std::vector<int> axisOf; // the plane each triangle lies in: 2 for the bottom, 0 the interface
  forEachDistinctFace(input.tets.front().data(), input.tets.size(),
    [&](const Face& face, std::uint32_t first, std::uint32_t second, std::uint32_t count)
    {
      const bool bottom = count == 1 && allOn(input, face, 2, 0);
      const bool interface =
        count == 2 && input.regions[first] != input.regions[second] && allOn(input, face, 0, 0.5);
      if (bottom || interface)
      {
        triangles.push_back(face);
        axisOf.push_back(bottom ? 2 : 0);
      }
    });
  std::sort(triangles.begin(), triangles.end()); // the visiting order follows a hash table
  axisOf.clear();
  for (const Triangle& triangle : triangles)
  {
    axisOf.push_back(allOn(input, triangle, 2, 0) ? 2 : 0);
  }
  CHECK_EQUAL(triangles.size(), std::size_t(16)); // 8 on the bottom, 8 on the interface
  const std::size_t duplicated =
    static_cast<std::size_t>(std::find(axisOf.begin(), axisOf.end(), 2) - axisOf.begin());
  triangles.push_back(triangles[duplicated]);
  axisOf.push_back(2);

  const std::vector<TriangleChild> children =
    findTriangleChildrenByPosition(input, triangles, output);

  // Which output faces should be children: those on the bottom or the interface.
  std::size_t bottomFaces = 0, interfaceFaces = 0, insideDuplicated = 0;
  forEachDistinctFace(output.tets.front().data(), output.tets.size(),
    [&](const Face& face, std::uint32_t first, std::uint32_t second, std::uint32_t count)
    {
      if (count == 1 && allOn(output, face, 2, 0))
      {
        ++bottomFaces;
        insideDuplicated += holdsCentroid(input, triangles[duplicated], output, face, 2);
      }
      interfaceFaces += count == 2 && output.regions[first] != output.regions[second] &&
        allOn(output, face, 0, 0.5);
    });
  CHECK_EQUAL(bottomFaces, std::size_t(72));
  CHECK_EQUAL(interfaceFaces, std::size_t(72));
  CHECK_EQUAL(insideDuplicated, std::size_t(9)); // a ninth of the input triangle's area each
  CHECK_EQUAL(children.size(), bottomFaces + interfaceFaces + insideDuplicated);

  std::vector<double> areaOfAxis(3, 0);
  for (std::size_t k = 0; k < children.size(); ++k)
  {
    const TriangleChild& child = children[k];
    CHECK(child.parent < triangles.size());
    const int axis = axisOf[child.parent];
    CHECK(allOn(output, child.corners, axis, axis == 2 ? 0 : 0.5));
    CHECK(holdsCentroid(input, triangles[child.parent], output, child.corners, axis));
    const std::array<double, 3> n = normalOf(output, child.corners);
    const std::array<double, 3> m = normalOf(input, triangles[child.parent]);
    CHECK(n[0] * m[0] + n[1] * m[1] + n[2] * m[2] > 0);
    if (child.parent != triangles.size() - 1)
    {
      areaOfAxis[axis] += areaOf(output, child.corners);
    }
    if (k > 0)
    {
      Face previous = children[k - 1].corners, current = child.corners;
      std::sort(previous.begin(), previous.end());
      std::sort(current.begin(), current.end());
      CHECK(children[k - 1].parent < child.parent ||
        (children[k - 1].parent == child.parent && previous < current));
    }
  }
  CHECK(std::abs(areaOfAxis[2] - 1) < 1e-12);
  CHECK(std::abs(areaOfAxis[0] - 1) < 1e-12);

  // Nothing tagged, nothing found; and a mesh elsewhere finds no child.
  CHECK(findTriangleChildrenByPosition(input, {}, output).empty());
  TetMesh shifted = output;
  for (std::size_t k = 0; k < shifted.coordinates.size(); k += 3)
  {
    shifted.coordinates[k + 2] += 2;
  }
  CHECK(findTriangleChildrenByPosition(input, triangles, shifted).empty());
}

} // namespace

int main()
{
  test_children_found_by_position();
  return cgmesh_test::finish("TestTaggedTriangles");
}
