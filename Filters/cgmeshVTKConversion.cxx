#include "cgmeshVTKConversion.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <limits>

namespace cgmesh
{

vtkIdType countNonTetrahedra(vtkUnstructuredGrid* grid)
{
  vtkIdType count = 0;
  const vtkIdType numberOfCells = grid->GetNumberOfCells();
  for (vtkIdType cellId = 0; cellId < numberOfCells; ++cellId)
  {
    if (grid->GetCellType(cellId) != VTK_TETRA)
    {
      ++count;
    }
  }
  return count;
}

namespace
{

void copyPoints(vtkUnstructuredGrid* grid, TetMesh& mesh)
{
  const vtkIdType numberOfPoints = grid->GetNumberOfPoints();
  mesh.coordinates.resize(3 * static_cast<size_t>(numberOfPoints));
  vtkPoints* points = grid->GetPoints();
  for (vtkIdType pointId = 0; pointId < numberOfPoints; ++pointId)
  {
    points->GetPoint(pointId, mesh.coordinates.data() + 3 * pointId);
  }
}

Status copyTetrahedra(vtkUnstructuredGrid* grid, TetMesh& mesh)
{
  mesh.tets.resize(static_cast<size_t>(grid->GetNumberOfCells()));
  auto iterator = vtk::TakeSmartPointer(grid->GetCells()->NewIterator());
  size_t tetIndex = 0;
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
  {
    vtkIdType numberOfCellPoints;
    const vtkIdType* cellPoints;
    iterator->GetCurrentCell(numberOfCellPoints, cellPoints);
    if (numberOfCellPoints != 4)
    {
      return Status::failure("a tetrahedron does not have 4 points");
    }
    for (int corner = 0; corner < 4; ++corner)
    {
      mesh.tets[tetIndex][corner] = static_cast<PointId>(cellPoints[corner]);
    }
    ++tetIndex;
  }
  return Status::success();
}

Status copyRegions(vtkUnstructuredGrid* grid, const std::string& regionArrayName, TetMesh& mesh)
{
  vtkAbstractArray* abstractArray = grid->GetCellData()->GetAbstractArray(regionArrayName.c_str());
  if (!abstractArray)
  {
    return Status::failure(
      "region array '" + regionArrayName + "' is not a cell array of the input");
  }
  vtkDataArray* regionArray = vtkDataArray::SafeDownCast(abstractArray);
  if (!regionArray)
  {
    return Status::failure("region array '" + regionArrayName + "' is not numeric");
  }
  const vtkIdType numberOfCells = grid->GetNumberOfCells();
  mesh.regions.resize(static_cast<size_t>(numberOfCells));
  for (vtkIdType cellId = 0; cellId < numberOfCells; ++cellId)
  {
    // Labels stored as floating point are rounded, not truncated (2.9999999 is region 3).
    const double value = std::round(regionArray->GetComponent(cellId, 0));
    if (!(std::abs(value) <= static_cast<double>(std::numeric_limits<int>::max())))
    {
      return Status::failure(
        "region array '" + regionArrayName + "' holds a value that is not a valid int");
    }
    mesh.regions[cellId] = static_cast<int>(value);
  }
  return Status::success();
}

} // namespace

Status convertToTetMesh(
  vtkUnstructuredGrid* grid, const std::string& regionArrayName, TetMesh& mesh)
{
  mesh = TetMesh();
  if (grid->GetNumberOfPoints() > 0)
  {
    copyPoints(grid, mesh);
  }
  if (grid->GetNumberOfCells() > 0)
  {
    Status status = copyTetrahedra(grid, mesh);
    if (!status.ok())
    {
      return status;
    }
  }
  if (!regionArrayName.empty())
  {
    return copyRegions(grid, regionArrayName, mesh);
  }
  return Status::success();
}

void convertToUnstructuredGrid(
  const TetMesh& mesh, vtkUnstructuredGrid* grid, const std::string& regionArrayName)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(mesh.numberOfPoints());
  for (PointId pointId = 0; pointId < mesh.numberOfPoints(); ++pointId)
  {
    points->SetPoint(pointId, mesh.point(pointId));
  }

  const vtkIdType numberOfTets = mesh.numberOfTets();
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(numberOfTets + 1);
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(4 * numberOfTets);
  for (vtkIdType tetId = 0; tetId < numberOfTets; ++tetId)
  {
    offsets->SetValue(tetId, 4 * tetId);
    for (int corner = 0; corner < 4; ++corner)
    {
      connectivity->SetValue(4 * tetId + corner, static_cast<vtkIdType>(mesh.tets[tetId][corner]));
    }
  }
  offsets->SetValue(numberOfTets, 4 * numberOfTets);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);

  grid->Initialize();
  grid->SetPoints(points);
  grid->SetCells(VTK_TETRA, cells);

  if (mesh.hasRegions() && !regionArrayName.empty())
  {
    vtkNew<vtkIntArray> regions;
    regions->SetName(regionArrayName.c_str());
    regions->SetNumberOfValues(numberOfTets);
    for (vtkIdType tetId = 0; tetId < numberOfTets; ++tetId)
    {
      regions->SetValue(tetId, mesh.regions[tetId]);
    }
    grid->GetCellData()->AddArray(regions);
  }
}

} // namespace cgmesh
