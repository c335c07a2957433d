#include "FinFetGenerator.h"

#include "CubeGenerator.h"
#include "FinFetLayout.h"

#include <cmath>

namespace cgmesh
{
namespace
{

// Subdivides every interval between breakpoints into pieces no longer than `spacing`.
std::vector<double> gradedLines(const std::vector<double>& breaks, double spacing)
{
  std::vector<double> lines = { breaks.front() };
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
  {
    const double length = breaks[i + 1] - breaks[i];
    const int pieces = std::max(1, static_cast<int>(std::ceil(length / spacing - 1e-9)));
    for (int k = 1; k <= pieces; ++k)
    {
      lines.push_back(k == pieces ? breaks[i + 1] : breaks[i] + length * k / pieces);
    }
  }
  return lines;
}

std::int64_t tetCountFor(double spacing)
{
  std::int64_t cells = 6;
  for (int axis = 0; axis < 3; ++axis)
  {
    cells *= static_cast<std::int64_t>(gradedLines(finFetBreaks(axis), spacing).size() - 1);
  }
  return cells;
}

} // namespace

std::vector<std::string> finFetMaterialNames()
{
  return { "substrate", "buried oxide", "fin channel", "source", "drain", "gate oxide", "gate",
    "spacer", "isolation oxide" };
}

Status generateFinFet(std::int64_t targetTets, TetMesh& mesh)
{
  if (targetTets < 1000 || targetTets > 500000000)
  {
    return Status::failure("the FinFET needs between 1,000 and 500,000,000 tetrahedra");
  }
  // Bisection on the grid spacing for the tet count closest to the target.
  double coarse = 40, fine = 0.01;
  for (int step = 0; step < 60; ++step)
  {
    const double middle = std::sqrt(coarse * fine);
    (tetCountFor(middle) > targetTets ? fine : coarse) = middle;
  }
  const double spacing =
    std::abs(tetCountFor(coarse) - targetTets) <= std::abs(tetCountFor(fine) - targetTets) ? coarse
                                                                                           : fine;
  const GridLines lines = { gradedLines(finFetBreaks(0), spacing),
    gradedLines(finFetBreaks(1), spacing), gradedLines(finFetBreaks(2), spacing) };
  Status status = generateKuhnGrid(lines, mesh);
  if (!status.ok())
  {
    return status;
  }
  mesh.regions.reserve(mesh.tets.size());
  for (const Tet& tet : mesh.tets)
  {
    double centroid[3] = { 0, 0, 0 };
    for (PointId p : tet)
    {
      for (int axis = 0; axis < 3; ++axis)
      {
        centroid[axis] += 0.25 * mesh.point(p)[axis];
      }
    }
    mesh.regions.push_back(finFetMaterialAt(centroid[0], centroid[1], centroid[2]));
  }
  return Status::success();
}

} // namespace cgmesh
