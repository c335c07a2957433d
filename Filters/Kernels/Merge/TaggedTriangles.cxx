#include "Merge/TaggedTriangles.h"

#include "Core/FaceKey.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

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

// The tagged triangles in a uniform grid over their bounding boxes, for finding the ones that
// hold a point. Cells about as large as a triangle, at most GridCellsPerAxis per axis.
class TriangleGrid
{
public:
  TriangleGrid(const TetMesh& mesh, const std::vector<Triangle>& triangles)
  {
    double extent = 0;
    for (int axis = 0; axis < 3; ++axis)
    {
      this->Low[axis] = HUGE_VAL;
      this->High[axis] = -HUGE_VAL;
    }
    for (const Triangle& triangle : triangles)
    {
      double low[3], high[3];
      this->boundsOf(mesh, triangle, low, high);
      double largest = 0;
      for (int axis = 0; axis < 3; ++axis)
      {
        this->Low[axis] = std::min(this->Low[axis], low[axis]);
        this->High[axis] = std::max(this->High[axis], high[axis]);
        largest = std::max(largest, high[axis] - low[axis]);
      }
      extent += largest;
    }
    double cell = triangles.empty() ? 1 : extent / static_cast<double>(triangles.size());
    for (int axis = 0; axis < 3; ++axis)
    {
      cell = std::max(cell, (this->High[axis] - this->Low[axis]) / GridCellsPerAxis);
    }
    this->Cell = cell > 0 ? cell : 1;
    for (int axis = 0; axis < 3; ++axis)
    {
      this->Cells[axis] = std::max<std::int64_t>(
        1, static_cast<std::int64_t>(std::ceil((this->High[axis] - this->Low[axis]) / this->Cell)));
    }
    // Counting sort of (cell, triangle) pairs into compressed rows.
    std::vector<std::pair<std::int64_t, std::size_t>> pairs;
    for (std::size_t t = 0; t < triangles.size(); ++t)
    {
      double low[3], high[3];
      this->boundsOf(mesh, triangles[t], low, high);
      std::int64_t first[3], last[3];
      for (int axis = 0; axis < 3; ++axis)
      {
        first[axis] = this->cellAlong(axis, low[axis]);
        last[axis] = this->cellAlong(axis, high[axis]);
      }
      for (std::int64_t i = first[0]; i <= last[0]; ++i)
      {
        for (std::int64_t j = first[1]; j <= last[1]; ++j)
        {
          for (std::int64_t k = first[2]; k <= last[2]; ++k)
          {
            pairs.emplace_back((i * this->Cells[1] + j) * this->Cells[2] + k, t);
          }
        }
      }
    }
    std::sort(pairs.begin(), pairs.end());
    this->Start.assign(
      static_cast<std::size_t>(this->Cells[0] * this->Cells[1] * this->Cells[2]) + 1, 0);
    for (const auto& pair : pairs)
    {
      ++this->Start[static_cast<std::size_t>(pair.first) + 1];
      this->Members.push_back(pair.second);
    }
    for (std::size_t c = 1; c < this->Start.size(); ++c)
    {
      this->Start[c] += this->Start[c - 1];
    }
  }

  // Calls visit(t) for every triangle whose cell holds `point` (none outside the grid).
  template <typename Visit>
  void forEachNear(const double point[3], Visit&& visit) const
  {
    std::int64_t index = 0;
    for (int axis = 0; axis < 3; ++axis)
    {
      const double offset = (point[axis] - this->Low[axis]) / this->Cell;
      if (!(offset >= -1e-9 * this->Cells[axis] && offset <= this->Cells[axis] * (1 + 1e-9)))
      {
        return;
      }
      index = index * this->Cells[axis] + this->cellAlong(axis, point[axis]);
    }
    for (std::size_t m = this->Start[static_cast<std::size_t>(index)];
         m < this->Start[static_cast<std::size_t>(index) + 1]; ++m)
    {
      visit(this->Members[m]);
    }
  }

private:
  static constexpr double GridCellsPerAxis = 256;

  static void boundsOf(const TetMesh& mesh, const Triangle& triangle, double low[3], double high[3])
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      low[axis] = HUGE_VAL;
      high[axis] = -HUGE_VAL;
      for (PointId p : triangle)
      {
        low[axis] = std::min(low[axis], mesh.point(p)[axis]);
        high[axis] = std::max(high[axis], mesh.point(p)[axis]);
      }
    }
  }

  // The cell along `axis` of coordinate `x`, clamped to the grid; a triangle is entered in every
  // cell its box touches, so a point on a cell's border finds it from either side.
  std::int64_t cellAlong(int axis, double x) const
  {
    const auto cell = static_cast<std::int64_t>(std::floor((x - this->Low[axis]) / this->Cell));
    return std::min(std::max<std::int64_t>(cell, 0), this->Cells[axis] - 1);
  }

  double Low[3], High[3];
  double Cell = 1;
  std::int64_t Cells[3] = { 1, 1, 1 };
  std::vector<std::size_t> Start;   // per cell, its first entry in Members
  std::vector<std::size_t> Members; // triangle indices, cell by cell
};

