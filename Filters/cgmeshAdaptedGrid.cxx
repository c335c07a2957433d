#include "cgmeshAdaptedGrid.h"

#include "cgmeshPointData.h"
#include "cgmeshVTKConversion.h"

#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace cgmesh
{

namespace
{

// One value per tet, then `fill` for each triangle after them.
template <typename Array, typename Values>
void addCellArray(vtkCellData* cellData, const char* name, const Values& perTet,
  vtkIdType numberOfCells, typename Array::ValueType fill)
{
  vtkNew<Array> array;
  array->SetName(name);
  array->SetNumberOfValues(numberOfCells);
  const vtkIdType tets = static_cast<vtkIdType>(perTet.size());
  for (vtkIdType cellId = 0; cellId < numberOfCells; ++cellId)
  {
    array->SetValue(
      cellId, cellId < tets ? static_cast<typename Array::ValueType>(perTet[cellId]) : fill);
  }
  cellData->AddArray(array);
}

} // namespace

void fillAdaptedGrid(
  const AdaptedGridInput& input, const AdaptationResult& result, vtkUnstructuredGrid* output)
{
  convertToUnstructuredGrid(result.mesh, output);
  // Input cell id of every output cell: the tets' parents are indices among the input's tets.
  std::vector<vtkIdType> parentOf(result.parentCell.size());
  for (std::size_t cellId = 0; cellId < parentOf.size(); ++cellId)
  {
    const CellId parent = result.parentCell[cellId];
    parentOf[cellId] = input.triangles ? input.triangles->tetCellIds[parent] : parent;
  }
  if (input.triangles)
  {
    const std::vector<TriangleChild> children =
      findTriangleChildren(*input.mesh, input.triangles->triangles, result.mesh, result.provenance);
    appendTriangles(children, output);
    for (const TriangleChild& child : children)
    {
      parentOf.push_back(input.triangles->triangleCellIds[child.parent]);
    }
  }
  // Every output cell receives all cell data of the input cell it came from.
  copyCellData(input.grid->GetCellData(), parentOf, output->GetCellData());
  if (!result.provenance.offsets.empty() && input.grid->GetPointData()->GetNumberOfArrays() > 0)
  {
    transferPointData(input.grid->GetPointData(), result.provenance,
      splitNames(input.interpolatedPointArrays), splitNames(input.labelPointArrays),
      output->GetPointData());
  }

  vtkCellData* cellData = output->GetCellData();
  const vtkIdType cells = output->GetNumberOfCells();
  addCellArray<vtkIntArray>(cellData, "PartitionId", result.partitionOfCell, cells, -1);
  addCellArray<vtkIntArray>(cellData, "ColorId", result.colorOfCell, cells, -1);
  addCellArray<vtkUnsignedCharArray>(
    cellData, "NearFormerInterface", result.nearFormerInterface, cells, 0);
  if (!result.edgeLengthRatio.empty())
  {
    addCellArray<vtkDoubleArray>(cellData, "EdgeLengthRatio", result.edgeLengthRatio, cells,
      std::numeric_limits<double>::quiet_NaN());
  }
}

} // namespace cgmesh
