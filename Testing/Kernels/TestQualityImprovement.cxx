// Quality improvement: each operation on a hand-made configuration (and coarsening only where it
// may collapse), then the whole pipeline on a multi-material device: conformity, conservation,
// fixed interfaces, better worst tets, identical output across thread counts; and the device's
// input improved before refinement.
#include "AdaptationDriver.h"
#include "Core/TetQuality.h"
#include "CubeGenerator.h"
#include "FinFetGenerator.h"
#include "Improvement/QualityImprover.h"
#include "ImprovementSweep.h"
#include "MeshChecks.h"
#include "PhaseReporter.h"
#include "Refinement/PartitionRefiner.h"
#include "Refinement/SizeField.h"
#include "ResultComparison.h"
#include "TestHarness.h"
#include "Validation/MeshValidation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

using namespace cgmesh;

namespace
{

double worstMeanRatio(const TetMesh& mesh)
{
  double worst = 1;
  for (const Tet& t : mesh.tets)
  {
    worst = std::min(
      worst, meanRatio(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]), mesh.point(t[3])));
  }
  return worst;
}

// A closed star: an octahedron split into 8 tets around an inner vertex placed off-centre.
// Improvement runs on the star as a partition: its boundary vertices are fixed.
PartitionMesh starAround(std::vector<double>& coordinates, const double inner[3])
{
  coordinates = { 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1 };
  coordinates.insert(coordinates.end(), inner, inner + 3);
  const PointId centre = 6;
  const int faces[8][3] = { { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 }, { 3, 0, 4 }, { 2, 0, 5 },
    { 1, 2, 5 }, { 3, 1, 5 }, { 0, 3, 5 } };
  PartitionMesh star;
  for (const auto& f : faces)
  {
    Tet tet = { f[0], f[1], f[2], centre };
    if (signedVolume6(coordinates.data() + 3 * f[0], coordinates.data() + 3 * f[1],
          coordinates.data() + 3 * f[2], coordinates.data() + 3 * centre) < 0)
    {
      std::swap(tet[0], tet[1]);
    }
    star.tets.push_back(tet);
    star.parentCells.push_back(0);
  }
  return star;
}

TetMesh asMesh(const PartitionMesh& partition, const std::vector<double>& coordinates)
{
  TetMesh mesh;
  mesh.coordinates = coordinates;
  mesh.tets = partition.tets;
  return mesh;
}

void test_smoothing_moves_free_vertex_only()
{
  std::vector<double> coordinates;
  const double inner[3] = { 0.5, 0.1, -0.15 }; // inside, far off-centre
  PartitionMesh star = starAround(coordinates, inner);
  const std::vector<double> boundaryBefore(coordinates.begin(), coordinates.begin() + 18);
  const MeshReport before = inspectMesh(asMesh(star, coordinates));
  const double worstBefore = worstMeanRatio(asMesh(star, coordinates));
  std::vector<double> provisional;
  ImprovementStatistics statistics;
  std::vector<PointId> moved;
  ImprovementParameters parameters;
  parameters.targetQuality = 0.9;
  CHECK(improvePartition(
    star, PartitionPoints{ &coordinates, &provisional }, parameters, statistics, moved)
          .ok());
  CHECK(statistics.vertexMoves >= 1);
  CHECK(moved.size() == 1 && moved[0] == 6);
  CHECK(std::equal(boundaryBefore.begin(), boundaryBefore.end(), coordinates.begin()));
  const MeshReport after = inspectMesh(asMesh(star, coordinates));
  CHECK(after.isValid());
  CHECK_CLOSE(after.volume, before.volume, 1e-12);
  CHECK(worstMeanRatio(asMesh(star, coordinates)) > worstBefore + 0.05);
}

