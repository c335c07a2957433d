#include "Validation/ContactGluing.h"

#include "Core/FaceKey.h"
#include "Core/Geometry.h"
#include "Core/LowestRootSets.h"
#include "Core/ParallelSort.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace cgmesh
{
namespace
{

// Pairs (p, q), p < q, of used points at most `tolerance` apart, in ascending order. Points are
// bucketed in a grid whose cells are 100 tolerances wide: small against any edge worth refining,
// so cells hold a point or two, and wide enough that a point must be looked for in a neighbouring
// cell only along axes where it lies within a tolerance of its cell's side (on 1 to 8 cells, not
// always 27). Cells are found by binary search in the sorted buckets, so no hashing order reaches
// the result.
Status coincidentPairs(const TetMesh& mesh, const std::vector<PointId>& used, const double low[3],
  double tolerance, const ParallelFor& parallelFor, std::vector<std::pair<PointId, PointId>>& pairs)
{
  using Cell = std::array<std::int64_t, 3>;
  const double cellSize = 100 * tolerance;
  const std::int64_t count = static_cast<std::int64_t>(used.size());
  std::vector<std::pair<Cell, PointId>> buckets(used.size());
  Status status = forEachRange(parallelFor, count, IndicesPerCopyRange,
    [&](std::int64_t begin, std::int64_t end)
    {
      for (std::int64_t i = begin; i < end; ++i)
      {
        const PointId p = used[i];
        Cell cell;
        for (int axis = 0; axis < 3; ++axis)
        {
          // At most 1 / (100 RelativeContactTolerance) cells per axis: no overflow.
          cell[axis] =
            static_cast<std::int64_t>(std::floor((mesh.point(p)[axis] - low[axis]) / cellSize));
        }
        buckets[i] = { cell, p };
      }
    });
  if (status.ok())
  {
    status = sortInParallel(buckets, parallelFor); // no two entries equal: the point ids differ
  }
  const double squaredTolerance = tolerance * tolerance;
  const double margin = 2.0 / 100; // a tolerance in cell widths, doubled against rounding
  // Each range of buckets collects its pairs; joined in range order, they are the serial scan's.
  const std::int64_t rangeSize = IndicesPerCopyRange;
  std::vector<std::vector<std::pair<PointId, PointId>>> pairsOfRange(
    (count + rangeSize - 1) / rangeSize);
  if (status.ok())
  {
    status = forEachRange(parallelFor, count, rangeSize,
      [&](std::int64_t begin, std::int64_t end)
      {
        auto& pairs = pairsOfRange[begin / rangeSize];
        for (std::int64_t i = begin; i < end; ++i)
        {
          const auto& [cell, p] = buckets[i];
          std::array<int, 3> from, to;
          for (int axis = 0; axis < 3; ++axis)
          {
            const double within = (mesh.point(p)[axis] - low[axis]) / cellSize - cell[axis];
            from[axis] = within < margin ? -1 : 0;
            to[axis] = within > 1 - margin ? 1 : 0;
          }
          for (int dx = from[0]; dx <= to[0]; ++dx)
          {
            for (int dy = from[1]; dy <= to[1]; ++dy)
            {
              for (int dz = from[2]; dz <= to[2]; ++dz)
              {
                const Cell neighbour = { cell[0] + dx, cell[1] + dy, cell[2] + dz };
                // The point's own cell, the only one for most points, is the run of equal cells
                // around it: found by stepping back, not by a search over all buckets.
                auto at = buckets.begin() + i;
                if (dx == 0 && dy == 0 && dz == 0)
                {
                  while (at != buckets.begin() && (at - 1)->first == cell)
                  {
                    --at;
                  }
                }
                else
                {
                  at = std::lower_bound(
                    buckets.begin(), buckets.end(), std::make_pair(neighbour, PointId(0)));
                }
                for (; at != buckets.end() && at->first == neighbour; ++at)
                {
                  const PointId q = at->second;
                  if (q != p && squaredDistance(mesh.point(p), mesh.point(q)) <= squaredTolerance)
                  {
                    pairs.emplace_back(std::min(p, q), std::max(p, q));
                  }
                }
              }
            }
          }
        }
      });
  }
  if (!status.ok())
  {
    return status;
  }
  pairs.clear();
  for (const auto& found : pairsOfRange)
  {
    pairs.insert(pairs.end(), found.begin(), found.end());
  }
  // Each pair was found from both ends (the neighbourhood test is not exactly symmetric).
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return Status::success();
}

// Compressed lists: the entries of key k are values[offsets[k] .. offsets[k + 1]).
struct Lists
{
  std::vector<std::size_t> offsets;
  std::vector<std::int64_t> values;

  Lists(std::size_t keys, const std::vector<std::pair<std::int64_t, std::int64_t>>& entries)
    : offsets(keys + 1, 0)
  {
    for (const auto& entry : entries)
    {
      ++this->offsets[entry.first + 1];
    }
    for (std::size_t k = 0; k < keys; ++k)
    {
      this->offsets[k + 1] += this->offsets[k];
    }
    this->values.resize(entries.size());
    std::vector<std::size_t> next(this->offsets.begin(), this->offsets.end() - 1);
    for (const auto& entry : entries) // in entry order: sorted entries give sorted lists
    {
      this->values[next[entry.first]++] = entry.second;
    }
  }
  const std::int64_t* begin(std::int64_t key) const { return this->values.data() + offsets[key]; }
  const std::int64_t* end(std::int64_t key) const { return this->values.data() + offsets[key + 1]; }
  bool empty(std::int64_t key) const { return offsets[key] == offsets[key + 1]; }
};

struct BoundaryFace
{
  Face corners; // ascending ids
  CellId tet;
};

// Boundary faces (held by one tet only) with a corner that coincides with another point: only
// those can have a copy. A face is held only by tets holding all its corners, so counting the
// faces of the tets with such a corner suffices, which keeps the face table to the contacts.
std::vector<BoundaryFace> contactFaceCandidates(const TetMesh& mesh, const Lists& partners)
{
  std::vector<PointId> corners;
  std::vector<CellId> tetOf;
  for (CellId t = 0; t < mesh.numberOfTets(); ++t)
  {
    const Tet& tet = mesh.tets[t];
    if (std::any_of(tet.begin(), tet.end(), [&](PointId p) { return !partners.empty(p); }))
    {
      corners.insert(corners.end(), tet.begin(), tet.end());
      tetOf.push_back(t);
    }
  }
  std::vector<BoundaryFace> faces;
  forEachDistinctFace(corners.data(), tetOf.size(),
    [&](const Face& face, std::size_t first, std::size_t, std::size_t count)
    {
      if (count == 1 &&
        std::any_of(face.begin(), face.end(), [&](PointId p) { return !partners.empty(p); }))
      {
        faces.push_back({ face, tetOf[first] });
      }
    });
  std::sort(faces.begin(), faces.end(),
    [](const BoundaryFace& a, const BoundaryFace& b) { return a.corners < b.corners; });
  return faces;
}

class FaceMatcher
{
public:
  FaceMatcher(const TetMesh& mesh, double tolerance)
    : Mesh(mesh)
    , SquaredTolerance(tolerance * tolerance)
  {
  }

  // The corner of `g` that each corner of `f` coincides with (the same point or one within the
  // tolerance), when both faces are copies of one face seen from opposite sides.
  bool match(const BoundaryFace& f, const BoundaryFace& g, std::array<PointId, 3>& partner) const
  {
    if (f.tet == g.tet || !this->wellSeparated(f.corners) || !this->wellSeparated(g.corners))
    {
      return false;
    }
    for (int k = 0; k < 3; ++k)
    {
      int found = 0;
      for (PointId q : g.corners)
      {
        if (this->coincide(f.corners[k], q))
        {
          partner[k] = q;
          ++found;
        }
      }
      if (found != 1)
      {
        return false;
      }
    }
    // Copies of one face bound tets on its two sides; two parts lying on top of each other
    // are not glued.
    std::array<double, 3> nf = this->outwardNormal(f), ng = this->outwardNormal(g);
    return nf[0] * ng[0] + nf[1] * ng[1] + nf[2] * ng[2] < 0;
  }

private:
  bool coincide(PointId p, PointId q) const
  {
    return p == q ||
      squaredDistance(this->Mesh.point(p), this->Mesh.point(q)) <= this->SquaredTolerance;
  }

  // Corners more than twice the tolerance apart: the corner correspondence is unambiguous and
  // merging cannot fold a tet.
  bool wellSeparated(const Face& face) const
  {
    const double limit = 4 * this->SquaredTolerance;
    return squaredDistance(this->Mesh.point(face[0]), this->Mesh.point(face[1])) > limit &&
      squaredDistance(this->Mesh.point(face[1]), this->Mesh.point(face[2])) > limit &&
      squaredDistance(this->Mesh.point(face[0]), this->Mesh.point(face[2])) > limit;
  }

  // The face's normal pointing away from its tet's fourth corner (whatever the tet's orientation).
  std::array<double, 3> outwardNormal(const BoundaryFace& face) const
  {
    const double* a = this->Mesh.point(face.corners[0]);
    const double* b = this->Mesh.point(face.corners[1]);
    const double* c = this->Mesh.point(face.corners[2]);
    PointId opposite = -1;
    for (PointId p : this->Mesh.tets[face.tet])
    {
      opposite =
        std::find(face.corners.begin(), face.corners.end(), p) == face.corners.end() ? p : opposite;
    }
    const double* o = this->Mesh.point(opposite);
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    std::array<double, 3> n = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
      u[0] * v[1] - u[1] * v[0] };
    const double side = n[0] * (o[0] - a[0]) + n[1] * (o[1] - a[1]) + n[2] * (o[2] - a[2]);
    if (side > 0)
    {
      n = { -n[0], -n[1], -n[2] };
    }
    return n;
  }

  const TetMesh& Mesh;
  double SquaredTolerance;
};

// Joins the corners of every pair of matching boundary faces.
void joinMatchingFaces(
  const TetMesh& mesh, const Lists& partners, double tolerance, LowestRootSets<PointId>& sets)
{
  const std::vector<BoundaryFace> faces = contactFaceCandidates(mesh, partners);
  std::vector<std::pair<std::int64_t, std::int64_t>> incidence; // (point, face), sorted
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    for (PointId p : faces[f].corners)
    {
      incidence.emplace_back(p, static_cast<std::int64_t>(f));
    }
  }
  std::sort(incidence.begin(), incidence.end());
  const Lists facesAt(static_cast<std::size_t>(mesh.numberOfPoints()), incidence);

  const FaceMatcher matcher(mesh, tolerance);
  std::vector<std::int64_t> candidates;
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    // A copy holds the first corner itself or a point coinciding with it.
    const PointId first = faces[f].corners[0];
    candidates.assign(facesAt.begin(first), facesAt.end(first));
    for (const std::int64_t* q = partners.begin(first); q != partners.end(first); ++q)
    {
      candidates.insert(candidates.end(), facesAt.begin(*q), facesAt.end(*q));
    }
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    for (std::int64_t g : candidates)
    {
      std::array<PointId, 3> partner;
      if (g > static_cast<std::int64_t>(f) && matcher.match(faces[f], faces[g], partner))
      {
        for (int k = 0; k < 3; ++k)
        {
          sets.join(faces[f].corners[k], partner[k]);
        }
      }
    }
  }
}

} // namespace

