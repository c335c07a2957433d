// Serial template refinement of one partition: heals the splits its processed neighbours made on
// shared edges, splits every other edge longer than the threshold, and posts the splits of
// interface edges to its outbox.
#ifndef cgmesh_PartitionRefiner_h
#define cgmesh_PartitionRefiner_h

#include "Core/ConstrainedFaces.h"
#include "Core/EdgeSplits.h"
#include "Core/PartitionMesh.h"
#include "Core/PostedSplits.h"
#include "Core/ProvisionalIds.h"
#include "Core/Status.h"
#include "Core/Tasks.h"
#include "Core/TetMesh.h"
#include "Refinement/TemplateTable.h"

#include <vector>

namespace cgmesh
{

// Read-only state shared by all partitions during one iteration.
struct RefinementContext
{
  const std::vector<double>* coordinates = nullptr;   // global points, xyz
  const std::vector<char>* interfaceVertex = nullptr; // 1 when a point lies in 2+ partitions
  double squaredThreshold = 0;                        // split edges with a larger squared length
  // With a size field: one size per global point, and edges are split by longerThanSize()
  // instead of the threshold.
  const std::vector<double>* sizes = nullptr;
  const TemplateTable* templates = nullptr; // required: refinePartition() sizes its output by it
  // Face diagonals follow the vertices' coordinates (lexicographic x, y, z) instead of their ids.
  // Pieces of one mesh refined by separate processes see a shared face with their own ids but
  // with bit-identical coordinates, so only this order cuts it alike on both sides.
  bool orderCornersByCoordinates = false;
  // When positive: the mean ratio below which the improvement after this pass works. Refinement
  // then lists the tets that may be below it (PartitionRefinement::tetsToScreen).
  double improvementTarget = 0;
  // Delaunay: TetGen's new points get weights in the old tets (for point data) and its new tets
  // the old tet holding their centroid as parent (for cell data). Where the run carries neither
  // (nor sizes, which are interpolated like point data), nothing is located: a tet's parent is
  // the old tet it descends from in TetGen.
  bool locateTetGenOutput = true;
};

// Every child of a tet split into eight across its shortest octahedron diagonal has a mean ratio
// (TetQuality.h) of at least this fraction of its parent's. All eight children have a volume of
// V/8, so a child's ratio to its parent's mean ratio is S / (4 S_child) for the sums of squared
// edge lengths S and S_child. The corner children are the parent halved: ratio 1. An inner child
// has the diagonal d between the midpoints of opposite edges a and b, d^2 = (S - 2P) / 4 with
// P = |a|^2 + |b|^2, and five edges that halve parent edges other than a or b, at most S / 4 in
// all; so its ratio is at least S / (2S - 2P). The shortest diagonal is the pair with the largest
// P, and the three pairs' P sum to S, so P >= S / 3 and the ratio is at least 3/4.
constexpr double FullSplitChildQuality = 0.75;

// A set of edges (the value is unused). Flat: the Delaunay interface rounds ask it about every
// long edge of a partition, and a node-based set's look-ups missed the cache each time.
using EdgeSet = FlatHashMap<EdgeKey, char, EdgeKeyHash, NoEdge>;

// Restricts which long edges a refinement pass may split: all (no set), only the listed ones, or
// all but the listed ones.
struct EdgeFilter
{
  const EdgeSet* edges = nullptr;
  bool onlyListed = true;

  bool allows(const EdgeKey& edge) const { return !edges || edges->contains(edge) == onlyListed; }
};

// Vertices a partition created. Until the colour is finished they carry provisional ids
// (Core/ProvisionalIds.h); finalizeNewPoints() turns them into global ids.
struct PartitionRefinement
{
  std::vector<double> newCoordinates;       // xyz per new vertex
  std::vector<double> newSizes;             // with a size field: h per new vertex
  std::vector<PointSource> newPointSources; // where each new vertex lies
  Outbox outbox;
  // Vertices this partition made or received during the iteration that lie on an interface
  // (older ones are flagged in RefinementContext::interfaceVertex).
  PointIdSet newInterfacePoints;
  std::vector<PointId> movedPoints; // vertices quality improvement moved
  std::int64_t healedSplits = 0;    // splits taken from neighbours' outboxes
  // The global ids of those splits' vertices: each lies in two partitions now.
  std::vector<PointId> receivedPoints;
  std::int64_t createdSplits = 0; // splits this partition made itself
  // With RefinementContext::improvementTarget: the indices (ascending) of the refined partition's
  // tets below it. Children of full splits that cannot be are not measured: corner children
  // (their parent halved) of a parent at the target, and every child of a parent at the target /
  // FullSplitChildQuality. The others are, as they are made (their corners' coordinates at hand):
  // improvement screened 400 k tets of the FinFET's 6.5 M at 77 ns each, from memory, before.
  std::vector<std::size_t> tetsToScreen;
};

// How many tets refinePartition() will make of `partition` (without healing, which never adds
// splits the partition would not make itself): the size guard's forecast.
std::int64_t predictTemplateTetCount(
  const PartitionMesh& partition, const RefinementContext& context);

// Marks the points that lie in tets of two or more partitions: only edges between two such points
// can be shared, so only their splits go to outboxes. `parallelFor` scans the partitions; the
// marks do not depend on it.
Status findInterfaceVertices(const std::vector<PartitionMesh>& partitions, PointId numberOfPoints,
  const ParallelFor& parallelFor, std::vector<char>& interfaceVertex);

// Refines `partition` in place. The tets' corners are global ids; the result may reference
// provisional ids (see above). Each tet is replaced where it stands, by itself or by its children
// one after another; with `origins`, each resulting tet's index in the partition before; with
// `faceMarks` (one per tet), which faces of each resulting tet lie in constrained faces before.
//
// With `passedUnsplit`, passes of one filter over a partition skip what they already know: on
// entry, either empty or one flag per tet, set where the tet came through the pass before
// unsplit and nothing has changed its corners since (their positions and sizes decide its edges,
// so none is long now); on return, one flag per resulting tet, set where it came through this
// pass unsplit. A pass after the first then measures only the children the one before made.
Status refinePartition(PartitionMesh& partition, const RefinementContext& context,
  const PostedSplits& received, PartitionRefinement& refinement,
  const EdgeFilter& filter = EdgeFilter(), std::vector<std::size_t>* origins = nullptr,
  ConstrainedFaceMarks* faceMarks = nullptr, std::vector<char>* passedUnsplit = nullptr);

// Rewrites provisional ids of the partition's tets, outbox and new point sources into global ids
// starting at `firstGlobalId`.
void finalizeNewPoints(
  PartitionMesh& partition, PartitionRefinement& refinement, PointId firstGlobalId);

} // namespace cgmesh

#endif
