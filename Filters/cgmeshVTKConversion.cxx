#include "cgmeshVTKConversion.h"

#include "cgmeshHandedOverArrays.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCellTypes.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace cgmesh
{

const unsigned char* cellTypesOf(vtkUnstructuredGrid* grid)
{
  vtkUnsignedCharArray* types = grid->GetCellTypesArray();
  return grid->GetNumberOfCells() > 0 && types ? types->GetPointer(0) : nullptr;
}

vtkIdType countNonTetrahedra(vtkUnstructuredGrid* grid, bool trianglesAccepted)
{
  const unsigned char* types = cellTypesOf(grid);
  // The count is read once: GetNumberOfCells() is a call into VTK's library, and asking it for
  // every cell was most of this loop (11 ms of the FinFET's 844k cells).
  const vtkIdType cells = grid->GetNumberOfCells();
  vtkIdType count = 0;
  for (vtkIdType cellId = 0; cellId < cells; ++cellId)
  {
    const int type = types[cellId];
    count += type != VTK_TETRA && !(trianglesAccepted && type == VTK_TRIANGLE);
  }
  return count;
}

namespace
{

// The input array that an array made by CopyAllocate copies: the attribute of the same kind, else
// the input array of that name (names are unique in field data); null for an unnamed array.
vtkAbstractArray* sourceOfCopy(vtkCellData* input, vtkCellData* output, int index)
{
  const int attribute = output->IsArrayAnAttribute(index);
  if (attribute >= 0)
  {
    return input->GetAbstractAttribute(attribute);
  }
  const char* name = output->GetArrayName(index);
  return name ? input->GetAbstractArray(name) : nullptr;
}

// Whether tuples of `source` can be copied into `target` as bytes from several threads at once:
// contiguous arrays of one numeric type (bits share bytes, strings own memory).
bool copiesAsBytes(vtkAbstractArray* source, vtkAbstractArray* target)
{
  return source && vtkDataArray::FastDownCast(source) && source->GetDataType() != VTK_BIT &&
    source->GetDataType() == target->GetDataType() &&
    source->GetNumberOfComponents() == target->GetNumberOfComponents() &&
    source->HasStandardMemoryLayout() && target->HasStandardMemoryLayout() &&
    source->GetDataTypeSize() > 0;
}

} // namespace

void copyCellData(vtkCellData* input, vtkIdType numberOfCells,
  const std::function<vtkIdType(vtkIdType)>& sourceOf, vtkCellData* output,
  const ParallelFor& parallelFor)
{
  output->CopyAllocate(input, numberOfCells);
  std::vector<vtkAbstractArray*> sources(output->GetNumberOfArrays());
  for (int index = 0; index < output->GetNumberOfArrays(); ++index)
  {
    sources[index] = sourceOfCopy(input, output, index);
  }
  if (std::find(sources.begin(), sources.end(), nullptr) != sources.end())
  {
    // An unnamed array cannot be paired with its source: VTK's own copy, one tuple at a time.
    vtkNew<vtkIdList> sourceIds;
    vtkNew<vtkIdList> targetIds;
    sourceIds->SetNumberOfIds(numberOfCells);
    targetIds->SetNumberOfIds(numberOfCells);
    for (vtkIdType cellId = 0; cellId < numberOfCells; ++cellId)
    {
      sourceIds->SetId(cellId, sourceOf(cellId));
      targetIds->SetId(cellId, cellId);
    }
    output->CopyData(input, sourceIds, targetIds);
    return;
  }
  for (int index = 0; index < output->GetNumberOfArrays(); ++index)
  {
    vtkAbstractArray* source = sources[index];
    vtkAbstractArray* target = output->GetAbstractArray(index);
    target->SetNumberOfTuples(numberOfCells);
    if (!copiesAsBytes(source, target))
    {
      for (vtkIdType cellId = 0; cellId < numberOfCells; ++cellId)
      {
        target->SetTuple(cellId, sourceOf(cellId), source);
      }
      continue;
    }
    const std::size_t tupleBytes =
      static_cast<std::size_t>(target->GetDataTypeSize()) * target->GetNumberOfComponents();
    const char* from = static_cast<const char*>(source->GetVoidPointer(0));
    char* to = static_cast<char*>(target->GetVoidPointer(0));
    // The ranges only copy bytes into a sized array: they cannot fail, so no Status to pass on.
    forEachRange(parallelFor, numberOfCells, IndicesPerCopyRange,
      [&](std::int64_t begin, std::int64_t end)
      {
        for (std::int64_t cellId = begin; cellId < end; ++cellId)
        {
          std::memcpy(to + cellId * tupleBytes, from + sourceOf(cellId) * tupleBytes, tupleBytes);
        }
      });
  }
}

std::string describeNonTetrahedra(vtkUnstructuredGrid* grid, bool trianglesAccepted)
{
  std::map<int, vtkIdType> countOfType;
  for (vtkIdType cellId = 0; cellId < grid->GetNumberOfCells(); ++cellId)
  {
    const int type = grid->GetCellType(cellId);
    if (type != VTK_TETRA && !(trianglesAccepted && type == VTK_TRIANGLE))
    {
      ++countOfType[type];
    }
  }
  if (countOfType.empty())
  {
    return std::string();
  }
  std::string types;
  bool volumeCells = false, lowerCells = false;
  for (const auto& entry : countOfType)
  {
    const char* className = vtkCellTypes::GetClassNameFromTypeId(entry.first);
    std::string name = className ? className : "type " + std::to_string(entry.first);
    if (name.rfind("vtk", 0) == 0)
    {
      name = name.substr(3);
    }
    types += (types.empty() ? "" : ", ") + std::to_string(entry.second) + " " + name;
    (vtkCellTypes::GetDimension(static_cast<unsigned char>(entry.first)) == 3 ? volumeCells
                                                                              : lowerCells) = true;
  }
  std::string advice;
  if (lowerCells)
  {
    advice += trianglesAccepted
      ? " Triangles are kept and refined, but other surface, line and vertex cells are not: keep "
        "the tetrahedra and triangles with ParaView's Extract Cells By Type (Tetra, Triangle)."
      : " Lower-dimensional cells (boundary, edge or point tags) are not accepted here: keep the "
        "tetrahedra with ParaView's Extract Cells By Type (Tetra).";
  }
  if (volumeCells)
  {
    advice += " Split other volume cells with ParaView's Tetrahedralize filter.";
  }
  return types + "." + advice;
}

namespace
{

// The conversions below read the input by ranges of points or cells, concurrently through
// `parallelFor`: only reads of the input's arrays, each range writing its own part of `mesh`.
// Serial, reading the 844k-tet FinFET took 0.07 s, the same at 1 and 2 threads.
void copyPoints(vtkUnstructuredGrid* grid, TetMesh& mesh, const ParallelFor& parallelFor)
{
  const vtkIdType numberOfPoints = grid->GetNumberOfPoints();
  mesh.coordinates.resize(3 * static_cast<size_t>(numberOfPoints));
  vtkDataArray* coordinates = grid->GetPoints()->GetData();
  forEachRange(parallelFor, numberOfPoints, IndicesPerCopyRange,
    [&](std::int64_t begin, std::int64_t end)
    {
      for (vtkIdType pointId = begin; pointId < end; ++pointId)
      {
        coordinates->GetTuple(pointId, mesh.coordinates.data() + 3 * pointId);
      }
    });
}

// The corners of cells [begin, end) from the cell array's offsets and connectivity; false when a
// cell does not have 4 points.
template <typename Index>
bool copyCorners(const Index* offsets, const Index* connectivity, std::int64_t begin,
  std::int64_t end, TetMesh& mesh)
{
  for (std::int64_t cell = begin; cell < end; ++cell)
  {
    if (offsets[cell + 1] - offsets[cell] != 4)
    {
      return false;
    }
    const Index* corners = connectivity + offsets[cell];
    for (int corner = 0; corner < 4; ++corner)
    {
      mesh.tets[cell][corner] = static_cast<PointId>(corners[corner]);
    }
  }
  return true;
}

Status copyTetrahedra(vtkUnstructuredGrid* grid, TetMesh& mesh, const ParallelFor& parallelFor)
{
  const vtkIdType numberOfCells = grid->GetNumberOfCells();
  mesh.tets.resize(static_cast<size_t>(numberOfCells));
  vtkCellArray* cells = grid->GetCells();
  const std::int64_t ranges = (numberOfCells + IndicesPerCopyRange - 1) / IndicesPerCopyRange;
  std::vector<char> failed(static_cast<std::size_t>(ranges), 0);
  const Status status = forEachRange(parallelFor, numberOfCells, IndicesPerCopyRange,
    [&](std::int64_t begin, std::int64_t end)
    {
      const bool copied = cells->IsStorage64Bit()
        ? copyCorners(cells->GetOffsetsArray64()->GetPointer(0),
            cells->GetConnectivityArray64()->GetPointer(0), begin, end, mesh)
        : copyCorners(cells->GetOffsetsArray32()->GetPointer(0),
            cells->GetConnectivityArray32()->GetPointer(0), begin, end, mesh);
      failed[begin / IndicesPerCopyRange] = !copied;
    });
  if (!status.ok())
  {
    return status;
  }
  if (std::find(failed.begin(), failed.end(), 1) != failed.end())
  {
    return Status::failure("a tetrahedron does not have 4 points");
  }
  return Status::success();
}

Status copyRegions(vtkUnstructuredGrid* grid, const std::string& regionArrayName, TetMesh& mesh,
  const ParallelFor& parallelFor)
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
  const std::int64_t ranges = (numberOfCells + IndicesPerCopyRange - 1) / IndicesPerCopyRange;
  std::vector<char> failed(static_cast<std::size_t>(ranges), 0);
  const Status status = forEachRange(parallelFor, numberOfCells, IndicesPerCopyRange,
    [&](std::int64_t begin, std::int64_t end)
    {
      for (vtkIdType cellId = begin; cellId < end; ++cellId)
      {
        // Labels stored as floating point are rounded, not truncated (2.9999999 is region 3).
        const double value = std::round(regionArray->GetComponent(cellId, 0));
        if (!(std::abs(value) <= static_cast<double>(std::numeric_limits<int>::max())))
        {
          failed[begin / IndicesPerCopyRange] = 1;
          return;
        }
        mesh.regions[cellId] = static_cast<int>(value);
      }
    });
  if (!status.ok())
  {
    return status;
  }
  if (std::find(failed.begin(), failed.end(), 1) != failed.end())
  {
    return Status::failure(
      "region array '" + regionArrayName + "' holds a value that is not a valid int");
  }
  return Status::success();
}

std::string arrayNames(vtkFieldData* data)
{
  std::string names;
  for (int i = 0; i < data->GetNumberOfArrays(); ++i)
  {
    const char* name = data->GetArrayName(i);
    names += std::string(names.empty() ? "" : ", ") + (name ? name : "(unnamed)");
  }
  return names.empty() ? std::string("none") : names;
}

// A point array gives one size per point; a cell array is averaged over the cells around each
// point (a point no cell uses keeps 0, which the kernel's check ignores: unused points are
// removed).
Status copySizes(vtkUnstructuredGrid* grid, const std::string& sizeArrayName, TetMesh& mesh)
{
  const std::string what = "size array '" + sizeArrayName + "'";
  vtkAbstractArray* pointArray = grid->GetPointData()->GetAbstractArray(sizeArrayName.c_str());
  vtkAbstractArray* abstractArray =
    pointArray ? pointArray : grid->GetCellData()->GetAbstractArray(sizeArrayName.c_str());
  if (!abstractArray)
  {
    return Status::failure(ErrorKind::InvalidOption,
      what + " is neither a point nor a cell array of the input (point arrays: " +
        arrayNames(grid->GetPointData()) + "; cell arrays: " + arrayNames(grid->GetCellData()) +
        ")");
  }
  vtkDataArray* sizes = vtkDataArray::SafeDownCast(abstractArray);
  if (!sizes)
  {
    return Status::failure(ErrorKind::InvalidInput, what + " is not numeric");
  }
  if (sizes->GetNumberOfComponents() != 1)
  {
    return Status::failure(ErrorKind::InvalidInput,
      what + " has " + std::to_string(sizes->GetNumberOfComponents()) +
        " components; a size field has one (a target edge length)");
  }
  const char* entity = pointArray ? "point" : "cell";
  for (vtkIdType id = 0; id < sizes->GetNumberOfTuples(); ++id)
  {
    const double h = sizes->GetComponent(id, 0);
    if (!(h > 0) || !std::isfinite(h))
    {
      std::ostringstream message;
      message << what << ": the value at " << entity << " " << id << " is " << h
              << "; sizes must be positive and finite";
      return Status::failure(ErrorKind::InvalidInput, message.str());
    }
  }
  mesh.sizes.assign(static_cast<std::size_t>(mesh.numberOfPoints()), 0.0);
  if (pointArray)
  {
    for (PointId p = 0; p < mesh.numberOfPoints(); ++p)
    {
      mesh.sizes[p] = sizes->GetComponent(p, 0);
    }
    return Status::success();
  }
  std::vector<int> cellsAround(mesh.sizes.size(), 0);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
  {
    for (PointId p : mesh.tets[t])
    {
      mesh.sizes[p] += sizes->GetComponent(static_cast<vtkIdType>(t), 0);
      ++cellsAround[p];
    }
  }
  for (std::size_t p = 0; p < mesh.sizes.size(); ++p)
  {
    mesh.sizes[p] /= std::max(cellsAround[p], 1);
  }
  return Status::success();
}

} // namespace