// The classic 3->2 case: a long edge (a, b) through a nearly flat triangle of three points; the
// three tets around it become two well-shaped tets on the triangle.
void test_edge_removal_three_to_two()
{
  std::vector<double> coordinates = { 0, 0, 1, 0, 0, -1, 1, 0, 0.05, -0.5, 0.866, -0.05, -0.5,
    -0.866, 0.02 };
  PartitionMesh ring;
  for (int i = 0; i < 3; ++i)
  {
    Tet tet = { 0, 1, 2 + i, 2 + (i + 1) % 3 };
    if (signedVolume6(coordinates.data() + 3 * tet[0], coordinates.data() + 3 * tet[1],
          coordinates.data() + 3 * tet[2], coordinates.data() + 3 * tet[3]) < 0)
    {
      std::swap(tet[2], tet[3]);
    }
    ring.tets.push_back(tet);
    ring.parentCells.push_back(i);
  }
  const MeshReport before = inspectMesh(asMesh(ring, coordinates));
  std::vector<double> provisional;
  ImprovementStatistics statistics;
  std::vector<PointId> moved;
  ImprovementParameters parameters;
  parameters.targetQuality = 0.9;
  CHECK(improvePartition(
    ring, PartitionPoints{ &coordinates, &provisional }, parameters, statistics, moved)
          .ok());
  CHECK_EQUAL(statistics.edgeRemovals, 1);
  CHECK_EQUAL(ring.tets.size(), 2u);
  const MeshReport after = inspectMesh(asMesh(ring, coordinates));
  CHECK(after.isValid());
  CHECK_CLOSE(after.volume, before.volume, 1e-12);
  CHECK_CLOSE(after.boundaryArea, before.boundaryArea, 1e-12);
}

// With a size field no change may make an edge longer than sqrt(2) h, except one that mends a
// sliver (mean ratio under 0.2): a star whose inner vertex sits nearly on corner 0, with h = 0.5
// (every edge of the octahedron already longer than sqrt(2) h), is mended anyway; a star whose
// worst tet is poor but no sliver stays as it is.
void test_size_bound_gives_way_to_mending_slivers()
{
  for (const bool sliver : { true, false })
  {
    std::vector<double> coordinates;
    const double nearCorner[3] = { 0.97, 0.01, -0.01 }, offCentre[3] = { 0.45, 0.1, -0.1 };
    PartitionMesh star = starAround(coordinates, sliver ? nearCorner : offCentre);
    const double worstBefore = worstMeanRatio(asMesh(star, coordinates));
    CHECK(sliver ? worstBefore < 0.2 : worstBefore > 0.2 && worstBefore < 0.5);
    const MeshReport before = inspectMesh(asMesh(star, coordinates));
    std::vector<double> provisional, sizes(7, 0.5), provisionalSizes;
    PartitionPoints points{ &coordinates, &provisional, &sizes, &provisionalSizes };
    ImprovementParameters parameters;
    ImprovementStatistics statistics;
    std::vector<PointId> moved;
    CHECK(improvePartition(star, points, parameters, statistics, moved).ok());
    const double worstAfter = worstMeanRatio(asMesh(star, coordinates));
    if (sliver)
    {
      CHECK(worstAfter > 0.3);
    }
    else
    {
      CHECK_EQUAL(statistics.vertexMoves + statistics.edgeRemovals + statistics.faceSwaps, 0);
      CHECK_CLOSE(worstAfter, worstBefore, 1e-15);
    }
    const MeshReport after = inspectMesh(asMesh(star, coordinates));
    CHECK(after.isValid());
    CHECK_CLOSE(after.volume, before.volume, 1e-12);
    CHECK_CLOSE(after.boundaryArea, before.boundaryArea, 1e-12);
  }
}

