// The improver's mesh (Improver.h): local numbering, incidence, qualities, which vertices are
// frozen, the parent cell of new tets, and writing the result back to the partition. The
// operations on it are in QualityImprover.cxx and EdgeCollapse.cxx.
#include "Improvement/Improver.h"

#include "Core/Geometry.h"
#include "Core/TetQuality.h"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace cgmesh
{
namespace improvement
{

double Improver::totalVolume(const std::vector<Corners>& tets) const
{
  double total = 0;
  for (const Corners& c : tets)
  {
    total += this->orientation(c[0], c[1], c[2], c[3]) / 6.0;
  }
  return total;
}

double Improver::largestVolume(IncidenceLists::List tets) const
{
  double largest = 0;
  for (int t : tets)
  {
    const Corners& c = this->Tets[t];
    largest = std::max(largest, this->orientation(c[0], c[1], c[2], c[3]) / 6.0);
  }
  return largest;
}

bool Improver::withinVolumeBound(const std::vector<Corners>& created, double largestReplaced) const
{
  if (!(this->Parameters.maximumVolume > 0))
  {
    return true;
  }
  const double allowed = std::max(this->Parameters.maximumVolume, largestReplaced);
  for (const Corners& c : created)
  {
    if (this->orientation(c[0], c[1], c[2], c[3]) / 6.0 > allowed)
    {
      return false;
    }
  }
  return true;
}

Improver::Improver(PartitionMesh& partition, const PartitionPoints& points)
  : Partition(partition)
  , Points(points)
{
  // Local numbers first, so that each vertex's incidence list is laid out once at its size (with
  // room for what the operations add): growing them one tet at a time was a fifth of building
  // the improver.
  const std::size_t tetCount = partition.tets.size();
  std::vector<Corners> local(tetCount);
  this->LocalOf.reserve(tetCount / 4 + 16);
  this->IdOf.reserve(tetCount / 4 + 16);
  this->Position.reserve(tetCount / 4 + 16);
  this->Size.reserve(tetCount / 4 + 16);
  for (std::size_t t = 0; t < tetCount; ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      local[t][k] = this->localVertex(partition.tets[t][k]);
    }
  }
  std::vector<int> tetsAt(this->IdOf.size(), 0);
  for (const Corners& corners : local)
  {
    for (int v : corners)
    {
      ++tetsAt[v];
    }
  }
  this->Incident.reserve(tetsAt, 8);
  this->Tets.reserve(tetCount);
  this->Regions.reserve(tetCount);
  this->Parents.reserve(tetCount);
  this->Qualities.reserve(tetCount);
  this->Alive.reserve(tetCount);
  for (std::size_t t = 0; t < tetCount; ++t)
  {
    this->addTet(
      local[t], partition.regions.empty() ? 0 : partition.regions[t], partition.parentCells[t]);
  }
  this->Fixedness.assign(this->IdOf.size(), Unknown);
  this->Moved.assign(this->IdOf.size(), 0);
  this->LastChange.assign(this->IdOf.size(), 0);
  this->FailedCollapseAt.assign(this->IdOf.size(), 0);
  this->NeighbourMark.assign(this->IdOf.size(), 0);
  this->RingMark.assign(this->IdOf.size(), 0);
}

// A vertex stays where it is when a face around it has no second tet (the domain boundary, a
// partition interface or the cut around the improver's tets) or has tets of two materials on its
// sides. Every operation changes only faces inside one material and inside the tets, so those
// faces stay and the answer never changes: it is worked out from the vertex's ball the first time
// it is asked. Only the vertices of poor tets (and, when coarsening, the ends of short edges)
// ever are, a small part of those whose faces a table of every tet's faces would have sorted
// out up front.
bool Improver::isFixed(int v)
{
  char& known = this->Fixedness[v];
  if (known != Unknown)
  {
    return known == Fixed;
  }
  if (!this->mayBeFree(v))
  {
    known = Fixed;
    return true;
  }
  // Each face at v is met as the edge (x, y) of its other two corners, with its tet's region, in
  // a small hash table: v is fixed when an edge is met once, or by tets of two regions. Slots
  // carry the number of the call that filled them, so the table is never cleared, and the edges
  // met once are counted as they come, so it is never scanned.
  std::size_t capacity = 16;
  while (capacity < 6 * this->Incident[v].size()) // three faces per tet, at most half full
  {
    capacity *= 2;
  }
  std::vector<LinkEdge>& table = this->LinkEdges;
  if (table.size() < capacity)
  {
    table.assign(capacity, LinkEdge());
  }
  if (++this->LinkEdgeCall == 0) // wrapped: no old slot may look filled
  {
    std::fill(table.begin(), table.end(), LinkEdge());
    this->LinkEdgeCall = 1;
  }
  const unsigned call = this->LinkEdgeCall;
  const std::size_t mask = capacity - 1;
  bool fixed = false;
  int metOnce = 0;
  for (int t : this->Incident[v])
  {
    const Corners& c = this->Tets[t];
    for (int skip = 0; skip < 4 && !fixed; ++skip)
    {
      if (c[skip] == v)
      {
        continue;
      }
      int other[2], n = 0;
      for (int k = 0; k < 4; ++k)
      {
        if (k != skip && c[k] != v)
        {
          other[n++] = c[k];
        }
      }
      const std::uint64_t key = (static_cast<std::uint64_t>(std::min(other[0], other[1])) << 32) |
        static_cast<std::uint32_t>(std::max(other[0], other[1]));
      for (std::size_t at = (key * 0x9E3779B97F4A7C15ull) >> 40 & mask;; at = (at + 1) & mask)
      {
        LinkEdge& slot = table[at];
        if (slot.call != call)
        {
          slot = { key, call, 1, this->Regions[t] };
          ++metOnce;
          break;
        }
        if (slot.key == key)
        {
          metOnce -= slot.count == 1;
          ++slot.count;
          fixed = slot.region != this->Regions[t];
          break;
        }
      }
    }
  }
  fixed = fixed || metOnce > 0;
  known = fixed ? Fixed : Free;
  return fixed;
}

void Improver::nextLinkStamp()
{
  if (++this->LinkStamp == 0) // wrapped: no old mark may match
  {
    std::fill(this->NeighbourMark.begin(), this->NeighbourMark.end(), 0);
    this->LinkStamp = 1;
  }
}

// A necessary condition for isFixed() to find v free, without its face table: the tets around a
// free vertex are of one region, and their faces opposite it close into a sphere, for which
// Euler's formula with every edge on two of its F triangles gives F / 2 + 2 distinct corners
// (boundary or interface vertices have more, or two regions). On the graded Big cube with its
// size field, 59% of the vertices asked about are fixed, most of them on partition faces.
bool Improver::mayBeFree(int v)
{
  const IncidenceLists::List ball = this->Incident[v];
  if (ball.empty() || ball.size() % 2 != 0)
  {
    return false;
  }
  this->nextLinkStamp();
  const int region = this->Regions[ball.front()];
  std::size_t neighbours = 0;
  for (int t : ball)
  {
    if (this->Regions[t] != region)
    {
      return false;
    }
    for (int w : this->Tets[t])
    {
      if (w != v && this->NeighbourMark[w] != this->LinkStamp)
      {
        this->NeighbourMark[w] = this->LinkStamp;
        ++neighbours;
      }
    }
  }
  return neighbours == ball.size() / 2 + 2;
}

int Improver::localVertex(PointId id)
{
  const int next = static_cast<int>(this->IdOf.size());
  bool inserted = false;
  const int local = this->LocalOf.findOrEmplace(id, next, inserted);
  if (!inserted)
  {
    return local;
  }
  this->IdOf.push_back(id);
  this->Position.push_back(this->Points.at(id));
  this->Size.push_back(this->Points.sizeAt(id));
  return next;
}

void Improver::addTet(const Corners& corners, int region, CellId parent)
{
  const int t = static_cast<int>(this->Tets.size());
  this->Tets.push_back(corners);
  this->Regions.push_back(region);
  this->Parents.push_back(parent);
  this->Qualities.push_back(this->quality(corners));
  this->Alive.push_back(1);
  for (int v : corners)
  {
    this->Incident.add(v, t);
    if (!this->LastChange.empty()) // built: the constructor's tets are no change
    {
      this->noteChangeAt(v);
    }
  }
}

void Improver::killTet(int t)
{
  this->Alive[t] = 0;
  for (int v : this->Tets[t])
  {
    this->noteChangeAt(v);
    this->Incident.remove(v, t);
  }
}

void Improver::tetsAroundEdge(int a, int b, std::vector<int>& found) const
{
  found.clear();
  for (int t : this->Incident[a]) // alive tets only: killTet removes the others
  {
    const Corners& c = this->Tets[t];
    if (c[0] == b || c[1] == b || c[2] == b || c[3] == b)
    {
      found.push_back(t);
    }
  }
}

int Improver::neighbourAcross(int t, const std::array<int, 3>& face) const
{
  for (int u : this->Incident[face[0]])
  {
    const Corners& c = this->Tets[u];
    const auto holds = [&c](int v)
    {
      return c[0] == v || c[1] == v || c[2] == v || c[3] == v;
    };
    if (u != t && holds(face[1]) && holds(face[2]))
    {
      return u;
    }
  }
  return -1;
}

// The replaced tet that contains the new tet's centroid: its input cell is the new tet's parent.
CellId Improver::parentOf(const Corners& corners, const std::vector<int>& replaced) const
{
  double centroid[3] = { 0, 0, 0 };
  for (int v : corners)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      centroid[axis] += 0.25 * this->at(v)[axis];
    }
  }
  int best = replaced.front();
  double bestMinimum = -std::numeric_limits<double>::max();
  for (int t : replaced)
  {
    const Corners& c = this->Tets[t];
    const double volume = this->orientation(c[0], c[1], c[2], c[3]);
    double minimum = std::numeric_limits<double>::max();
    for (int i = 0; i < 4; ++i)
    {
      const double* p[4] = { this->at(c[0]), this->at(c[1]), this->at(c[2]), this->at(c[3]) };
      p[i] = centroid;
      minimum = std::min(minimum, signedVolume6(p[0], p[1], p[2], p[3]) / volume);
    }
    if (minimum > bestMinimum)
    {
      bestMinimum = minimum;
      best = t;
    }
  }
  return this->Parents[best];
}

