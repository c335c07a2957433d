#include "cgmeshTetQuality.h"

#include "Core/TetQuality.h"
#include "ParallelFor.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkMeshQuality.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkTetra.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cstdint>

namespace cgmesh
{

Status addTetQualityArrays(vtkUnstructuredGrid* grid, int threads)
{
  const vtkIdType numberOfCells = grid->GetNumberOfCells();
  vtkNew<vtkDoubleArray> edgeRatio;
  edgeRatio->SetName("EdgeRatio");
  edgeRatio->SetNumberOfValues(numberOfCells);
  vtkNew<vtkDoubleArray> minDihedralAngle;
  minDihedralAngle->SetName("MinDihedralAngle");
  minDihedralAngle->SetNumberOfValues(numberOfCells);

  constexpr vtkIdType CellsPerBlock = 16384;
  const vtkIdType blocks = (numberOfCells + CellsPerBlock - 1) / CellsPerBlock;
  vtkPoints* points = grid->GetPoints();
  vtkCellArray* cells = grid->GetCells();
  // Each block writes only its own cells' values, so the blocks need no synchronisation.
  const Status status = runParallel(resolveThreadCount(threads), blocks,
    [&](std::int64_t block)
    {
      vtkNew<vtkTetra> tetra;
      vtkNew<vtkIdList> corners;
      double coordinates[3];
      const vtkIdType end = std::min(numberOfCells, (block + 1) * CellsPerBlock);
      for (vtkIdType cellId = block * CellsPerBlock; cellId < end; ++cellId)
      {
        cells->GetCellAtId(cellId, corners); // the id-list overload is safe to call concurrently
        for (vtkIdType corner = 0; corner < 4; ++corner)
        {
          points->GetPoint(corners->GetId(corner), coordinates);
          tetra->GetPoints()->SetPoint(corner, coordinates);
        }
        edgeRatio->SetValue(cellId, vtkMeshQuality::TetEdgeRatio(tetra));
        double p[4][3];
        for (int corner = 0; corner < 4; ++corner)
        {
          tetra->GetPoints()->GetPoint(corner, p[corner]);
        }
        minDihedralAngle->SetValue(cellId, minimumDihedralAngle(p[0], p[1], p[2], p[3]));
      }
    });
  if (status.ok())
  {
    grid->GetCellData()->AddArray(edgeRatio);
    grid->GetCellData()->AddArray(minDihedralAngle);
  }
  return status;
}

} // namespace cgmesh
