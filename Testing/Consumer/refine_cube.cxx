// Refines a small tetrahedral cube with vtkCoarseGrainedMeshAdaptation from an installed cgmesh
// and checks the result: every edge is split, so each tet becomes eight.
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkCoarseGrainedMeshAdaptation.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include <array>
#include <cstdlib>
#include <iostream>
#include <utility>

namespace
{
// Sign of the determinant of the edge vectors from corner 0 (positive for VTK's orientation).
int OrientedVolumeSign(vtkPoints* points, const vtkIdType ids[4])
{
  double p[4][3];
  for (int v = 0; v < 4; ++v)
  {
    points->GetPoint(ids[v], p[v]);
  }
  double e[3][3];
  for (int v = 0; v < 3; ++v)
  {
    for (int c = 0; c < 3; ++c)
    {
      e[v][c] = p[v + 1][c] - p[0][c];
    }
  }
  const double determinant = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
    e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
    e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
  return determinant > 0 ? 1 : -1;
}

// An n x n x n grid of unit voxels, each cut into the six Kuhn tetrahedra around the diagonal
// from corner 0 to corner 7; neighbouring voxels then share their face diagonals (conforming).
vtkNew<vtkUnstructuredGrid> MakeKuhnCube(int n)
{
  vtkNew<vtkPoints> points;
  for (int k = 0; k <= n; ++k)
  {
    for (int j = 0; j <= n; ++j)
    {
      for (int i = 0; i <= n; ++i)
      {
        points->InsertNextPoint(i, j, k);
      }
    }
  }
  const auto pointId = [n](int i, int j, int k)
  {
    return i + (n + 1) * (j + (n + 1) * k);
  };
  // Corner c of a voxel has offset (c & 1, (c >> 1) & 1, (c >> 2) & 1).
  const std::array<std::array<int, 4>, 6> kuhnTets = { { { 0, 1, 3, 7 }, { 0, 1, 5, 7 },
    { 0, 2, 3, 7 }, { 0, 2, 6, 7 }, { 0, 4, 5, 7 }, { 0, 4, 6, 7 } } };

  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  grid->Allocate(6 * n * n * n);
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        for (const auto& tet : kuhnTets)
        {
          vtkIdType ids[4];
          for (int v = 0; v < 4; ++v)
          {
            const int c = tet[v];
            ids[v] = pointId(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
          }
          // Half of the Kuhn tets come out mirrored: swap two corners to orient all alike.
          if (OrientedVolumeSign(points, ids) < 0)
          {
            std::swap(ids[2], ids[3]);
          }
          grid->InsertNextCell(VTK_TETRA, 4, ids);
        }
      }
    }
  }
  return grid;
}
}

int main()
{
  vtkNew<vtkUnstructuredGrid> cube = MakeKuhnCube(4);

  vtkNew<vtkCoarseGrainedMeshAdaptation> adaptation;
  adaptation->SetInputData(cube);
  adaptation->SetNumberOfPartitions(8);
  adaptation->SetMaximumEdgeLength(0.5); // below every edge of the unit voxels
  adaptation->SetNumberOfThreads(2);
  adaptation->Update();

  vtkUnstructuredGrid* refined = adaptation->GetOutput();
  const vtkIdType expected = 8 * cube->GetNumberOfCells();
  if (refined->GetNumberOfCells() != expected)
  {
    std::cerr << "expected " << expected << " cells, got " << refined->GetNumberOfCells() << "\n";
    return EXIT_FAILURE;
  }
  for (const char* name : { "PartitionId", "ColorId", "EdgeRatio", "MinDihedralAngle" })
  {
    if (!refined->GetCellData()->GetArray(name))
    {
      std::cerr << "cell array " << name << " missing\n";
      return EXIT_FAILURE;
    }
  }
  std::cout << "refined " << cube->GetNumberOfCells() << " -> " << refined->GetNumberOfCells()
            << " tets\n";
  return EXIT_SUCCESS;
}
