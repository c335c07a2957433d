// Mixed tetrahedra and triangles, as FEM and TCAD meshes from Gmsh, Exodus or meshio hold them:
// the triangles tag boundary and material-interface faces (boundary conditions, contacts) and are
// refined with the tet faces they lie on, their children carrying their cell data.
#ifndef cgmeshTriangleCells_h
#define cgmeshTriangleCells_h

#include "cgmeshFiltersModule.h" // for export macro
#include "vtkType.h"             // for vtkIdType

#include "Core/FaceKey.h"
#include "Core/Status.h"
#include "Merge/TaggedTriangles.h"

#include <utility>
#include <vector>

class vtkUnstructuredGrid;

namespace cgmesh
{

struct TriangleCells
{
  std::vector<vtkIdType> tetCellIds;      // input cell id of each tet, in input order
  std::vector<vtkIdType> triangleCellIds; // input cell id of each triangle, in input order
  std::vector<Triangle> triangles;        // the triangles' point ids
};

// Whether `grid` holds at least one triangle.
CGMESHFILTERS_EXPORT bool hasTriangles(vtkUnstructuredGrid* grid);

// `tets` gets the points and point data of `grid` (shared, not copied) and its tetrahedra with
// their cell data; `cells` records which input cell each tet and triangle was. `grid` must hold
// only tetrahedra and triangles.
CGMESHFILTERS_EXPORT void separateTriangles(
  vtkUnstructuredGrid* grid, vtkUnstructuredGrid* tets, TriangleCells& cells);

// Fails, naming the count and the first offender by input cell id and points, unless every
// triangle is a face of a tet of `mesh` (the tets of `cells`) on the boundary or between two
// regions: a face inside one region is not kept by refinement, so its tag could not be.
CGMESHFILTERS_EXPORT Status checkTriangleCells(const TetMesh& mesh, const TriangleCells& cells);

// The triangles' surface classes, as AdaptationOptions::surfaceClasses takes them: triangles with
// equal values in every cell array of `grid` share a class; a face listed twice with different
// values gets a class of its own.
CGMESHFILTERS_EXPORT std::vector<std::pair<Face, int>> surfaceClassesOf(
  vtkUnstructuredGrid* grid, const TriangleCells& cells);

// Appends `children` to `grid` as VTK_TRIANGLE cells (after its tetrahedra).
CGMESHFILTERS_EXPORT void appendTriangles(
  const std::vector<TriangleChild>& children, vtkUnstructuredGrid* grid);

} // namespace cgmesh

#endif