bool isIntegerDataType(int type)
{
  switch (type)
  {
    case VTK_CHAR:
    case VTK_SIGNED_CHAR:
    case VTK_UNSIGNED_CHAR:
    case VTK_SHORT:
    case VTK_UNSIGNED_SHORT:
    case VTK_INT:
    case VTK_UNSIGNED_INT:
    case VTK_LONG:
    case VTK_UNSIGNED_LONG:
    case VTK_LONG_LONG:
    case VTK_UNSIGNED_LONG_LONG:
    case VTK_ID_TYPE:
      return true;
    default:
      return false;
  }
}

Status convertToTetMesh(vtkUnstructuredGrid* grid, const std::string& regionArrayName,
  TetMesh& mesh, const std::string& sizeArrayName, const ParallelFor& parallelFor)
{
  mesh = TetMesh();
  if (grid->GetNumberOfPoints() > 0)
  {
    copyPoints(grid, mesh, parallelFor);
  }
  if (grid->GetNumberOfCells() > 0)
  {
    Status status = copyTetrahedra(grid, mesh, parallelFor);
    if (!status.ok())
    {
      return status;
    }
  }
  if (!regionArrayName.empty())
  {
    Status status = copyRegions(grid, regionArrayName, mesh, parallelFor);
    if (!status.ok())
    {
      return status;
    }
  }
  if (!sizeArrayName.empty())
  {
    return copySizes(grid, sizeArrayName, mesh);
  }
  return Status::success();
}

