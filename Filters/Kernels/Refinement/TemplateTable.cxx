#include "Refinement/TemplateTable.h"

#include "Core/Geometry.h"

#include <algorithm>
#include <numeric>
#include <set>
#include <string>

namespace cgmesh
{
namespace
{

using Triangle = std::array<int, 3>;
using IntPoint = std::array<std::int64_t, 3>;

// Reference tet scaled by two so that every edge midpoint has integer coordinates: all the
// orientation tests below are exact.
std::array<IntPoint, 10> referencePoints()
{
  std::array<IntPoint, 10> points = { { { 0, 0, 0 }, { 2, 0, 0 }, { 0, 2, 0 }, { 0, 0, 2 } } };
  for (int e = 0; e < 6; ++e)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      points[4 + e][axis] =
        (points[TetEdgeCorners[e][0]][axis] + points[TetEdgeCorners[e][1]][axis]) / 2;
    }
  }
  return points;
}

const std::array<IntPoint, 10> Reference = referencePoints();

std::int64_t orient(int a, int b, int c, int d)
{
  const IntPoint& p = Reference[a];
  std::int64_t u[3], v[3], w[3];
  for (int i = 0; i < 3; ++i)
  {
    u[i] = Reference[b][i] - p[i];
    v[i] = Reference[c][i] - p[i];
    w[i] = Reference[d][i] - p[i];
  }
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
    u[2] * (v[0] * w[1] - v[1] * w[0]);
}

// Orientation-preserving rotation that puts the smallest vertex first.
Triangle canonical(Triangle t)
{
  const int first = static_cast<int>(std::min_element(t.begin(), t.end()) - t.begin());
  std::rotate(t.begin(), t.begin() + first, t.end());
  return t;
}

Triangle reversed(const Triangle& t)
{
  return canonical({ t[0], t[2], t[1] });
}

// A reference face plane contains the triangle: x = 0, y = 0, z = 0 or x + y + z = 2.
bool onReferenceBoundary(const Triangle& t)
{
  for (int axis = 0; axis < 3; ++axis)
  {
    if (Reference[t[0]][axis] == 0 && Reference[t[1]][axis] == 0 && Reference[t[2]][axis] == 0)
    {
      return true;
    }
  }
  auto onSlanted = [](int v)
  {
    return Reference[v][0] + Reference[v][1] + Reference[v][2] == 2;
  };
  return onSlanted(t[0]) && onSlanted(t[1]) && onSlanted(t[2]);
}

LocalTet positivelyOriented(int a, int b, int c, int d)
{
  if (orient(a, b, c, d) < 0)
  {
    std::swap(c, d);
  }
  return { static_cast<std::uint8_t>(a), static_cast<std::uint8_t>(b), static_cast<std::uint8_t>(c),
    static_cast<std::uint8_t>(d) };
}

// The faces of tet (a, b, c, d), each oriented to see the tet's inside positively.
std::array<Triangle, 4> inwardFaces(const LocalTet& tet)
{
  std::array<Triangle, 4> faces;
  for (int skip = 0; skip < 4; ++skip)
  {
    Triangle face;
    int n = 0;
    for (int i = 0; i < 4; ++i)
    {
      if (i != skip)
      {
        face[n++] = tet[i];
      }
    }
    if (orient(face[0], face[1], face[2], tet[skip]) < 0)
    {
      std::swap(face[1], face[2]);
    }
    faces[skip] = canonical(face);
  }
  return faces;
}

// Finds a tetrahedralisation of the reference tet whose boundary is a given triangulation, by
// depth-first search over the apex of the first open face (iterative deepening on the number of
// tets, so the fewest-tets solution wins). Validity: every tet is positive, contains no other
// vertex, and every face is closed by exactly two tets or lies on the prescribed boundary; such a
// chain covers the reference tet exactly once.
class TemplateSearch
{
public:
  TemplateSearch(std::vector<int> vertices, const std::vector<Triangle>& boundary)
    : Vertices(std::move(vertices))
  {
    for (const Triangle& t : boundary)
    {
      this->Front.insert(canonical(t));
    }
  }

  bool run(std::vector<LocalTet>& tets)
  {
    for (int limit = 1; limit <= 16; ++limit)
    {
      if (this->extend(limit))
      {
        tets = this->Tets;
        return true;
      }
    }
    return false;
  }

private:
  bool containsOtherVertex(const LocalTet& tet) const
  {
    const auto faces = inwardFaces(tet);
    for (int v : this->Vertices)
    {
      if (std::find(tet.begin(), tet.end(), v) != tet.end())
      {
        continue;
      }
      bool inside = true;
      for (const Triangle& f : faces)
      {
        inside = inside && orient(f[0], f[1], f[2], v) >= 0;
      }
      if (inside)
      {
        return true;
      }
    }
    return false;
  }

