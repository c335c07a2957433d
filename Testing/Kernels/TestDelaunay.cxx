// Delaunay refinement through adaptMesh(): conformity, conserved volumes and material interfaces,
// identical output for any thread count and for serialised TetGen calls, the volume bound inside
// partitions, the template fallback when TetGen fails or its worker process dies, new tets'
// parents, and the time a TetGen call may take.
#include "AdaptationDriver.h"
#include "Core/Geometry.h"
#include "Core/ProvisionalIds.h"
#include "CubeGenerator.h"
#include "DelaunayTestSupport.h"
#include "MeshChecks.h"
#include "Refinement/TemplateTable.h"
#include "Refinement/TetGenRefiner.h"
#include "ResultComparison.h"
#include "TestHarness.h"
#include "WorkerPool.h"

#define TETLIBRARY
#include <tetgen.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <set>
#include <stdlib.h>
#include <thread>

using namespace cgmesh;
using cgmesh_test::delaunayOptions;
using cgmesh_test::PartitionSetting;
using cgmesh_test::run;

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
  CHECK(setenv(WorkerPool::KillPartitionsVariable, "3,17,40", 1) == 0);
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
  CHECK(unsetenv(WorkerPool::KillPartitionsVariable) == 0);
}

// An abort while TetGen calls run (here: a worker that hangs on every call, the pool's test hook)
// ends the run at once, not when the calls' time limit would (a worker that hangs uses no
// processor time: ten times the limit on the clock, at least 20 s): the hung worker is
// killed, its partitions counted as no failure, and the front end's hook is only ever called on
// the thread that started the run. At one thread that thread's own call hangs; at two, the other
// thread's, while the calling thread has done its share and waits; at four on a machine of fewer
// cores, threads share workers and may wait for their turn at the hung one.
void test_abort_cuts_tetgen_calls_short()
{
  const TetMesh input = threeRegionCube(8);
  for (int threads : { 1, 2, 4 })
  {
    CHECK(setenv(WorkerPool::StallWorkerVariable, threads == 2 ? "1" : "0", 1) == 0);
    AdaptationOptions options = delaunayOptions(threads, 1);
    const std::thread::id caller = std::this_thread::get_id();
    const auto start = std::chrono::steady_clock::now();
    bool onCaller = true;
    options.abortRequested = [&]
    {
      onCaller = onCaller && std::this_thread::get_id() == caller;
      return std::chrono::steady_clock::now() - start > std::chrono::milliseconds(500);
    };
    AdaptationResult result;
    CHECK(adaptMesh(input, options, result).ok());
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(result.summary.aborted);
    CHECK(result.mesh.tets.empty());
    CHECK(onCaller);
    CHECK(seconds < 8.0);
    CHECK_EQUAL(result.summary.delaunayFallbacks, std::int64_t(0));
    CHECK(result.summary.warnings.empty());
    std::cout << "aborted with hung TetGen workers at " << threads << " thread(s) after " << seconds
              << " s\n";
  }
  CHECK(unsetenv(WorkerPool::StallWorkerVariable) == 0);
}