void convertToUnstructuredGrid(TetMesh&& mesh, vtkUnstructuredGrid* grid,
  const std::string& regionArrayName, const ParallelFor& parallelFor)
{
  static_assert(sizeof(Tet) == 4 * sizeof(vtkIdType), "a tet's corners are VTK's connectivity");
  const vtkIdType numberOfTets = mesh.numberOfTets();
  vtkSmartPointer<vtkDoubleArray> coordinates =
    arrayTakingOver<vtkDoubleArray>(std::move(mesh.coordinates), 3);
  coordinates->SetName("Points"); // as vtkPoints names its own
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);

  vtkSmartPointer<vtkIdTypeArray> connectivity =
    arrayTakingOver<vtkIdTypeArray>(std::move(mesh.tets));
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(numberOfTets + 1);
  vtkIdType* offset = offsets->GetPointer(0);
  forEachRange(parallelFor, numberOfTets + 1, IndicesPerCopyRange,
    [&](std::int64_t begin, std::int64_t end)
    {
      for (std::int64_t tetId = begin; tetId < end; ++tetId)
      {
        offset[tetId] = 4 * tetId;
      }
    });
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  // The cell types filled here by ranges, and handed over with no polyhedron faces: given a type
  // or a types array alone, VTK fills or scans the types on one thread for polyhedra (the Big
  // cube's 6 M tets: 10-15 ms of its 13-20 ms output at one thread, on every thread count).
  vtkNew<vtkUnsignedCharArray> types;
  types->SetNumberOfValues(numberOfTets);
  unsigned char* type = types->GetPointer(0);
  forEachRange(parallelFor, numberOfTets, IndicesPerCopyRange,
    [&](std::int64_t begin, std::int64_t end)
    { std::fill(type + begin, type + end, static_cast<unsigned char>(VTK_TETRA)); });

  grid->Initialize();
  grid->SetPoints(points);
  grid->SetCells(types, cells, nullptr, nullptr);
  if (mesh.hasRegions() && !regionArrayName.empty())
  {
    vtkSmartPointer<vtkIntArray> regions = arrayTakingOver<vtkIntArray>(std::move(mesh.regions));
    regions->SetName(regionArrayName.c_str());
    grid->GetCellData()->AddArray(regions);
  }
  mesh = TetMesh();
}

void convertToUnstructuredGrid(const TetMesh& mesh, vtkUnstructuredGrid* grid,
  const std::string& regionArrayName, const ParallelFor& parallelFor)
{
  TetMesh copy;
  copy.coordinates = mesh.coordinates;
  copy.tets = mesh.tets;
  if (!regionArrayName.empty())
  {
    copy.regions = mesh.regions;
  }
  convertToUnstructuredGrid(std::move(copy), grid, regionArrayName, parallelFor);
}

} // namespace cgmesh