// Whether `point` lies in triangle (a, b, c) and `normal` is parallel to it, both within rounding
// of coordinates as large as the triangle's edges.
bool holds(const double* a, const double* b, const double* c, const double point[3],
  const std::array<double, 3>& normal)
{
  const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  const double w[3] = { point[0] - a[0], point[1] - a[1], point[2] - a[2] };
  const std::array<double, 3> n = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
    u[0] * v[1] - u[1] * v[0] };
  const double area2 = std::sqrt(dot(n, n));
  const double longest = std::sqrt(
    std::max({ u[0] * u[0] + u[1] * u[1] + u[2] * u[2], v[0] * v[0] + v[1] * v[1] + v[2] * v[2],
      (c[0] - b[0]) * (c[0] - b[0]) + (c[1] - b[1]) * (c[1] - b[1]) +
        (c[2] - b[2]) * (c[2] - b[2]) }));
  const double normalLength = std::sqrt(dot(normal, normal));
  if (!(area2 > 0) || !(normalLength > 0))
  {
    return false;
  }
  // Off the plane by at most a millionth of the longest edge, and facing the same line.
  const std::array<double, 3> offset = { w[0], w[1], w[2] };
  if (std::abs(dot(offset, n)) > 1e-6 * longest * area2 ||
    std::abs(dot(normal, n)) < (1 - 1e-6) * normalLength * area2)
  {
    return false;
  }
  // Barycentric coordinates in the plane, from the sub-triangles' signed areas.
  const auto signedArea = [&](const double* p, const double* q)
  {
    const double e[3] = { q[0] - p[0], q[1] - p[1], q[2] - p[2] };
    const double f[3] = { point[0] - p[0], point[1] - p[1], point[2] - p[2] };
    const std::array<double, 3> cross = { e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2],
      e[0] * f[1] - e[1] * f[0] };
    return dot(cross, n) / (area2 * area2);
  };
  const double slack = -1e-9;
  return signedArea(a, b) >= slack && signedArea(b, c) >= slack && signedArea(c, a) >= slack;
}

// The children found as (parent, sorted corners), in that order, each turned to face the way its
// parent does.
std::vector<TriangleChild> orientedChildren(const std::vector<std::pair<std::size_t, Face>>& found,
  const TetMesh& input, const std::vector<Triangle>& triangles, const TetMesh& output)
{
  std::vector<TriangleChild> children;
  children.reserve(found.size());
  for (const auto& [parent, corners] : found)
  {
    TriangleChild child{ parent, corners };
    if (dot(triangleNormal(output, child.corners), triangleNormal(input, triangles[parent])) < 0)
    {
      std::swap(child.corners[1], child.corners[2]);
    }
    children.push_back(child);
  }
  return children;
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
  if (triangles.empty())
  {
    return {};
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
  return orientedChildren(found, input, triangles, output);
}

std::vector<TriangleChild> findTriangleChildrenByPosition(
  const TetMesh& input, const std::vector<Triangle>& triangles, const TetMesh& output)
{
  if (triangles.empty() || output.tets.empty())
  {
    return {};
  }
  const TriangleGrid grid(input, triangles);
  const TriangleIndex index(triangles);
  std::vector<std::pair<std::size_t, Face>> found; // (parent, sorted corners)
  forEachDistinctFace(output.tets.front().data(), output.tets.size(),
    [&](const Face& face, std::uint32_t first, std::uint32_t second, std::uint32_t count)
    {
      // Only faces refinement keeps as faces can carry a tag: the boundary and region interfaces.
      if (count > 2 ||
        (count == 2 && (!output.hasRegions() || output.regions[first] == output.regions[second])))
      {
        return;
      }
      double centroid[3] = { 0, 0, 0 };
      for (PointId p : face)
      {
        for (int axis = 0; axis < 3; ++axis)
        {
          centroid[axis] += output.point(p)[axis] / 3;
        }
      }
      const std::array<double, 3> normal = triangleNormal(output, face);
      std::size_t parent = triangles.size();
      grid.forEachNear(centroid,
        [&](std::size_t t)
        {
          const Triangle& corners = triangles[t];
          if (t < parent &&
            holds(input.point(corners[0]), input.point(corners[1]), input.point(corners[2]),
              centroid, normal))
          {
            parent = t;
          }
        });
      if (parent == triangles.size())
      {
        return;
      }
      // The parent, and any triangle listed at the same corners (one face in two tag sets).
      Face corners = triangles[parent];
      std::sort(corners.begin(), corners.end());
      const auto range = index.find(corners);
      for (std::size_t e = range.first; e < range.second; ++e)
      {
        found.emplace_back(index.entries[e].second, face);
      }
    });
  std::sort(found.begin(), found.end());
  return orientedChildren(found, input, triangles, output);
}

} // namespace cgmesh
