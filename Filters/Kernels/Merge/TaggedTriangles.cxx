#include "Merge/TaggedTriangles.h"

#include "Core/FaceKey.h"

#include <algorithm>
#include <cmath>

namespace cgmesh
{
namespace
{

// Sorted corner triples with the index of the triangle each came from, for binary search (several
// triangles may share corners: one face in two tag sets).
struct TriangleIndex
{
  std::vector<std::pair<Face, std::size_t>> entries;

  explicit TriangleIndex(const std::vector<Triangle>& triangles)
  {
    entries.reserve(triangles.size());
    for (std::size_t t = 0; t < triangles.size(); ++t)
    {
      Face key = triangles[t];
      std::sort(key.begin(), key.end());
      entries.emplace_back(key, t);
    }
    std::sort(entries.begin(), entries.end());
  }

  // [first, last) of the entries with corners `key`.
  std::pair<std::size_t, std::size_t> find(const Face& key) const
  {
    const auto less = [](const std::pair<Face, std::size_t>& entry, const Face& face)
    {
      return entry.first < face;
    };
    const auto first = std::lower_bound(entries.begin(), entries.end(), key, less);
    auto last = first;
    while (last != entries.end() && last->first == key)
    {
      ++last;
    }
    return { static_cast<std::size_t>(first - entries.begin()),
      static_cast<std::size_t>(last - entries.begin()) };
  }
};

bool hasRepeatedCorner(const Face& sorted)
{
  return sorted[0] == sorted[1] || sorted[1] == sorted[2];
}

// Input points an output point is made of: at most three with a weight that is not negligible.
// Boundary and interface points have exact weights; the tolerance only keeps a relocated interior
// point that lies a rounding error away from a face from looking like a point on it.
constexpr double NegligibleWeight = 1e-9;

struct Sources
{
  PointId points[3];
  int count = 0; // -1: more than three, or one that no tagged triangle has
};

std::vector<Sources> tagSources(const PointProvenance& provenance,
  const std::vector<char>& isTriangleCorner, PointId outputPoints)
{
  std::vector<Sources> sources(static_cast<std::size_t>(outputPoints));
  for (PointId p = 0; p < outputPoints; ++p)
  {
    Sources& s = sources[p];
    for (std::int64_t k = provenance.offsets[p]; k < provenance.offsets[p + 1] && s.count >= 0; ++k)
    {
      if (std::abs(provenance.weights[k]) <= NegligibleWeight)
      {
        continue;
      }
      const PointId source = provenance.sources[k];
      if (s.count == 3 || !isTriangleCorner[source])
      {
        s.count = -1;
        break;
      }
      s.points[s.count++] = source;
    }
  }
  return sources;
}

// The union of the three corners' sources when it has exactly three points, sorted; else a key
// with a repeated entry, which matches no triangle.
Face sourceUnion(const Sources& a, const Sources& b, const Sources& c)
{
  Face key{ -1, -1, -1 };
  int n = 0;
  for (const Sources* s : { &a, &b, &c })
  {
    for (int k = 0; k < s->count; ++k)
    {
      const PointId point = s->points[k];
      if (std::find(key.begin(), key.begin() + n, point) != key.begin() + n)
      {
        continue;
      }
      if (n == 3)
      {
        return { -1, -1, -1 };
      }
      key[n++] = point;
    }
  }
  if (n != 3)
  {
    return { -1, -1, -1 };
  }
  std::sort(key.begin(), key.end());
  return key;
}

std::array<double, 3> triangleNormal(const TetMesh& mesh, const Triangle& corners)
{
  const double* p0 = mesh.point(corners[0]);
  const double* p1 = mesh.point(corners[1]);
  const double* p2 = mesh.point(corners[2]);
  const double a[3] = { p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2] };
  const double b[3] = { p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2] };
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}

double dot(const std::array<double, 3>& u, const std::array<double, 3>& v)
{
  return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

} // namespace

TaggedTriangleCheck checkTaggedTriangles(
  const TetMesh& mesh, const std::vector<Triangle>& triangles)
{
  const TriangleIndex index(triangles);
  // Per entry: how many tets hold the face, and whether they are of different regions.
  std::vector<int> tetsHolding(index.entries.size(), 0);
  std::vector<int> firstRegion(index.entries.size(), 0);
  std::vector<char> twoRegions(index.entries.size(), 0);
  for (CellId t = 0; t < mesh.numberOfTets(); ++t)
  {
    const int region = mesh.hasRegions() ? mesh.regions[t] : 0;
    for (int skip = 0; skip < 4; ++skip)
    {
      const auto range = index.find(sortedFace(mesh.tets[t].data(), skip));
      for (std::size_t e = range.first; e < range.second; ++e)
      {
        if (tetsHolding[e]++ == 0)
        {
          firstRegion[e] = region;
        }
        else if (firstRegion[e] != region)
        {
          twoRegions[e] = 1;
        }
      }
    }
  }
  TaggedTriangleCheck check;
  std::vector<char> notFace(triangles.size(), 0);
  std::vector<char> insideRegion(triangles.size(), 0);
  for (std::size_t e = 0; e < index.entries.size(); ++e)
  {
    const std::size_t t = index.entries[e].second;
    notFace[t] = tetsHolding[e] == 0 || hasRepeatedCorner(index.entries[e].first);
    insideRegion[t] = tetsHolding[e] == 2 && !twoRegions[e];
  }
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    if (notFace[t] && check.notFaces++ == 0)
    {
      check.firstNotFace = t;
    }
    if (insideRegion[t] && check.insideRegion++ == 0)
    {
      check.firstInsideRegion = t;
    }
  }
  return check;
}

std::vector<TriangleChild> findTriangleChildren(const TetMesh& input,
  const std::vector<Triangle>& triangles, const TetMesh& output, const PointProvenance& provenance)
{
  std::vector<TriangleChild> children;
  if (triangles.empty())
  {
    return children;
  }
  const TriangleIndex index(triangles);
  std::vector<char> isTriangleCorner(static_cast<std::size_t>(input.numberOfPoints()), 0);
  for (const Triangle& triangle : triangles)
  {
    for (PointId p : triangle)
    {
      isTriangleCorner[p] = 1;
    }
  }
  const std::vector<Sources> sources =
    tagSources(provenance, isTriangleCorner, output.numberOfPoints());

  // Candidates from every tet face whose corners all lie on tagged triangles; a face between two
  // tets is found twice and kept once.
  std::vector<std::pair<std::size_t, Face>> found; // (parent, sorted corners)
  for (const Tet& tet : output.tets)
  {
    for (int skip = 0; skip < 4; ++skip)
    {
      const Face face = sortedFace(tet.data(), skip);
      const Sources& a = sources[face[0]];
      const Sources& b = sources[face[1]];
      const Sources& c = sources[face[2]];
      if (a.count <= 0 || b.count <= 0 || c.count <= 0)
      {
        continue;
      }
      const auto range = index.find(sourceUnion(a, b, c));
      for (std::size_t e = range.first; e < range.second; ++e)
      {
        found.emplace_back(index.entries[e].second, face);
      }
    }
  }
  std::sort(found.begin(), found.end());
  found.erase(std::unique(found.begin(), found.end()), found.end());

  children.reserve(found.size());
  for (const auto& entry : found)
  {
    TriangleChild child{ entry.first, entry.second };
    if (dot(triangleNormal(output, child.corners), triangleNormal(input, triangles[child.parent])) <
      0)
    {
      std::swap(child.corners[1], child.corners[2]);
    }
    children.push_back(child);
  }
  return children;
}

} // namespace cgmesh