// The time limit counts the processor time a worker spends on the call, not the time on the
// clock, which the machine's load stretches (the pool's test hooks set every call's limit to 1 s).
// A worker that computes on is stopped once it has used its second: both partitions fall back,
// and the warnings say which time was counted. A worker that hangs without computing is not
// stopped at one second on the clock: the run goes on until its abort, two seconds later.
void test_time_limit_counts_processor_time()
{
  const TetMesh input = threeRegionCube(4);
  CHECK(setenv(WorkerPool::TimeLimitVariable, "1", 1) == 0);
  CHECK(setenv(WorkerPool::SpinWorkerVariable, "0", 1) == 0);
  AdaptationOptions options = delaunayOptions(1, 1);
  options.numberOfPartitions = 2;
  const AdaptationResult result = run(input, options);
  CHECK(unsetenv(WorkerPool::SpinWorkerVariable) == 0);
  cgmesh_test::checkValidAndConserving(input, result.mesh);
  CHECK_EQUAL(result.summary.delaunayFallbacks, std::int64_t(2));
  CHECK_EQUAL(result.summary.warnings.size(), std::size_t(2));
  for (const AdaptationWarning& warning : result.summary.warnings)
  {
    CHECK(warning.text.find(
            "TetGen took longer than 1 s of processor time on this partition and was stopped") !=
      std::string::npos);
  }

  CHECK(setenv(WorkerPool::StallWorkerVariable, "0", 1) == 0);
  const auto start = std::chrono::steady_clock::now();
  options.abortRequested = [&]
  {
    return std::chrono::steady_clock::now() - start > std::chrono::seconds(3);
  };
  AdaptationResult stalled;
  CHECK(adaptMesh(input, options, stalled).ok());
  CHECK(stalled.summary.aborted);
  CHECK_EQUAL(stalled.summary.delaunayFallbacks, std::int64_t(0));
  CHECK(stalled.summary.warnings.empty());
  CHECK(unsetenv(WorkerPool::StallWorkerVariable) == 0);
  CHECK(unsetenv(WorkerPool::TimeLimitVariable) == 0);
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

// TetGen's reply is checked, not trusted: face neighbours that do not name each other back, or
// an interior face reported as hull, send the partition to the next attempt and, when every
// attempt fails, to the template fallback with the reason.
void test_tampered_tetgen_output_is_refused()
{
  TetMesh mesh;
  CHECK(generateKuhnCube(3, mesh).ok());
  const DelaunayParameters parameters{ 0.05 * (1.0 / mesh.numberOfTets()), 2.0, false };
  const PartitionSetting setting(mesh, parameters);
  const RefinementContext& context = setting.context;
  WorkerPool pool(1);

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
      const std::string failure = pool.runTetGen(0, in, switches, out);
      return failure.empty() && out.neighborlist ? tamper(switches, out) : failure;
    };
    CHECK(refinePartitionDelaunay(
      partition, context, PostedSplits(), parameters, runner, refinement, outcome)
            .ok());
    return outcome;
  };

  const DelaunayOutcome untouched =
    refineWith([](const std::string&, tetgenio&) { return std::string(); });
  CHECK(!untouched.fellBack);
  CHECK(!untouched.retried && !untouched.withoutQualityBound);
  CHECK(untouched.tetgenPoints > 0);
  // The call refining given tets to the volume bound caps the points it may add.
  CHECK(calls.size() == 1 && calls[0].find('S') != std::string::npos);
  const long steinerCap = calls.empty() ? 0 : std::atol(calls[0].c_str() + calls[0].find('S') + 1);
  CHECK(steinerCap >= SteinerCapFloor && untouched.tetgenPoints < steinerCap / 2);

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
  // Refined in three orders, then without q, then meshed anew from its kept faces and points.
  CHECK_EQUAL(calls.size(), std::size_t(5));
  CHECK(
    calls.size() == 5 && calls[4].rfind('p', 0) == 0 && calls[4].find('q') != std::string::npos);

  // Refinement fails in every order and without q (as TetGen's cluster of points a rounding
  // apart on non-Delaunay tets does); meshed anew, the partition is TetGen's after all.
  const DelaunayOutcome refinedAnew = refineWith(
    [&](const std::string& switches, tetgenio& out)
    {
      if (switches.rfind('r', 0) == 0)
      {
        openFace(out);
      }
      return std::string();
    });
  CHECK(!refinedAnew.fellBack);
  CHECK(refinedAnew.retried && refinedAnew.remeshed && !refinedAnew.withoutQualityBound);
  CHECK(refinedAnew.tetgenPoints > 0);
  CHECK_EQUAL(calls.size(), std::size_t(5));

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

  // A refining call that adds more than half its cap in points (TetGen inserting one
  // circumcentre again and again into tets that are not Delaunay) ends the refining attempts;
  // the partition is meshed anew at once, and is TetGen's.
  const DelaunayOutcome runaway = refineWith(
    [&](const std::string& switches, tetgenio& out)
    {
      if (switches.rfind('r', 0) != 0)
      {
        return std::string();
      }
      const int added = static_cast<int>(steinerCap / 2) + 1;
      REAL* points = new REAL[3 * (out.numberofpoints + added)];
      std::copy(out.pointlist, out.pointlist + 3 * out.numberofpoints, points);
      for (int k = 0; k < added; ++k)
      {
        std::copy(out.pointlist, out.pointlist + 3, points + 3 * (out.numberofpoints + k));
      }
      delete[] out.pointlist;
      out.pointlist = points;
      out.numberofpoints += added;
      return std::string();
    });
  CHECK(!runaway.fellBack);
  CHECK(runaway.retried && runaway.remeshed && runaway.tetgenPoints > 0);
  CHECK_EQUAL(calls.size(), std::size_t(2));
  CHECK(calls.size() == 2 && calls[0].rfind('r', 0) == 0 && calls[1].rfind('p', 0) == 0);

  // Where meshing anew fails as well, the partition falls back with that call's reason.
  const DelaunayOutcome runawayThenOpen = refineWith(
    [&](const std::string& switches, tetgenio& out)
    {
      if (switches.rfind('r', 0) == 0)
      {
        return std::string(TetGenRunawayReason) + " (as above)";
      }
      openFace(out);
      return std::string();
    });
  CHECK(runawayThenOpen.fellBack);
  CHECK(runawayThenOpen.reason.find("changed the partition boundary") != std::string::npos);
  CHECK_EQUAL(calls.size(), std::size_t(2));

  // A call stopped at the time limit ends the attempts at once.
  const DelaunayOutcome timedOut = refineWith([](const std::string&, tetgenio&)
    { return std::string(TetGenTimeLimitReason) + " 30 s on this partition and was stopped"; });
  CHECK(timedOut.fellBack);
  CHECK(timedOut.reason.rfind(TetGenTimeLimitReason, 0) == 0);
  CHECK_EQUAL(calls.size(), std::size_t(1));
}

} // namespace

