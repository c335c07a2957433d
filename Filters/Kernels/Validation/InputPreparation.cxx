#include "Validation/InputPreparation.h"

#include "Core/Geometry.h"
#include "Validation/ContactGluing.h"

#include <algorithm>
#include <cmath>

namespace cgmesh
{
namespace
{

Status checkCoordinates(const TetMesh& mesh)
{
  std::vector<char> used(mesh.numberOfPoints(), 0);
  for (const Tet& tet : mesh.tets)
  {
    for (PointId p : tet)
    {
      used[p] = 1;
    }
  }
  PointId nonFinite = 0, first = -1;
  for (PointId p = 0; p < mesh.numberOfPoints(); ++p)
  {
    const double* x = mesh.point(p);
    if (used[p] && !(std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2])))
    {
      first = nonFinite++ == 0 ? p : first;
    }
  }
  if (nonFinite > 0)
  {
    return Status::failure(ErrorKind::InvalidInput,
      std::to_string(nonFinite) + " points have NaN or infinite coordinates (the first is point " +
        std::to_string(first) + ")");
  }
  return Status::success();
}

// Reorients inverted tets; refuses tets whose volume is zero relative to their size. Ranges of
// tets are checked concurrently and their counts added in range order.
Status orientTets(TetMesh& mesh, InputRepairs& repairs, const ParallelFor& parallelFor)
{
  struct Counts
  {
    CellId degenerate = 0, firstDegenerate = -1, reoriented = 0;
  };
  const std::int64_t rangeSize = IndicesPerCopyRange;
  std::vector<Counts> countsOfRange((mesh.numberOfTets() + rangeSize - 1) / rangeSize);
  const Status status = forEachRange(parallelFor, mesh.numberOfTets(), rangeSize,
    [&](std::int64_t begin, std::int64_t end)
    {
      Counts& counts = countsOfRange[begin / rangeSize];
      for (CellId t = begin; t < end; ++t)
      {
        Tet& tet = mesh.tets[t];
        double longestSquared = 0;
        for (const auto& edge : TetEdgeCorners)
        {
          longestSquared =
            std::max(longestSquared, squaredEdgeLength(mesh, tet[edge[0]], tet[edge[1]]));
        }
        const double volume6 = signedVolume6(mesh, tet);
        if (!(std::abs(volume6) > 1e-12 * longestSquared * std::sqrt(longestSquared)))
        {
          counts.firstDegenerate = counts.degenerate++ == 0 ? t : counts.firstDegenerate;
        }
        else if (volume6 < 0)
        {
          std::swap(tet[2], tet[3]);
          ++counts.reoriented;
        }
      }
    });
  if (!status.ok())
  {
    return status;
  }
  CellId degenerate = 0, first = -1;
  for (const Counts& counts : countsOfRange)
  {
    first = degenerate == 0 ? counts.firstDegenerate : first;
    degenerate += counts.degenerate;
    repairs.reorientedTets += counts.reoriented;
  }
  if (degenerate > 0)
  {
    return Status::failure(ErrorKind::InvalidInput,
      std::to_string(degenerate) +
        " tetrahedra have zero volume or repeat a point (the first is cell " +
        std::to_string(first) + "); remove them before refining");
  }
  return Status::success();
}

} // namespace

Status prepareInput(
  const TetMesh& input, TetMesh& prepared, InputRepairs& repairs, const ParallelFor& parallelFor)
{
  repairs = InputRepairs();
  prepared = input;
  Status status = checkCoordinates(prepared);
  if (!status.ok())
  {
    return status;
  }
  ContactGluing gluing;
  status = glueMatchingFaces(prepared, parallelFor, gluing);
  if (!status.ok())
  {
    return status;
  }
  repairs.gluedPoints = gluing.gluedPoints;
  repairs.keptApartPoints = gluing.keptApartPoints;
  repairs.firstKeptApartPoint = gluing.firstKeptApart;
  return orientTets(prepared, repairs, parallelFor);
}

} // namespace cgmesh
