// Template refinement of sliver-laden inputs: with ImproveInput such an input is meshed anew by
// TetGen before templates cut it (conforming, conserving, the same for any thread count, far
// better shapes, with and without a size field), never where the boundary triangulation or the
// tets outside a selection must stay (then a warning says so); and the mean-ratio screen that
// counts slivers agrees with the angle itself.
#include "AdaptationDriver.h"
#include "Core/TetQuality.h"
#include "CubeGenerator.h"
#include "DelaunayTestSupport.h"
#include "MeshChecks.h"
#include "Refinement/TetGenRefiner.h"
#include "ResultComparison.h"
#include "SliverLadenMeshes.h"
#include "TestHarness.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <string>
#include <vector>

using namespace cgmesh;
using cgmesh_test::run;
using cgmesh_test::shareBelow;
using cgmesh_test::sliverLadenBlock;

namespace
{

bool warns(const AdaptationResult& result, WarningKind kind)
{
  return std::any_of(result.summary.warnings.begin(), result.summary.warnings.end(),
    [kind](const AdaptationWarning& warning) { return warning.kind == kind; });
}

bool warnsOfUnusedPoints(const AdaptationResult& result)
{
  return warns(result, WarningKind::UnusedPointsRemoved);
}

// A run that refines a sliver-laden input as given says so, and why.
void checkWarnsOfSliversKept(const AdaptationResult& result, const std::string& reason)
{
  CHECK(warns(result, WarningKind::SliverLadenInputKept));
  for (const AdaptationWarning& warning : result.summary.warnings)
  {
    if (warning.kind == WarningKind::SliverLadenInputKept)
    {
      CHECK(warning.text.find(reason) != std::string::npos);
    }
  }
}

AdaptationOptions templateOptions()
{
  AdaptationOptions options;
  options.numberOfPartitions = 8;
  options.edgeLengthFactor = 0.5;
  options.numberOfThreads = 1;
  return options;
}

} // namespace

// The screen passes over no tet under the angle: the sliver-laden block's tets, and tets flattened
// towards a plane, a line and a point by factors down to 1e-9, for several angles.
void test_mean_ratio_screen_agrees_with_the_angle()
{
  std::vector<std::array<double, 12>> tets;
  const TetMesh block = sliverLadenBlock(1500);
  for (const Tet& tet : block.tets)
  {
    std::array<double, 12> corners;
    for (int k = 0; k < 4; ++k)
    {
      std::copy_n(block.point(tet[k]), 3, corners.begin() + 3 * k);
    }
    tets.push_back(corners);
  }
  cgmesh_test::UnitRandom random;
  for (int i = 0; i < 20000; ++i)
  {
    const double flattening = std::pow(10.0, -9.0 * random.next());
    const int flattenedAxes = 1 + i % 3; // towards a plane, a line, a point
    std::array<double, 12> corners;
    for (int k = 0; k < 12; ++k)
    {
      corners[k] = random.next() * (k % 3 < flattenedAxes ? flattening : 1.0);
    }
    tets.push_back(corners);
  }
  for (const double degrees : { 0.1, RemeshSliverDegrees, 3.0 })
  {
    const double ceiling = meanRatioCeiling(degrees);
    std::int64_t below = 0;
    for (const auto& c : tets)
    {
      const bool exact = minimumDihedralAngle(&c[0], &c[3], &c[6], &c[9]) < degrees;
      CHECK_EQUAL(minimumDihedralAngleBelow(&c[0], &c[3], &c[6], &c[9], degrees, ceiling), exact);
      below += exact ? 1 : 0;
    }
    std::cout << below << " of " << tets.size() << " tets under " << degrees
              << " degrees, mean ratio ceiling " << ceiling << "\n";
    CHECK(below > 1000 && below < static_cast<std::int64_t>(tets.size()) - 1000);
  }
  // The regular tet clears the ceiling of every angle under its own, 70.53 degrees, that the
  // ceiling can tell (the ceiling reaches 1 near 2.5 degrees).
  const double regular[12] = { 1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1 };
  CHECK(meanRatio(regular, regular + 3, regular + 9, regular + 6) > 0.999999);
  CHECK(!meanRatioBelow(regular, regular + 3, regular + 9, regular + 6, meanRatioCeiling(2.0)));
}

