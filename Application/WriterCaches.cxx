#include "WriterCaches.h"

#include "vtkCellData.h"
#include "vtkCellTypes.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <array>

namespace cgmesh
{

namespace
{

// A grid that may set vtkUnstructuredGrid's protected cache of distinct cell types.
class vtkWriterCachedGrid : public vtkUnstructuredGrid
{
public:
  static vtkWriterCachedGrid* New();
  vtkTypeMacro(vtkWriterCachedGrid, vtkUnstructuredGrid);

  // The types in increasing order, as VTK lists them, stamped with the types array's MTime as VTK
  // stamps its own result.
  void CacheDistinctCellTypes()
  {
    vtkUnsignedCharArray* types = this->GetCellTypesArray();
    if (!types)
      return;
    std::array<bool, 256> present{};
    const unsigned char* type = types->GetPointer(0);
    for (vtkIdType cell = 0; cell < types->GetNumberOfValues(); ++cell)
      present[type[cell]] = true;
    vtkNew<vtkCellTypes> distinct;
    for (int value = 0; value < 256; ++value)
    {
      if (present[value])
        distinct->InsertNextType(static_cast<unsigned char>(value));
    }
    this->DistinctCellTypes = distinct.Get();
    this->DistinctCellTypesUpdateMTime = types->GetMTime();
  }
};
vtkStandardNewMacro(vtkWriterCachedGrid);

// The range of a one-component array as vtkDataArray::GetRange() computes it (the comparisons of
// vtkMathUtilities::UpdateRange, in the value type, then converted). False when there are no
// values or a NaN, which VTK skips.
template <typename Value>
bool componentRange(const Value* values, vtkIdType count, double range[2])
{
  if (count == 0)
    return false;
  // Without a branch per value the loop vectorises: the NaN test is gathered, and without NaNs
  // the running minimum and maximum are VTK's whatever the order.
  Value low = values[0], high = values[0];
  bool anyNaN = false;
  for (vtkIdType index = 0; index < count; ++index)
  {
    const Value value = values[index];
    anyNaN |= value != value;
    low = value < low ? value : low;
    high = value > high ? value : high;
  }
  if (anyNaN)
    return false;
  range[0] = static_cast<double>(low);
  range[1] = static_cast<double>(high);
  return true;
}

// Stores a one-component array's range where GetRange() looks first. The per-component ranges
// are not written into the file (a cached vector norm range would be).
void storeRange(vtkDataArray* array, const double range[2])
{
  vtkNew<vtkInformationVector> perComponent;
  perComponent->SetNumberOfInformationObjects(1);
  perComponent->GetInformationObject(0)->Set(vtkDataArray::COMPONENT_RANGE(), range, 2);
  array->GetInformation()->Set(vtkAbstractArray::PER_COMPONENT(), perComponent);
}

void cacheRange(vtkDataArray* array)
{
  if (!array || array->GetNumberOfComponents() != 1 || !array->HasStandardMemoryLayout())
    return;
  double range[2];
  bool found = false;
  switch (array->GetDataType())
  {
    vtkTemplateMacro(found = componentRange(static_cast<const VTK_TT*>(array->GetVoidPointer(0)),
                       array->GetNumberOfTuples(), range));
  }
  if (found)
    storeRange(array, range);
}

void cacheRanges(vtkFieldData* arrays)
{
  for (int index = 0; index < arrays->GetNumberOfArrays(); ++index)
    cacheRange(arrays->GetArray(index));
}

} // namespace

vtkSmartPointer<vtkUnstructuredGrid> gridWithWriterCaches(vtkUnstructuredGrid* grid)
{
  vtkNew<vtkWriterCachedGrid> copy;
  copy->ShallowCopy(grid);
  copy->CacheDistinctCellTypes();
  cacheRanges(copy->GetPointData());
  cacheRanges(copy->GetCellData());
  cacheRanges(copy->GetFieldData());
  return vtkSmartPointer<vtkUnstructuredGrid>(copy.Get());
}

} // namespace cgmesh
