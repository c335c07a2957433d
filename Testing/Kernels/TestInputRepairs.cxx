// Awkward and bad inputs through adaptMesh(): each gives a valid conforming mesh or a clear error,
// and the input is never modified.
#include "AdaptationDriver.h"
#include "CubeGenerator.h"
#include "TestHarness.h"
#include "Validation/MeshValidation.h"

#include <cmath>
#include <limits>

using namespace cgmesh;

namespace
{

TetMesh cube(int n, double scale = 1.0)
{
  TetMesh mesh;
  CHECK(generateKuhnCube(n, mesh).ok());
  for (double& c : mesh.coordinates)
  {
    c *= scale;
  }
  return mesh;
}

AdaptationOptions templateOptions(int partitions)
{
  AdaptationOptions options;
  options.numberOfPartitions = partitions;
  options.numberOfIterations = 1;
  options.edgeLengthFactor = 0.5;
  options.numberOfThreads = 2;
  return options;
}

// Runs, checks the input is untouched, and for a success checks validity and conservation.
Status refineAndCheck(
  const TetMesh& input, const AdaptationOptions& options, AdaptationResult& result)
{
  const TetMesh copy = input;
  const Status status = adaptMesh(input, options, result);
  CHECK(copy.coordinates.size() == input.coordinates.size() && copy.tets == input.tets &&
    copy.regions == input.regions);
  CHECK(std::equal(copy.coordinates.begin(), copy.coordinates.end(), input.coordinates.begin(),
    [](double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }));
  if (!status.ok())
  {
    CHECK(result.mesh.tets.empty());
    CHECK(!status.message().empty() && status.message().find('\n') == std::string::npos);
    return status;
  }
  const MeshReport after = inspectMesh(result.mesh);
  if (!after.isValid())
  {
    std::cerr << after.describeProblems();
  }
  CHECK(after.isValid());
  return status;
}

void test_non_finite_coordinates_are_refused()
{
  for (double bad :
    { std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity() })
  {
    TetMesh mesh = cube(2);
    mesh.coordinates[3 * 5 + 1] = bad;
    AdaptationResult result;
    const Status status = refineAndCheck(mesh, templateOptions(4), result);
    CHECK(!status.ok());
    CHECK(status.message().find("NaN or infinite") != std::string::npos);
  }
}

void test_zero_volume_tets_are_refused()
{
  TetMesh mesh = cube(2);
  mesh.tets[3][3] = mesh.tets[3][2]; // repeats a point
  AdaptationResult result;
  Status status = refineAndCheck(mesh, templateOptions(4), result);
  CHECK(!status.ok() && status.message().find("zero volume") != std::string::npos);
  mesh = cube(2);
  mesh.coordinates.insert(mesh.coordinates.end(), { 0.25, 0.25, 0.0 }); // flat tet on the floor
  mesh.tets.push_back({ 0, 1, 3, mesh.numberOfPoints() - 1 });
  status = refineAndCheck(mesh, templateOptions(4), result);
  CHECK(!status.ok());
}

void test_inverted_tets_are_reoriented()
{
  const TetMesh reference = cube(3);
  const double volume = inspectMesh(reference).volume;
  for (int every : { 1, 2 }) // all inverted (Netgen), every other one (DOLFIN)
  {
    TetMesh mesh = reference;
    for (std::size_t t = 0; t < mesh.tets.size(); t += every)
    {
      std::swap(mesh.tets[t][0], mesh.tets[t][1]);
    }
    AdaptationResult result;
    CHECK(refineAndCheck(mesh, templateOptions(8), result).ok());
    CHECK_EQUAL(result.summary.reorientedTets,
      static_cast<std::int64_t>((mesh.tets.size() + every - 1) / every));
    const MeshReport report = inspectMesh(result.mesh);
    CHECK_EQUAL(report.invertedTets, 0);
    CHECK_CLOSE(report.volume, volume, 1e-12);
  }
}

// Two cubes side by side whose touching faces have their own copies of the points.
void test_touching_parts_without_shared_points_are_joined()
{
  TetMesh mesh = cube(2);
  const TetMesh second = cube(2);
  const PointId offset = mesh.numberOfPoints();
  for (PointId p = 0; p < second.numberOfPoints(); ++p)
  {
    mesh.coordinates.insert(
      mesh.coordinates.end(), { second.point(p)[0] + 1.0, second.point(p)[1], second.point(p)[2] });
  }
  for (Tet tet : second.tets)
  {
    for (PointId& p : tet)
    {
      p += offset;
    }
    mesh.tets.push_back(tet);
  }
  AdaptationResult result;
  CHECK(refineAndCheck(mesh, templateOptions(4), result).ok());
  CHECK_EQUAL(result.summary.mergedPoints, 9);
  const MeshReport report = inspectMesh(result.mesh);
  CHECK_EQUAL(report.duplicatePoints, 0);
  CHECK_CLOSE(report.boundaryArea, 10.0, 1e-12); // the joined 2 x 1 x 1 box
}

void test_scale_invariance()
{
  for (double scale : { 1e-6, 1e6, 1e-4 })
  {
    const TetMesh mesh = cube(3, scale);
    AdaptationResult result;
    CHECK(refineAndCheck(mesh, templateOptions(8), result).ok());
    CHECK(result.mesh.numberOfTets() > mesh.numberOfTets());
    CHECK_CLOSE(inspectMesh(result.mesh).volume / (scale * scale * scale), 1.0, 1e-9);
  }
}

void test_tiny_meshes_and_partition_counts()
{
  TetMesh one;
  one.coordinates = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  one.tets = { { 0, 1, 2, 3 } };
  one.regions = { -7 };
  AdaptationResult result;
  CHECK(refineAndCheck(one, templateOptions(1024), result).ok());
  CHECK_EQUAL(result.summary.plan.partitions, 1);
  CHECK(result.mesh.numberOfTets() > 1);
  CHECK(result.mesh.regions == std::vector<int>(result.mesh.tets.size(), -7));

  TetMesh empty;
  CHECK(refineAndCheck(empty, templateOptions(4), result).ok());
  CHECK(result.mesh.tets.empty());

  CHECK(refineAndCheck(cube(2), templateOptions(1), result).ok());
  CHECK_EQUAL(result.summary.numberOfColors, 1);
  CHECK(refineAndCheck(cube(2), templateOptions(48), result).ok());
  CHECK_EQUAL(result.summary.plan.partitions, 48);
}

void test_size_guard_refuses_before_refining()
{
  AdaptationOptions options = templateOptions(8);
  options.numberOfIterations = 3;
  options.edgeLengthFactor = 0.1;
  options.maximumNumberOfCells = 50000;
  AdaptationResult result;
  const Status status = refineAndCheck(cube(4), options, result);
  CHECK(!status.ok());
  CHECK(status.message().find("MaximumNumberOfCells") != std::string::npos);
  options.maximumNumberOfCells = 0; // no limit
  options.numberOfIterations = 1;
  CHECK(refineAndCheck(cube(4), options, result).ok());
}

} // namespace

int main()
{
  test_non_finite_coordinates_are_refused();
  test_zero_volume_tets_are_refused();
  test_inverted_tets_are_reoriented();
  test_touching_parts_without_shared_points_are_joined();
  test_scale_invariance();
  test_tiny_meshes_and_partition_counts();
  test_size_guard_refuses_before_refining();
  return cgmesh_test::finish("TestInputRepairs");
}