// With ImproveInput, a sliver-laden input is meshed anew as a whole by one TetGen call (its
// boundary and material-interface faces free to split) and improved, then refined: conforming,
// conserving every region, the same for any thread count, no point left over, and far better
// shapes than templates cutting the slivers.
void test_sliver_laden_input_is_meshed_anew_before_templates()
{
  const TetMesh input = sliverLadenBlock(1500);
  AdaptationOptions options = templateOptions();
  options.improveInput = false;
  const AdaptationResult asGiven = run(input, options);
  CHECK_EQUAL(asGiven.summary.inputRemeshedBoxes, std::int64_t(0));
  checkWarnsOfSliversKept(asGiven, "ImproveInput is off");
  options.improveInput = true;
  const AdaptationResult serial = run(input, options);
  cgmesh_test::checkValidAndConserving(input, serial.mesh);
  CHECK_EQUAL(serial.summary.inputRemeshedBoxes, std::int64_t(1));
  CHECK(!warns(serial, WarningKind::SliverLadenInputKept));
  CHECK_EQUAL(serial.summary.inputDroppedPoints, std::int64_t(0));
  CHECK_EQUAL(serial.summary.inputRemeshFailures, std::int64_t(0));
  CHECK(!warnsOfUnusedPoints(serial));
  const double p1AsGiven = cgmesh_test::minimumDihedralPercentile(asGiven.mesh, 0.01);
  const double p1 = cgmesh_test::minimumDihedralPercentile(serial.mesh, 0.01);
  const double underAsGiven = shareBelow(asGiven.mesh.tets, asGiven.mesh.coordinates, 1.0);
  const double under = shareBelow(serial.mesh.tets, serial.mesh.coordinates, 1.0);
  std::cout << "sliver-laden block, templates: " << asGiven.mesh.numberOfTets()
            << " tets refined as given (minimum dihedral p1 " << p1AsGiven
            << " degrees, share under"
            << " 1 degree " << underAsGiven << "), " << serial.mesh.numberOfTets()
            << " meshed anew first (" << p1 << ", " << under << ")\n";
  CHECK(p1 > 10.0 && p1AsGiven < 2.0);
  CHECK(under == 0.0 && underAsGiven > RemeshSliverShare);
  options.numberOfThreads = 2;
  CHECK(cgmesh_test::identicalResults(serial, run(input, options)));

  // Without ImproveQuality nothing is changed before refining.
  options.improveQuality = false;
  const AdaptationResult unimproved = run(input, options);
  CHECK_EQUAL(unimproved.summary.inputRemeshedBoxes, std::int64_t(0));
  checkWarnsOfSliversKept(unimproved, "ImproveQuality is off");

  // An input with few slivers is neither meshed anew nor warned about.
  TetMesh cube;
  CHECK(generateKuhnCube(6, cube).ok());
  const AdaptationResult good = run(cube, templateOptions());
  CHECK_EQUAL(good.summary.inputRemeshedBoxes, std::int64_t(0));
  CHECK(good.summary.warnings.empty());
}

// The same with a size field (finer in the inner cube): the sizes follow TetGen's points, and the
// passes end with fewer tets, more edges within the field's bounds and good shapes (TetGen's
// points on the boundary, where its shapes need them, stay: coarsening moves no boundary vertex).
void test_sliver_laden_input_with_a_size_field()
{
  TetMesh input = sliverLadenBlock(1500);
  for (PointId p = 0; p < input.numberOfPoints(); ++p)
  {
    const double* x = input.point(p);
    const bool inner =
      std::abs(x[0] - 0.5) < 0.2 && std::abs(x[1] - 0.5) < 0.2 && std::abs(x[2] - 0.5) < 0.2;
    input.sizes.push_back(inner ? 0.04 : 0.08);
  }
  AdaptationOptions options = templateOptions();
  options.numberOfIterations = 10;
  options.improveInput = false;
  const AdaptationResult asGiven = run(input, options);
  options.improveInput = true;
  const AdaptationResult serial = run(input, options);
  cgmesh_test::checkValidAndConserving(input, serial.mesh);
  CHECK_EQUAL(serial.summary.inputRemeshedBoxes, std::int64_t(1));
  CHECK(serial.summary.refinementConverged);
  CHECK(!warnsOfUnusedPoints(serial));
  const double within = serial.summary.edgeSizes.shareWithinBounds;
  const double p1 = cgmesh_test::minimumDihedralPercentile(serial.mesh, 0.01);
  std::cout << "sliver-laden block with a size field: " << asGiven.mesh.numberOfTets()
            << " tets refined as given (" << asGiven.summary.edgeSizes.shareWithinBounds
            << " of the edges within bounds, minimum dihedral p1 "
            << cgmesh_test::minimumDihedralPercentile(asGiven.mesh, 0.01) << " degrees), "
            << serial.mesh.numberOfTets() << " meshed anew first (" << within << ", " << p1
            << ")\n";
  CHECK(serial.mesh.numberOfTets() < asGiven.mesh.numberOfTets());
  CHECK(within > asGiven.summary.edgeSizes.shareWithinBounds + 0.1);
  CHECK(p1 > 10.0);
  options.numberOfThreads = 2;
  CHECK(cgmesh_test::identicalResults(serial, run(input, options)));
}

// Not where the tets must stay as given: outside a RefinementRegions selection, or with the
// boundary triangulation kept (pieces across processes). Those runs match the
// runs that never improve the input first, and warn that the slivers were refined as given.
void test_sliver_laden_input_kept_where_it_must_stay()
{
  const TetMesh input = sliverLadenBlock(1500);
  AdaptationOptions options = templateOptions();
  options.refinementRegions = "2";
  const AdaptationResult selected = run(input, options);
  CHECK_EQUAL(selected.summary.inputRemeshedBoxes, std::int64_t(0));
  checkWarnsOfSliversKept(selected, "RefinementRegions or RefinementBox");
  options.improveInput = false;
  CHECK(cgmesh_test::identicalResults(selected, run(input, options)));

  options = templateOptions();
  options.keepBoundaryTriangulation = true;
  const AdaptationResult kept = run(input, options);
  CHECK_EQUAL(kept.summary.inputRemeshedBoxes, std::int64_t(0));
  checkWarnsOfSliversKept(kept, "pieces of a mesh across processes");
  cgmesh_test::checkValidAndConserving(input, kept.mesh);
}

int main()
{
  test_mean_ratio_screen_agrees_with_the_angle();
  test_sliver_laden_input_is_meshed_anew_before_templates();
  test_sliver_laden_input_with_a_size_field();
  test_sliver_laden_input_kept_where_it_must_stay();
  return cgmesh_test::finish("TestTemplateSlivers");
}
