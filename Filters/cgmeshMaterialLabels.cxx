#include "cgmeshMaterialLabels.h"

#include "cgmeshVTKConversion.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <map>
#include <set>
#include <unordered_set>

namespace cgmesh
{
namespace
{

// Materials are few: an array with more distinct values than 64, or than 1% of the cells when
// that is more, numbers cells (or, after a refinement, the cells' parents) instead.
bool looksLikeIds(vtkDataArray* array)
{
  const vtkIdType count = array->GetNumberOfTuples();
  const std::size_t mostLabels = std::max<std::size_t>(64, static_cast<std::size_t>(count / 100));
  std::unordered_set<long long> seen;
  for (vtkIdType i = 0; i < count; ++i)
  {
    seen.insert(static_cast<long long>(array->GetComponent(i, 0)));
    if (seen.size() > mostLabels)
    {
      return true;
    }
  }
  return false;
}

} // namespace

std::vector<std::string> findMaterialLabelArrays(vtkUnstructuredGrid* grid)
{
  static const char* const notLabels[] = { "vtkOriginalCellIds", "vtkGhostType", "vtkProcessId",
    "PartitionId", "ColorId", "NearFormerInterface" };
  std::vector<std::string> names;
  vtkCellData* cellData = grid->GetCellData();
  for (int index = 0; index < cellData->GetNumberOfArrays(); ++index)
  {
    vtkDataArray* array = cellData->GetArray(index);
    const int attribute = cellData->IsArrayAnAttribute(index);
    if (!array || !array->GetName() || array->GetNumberOfComponents() != 1 ||
      !isIntegerDataType(array->GetDataType()) || attribute == vtkDataSetAttributes::GLOBALIDS ||
      attribute == vtkDataSetAttributes::PEDIGREEIDS)
    {
      continue;
    }
    bool excluded = false;
    for (const char* name : notLabels)
    {
      excluded = excluded || std::string(name) == array->GetName();
    }
    if (!excluded && !looksLikeIds(array))
    {
      names.emplace_back(array->GetName());
    }
  }
  return names;
}

Status combineMaterialLabels(vtkUnstructuredGrid* grid, const std::vector<std::string>& arrayNames,
  const ParallelFor& parallelFor, TetMesh& mesh)
{
  const vtkIdType cells = grid->GetNumberOfCells();
  std::vector<vtkDataArray*> arrays;
  for (const std::string& name : arrayNames)
  {
    arrays.push_back(grid->GetCellData()->GetArray(name.c_str()));
  }
  using Combination = std::vector<long long>;
  auto readValues = [&](vtkIdType cell, Combination& values)
  {
    for (std::size_t k = 0; k < arrays.size(); ++k)
    {
      values[k] = static_cast<long long>(arrays[k]->GetComponent(cell, 0));
    }
  };
  // Ranges of cells run concurrently. Neighbouring cells mostly belong to one material, so each
  // range handles its runs of cells with the same combination, one look-up per run. Two passes:
  // the combinations first (numbered in sorted order), then each cell's number.
  const std::int64_t rangeSize = IndicesPerCopyRange;
  auto forEachRun = [&](std::int64_t begin, std::int64_t end, auto&& visit)
  {
    Combination values(arrays.size()), next(arrays.size());
    for (vtkIdType first = begin; first < end;)
    {
      readValues(first, values);
      vtkIdType last = first + 1;
      while (last < end && (readValues(last, next), next == values))
      {
        ++last;
      }
      visit(values, first, last);
      first = last;
    }
  };
  std::vector<std::set<Combination>> combinationsOfRange((cells + rangeSize - 1) / rangeSize);
  Status status = forEachRange(parallelFor, cells, rangeSize,
    [&](std::int64_t begin, std::int64_t end)
    {
      forEachRun(begin, end,
        [&](const Combination& values, vtkIdType, vtkIdType)
        { combinationsOfRange[begin / rangeSize].insert(values); });
    });
  if (!status.ok())
  {
    return status;
  }
  std::map<Combination, int> idOf;
  for (const auto& combinations : combinationsOfRange)
  {
    for (const Combination& values : combinations)
    {
      idOf.emplace(values, 0);
    }
  }
  int next = 0;
  for (auto& entry : idOf)
  {
    entry.second = next++;
  }
  mesh.regions.resize(static_cast<std::size_t>(cells));
  return forEachRange(parallelFor, cells, rangeSize,
    [&](std::int64_t begin, std::int64_t end)
    {
      forEachRun(begin, end,
        [&](const Combination& values, vtkIdType first, vtkIdType last)
        { std::fill(mesh.regions.begin() + first, mesh.regions.begin() + last, idOf.at(values)); });
    });
}

} // namespace cgmesh