// A new tet's parent is an old tet that holds its centroid, wherever the walk to it starts. The
// first attribute TetGen hands back (the old tet a new one descends from) says where walks start:
// replaced by unrelated old tets, it leaves every parent that holds its centroid strictly inside
// as it was; a centroid on a face of two old tets (the Kuhn cube's grid makes a few dozen) may go
// to either.
void test_parents_hold_the_centroids_wherever_walks_start()
{
  TetMesh mesh;
  CHECK(generateKuhnCube(3, mesh).ok());
  const DelaunayParameters parameters{ 0.05 * (1.0 / mesh.numberOfTets()), 2.0, false };
  const PartitionSetting setting(mesh, parameters);
  WorkerPool pool(1);
  struct Refined
  {
    PartitionMesh partition;
    PartitionRefinement refinement;
  };
  auto refine = [&](bool scrambleStarts)
  {
    Refined refined;
    refined.partition.tets = mesh.tets;
    for (CellId t = 0; t < mesh.numberOfTets(); ++t)
    {
      refined.partition.parentCells.push_back(t);
    }
    const TetGenRunner runner = [&](const tetgenio& in, const std::string& switches, tetgenio& out)
    {
      const std::string failure = pool.runTetGen(0, in, switches, out);
      for (int t = 0; failure.empty() && scrambleStarts && t < out.numberoftetrahedra; ++t)
      {
        out.tetrahedronattributelist[static_cast<std::size_t>(t) *
          out.numberoftetrahedronattributes] = (7919 * t) % in.numberoftetrahedra;
      }
      return failure;
    };
    DelaunayOutcome outcome;
    CHECK(refinePartitionDelaunay(refined.partition, setting.context, PostedSplits(), parameters,
      runner, refined.refinement, outcome)
            .ok());
    CHECK(!outcome.fellBack && outcome.tetgenPoints > 0);
    return refined;
  };
  const Refined walked = refine(false);
  const Refined scrambled = refine(true);
  CHECK(walked.partition.tets == scrambled.partition.tets);
  CHECK(walked.partition.parentCells.size() == walked.partition.tets.size());
  CHECK(scrambled.partition.parentCells.size() == walked.partition.tets.size());
  // The smallest barycentric coordinate of tet t's centroid in the parent `refined` gave it.
  auto deepestInParent = [&](const Refined& refined, std::size_t t)
  {
    double centroid[3] = { 0, 0, 0 };
    for (PointId p : walked.partition.tets[t])
    {
      const double* x = pointCoordinates(mesh.coordinates, walked.refinement.newCoordinates, p);
      for (int axis = 0; axis < 3; ++axis)
      {
        centroid[axis] += 0.25 * x[axis];
      }
    }
    const Tet& parent = mesh.tets[static_cast<std::size_t>(refined.partition.parentCells[t])];
    const double* c[4] = { mesh.point(parent[0]), mesh.point(parent[1]), mesh.point(parent[2]),
      mesh.point(parent[3]) };
    const double whole = signedVolume6(c[0], c[1], c[2], c[3]);
    double lowest = 1;
    for (int k = 0; k < 4; ++k)
    {
      const double* q[4] = { c[0], c[1], c[2], c[3] };
      q[k] = centroid;
      lowest = std::min(lowest, signedVolume6(q[0], q[1], q[2], q[3]) / whole);
    }
    return lowest;
  };
  std::size_t onFaces = 0;
  for (std::size_t t = 0; t < walked.partition.tets.size() && t < scrambled.partition.tets.size();
       ++t)
  {
    const double inWalked = deepestInParent(walked, t);
    CHECK(inWalked >= -1e-12);
    CHECK(deepestInParent(scrambled, t) >= -1e-12);
    if (inWalked > 1e-12)
    {
      CHECK(walked.partition.parentCells[t] == scrambled.partition.parentCells[t]);
    }
    else
    {
      ++onFaces;
    }
  }
  CHECK(onFaces < walked.partition.tets.size() / 10);
}

