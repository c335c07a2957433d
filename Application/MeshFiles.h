// Reading and writing unstructured grids as XML (.vtu) or legacy (.vtk) files, chosen by extension.
#ifndef cgmesh_MeshFiles_h
#define cgmesh_MeshFiles_h

#include "Core/Status.h"

#include <string>

class vtkUnstructuredGrid;

namespace cgmesh
{

// Fails with a one-line message for a missing file, an unknown extension or a reader error.
Status readUnstructuredGrid(const std::string& fileName, vtkUnstructuredGrid* grid);

// Fails unless `fileName` has a known extension and its directory exists: checked before a long
// run, so that a typo does not cost a refinement.
Status checkOutputFileName(const std::string& fileName);

// Writes to a temporary file next to `fileName` and renames it, so a failed write never leaves a
// partial `fileName` behind.
Status writeUnstructuredGrid(vtkUnstructuredGrid* grid, const std::string& fileName);

} // namespace cgmesh

#endif
