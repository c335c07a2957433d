// Gmsh .msh (formats 2.2 and 4.1) and Medit .mesh files, read and written through Gmsh's own
// library (Debian's libgmsh-dev), so every variant Gmsh itself writes is understood.
//
// In memory a file becomes an unstructured grid of tetrahedra and triangles (lines and points,
// which tag curves and corners, are read too, and the filter then names them) with two integer
// cell arrays: `Tag`, the physical group of each cell (for Medit, its reference), and `Entity`,
// the elementary entity it was meshed on. Cells of an entity that belongs to no physical group get
// the entity's tag as their `Tag`; an entity in several physical groups is read once, under the
// first. Writing is the reverse: one discrete entity per (dimension, Entity) and one physical
// group per (dimension, Tag), so physical volumes and surfaces survive the round trip; each node
// is classified on the lowest-dimensional entity of its cells, as in Gmsh's own meshes (Medit
// vertex references are those entities). Point data
// and other cell arrays are not stored: the formats have no place for them.
#ifndef cgmesh_GmshFiles_h
#define cgmesh_GmshFiles_h

#include "Core/Status.h"
#include "MeshFiles.h"

#include <string>

class vtkUnstructuredGrid;

namespace cgmesh
{

// The elementary entity of each cell (the physical group is in TagArrayName, MeshFiles.h).
constexpr const char* EntityArrayName = "Entity";

// True for the extensions handled here (.msh, .mesh).
bool isGmshFileName(const std::string& fileName);

// `names`, when given, receives the physical group names.
Status readGmshFile(const std::string& fileName, vtkUnstructuredGrid* grid, MeshFileNames* names);

// options.tagArray names the integer cell array whose values become physical groups (and
// entities, when the grid has no `Entity` array); empty or missing: every cell is in group 1.
// options.mshVersion is 2.2 or 4.1 (ignored for .mesh); options.names, when given, names groups.
Status writeGmshFile(
  vtkUnstructuredGrid* grid, const std::string& fileName, const WriteOptions& options);

} // namespace cgmesh

#endif
