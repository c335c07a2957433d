// TetGen's .node/.ele/.face files, read and written through TetGen's own library (tetgenio, the
// library the Delaunay method already uses). IN or OUT names the .ele or the .node file; the
// three files share its base name.
//
// In memory: the .node points (their boundary markers, when present, as the integer point array
// Marker), the .ele tetrahedra with their first attribute (TetGen's region attribute) as the cell
// array Tag (TagArrayName), and the .face triangles, when the file exists, with their markers as
// Tag. Writing is the reverse: tetrahedra and triangles are numbered from 1, as TetGen numbers its
// own output.
#ifndef cgmesh_TetGenFiles_h
#define cgmesh_TetGenFiles_h

#include "Core/Status.h"
#include "MeshFiles.h"

#include <string>

class vtkUnstructuredGrid;

namespace cgmesh
{

// True for the extensions handled here (.ele, .node).
bool isTetGenFileName(const std::string& fileName);

Status readTetGenFiles(const std::string& fileName, vtkUnstructuredGrid* grid);

// options.tagArray gives the region attributes and face markers; empty or missing: none are
// written. Writes the .node, .ele and .face files of `fileName`'s base name.
Status writeTetGenFiles(
  vtkUnstructuredGrid* grid, const std::string& fileName, const WriteOptions& options);

} // namespace cgmesh

#endif
