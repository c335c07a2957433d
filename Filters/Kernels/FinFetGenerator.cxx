#include "FinFetGenerator.h"

#include "CubeGenerator.h"

#include <cmath>

namespace cgmesh
{
namespace
{

// Material breakpoints along each axis (nm). x: source | spacer | gate | spacer | drain;
// y: isolation | gate | oxide | fin | oxide | gate | isolation; z: substrate | buried oxide |
// fin | top oxide | gate.
const std::vector<double> XBreaks = { 0, 15, 20, 40, 45, 60 };
const std::vector<double> YBreaks = { -17, -11, -7, -5, 5, 7, 11, 17 };
const std::vector<double> ZBreaks = { 0, 20, 30, 60, 62, 72 };

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

bool inside(double value, double low, double high)
{
  return value > low && value < high;
}

FinFetMaterial materialAt(double x, double y, double z)
{
  if (z < 20)
  {
    return Substrate;
  }
  if (z < 30)
  {
    return BuriedOxide;
  }
  const bool underGate = inside(x, 20, 40);
  const bool inSpacer = inside(x, 15, 20) || inside(x, 40, 45);
  if (inside(y, -5, 5) && z < 60)
  {
    return underGate ? FinChannel : (x < 30 ? Source : Drain);
  }
  const bool besideFin = inside(y, -7, 7) && z < 62;
  if (underGate)
  {
    return besideFin ? GateOxide : (inside(y, -11, 11) ? Gate : Isolation);
  }
  return inSpacer && inside(y, -11, 11) ? Spacer : Isolation;
}

std::int64_t tetCountFor(double spacing)
{
  std::int64_t cells = 6;
  for (const auto* breaks : { &XBreaks, &YBreaks, &ZBreaks })
  {
    cells *= static_cast<std::int64_t>(gradedLines(*breaks, spacing).size() - 1);
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
  const GridLines lines = { gradedLines(XBreaks, spacing), gradedLines(YBreaks, spacing),
    gradedLines(ZBreaks, spacing) };
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
    mesh.regions.push_back(materialAt(centroid[0], centroid[1], centroid[2]));
  }
  return Status::success();
}

} // namespace cgmesh