// Coarsening a star whose inner vertex lies next to corner 0: with h = 1.5 everywhere only the
// edge from the inner vertex to corner 0 is shorter than h / sqrt(2), and collapsing it leaves
// the octahedron as four tets around its diagonal (corner 0 to corner 1, 2 < sqrt(2) h). Done
// where the inner vertex may be collapsed (no flags, or flagged), refused where it is not
// flagged; the volume is kept either way.
void test_collapse_only_where_flagged()
{
  for (int flags = 0; flags < 3; ++flags) // none, inner vertex not flagged, flagged
  {
    std::vector<double> coordinates;
    const double inner[3] = { 0.7, 0.05, -0.02 };
    PartitionMesh star = starAround(coordinates, inner);
    const MeshReport before = inspectMesh(asMesh(star, coordinates));
    std::vector<double> provisional, sizes(7, 1.5), provisionalSizes;
    PartitionPoints points{ &coordinates, &provisional, &sizes, &provisionalSizes };
    std::vector<char> collapsible(7, 0);
    collapsible[6] = flags == 2;
    ImprovementParameters parameters;
    parameters.improve = false;
    parameters.coarsen = true;
    parameters.collapsibleVertices = flags == 0 ? nullptr : &collapsible;
    ImprovementStatistics statistics;
    std::vector<PointId> moved;
    CHECK(improvePartition(star, points, parameters, statistics, moved).ok());
    const bool collapsed = flags != 1;
    CHECK_EQUAL(statistics.edgeCollapses, collapsed ? 1 : 0);
    CHECK_EQUAL(star.tets.size(), collapsed ? 4u : 8u);
    const bool innerUsed = std::any_of(star.tets.begin(), star.tets.end(),
      [](const Tet& tet) { return std::find(tet.begin(), tet.end(), 6) != tet.end(); });
    CHECK(innerUsed != collapsed);
    const MeshReport after = inspectMesh(asMesh(star, coordinates));
    CHECK_EQUAL(after.invertedTets + after.degenerateTets + after.overSharedFaces, 0);
    CHECK_EQUAL(after.misorientedFacePairs, 0);
    CHECK_EQUAL(after.unusedPoints, collapsed ? 1 : 0); // the inner vertex, left by the merge
    CHECK_EQUAL(after.boundaryFaces, before.boundaryFaces);
    CHECK_CLOSE(after.volume, before.volume, 1e-12);
    CHECK_CLOSE(after.boundaryArea, before.boundaryArea, 1e-12);
  }
}

// A small device refined once (factor 0.6), without improvement: poor tets and, against sizes
// under the refinement's threshold, short edges to work on.
AdaptationResult refinedDevice()
{
  TetMesh input;
  CHECK(generateFinFet(15000, input).ok());
  AdaptationOptions options;
  options.numberOfPartitions = 8;
  options.edgeLengthFactor = 0.6;
  options.improveQuality = false;
  AdaptationResult refined;
  CHECK(adaptMesh(input, options, refined).ok());
  return refined;
}

// The whole mesh as one partition, so that only its boundary and material interfaces freeze.
PartitionMesh asOnePartition(const TetMesh& mesh)
{
  PartitionMesh partition;
  partition.tets = mesh.tets;
  partition.regions = mesh.regions;
  partition.parentCells.assign(partition.tets.size(), 0);
  return partition;
}

// The tets improvePartition() reports left to do are exactly those that still need improvement
// afterwards, tried on a refined device taken whole as one partition (its boundary and material
// interfaces frozen, so work is left there), with and without coarsening to a size field.
void test_tets_left_are_those_still_needing_work()
{
  const AdaptationResult refined = refinedDevice();
  for (bool coarsen : { false, true })
  {
    PartitionMesh partition = asOnePartition(refined.mesh);
    std::vector<double> coordinates = refined.mesh.coordinates, provisional, provisionalSizes;
    // Sizes that make part of the edges short.
    std::vector<double> sizes(
      refined.mesh.numberOfPoints(), 0.8 * refined.summary.plan.edgeLengthThreshold);
    PartitionPoints points{ &coordinates, &provisional };
    if (coarsen)
    {
      points.globalSizes = &sizes;
      points.provisionalSizes = &provisionalSizes;
    }
    ImprovementParameters parameters;
    parameters.coarsen = coarsen;
    ImprovementStatistics statistics;
    std::vector<PointId> moved;
    std::vector<std::size_t> left = { 12345 }; // replaced, not appended to
    CHECK(improvePartition(partition, points, parameters, statistics, moved, &left).ok());
    std::vector<std::size_t> expected;
    for (std::size_t t = 0; t < partition.tets.size(); ++t)
    {
      if (needsImprovement(partition.tets[t], points, parameters))
      {
        expected.push_back(t);
      }
    }
    CHECK(left == expected);
    std::cout << (coarsen ? "with" : "without") << " coarsening: " << expected.size() << " of "
              << partition.tets.size() << " tets left to improve\n";
    CHECK(!expected.empty() && expected.size() < partition.tets.size());
    CHECK(statistics.edgeRemovals + statistics.faceSwaps + statistics.vertexMoves > 0);
    CHECK(!coarsen || statistics.edgeCollapses > 0);
  }
}

