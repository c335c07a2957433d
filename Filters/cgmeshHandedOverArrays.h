// VTK arrays that take over the storage of a std::vector instead of copying it. The merged mesh and
// the run's per-cell arrays are the largest allocations of a run; copying them into fresh VTK
// arrays cost a tenth of the filter's time and put two copies of the connectivity in memory at
// once.
#ifndef cgmeshHandedOverArrays_h
#define cgmeshHandedOverArrays_h

#include "cgmeshFiltersModule.h" // for export macro

#include "vtkAOSDataArrayTemplate.h"
#include "vtkSmartPointer.h"

#include <memory>
#include <type_traits>
#include <utility>

namespace cgmesh
{

// Owner of storage a VTK array reads and writes; deleting it frees the storage.
struct HandedOverStorage
{
  virtual ~HandedOverStorage() = default;
};

template <typename Vector>
struct HandedOverVector final : HandedOverStorage
{
  explicit HandedOverVector(Vector&& taken)
    : values(std::move(taken))
  {
  }
  Vector values;
};

// Keeps `storage` until VTK gives back the buffer that starts at `data`.
CGMESHFILTERS_EXPORT void keepHandedOverStorage(
  const void* data, std::unique_ptr<HandedOverStorage> storage);

// The free function of every handed-over VTK buffer: deletes the storage kept for `data`. VTK calls
// it when the array is deleted or reallocates its buffer (it then copies into storage of its own).
CGMESHFILTERS_EXPORT void releaseHandedOverStorage(void* data);

// Number of buffers handed over and not yet given back (for tests).
CGMESHFILTERS_EXPORT std::size_t handedOverStorageCount();

// A new VTK array of `components` components whose values are those of `values`, without a copy:
// `values` is left empty and its storage lives as long as the array's buffer. The vector's elements
// may be several values each (a std::array of point ids per tet, read as four vtkIdType), of the
// same size and representation as the array's values.
template <typename Array, typename Vector>
vtkSmartPointer<Array> arrayTakingOver(Vector&& values, int components = 1)
{
  static_assert(!std::is_lvalue_reference<Vector>::value, "the vector is taken: pass an rvalue");
  using Value = typename Array::ValueType;
  using Element = typename Vector::value_type;
  static_assert(
    sizeof(Element) % sizeof(Value) == 0, "an element must be a whole number of values");
  auto array = vtkSmartPointer<Array>::New();
  array->SetNumberOfComponents(components);
  const vtkIdType count = static_cast<vtkIdType>(values.size() * (sizeof(Element) / sizeof(Value)));
  if (count == 0)
  {
    values = Vector();
    return array;
  }
  auto storage = std::make_unique<HandedOverVector<Vector>>(std::move(values));
  // The same 64-bit integers or doubles under VTK's spelling of their type (vtkIdType is long long,
  // PointId is int64_t); only VTK's own code reads them through this pointer.
  Value* data = reinterpret_cast<Value*>(storage->values.data());
  keepHandedOverStorage(data, std::move(storage));
  array->SetArray(data, count, /*save=*/0, Array::VTK_DATA_ARRAY_USER_DEFINED);
  array->SetArrayFreeFunction(&releaseHandedOverStorage);
  return array;
}

} // namespace cgmesh

#endif
