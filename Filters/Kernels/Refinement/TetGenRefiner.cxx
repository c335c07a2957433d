#include "Refinement/TetGenRefiner.h"

#include "Refinement/ConstrainedEdgeSplits.h"
#include "Refinement/SizeField.h"
#include "Refinement/TetGenSession.h"

#include "Core/ConstrainedFaces.h"
#include "Core/FaceKey.h"
#include "Core/Geometry.h"
#include "Core/TetQuality.h"

#define TETLIBRARY
#include <tetgen.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cgmesh
{
namespace
{

// Faces meeting at this dihedral angle or flatter count as coplanar when kept faces may merge:
// exactly coplanar ones do, those of a faceted curved surface (a degree or more apart) stay
// apart. TetGen's own default, 179.9, would flatten a finely faceted surface a little, which
// validation then refuses.
constexpr const char* CoplanarFacetDegrees = "179.9999";

std::string tetgenSwitches(
  const DelaunayParameters& parameters, bool qualityBound, bool sizeField, bool remesh)
{
  // r: refine the given mesh, or p: mesh the kept faces and the points anew, with A: the region
  // attributes from the region list; Y: keep the given boundary and interface faces (unless they
  // may split); M: do not merge coplanar facets (unless the kept faces may split, see
  // mergeCoplanarFaces); Q: quiet; n: return the face neighbours (for validation); q: the
  // radius-edge bound, when asked; a: the volume bound, when there is one; m: the sizes given per
  // point, with a size field.
  std::string switches = remesh
    ? (parameters.keptFacesMaySplit ? "p" + std::string(CoplanarFacetDegrees) + "AQn" : "pAYMQn")
    : "rYMQn";
  char bound[64];
  if (qualityBound)
  {
    std::snprintf(bound, sizeof(bound), "q%.17g", parameters.radiusEdgeRatio);
    switches += bound;
  }
  else if (sizeField)
  {
    // TetGen refines only with q; a radius-edge bound no tet reaches leaves the shapes alone.
    switches += "q1000";
  }
  if (parameters.maximumVolume > 0 && !parameters.shapesOnly)
  {
    std::snprintf(bound, sizeof(bound), "a%.17g", parameters.maximumVolume);
    switches += bound;
  }
  return sizeField ? switches + "m" : switches;
}

// Whether TetGen should mesh the partition anew from its kept faces and points rather than refine
// its tets: when its tets hold many slivers. TetGen cannot split a kept face, and refining a mesh
// whose slivers rest on kept faces costs it minutes and leaves worse slivers (a partition of the
// TetGen mesh of random points in a block: 116 s and min dihedral p1 0.005 degrees when refined,
// 0.9 s and 7.6 degrees when meshed anew). Meshing anew costs about 1.5 times refining on good
// partitions, so it is kept for those that need it.
bool holdsManySlivers(const PartitionMesh& partition, const RefinementContext& context,
  const PartitionRefinement& refinement)
{
  std::int64_t slivers = 0;
  const double ceiling = meanRatioCeiling(RemeshSliverDegrees);
  for (const Tet& tet : partition.tets)
  {
    const double* p[4];
    for (int k = 0; k < 4; ++k)
    {
      p[k] = pointCoordinates(*context.coordinates, refinement.newCoordinates, tet[k]);
    }
    if (minimumDihedralAngleBelow(p[0], p[1], p[2], p[3], RemeshSliverDegrees, ceiling))
    {
      ++slivers;
    }
  }
  return exceedsSliverShare(slivers, partition.tets.size());
}

// Lets TetGen merge neighbouring coplanar kept faces into one facet, which it may then
// triangulate anew (Delaunay flips within the facet) as well as split: only for the whole mesh,
// whose kept faces no other partition shares. Kept as given, each its own facet, a needle
// triangle of a flat boundary can only be split into smaller needles, and every tet on it has a
// dihedral angle as small as the needle's: the benchmark's poor input (a fin on a block, its flat
// faces cut into needles by the fin's footprint) kept 1.9 degrees that way and 6.4 merged, with
// 64 partitions (serial TetGen: 4.7). A single marker is enough: where two kept faces meet with no
// third at their edge, they lie in one region's boundary or one interface, as any other patch or
// region brings a third face to that edge, which TetGen keeps as a segment. Tagged faces get a
// marker per surface class (TetGen merges facets of equal markers only), so that a tag's border
// stays a segment too. Facet f is kept face order.sourceOf(f).
void mergeCoplanarFaces(tetgenio& in, const std::vector<Face>& keptFaces, const TetOrder& order,
  const SurfaceClasses* classes)
{
  for (int f = 0; f < in.numberoffacets; ++f)
  {
    int marker = 1;
    if (classes)
    {
      Face key = keptFaces[order.sourceOf(static_cast<std::size_t>(f))];
      std::sort(key.begin(), key.end());
      const auto found = std::lower_bound(classes->begin(), classes->end(), key,
        [](const std::pair<Face, int>& entry, const Face& face) { return entry.first < face; });
      if (found != classes->end() && found->first == key)
      {
        marker = found->second + 2;
      }
    }
    in.facetmarkerlist[f] = marker;
  }
}

// One TetGen call of a partition: the order the tets (or when remeshing, the kept faces) are
// handed over in, whether the radius-edge bound applies, and whether the partition is meshed anew.
struct TetGenAttempt
{
  TetOrder order;
  bool qualityBound;
  TetGenInput input;
};

// Runs the attempts in turn until one gives a valid mesh, which the partition adopts; returns
// the last failure, empty on success. A call stopped at the time limit while refining (switch r)
// ends the attempts; one stopped at its cap on added points ends the refining ones, and the
// partition goes on to being meshed anew, where that is an attempt.
std::string runAttempts(const std::vector<TetGenAttempt>& attempts, PartitionMesh& partition,
  const std::vector<Face>& keptFaces, const RefinementContext& context,
  const DelaunayParameters& parameters, PointId firstDroppablePoint, const TetGenRunner& runTetGen,
  PartitionRefinement& refinement, DelaunayOutcome& outcome)
{
  std::string failure;
  bool refiningStopped = false;
  for (const TetGenAttempt& attempt : attempts)
  {
    if (refiningStopped && attempt.input == TetGenInput::Tets)
    {
      continue;
    }
    TetGenSession session(partition, context, refinement);
    tetgenio in, out;
    session.prepareInput(in, keptFaces, attempt.order, attempt.input, firstDroppablePoint);
    const bool remesh = attempt.input != TetGenInput::Tets;
    if (remesh && parameters.keptFacesMaySplit)
    {
      mergeCoplanarFaces(in, keptFaces, attempt.order, parameters.surfaceClasses);
    }
    const bool sizeField = context.sizes != nullptr && !parameters.shapesOnly;
    std::string switches = tetgenSwitches(parameters, attempt.qualityBound, sizeField, remesh);
    // Refining given tets that are not Delaunay (a later pass gets TetGen's tets cut by the
    // interface rounds' templates), TetGen can insert the circumcentre of a tet over the bound
    // where the cavity it opens leaves that tet in place: the same centre then goes in again and
    // again, each time a rounding apart (on a second pass over the Big cube, 104,000 points in 5 s
    // at one spot, until the time limit). A cap far above the forecast ends such a call at once.
    const bool capped = !remesh && !sizeField && parameters.maximumVolume > 0 &&
      !parameters.shapesOnly && in.numberoftetrahedra > 0;
    const double cap = capped ? std::min(1e9,
                                  std::max<double>(SteinerCapFloor,
                                    2.0 * forecastRefinedTets(in, parameters.maximumVolume)))
                              : 0;
    if (capped)
    {
      switches += "S" + std::to_string(static_cast<long long>(cap));
    }
    failure = runTetGen(in, switches, out);
    // A normal call adds about a fifth of its output tets in points; the cap stops TetGen at or
    // just under it.
    if (failure.empty() && capped && out.numberofpoints - in.numberofpoints > cap / 2)
    {
      failure = std::string(TetGenRunawayReason) + " (" +
        std::to_string(out.numberofpoints - in.numberofpoints) +
        ", more than the forecast output tets): it was repeating one insertion";
    }
    if (failure.empty())
    {
      failure = session.validate(in, out, remesh && parameters.keptFacesMaySplit);
    }
    if (failure.empty())
    {
      session.adoptOutput(out, partition, refinement, outcome);
      outcome.withoutQualityBound = !attempt.qualityBound;
      outcome.remeshed = remesh;
      outcome.droppedPoints = session.droppedPoints();
      return failure;
    }
    if (failure == WorkerCallAbortedReason)
    {
      break;
    }
    outcome.retried = true;
    if (!remesh && failure.rfind(TetGenTimeLimitReason, 0) == 0)
    {
      break; // the same in every order and without q: the partition falls back
    }
    // A runaway repeats one insertion into tets that are not Delaunay, in every order and
    // without q alike; meshed anew from the kept faces and all the points they are Delaunay
    // again. The study's greedy-coloured Delaunay cubes (1,024 partitions, two passes) lost two
    // partitions each to templates that way.
    refiningStopped = refiningStopped || (!remesh && failure.rfind(TetGenRunawayReason, 0) == 0);
  }
  return failure;
}

// Runs TetGen on the partition; an empty string means the partition now holds TetGen's mesh.
std::string refineWithTetGen(PartitionMesh& partition, const std::vector<Face>& keptFaces,
  const RefinementContext& context, const DelaunayParameters& parameters,
  const TetGenRunner& runTetGen, PartitionRefinement& refinement, DelaunayOutcome& outcome)
{
  if (parameters.simulateFailure)
  {
    return "simulated TetGen failure";
  }
  // TetGen 1.5 aborts on some inputs with many coplanar and cospherical points (its symbolic
  // perturbation asserts in insphere_s), or flips a kept face among coplanar ones; the same tets
  // in another order take other insertion paths, so a failed call is tried again with the tets
  // reversed, then strided. On sliver-laden partitions the flips come from the radius-edge
  // refinement itself, in every order, and never from the volume bound alone: the last attempt
  // drops q and leaves the shapes to the improvement sweeps, before the partition falls back. A
  // call stopped at the time limit ends the attempts: on the partitions measured, TetGen loops on
  // the same kept faces in every order and without q too, and each attempt costs the whole limit.
  // A sliver-laden partition is first meshed anew; where TetGen fails on that too (it can loop
  // on kept faces that are slivers' faces), the partition is refined as any other.
  //
  // Any other partition is meshed anew last, before it falls back to templates. A later pass
  // refines tets that are not Delaunay (TetGen's, cut by the interface rounds' templates), and on
  // grid-like meshes TetGen can put a circumcentre exactly on a vertex already there, then a
  // cluster of points a rounding apart around it, in every order and without q alike; meshed
  // anew from the kept faces and all the points, the partition is Delaunay again. The study's
  // Delaunay cubes at 1,024 partitions (two passes) lost 2 (Small cube) and 3 (Big cube)
  // partitions to templates that way, and none with this attempt.
  std::vector<TetGenAttempt> attempts;
  const bool slivers = holdsManySlivers(partition, context, refinement);
  if (slivers)
  {
    attempts.push_back(
      { TetOrder::forward(keptFaces.size()), true, TetGenInput::KeptFacesAndPoints });
  }
  const std::size_t count = partition.tets.size();
  attempts.push_back({ TetOrder::forward(count), true, TetGenInput::Tets });
  attempts.push_back({ TetOrder::reversed(count), true, TetGenInput::Tets });
  attempts.push_back({ TetOrder::strided(count), true, TetGenInput::Tets });
  attempts.push_back({ TetOrder::forward(count), false, TetGenInput::Tets });
  if (!slivers)
  {
    attempts.push_back(
      { TetOrder::forward(keptFaces.size()), true, TetGenInput::KeptFacesAndPoints });
  }
  return runAttempts(
    attempts, partition, keptFaces, context, parameters, 0, runTetGen, refinement, outcome);
}

// TetGen's output tets per regular tet of edge h that fills the same volume: 1.68 M tets on the
// Big cube with h = 0.01 + 0.08 |x - 0.5|, whose volume holds 1.02 M regular tets.
constexpr double SizeFieldTetsPerRegularTet = 1.65;

} // namespace

void setTriangleFacets(tetgenio& io, const int* corners, int count)
{
  io.numberoffacets = count;
  io.facetlist = new tetgenio::facet[static_cast<std::size_t>(count)];
  for (int f = 0; f < count; ++f)
  {
    tetgenio::facet& facet = io.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(facet.polygonlist);
    facet.polygonlist[0].numberofvertices = 3;
    facet.polygonlist[0].vertexlist = new int[3];
    std::copy_n(corners + 3 * f, 3, facet.polygonlist[0].vertexlist);
  }
}

double forecastRefinedTets(const tetgenio& in, double maximumVolume)
{
  double volume = 0;
  for (int t = 0; t < in.numberoftetrahedra; ++t)
  {
    const int* corners = in.tetrahedronlist + static_cast<std::size_t>(t) * in.numberofcorners;
    const double* p[4];
    for (int k = 0; k < 4; ++k)
    {
      p[k] = in.pointlist + 3 * static_cast<std::size_t>(corners[k] - in.firstnumber);
    }
    volume += std::abs(signedVolume6(p[0], p[1], p[2], p[3])) / 6.0;
  }
  return in.numberoftetrahedra + 4.0 * volume / maximumVolume;
}

double forecastDelaunayTets(double volume, double maximumVolume)
{
  return 3.0 * volume / maximumVolume;
}

double forecastDelaunayTetsForSizes(
  const TetList& tets, const std::vector<double>& coordinates, const std::vector<double>& sizes)
{
  double total = 0;
  for (const Tet& tet : tets)
  {
    total += SizeFieldTetsPerRegularTet * regularTetsFilling(tet, coordinates, sizes);
  }
  return total;
}

double interfaceEdgeLengthForVolume(double maximumVolume)
{
  return std::cbrt(6.0 * std::sqrt(2.0) * maximumVolume);
}

Status remeshPartitionDelaunay(PartitionMesh& partition, const RefinementContext& context,
  const DelaunayParameters& parameters, PointId firstDroppablePoint, const TetGenRunner& runTetGen,
  PartitionRefinement& refinement, DelaunayOutcome& outcome)
{
  if (partition.tets.empty())
  {
    return Status::success();
  }
  std::vector<Face> keptFaces, regionInterfaceFaces;
  findConstrainedFaces(partition, keptFaces, regionInterfaceFaces);
  keptFaces.insert(keptFaces.end(), regionInterfaceFaces.begin(), regionInterfaceFaces.end());
  // A second order of the faces where TetGen fails on the first (see refineWithTetGen).
  const std::vector<TetGenAttempt> attempts{
    { TetOrder::forward(keptFaces.size()), true, TetGenInput::KeptFacesAndOwnPoints },
    { TetOrder::strided(keptFaces.size()), true, TetGenInput::KeptFacesAndOwnPoints },
  };
  outcome.reason = parameters.simulateFailure
    ? std::string("simulated TetGen failure")
    : runAttempts(attempts, partition, keptFaces, context, parameters, firstDroppablePoint,
        runTetGen, refinement, outcome);
  outcome.fellBack = !outcome.reason.empty();
  return Status::success();
}

Status refinePartitionDelaunay(PartitionMesh& partition, const RefinementContext& context,
  const PostedSplits& received, const DelaunayParameters& parameters, const TetGenRunner& runTetGen,
  PartitionRefinement& refinement, DelaunayOutcome& outcome)
{
  if (partition.tets.empty())
  {
    return Status::success();
  }
  std::vector<Face> boundaryFaces, regionInterfaceFaces;
  Status status = splitConstrainedEdges(
    partition, context, received, refinement, boundaryFaces, regionInterfaceFaces);
  if (!status.ok() || parameters.constrainedEdgesOnly)
  {
    return status;
  }
  const std::size_t boundaryCount = boundaryFaces.size();
  std::vector<Face> keptFaces = boundaryFaces;
  keptFaces.insert(keptFaces.end(), regionInterfaceFaces.begin(), regionInterfaceFaces.end());

  const std::string failure =
    refineWithTetGen(partition, keptFaces, context, parameters, runTetGen, refinement, outcome);
  if (failure.empty())
  {
    return Status::success();
  }
  // Fallback: template-split the interior. The boundary stays frozen: its splits are already
  // posted, and neighbours will heal exactly those.
  outcome.fellBack = true;
  outcome.reason = failure;
  keptFaces.resize(boundaryCount); // the partition is as TetGen received it
  EdgeSet frozenEdges;
  addFaceEdges(keptFaces, frozenEdges);
  return refinePartition(
    partition, context, PostedSplits(), refinement, EdgeFilter{ &frozenEdges, false });
}

} // namespace cgmesh