// With settledVertices, an improver clears the flags of the vertices it could not collapse while
// they were free (ImprovementParameters::settledVertices): each such vertex is still in the mesh,
// lies on no boundary or material interface, and every vertex there keeps its flag. Tried on the
// refined device taken whole as one partition, every vertex flagged, with sizes that make part
// of the edges short.
void test_settled_vertices_are_free_ones_that_stayed()
{
  const AdaptationResult refined = refinedDevice();
  PartitionMesh partition = asOnePartition(refined.mesh);
  const std::size_t pointCount = static_cast<std::size_t>(refined.mesh.numberOfPoints());
  std::vector<double> coordinates = refined.mesh.coordinates, provisional, provisionalSizes;
  std::vector<double> sizes(pointCount, 0.8 * refined.summary.plan.edgeLengthThreshold);
  PartitionPoints points{ &coordinates, &provisional, &sizes, &provisionalSizes };
  std::vector<char> flags(pointCount, 1);
  ImprovementParameters parameters;
  parameters.coarsen = true;
  parameters.collapsibleVertices = &flags;
  parameters.settledVertices = &flags;
  ImprovementStatistics statistics;
  std::vector<PointId> moved;
  CHECK(improvePartition(partition, points, parameters, statistics, moved).ok());
  CHECK(statistics.edgeCollapses > 0);

  // Vertices in use, and those on a face with one tet or with tets of two regions.
  std::vector<char> used(pointCount, 0), constrained(pointCount, 0);
  std::map<std::array<PointId, 3>, std::vector<int>> regionsAtFace;
  for (std::size_t t = 0; t < partition.tets.size(); ++t)
  {
    const Tet& tet = partition.tets[t];
    for (int skip = 0; skip < 4; ++skip)
    {
      std::array<PointId, 3> face;
      int n = 0;
      for (int k = 0; k < 4; ++k)
      {
        used[tet[k]] = 1;
        if (k != skip)
        {
          face[n++] = tet[k];
        }
      }
      std::sort(face.begin(), face.end());
      regionsAtFace[face].push_back(partition.regions[t]);
    }
  }
  for (const auto& [face, regions] : regionsAtFace)
  {
    if (regions.size() == 1 || regions[0] != regions[1])
    {
      for (PointId p : face)
      {
        constrained[p] = 1;
      }
    }
  }
  std::size_t settled = 0, constrainedFlagged = 0, constrainedCount = 0;
  for (std::size_t p = 0; p < pointCount; ++p)
  {
    if (flags[p] == 0)
    {
      ++settled;
      CHECK(used[p] && !constrained[p]);
    }
    if (used[p] && constrained[p])
    {
      ++constrainedCount;
      constrainedFlagged += flags[p];
    }
  }
  std::cout << settled << " of " << pointCount << " vertices settled after "
            << statistics.edgeCollapses << " collapses\n";
  CHECK(settled > 0);
  CHECK_EQUAL(constrainedFlagged, constrainedCount);
}

