// The mesh-editing core of quality improvement and coarsening (QualityImprover.h): one
// partition's tets in local vertex numbers, with incidence, qualities and the vertices that may
// not move, built and written back in Improver.cxx. The operations live in QualityImprover.cxx
// (edge removal, face swaps, smoothing) and EdgeCollapse.cxx (coarsening). Internal to the
// Improvement kernels.
#ifndef cgmesh_Improver_h
#define cgmesh_Improver_h

#include "Core/EdgeSplits.h"
#include "Core/Geometry.h"
#include "Core/TetQuality.h"
#include "Improvement/IncidenceLists.h"
#include "Improvement/QualityImprover.h"
#include "Refinement/SizeField.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace cgmesh
{
namespace improvement
{

using Corners = std::array<int, 4>; // local vertex numbers

// Edge removal takes rings of 3 to MaximumRing tets; a table over the ring's chains.
constexpr int MaximumRing = 7;
template <typename Value>
using RingTable = std::array<std::array<Value, MaximumRing>, MaximumRing>;

// A change must beat the worst tet it replaces by more than rounding; both are cubed mean ratios
// (the Improver's quality), the margin is on the mean ratio.
inline bool improves(double afterCubed, double beforeCubed)
{
  return std::cbrt(afterCubed) > std::cbrt(beforeCubed) + 1e-12;
}

class Improver
{
public:
  Improver(PartitionMesh& partition, const PartitionPoints& points);

  void run(const ImprovementParameters& parameters, ImprovementStatistics& statistics);
  // Hands the tets back to the partition (and the moved vertices to `movedPoints`); with
  // `tetsLeft`, appends firstIndex + i for each tet i handed back that still needs improvement.
  void writeBack(std::vector<PointId>& movedPoints, std::size_t firstIndex = 0,
    std::vector<std::size_t>* tetsLeft = nullptr);

private:
  const double* at(int v) const { return this->Position[v]; }
  // The cubed mean ratio (cubedMeanRatio): every quality the improver holds or compares is one,
  // and the targets are cubed to match (run()), which keeps cube roots out of its loops.
  double quality(const Corners& t) const
  {
    return cubedMeanRatio(this->at(t[0]), this->at(t[1]), this->at(t[2]), this->at(t[3]));
  }
  double orientation(int a, int b, int c, int d) const
  {
    return signedVolume6(this->at(a), this->at(b), this->at(c), this->at(d));
  }
  int localVertex(PointId id);
  void addTet(const Corners& corners, int region, CellId parent);
  void killTet(int t);
  // The tets around edge (a, b), into `found`; the tet other than t on face `face` of t, or -1.
  void tetsAroundEdge(int a, int b, std::vector<int>& found) const;
  int neighbourAcross(int t, const std::array<int, 3>& face) const;
  CellId parentOf(const Corners& corners, const std::vector<int>& replaced) const;

  bool removeEdge(int a, int b);
  bool withinVolumeBound(const std::vector<Corners>& created, double largestReplaced) const;
  double largestVolume(IncidenceLists::List tets) const;
  bool orderedRing(int a, int b, const std::vector<int>& around, std::vector<int>& ring) const;
  double triangleQuality(int p, int q, int r, int a, int b, double side) const;
  double bestRingTriangulation(
    int a, int b, const std::vector<int>& ring, RingTable<int>& split) const;
  std::vector<Corners> ringTets(
    int a, int b, const std::vector<int>& ring, const RingTable<int>& split) const;
  double totalVolume(const std::vector<Corners>& tets) const;
  bool swapFace(int t, int skip);
  bool smoothVertex(int v);
  void smoothVerticesOfPoorTets(ImprovementStatistics& statistics);
  bool isFixed(int v);
  bool needsWork(int t) const;
  bool mayBeFree(int v);
  void nextLinkStamp();

  // The size field (EdgeCollapse.cxx), and coarsening.
  double sizeAt(int v) const { return this->Size[v]; }
  // Whether edge (a, b) is shorter than h / sqrt(2): asked for every edge of the tets coarsening
  // looks at, so defined here to be inlined.
  bool isShort(int a, int b) const
  {
    return shorterThanSize(
      squaredDistance(this->at(a), this->at(b)), this->sizeAt(a), this->sizeAt(b));
  }
  // Whether an edge from v to one of the `count` vertices at `neighbours` is longer than
  // sqrt(2) h (never without a size field: then nothing is looked at).
  bool longerThanSizeAt(int v, const int* neighbours, std::size_t count) const;
  bool hasEdgeLongerThanSize(const Corners& tet) const;
  // Whether a change that replaces tets whose worst cubed mean ratio is `worstBefore` must keep
  // every edge within sqrt(2) h: not when it mends a sliver (SliverMeanRatio).
  bool keepsSizeBound(double worstBefore) const { return worstBefore >= SliverCubed; }
  void coarsen(ImprovementStatistics& statistics);
  bool collapseVertex(int a);
  bool collapseMakesLongEdge(int a, int b, const std::vector<int>& ball);
  bool linkConditionHolds(int a, int b);
  void noteChangeAt(int v) { this->LastChange[v] = ++this->ChangeClock; }
  bool unchangedSinceFailedCollapse(int a) const;

  PartitionMesh& Partition;
  const PartitionPoints& Points;
  std::vector<PointId> IdOf;
  // Per local vertex, where its coordinates live and its size: looked up once, as every test
  // reads them (improvement adds no point, so the storage never moves).
  std::vector<double*> Position;
  std::vector<double> Size;
  FlatHashMap<PointId, int, PointIdHash, NoPoint> LocalOf;
  std::vector<Corners> Tets;
  std::vector<int> Regions;
  std::vector<CellId> Parents;
  std::vector<double> Qualities; // cubed mean ratio of each tet, kept current
  std::vector<char> Alive;
  IncidenceLists Incident; // alive tets at each vertex (killTet removes)
  enum Fixity : char
  {
    Unknown,
    Free,
    Fixed
  };
  std::vector<char> Fixedness; // a Fixity per vertex, found when first asked (isFixed)
  std::vector<char> Moved;
  std::vector<char> SmoothingCandidate; // scratch of smoothVerticesOfPoorTets
  // Scratch of smoothVertex, kept for their memory: the vertex's neighbours and its tets.
  std::vector<int> SmoothingNeighbours;
  std::vector<Corners> SmoothingStar;
  // A failed collapse of a is a function of a's ball: its tets, their corners' positions and the
  // incidence of those corners (the link condition). Every change stamps the vertices it touches
  // with the clock, so a vertex whose ball holds no stamp newer than its failure would fail again
  // and is not tried (EdgeCollapse.cxx).
  std::uint64_t ChangeClock = 0;
  std::vector<std::uint64_t> LastChange;       // clock of the last change at each vertex
  std::vector<std::uint64_t> FailedCollapseAt; // clock when its collapse last failed; 0: never
  ImprovementParameters Parameters;
  double TargetCubed = 0;        // Parameters.targetQuality cubed
  double CollapseFloorCubed = 0; // Parameters.collapseQualityFloor cubed
  // A tet under this mean ratio is a sliver: the size field's long-edge guard gives way to mending
  // it. The Delaunay method's graded cube kept a cluster of 1.5 to 6 degree tets that one edge
  // longer than sqrt(2) h would have mended.
  static constexpr double SliverMeanRatio = 0.2;
  static constexpr double SliverCubed = SliverMeanRatio * SliverMeanRatio * SliverMeanRatio;
  // Scratch of removeEdge (the tets around the edge, its ring), kept for their memory: it runs for
  // every edge of every poor tet.
  std::vector<int> AroundEdge, Ring;
  // Scratch of collapseVertex and linkConditionHolds, kept for their memory.
  std::vector<std::pair<double, int>> CollapseCandidates;
  std::vector<int> CollapseBall;
  std::vector<Corners> CollapseCreated;
  std::vector<int> CollapseSources;
  std::vector<int> LinkRing;
  std::vector<std::pair<int, int>> LinkRingEdges, LinkEdgesOfA, LinkEdgesOfB;
  // LinkStamp where a vertex neighbours the collapsed end, is a new neighbour of the kept one, is
  // a collapse candidate looked at, or a neighbour mayBeFree() counted; nextLinkStamp() starts a
  // new marking.
  std::vector<unsigned> NeighbourMark;
  // RingStamp where a vertex is on the ring of the edge linkConditionHolds() looks at.
  std::vector<unsigned> RingMark;
  struct LinkEdge // a face at the vertex isFixed looks at, by its other two corners
  {
    std::uint64_t key = 0;
    unsigned call = 0; // the isFixed call that filled the slot; any other: a free slot
    int count = 0;
    int region = 0;
  };
  std::vector<LinkEdge> LinkEdges; // scratch of isFixed
  unsigned LinkEdgeCall = 0;
  unsigned LinkStamp = 0;
  unsigned RingStamp = 0;
};

} // namespace improvement
} // namespace cgmesh

#endif