  // Number of open faces the tet would close, or -1 when it may not be placed.
  int closedFaceCount(const LocalTet& tet) const
  {
    if (this->containsOtherVertex(tet))
    {
      return -1;
    }
    int closes = 0;
    for (const Triangle& f : inwardFaces(tet))
    {
      if (this->Used.count(f))
      {
        return -1;
      }
      if (this->Front.count(f))
      {
        ++closes;
      }
      else if (onReferenceBoundary(f))
      {
        return -1;
      }
    }
    return closes;
  }

  bool extend(int remaining)
  {
    if (this->Front.empty())
    {
      return true;
    }
    if (remaining == 0)
    {
      return false;
    }
    const Triangle open = *this->Front.begin();
    std::vector<std::pair<int, LocalTet>> candidates;
    for (int apex : this->Vertices)
    {
      if (std::find(open.begin(), open.end(), apex) != open.end() ||
        orient(open[0], open[1], open[2], apex) <= 0)
      {
        continue;
      }
      const LocalTet tet = { static_cast<std::uint8_t>(open[0]), static_cast<std::uint8_t>(open[1]),
        static_cast<std::uint8_t>(open[2]), static_cast<std::uint8_t>(apex) };
      const int closes = this->closedFaceCount(tet);
      if (closes >= 1)
      {
        candidates.emplace_back(closes, tet);
      }
    }
    std::stable_sort(candidates.begin(), candidates.end(),
      [](const auto& x, const auto& y) { return x.first > y.first; });
    for (const auto& candidate : candidates)
    {
      this->place(candidate.second);
      if (this->extend(remaining - 1))
      {
        return true;
      }
      this->remove(candidate.second);
    }
    return false;
  }

  void place(const LocalTet& tet)
  {
    for (const Triangle& f : inwardFaces(tet))
    {
      this->Used.insert(f);
      if (!this->Front.erase(f))
      {
        this->Front.insert(reversed(f));
      }
    }
    this->Tets.push_back(tet);
  }

  void remove(const LocalTet& tet)
  {
    for (const Triangle& f : inwardFaces(tet))
    {
      this->Used.erase(f);
      if (!this->Front.erase(reversed(f)))
      {
        this->Front.insert(f);
      }
    }
    this->Tets.pop_back();
  }

  std::vector<int> Vertices;
  std::set<Triangle> Front; // open faces, oriented towards the side that still needs a tet
  std::set<Triangle> Used;  // faces already bounding a placed tet, seen from that tet
  std::vector<LocalTet> Tets;
};

std::vector<Triangle> boundaryTriangulation(int splitMask, const std::array<int, 4>& cornerRanks)
{
  std::vector<Triangle> boundary;
  for (int opposite = 0; opposite < 4; ++opposite)
  {
    Triangle face;
    int n = 0;
    for (int i = 0; i < 4; ++i)
    {
      if (i != opposite)
      {
        face[n++] = i;
      }
    }
    for (Triangle t : triangulateFace(face, splitMask, cornerRanks))
    {
      if (orient(t[0], t[1], t[2], opposite) < 0)
      {
        std::swap(t[1], t[2]);
      }
      boundary.push_back(t);
    }
  }
  return boundary;
}

std::int64_t totalOrientation(const std::vector<LocalTet>& tets)
{
  std::int64_t sum = 0;
  for (const LocalTet& t : tets)
  {
    const std::int64_t o = orient(t[0], t[1], t[2], t[3]);
    if (o <= 0)
    {
      return -1;
    }
    sum += o;
  }
  return sum;
}

// Whether `tets` are positive and fill the reference tet's volume exactly.
bool fillsReference(const std::vector<LocalTet>& tets)
{
  return totalOrientation(tets) == orient(0, 1, 2, 3);
}

// Whether local vertex v (a corner, or 4 + e for the midpoint of edge e) belongs to the template
// of `splitMask`.
bool isTemplateVertex(int splitMask, int v)
{
  return (v >= 0 && v < 4) || (v >= 4 && v < 10 && ((splitMask >> (v - 4)) & 1));
}

