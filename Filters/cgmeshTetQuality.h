// Per-tetrahedron quality arrays shared by the filter and the command-line driver.
#ifndef cgmeshTetQuality_h
#define cgmeshTetQuality_h

#include "cgmeshFiltersModule.h" // for export macro

class vtkUnstructuredGrid;

namespace cgmesh
{

// Adds the cell arrays EdgeRatio and MinDihedralAngle (degrees) to `grid`, which must hold only
// linear tetrahedra. The values are vtkMeshQuality's per-cell tet measures, computed in blocks of
// cells spread over `threads` threads (0 = all cores); the result does not depend on `threads`.
// Returns the seconds spent.
CGMESHFILTERS_EXPORT double addTetQualityArrays(vtkUnstructuredGrid* grid, int threads);

} // namespace cgmesh

#endif
