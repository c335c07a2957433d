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

template <typename T>
void sortUnique(std::vector<T>& values)
{
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
}

template <typename T>
std::vector<T> intersection(const std::vector<T>& first, const std::vector<T>& second)
{
  std::vector<T> common;
  std::set_intersection(
    first.begin(), first.end(), second.begin(), second.end(), std::back_inserter(common));
  return common;
}

bool holds(const Corners& corners, int v)
{
  return std::find(corners.begin(), corners.end(), v) != corners.end();
}

} // namespace

bool Improver::isShort(int a, int b) const
{
  return shorterThanSize(
    squaredDistance(this->at(a), this->at(b)), this->sizeAt(a), this->sizeAt(b));
}

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
bool Improver::linkConditionHolds(int a, int b) const
{
  struct Link
  {
    std::vector<int> vertices;
    std::vector<Edge> edges;
  };
  const auto linkOf = [this](int v)
  {
    Link link;
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
      link.vertices.insert(link.vertices.end(), face, face + 3);
      link.edges.push_back(edgeOf(face[0], face[1]));
      link.edges.push_back(edgeOf(face[1], face[2]));
      link.edges.push_back(edgeOf(face[0], face[2]));
    }
    sortUnique(link.vertices);
    sortUnique(link.edges);
    return link;
  };
  Link edgeLink; // of (a, b): the other two corners of each tet holding both
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
    edgeLink.vertices.insert(edgeLink.vertices.end(), other, other + 2);
    edgeLink.edges.push_back(edgeOf(other[0], other[1]));
  }
  sortUnique(edgeLink.vertices);
  sortUnique(edgeLink.edges);
  const Link linkA = linkOf(a), linkB = linkOf(b);
  for (int v : intersection(linkA.vertices, linkB.vertices))
  {
    if (v != a && v != b &&
      !std::binary_search(edgeLink.vertices.begin(), edgeLink.vertices.end(), v))
    {
      return false;
    }
  }
  for (const Edge& e : intersection(linkA.edges, linkB.edges))
  {
    const bool touchesEnds = e.first == a || e.first == b || e.second == a || e.second == b;
    if (!touchesEnds && !std::binary_search(edgeLink.edges.begin(), edgeLink.edges.end(), e))
    {
      return false;
    }
  }
  return true;
}

// Removes free vertex a along its shortest short edge that passes every test (see
// ImprovementParameters::coarsen); false when none does.
bool Improver::collapseVertex(int a)
{
  if (this->Fixed[a] || this->Incident[a].empty())
  {
    return false;
  }
  const std::vector<int> ball = this->Incident[a];
  std::vector<std::pair<double, int>> candidates;
  double worstBefore = std::numeric_limits<double>::max();
  for (int t : ball)
  {
    worstBefore = std::min(worstBefore, this->Qualities[t]);
    for (int b : this->Tets[t])
    {
      if (b != a && this->isShort(a, b))
      {
        candidates.emplace_back(squaredDistance(this->at(a), this->at(b)), b);
      }
    }
  }
  sortUnique(candidates); // shortest first, ties by vertex: deterministic
  const double floor = std::min(this->Parameters.collapseQualityFloor, worstBefore);
  std::vector<Corners> replaced;
  for (int t : ball)
  {
    replaced.push_back(this->Tets[t]);
  }
  const double volumeBefore = this->totalVolume(replaced);
  const double largestBefore = this->largestVolume(ball);

  for (const auto& [lengthSquared, b] : candidates)
  {
    std::vector<Corners> created;
    std::vector<int> sources; // the tet each created one replaces
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
      // No edge longer than sqrt(2) h, which refinement would split again.
      valid = valid && !this->longerThanSizeAt(b, corners.data(), corners.size());
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

} // namespace improvement
} // namespace cgmesh