// Without point data, sizes or cell data beyond the regions, nothing TetGen returns is located in
// the old tets: a new tet's parent is the input tet it descends from. The mesh, its regions and
// the partition and colour of every tet are those of the run that locates; some parents differ,
// each of its tet's region; and the output is the same for any thread count.
void test_parents_by_descent_without_cell_data()
{
  const TetMesh input = threeRegionCube(8);
  AdaptationOptions options = delaunayOptions(1, 1);
  options.pointProvenance = false;
  const AdaptationResult located = run(input, options);
  options.cellDataByParent = false;
  const AdaptationResult descended = run(input, options);
  cgmesh_test::checkValidAndConserving(input, descended.mesh);
  CHECK(descended.summary.tetgenPoints > 0);
  CHECK(descended.mesh.tets == located.mesh.tets);
  CHECK(descended.mesh.coordinates == located.mesh.coordinates);
  CHECK(descended.mesh.regions == located.mesh.regions);
  CHECK(descended.partitionOfCell == located.partitionOfCell);
  CHECK(descended.colorOfCell == located.colorOfCell);
  CHECK_EQUAL(descended.parentCell.size(), located.parentCell.size());
  std::size_t differing = 0;
  for (std::size_t t = 0; t < descended.parentCell.size() && t < located.parentCell.size(); ++t)
  {
    CHECK_EQUAL(input.regions[descended.parentCell[t]], descended.mesh.regions[t]);
    differing += descended.parentCell[t] != located.parentCell[t];
  }
  CHECK(differing > 0);
  options.numberOfThreads = 3;
  CHECK(cgmesh_test::identicalResults(descended, run(input, options)));
}

// The processor time a TetGen call may take: with a volume bound on given tets, about 20 times
// what its forecast output takes and at least 2 s; without one (or with sizes per point), 30 s
// plus 2 ms a tet, and for a remeshed partition (no tets) six tets a point.
void test_tetgen_time_limit_follows_the_forecast_output()
{
  tetgenio in;
  in.numberofpoints = 4;
  in.pointlist = new REAL[12]{ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 }; // volume 1/6
  in.numberoftetrahedra = 1;
  in.numberofcorners = 4;
  in.tetrahedronlist = new int[4]{ 0, 1, 2, 3 };
  in.firstnumber = 0;
  CHECK_CLOSE(tetgenTimeLimitSeconds(in, "rYMQnq2a0.001"), 2.0, 1e-12);
  CHECK_CLOSE(tetgenTimeLimitSeconds(in, "rYMQnq2a1e-7"), 5e-5 * (1 + 4.0 / 6.0 / 1e-7), 1e-6);
  CHECK_CLOSE(tetgenTimeLimitSeconds(in, "rYMQnq2"), 30.002, 1e-12);
  CHECK_CLOSE(tetgenTimeLimitSeconds(in, "rYMQnq1000a1e-7m"), 30.002, 1e-12);
  in.numberoftetrahedra = 0;
  CHECK_CLOSE(tetgenTimeLimitSeconds(in, "pAYMQnq2a1e-7"), 30.0 + 0.002 * 24, 1e-12);
}

int main()
{
  test_conforming_and_identical_across_threads();
  test_concurrent_tetgen_matches_serialised_calls();
  test_volume_bound_inside_partitions();
  test_failed_partitions_fall_back_to_templates();
  test_worker_deaths_fall_back_like_failures();
  test_abort_cuts_tetgen_calls_short();
  test_time_limit_counts_processor_time();
  test_bad_delaunay_options_are_refused();
  test_tampered_tetgen_output_is_refused();
  test_parents_hold_the_centroids_wherever_walks_start();
  test_parents_by_descent_without_cell_data();
  test_tetgen_time_limit_follows_the_forecast_output();
  return cgmesh_test::finish("TestDelaunay");
}
