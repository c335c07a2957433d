// Material labels kept by default: when no region array is chosen, the integer cell arrays of the
// input are taken together as the region labelling, so that improvement never moves a material
// interface and the Delaunay method keeps it, whatever array the user forgot to name.
#ifndef cgmeshMaterialLabels_h
#define cgmeshMaterialLabels_h

#include "cgmeshFiltersModule.h" // for export macro

#include "Core/Status.h"
#include "Core/Tasks.h"
#include "Core/TetMesh.h"

#include <string>
#include <vector>

class vtkUnstructuredGrid;

namespace cgmesh
{

// The cell arrays of `grid` that label materials: single-component arrays of an integer type,
// except ids (the global and pedigree id attributes, vtkOriginalCellIds), VTK's ghost and process
// flags, and the arrays cgmesh itself adds to its output (PartitionId, ColorId,
// NearFormerInterface), which describe a previous run, not the materials, and arrays with more
// than 64 distinct values, or 1% of the cells when that is more (ids again, under another name,
// or parent ids carried over by an earlier refinement). In array order.
CGMESHFILTERS_EXPORT std::vector<std::string> findMaterialLabelArrays(vtkUnstructuredGrid* grid);

// Sets mesh.regions from the arrays named: cells with the same value in every array share a
// region id, numbered 0, 1, ... in the sorted order of the value combinations. Reads ranges of
// cells through `parallelFor`; the result does not depend on the schedule.
CGMESHFILTERS_EXPORT Status combineMaterialLabels(vtkUnstructuredGrid* grid,
  const std::vector<std::string>& arrayNames, const ParallelFor& parallelFor, TetMesh& mesh);

} // namespace cgmesh

#endif
