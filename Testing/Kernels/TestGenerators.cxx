// The benchmark meshes: cube sizes, and the FinFET's materials in both generators.
#include "CubeGenerator.h"
#include "FinFetGenerator.h"
#include "TestHarness.h"
#include "Validation/MeshValidation.h"

#include <cmath>

using namespace cgmesh;

namespace
{

void test_cubes()
{
  for (int n : { 10, 25 })
  {
    TetMesh mesh;
    CHECK(generateKuhnCube(n, mesh).ok());
    CHECK_EQUAL(mesh.numberOfTets(), 6 * n * n * n);
    const MeshReport report = inspectMesh(mesh);
    CHECK(report.isValid());
    CHECK_CLOSE(report.volume, 1.0, 1e-9);
  }
  TetMesh mesh;
  CHECK(!generateKuhnCube(0, mesh).ok());
}

void test_finfet_generators_agree_on_materials()
{
  TetMesh structured, delaunay;
  CHECK(generateFinFet(30000, structured).ok());
  CHECK(generateFinFetWithTetGen(30000, delaunay).ok());
  CHECK(std::abs(delaunay.numberOfTets() - 30000) <= 3000); // coarse: boundary facets dominate
  const MeshReport a = inspectMesh(structured);
  const MeshReport b = inspectMesh(delaunay);
  CHECK(a.isValid());
  CHECK(b.isValid());
  CHECK_EQUAL(b.regionVolumes.size(), finFetMaterialNames().size());
  CHECK_EQUAL(a.regionVolumes.size(), b.regionVolumes.size());
  for (const auto& region : a.regionVolumes)
  {
    CHECK_CLOSE(b.regionVolumes.at(region.first), region.second, 1e-9);
  }
  CHECK_CLOSE(b.regionInterfaceArea, a.regionInterfaceArea, 1e-9);
  CHECK_CLOSE(b.boundaryArea, a.boundaryArea, 1e-9);
}

} // namespace

int main()
{
  test_cubes();
  test_finfet_generators_agree_on_materials();
  return cgmesh_test::finish("TestGenerators");
}
