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

// Comma-separated names, trimmed; empty entries dropped.
std::vector<std::string> splitNames(const std::string& text)
{
  std::vector<std::string> names;
  std::size_t start = 0;
  while (start <= text.size())
  {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    std::string name = text.substr(start, comma - start);
    name.erase(0, name.find_first_not_of(" \t"));
    name.erase(name.find_last_not_of(" \t") + 1);
    if (!name.empty())
    {
      names.push_back(name);
    }
    start = comma + 1;
  }
  return names;
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
      splitNames(input.interpolatedPointArrays), output->GetPointData());
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