// needsImprovement() of tet t, from the improver's own copies of the points and sizes: the same
// values, without looking each point up again.
bool Improver::needsWork(int t) const
{
  // The kept quality clears most tets without their points: a hair above the target, it cannot
  // be a rounding away from the measure below.
  if (!this->Parameters.coarsen && this->Qualities[t] > this->TargetCubed * (1 + 1e-9))
  {
    return false;
  }
  const Corners& c = this->Tets[t];
  if (this->Parameters.improve &&
    meanRatioBelow(this->at(c[0]), this->at(c[1]), this->at(c[2]), this->at(c[3]),
      this->Parameters.targetQuality))
  {
    return true;
  }
  if (!this->Parameters.coarsen)
  {
    return false;
  }
  for (const auto& corners : TetEdgeCorners)
  {
    const int a = c[corners[0]], b = c[corners[1]];
    if ((mayCollapse(this->IdOf[a], this->Parameters) ||
          mayCollapse(this->IdOf[b], this->Parameters)) &&
      this->isShort(a, b))
    {
      return true;
    }
  }
  return false;
}

void Improver::writeBack(
  std::vector<PointId>& movedPoints, std::size_t firstIndex, std::vector<std::size_t>* tetsLeft)
{
  if (this->Parameters.settledVertices)
  {
    for (std::size_t v = 0; v < this->IdOf.size(); ++v)
    {
      if (this->Fixedness[v] == Free && this->FailedCollapseAt[v] != 0)
      {
        (*this->Parameters.settledVertices)[this->IdOf[v]] = 0;
      }
    }
  }
  PartitionMesh improved;
  const bool hasRegions = !this->Partition.regions.empty();
  improved.tets.reserve(this->Tets.size());
  improved.parentCells.reserve(this->Tets.size());
  improved.regions.reserve(hasRegions ? this->Tets.size() : 0);
  for (std::size_t t = 0; t < this->Tets.size(); ++t)
  {
    if (!this->Alive[t])
    {
      continue;
    }
    if (tetsLeft && this->needsWork(static_cast<int>(t)))
    {
      tetsLeft->push_back(firstIndex + improved.tets.size());
    }
    const Corners& c = this->Tets[t];
    improved.tets.push_back(
      { this->IdOf[c[0]], this->IdOf[c[1]], this->IdOf[c[2]], this->IdOf[c[3]] });
    improved.parentCells.push_back(this->Parents[t]);
    if (hasRegions)
    {
      improved.regions.push_back(this->Regions[t]);
    }
  }
  this->Partition = std::move(improved);
  for (std::size_t v = 0; v < this->IdOf.size(); ++v)
  {
    if (this->Moved[v])
    {
      movedPoints.push_back(this->IdOf[v]);
    }
  }
}

} // namespace improvement
} // namespace cgmesh