// Refinement's list of the tets that may be under the target (PartitionRefinement::tetsToScreen)
// loses no work: the device meshed by TetGen (poor tets in it), refined as one partition with
// full and partial splits, is improved the same with the list as with every tet screened.
void test_screening_the_listed_tets_finds_all_work()
{
  TetMesh input;
  CHECK(generateFinFetWithTetGen(15000, input).ok());
  PartitionMesh partition;
  partition.tets = input.tets;
  partition.regions = input.regions;
  for (std::size_t t = 0; t < input.tets.size(); ++t)
  {
    partition.parentCells.push_back(static_cast<CellId>(t));
  }
  std::vector<double> lengths;
  for (const Tet& tet : input.tets)
  {
    lengths.push_back(std::sqrt(squaredDistance(input.point(tet[0]), input.point(tet[1]))));
  }
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 4, lengths.end());
  const std::vector<char> noInterface(input.numberOfPoints(), 0);
  const TemplateTable templates;
  RefinementContext context;
  context.coordinates = &input.coordinates;
  context.interfaceVertex = &noInterface;
  context.squaredThreshold = lengths[lengths.size() / 4] * lengths[lengths.size() / 4];
  context.templates = &templates;
  const ImprovementParameters parameters;
  context.improvementTarget = parameters.targetQuality;
  PartitionRefinement refinement;
  CHECK(refinePartition(partition, context, PostedSplits(), refinement).ok());
  const std::vector<std::size_t> listed = refinement.tetsToScreen;
  std::cout << listed.size() << " of " << partition.tets.size() << " refined tets listed\n";
  CHECK(!listed.empty() && listed.size() < partition.tets.size());

  struct Outcome
  {
    PartitionMesh partition;
    std::vector<double> coordinates, newCoordinates;
    ImprovementStatistics statistics;
    std::vector<std::size_t> left;
  };
  auto improve = [&](const std::vector<std::size_t>* tetsToScreen)
  {
    Outcome outcome{ partition, input.coordinates, refinement.newCoordinates, {}, {} };
    PartitionPoints points{ &outcome.coordinates, &outcome.newCoordinates };
    std::vector<PointId> moved;
    CHECK(improvePartition(
      outcome.partition, points, parameters, outcome.statistics, moved, &outcome.left, tetsToScreen)
            .ok());
    return outcome;
  };
  const Outcome all = improve(nullptr), screened = improve(&listed);
  CHECK(all.statistics.poorTets > 0 && all.statistics.edgeRemovals > 0);
  CHECK_EQUAL(screened.statistics.poorTets, all.statistics.poorTets);
  CHECK_EQUAL(screened.statistics.edgeRemovals, all.statistics.edgeRemovals);
  CHECK_EQUAL(screened.statistics.vertexMoves, all.statistics.vertexMoves);
  CHECK(screened.partition.tets == all.partition.tets);
  CHECK(screened.coordinates == all.coordinates && screened.newCoordinates == all.newCoordinates);
  CHECK(screened.left == all.left);
}

// Moved and derived points are relocated in the input: linear point data stays exact.
void checkLinearDataExact(const TetMesh& input, const AdaptationResult& result)
{
  for (PointId p = 0; p < result.mesh.numberOfPoints(); ++p)
  {
    double interpolated = 0;
    for (auto k = result.provenance.offsets[p]; k < result.provenance.offsets[p + 1]; ++k)
    {
      const double* source = input.point(result.provenance.sources[k]);
      interpolated += result.provenance.weights[k] * (2 * source[0] - source[1] + source[2]);
    }
    const double* point = result.mesh.point(p);
    CHECK_CLOSE(interpolated, 2 * point[0] - point[1] + point[2], 1e-9);
  }
}

std::int64_t tetsBelowTarget(const TetMesh& mesh)
{
  std::int64_t below = 0;
  for (const Tet& t : mesh.tets)
  {
    below +=
      meanRatioBelow(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]), mesh.point(t[3]), 0.5);
  }
  return below;
}

// Runs `options` on the input without improvement, then with it.
void adaptWithoutAndWithImprovement(const TetMesh& input, AdaptationOptions options,
  AdaptationResult& plain, AdaptationResult& improved)
{
  options.improveQuality = false;
  CHECK(adaptMesh(input, options, plain).ok());
  options.improveQuality = true;
  CHECK(adaptMesh(input, options, improved).ok());
}

void test_device_refinement_with_improvement()
{
  TetMesh input;
  CHECK(generateFinFet(15000, input).ok());
  AdaptationOptions options;
  options.numberOfPartitions = 32;
  options.edgeLengthFactor = 0.6; // splits only some edges: irregular templates to improve
  options.numberOfThreads = 1;
  AdaptationResult plain, improved;
  adaptWithoutAndWithImprovement(input, options, plain, improved);
  options.improveQuality = true;

  cgmesh_test::checkValidAndConserving(input, improved.mesh);
  CHECK(
    improved.summary.edgeRemovals + improved.summary.faceSwaps + improved.summary.vertexMoves > 0);
  const double worstPlain = worstMeanRatio(plain.mesh);
  const double worstImproved = worstMeanRatio(improved.mesh);
  std::cout << "worst mean ratio " << worstPlain << " -> " << worstImproved
            << "; 1st percentile of the minimum dihedral angle "
            << cgmesh_test::minimumDihedralPercentile(plain.mesh, 0.01) << " -> "
            << cgmesh_test::minimumDihedralPercentile(improved.mesh, 0.01) << " degrees; "
            << improved.summary.edgeRemovals << " edge removals, " << improved.summary.faceSwaps
            << " face swaps, " << improved.summary.vertexMoves << " vertex moves\n";
  CHECK(worstImproved > worstPlain);
  CHECK(cgmesh_test::minimumDihedralPercentile(improved.mesh, 0.01) >=
    cgmesh_test::minimumDihedralPercentile(plain.mesh, 0.01));
  CHECK_EQUAL(improved.nearFormerInterface.size(), improved.mesh.tets.size());

  checkLinearDataExact(input, improved);

  options.numberOfThreads = 2;
  AdaptationResult parallel;
  CHECK(adaptMesh(input, options, parallel).ok());
  CHECK(cgmesh_test::identicalResults(improved, parallel));
}

