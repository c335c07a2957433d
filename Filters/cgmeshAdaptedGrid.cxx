#include "cgmeshAdaptedGrid.h"

#include "cgmeshPointData.h"
#include "cgmeshVTKConversion.h"

#include "ParallelFor.h"

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
  vtkIdType numberOfCells, typename Array::ValueType fill, const ParallelFor& parallelFor)
{
  vtkNew<Array> array;
  array->SetName(name);
  array->SetNumberOfValues(numberOfCells);
  auto* value = array->GetPointer(0);
  const vtkIdType tets = static_cast<vtkIdType>(perTet.size());
  forEachRange(parallelFor, numberOfCells, IndicesPerCopyRange,
    [&](std::int64_t begin, std::int64_t end)
    {
      for (std::int64_t cellId = begin; cellId < end; ++cellId)
      {
        value[cellId] =
          cellId < tets ? static_cast<typename Array::ValueType>(perTet[cellId]) : fill;
      }
    });
  cellData->AddArray(array);
}

} // namespace

void fillAdaptedGrid(
  const AdaptedGridInput& input, const AdaptationResult& result, vtkUnstructuredGrid* output)
{
  const ParallelFor parallelFor = parallelForOn(result.summary.plan.threads);
  convertToUnstructuredGrid(result.mesh, output, std::string(), parallelFor);
  std::vector<vtkIdType> triangleParents; // input cell ids of the triangles appended
  if (input.triangles)
  {
    const std::vector<TriangleChild> children =
      findTriangleChildren(*input.mesh, input.triangles->triangles, result.mesh, result.provenance);
    appendTriangles(children, output);
    for (const TriangleChild& child : children)
    {
      triangleParents.push_back(input.triangles->triangleCellIds[child.parent]);
    }
  }
  // Input cell id of every output cell: the tets' parents are indices among the input's tets.
  const vtkIdType tets = static_cast<vtkIdType>(result.parentCell.size());
  const auto parentOf = [&](vtkIdType cellId) -> vtkIdType
  {
    if (cellId >= tets)
    {
      return triangleParents[cellId - tets];
    }
    const CellId parent = result.parentCell[cellId];
    return input.triangles ? input.triangles->tetCellIds[parent] : parent;
  };
  // Every output cell receives all cell data of the input cell it came from.
  copyCellData(input.grid->GetCellData(), output->GetNumberOfCells(), parentOf,
    output->GetCellData(), parallelFor);
  if (!result.provenance.offsets.empty() && input.grid->GetPointData()->GetNumberOfArrays() > 0)
  {
    transferPointData(input.grid->GetPointData(), result.provenance,
      splitNames(input.interpolatedPointArrays), splitNames(input.labelPointArrays),
      output->GetPointData());
  }

  vtkCellData* cellData = output->GetCellData();
  const vtkIdType cells = output->GetNumberOfCells();
  addCellArray<vtkIntArray>(
    cellData, "PartitionId", result.partitionOfCell, cells, -1, parallelFor);
  addCellArray<vtkIntArray>(cellData, "ColorId", result.colorOfCell, cells, -1, parallelFor);
  addCellArray<vtkUnsignedCharArray>(
    cellData, "NearFormerInterface", result.nearFormerInterface, cells, 0, parallelFor);
  if (!result.edgeLengthRatio.empty())
  {
    addCellArray<vtkDoubleArray>(cellData, "EdgeLengthRatio", result.edgeLengthRatio, cells,
      std::numeric_limits<double>::quiet_NaN(), parallelFor);
  }
}

} // namespace cgmesh
