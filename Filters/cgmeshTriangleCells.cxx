#include "cgmeshTriangleCells.h"

#include "cgmeshVTKConversion.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVariant.h"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <map>
#include <string>

namespace cgmesh
{

namespace
{

// "cell 12 (points 4, 9, 7)"
std::string describeTriangle(const TriangleCells& cells, std::size_t index)
{
  const Triangle& corners = cells.triangles[index];
  return "cell " + std::to_string(cells.triangleCellIds[index]) + " (points " +
    std::to_string(corners[0]) + ", " + std::to_string(corners[1]) + ", " +
    std::to_string(corners[2]) + ")";
}

} // namespace

std::vector<std::pair<Face, int>> surfaceClassesOf(
  vtkUnstructuredGrid* grid, const TriangleCells& cells)
{
  // Each triangle's values in every cell array, as bytes: equal bytes, one class.
  vtkCellData* cellData = grid->GetCellData();
  std::map<std::string, int> classOfValues;
  std::vector<std::pair<Face, int>> entries;
  entries.reserve(cells.triangles.size());
  for (std::size_t t = 0; t < cells.triangles.size(); ++t)
  {
    const vtkIdType cellId = cells.triangleCellIds[t];
    std::string values;
    for (int a = 0; a < cellData->GetNumberOfArrays(); ++a)
    {
      vtkAbstractArray* array = cellData->GetAbstractArray(a);
      const int components = array->GetNumberOfComponents();
      vtkDataArray* numbers = vtkDataArray::SafeDownCast(array);
      for (int c = 0; c < components; ++c)
      {
        if (numbers)
        {
          const double value = numbers->GetComponent(cellId, c);
          values.append(reinterpret_cast<const char*>(&value), sizeof(value));
        }
        else
        {
          values += array->GetVariantValue(cellId * components + c).ToString();
          values.push_back('\0');
        }
      }
    }
    auto known = classOfValues.find(values); // a few classes, looked up for every triangle
    if (known == classOfValues.end())
    {
      known =
        classOfValues.emplace(std::move(values), static_cast<int>(classOfValues.size())).first;
    }
    Face corners = cells.triangles[t];
    std::sort(corners.begin(), corners.end());
    entries.emplace_back(corners, known->second);
  }
  std::sort(entries.begin(), entries.end());
  // One entry per face: a face in two classes (in two tag sets) merges with neither.
  int nextClass = static_cast<int>(classOfValues.size());
  std::vector<std::pair<Face, int>> classes;
  for (std::size_t first = 0; first < entries.size();)
  {
    std::size_t last = first + 1;
    while (last < entries.size() && entries[last].first == entries[first].first)
    {
      ++last;
    }
    const bool mixed = entries[last - 1].second != entries[first].second;
    classes.emplace_back(entries[first].first, mixed ? nextClass++ : entries[first].second);
    first = last;
  }
  return classes;
}

bool hasTriangles(vtkUnstructuredGrid* grid)
{
  const unsigned char* types = cellTypesOf(grid);
  return types &&
    std::memchr(types, VTK_TRIANGLE, static_cast<std::size_t>(grid->GetNumberOfCells())) != nullptr;
}

void separateTriangles(vtkUnstructuredGrid* grid, vtkUnstructuredGrid* tets, TriangleCells& cells)
{
  cells = TriangleCells();
  vtkNew<vtkCellArray> tetCells;
  auto iterator = vtk::TakeSmartPointer(grid->GetCells()->NewIterator());
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
  {
    const vtkIdType cellId = iterator->GetCurrentCellId();
    vtkIdType count;
    const vtkIdType* points;
    iterator->GetCurrentCell(count, points);
    if (grid->GetCellType(cellId) == VTK_TRIANGLE)
    {
      cells.triangleCellIds.push_back(cellId);
      cells.triangles.push_back({ points[0], points[1], points[2] });
      continue;
    }
    cells.tetCellIds.push_back(cellId);
    tetCells->InsertNextCell(count, points);
  }
  tets->Initialize();
  tets->SetPoints(grid->GetPoints());
  tets->GetPointData()->ShallowCopy(grid->GetPointData());
  tets->SetCells(VTK_TETRA, tetCells);
  copyCellData(
    grid->GetCellData(), static_cast<vtkIdType>(cells.tetCellIds.size()),
    [&cells](vtkIdType tet) { return cells.tetCellIds[tet]; }, tets->GetCellData());
  tets->GetFieldData()->ShallowCopy(grid->GetFieldData());
}

Status checkTriangleCells(const TetMesh& mesh, const TriangleCells& cells)
{
  const TaggedTriangleCheck check = checkTaggedTriangles(mesh, cells.triangles);
  const std::string of =
    " of the input's " + std::to_string(cells.triangles.size()) + " triangles ";
  if (check.notFaces > 0)
  {
    return Status::failure(ErrorKind::InvalidInput,
      std::to_string(check.notFaces) + of + "are not faces of its tetrahedra (the first is " +
        describeTriangle(cells, check.firstNotFace) +
        "); triangles tag faces of the tetrahedra and are refined with them");
  }
  if (check.insideRegion > 0)
  {
    return Status::failure(ErrorKind::InvalidInput,
      std::to_string(check.insideRegion) + of +
        "lie between two tetrahedra of the same material (the first is " +
        describeTriangle(cells, check.firstInsideRegion) +
        "); refinement keeps only the boundary and the faces between materials, so only those "
        "can carry triangles. Give the two sides different values in the region array, or "
        "drop those triangles");
  }
  return Status::success();
}

void appendTriangles(const std::vector<TriangleChild>& children, vtkUnstructuredGrid* grid)
{
  for (const TriangleChild& child : children)
  {
    const vtkIdType corners[3] = { child.corners[0], child.corners[1], child.corners[2] };
    grid->InsertNextCell(VTK_TRIANGLE, 3, corners);
  }
}

} // namespace cgmesh