// Over several refinement passes a partition is improved once it has settled, or in the last
// pass allowed: both when the passes converge and when the iteration limit stops them, the
// output is improved as much as after a single pass (worse worst tets, or none of the operations,
// would show a partition left out), and the same for any thread count.
void test_improvement_over_several_passes()
{
  TetMesh input;
  CHECK(generateFinFet(15000, input).ok());
  for (const int iterations : { 2, 10 })
  {
    AdaptationOptions options;
    options.numberOfPartitions = 32;
    options.edgeLengthFactor = 0.3; // more than two passes to converge
    options.numberOfIterations = iterations;
    options.numberOfThreads = 1;
    AdaptationResult plain, improved;
    adaptWithoutAndWithImprovement(input, options, plain, improved);
    options.improveQuality = true;
    CHECK_EQUAL(improved.summary.refinementConverged, iterations == 10);
    CHECK(improved.summary.iterationsRun >= 2);

    cgmesh_test::checkValidAndConserving(input, improved.mesh);
    CHECK(
      improved.summary.edgeRemovals + improved.summary.faceSwaps + improved.summary.vertexMoves >
      0);
    std::cout << iterations << " iterations allowed, " << improved.summary.iterationsRun
              << " run: worst mean ratio " << worstMeanRatio(plain.mesh) << " -> "
              << worstMeanRatio(improved.mesh) << ", tets below the target "
              << tetsBelowTarget(plain.mesh) << " -> " << tetsBelowTarget(improved.mesh) << "\n";
    CHECK(worstMeanRatio(improved.mesh) > worstMeanRatio(plain.mesh));
    CHECK(2 * tetsBelowTarget(improved.mesh) < tetsBelowTarget(plain.mesh));

    options.numberOfThreads = 2;
    AdaptationResult parallel;
    CHECK(adaptMesh(input, options, parallel).ok());
    CHECK(cgmesh_test::identicalResults(improved, parallel));
  }
}

// The FinFET meshed by TetGen (radius-edge bound only, so slivers stay) has poor tets before
// refinement. Improving it first (ImproveInput, the default) keeps every invariant, exact linear
// point data through the moved input points and thread independence, and leaves fewer poor tets
// and a better 1st percentile of the minimum dihedral angle than improving after refinement
// only. A refinement selection turns it off.
void test_input_improved_before_refinement()
{
  TetMesh input;
  CHECK(generateFinFetWithTetGen(15000, input).ok());
  CHECK(tetsBelowTarget(input) > 0);
  AdaptationOptions options;
  options.numberOfPartitions = 32;
  options.edgeLengthFactor = 0.5;
  options.numberOfThreads = 1;
  options.improveInput = false;
  AdaptationResult afterOnly;
  CHECK(adaptMesh(input, options, afterOnly).ok());
  options.improveInput = true;
  AdaptationResult first;
  CHECK(adaptMesh(input, options, first).ok());

  cgmesh_test::checkValidAndConserving(input, first.mesh);
  cgmesh_test::checkValidAndConserving(input, afterOnly.mesh);
  checkLinearDataExact(input, first);
  const double p1First = cgmesh_test::minimumDihedralPercentile(first.mesh, 0.01);
  const double p1AfterOnly = cgmesh_test::minimumDihedralPercentile(afterOnly.mesh, 0.01);
  std::cout << "input improved first: " << tetsBelowTarget(first.mesh)
            << " tets below mean ratio 0.5, minimum dihedral p1 " << p1First
            << " degrees; improved after refinement only: " << tetsBelowTarget(afterOnly.mesh)
            << ", " << p1AfterOnly << " degrees\n";
  CHECK(tetsBelowTarget(first.mesh) < tetsBelowTarget(afterOnly.mesh));
  CHECK(p1First > p1AfterOnly);

  options.numberOfThreads = 2;
  AdaptationResult parallel;
  CHECK(adaptMesh(input, options, parallel).ok());
  CHECK(cgmesh_test::identicalResults(first, parallel));

  // A selection promises the tets outside it stay as they are: the input is not improved first.
  options.refinementRegions = "2";
  AdaptationResult selected, selectedWithout;
  CHECK(adaptMesh(input, options, selected).ok());
  options.improveInput = false;
  CHECK(adaptMesh(input, options, selectedWithout).ok());
  CHECK(cgmesh_test::identicalResults(selected, selectedWithout));
}

