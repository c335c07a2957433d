// The quality arrays of a whole grid (cgmeshTetQuality.h) compute many tets at once in vector
// lanes; each value must be the very bits the one-tet functions of Core/TetQuality.h give, for
// good, poor, inverted, flat and coincident tets, for triangles among the tets, and for cell counts
// that leave part of a lane block or of a thread block empty.
#include "FilterTestSupport.h"

#include "Core/TetQuality.h"
#include "cgmeshTetQuality.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <cstring>
#include <iostream>
#include <random>
#include <vector>

namespace
{

bool sameBits(double a, double b)
{
  return std::memcmp(&a, &b, sizeof(double)) == 0;
}

// `cellCount` cells over random points and a few exact special shapes; every 97th cell is a
// triangle, whose values must be NaN.
vtkSmartPointer<vtkUnstructuredGrid> gridOfAwkwardTets(vtkIdType cellCount, unsigned seed)
{
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int p = 0; p < 200; ++p)
  {
    points->InsertNextPoint(coordinate(random), coordinate(random), coordinate(random));
  }
  // Exact shapes: the unit right-corner tet, a flat one, a needle and a point four times over.
  const double special[][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 1, 0 },
    { 0.5, 0.5, 0 }, { 1e-9, 0, 0 }, { 2e-9, 1e-12, 0 }, { 1e150, 1e150, 0 }, { 0, 1e150, 1e150 } };
  const vtkIdType firstSpecial = points->GetNumberOfPoints();
  for (const auto& xyz : special)
  {
    points->InsertNextPoint(xyz);
  }
  const vtkIdType specialTets[][4] = { { 0, 1, 2, 3 }, { 0, 2, 1, 3 }, { 0, 1, 2, 4 },
    { 0, 1, 4, 5 }, { 0, 6, 7, 3 }, { 0, 0, 0, 0 }, { 0, 0, 1, 2 }, { 0, 1, 8, 9 } };

  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  grid->Allocate(cellCount);
  std::uniform_int_distribution<vtkIdType> pick(0, 199);
  for (vtkIdType cell = 0; cell < cellCount; ++cell)
  {
    if (cell % 97 == 50)
    {
      const vtkIdType triangle[3] = { pick(random), pick(random), pick(random) };
      grid->InsertNextCell(VTK_TRIANGLE, 3, triangle);
      continue;
    }
    vtkIdType corners[4];
    if (cell % 13 == 5)
    {
      const auto& tet = specialTets[(cell / 13) % 8];
      for (int k = 0; k < 4; ++k)
      {
        corners[k] = firstSpecial + tet[k];
      }
    }
    else
    {
      for (vtkIdType& corner : corners)
      {
        corner = pick(random);
      }
    }
    grid->InsertNextCell(VTK_TETRA, 4, corners);
  }
  return grid;
}

void checkArraysMatchOneTetFunctions(vtkIdType cellCount, int threads)
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = gridOfAwkwardTets(cellCount, 7 + cellCount);
  CGMESH_CHECK(cgmesh::addTetQualityArrays(grid, threads).ok(), "quality arrays computed");
  auto* ratios = vtkDoubleArray::SafeDownCast(grid->GetCellData()->GetArray("EdgeRatio"));
  auto* angles = vtkDoubleArray::SafeDownCast(grid->GetCellData()->GetArray("MinDihedralAngle"));
  CGMESH_CHECK(ratios && angles, "both arrays present as doubles");
  if (!ratios || !angles)
  {
    return;
  }
  CGMESH_CHECK(ratios->GetNumberOfValues() == cellCount && angles->GetNumberOfValues() == cellCount,
    "one value per cell");
  vtkIdType mismatches = 0, nonTetsWithValues = 0, specialSeen = 0;
  for (vtkIdType cell = 0; cell < cellCount; ++cell)
  {
    if (grid->GetCellType(cell) != VTK_TETRA)
    {
      nonTetsWithValues +=
        !std::isnan(ratios->GetValue(cell)) || !std::isnan(angles->GetValue(cell));
      continue;
    }
    const vtkIdType* corners = nullptr;
    vtkIdType count = 0;
    grid->GetCellPoints(cell, count, corners);
    double p[4][3];
    for (int k = 0; k < 4; ++k)
    {
      grid->GetPoint(corners[k], p[k]);
    }
    const double ratio = cgmesh::edgeRatio(p[0], p[1], p[2], p[3]);
    const double angle = cgmesh::minimumDihedralAngle(p[0], p[1], p[2], p[3]);
    specialSeen += !std::isfinite(ratio) || angle == 180.0 || std::isnan(angle);
    if (!sameBits(ratios->GetValue(cell), ratio) || !sameBits(angles->GetValue(cell), angle))
    {
      if (mismatches++ < 5)
      {
        std::cerr << "cell " << cell << ": arrays " << ratios->GetValue(cell) << ", "
                  << angles->GetValue(cell) << "; one-tet functions " << ratio << ", " << angle
                  << "\n";
      }
    }
  }
  CGMESH_CHECK(mismatches == 0, "every value is the one-tet functions' bits");
  CGMESH_CHECK(nonTetsWithValues == 0, "triangles get NaN");
  CGMESH_CHECK(cellCount < 100 || specialSeen > 0, "degenerate tets were among the cells");
}

void checkKnownValues()
{
  // The unit right-corner tet: dihedral angles 90 (three) and acos(1/sqrt(3)) (three), the
  // smallest 54.7356 degrees; edges 1 and sqrt(2).
  const double o[3] = { 0, 0, 0 }, x[3] = { 1, 0, 0 }, y[3] = { 0, 1, 0 }, z[3] = { 0, 0, 1 };
  CGMESH_CHECK(std::abs(cgmesh::minimumDihedralAngle(o, x, y, z) -
                 std::acos(1 / std::sqrt(3.0)) * 180 / M_PI) < 1e-12,
    "right-corner tet's smallest dihedral angle");
  CGMESH_CHECK(std::abs(cgmesh::edgeRatio(o, x, y, z) - std::sqrt(2.0)) < 1e-15,
    "right-corner tet's edge ratio");
}

} // namespace

int main()
{
  checkKnownValues();
  // Cell counts: fewer than one lane block, a lane block's tail, and past one thread block.
  for (vtkIdType cellCount : { 5, 16, 1001, 16384 + 37 })
  {
    for (int threads : { 1, 2 })
    {
      checkArraysMatchOneTetFunctions(cellCount, threads);
    }
  }
  if (cgmesh_test::FailureCount > 0)
  {
    std::cerr << cgmesh_test::FailureCount << " check(s) failed\n";
    return 1;
  }
  std::cout << "tet quality arrays: all checks passed\n";
  return 0;
}
