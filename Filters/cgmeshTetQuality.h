// Per-tetrahedron quality arrays shared by the filter and the command-line driver.
#ifndef cgmeshTetQuality_h
#define cgmeshTetQuality_h

#include "Core/Status.h"
#include "cgmeshFiltersModule.h" // for export macro

class vtkUnstructuredGrid;

namespace cgmesh
{

// Adds the cell arrays EdgeRatio and MinDihedralAngle (degrees) to `grid`, which must hold only
// linear tetrahedra and triangles (NaN for a triangle: the measures are of tets), computed in
// blocks of cells spread over `threads` threads (0 = all cores); the result does not depend on
// `threads`. EdgeRatio is the longest edge over the shortest, as vtkMeshQuality's tet edge ratio.
// MinDihedralAngle is the smallest angle between two faces, from the face normals
// (cgmesh::minimumDihedralAngle): vtkMeshQuality's tet MIN_ANGLE in ParaView 5.11's VTK returns
// other values (60 degrees for a Kuhn tet whose dihedral angles are 45, 60 and 90; up to 87
// degrees, above the regular tet's 70.53).
// On failure (a block that threw) neither array is added: never a partly filled one.
CGMESHFILTERS_EXPORT Status addTetQualityArrays(vtkUnstructuredGrid* grid, int threads);

} // namespace cgmesh

#endif