// A tet's corners as coordinates, in lexicographic order: the same key in two meshes whatever
// their point numbering.
std::array<double, 12> cornerKey(const TetMesh& mesh, const Tet& tet)
{
  std::array<std::array<double, 3>, 4> corners;
  for (int k = 0; k < 4; ++k)
  {
    std::copy_n(mesh.point(tet[k]), 3, corners[k].begin());
  }
  std::sort(corners.begin(), corners.end());
  std::array<double, 12> key;
  for (int k = 0; k < 4; ++k)
  {
    std::copy(corners[k].begin(), corners[k].end(), key.begin() + 3 * k);
  }
  return key;
}

// A refinement selection promises the tets outside it change only where refinement's closure
// templates split them, and improvement keeps it: on the TetGen FinFET (poor tets everywhere),
// every input tet with at most one corner in the selection (so no edge to split) is in the output
// exactly as it was, although poor ones are among them and improvement works inside the
// selection. The output stays valid and the same for 1 and 2 threads.
void test_selection_keeps_the_tets_outside_it()
{
  TetMesh input;
  CHECK(generateFinFetWithTetGen(15000, input).ok());
  // The box: everything below the middle height, written exactly (17 digits) for the option.
  double low = HUGE_VAL, high = -HUGE_VAL;
  for (PointId p = 0; p < input.numberOfPoints(); ++p)
  {
    low = std::min(low, input.point(p)[2]);
    high = std::max(high, input.point(p)[2]);
  }
  const std::array<double, 6> lowerHalf = { -1e9, -1e9, -1e9, 1e9, 1e9, 0.5 * (low + high) };
  std::ostringstream boxText;
  boxText.precision(17);
  for (int k = 0; k < 6; ++k)
  {
    boxText << (k ? "," : "") << lowerHalf[k];
  }
  struct Case
  {
    const char* regions;
    std::string box;
  };
  for (const Case& selection : { Case{ "2", "" }, Case{ "", boxText.str() } })
  {
    AdaptationOptions options;
    options.refinementRegions = selection.regions;
    options.refinementBox = selection.box;
    options.numberOfPartitions = 32;
    options.edgeLengthFactor = 0.5;
    options.numberOfThreads = 1;
    AdaptationResult result;
    CHECK(adaptMesh(input, options, result).ok());
    cgmesh_test::checkValidAndConserving(input, result.mesh);
    CHECK(result.summary.edgeRemovals + result.summary.vertexMoves > 0);

    std::array<double, 6> box;
    const bool byBox = !selection.box.empty();
    if (byBox)
    {
      std::copy(lowerHalf.begin(), lowerHalf.end(), box.begin());
    }
    const std::vector<char> selected =
      byBox ? selectTets(input, {}, &box) : selectTets(input, { 2 }, nullptr);
    std::vector<char> selectedPoint(input.numberOfPoints(), 0);
    for (std::size_t t = 0; t < input.tets.size(); ++t)
    {
      for (PointId p : input.tets[t])
      {
        selectedPoint[p] |= selected[t];
      }
    }
    std::set<std::array<double, 12>> outputTets;
    for (const Tet& tet : result.mesh.tets)
    {
      outputTets.insert(cornerKey(result.mesh, tet));
    }
    int outside = 0, poorOutside = 0, changed = 0;
    for (const Tet& tet : input.tets)
    {
      int selectedCorners = 0;
      for (PointId p : tet)
      {
        selectedCorners += selectedPoint[p];
      }
      if (selectedCorners > 1)
      {
        continue;
      }
      ++outside;
      poorOutside += meanRatio(input.point(tet[0]), input.point(tet[1]), input.point(tet[2]),
                       input.point(tet[3])) < 0.5;
      changed += outputTets.count(cornerKey(input, tet)) == 0;
    }
    std::cout << "selection " << (byBox ? "box " + selection.box : std::string("region 2")) << ": "
              << outside << " input tets outside, " << poorOutside << " of them poor, " << changed
              << " changed; " << result.summary.edgeRemovals << " edge removals\n";
    CHECK(outside > 0 && poorOutside > 0);
    CHECK_EQUAL(changed, 0);

    options.numberOfThreads = 2;
    AdaptationResult parallel;
    CHECK(adaptMesh(input, options, parallel).ok());
    CHECK(cgmesh_test::identicalResults(result, parallel));
  }
}
} // namespace