Status glueMatchingFaces(TetMesh& mesh, const std::vector<PointId>& used,
  const ParallelFor& parallelFor, ContactGluing& outcome)
{
  outcome = ContactGluing();
  if (used.empty())
  {
    return Status::success();
  }
  double low[3], high[3];
  for (int axis = 0; axis < 3; ++axis)
  {
    low[axis] = high[axis] = mesh.point(used[0])[axis];
  }
  for (PointId p : used)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      low[axis] = std::min(low[axis], mesh.point(p)[axis]);
      high[axis] = std::max(high[axis], mesh.point(p)[axis]);
    }
  }
  outcome.tolerance = RelativeContactTolerance * std::sqrt(squaredDistance(low, high));
  if (!(outcome.tolerance > 0))
  {
    return Status::success(); // every used point in one place: degenerate tets, refused later
  }

  std::vector<std::pair<PointId, PointId>> pairs;
  const Status status = coincidentPairs(mesh, used, low, outcome.tolerance, parallelFor, pairs);
  if (!status.ok() || pairs.empty())
  {
    return status; // or nothing coincides: every point is its own root
  }
  std::vector<std::pair<std::int64_t, std::int64_t>> symmetric;
  for (const auto& [p, q] : pairs)
  {
    symmetric.emplace_back(p, q);
    symmetric.emplace_back(q, p);
  }
  std::sort(symmetric.begin(), symmetric.end());
  const Lists partners(static_cast<std::size_t>(mesh.numberOfPoints()), symmetric);

  LowestRootSets<PointId> sets(mesh.numberOfPoints());
  joinMatchingFaces(mesh, partners, outcome.tolerance, sets);
  for (PointId p : used)
  {
    outcome.gluedPoints += sets.root(p) != p ? 1 : 0;
  }
  // Coincident points that stay distinct: of each such pair of representatives, the higher one
  // (what merging every coincident point would have dropped).
  std::vector<PointId> keptApart;
  for (const auto& [p, q] : pairs)
  {
    const PointId a = sets.root(p), b = sets.root(q);
    if (a != b)
    {
      keptApart.push_back(std::max(a, b));
    }
  }
  std::sort(keptApart.begin(), keptApart.end());
  keptApart.erase(std::unique(keptApart.begin(), keptApart.end()), keptApart.end());
  outcome.keptApartPoints = static_cast<PointId>(keptApart.size());
  outcome.firstKeptApart = keptApart.empty() ? -1 : keptApart.front();

  for (Tet& tet : mesh.tets)
  {
    for (PointId& p : tet)
    {
      p = sets.root(p);
    }
  }
  return Status::success();
}

} // namespace cgmesh
