// Size fields: gradation limiting, refinement to a graded field through adaptMesh() (converged,
// every edge at most sqrt(2) h at its midpoint, conforming, volumes and regions conserved, the
// same output for any thread count), the same with the Delaunay method, coarsening where the field
// is coarser than the mesh, and the refusal of bad fields.
#include "AdaptationDriver.h"
#include "Core/ConstrainedFaces.h"
#include "Core/Geometry.h"
#include "Core/TetQuality.h"
#include "CubeGenerator.h"
#include "FinFetGenerator.h"
#include "MeshChecks.h"
#include "Refinement/SizeField.h"
#include "ResultComparison.h"
#include "ScheduleForTests.h"
#include "TestHarness.h"
#include "Validation/MeshValidation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <random>
#include <set>
#include <utility>

using namespace cgmesh;

namespace
{

// A band of fine sizes along x = 0.5, coarse towards x = 0 and 1, and two regions.
TetMesh gradedCube(int n)
{
  TetMesh mesh;
  CHECK(generateKuhnCube(n, mesh).ok());
  for (PointId p = 0; p < mesh.numberOfPoints(); ++p)
  {
    mesh.sizes.push_back(0.04 + 0.3 * std::abs(mesh.point(p)[0] - 0.5));
  }
  for (const Tet& tet : mesh.tets)
  {
    mesh.regions.push_back(mesh.point(tet[0])[2] + mesh.point(tet[3])[2] < 1.0 ? 1 : 2);
  }
  return mesh;
}

void test_gradation_limits_neighbouring_sizes()
{
  TetMesh mesh;
  CHECK(generateKuhnCube(6, mesh).ok());
  mesh.sizes.assign(mesh.numberOfPoints(), 1.0);
  mesh.sizes[100] = 0.01;
  const std::vector<double> given = mesh.sizes;
  limitSizeGradation(mesh, 1.3, mesh.sizes);
  CHECK_EQUAL(mesh.sizes[100], 0.01);
  for (PointId p = 0; p < mesh.numberOfPoints(); ++p)
  {
    CHECK(mesh.sizes[p] <= given[p]);
  }
  bool lowered = false;
  for (const Tet& tet : mesh.tets)
  {
    for (const auto& corners : TetEdgeCorners)
    {
      const double a = mesh.sizes[tet[corners[0]]], b = mesh.sizes[tet[corners[1]]];
      CHECK(std::max(a, b) <= 1.3 * std::min(a, b) * (1 + 1e-12));
      lowered = lowered || (a < 1.0 && a > 0.01);
    }
  }
  CHECK(lowered);
}

void test_refinement_to_a_graded_field()
{
  const TetMesh input = gradedCube(5);
  AdaptationOptions options;
  options.numberOfIterations = 12;
  options.numberOfPartitions = 16;
  options.numberOfThreads = 1;
  AdaptationResult serial;
  CHECK(adaptMesh(input, options, serial).ok());
  CHECK(serial.summary.plan.sizeField);
  CHECK(serial.summary.refinementConverged);
  CHECK(serial.summary.iterationsRun < 12);
  CHECK(serial.mesh.numberOfTets() > 10 * input.numberOfTets());

  cgmesh_test::checkValidAndConserving(input, serial.mesh);

  // Converged: no edge is longer than sqrt(2) h at its midpoint, h being the graded field
  // interpolated along the splits.
  CHECK_EQUAL(serial.mesh.sizes.size(), static_cast<std::size_t>(serial.mesh.numberOfPoints()));
  double smallest = std::numeric_limits<double>::infinity();
  for (const Tet& tet : serial.mesh.tets)
  {
    for (const auto& corners : TetEdgeCorners)
    {
      const PointId a = tet[corners[0]], b = tet[corners[1]];
      CHECK(!longerThanSize(
        squaredEdgeLength(serial.mesh, a, b), serial.mesh.sizes[a], serial.mesh.sizes[b]));
    }
    for (PointId p : tet)
    {
      smallest = std::min(smallest, serial.mesh.sizes[p]);
    }
  }
  // Midpoints average their ends and gradation only lowers sizes towards the smallest one, so
  // the finest size is the input's.
  CHECK_CLOSE(smallest, *std::min_element(input.sizes.begin(), input.sizes.end()), 1e-12);
  CHECK_EQUAL(serial.edgeLengthRatio.size(), static_cast<std::size_t>(serial.mesh.numberOfTets()));
  CHECK(*std::max_element(serial.edgeLengthRatio.begin(), serial.edgeLengthRatio.end()) < 1.6);
  CHECK(serial.summary.edgeSizes.edges > 0);
  CHECK(serial.summary.edgeSizes.shareWithinBounds > 0.8);
  CHECK_EQUAL(serial.summary.edgeSizes.histogram[4] + serial.summary.edgeSizes.histogram[5], 0);

  for (int threads : { 2, 3 })
  {
    options.numberOfThreads = threads;
    AdaptationResult parallel;
    CHECK(adaptMesh(input, options, parallel).ok());
    CHECK(cgmesh_test::identicalResults(serial, parallel));
    CHECK(parallel.mesh.sizes == serial.mesh.sizes);
  }
}

// Template passes skip the partitions an earlier pass found nothing to split in while nothing
// has changed them: with a steep size field and coarsening (five passes) and in a refinement box
// (four passes; the partitions far from it never split), the output is the one that reading them
// again gives, and some reads were skipped.
void test_settled_partitions_are_not_read_again()
{
  // Fine along x = 0.5 and, gradation allowing, coarse enough towards x = 0 and 1 for the
  // partitions there to settle after a pass or two.
  TetMesh steep = gradedCube(6);
  for (PointId p = 0; p < steep.numberOfPoints(); ++p)
  {
    steep.sizes[p] = 0.03 + 0.6 * std::abs(steep.point(p)[0] - 0.5);
  }
  TetMesh boxed = gradedCube(6);
  boxed.sizes.clear();
  for (const TetMesh& input : { steep, boxed })
  {
    AdaptationOptions options;
    options.numberOfIterations = 12;
    options.numberOfPartitions = 256;
    options.numberOfThreads = 2;
    options.sizeGradation = 4;
    if (input.sizes.empty())
    {
      options.refinementBox = "0,0,0,0.3,1,1";
      options.edgeLengthFactor = 0.3;
      options.numberOfIterations = 4;
    }
    AdaptationResult skipping, reading;
    CHECK(adaptMesh(input, options, skipping).ok());
    options.skipSettledPartitions = false;
    CHECK(adaptMesh(input, options, reading).ok());
    CHECK(skipping.summary.iterationsRun > 2);
    CHECK(skipping.summary.skippedPartitionReads > 0);
    CHECK_EQUAL(reading.summary.skippedPartitionReads, 0);
    CHECK(cgmesh_test::identicalResults(skipping, reading));
    CHECK(skipping.mesh.sizes == reading.mesh.sizes);
    cgmesh_test::checkValidAndConserving(input, skipping.mesh);
  }
}

// measureEdgeSizes() against a set of all edges of `mesh`, run in order and with its tasks taken
// last to first.
void checkEdgeMeasure(const TetMesh& mesh)
{
  std::set<std::pair<PointId, PointId>> edges;
  for (const Tet& tet : mesh.tets)
  {
    for (const auto& corners : TetEdgeCorners)
    {
      edges.insert(std::minmax(tet[corners[0]], tet[corners[1]]));
    }
  }
  EdgeSizeReport expected;
  std::int64_t within = 0;
  for (const auto& [a, b] : edges)
  {
    if (!std::isfinite(mesh.sizes[a]) || !std::isfinite(mesh.sizes[b]))
    {
      continue;
    }
    const double ratio =
      std::sqrt(squaredEdgeLength(mesh, a, b)) / (0.5 * (mesh.sizes[a] + mesh.sizes[b]));
    const double bounds[5] = { 0.5, std::sqrt(0.5), 1.0, std::sqrt(2.0), 2.0 };
    ++expected.histogram[std::upper_bound(bounds, bounds + 5, ratio) - bounds];
    ++expected.edges;
    within += ratio >= bounds[1] * (1 - 1e-12) && ratio <= bounds[3] * (1 + 1e-12);
  }
  CHECK(expected.edges > 10000 && expected.edges < static_cast<std::int64_t>(edges.size()));

  for (const ParallelFor& parallelFor : { ParallelFor(runSerially), ParallelFor(runBackwards) })
  {
    EdgeSizeReport measured;
    CHECK(measureEdgeSizes(mesh, parallelFor, measured).ok());
    CHECK_EQUAL(measured.edges, expected.edges);
    CHECK(measured.histogram == expected.histogram);
    CHECK_EQUAL(measured.shareWithinBounds,
      static_cast<double>(within) / static_cast<double>(expected.edges));
  }
}

// The edge measure counts every edge of the mesh once, whatever the schedule of its tasks, with
// some points outside the field (infinite size), whose edges do not count: on the graded cube
// refined and coarsened (irregular valences), and on a Kuhn cube of 105,456 tets with its points
// numbered at random, so that the edges' lower ends are listed by several blocks of tets into
// several ranges of points each.
void test_edge_measure_counts_every_edge_once()
{
  const TetMesh input = gradedCube(5);
  AdaptationOptions options;
  options.numberOfIterations = 12;
  options.numberOfPartitions = 16;
  AdaptationResult refined;
  CHECK(adaptMesh(input, options, refined).ok());
  TetMesh mesh = refined.mesh;
  for (PointId p = 0; p < mesh.numberOfPoints(); p += 7)
  {
    mesh.sizes[p] = std::numeric_limits<double>::infinity();
  }
  checkEdgeMeasure(mesh);

  TetMesh cube = gradedCube(26);
  CHECK(cube.tets.size() > 65536 && cube.numberOfPoints() > 2 * 8192);
  std::vector<PointId> newIdOf(static_cast<std::size_t>(cube.numberOfPoints()));
  std::iota(newIdOf.begin(), newIdOf.end(), PointId{ 0 });
  std::shuffle(newIdOf.begin(), newIdOf.end(), std::mt19937(12345));
  TetMesh shuffled = cube;
  for (std::size_t p = 0; p < newIdOf.size(); ++p)
  {
    std::copy_n(cube.point(static_cast<PointId>(p)), 3, &shuffled.coordinates[3 * newIdOf[p]]);
    shuffled.sizes[newIdOf[p]] =
      p % 11 == 0 ? std::numeric_limits<double>::infinity() : 0.3 * cube.sizes[p];
  }
  for (Tet& tet : shuffled.tets)
  {
    for (PointId& corner : tet)
    {
      corner = newIdOf[corner];
    }
  }
  checkEdgeMeasure(shuffled);
}

// The Delaunay method with a size field: TetGen gets the sizes per point (switch m) and refines
// each partition in one pass; the mesh is valid and conserving, the new points carry
// interpolated sizes, most edges lie within [h / sqrt(2), sqrt(2) h] with none far beyond, the
// finest part of the field gets the smallest tets, and the output does not depend on the thread
// count.
void test_delaunay_refinement_to_a_graded_field()
{
  const TetMesh input = gradedCube(5);
  AdaptationOptions options;
  options.method = RefinementMethod::Delaunay;
  options.numberOfIterations = 10; // Delaunay to sizes makes one pass whatever is asked
  options.numberOfPartitions = 8;
  options.numberOfThreads = 1;
  AdaptationResult serial;
  CHECK(adaptMesh(input, options, serial).ok());
  CHECK(serial.summary.plan.sizeField);
  CHECK_EQUAL(serial.summary.plan.volumeBound, 0.0);
  CHECK_EQUAL(serial.summary.iterationsRun, 1);
  CHECK_EQUAL(serial.summary.delaunayFallbacks, 0);
  CHECK(serial.summary.tetgenPoints > 0);
  CHECK(serial.mesh.numberOfTets() > 10 * input.numberOfTets());
  cgmesh_test::checkValidAndConserving(input, serial.mesh);

  CHECK_EQUAL(serial.mesh.sizes.size(), static_cast<std::size_t>(serial.mesh.numberOfPoints()));
  const double finest = *std::min_element(input.sizes.begin(), input.sizes.end());
  const double coarsest = *std::max_element(input.sizes.begin(), input.sizes.end());
  for (double size : serial.mesh.sizes)
  {
    CHECK(size >= finest * (1 - 1e-12) && size <= coarsest * (1 + 1e-12));
  }
  CHECK(serial.summary.edgeSizes.shareWithinBounds > 0.85);
  const auto& histogram = serial.summary.edgeSizes.histogram;
  CHECK(histogram[5] < serial.summary.edgeSizes.edges / 1000); // at most 0.1% beyond 2 h
  // Tets near the fine band (x = 0.5) are smaller than those near the coarse faces x = 0, 1.
  double nearBand = 0, nearFaces = 0;
  int bandTets = 0, faceTets = 0;
  for (const Tet& tet : serial.mesh.tets)
  {
    const double x = 0.25 *
      (serial.mesh.point(tet[0])[0] + serial.mesh.point(tet[1])[0] + serial.mesh.point(tet[2])[0] +
        serial.mesh.point(tet[3])[0]);
    const double volume = signedVolume6(serial.mesh.point(tet[0]), serial.mesh.point(tet[1]),
                            serial.mesh.point(tet[2]), serial.mesh.point(tet[3])) /
      6.0;
    if (std::abs(x - 0.5) < 0.1)
    {
      nearBand += volume;
      ++bandTets;
    }
    else if (std::abs(x - 0.5) > 0.4)
    {
      nearFaces += volume;
      ++faceTets;
    }
  }
  CHECK(bandTets > 0 && faceTets > 0);
  CHECK(nearBand / bandTets < 0.25 * (nearFaces / faceTets));

  options.numberOfThreads = 2;
  AdaptationResult parallel;
  CHECK(adaptMesh(input, options, parallel).ok());
  CHECK(cgmesh_test::identicalResults(serial, parallel));
  CHECK(parallel.mesh.sizes == serial.mesh.sizes);
}

// The coordinates of the points on boundary and region-interface faces, sorted.
std::vector<std::array<double, 3>> constrainedPoints(const TetMesh& mesh)
{
  PartitionMesh whole;
  whole.tets = mesh.tets;
  whole.regions = mesh.regions;
  whole.parentCells.assign(mesh.tets.size(), 0);
  std::vector<Face> boundaryFaces, interfaceFaces;
  findConstrainedFaces(whole, boundaryFaces, interfaceFaces);
  std::vector<std::array<double, 3>> points;
  for (const auto* faces : { &boundaryFaces, &interfaceFaces })
  {
    for (const Face& face : *faces)
    {
      for (PointId p : face)
      {
        points.push_back({ mesh.point(p)[0], mesh.point(p)[1], mesh.point(p)[2] });
      }
    }
  }
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  return points;
}

double worstMeanRatio(const TetMesh& mesh)
{
  double worst = 1;
  for (const Tet& tet : mesh.tets)
  {
    worst = std::min(worst,
      meanRatio(mesh.point(tet[0]), mesh.point(tet[1]), mesh.point(tet[2]), mesh.point(tet[3])));
  }
  return worst;
}

// A field finer than the mesh on the left half (x < 0.5) and coarser on the right: refinement on
// the left, collapses on the right. Against the same run without coarsening: edges collapsed,
// fewer points, more edges within [h / sqrt(2), sqrt(2) h]; still valid and conserving; every
// boundary and interface point where it was (none removed, none added by coarsening); no tet
// worse than min(0.3, the uncoarsened run's worst); the same output for any thread count.
void test_coarsening_where_the_field_is_coarse()
{
  TetMesh input;
  CHECK(generateKuhnCube(12, input).ok());
  for (PointId p = 0; p < input.numberOfPoints(); ++p)
  {
    input.sizes.push_back(input.point(p)[0] < 0.5 ? 0.06 : 0.3);
  }
  for (const Tet& tet : input.tets)
  {
    input.regions.push_back(input.point(tet[0])[2] + input.point(tet[3])[2] < 1.0 ? 1 : 2);
  }
  AdaptationOptions options;
  options.numberOfIterations = 6;
  options.numberOfPartitions = 16;
  options.numberOfThreads = 1;
  options.sizeGradation = 1e6; // the step as given
  CHECK(options.coarsen);      // on by default
  AdaptationResult coarsened, refinedOnly;
  CHECK(adaptMesh(input, options, coarsened).ok());
  options.coarsen = false;
  CHECK(adaptMesh(input, options, refinedOnly).ok());
  CHECK_EQUAL(refinedOnly.summary.edgeCollapses, 0);
  CHECK(coarsened.summary.edgeCollapses > 100);
  CHECK(coarsened.mesh.numberOfPoints() < refinedOnly.mesh.numberOfPoints());
  CHECK(coarsened.summary.edgeSizes.shareWithinBounds >
    refinedOnly.summary.edgeSizes.shareWithinBounds + 0.02);

  cgmesh_test::checkValidAndConserving(input, coarsened.mesh);
  CHECK(constrainedPoints(coarsened.mesh) == constrainedPoints(refinedOnly.mesh));
  CHECK(worstMeanRatio(coarsened.mesh) >= std::min(0.3, worstMeanRatio(refinedOnly.mesh)));

  options.coarsen = true;
  for (int threads : { 2, 3 })
  {
    options.numberOfThreads = threads;
    AdaptationResult parallel;
    CHECK(adaptMesh(input, options, parallel).ok());
    CHECK(cgmesh_test::identicalResults(coarsened, parallel));
  }
}

// A size field is for the refined mesh: improving the input before refinement (ImproveInput)
// neither coarsens it nor refuses changes that make edges longer than sqrt(2) h, which refinement
// splits anyway. So on the poor input of a TetGen FinFET, a field finer than every edge (which
// would refuse nearly every change) and one coarser than every edge (which refuses none) see the
// input improved alike. Both fields are uniform, a power of 2 apart, so the partitions balanced
// on the output they forecast are the same.
void test_input_improvement_ignores_the_size_field()
{
  TetMesh input;
  CHECK(generateFinFetWithTetGen(15000, input).ok());
  double shortest = std::numeric_limits<double>::infinity(), longest = 0;
  for (const Tet& tet : input.tets)
  {
    for (const auto& corners : TetEdgeCorners)
    {
      const double squared = squaredEdgeLength(input, tet[corners[0]], tet[corners[1]]);
      shortest = std::min(shortest, squared);
      longest = std::max(longest, squared);
    }
  }
  const double fine = 0.5 * std::sqrt(shortest);
  double coarse = fine;
  while (coarse < std::sqrt(longest))
  {
    coarse *= 2;
  }
  AdaptationOptions options;
  options.numberOfPartitions = 32;
  options.numberOfThreads = 2;
  options.numberOfIterations = 1;
  options.coarsen = false;
  AdaptationSummary improved[2];
  for (int run = 0; run < 2; ++run)
  {
    TetMesh sized = input;
    sized.sizes.assign(input.numberOfPoints(), run == 0 ? fine : coarse);
    AdaptationResult result;
    CHECK(adaptMesh(sized, options, result).ok());
    CHECK(result.summary.plan.sizeField);
    CHECK_EQUAL(result.mesh.numberOfTets() > input.numberOfTets(), run == 0); // fine refines
    cgmesh_test::checkValidAndConserving(sized, result.mesh);
    improved[run] = result.summary;
  }
  CHECK(improved[0].inputEdgeRemovals > 0);
  CHECK(improved[0].inputEdgeRemovals <= improved[0].edgeRemovals);
  CHECK(improved[0].inputVertexMoves <= improved[0].vertexMoves);
  CHECK_EQUAL(improved[0].inputEdgeRemovals, improved[1].inputEdgeRemovals);
  CHECK_EQUAL(improved[0].inputFaceSwaps, improved[1].inputFaceSwaps);
  CHECK_EQUAL(improved[0].inputVertexMoves, improved[1].inputVertexMoves);
}

void test_bad_size_fields_are_refused()
{
  AdaptationOptions options;
  AdaptationResult result;
  TetMesh input = gradedCube(2);
  input.sizes[3] = -0.5;
  Status status = adaptMesh(input, options, result);
  CHECK(status.kind() == ErrorKind::InvalidInput);
  CHECK(status.message().find("point 3") != std::string::npos);
  input.sizes[3] = std::numeric_limits<double>::quiet_NaN();
  CHECK(adaptMesh(input, options, result).kind() == ErrorKind::InvalidInput);
  input.sizes.pop_back();
  CHECK(adaptMesh(input, options, result).kind() == ErrorKind::InvalidInput);

  input = gradedCube(2);
  options.sizeGradation = 0.5;
  CHECK(adaptMesh(input, options, result).kind() == ErrorKind::InvalidOption);
}

// Children per input tet, and whether an input tet shares a point with a selected one.
std::vector<int> childrenOf(const AdaptationResult& result, CellId inputTets)
{
  std::vector<int> children(inputTets, 0);
  for (CellId parent : result.parentCell)
  {
    ++children[parent];
  }
  return children;
}

std::vector<char> touchesSelected(const TetMesh& mesh, const std::vector<char>& selected)
{
  std::vector<char> pointSelected(mesh.numberOfPoints(), 0), touches(mesh.tets.size(), 0);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
  {
    for (PointId p : mesh.tets[t])
    {
      pointSelected[p] |= selected[t];
    }
  }
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
  {
    for (PointId p : mesh.tets[t])
    {
      touches[t] |= pointSelected[p];
    }
  }
  return touches;
}

// Refinement restricted to a region or a box: the selected tets are refined, the tets that share
// no point with them are untouched, the mesh stays conforming with every region's volume, and
// the output does not depend on the thread count.
void test_refinement_regions_and_box()
{
  TetMesh input = gradedCube(6);
  input.sizes.clear();
  const std::array<double, 6> box = { 0, 0, 0, 0.3, 1, 1 };
  struct Case
  {
    const char* regions;
    const char* box;
  };
  for (const Case& selection : { Case{ "2", "" }, Case{ "", "0,0,0,0.3,1,1" } })
  {
    AdaptationOptions options;
    options.refinementRegions = selection.regions;
    options.refinementBox = selection.box;
    options.numberOfIterations = 2;
    options.numberOfPartitions = 16;
    options.numberOfThreads = 1;
    AdaptationResult serial;
    CHECK(adaptMesh(input, options, serial).ok());
    CHECK(serial.summary.plan.restricted());
    CHECK(!serial.summary.plan.sizeField && serial.edgeLengthRatio.empty());
    cgmesh_test::checkValidAndConserving(input, serial.mesh);
    const std::vector<char> selected =
      selection.box[0] ? selectTets(input, {}, &box) : selectTets(input, { 2 }, nullptr);
    const std::vector<char> near = touchesSelected(input, selected);
    const std::vector<int> children = childrenOf(serial, input.numberOfTets());
    int refined = 0, untouched = 0;
    for (std::size_t t = 0; t < input.tets.size(); ++t)
    {
      refined += selected[t] && children[t] > 1;
      untouched += !near[t];
      CHECK(near[t] || children[t] == 1);
    }
    CHECK(refined > 0 && untouched > 0);
    CHECK(std::count(selected.begin(), selected.end(), 1) < static_cast<long>(selected.size()));
    options.numberOfThreads = 2;
    AdaptationResult parallel;
    CHECK(adaptMesh(input, options, parallel).ok());
    CHECK(cgmesh_test::identicalResults(serial, parallel));
  }
}

void test_bad_selections_are_refused()
{
  const TetMesh input = gradedCube(2);
  TetMesh withoutRegions = input;
  withoutRegions.regions.clear();
  withoutRegions.sizes.clear();
  struct Case
  {
    const TetMesh* mesh;
    const char* regions;
    const char* box;
    RefinementMethod method;
  };
  const Case cases[] = { { &input, "2,x", "", RefinementMethod::Template },
    { &input, "2,", "", RefinementMethod::Template },
    { &input, "2.5", "", RefinementMethod::Template },
    { &input, "2,99", "", RefinementMethod::Template }, // no tet of region 99
    { &input, "", "0,0,0,1,1", RefinementMethod::Template },
    { &input, "", "1,0,0,0,1,1", RefinementMethod::Template },
    { &withoutRegions, "2", "", RefinementMethod::Template },
    { &withoutRegions, "", "0,0,0,1,1,1", RefinementMethod::Delaunay } };
  for (const Case& bad : cases)
  {
    AdaptationOptions options;
    options.refinementRegions = bad.regions;
    options.refinementBox = bad.box;
    options.method = bad.method;
    AdaptationResult result;
    CHECK(adaptMesh(*bad.mesh, options, result).kind() == ErrorKind::InvalidOption);
  }
  // The refusal of an unknown region names it and the regions there are.
  AdaptationOptions options;
  options.refinementRegions = "2,99";
  AdaptationResult result;
  const Status unknown = adaptMesh(input, options, result);
  CHECK(unknown.message().find("region 99, which no tet has") != std::string::npos);
  CHECK(unknown.message().find("values are 1, 2") != std::string::npos);
}

} // namespace

int main()
{
  test_gradation_limits_neighbouring_sizes();
  test_refinement_to_a_graded_field();
  test_edge_measure_counts_every_edge_once();
  test_delaunay_refinement_to_a_graded_field();
  test_coarsening_where_the_field_is_coarse();
  test_input_improvement_ignores_the_size_field();
  test_bad_size_fields_are_refused();
  test_refinement_regions_and_box();
  test_settled_partitions_are_not_read_again();
  test_bad_selections_are_refused();
  return cgmesh_test::finish("TestSizeField");
}