// Slivers at a vertex that lies on a box face of the first sweep's layout along x and of the
// shifted layout's along y (two boxes per axis over the unit cube: faces at 0.5, then at 0.25 and
// 0.75): both layouts cut its ball and fix it. The third sweep puts the cluster around the work
// left into one box, and the slivers are repaired; everything stays valid.
void test_sweeps_reach_a_vertex_both_layouts_cut()
{
  TetMesh cube;
  CHECK(generateKuhnCube(8, cube).ok());
  PointId cutTwice = -1;
  for (PointId p = 0; p < cube.numberOfPoints(); ++p)
  {
    const double* x = cube.point(p);
    if (std::abs(x[0] - 0.5) < 1e-12 && std::abs(x[1] - 0.25) < 1e-12 &&
      std::abs(x[2] - 0.625) < 1e-12)
    {
      cutTwice = p;
    }
  }
  CHECK(cutTwice >= 0);
  if (cutTwice < 0)
  {
    return;
  }
  AdaptationState state;
  state.coordinates = cube.coordinates;
  state.coordinates[3 * cutTwice + 2] += 0.9 * 0.125; // nearly onto its neighbours: slivers
  state.inputPointCount = cube.numberOfPoints();
  PartitionMesh all;
  all.tets = cube.tets;
  for (CellId t = 0; t < cube.numberOfTets(); ++t)
  {
    all.parentCells.push_back(t);
  }
  state.partitions.push_back(all);
  state.improvementLeft.assign(1, ImprovementLeft());
  auto worstAround = [&]()
  {
    double worst = 1;
    for (const PartitionMesh& partition : state.partitions)
    {
      for (const Tet& tet : partition.tets)
      {
        if (std::find(tet.begin(), tet.end(), cutTwice) != tet.end())
        {
          worst = std::min(worst,
            meanRatio(&state.coordinates[3 * tet[0]], &state.coordinates[3 * tet[1]],
              &state.coordinates[3 * tet[2]], &state.coordinates[3 * tet[3]]));
        }
      }
    }
    return worst;
  };
  const double before = worstAround();
  CHECK(before > 0 && before < 0.3);

  ColorLoopSetup setup;
  setup.threads = 2;
  setup.improve = true;
  const std::vector<char> formerInterface(cube.numberOfPoints(), 1);
  AdaptationOptions options;
  AdaptationSummary summary;
  PhaseReporter reporter([](double, const char*) {});
  CHECK(improveAcrossFormerInterfaces(setup, options, 2, formerInterface, state, summary, reporter)
          .ok());
  CHECK(worstAround() > 0.3);
  TetMesh perturbed = cube, improved;
  perturbed.coordinates = improved.coordinates = state.coordinates;
  for (const PartitionMesh& partition : state.partitions)
  {
    improved.tets.insert(improved.tets.end(), partition.tets.begin(), partition.tets.end());
  }
  cgmesh_test::checkValidAndConserving(perturbed, improved);
}

int main()
{
  test_smoothing_moves_free_vertex_only();
  test_edge_removal_three_to_two();
  test_collapse_only_where_flagged();
  test_size_bound_gives_way_to_mending_slivers();
  test_tets_left_are_those_still_needing_work();
  test_settled_vertices_are_free_ones_that_stayed();
  test_screening_the_listed_tets_finds_all_work();
  test_device_refinement_with_improvement();
  test_improvement_over_several_passes();
  test_input_improved_before_refinement();
  test_selection_keeps_the_tets_outside_it();
  test_sweeps_reach_a_vertex_both_layouts_cut();
  return cgmesh_test::finish("TestQualityImprovement");
}
