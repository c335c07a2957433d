// Conversion between vtkUnstructuredGrid and the VTK-free cgmesh::TetMesh, shared by the filter and
// the command-line driver.
#ifndef cgmeshVTKConversion_h
#define cgmeshVTKConversion_h

#include "cgmeshFiltersModule.h" // for export macro
#include "vtkType.h"             // for vtkIdType

#include "Core/Status.h"
#include "Core/Tasks.h"
#include "Core/TetMesh.h"

#include <functional>
#include <string>
#include <vector>

class vtkCellData;
class vtkUnstructuredGrid;

namespace cgmesh
{

// Whether a VTK data type (VTK_INT, VTK_DOUBLE, ...) is an integer type, vtkIdType included.
CGMESHFILTERS_EXPORT bool isIntegerDataType(int vtkType);

// The cell type of every cell of `grid`, read from its types array (one virtual GetCellType()
// call per cell cost 0.05 s on 844k cells); null when the grid has no cells.
const unsigned char* cellTypesOf(vtkUnstructuredGrid* grid);

// Number of cells of `grid` that are not linear tetrahedra (VTK_TETRA), nor triangles when
// `trianglesAccepted`.
CGMESHFILTERS_EXPORT vtkIdType countNonTetrahedra(
  vtkUnstructuredGrid* grid, bool trianglesAccepted = false);

// The cells of `grid` that are not linear tetrahedra (nor triangles, when `trianglesAccepted`), by
// type ("3 Line, 2 Hexahedron"), and what to do about them: lower-dimensional cells are dropped
// with Extract Cells By Type, other volume cells are split with Tetrahedralize. Empty when there
// are none.
CGMESHFILTERS_EXPORT std::string describeNonTetrahedra(
  vtkUnstructuredGrid* grid, bool trianglesAccepted = false);

// Output cell i receives every array's tuple of input cell sourceOf(i), for the `numberOfCells`
// output cells. `parallelFor` runs the copies of plain arrays in ranges of cells (sourceOf is
// called concurrently); the output does not depend on it.
CGMESHFILTERS_EXPORT void copyCellData(vtkCellData* input, vtkIdType numberOfCells,
  const std::function<vtkIdType(vtkIdType)>& sourceOf, vtkCellData* output,
  const ParallelFor& parallelFor = ParallelFor(runSerially));

// Copies points and tetrahedra of `grid` into `mesh`. When `regionArrayName` is not empty the named
// cell array (any numeric type, first component, converted to int) becomes mesh.regions; a missing
// or non-numeric array is a failure. When `sizeArrayName` is not empty the named point array, or
// else cell array averaged to the points, becomes mesh.sizes (one component, positive and finite
// values, else a failure naming the first bad value). The grid must hold only VTK_TETRA cells.
// Points, cells and regions are read by ranges through `parallelFor`.
CGMESHFILTERS_EXPORT Status convertToTetMesh(vtkUnstructuredGrid* grid,
  const std::string& regionArrayName, TetMesh& mesh,
  const std::string& sizeArrayName = std::string(),
  const ParallelFor& parallelFor = ParallelFor(runSerially));

// Replaces the geometry of `grid` with `mesh` (double points, VTK_TETRA cells). When the mesh has
// regions and `regionArrayName` is not empty, they are stored as an int cell array of that name.
// The grid's points, connectivity and regions take over the mesh's vectors without a copy (see
// cgmeshHandedOverArrays.h); `mesh` is left empty. `parallelFor` fills the offsets in ranges: the
// first write to a fresh page costs more than the write itself, and it is done by the thread that
// writes it.
CGMESHFILTERS_EXPORT void convertToUnstructuredGrid(TetMesh&& mesh, vtkUnstructuredGrid* grid,
  const std::string& regionArrayName = std::string(),
  const ParallelFor& parallelFor = ParallelFor(runSerially));

// The same for a mesh the caller keeps: its points, tets and regions are copied first.
CGMESHFILTERS_EXPORT void convertToUnstructuredGrid(const TetMesh& mesh, vtkUnstructuredGrid* grid,
  const std::string& regionArrayName = std::string(),
  const ParallelFor& parallelFor = ParallelFor(runSerially));

} // namespace cgmesh

#endif
