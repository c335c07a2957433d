// The whole pipeline through adaptMesh(): conformity, conservation, exact tet counts, point
// provenance and bit-identical output for any thread count.
#include "AdaptationDriver.h"
#include "CubeGenerator.h"
#include "MeshChecks.h"
#include "ResultComparison.h"
#include "TestHarness.h"
#include "Validation/MeshValidation.h"

using namespace cgmesh;

namespace
{

TetMesh cubeWithRegions(int n)
{
  TetMesh mesh;
  CHECK(generateKuhnCube(n, mesh).ok());
  for (const Tet& tet : mesh.tets)
  {
    double x = 0;
    for (PointId p : tet)
    {
      x += mesh.point(p)[0];
    }
    mesh.regions.push_back(x < 2.0 ? 7 : -3); // centroid left or right of x = 0.5
  }
  return mesh;
}

AdaptationResult refine(const TetMesh& input, int partitions, int threads, int iterations,
  AdaptationOptions options = AdaptationOptions())
{
  options.numberOfPartitions = partitions;
  options.numberOfThreads = threads;
  options.numberOfIterations = iterations;
  options.edgeLengthFactor = 0.25;
  options.improveQuality = false; // pure templates: exact 8x tets per iteration
  AdaptationResult result;
  const Status status = adaptMesh(input, options, result);
  CHECK(status.ok());
  if (!status.ok())
  {
    std::cerr << status.message() << "\n";
  }
  return result;
}

void checkRefinedCube(const TetMesh& input, const AdaptationResult& result, int iterations)
{
  cgmesh_test::checkValidAndConserving(input, result.mesh);
  CHECK_EQUAL(result.mesh.numberOfTets(), input.numberOfTets() << (3 * iterations));
  // A linear field interpolated through the provenance weights is reproduced exactly.
  for (PointId p = 0; p < result.mesh.numberOfPoints(); ++p)
  {
    double interpolated = 0;
    for (std::int64_t k = result.provenance.offsets[p]; k < result.provenance.offsets[p + 1]; ++k)
    {
      const double* source = input.point(result.provenance.sources[k]);
      interpolated += result.provenance.weights[k] * (source[0] + 2 * source[1] + 3 * source[2]);
    }
    const double* point = result.mesh.point(p);
    CHECK_CLOSE(interpolated, point[0] + 2 * point[1] + 3 * point[2], 1e-12);
  }
}

// Without improvement the output tets stay in their refinement partitions, so a tet is near a
// former interface exactly when one of its corners lies in tets of two partitions. The passes
// after the first keep those points from the posted splits the partitions took, not from a scan
// of the refined tets: a point missed or added there shows here.
void test_former_interfaces_follow_the_passes()
{
  const TetMesh input = cubeWithRegions(4);
  for (int partitions : { 5, 16, 100 })
  {
    const AdaptationResult result = refine(input, partitions, 2, 3);
    const TetMesh& mesh = result.mesh;
    CHECK_EQUAL(result.partitionOfCell.size(), mesh.tets.size());
    CHECK_EQUAL(result.nearFormerInterface.size(), mesh.tets.size());
    if (result.partitionOfCell.size() != mesh.tets.size() ||
      result.nearFormerInterface.size() != mesh.tets.size())
    {
      continue;
    }
    std::vector<int> firstPartition(static_cast<std::size_t>(mesh.numberOfPoints()), -1);
    std::vector<char> shared(firstPartition.size(), 0);
    for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    {
      for (PointId p : mesh.tets[t])
      {
        if (firstPartition[p] < 0)
        {
          firstPartition[p] = result.partitionOfCell[t];
        }
        shared[p] |= firstPartition[p] != result.partitionOfCell[t];
      }
    }
    std::int64_t near = 0, wrong = 0;
    for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    {
      const Tet& tet = mesh.tets[t];
      const bool expected = shared[tet[0]] || shared[tet[1]] || shared[tet[2]] || shared[tet[3]];
      near += expected;
      wrong += expected != (result.nearFormerInterface[t] != 0);
    }
    CHECK(near > 0 && near < static_cast<std::int64_t>(mesh.tets.size()));
    CHECK_EQUAL(wrong, 0);
  }
}

void test_cube_refinement_at_partition_counts()
{
  const TetMesh input = cubeWithRegions(6);
  for (int partitions : { 1, 4, 64, 1024 })
  {
    const AdaptationResult serial = refine(input, partitions, 1, 2);
    checkRefinedCube(input, serial, 2);
    CHECK_EQUAL(serial.summary.plan.partitions, partitions > 1296 ? 1296 : partitions);
    CHECK(serial.summary.numberOfColors >= (partitions > 1 ? 2 : 1));
    for (int threads : { 2, 3 })
    {
      CHECK(cgmesh_test::identicalResults(serial, refine(input, partitions, threads, 2)));
    }
  }
}

void test_every_coloring_gives_identical_output_across_threads()
{
  const TetMesh input = cubeWithRegions(6);
  for (const char* coloring : { "greedy", "greedy-lu", "iterative", "recoloring" })
  {
    AdaptationOptions options;
    options.coloring = coloring;
    const AdaptationResult serial = refine(input, 64, 1, 1, options);
    checkRefinedCube(input, serial, 1);
    CHECK(cgmesh_test::identicalResults(serial, refine(input, 64, 2, 1, options)));
    CHECK_EQUAL(serial.summary.partitionsPerColor.size(),
      static_cast<std::size_t>(serial.summary.numberOfColors));
    std::int64_t cells = 0;
    for (std::int64_t count : serial.summary.cellsPerColor)
    {
      cells += count;
    }
    CHECK_EQUAL(cells, serial.mesh.numberOfTets());
    CHECK(serial.summary.colorBalance >= 1.0);
  }
}

// Templates use Hilbert runs by default; METIS must work for them as well, down to one tet per
// partition.
void test_each_partitioner_conforms_for_any_thread_count()
{
  const TetMesh input = cubeWithRegions(6);
  for (PartitionerKind partitioner :
    { PartitionerKind::Metis, PartitionerKind::Hilbert, PartitionerKind::CurveChunks })
  {
    for (int partitions : { 64, 1296 })
    {
      AdaptationOptions options;
      options.partitioner = partitioner;
      const AdaptationResult serial = refine(input, partitions, 1, 2, options);
      CHECK(serial.summary.plan.partitioner == partitioner);
      checkRefinedCube(input, serial, 2);
      CHECK(serial.summary.interfacePoints > 0);
      CHECK(cgmesh_test::identicalResults(serial, refine(input, partitions, 2, 2, options)));
      CHECK(cgmesh_test::identicalResults(serial, refine(input, partitions, 3, 2, options)));
    }
  }
}

void test_partition_by_region()
{
  const TetMesh input = cubeWithRegions(6);
  for (int perRegion : { 1, 5 })
  {
    AdaptationOptions options;
    options.partitionByRegion = true;
    options.partitionsPerRegion = perRegion;
    const AdaptationResult result = refine(input, 0, 2, 1, options);
    checkRefinedCube(input, result, 1);
    CHECK_EQUAL(result.summary.plan.partitions, 2 * perRegion);
    // Every partition lies inside one region.
    std::vector<int> regionOfPartition(result.summary.plan.partitions, 0);
    for (std::size_t t = 0; t < result.partitionOfCell.size(); ++t)
    {
      regionOfPartition[result.partitionOfCell[t]] = result.mesh.regions[t];
    }
    for (std::size_t t = 0; t < result.partitionOfCell.size(); ++t)
    {
      CHECK_EQUAL(regionOfPartition[result.partitionOfCell[t]], result.mesh.regions[t]);
    }
    CHECK(cgmesh_test::identicalResults(result, refine(input, 0, 1, 1, options)));
  }
  TetMesh noRegions;
  CHECK(generateKuhnCube(2, noRegions).ok());
  AdaptationOptions options;
  options.partitionByRegion = true;
  AdaptationResult result;
  CHECK(!adaptMesh(noRegions, options, result).ok());
}

void test_partition_count_clamped_to_tets()
{
  TetMesh input;
  CHECK(generateKuhnCube(1, input).ok());
  const AdaptationResult result = refine(input, 1024, 2, 1);
  CHECK_EQUAL(result.summary.plan.partitions, 6);
  CHECK_EQUAL(result.summary.warnings.size(), 1u);
  CHECK(result.summary.warnings[0].kind == WarningKind::PartitionsReduced);
  checkRefinedCube(input, result, 1);
}

// NumberOfPartitions 0: 1024 for templates; for Delaunay one per 30,000 forecast tets (3 x volume
// / V) within [8, 1024]; never more than the tets, and never a warning.
void test_automatic_partition_count()
{
  TetMesh input;
  CHECK(generateKuhnCube(8, input).ok()); // 3072 tets, unit volume
  std::vector<AdaptationWarning> warnings;
  AdaptationOptions options;
  CHECK_EQUAL(options.numberOfPartitions, 0);
  CHECK_EQUAL(resolvePlan(input, options, warnings).partitions, 1024);
  options.method = RefinementMethod::Delaunay;
  options.maximumVolume = 1e-5; // forecast 300,000 tets
  CHECK_EQUAL(resolvePlan(input, options, warnings).partitions, 10);
  options.maximumVolume = 1e-4; // 30,000 tets
  CHECK_EQUAL(resolvePlan(input, options, warnings).partitions, 8);
  options.maximumVolume = 5e-7; // 6 M tets
  CHECK_EQUAL(resolvePlan(input, options, warnings).partitions, 200);
  options.maximumVolume = 1e-7; // 30 M tets
  CHECK_EQUAL(resolvePlan(input, options, warnings).partitions, 1000);
  options.maximumVolume = 1e-8;
  CHECK_EQUAL(resolvePlan(input, options, warnings).partitions, 1024);
  CHECK(generateKuhnCube(2, input).ok()); // 48 tets
  options.method = RefinementMethod::Template;
  CHECK_EQUAL(resolvePlan(input, options, warnings).partitions, 48);
  CHECK(warnings.empty());
}

void test_bad_options_are_refused()
{
  TetMesh input;
  CHECK(generateKuhnCube(2, input).ok());
  AdaptationOptions options;
  AdaptationResult result;
  options.coloring = "no-such-colouring";
  Status status = adaptMesh(input, options, result);
  CHECK(status.kind() == ErrorKind::InvalidOption);
  CHECK(result.mesh.tets.empty());
  options = AdaptationOptions();
  options.edgeLengthFactor = 0;
  CHECK(adaptMesh(input, options, result).kind() == ErrorKind::InvalidOption);
  options = AdaptationOptions();
  options.maximumNumberOfCells = 10;
  status = adaptMesh(input, options, result);
  CHECK(status.kind() == ErrorKind::SizeLimit);
  CHECK(status.message().find("MaximumNumberOfCells") != std::string::npos);
  input.tets.push_back({ 0, 1, 2, 999 });
  CHECK(adaptMesh(input, AdaptationOptions(), result).kind() == ErrorKind::InvalidInput);
}

void test_abort_between_colours()
{
  const TetMesh input = cubeWithRegions(4);
  AdaptationOptions options;
  options.numberOfPartitions = 16;
  int polls = 0;
  options.abortRequested = [&polls]()
  {
    return ++polls > 1;
  };
  AdaptationResult result;
  CHECK(adaptMesh(input, options, result).ok());
  CHECK(result.summary.aborted);
  CHECK(result.mesh.tets.empty());
}

// Passes stop after one that adds no point, and say so; the result is that of that many passes.
void test_iterations_stop_when_a_pass_adds_nothing()
{
  const TetMesh input = cubeWithRegions(3);
  AdaptationOptions options;
  options.numberOfPartitions = 8;
  options.numberOfThreads = 2;
  options.edgeLengthFactor = 0.25;
  options.improveQuality = false;
  options.numberOfIterations = 10;
  AdaptationResult many;
  CHECK(adaptMesh(input, options, many).ok());
  const int run = many.summary.iterationsRun;
  CHECK(run >= 2 && run < 10);
  CHECK(many.summary.refinementConverged);

  options.numberOfIterations = run;
  AdaptationResult exact;
  CHECK(adaptMesh(input, options, exact).ok());
  CHECK(cgmesh_test::identicalResults(many, exact));

  // The last pass run added nothing: one pass fewer gives the same mesh, but cannot know it is
  // done, since its own last pass added points.
  options.numberOfIterations = run - 1;
  AdaptationResult fewer;
  CHECK(adaptMesh(input, options, fewer).ok());
  CHECK_EQUAL(fewer.summary.iterationsRun, run - 1);
  CHECK(!fewer.summary.refinementConverged);
  CHECK(cgmesh_test::identicalResults(many, fewer));
}

// Without point data to interpolate, the front end asks for no provenance: same mesh, none made.
void test_point_provenance_only_when_asked()
{
  const TetMesh input = cubeWithRegions(4);
  AdaptationOptions options;
  options.numberOfPartitions = 16;
  options.numberOfThreads = 2;
  AdaptationResult with, without;
  CHECK(adaptMesh(input, options, with).ok());
  options.pointProvenance = false;
  CHECK(adaptMesh(input, options, without).ok());
  CHECK(without.provenance.offsets.empty() && without.provenance.sources.empty());
  CHECK(with.provenance.offsets.size() == static_cast<std::size_t>(with.mesh.numberOfPoints()) + 1);
  CHECK(with.mesh.coordinates == without.mesh.coordinates);
  CHECK(with.mesh.tets == without.mesh.tets);
  CHECK(with.parentCell == without.parentCell);
}

} // namespace

int main()
{
  test_cube_refinement_at_partition_counts();
  test_former_interfaces_follow_the_passes();
  test_every_coloring_gives_identical_output_across_threads();
  test_each_partitioner_conforms_for_any_thread_count();
  test_partition_by_region();
  test_partition_count_clamped_to_tets();
  test_automatic_partition_count();
  test_bad_options_are_refused();
  test_abort_between_colours();
  test_iterations_stop_when_a_pass_adds_nothing();
  test_point_provenance_only_when_asked();
  return cgmesh_test::finish("TestAdaptMesh");
}