std::vector<LocalTet> buildFullSplit(int diagonal)
{
  std::vector<LocalTet> tets;
  for (int corner = 0; corner < 4; ++corner)
  {
    std::array<int, 3> midpoints;
    int n = 0;
    for (int other = 0; other < 4; ++other)
    {
      if (other != corner)
      {
        midpoints[n++] = 4 + localEdgeIndex(corner, other);
      }
    }
    tets.push_back(positivelyOriented(corner, midpoints[0], midpoints[1], midpoints[2]));
  }
  // Opposite edge pairs (0,5), (1,4), (2,3): their midpoints are the octahedron's opposite
  // vertices. The chosen pair is the axis; the other four form the equator, in cyclic order.
  const int axisEdge[3][2] = { { 0, 5 }, { 1, 4 }, { 2, 3 } };
  const int* axis = axisEdge[diagonal];
  const int* first = axisEdge[(diagonal + 1) % 3];
  const int* second = axisEdge[(diagonal + 2) % 3];
  const int equator[4] = { 4 + first[0], 4 + second[0], 4 + first[1], 4 + second[1] };
  for (int i = 0; i < 4; ++i)
  {
    tets.push_back(positivelyOriented(4 + axis[0], 4 + axis[1], equator[i], equator[(i + 1) % 4]));
  }
  return tets;
}

// Whether `tets` tile the reference tet with exactly the faces `boundary` on its surface: every
// face seen once from each side inside, once from inside on the surface, and every face of
// `boundary` there. Checks templates that were not found by the search here (TemplateData).
bool tilesWithBoundary(const std::vector<LocalTet>& tets, const std::vector<Triangle>& boundary)
{
  // Sorted lists rather than sets: the check runs for every entry of the table at start-up.
  std::vector<Triangle> seen;
  seen.reserve(4 * tets.size());
  for (const LocalTet& tet : tets)
  {
    const std::array<Triangle, 4> faces = inwardFaces(tet);
    seen.insert(seen.end(), faces.begin(), faces.end());
  }
  std::sort(seen.begin(), seen.end());
  if (std::adjacent_find(seen.begin(), seen.end()) != seen.end())
  {
    return false; // two tets on the same side of a face: they overlap
  }
  std::vector<Triangle> surface;
  for (const Triangle& face : boundary)
  {
    surface.push_back(canonical(face));
  }
  std::sort(surface.begin(), surface.end());
  const auto has = [](const std::vector<Triangle>& faces, const Triangle& face)
  {
    return std::binary_search(faces.begin(), faces.end(), face);
  };
  std::size_t onSurface = 0;
  for (const Triangle& face : seen)
  {
    if (has(seen, reversed(face)))
    {
      continue;
    }
    if (!has(surface, face))
    {
      return false; // an open face that is not one of the required surface triangles
    }
    ++onSurface;
  }
  // Every required triangle is there (each open face is a distinct one of them).
  return onSurface == surface.size() &&
    std::adjacent_find(surface.begin(), surface.end()) == surface.end();
}

} // namespace

int localEdgeIndex(int a, int b)
{
  for (int e = 0; e < 6; ++e)
  {
    if ((TetEdgeCorners[e][0] == a && TetEdgeCorners[e][1] == b) ||
      (TetEdgeCorners[e][0] == b && TetEdgeCorners[e][1] == a))
    {
      return e;
    }
  }
  return -1;
}

std::vector<std::array<int, 3>> triangulateFace(
  const std::array<int, 3>& face, int splitMask, const std::array<int, 4>& cornerRanks)
{
  auto midpoint = [](int a, int b)
  {
    return 4 + localEdgeIndex(a, b);
  };
  auto isSplit = [splitMask](int a, int b)
  {
    return (splitMask >> localEdgeIndex(a, b)) & 1;
  };
  const int a = face[0], b = face[1], c = face[2];
  const int splitCount = isSplit(a, b) + isSplit(b, c) + isSplit(a, c);
  if (splitCount == 0)
  {
    return { { a, b, c } };
  }
  if (splitCount == 3)
  {
    const int ab = midpoint(a, b), bc = midpoint(b, c), ac = midpoint(a, c);
    return { { a, ab, ac }, { b, bc, ab }, { c, ac, bc }, { ab, bc, ac } };
  }
  // Rotate so that the split edges are (p, q) [and (p, r) when two are split].
  std::array<int, 3> rotated = face;
  for (int turn = 0; turn < 3; ++turn)
  {
    const int p = rotated[0], q = rotated[1], r = rotated[2];
    if (splitCount == 1 && isSplit(p, q))
    {
      const int m = midpoint(p, q);
      return { { p, m, r }, { m, q, r } };
    }
    if (splitCount == 2 && isSplit(p, q) && isSplit(p, r))
    {
      const int pq = midpoint(p, q), pr = midpoint(p, r);
      if (cornerRanks[q] < cornerRanks[r])
      {
        return { { p, pq, pr }, { pq, q, pr }, { q, r, pr } };
      }
      return { { p, pq, pr }, { pq, q, r }, { pq, r, pr } };
    }
    std::rotate(rotated.begin(), rotated.begin() + 1, rotated.end());
  }
  return {};
}

