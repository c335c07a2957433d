// Delaunay refinement through adaptMesh(): conformity, conserved volumes and material interfaces,
// identical output for any thread count and for serialised TetGen calls, the volume bound inside
// partitions, and the template fallback when TetGen fails or its worker process dies.
#include "AdaptationDriver.h"
#include "Core/Geometry.h"
#include "Core/TetQuality.h"
#include "CubeGenerator.h"
#include "MeshChecks.h"
#include "Refinement/TemplateTable.h"
#include "Refinement/TetGenRefiner.h"
#include "ResultComparison.h"
#include "TestHarness.h"
#include "TetGenWorkers.h"

#define TETLIBRARY
#include <tetgen.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <stdlib.h>

using namespace cgmesh;

namespace
{

// Three materials: a slab, and the rest cut by the plane x + y = 1.
TetMesh threeRegionCube(int n)
{
  TetMesh mesh;
  CHECK(generateKuhnCube(n, mesh).ok());
  for (const Tet& tet : mesh.tets)
  {
    double centroid[3] = { 0, 0, 0 };
    for (PointId p : tet)
    {
      for (int axis = 0; axis < 3; ++axis)
      {
        centroid[axis] += 0.25 * mesh.point(p)[axis];
      }
    }
    mesh.regions.push_back(centroid[2] < 0.25 ? 10 : (centroid[0] + centroid[1] < 1 ? 20 : 30));
  }
  return mesh;
}

// A block with a cube inside, both materials filled by TetGen with pseudo-random points and no
// quality bound: full of slivers, as unstructured meshes made without one are, while the faces of
// both cubes are good triangles. Region 1 is the block around the inner cube, region 2 the cube.
TetMesh sliverLadenBlock(int pointCount)
{
  tetgenio in, out;
  in.numberofpoints = 16 + pointCount;
  in.pointlist = new REAL[3 * in.numberofpoints];
  std::uint64_t state = 12345;
  for (int i = 0; i < in.numberofpoints; ++i)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      const int corner = (i >> axis) & 1;
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      in.pointlist[3 * i + axis] = i < 8 ? corner
        : i < 16                         ? 0.35 + 0.3 * corner
                                         : static_cast<double>(state >> 11) / 9007199254740992.0;
    }
  }
  // The six faces of each cube, as quadrilaterals of corner indices.
  const int faces[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 },
    { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
  in.numberoffacets = 12;
  in.facetlist = new tetgenio::facet[12];
  for (int f = 0; f < 12; ++f)
  {
    tetgenio::facet& facet = in.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(facet.polygonlist);
    facet.polygonlist[0].numberofvertices = 4;
    facet.polygonlist[0].vertexlist = new int[4];
    for (int k = 0; k < 4; ++k)
    {
      facet.polygonlist[0].vertexlist[k] = faces[f % 6][k] + (f < 6 ? 0 : 8);
    }
  }
  in.numberofregions = 2;
  in.regionlist = new REAL[10]{ 0.1, 0.1, 0.1, 1, -1, 0.5, 0.5, 0.5, 2, -1 };
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

// The share of tets whose smallest dihedral angle is below `degrees`.
double shareBelow(const TetList& tets, const std::vector<double>& coordinates, double degrees)
{
  std::size_t below = 0;
  for (const Tet& tet : tets)
  {
    below += minimumDihedralAngle(coordinates.data() + 3 * tet[0], coordinates.data() + 3 * tet[1],
               coordinates.data() + 3 * tet[2], coordinates.data() + 3 * tet[3]) < degrees;
  }
  return static_cast<double>(below) / static_cast<double>(tets.size());
}

AdaptationOptions delaunayOptions(int threads, int iterations)
{
  AdaptationOptions options;
  options.method = RefinementMethod::Delaunay;
  options.numberOfPartitions = 64;
  options.numberOfThreads = threads;
  options.numberOfIterations = iterations;
  options.volumeFactor = 0.05;
  return options;
}

AdaptationResult run(const TetMesh& input, const AdaptationOptions& options)
{
  AdaptationResult result;
  const Status status = adaptMesh(input, options, result);
  CHECK(status.ok());
  if (!status.ok())
  {
    std::cerr << status.message() << "\n";
  }
  return result;
}

void checkConserved(const TetMesh& input, const AdaptationResult& result)
{
  cgmesh_test::checkValidAndConserving(input, result.mesh);
  CHECK(result.mesh.numberOfTets() > 4 * input.numberOfTets());
  // No edge of rounding-noise length (TetGen can leave such point clusters; they are refused).
  double shortest = HUGE_VAL;
  for (const Tet& tet : result.mesh.tets)
  {
    for (const auto& edge : TetEdgeCorners)
    {
      shortest = std::min(shortest, squaredEdgeLength(result.mesh, tet[edge[0]], tet[edge[1]]));
    }
  }
  CHECK(std::sqrt(shortest) > 1e-6);
  // Point data stays linear: provenance reproduces a linear field at TetGen's points too.
  for (PointId p = 0; p < result.mesh.numberOfPoints(); ++p)
  {
    double interpolated = 0;
    for (std::int64_t k = result.provenance.offsets[p]; k < result.provenance.offsets[p + 1]; ++k)
    {
      const double* source = input.point(result.provenance.sources[k]);
      interpolated += result.provenance.weights[k] * (source[0] - 2 * source[1] + 5 * source[2]);
    }
    const double* point = result.mesh.point(p);
    CHECK_CLOSE(interpolated, point[0] - 2 * point[1] + 5 * point[2], 1e-9);
  }
}

void test_conforming_and_identical_across_threads()
{
  const TetMesh input = threeRegionCube(8);
  for (int iterations : { 1, 2 })
  {
    const AdaptationResult serial = run(input, delaunayOptions(1, iterations));
    checkConserved(input, serial);
    CHECK(serial.summary.tetgenPoints > 0);
    CHECK_EQUAL(serial.summary.delaunayFallbacks, 0);
    const AdaptationResult parallel = run(input, delaunayOptions(3, iterations));
    CHECK(parallel.summary.concurrentTetGen);
    CHECK(cgmesh_test::identicalResults(serial, parallel));
  }
}

// Stress: many overlapping TetGen calls against the same partitions refined one call at a time.
void test_concurrent_tetgen_matches_serialised_calls()
{
  const TetMesh input = threeRegionCube(8);
  AdaptationOptions serialised = delaunayOptions(4, 1);
  serialised.numberOfPartitions = 128;
  serialised.serializeTetGen = true;
  const AdaptationResult reference = run(input, serialised);
  CHECK(!reference.summary.concurrentTetGen);
  AdaptationOptions concurrent = serialised;
  concurrent.serializeTetGen = false;
  for (int repeat = 0; repeat < 2; ++repeat)
  {
    concurrent.numberOfThreads = 2 + 2 * repeat;
    const AdaptationResult result = run(input, concurrent);
    CHECK(result.summary.concurrentTetGen);
    CHECK(cgmesh_test::identicalResults(reference, result));
  }
}

// Points on a surface TetGen had to keep: partition interfaces (points of two partitions), the
// domain boundary and material interfaces.
std::vector<char> constrainedPoints(const AdaptationResult& result)
{
  const TetMesh& mesh = result.mesh;
  std::vector<char> constrained(mesh.numberOfPoints(), 0);
  std::vector<int> partitionOfPoint(mesh.numberOfPoints(), -1);
  std::map<std::array<PointId, 3>, std::vector<std::size_t>> faces;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
  {
    for (PointId p : mesh.tets[t])
    {
      if (partitionOfPoint[p] >= 0 && partitionOfPoint[p] != result.partitionOfCell[t])
      {
        constrained[p] = 1;
      }
      partitionOfPoint[p] = result.partitionOfCell[t];
    }
    for (int skip = 0; skip < 4; ++skip)
    {
      std::array<PointId, 3> face;
      int n = 0;
      for (int i = 0; i < 4; ++i)
      {
        if (i != skip)
        {
          face[n++] = mesh.tets[t][i];
        }
      }
      std::sort(face.begin(), face.end());
      faces[face].push_back(t);
    }
  }
  for (const auto& entry : faces)
  {
    const auto& tets = entry.second;
    if (tets.size() == 1 || mesh.regions[tets[0]] != mesh.regions[tets[1]])
    {
      for (PointId p : entry.first)
      {
        constrained[p] = 1;
      }
    }
  }
  return constrained;
}

// TetGen enforces the volume bound away from the faces it must keep. It may not split those faces
// (switch Y), so it skips a bad tet whose circumcentre encroaches on one: tets near them may
// exceed the bound, and rarely one further in, by a little (the limits below).
void test_volume_bound_inside_partitions()
{
  const TetMesh input = threeRegionCube(8);
  AdaptationOptions options = delaunayOptions(2, 1);
  options.numberOfPartitions = 8; // large partitions: a real interior
  const AdaptationResult result = run(input, options);
  const std::vector<char> constrained = constrainedPoints(result);
  // Grow the constrained point set by `Layers` rings of tets.
  constexpr int Layers = 1;
  std::vector<char> nearConstrained = constrained;
  for (int layer = 0; layer < Layers; ++layer)
  {
    const std::vector<char> reached = nearConstrained;
    for (const Tet& tet : result.mesh.tets)
    {
      if (reached[tet[0]] || reached[tet[1]] || reached[tet[2]] || reached[tet[3]])
      {
        for (PointId p : tet)
        {
          nearConstrained[p] = 1;
        }
      }
    }
  }
  std::int64_t interior = 0, interiorAbove = 0, atInterface = 0, interfaceAbove = 0;
  double worstInteriorRatio = 0;
  for (const Tet& tet : result.mesh.tets)
  {
    const bool touchesInterface = nearConstrained[tet[0]] || nearConstrained[tet[1]] ||
      nearConstrained[tet[2]] || nearConstrained[tet[3]];
    const bool above =
      signedVolume6(result.mesh, tet) / 6.0 > result.summary.plan.volumeBound * (1 + 1e-9);
    (touchesInterface ? atInterface : interior) += 1;
    (touchesInterface ? interfaceAbove : interiorAbove) += above;
    if (!touchesInterface)
    {
      worstInteriorRatio = std::max(worstInteriorRatio,
        signedVolume6(result.mesh, tet) / 6.0 / result.summary.plan.volumeBound);
    }
  }
  std::cout << "tets above the volume bound: " << interiorAbove << " of " << interior
            << " inside partitions, " << interfaceAbove << " of " << atInterface
            << " within one layer of interfaces, boundaries or material interfaces; largest "
            << "interior volume / bound " << worstInteriorRatio << "\n";
  CHECK_EQUAL(result.summary.delaunayFallbacks, 0);
  CHECK(interior > result.mesh.numberOfTets() / 20);
  CHECK(interiorAbove * 1000 <= interior);
  CHECK(worstInteriorRatio <= 1.25);
}

void test_failed_partitions_fall_back_to_templates()
{
  const TetMesh input = threeRegionCube(8);
  AdaptationOptions options = delaunayOptions(2, 2);
  options.simulateTetGenFailureIn = { 0, 7 };
  const AdaptationResult result = run(input, options);
  checkConserved(input, result);
  CHECK_EQUAL(result.summary.delaunayFallbacks, 4);
  CHECK((std::multiset<int>(result.summary.fallbackPartitions.begin(),
           result.summary.fallbackPartitions.end()) == std::multiset<int>{ 0, 0, 7, 7 }));
  int namingWarnings = 0;
  for (const AdaptationWarning& warning : result.summary.warnings)
  {
    CHECK(warning.kind == WarningKind::DelaunayFallback);
    namingWarnings += (warning.partition == 0 && warning.text.rfind("partition 0:", 0) == 0) ||
      (warning.partition == 7 && warning.text.rfind("partition 7:", 0) == 0);
  }
  CHECK_EQUAL(namingWarnings, 4);
  options.numberOfThreads = 1;
  CHECK(cgmesh_test::identicalResults(result, run(input, options)));
}

// Worker processes killed on chosen partitions (the pool's test hook): the call and its retry
// die, the partitions fall back exactly as after a TetGen error, and the replaced workers refine
// every other partition, so the result equals that of simulated failures on the same partitions.
void test_worker_deaths_fall_back_like_failures()
{
  const TetMesh input = threeRegionCube(8);
  AdaptationOptions simulated = delaunayOptions(2, 1);
  simulated.simulateTetGenFailureIn = { 3, 17, 40 };
  const AdaptationResult reference = run(input, simulated);
  CHECK(setenv(TetGenWorkerPool::KillPartitionsVariable, "3,17,40", 1) == 0);
  for (int threads : { 2, 4 })
  {
    const AdaptationResult result = run(input, delaunayOptions(threads, 1));
    CHECK(cgmesh_test::identicalResults(reference, result));
    CHECK((std::multiset<int>(result.summary.fallbackPartitions.begin(),
             result.summary.fallbackPartitions.end()) == std::multiset<int>{ 3, 17, 40 }));
    // The simulated failures never call TetGen; each death is retried once, and dies again.
    CHECK_EQUAL(result.summary.tetgenRetries, reference.summary.tetgenRetries + 3);
    CHECK_EQUAL(result.summary.tetgenPoints, reference.summary.tetgenPoints);
    for (const AdaptationWarning& warning : result.summary.warnings)
    {
      // The spawner's wait status names how the worker ended.
      CHECK(warning.text.find("the TetGen process stopped unexpectedly (TetGen aborted on this "
                              "partition, SIGABRT)") != std::string::npos);
    }
  }
  CHECK(unsetenv(TetGenWorkerPool::KillPartitionsVariable) == 0);
}

void test_bad_delaunay_options_are_refused()
{
  const TetMesh input = threeRegionCube(2);
  AdaptationOptions options = delaunayOptions(1, 1);
  options.volumeFactor = 0;
  AdaptationResult result;
  CHECK(!adaptMesh(input, options, result).ok());
  options = delaunayOptions(1, 1);
  options.radiusEdgeRatio = 0.5;
  CHECK(!adaptMesh(input, options, result).ok());
}

// What refinePartitionDelaunay() needs of a whole mesh handed over as one partition: no interface
// vertices, the templates, and the interface length of the volume bound.
struct PartitionSetting
{
  PartitionSetting(const TetMesh& mesh, const DelaunayParameters& parameters)
    : interfaceVertex(mesh.numberOfPoints(), 0)
  {
    context.coordinates = &mesh.coordinates;
    context.interfaceVertex = &this->interfaceVertex;
    context.templates = &this->templates;
    const double interfaceLength = interfaceEdgeLengthForVolume(parameters.maximumVolume);
    context.squaredThreshold = interfaceLength * interfaceLength;
  }
  PartitionSetting(const PartitionSetting&) = delete;

  const TemplateTable templates;
  const std::vector<char> interfaceVertex;
  RefinementContext context;
};

// TetGen's reply is checked, not trusted: face neighbours that do not name each other back, or
// an interior face reported as hull, send the partition to the template fallback with the reason.
void test_tampered_tetgen_output_is_refused()
{
  TetMesh mesh;
  CHECK(generateKuhnCube(3, mesh).ok());
  const DelaunayParameters parameters{ 0.05 * (1.0 / mesh.numberOfTets()), 2.0, false };
  const PartitionSetting setting(mesh, parameters);
  const RefinementContext& context = setting.context;
  TetGenWorkerPool pool(1);

  // `tamper` sees each TetGen call's switches and successful output; a reason it returns stands
  // for a failed call.
  std::vector<std::string> calls;
  auto refineWith = [&](const std::function<std::string(const std::string&, tetgenio&)>& tamper)
  {
    PartitionMesh partition;
    partition.tets = mesh.tets;
    for (CellId t = 0; t < mesh.numberOfTets(); ++t)
    {
      partition.parentCells.push_back(t);
    }
    PartitionRefinement refinement;
    DelaunayOutcome outcome;
    calls.clear();
    const TetGenRunner runner = [&](const tetgenio& in, const std::string& switches, tetgenio& out)
    {
      calls.push_back(switches);
      const std::string failure = pool.run(0, in, switches, out);
      return failure.empty() && out.neighborlist ? tamper(switches, out) : failure;
    };
    CHECK(refinePartitionDelaunay(
      partition, context, EdgeMidpointMap(), parameters, runner, refinement, outcome)
            .ok());
    return outcome;
  };

  const DelaunayOutcome untouched =
    refineWith([](const std::string&, tetgenio&) { return std::string(); });
  CHECK(!untouched.fellBack);
  CHECK(!untouched.retried && !untouched.withoutQualityBound);
  CHECK(untouched.tetgenPoints > 0);

  // Tet 0 names a tet that does not name it back.
  const DelaunayOutcome oneSided = refineWith(
    [](const std::string&, tetgenio& out)
    {
      for (int slot = 0; slot < 4; ++slot)
      {
        const int n = out.neighborlist[slot];
        if (n >= 0)
        {
          int* back = out.neighborlist + 4 * n;
          std::replace(back, back + 4, 0, -1);
          break;
        }
      }
      return std::string();
    });
  CHECK(oneSided.fellBack);
  CHECK(oneSided.reason.find("inconsistent face neighbours") != std::string::npos);

  // An interior face reported as hull on both sides: the boundary no longer matches, as when
  // TetGen flips a kept face.
  const auto openFace = [](tetgenio& out)
  {
    for (int slot = 0; slot < 4; ++slot)
    {
      const int n = out.neighborlist[slot];
      if (n >= 0)
      {
        out.neighborlist[slot] = -1;
        int* back = out.neighborlist + 4 * n;
        std::replace(back, back + 4, 0, -1);
        break;
      }
    }
  };
  const DelaunayOutcome opened = refineWith(
    [&](const std::string&, tetgenio& out)
    {
      openFace(out);
      return std::string();
    });
  CHECK(opened.fellBack);
  CHECK(opened.reason.find("changed the partition boundary") != std::string::npos);
  CHECK_EQUAL(calls.size(), std::size_t(4));

  // Flips under the radius-edge bound only (what sliver-laden partitions show): three attempts
  // with q fail, the fourth, without q, refines the partition.
  const DelaunayOutcome flippedUnderQ = refineWith(
    [&](const std::string& switches, tetgenio& out)
    {
      if (switches.find('q') != std::string::npos)
      {
        openFace(out);
      }
      return std::string();
    });
  CHECK(!flippedUnderQ.fellBack);
  CHECK(flippedUnderQ.retried && flippedUnderQ.withoutQualityBound);
  CHECK(flippedUnderQ.tetgenPoints > 0);
  CHECK_EQUAL(calls.size(), std::size_t(4));
  CHECK(calls.size() == 4 && calls[3].find('q') == std::string::npos &&
    calls[3].find('a') != std::string::npos);

  // A call stopped at the time limit ends the attempts at once.
  const DelaunayOutcome timedOut = refineWith([](const std::string&, tetgenio&)
    { return std::string(TetGenTimeLimitReason) + " 30 s on this partition and was stopped"; });
  CHECK(timedOut.fellBack);
  CHECK(timedOut.reason.rfind(TetGenTimeLimitReason, 0) == 0);
  CHECK_EQUAL(calls.size(), std::size_t(1));
}

// The sliver-laden block without its inner cube (region 2): a partition around a cavity of others.
PartitionMesh partitionAroundCavity(const TetMesh& mesh)
{
  PartitionMesh partition;
  for (CellId t = 0; t < mesh.numberOfTets(); ++t)
  {
    if (mesh.regions[t] != 2)
    {
      partition.tets.push_back(mesh.tets[t]);
      partition.regions.push_back(mesh.regions[t]);
      partition.parentCells.push_back(t);
    }
  }
  return partition;
}

// A TetGen runner in one worker that checks each call meshes anew (switches starting pA).
TetGenRunner remeshingRunner(TetGenWorkerPool& pool)
{
  return [&pool](const tetgenio& in, const std::string& switches, tetgenio& out)
  {
    CHECK(switches.rfind("pA", 0) == 0);
    return pool.run(0, in, switches, out);
  };
}

// A partition full of slivers is meshed anew from its kept faces and points (switch p), not
// refined (switch r): TetGen cannot split a kept face, and refining slivers that rest on them
// costs it minutes and leaves worse ones. The partition encloses a cavity (tets of other
// partitions), which TetGen fills too: those tets and their points must not come back.
void test_sliver_laden_partition_is_meshed_anew_around_a_cavity()
{
  const TetMesh mesh = sliverLadenBlock(1500);
  CHECK(shareBelow(mesh.tets, mesh.coordinates, RemeshSliverDegrees) > 10 * RemeshSliverShare);
  PartitionMesh partition = partitionAroundCavity(mesh);
  double cavityVolume = 0;
  std::map<int, double> volumeOfRegion;
  for (CellId t = 0; t < mesh.numberOfTets(); ++t)
  {
    const double volume = signedVolume6(mesh, mesh.tets[t]) / 6.0;
    (mesh.regions[t] == 2 ? cavityVolume : volumeOfRegion[mesh.regions[t]]) += volume;
  }
  CHECK(cavityVolume > 0.01);
  const DelaunayParameters parameters{ 0.5 / mesh.numberOfTets(), 2.0, false };
  const PartitionSetting setting(mesh, parameters);
  const RefinementContext& context = setting.context;
  TetGenWorkerPool pool(1);
  const TetGenRunner runner = remeshingRunner(pool);
  PartitionRefinement refinement;
  DelaunayOutcome outcome;
  const std::size_t inputTets = partition.tets.size();
  CHECK(refinePartitionDelaunay(
    partition, context, EdgeMidpointMap(), parameters, runner, refinement, outcome)
          .ok());
  CHECK(outcome.remeshed && !outcome.fellBack);
  CHECK(partition.tets.size() > 2 * inputTets);

  // Every point is the input's or one TetGen inserted and a tet uses; the cavity stays empty.
  std::vector<double> coordinates = mesh.coordinates;
  coordinates.insert(
    coordinates.end(), refinement.newCoordinates.begin(), refinement.newCoordinates.end());
  const auto globalOf = [&mesh](PointId p)
  {
    return p >= 0 ? p : mesh.numberOfPoints() - p - 1;
  };
  std::vector<char> used(coordinates.size() / 3, 0);
  std::map<int, double> volumeAfter;
  TetList tets;
  for (std::size_t t = 0; t < partition.tets.size(); ++t)
  {
    Tet tet;
    for (int k = 0; k < 4; ++k)
    {
      tet[k] = globalOf(partition.tets[t][k]);
      used[tet[k]] = 1;
    }
    const double volume =
      signedVolume6(coordinates.data() + 3 * tet[0], coordinates.data() + 3 * tet[1],
        coordinates.data() + 3 * tet[2], coordinates.data() + 3 * tet[3]);
    CHECK(volume > 0);
    volumeAfter[partition.regions[t]] += volume / 6.0;
    tets.push_back(tet);
  }
  CHECK(std::count(used.begin() + mesh.numberOfPoints(), used.end(), 0) == 0);
  CHECK_EQUAL(refinement.newPointSources.size(), refinement.newCoordinates.size() / 3);
  CHECK_EQUAL(volumeAfter.size(), volumeOfRegion.size());
  for (const auto& region : volumeOfRegion)
  {
    CHECK_CLOSE(volumeAfter[region.first], region.second, 1e-12);
  }
  // Meshed anew, the partition holds far fewer slivers than it was given.
  const double before = shareBelow(mesh.tets, mesh.coordinates, RemeshSliverDegrees);
  const double after = shareBelow(tets, coordinates, RemeshSliverDegrees);
  std::cout << "share of tets under " << RemeshSliverDegrees << " degrees: " << before
            << " before, " << after << " after\n";
  CHECK(after < 0.25 * before);
}

// The whole method on a sliver-laden two-material mesh: conforming, conserving, the same for any
// thread count, and its partitions meshed anew.
void test_sliver_laden_mesh_conforms_across_threads()
{
  const TetMesh input = sliverLadenBlock(1500);
  AdaptationOptions options = delaunayOptions(1, 1);
  options.numberOfPartitions = 8;
  options.volumeFactor = 0.5;
  options.improveInput = false; // refined as given (see the next test)
  const AdaptationResult serial = run(input, options);
  cgmesh_test::checkValidAndConserving(input, serial.mesh);
  CHECK(serial.summary.tetgenRemeshed > 0);
  CHECK(serial.mesh.numberOfTets() > 2 * input.numberOfTets());
  std::cout << "sliver-laden block: " << serial.summary.tetgenRemeshed << " of "
            << options.numberOfPartitions << " partitions meshed anew, "
            << serial.summary.delaunayFallbacks << " fallbacks\n";
  options.numberOfThreads = 2;
  CHECK(cgmesh_test::identicalResults(serial, run(input, options)));

  // The sweep across former interfaces meshed its boxes anew without the points refinement had
  // crowded there: the slivers those made are gone, and no point is left over but those.
  CHECK(serial.summary.sweepRemeshedBoxes > 0 && serial.summary.sweepDroppedPoints > 0);
  CHECK_EQUAL(serial.summary.sweepRemeshFailures, std::int64_t(0));
  CHECK(std::none_of(serial.summary.warnings.begin(), serial.summary.warnings.end(),
    [](const AdaptationWarning& warning)
    { return warning.kind == WarningKind::UnusedPointsRemoved; }));
  options.numberOfThreads = 1;
  options.remeshAcrossFormerInterfaces = false;
  const AdaptationResult unswept = run(input, options);
  CHECK_EQUAL(unswept.summary.sweepRemeshedBoxes, std::int64_t(0));
  const double sliversAfterSweep = shareBelow(serial.mesh.tets, serial.mesh.coordinates, 1.0);
  const double sliversWithout = shareBelow(unswept.mesh.tets, unswept.mesh.coordinates, 1.0);
  std::cout << "share of output tets under 1 degree: " << sliversAfterSweep << " with the sweep ("
            << serial.summary.sweepRemeshedBoxes << " boxes, " << serial.summary.sweepDroppedPoints
            << " points dropped), " << sliversWithout << " without\n";
  CHECK(sliversAfterSweep < 0.25 * sliversWithout);
}

// With ImproveInput, a sliver-laden input is meshed anew before it is refined: its interface
// rounds first, then TetGen on the clusters of its slivers with the radius-edge bound alone, then
// improvement. Refinement's partitions then hold TetGen's tets, not the input's slivers: fewer of
// them are meshed anew, and the output is conforming, conserving and the same for any thread
// count, with no point left over but those the clusters dropped.
void test_sliver_laden_input_is_meshed_anew_first()
{
  const TetMesh input = sliverLadenBlock(1500);
  AdaptationOptions options = delaunayOptions(1, 1);
  options.numberOfPartitions = 8;
  options.volumeFactor = 0.5;
  options.improveQuality = true;
  options.improveInput = false;
  const AdaptationResult refinedAsGiven = run(input, options);
  options.improveInput = true;
  const AdaptationResult serial = run(input, options);
  cgmesh_test::checkValidAndConserving(input, serial.mesh);
  CHECK(serial.summary.inputRemeshedBoxes > 0 && serial.summary.inputDroppedPoints > 0);
  CHECK_EQUAL(serial.summary.inputRemeshFailures, std::int64_t(0));
  CHECK_EQUAL(serial.summary.delaunayFallbacks, std::int64_t(0));
  CHECK(std::none_of(serial.summary.warnings.begin(), serial.summary.warnings.end(),
    [](const AdaptationWarning& warning)
    { return warning.kind == WarningKind::UnusedPointsRemoved; }));
  CHECK(serial.summary.tetgenRemeshed < refinedAsGiven.summary.tetgenRemeshed);
  CHECK_EQUAL(refinedAsGiven.summary.inputRemeshedBoxes, std::int64_t(0));
  const double under = shareBelow(serial.mesh.tets, serial.mesh.coordinates, 1.0);
  const double underAsGiven =
    shareBelow(refinedAsGiven.mesh.tets, refinedAsGiven.mesh.coordinates, 1.0);
  std::cout << "sliver-laden block meshed anew first: " << serial.summary.inputRemeshedBoxes
            << " clusters (" << serial.summary.inputDroppedPoints << " points dropped), "
            << serial.summary.tetgenRemeshed << " partitions meshed anew in refinement (against "
            << refinedAsGiven.summary.tetgenRemeshed << "), share of output tets under 1 degree "
            << under << " (against " << underAsGiven << ")\n";
  CHECK(under <= underAsGiven);
  options.numberOfThreads = 2;
  CHECK(cgmesh_test::identicalResults(serial, run(input, options)));
}

// The sweep's kernel: a partition meshed anew from its kept faces drops exactly its interior
// points from `firstDroppablePoint` on, keeps every other point, its region volumes and the cavity
// of other partitions it encloses.
void test_sweep_box_drops_only_interior_points_refinement_made()
{
  const TetMesh mesh = sliverLadenBlock(1500);
  const PartitionMesh partition = partitionAroundCavity(mesh);
  // The points of kept faces, found here on their own: faces of one tet of the partition, or of
  // two tets of different regions.
  std::map<std::array<PointId, 3>, std::vector<std::size_t>> tetsOfFace;
  for (std::size_t t = 0; t < partition.tets.size(); ++t)
  {
    for (int skip = 0; skip < 4; ++skip)
    {
      std::array<PointId, 3> face;
      for (int k = 0, n = 0; k < 4; ++k)
      {
        if (k != skip)
        {
          face[n++] = partition.tets[t][k];
        }
      }
      std::sort(face.begin(), face.end());
      tetsOfFace[face].push_back(t);
    }
  }
  std::vector<char> onKeptFace(mesh.numberOfPoints(), 0), inPartition(mesh.numberOfPoints(), 0);
  for (const auto& entry : tetsOfFace)
  {
    const std::vector<std::size_t>& owners = entry.second;
    if (owners.size() == 1 || partition.regions[owners[0]] != partition.regions[owners[1]])
    {
      for (PointId p : entry.first)
      {
        onKeptFace[p] = 1;
      }
    }
  }
  for (const Tet& tet : partition.tets)
  {
    for (PointId p : tet)
    {
      inPartition[p] = 1;
    }
  }
  const PointId firstDroppable = mesh.numberOfPoints() / 2; // as if refinement made the rest
  std::int64_t droppable = 0;
  for (PointId p = firstDroppable; p < mesh.numberOfPoints(); ++p)
  {
    droppable += inPartition[p] && !onKeptFace[p];
  }
  CHECK(droppable > 100);

  const DelaunayParameters parameters{ 0.5 / mesh.numberOfTets(), 2.0, false };
  const PartitionSetting setting(mesh, parameters);
  TetGenWorkerPool pool(1);
  const TetGenRunner runner = remeshingRunner(pool);
  PartitionRefinement refinement;
  DelaunayOutcome outcome;
  PartitionMesh remeshed = partition;
  CHECK(remeshPartitionDelaunay(
    remeshed, setting.context, parameters, firstDroppable, runner, refinement, outcome)
          .ok());
  CHECK(outcome.remeshed && !outcome.fellBack);
  CHECK_EQUAL(outcome.droppedPoints, droppable);
  CHECK(refinement.newPointSources.empty() || outcome.tetgenPoints > 0);

  std::vector<char> usedAfter(mesh.numberOfPoints(), 0);
  std::map<int, double> before, after;
  for (std::size_t t = 0; t < partition.tets.size(); ++t)
  {
    before[partition.regions[t]] += signedVolume6(mesh, partition.tets[t]) / 6.0;
  }
  std::vector<double> coordinates = mesh.coordinates;
  coordinates.insert(
    coordinates.end(), refinement.newCoordinates.begin(), refinement.newCoordinates.end());
  for (std::size_t t = 0; t < remeshed.tets.size(); ++t)
  {
    Tet tet;
    for (int k = 0; k < 4; ++k)
    {
      const PointId p = remeshed.tets[t][k];
      tet[k] = p >= 0 ? p : mesh.numberOfPoints() - p - 1;
      if (p >= 0)
      {
        usedAfter[p] = 1;
      }
    }
    const double volume =
      signedVolume6(coordinates.data() + 3 * tet[0], coordinates.data() + 3 * tet[1],
        coordinates.data() + 3 * tet[2], coordinates.data() + 3 * tet[3]);
    CHECK(volume > 0);
    after[remeshed.regions[t]] += volume / 6.0;
  }
  for (PointId p = 0; p < mesh.numberOfPoints(); ++p)
  {
    const bool dropped = p >= firstDroppable && inPartition[p] && !onKeptFace[p];
    CHECK_EQUAL(static_cast<int>(usedAfter[p]), static_cast<int>(inPartition[p] && !dropped));
  }
  CHECK_EQUAL(after.size(), before.size());
  for (const auto& region : before)
  {
    CHECK_CLOSE(after[region.first], region.second, 1e-12);
  }

  // A failed call leaves the partition as it was.
  PartitionMesh kept = partition;
  PartitionRefinement untouched;
  DelaunayOutcome failed;
  CHECK(remeshPartitionDelaunay(
    kept, setting.context, parameters, firstDroppable,
    [](const tetgenio&, const std::string&, tetgenio&) { return std::string("refused"); },
    untouched, failed)
          .ok());
  CHECK(failed.fellBack && failed.reason == "refused" && !failed.remeshed);
  CHECK(kept.tets == partition.tets && untouched.newCoordinates.empty());
}

} // namespace

int main()
{
  test_conforming_and_identical_across_threads();
  test_concurrent_tetgen_matches_serialised_calls();
  test_volume_bound_inside_partitions();
  test_failed_partitions_fall_back_to_templates();
  test_worker_deaths_fall_back_like_failures();
  test_bad_delaunay_options_are_refused();
  test_tampered_tetgen_output_is_refused();
  test_sliver_laden_partition_is_meshed_anew_around_a_cavity();
  test_sliver_laden_mesh_conforms_across_threads();
  test_sliver_laden_input_is_meshed_anew_first();
  test_sweep_box_drops_only_interior_points_refinement_made();
  return cgmesh_test::finish("TestDelaunay");
}
