#include "cgmeshAdaptedGrid.h"

#include "cgmeshHandedOverArrays.h"
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
#include <cmath>
#include <limits>
#include <vector>

namespace cgmesh
{

namespace
{

// One value per tet, then `fill` for each triangle after them. The array takes over `perTet`'s
// storage when the result is handed over, and a copy of it when the caller keeps the result.
template <typename Array, typename Values>
void addCellArray(vtkCellData* cellData, const char* name, Values& perTet, vtkIdType numberOfCells,
  typename Values::value_type fill, ResultArrays handling)
{
  Values values = handling == ResultArrays::HandOver ? std::move(perTet) : perTet;
  values.resize(static_cast<std::size_t>(numberOfCells), fill);
  vtkSmartPointer<Array> array = arrayTakingOver<Array>(std::move(values));
  array->SetName(name);
  cellData->AddArray(array);
}

} // namespace

void fillAdaptedGrid(const AdaptedGridInput& input, AdaptationResult& result,
  vtkUnstructuredGrid* output, ResultArrays handling)
{
  const ParallelFor parallelFor = parallelForOn(result.summary.plan.threads);
  const std::vector<TriangleChild> children = !input.triangles ? std::vector<TriangleChild>()
    : result.summary.boundaryRetriangulated
    ? findTriangleChildrenByPosition(*input.mesh, input.triangles->triangles, result.mesh)
    : findTriangleChildren(*input.mesh, input.triangles->triangles, result.mesh, result.provenance);
  // The graded size field the run refined to, per output point: what EdgeLengthRatio and the share
  // of edges within bounds measure against (the input's own size array, interpolated, is not
  // graded). A point outside a refinement selection has no target: NaN.
  std::vector<double> targetEdgeLength;
  if (result.summary.plan.sizeField)
  {
    targetEdgeLength =
      handling == ResultArrays::HandOver ? std::move(result.mesh.sizes) : result.mesh.sizes;
    for (double& size : targetEdgeLength)
    {
      size = std::isfinite(size) ? size : std::numeric_limits<double>::quiet_NaN();
    }
  }
  if (handling == ResultArrays::HandOver)
  {
    convertToUnstructuredGrid(std::move(result.mesh), output, std::string(), parallelFor);
  }
  else
  {
    convertToUnstructuredGrid(result.mesh, output, std::string(), parallelFor);
  }
  std::vector<vtkIdType> triangleParents; // input cell ids of the triangles appended
  if (input.triangles)
  {
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
  if (!targetEdgeLength.empty())
  {
    vtkSmartPointer<vtkDoubleArray> array =
      arrayTakingOver<vtkDoubleArray>(std::move(targetEdgeLength));
    array->SetName("TargetEdgeLength");
    output->GetPointData()->AddArray(array);
  }

  vtkCellData* cellData = output->GetCellData();
  const vtkIdType cells = output->GetNumberOfCells();
  addCellArray<vtkIntArray>(cellData, "PartitionId", result.partitionOfCell, cells, -1, handling);
  addCellArray<vtkIntArray>(cellData, "ColorId", result.colorOfCell, cells, -1, handling);
  addCellArray<vtkUnsignedCharArray>(
    cellData, "NearFormerInterface", result.nearFormerInterface, cells, 0, handling);
  if (!result.edgeLengthRatio.empty())
  {
    addCellArray<vtkDoubleArray>(cellData, "EdgeLengthRatio", result.edgeLengthRatio, cells,
      std::numeric_limits<double>::quiet_NaN(), handling);
  }
}

} // namespace cgmesh