std::vector<std::array<int, 4>> TemplateTable::rankOrders()
{
  std::vector<std::array<int, 4>> orders;
  std::array<int, 4> ranks = { 0, 1, 2, 3 };
  do
  {
    orders.push_back(ranks);
  } while (std::next_permutation(ranks.begin(), ranks.end()));
  return orders;
}

int TemplateTable::rankCode(const std::array<int, 4>& cornerRanks)
{
  return cornerRanks[0] | (cornerRanks[1] << 2) | (cornerRanks[2] << 4) | (cornerRanks[3] << 6);
}

TemplateTable::TemplateTable(const ParallelFor& parallelFor)
  : Partial(64 * 256)
{
  const std::vector<std::array<int, 4>> orders = rankOrders();
  // Each order fills its own entries; a failed search records its mask (0: none failed).
  std::vector<int> failedMask(orders.size(), 0);
  this->Validity = parallelFor(static_cast<std::int64_t>(orders.size()),
    [&](std::int64_t order)
    {
      const std::array<int, 4>& orderRanks = orders[order];
      for (int mask = 1; mask < 63; ++mask)
      {
        std::vector<int> vertices;
        for (int v = 0; v < 10; ++v)
        {
          if (isTemplateVertex(mask, v))
          {
            vertices.push_back(v);
          }
        }
        std::vector<LocalTet> tets;
        TemplateSearch search(vertices, boundaryTriangulation(mask, orderRanks));
        if (!search.run(tets) || !fillsReference(tets))
        {
          failedMask[order] = mask;
          return;
        }
        this->Partial[mask * 256 + rankCode(orderRanks)] = std::move(tets);
      }
    });
  if (!this->Validity.ok())
  {
    return;
  }
  for (int mask : failedMask)
  {
    if (mask != 0)
    {
      this->Validity = Status::failure(
        ErrorKind::Internal, "no valid template for split mask " + std::to_string(mask));
      return;
    }
  }
  this->addFullSplits();
}

TemplateTable::TemplateTable(const TemplateData& data)
  : Partial(64 * 256)
{
  const std::vector<std::array<int, 4>> orders = rankOrders();
  for (int mask = 1; mask < 63; ++mask)
  {
    for (std::size_t order = 0; order < orders.size(); ++order)
    {
      const std::size_t entry = (mask - 1) * orders.size() + order;
      std::vector<LocalTet> tets;
      for (std::uint32_t t = data.offsets[entry]; t < data.offsets[entry + 1]; ++t)
      {
        const std::uint8_t* corners = data.corners + 4 * t;
        if (!std::all_of(
              corners, corners + 4, [mask](std::uint8_t v) { return isTemplateVertex(mask, v); }))
        {
          tets.clear(); // a corner of no vertex of the template: fails the check below
          break;
        }
        tets.push_back({ corners[0], corners[1], corners[2], corners[3] });
      }
      if (!fillsReference(tets) ||
        !tilesWithBoundary(tets, boundaryTriangulation(mask, orders[order])))
      {
        this->Validity = Status::failure(ErrorKind::Internal,
          "the compiled template for split mask " + std::to_string(mask) + " is not valid");
        return;
      }
      this->Partial[mask * 256 + rankCode(orders[order])] = std::move(tets);
    }
  }
  this->addFullSplits();
}

void TemplateTable::addFullSplits()
{
  this->MostChildren[0] = 1;
  for (int mask = 1; mask < 63; ++mask)
  {
    for (int code = 0; code < 256; ++code)
    {
      this->MostChildren[mask] = std::max(
        this->MostChildren[mask], static_cast<int>(this->Partial[mask * 256 + code].size()));
    }
  }
  for (int diagonal = 0; diagonal < 3; ++diagonal)
  {
    this->Full[diagonal] = buildFullSplit(diagonal);
    if (!fillsReference(this->Full[diagonal]))
    {
      this->Validity = Status::failure(
        ErrorKind::Internal, "invalid full-split template " + std::to_string(diagonal));
      return;
    }
    this->MostChildren[63] =
      std::max(this->MostChildren[63], static_cast<int>(this->Full[diagonal].size()));
  }
}

const std::vector<LocalTet>& TemplateTable::partialSplit(
  int splitMask, const std::array<int, 4>& cornerRanks) const
{
  return this->Partial[splitMask * 256 + rankCode(cornerRanks)];
}

const std::vector<LocalTet>& TemplateTable::fullSplit(int diagonal) const
{
  return this->Full[diagonal];
}

} // namespace cgmesh
