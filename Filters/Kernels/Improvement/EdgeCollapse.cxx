// Coarsening by edge collapse: a free vertex a with an edge (a, b) shorter than h / sqrt(2) is
// removed, every tet around a that does not hold b taking b in its place, and those that hold b
// vanish. Only free vertices go (on no domain boundary, partition or box cut, or material
// interface face), so every face that stays is unchanged or lay around a, and boundaries and
// interfaces keep their triangles exactly. Vertices frozen here are reached by the box sweeps.
#include "Improvement/Improver.h"

#include "Refinement/SizeField.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace cgmesh
{
namespace improvement
{
namespace
{

using Edge = std::pair<int, int>;

Edge edgeOf(int v, int w)
{
  return v < w ? Edge{ v, w } : Edge{ w, v };
}

bool holds(const Corners& corners, int v)
{
  return std::find(corners.begin(), corners.end(), v) != corners.end();
}

} // namespace

bool Improver::longerThanSizeAt(int v, const int* neighbours, std::size_t count) const
{
  if (!this->Points.globalSizes)
  {
    return false;
  }
  for (std::size_t k = 0; k < count; ++k)
  {
    const int w = neighbours[k];
    if (w != v &&
      longerThanSize(squaredDistance(this->at(v), this->at(w)), this->sizeAt(v), this->sizeAt(w)))
    {
      return true;
    }
  }
  return false;
}

bool Improver::hasEdgeLongerThanSize(const Corners& tet) const
{
  for (const auto& corners : TetEdgeCorners)
  {
    if (this->longerThanSizeAt(tet[corners[0]], &tet[corners[1]], 1))
    {
      return true;
    }
  }
  return false;
}

// The link condition of edge (a, b): the vertices and edges the links of a and of b share are
// exactly those of the link of the edge. Without it a collapse can glue two sheets of the mesh
// together (two tets on one face, an edge in a pinch), which no orientation test sees.
//
// The edge's link is its ring R (the other two corners of each tet holding a and b) with the ring
// edges. So: every common neighbour of a and b lies in R, and then every edge of both links not
// touching a or b joins two vertices of R, and must be a ring edge. Small lists and a mark per
// vertex do it; sorting both links took a third of the coarsening time.
bool Improver::linkConditionHolds(int a, int b)
{
  std::vector<int>& ring = this->LinkRing;
  std::vector<Edge>& ringEdges = this->LinkRingEdges;
  ring.clear();
  ringEdges.clear();
  for (int t : this->Incident[a])
  {
    if (!holds(this->Tets[t], b))
    {
      continue;
    }
    int other[2], n = 0;
    for (int w : this->Tets[t])
    {
      if (w != a && w != b)
      {
        other[n++] = w;
      }
    }
    ring.insert(ring.end(), other, other + 2);
    ringEdges.push_back(edgeOf(other[0], other[1]));
  }
  // Ring membership by a mark per vertex: looked up for every corner of both balls, a search of
  // the ring each time was the larger part of this test.
  if (++this->RingStamp == 0) // wrapped: no old mark may match
  {
    std::fill(this->RingMark.begin(), this->RingMark.end(), 0);
    this->RingStamp = 1;
  }
  for (int v : ring)
  {
    this->RingMark[v] = this->RingStamp;
  }
  const auto inRing = [this](int v)
  {
    return this->RingMark[v] == this->RingStamp;
  };

  this->nextLinkStamp();
  for (int t : this->Incident[a])
  {
    for (int w : this->Tets[t])
    {
      this->NeighbourMark[w] = this->LinkStamp;
    }
  }
  for (int t : this->Incident[b])
  {
    for (int w : this->Tets[t])
    {
      if (w != a && w != b && this->NeighbourMark[w] == this->LinkStamp && !inRing(w))
      {
        return false; // a common neighbour off the ring
      }
    }
  }
  // The edges of a vertex's link among ring vertices: those of the faces opposite it.
  const auto ringEdgesOfLink = [&](int v, std::vector<Edge>& edges)
  {
    edges.clear();
    for (int t : this->Incident[v])
    {
      int face[3], n = 0;
      for (int w : this->Tets[t])
      {
        if (w != v)
        {
          face[n++] = w;
        }
      }
      for (int k = 0; k < 3; ++k)
      {
        const int x = face[k], y = face[(k + 1) % 3];
        if (x != a && x != b && y != a && y != b && inRing(x) && inRing(y))
        {
          edges.push_back(edgeOf(x, y));
        }
      }
    }
  };
  ringEdgesOfLink(a, this->LinkEdgesOfA);
  ringEdgesOfLink(b, this->LinkEdgesOfB);
  for (const Edge& e : this->LinkEdgesOfA)
  {
    const auto has = [&e](const std::vector<Edge>& edges)
    {
      return std::find(edges.begin(), edges.end(), e) != edges.end();
    };
    if (has(this->LinkEdgesOfB) && !has(ringEdges))
    {
      return false; // an edge of both links off the ring
    }
  }
  return true;
}

// Whether collapsing a onto b gives b an edge longer than sqrt(2) h, which refinement would split
// again: b's new neighbours are the corners of the tets around a that do not hold b. Looked at
// before orientation and quality, each neighbour once: on the FinFET it failed three times as
// often as those two together, and costs a fraction of the quality.
bool Improver::collapseMakesLongEdge(int a, int b, const std::vector<int>& ball)
{
  this->nextLinkStamp();
  for (int t : ball)
  {
    const Corners& corners = this->Tets[t];
    if (holds(corners, b))
    {
      continue;
    }
    for (int w : corners)
    {
      if (w == a || this->NeighbourMark[w] == this->LinkStamp)
      {
        continue;
      }
      this->NeighbourMark[w] = this->LinkStamp;
      if (this->longerThanSizeAt(b, &w, 1))
      {
        return true;
      }
    }
  }
  return false;
}

// Removes free vertex a along its shortest short edge that passes every test (see
// ImprovementParameters::coarsen); false when none does.
bool Improver::collapseVertex(int a)
{
  if (this->Incident[a].empty() || this->isFixed(a))
  {
    return false;
  }
  std::vector<std::pair<double, int>>& candidates = this->CollapseCandidates;
  candidates.clear();
  // Each neighbour once: it is a corner of several tets of the ball (on the FinFET with its size
  // field, gathering the candidates took 0.78 s of coarsening's 3.5 s at one thread, 0.43 s so).
  this->nextLinkStamp();
  for (int t : this->Incident[a])
  {
    for (int b : this->Tets[t])
    {
      if (b == a || this->NeighbourMark[b] == this->LinkStamp)
      {
        continue;
      }
      this->NeighbourMark[b] = this->LinkStamp;
      if (this->isShort(a, b))
      {
        candidates.emplace_back(squaredDistance(this->at(a), this->at(b)), b);
      }
    }
  }
  if (candidates.empty())
  {
    return false;
  }
  // Shortest first, ties by vertex: deterministic. Each neighbour is listed once already.
  std::sort(candidates.begin(), candidates.end());
  // A copy of the ball: the collapse changes the incidence.
  std::vector<int>& ball = this->CollapseBall;
  ball.assign(this->Incident[a].begin(), this->Incident[a].end());
  // The ball's measures before, taken once a candidate passes the length test: on the graded Big
  // cube most attempts that get this far fail it for every candidate (252,000 rejections for
  // 70,000 collapses).
  bool measured = false;
  double floor = 0, volumeBefore = 0, largestBefore = 0;
  const auto measureBall = [&]
  {
    double worstBefore = std::numeric_limits<double>::max();
    for (int t : ball)
    {
      worstBefore = std::min(worstBefore, this->Qualities[t]);
      const Corners& c = this->Tets[t];
      const double volume = this->orientation(c[0], c[1], c[2], c[3]) / 6.0;
      volumeBefore += volume;
      largestBefore = std::max(largestBefore, volume);
    }
    floor = std::min(this->CollapseFloorCubed, worstBefore);
    measured = true;
  };

  std::vector<Corners>& created = this->CollapseCreated;
  std::vector<int>& sources = this->CollapseSources; // the tet each created one replaces
  for (const auto& [lengthSquared, b] : candidates)
  {
    if (this->collapseMakesLongEdge(a, b, ball))
    {
      continue;
    }
    if (!measured)
    {
      measureBall();
    }
    created.clear();
    sources.clear();
    bool valid = true;
    for (std::size_t i = 0; i < ball.size() && valid; ++i)
    {
      Corners corners = this->Tets[ball[i]];
      if (holds(corners, b))
      {
        continue; // flattened onto the collapsed edge: it vanishes
      }
      std::replace(corners.begin(), corners.end(), a, b);
      valid = this->orientation(corners[0], corners[1], corners[2], corners[3]) > 0 &&
        this->quality(corners) >= floor;
      created.push_back(corners);
      sources.push_back(ball[i]);
    }
    if (!valid || created.empty() ||
      std::abs(this->totalVolume(created) - volumeBefore) > 1e-10 * volumeBefore ||
      !this->withinVolumeBound(created, largestBefore) || !this->linkConditionHolds(a, b))
    {
      continue;
    }
    for (int t : ball)
    {
      this->killTet(t);
    }
    for (std::size_t i = 0; i < created.size(); ++i)
    {
      this->addTet(created[i], this->Regions[sources[i]], this->Parents[sources[i]]);
    }
    return true;
  }
  return false;
}

bool Improver::unchangedSinceFailedCollapse(int a) const
{
  const std::uint64_t failed = this->FailedCollapseAt[a];
  if (failed == 0)
  {
    return false;
  }
  for (int t : this->Incident[a])
  {
    for (int w : this->Tets[t])
    {
      if (this->LastChange[w] > failed)
      {
        return false;
      }
    }
  }
  return true;
}

// One pass of coarsening over the vertices in order. Only a vertex with a short edge can go, and
// edges change only where a collapse made tets: the ends of the short edges at the start and the
// corners of the tets each collapse made are the only vertices worth visiting. Visiting every
// vertex, as the same pass without the marks does, looked at 24 balls per collapse on the FinFET.
// A vertex whose collapse failed and whose ball has not changed since is not tried again, as it
// would fail again: on the FinFET with a size field, 208,000 of 2.4 M visits.
void Improver::coarsen(ImprovementStatistics& statistics)
{
  std::vector<char> worthVisiting(this->IdOf.size(), 0);
  std::vector<char> collapsible(this->IdOf.size(), 1);
  if (this->Parameters.collapsibleVertices)
  {
    for (std::size_t v = 0; v < collapsible.size(); ++v)
    {
      collapsible[v] = mayCollapse(this->IdOf[v], this->Parameters);
    }
  }
  for (std::size_t t = 0; t < this->Tets.size(); ++t)
  {
    if (!this->Alive[t])
    {
      continue;
    }
    const Corners& tet = this->Tets[t];
    for (const auto& corners : TetEdgeCorners)
    {
      const int a = tet[corners[0]], b = tet[corners[1]];
      if (this->isShort(a, b))
      {
        worthVisiting[a] = worthVisiting[a] || collapsible[a];
        worthVisiting[b] = worthVisiting[b] || collapsible[b];
      }
    }
  }
  for (int v = 0; v < static_cast<int>(this->IdOf.size()); ++v)
  {
    const std::size_t tetsBefore = this->Tets.size();
    if (!worthVisiting[v] || this->unchangedSinceFailedCollapse(v))
    {
      continue;
    }
    if (!this->collapseVertex(v))
    {
      this->FailedCollapseAt[v] = ++this->ChangeClock;
      continue;
    }
    ++statistics.edgeCollapses;
    for (std::size_t t = tetsBefore; t < this->Tets.size(); ++t)
    {
      for (int w : this->Tets[t])
      {
        worthVisiting[w] = collapsible[w];
      }
    }
  }
}

} // namespace improvement
} // namespace cgmesh
