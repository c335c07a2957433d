// Delaunay refinement of sliver-laden meshes: a partition full of slivers meshed anew around a
// cavity, the whole method on a sliver-laden two-material block (conforming, conserving, the same
// for any thread count, with and without the sweep across former interfaces, and with the input
// meshed anew first), the whole mesh meshed anew with its boundary free, and the sweep's kernel
// dropping only the interior points refinement made.
#include "AdaptationDriver.h"
#include "AdaptationPlan.h"
#include "Core/Geometry.h"
#include "Core/TetQuality.h"
#include "DelaunayTestSupport.h"
#include "MeshChecks.h"
#include "Refinement/TetGenRefiner.h"
#include "ResultComparison.h"
#include "SliverLadenMeshes.h"
#include "TestHarness.h"
#include "WorkerPool.h"

#define TETLIBRARY
#include <tetgen.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

using namespace cgmesh;
using cgmesh_test::delaunayOptions;
using cgmesh_test::PartitionSetting;
using cgmesh_test::run;
using cgmesh_test::shareBelow;
using cgmesh_test::sliverLadenBlock;
using cgmesh_test::sliverLadenFinOnBlock;

namespace
{

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

// The kept faces of `tets` (corners sorted): faces of one tet, and faces between two regions.
std::vector<std::array<PointId, 3>> keptFacesOf(
  const TetList& tets, const std::vector<int>& regions)
{
  std::map<std::array<PointId, 3>, std::vector<std::size_t>> tetsOfFace;
  for (std::size_t t = 0; t < tets.size(); ++t)
  {
    for (int skip = 0; skip < 4; ++skip)
    {
      std::array<PointId, 3> face;
      for (int k = 0, n = 0; k < 4; ++k)
      {
        if (k != skip)
        {
          face[n++] = tets[t][k];
        }
      }
      std::sort(face.begin(), face.end());
      tetsOfFace[face].push_back(t);
    }
  }
  std::vector<std::array<PointId, 3>> kept;
  for (const auto& [face, owners] : tetsOfFace)
  {
    if (owners.size() == 1 || regions[owners[0]] != regions[owners[1]])
    {
      kept.push_back(face);
    }
  }
  return kept;
}

// The total area of the kept faces of `tets` and how many of them have a corner at or after
// `firstNewPoint`.
double keptFaceArea(const TetList& tets, const std::vector<int>& regions,
  const std::vector<double>& xyz, PointId firstNewPoint, std::size_t& facesWithNewPoints)
{
  double area = 0;
  facesWithNewPoints = 0;
  for (const auto& face : keptFacesOf(tets, regions))
  {
    area +=
      triangleArea(xyz.data() + 3 * face[0], xyz.data() + 3 * face[1], xyz.data() + 3 * face[2]);
    facesWithNewPoints += face[2] >= firstNewPoint ? 1 : 0;
  }
  return area;
}

// The smallest angle, in degrees, of a triangle among the kept faces of `tets`.
double smallestKeptFaceAngle(
  const TetList& tets, const std::vector<int>& regions, const std::vector<double>& xyz)
{
  double smallest = 180;
  for (const auto& face : keptFacesOf(tets, regions))
  {
    for (int k = 0; k < 3; ++k)
    {
      const double* apex = xyz.data() + 3 * face[k];
      const double* b = xyz.data() + 3 * face[(k + 1) % 3];
      const double* c = xyz.data() + 3 * face[(k + 2) % 3];
      const double u[3] = { b[0] - apex[0], b[1] - apex[1], b[2] - apex[2] };
      const double v[3] = { c[0] - apex[0], c[1] - apex[1], c[2] - apex[2] };
      const double cosine = (u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) /
        std::sqrt(
          (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
      smallest = std::min(smallest, std::acos(std::max(-1.0, std::min(1.0, cosine))) * 180 / M_PI);
    }
  }
  return smallest;
}

// The smallest dihedral angle of `tets`, in degrees.
double smallestDihedralAngle(const TetList& tets, const std::vector<double>& xyz)
{
  double smallest = 180;
  for (const Tet& tet : tets)
  {
    smallest = std::min(smallest,
      minimumDihedralAngle(xyz.data() + 3 * tet[0], xyz.data() + 3 * tet[1],
        xyz.data() + 3 * tet[2], xyz.data() + 3 * tet[3]));
  }
  return smallest;
}

// One partition holding the whole mesh, its tets' parents their own ids.
PartitionMesh wholeMeshAsPartition(const TetMesh& mesh)
{
  PartitionMesh whole;
  for (CellId t = 0; t < mesh.numberOfTets(); ++t)
  {
    whole.tets.push_back(mesh.tets[t]);
    whole.regions.push_back(mesh.regions[t]);
    whole.parentCells.push_back(t);
  }
  return whole;
}

// A partition TetGen gave back, in global ids over the mesh's points followed by the new ones,
// with its volume per region; checks that every tet is positive.
struct GlobalPartition
{
  std::vector<double> coordinates;
  TetList tets;
  std::map<int, double> volumeOfRegion;
};

GlobalPartition inGlobalIds(
  const TetMesh& mesh, const PartitionMesh& partition, const PartitionRefinement& refinement)
{
  GlobalPartition global;
  global.coordinates = mesh.coordinates;
  global.coordinates.insert(
    global.coordinates.end(), refinement.newCoordinates.begin(), refinement.newCoordinates.end());
  const double* xyz = global.coordinates.data();
  for (std::size_t t = 0; t < partition.tets.size(); ++t)
  {
    Tet tet;
    for (int k = 0; k < 4; ++k)
    {
      const PointId p = partition.tets[t][k];
      tet[k] = p >= 0 ? p : mesh.numberOfPoints() - p - 1;
    }
    const double volume =
      signedVolume6(xyz + 3 * tet[0], xyz + 3 * tet[1], xyz + 3 * tet[2], xyz + 3 * tet[3]);
    CHECK(volume > 0);
    global.volumeOfRegion[partition.regions[t]] += volume / 6.0;
    global.tets.push_back(tet);
  }
  return global;
}

// A TetGen runner in one worker that checks each call meshes anew (switches starting pA).
TetGenRunner remeshingRunner(WorkerPool& pool)
{
  return [&pool](const tetgenio& in, const std::string& switches, tetgenio& out)
  {
    CHECK(switches.rfind("pA", 0) == 0);
    return pool.runTetGen(0, in, switches, out);
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
  WorkerPool pool(1);
  const TetGenRunner runner = remeshingRunner(pool);
  PartitionRefinement refinement;
  DelaunayOutcome outcome;
  const std::size_t inputTets = partition.tets.size();
  CHECK(refinePartitionDelaunay(
    partition, context, PostedSplits(), parameters, runner, refinement, outcome)
          .ok());
  CHECK(outcome.remeshed && !outcome.fellBack);
  CHECK(partition.tets.size() > 2 * inputTets);

  // Every point is the input's or one TetGen inserted and a tet uses; the cavity stays empty.
  GlobalPartition global = inGlobalIds(mesh, partition, refinement);
  std::vector<char> used(global.coordinates.size() / 3, 0);
  for (const Tet& tet : global.tets)
  {
    for (PointId p : tet)
    {
      used[p] = 1;
    }
  }
  CHECK(std::count(used.begin() + mesh.numberOfPoints(), used.end(), 0) == 0);
  CHECK_EQUAL(refinement.newPointSources.size(), refinement.newCoordinates.size() / 3);
  CHECK_EQUAL(global.volumeOfRegion.size(), volumeOfRegion.size());
  for (const auto& region : volumeOfRegion)
  {
    CHECK_CLOSE(global.volumeOfRegion[region.first], region.second, 1e-12);
  }
  // Meshed anew, the partition holds far fewer slivers than it was given.
  const double before = shareBelow(mesh.tets, mesh.coordinates, RemeshSliverDegrees);
  const double after = shareBelow(global.tets, global.coordinates, RemeshSliverDegrees);
  std::cout << "share of tets under " << RemeshSliverDegrees << " degrees: " << before
            << " before, " << after << " after\n";
  CHECK(after < 0.25 * before);
}

// Delaunay on the sliver-laden block at half its mean tet volume, on one thread, improving (the
// input first with `improveInput`: a sliver-laden input is then meshed anew); 0 partitions:
// automatic.
AdaptationOptions sliverLadenBlockOptions(int partitions, bool improveInput)
{
  AdaptationOptions options = delaunayOptions(1, 1);
  options.numberOfPartitions = partitions;
  options.volumeFactor = 0.5;
  options.improveQuality = true;
  options.improveInput = improveInput;
  return options;
}

// The whole method on a sliver-laden two-material mesh: conforming, conserving, the same for any
// thread count, and its partitions meshed anew.
void test_sliver_laden_mesh_conforms_across_threads()
{
  const TetMesh input = sliverLadenBlock(1500);
  // Refined as given (see the next test).
  AdaptationOptions options = sliverLadenBlockOptions(8, false);
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

// How many sliver-laden-input-kept warnings the run gave.
std::size_t keptSliversWarnings(const AdaptationResult& result)
{
  return static_cast<std::size_t>(
    std::count_if(result.summary.warnings.begin(), result.summary.warnings.end(),
      [](const AdaptationWarning& warning)
      { return warning.kind == WarningKind::SliverLadenInputKept; }));
}

// With ImproveInput, a sliver-laden input is meshed anew before it is refined; without, it is
// refined as given and the run warns. Where its boundary may be re-triangulated, as a whole: one
// TetGen call from its boundary and material interface faces, which TetGen may split, and all its
// points, so nothing is dropped. Where the boundary triangulation is kept (tagged triangles,
// pieces across processes): its interface rounds first, then TetGen on the clusters of its
// slivers, which drop the points the rounds put inside them. Either way, refinement's partitions
// then hold TetGen's tets, not the input's slivers (as a whole, at this size, the call refines
// them to the bound too, next test): fewer of them are meshed anew, and the output is
// conforming, conserving and the same for any thread count, with no point left over but those
// the clusters dropped.
void test_sliver_laden_input_is_meshed_anew_first()
{
  const TetMesh input = sliverLadenBlock(1500);
  AdaptationOptions options = sliverLadenBlockOptions(8, false);
  const AdaptationResult refinedAsGiven = run(input, options);
  CHECK_EQUAL(refinedAsGiven.summary.inputRemeshedBoxes, std::int64_t(0));
  // Refined as given, the run says so, why, and what it costs.
  CHECK_EQUAL(keptSliversWarnings(refinedAsGiven), std::size_t(1));
  for (const AdaptationWarning& warning : refinedAsGiven.summary.warnings)
  {
    if (warning.kind == WarningKind::SliverLadenInputKept)
    {
      CHECK(warning.text.find("(ImproveInput is off)") != std::string::npos);
      CHECK(warning.text.find("against the slivers' faces") != std::string::npos);
    }
  }
  const double underAsGiven =
    shareBelow(refinedAsGiven.mesh.tets, refinedAsGiven.mesh.coordinates, 1.0);
  for (bool keepBoundary : { false, true })
  {
    options.improveInput = true;
    options.keepBoundaryTriangulation = keepBoundary;
    options.numberOfThreads = 1;
    const AdaptationResult serial = run(input, options);
    cgmesh_test::checkValidAndConserving(input, serial.mesh);
    if (keepBoundary)
    {
      CHECK(serial.summary.inputRemeshedBoxes > 0 && serial.summary.inputDroppedPoints > 0);
    }
    else
    {
      CHECK_EQUAL(serial.summary.inputRemeshedBoxes, std::int64_t(1));
      CHECK_EQUAL(serial.summary.inputDroppedPoints, std::int64_t(0));
    }
    CHECK_EQUAL(serial.summary.inputRemeshFailures, std::int64_t(0));
    CHECK_EQUAL(serial.summary.delaunayFallbacks, std::int64_t(0));
    CHECK_EQUAL(keptSliversWarnings(serial), std::size_t(0));
    CHECK(std::none_of(serial.summary.warnings.begin(), serial.summary.warnings.end(),
      [](const AdaptationWarning& warning)
      { return warning.kind == WarningKind::UnusedPointsRemoved; }));
    CHECK(serial.summary.tetgenRemeshed < refinedAsGiven.summary.tetgenRemeshed);
    const double under = shareBelow(serial.mesh.tets, serial.mesh.coordinates, 1.0);
    std::cout << "sliver-laden block meshed anew first"
              << (keepBoundary ? " around its slivers, boundary kept: " : " as a whole: ")
              << serial.summary.inputRemeshedBoxes << " boxes ("
              << serial.summary.inputDroppedPoints << " points dropped), "
              << serial.summary.tetgenRemeshed << " partitions meshed anew in refinement (against "
              << refinedAsGiven.summary.tetgenRemeshed << "), " << serial.mesh.tets.size()
              << " tets, share of output tets under 1 degree " << under << " (against "
              << underAsGiven << ")\n";
    CHECK(under <= underAsGiven);
    options.numberOfThreads = 2;
    CHECK(cgmesh_test::identicalResults(serial, run(input, options)));
  }
}

// A small Delaunay run on a sliver-laden input is refined to its volume bound in the one TetGen
// call that meshes the input anew (AdaptationPlan::wholeInputCallRefines); the refinement passes
// then only improve. The output is valid and conserving, meets the bound, is the same at 1 and 2
// threads, and TetGen refined nothing in the partitions. A forecast beyond the fewest automatic
// partitions' share keeps the partitions refining.
void test_small_sliver_laden_input_is_refined_in_one_call()
{
  const TetMesh input = sliverLadenBlock(1500);
  AdaptationOptions options = sliverLadenBlockOptions(0, true);
  std::vector<AdaptationWarning> warnings;
  const AdaptationPlan plan = resolvePlan(input, options, warnings);
  CHECK(plan.wholeInputCallRefines);
  const AdaptationResult serial = run(input, options);
  cgmesh_test::checkValidAndConserving(input, serial.mesh);
  CHECK_EQUAL(serial.summary.inputRemeshedBoxes, std::int64_t(1));
  CHECK_EQUAL(serial.summary.iterationsRun, 1);
  CHECK(serial.summary.refinementConverged);
  // Every input point is kept and every new one is TetGen's: no interface round split an edge.
  CHECK_EQUAL(serial.mesh.numberOfPoints(), input.numberOfPoints() + serial.summary.tetgenPoints);
  CHECK_EQUAL(serial.summary.delaunayFallbacks, std::int64_t(0));
  CHECK(serial.mesh.numberOfTets() > 2 * input.numberOfTets());
  std::size_t overBound = 0;
  for (const Tet& tet : serial.mesh.tets)
  {
    overBound += signedVolume6(serial.mesh, tet) / 6.0 > plan.volumeBound * (1 + 1e-9);
  }
  std::cout << "small sliver-laden block refined in one call: " << input.tets.size() << " tets to "
            << serial.mesh.tets.size() << ", " << overBound << " over the volume bound\n";
  CHECK(overBound * 1000 <= serial.mesh.tets.size()); // TetGen's a: a few per mille at most
  options.numberOfThreads = 2;
  CHECK(cgmesh_test::identicalResults(serial, run(input, options)));

  // Delaunay forecasts 3 x volume / V tets, 3 n / VolumeFactor for n input tets: one call refines
  // up to 240,000 (8 partitions of 30,000). A factor that forecasts 300,000 keeps the partitions
  // refining after the whole input is meshed anew with the radius-edge bound alone: their
  // interface rounds split edges, so not every new point is TetGen's.
  options.volumeFactor = 3.0 * static_cast<double>(input.tets.size()) / 300000.0;
  CHECK(!resolvePlan(input, options, warnings).wholeInputCallRefines);
  options.numberOfThreads = 1;
  const AdaptationResult partitioned = run(input, options);
  cgmesh_test::checkValidAndConserving(input, partitioned.mesh);
  CHECK_EQUAL(partitioned.summary.inputRemeshedBoxes, std::int64_t(1));
  CHECK_EQUAL(partitioned.summary.delaunayFallbacks, std::int64_t(0));
  CHECK(
    partitioned.mesh.numberOfPoints() > input.numberOfPoints() + partitioned.summary.tetgenPoints);
  std::cout << "larger sliver-laden run, partitions refining: " << partitioned.mesh.tets.size()
            << " tets\n";
  options.volumeFactor = 0.5;
  options.improveInput = false; // not meshed anew: refined by the partitions as given
  CHECK(resolvePlan(input, options, warnings).wholeInputCallRefines);
  CHECK_EQUAL(run(input, options).summary.inputRemeshedBoxes, std::int64_t(0));
}

// Meshing the whole mesh anew, as a sliver-laden input is: the radius-edge bound alone, the kept
// faces free to split and merge.
DelaunayParameters wholeMeshParameters()
{
  DelaunayParameters parameters{ 0, 2.0, false };
  parameters.shapesOnly = true;
  parameters.keptFacesMaySplit = true;
  return parameters;
}

// Checks that `remeshed` (`global` in global ids) keeps each region's volume of `mesh` (to 1e-12)
// and the area of its kept faces (to 1e-9 relative); returns how many of its kept faces have a
// corner TetGen added.
std::size_t checkVolumesAndKeptArea(
  const TetMesh& mesh, const PartitionMesh& remeshed, const GlobalPartition& global)
{
  std::map<int, double> before;
  for (CellId t = 0; t < mesh.numberOfTets(); ++t)
  {
    before[mesh.regions[t]] += signedVolume6(mesh, mesh.tets[t]) / 6.0;
  }
  CHECK_EQUAL(global.volumeOfRegion.size(), before.size());
  for (const auto& region : before)
  {
    const auto found = global.volumeOfRegion.find(region.first);
    CHECK(found != global.volumeOfRegion.end());
    if (found != global.volumeOfRegion.end())
    {
      CHECK_CLOSE(found->second, region.second, 1e-12);
    }
  }
  std::size_t facesWithNewPoints = 0;
  const double areaBefore = keptFaceArea(
    mesh.tets, mesh.regions, mesh.coordinates, mesh.numberOfPoints(), facesWithNewPoints);
  const double areaAfter = keptFaceArea(
    global.tets, remeshed.regions, global.coordinates, mesh.numberOfPoints(), facesWithNewPoints);
  CHECK_CLOSE(areaAfter, areaBefore, 1e-9 * areaBefore);
  return facesWithNewPoints;
}

// The whole mesh meshed anew with its kept faces free to split (a sliver-laden input without
// tagged triangles): TetGen is called without Y, splits boundary faces, and the result keeps
// every region's volume and the boundary's area. A result whose new boundary point has left the
// surface is refused, and the mesh stays as it was.
void test_whole_mesh_meshed_anew_with_its_boundary_free()
{
  const TetMesh mesh = sliverLadenBlock(1500);
  const PartitionMesh whole = wholeMeshAsPartition(mesh);
  const DelaunayParameters parameters = wholeMeshParameters();
  const PartitionSetting setting(mesh, parameters);
  WorkerPool pool(1);
  const TetGenRunner runner = [&pool](
                                const tetgenio& in, const std::string& switches, tetgenio& out)
  {
    CHECK(switches[0] == 'p' && switches.find('A') != std::string::npos &&
      switches.find('Y') == std::string::npos && switches.find('M') == std::string::npos);
    return pool.runTetGen(0, in, switches, out);
  };
  PartitionRefinement refinement;
  DelaunayOutcome outcome;
  PartitionMesh remeshed = whole;
  CHECK(remeshPartitionDelaunay(
    remeshed, setting.context, parameters, mesh.numberOfPoints(), runner, refinement, outcome)
          .ok());
  CHECK(outcome.remeshed && !outcome.fellBack);
  CHECK_EQUAL(outcome.droppedPoints, std::int64_t(0));
  const GlobalPartition global = inGlobalIds(mesh, remeshed, refinement);
  const std::size_t facesWithNewPoints = checkVolumesAndKeptArea(mesh, remeshed, global);
  std::cout << "whole block meshed anew, boundary free: " << mesh.tets.size() << " tets to "
            << global.tets.size() << ", " << facesWithNewPoints
            << " boundary and interface faces with a point TetGen added\n";
  CHECK(facesWithNewPoints > 0); // TetGen did split kept faces

  // The same call, its first new point on the block's boundary pushed off it, away from the
  // block's centre (scaled from the origin, a point of a face through it stays in that face).
  const TetGenRunner pushing = [&pool](
                                 const tetgenio& in, const std::string& switches, tetgenio& out)
  {
    const std::string failure = pool.runTetGen(0, in, switches, out);
    for (int t = 0; failure.empty() && t < out.numberoftetrahedra; ++t)
    {
      for (int k = 0; k < 4; ++k)
      {
        const int p = out.tetrahedronlist[4 * t + k];
        if (out.neighborlist[4 * t + (k + 1) % 4] == -1 && p >= in.numberofpoints)
        {
          for (int axis = 0; axis < 3; ++axis)
          {
            double& coordinate = out.pointlist[3 * p + axis];
            coordinate = 0.5 + 1.01 * (coordinate - 0.5);
          }
          return failure;
        }
      }
    }
    return failure;
  };
  PartitionRefinement pushedRefinement;
  DelaunayOutcome pushedOutcome;
  PartitionMesh pushed = whole;
  CHECK(remeshPartitionDelaunay(pushed, setting.context, parameters, mesh.numberOfPoints(), pushing,
    pushedRefinement, pushedOutcome)
          .ok());
  CHECK(pushedOutcome.fellBack && !pushedOutcome.remeshed);
  CHECK(pushedOutcome.reason.rfind("TetGen changed", 0) == 0);
  CHECK(pushed.tets == whole.tets && pushedRefinement.newCoordinates.empty());
}

// Meshed anew as a whole, neighbouring coplanar kept faces become one facet that TetGen
// triangulates anew: the needles of the fin-on-block's flat faces go, where kept face by face
// they could only be split into smaller needles and the tets on them stayed slivers. The
// boundary keeps its area and each region its volume.
void test_whole_mesh_meshed_anew_loses_the_needles_of_flat_faces()
{
  const TetMesh mesh = sliverLadenFinOnBlock(3000);
  const double needleBefore = smallestKeptFaceAngle(mesh.tets, mesh.regions, mesh.coordinates);
  CHECK(needleBefore < 3);
  const DelaunayParameters parameters = wholeMeshParameters();
  const PartitionSetting setting(mesh, parameters);
  WorkerPool pool(1);
  const TetGenRunner runner = [&pool](
                                const tetgenio& in, const std::string& switches, tetgenio& out)
  {
    return pool.runTetGen(0, in, switches, out);
  };
  PartitionMesh remeshed = wholeMeshAsPartition(mesh);
  PartitionRefinement refinement;
  DelaunayOutcome outcome;
  CHECK(remeshPartitionDelaunay(
    remeshed, setting.context, parameters, mesh.numberOfPoints(), runner, refinement, outcome)
          .ok());
  CHECK(outcome.remeshed && !outcome.fellBack);
  const GlobalPartition global = inGlobalIds(mesh, remeshed, refinement);
  checkVolumesAndKeptArea(mesh, remeshed, global);
  const double needleAfter =
    smallestKeptFaceAngle(global.tets, remeshed.regions, global.coordinates);
  const double dihedralBefore = smallestDihedralAngle(mesh.tets, mesh.coordinates);
  const double dihedralAfter = smallestDihedralAngle(global.tets, global.coordinates);
  std::cout << "fin on block meshed anew as a whole: smallest kept face angle " << needleBefore
            << " to " << needleAfter << " degrees, smallest dihedral angle " << dihedralBefore
            << " to " << dihedralAfter << " degrees, " << mesh.tets.size() << " to "
            << global.tets.size() << " tets\n";
  CHECK(needleAfter > 2 * needleBefore);
  CHECK(dihedralAfter > 2 * needleBefore);
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
  std::vector<char> onKeptFace(mesh.numberOfPoints(), 0), inPartition(mesh.numberOfPoints(), 0);
  for (const auto& face : keptFacesOf(partition.tets, partition.regions))
  {
    for (PointId p : face)
    {
      onKeptFace[p] = 1;
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
  WorkerPool pool(1);
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

  std::map<int, double> before;
  for (std::size_t t = 0; t < partition.tets.size(); ++t)
  {
    before[partition.regions[t]] += signedVolume6(mesh, partition.tets[t]) / 6.0;
  }
  GlobalPartition global = inGlobalIds(mesh, remeshed, refinement);
  std::vector<char> usedAfter(mesh.numberOfPoints(), 0);
  for (const Tet& tet : global.tets)
  {
    for (PointId p : tet)
    {
      if (p < mesh.numberOfPoints())
      {
        usedAfter[p] = 1;
      }
    }
  }
  for (PointId p = 0; p < mesh.numberOfPoints(); ++p)
  {
    const bool dropped = p >= firstDroppable && inPartition[p] && !onKeptFace[p];
    CHECK_EQUAL(static_cast<int>(usedAfter[p]), static_cast<int>(inPartition[p] && !dropped));
  }
  CHECK_EQUAL(global.volumeOfRegion.size(), before.size());
  for (const auto& region : before)
  {
    CHECK_CLOSE(global.volumeOfRegion[region.first], region.second, 1e-12);
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
  test_sliver_laden_partition_is_meshed_anew_around_a_cavity();
  test_sliver_laden_mesh_conforms_across_threads();
  test_sliver_laden_input_is_meshed_anew_first();
  test_small_sliver_laden_input_is_refined_in_one_call();
  test_whole_mesh_meshed_anew_with_its_boundary_free();
  test_whole_mesh_meshed_anew_loses_the_needles_of_flat_faces();
  test_sweep_box_drops_only_interior_points_refinement_made();
  return cgmesh_test::finish("TestDelaunaySlivers");
}
