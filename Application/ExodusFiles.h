// Exodus II files (.exo, .e, .ex2, .g, .gen), read and written through the Exodus library that
// ParaView's VTK carries (SEACAS's libexodus, CMake target VTK::exodusII), so every variant the
// library writes (32- or 64-bit integers, netCDF classic or 64-bit offset) is understood.
//
// In memory a file becomes:
// - its nodes, in file order;
// - the tetrahedra of every element block, block after block, with the block id as the cell
//   array Tag (TagArrayName);
// - then one triangle per side set entry (element, side), with the corners of that side of its
//   element in the order that makes the normal point out of the element, and the side set id as
//   its Tag;
// - one integer point array per node set, 1 on its nodes and 0 elsewhere, named after the set
//   (NodeSet<id> when it has no name). Refinement gives a new point the label only when both ends
//   of its edge carry it, so a node set on a face stays exactly the nodes on that face.
// Block and side set names go to MeshFileNames::physicalNames under dimensions 3 and 2, where Gmsh
// files keep their physical volume and surface names, so .exo and .msh convert into each other
// with their names; node set ids go to MeshFileNames::nodeSets.
//
// Writing is the reverse: one TETRA block per Tag value of the tetrahedra (ascending, elements
// numbered block after block), one side set per Tag value of the triangles, each triangle written
// as the side of the tetrahedron it faces out of (of either tetrahedron it is a face of, when it
// faces out of neither), and one node set per point array that MeshFileNames::nodeSets records or
// that is named NodeSet<id>. Ids must be positive: when a Tag value is not, every id is shifted
// and the names say by how much, as in Gmsh files. Time steps, results variables, attributes and
// distribution factors are not read, and other point and cell arrays are not written (the filter's
// own arrays belong in .vtu files).
#ifndef cgmesh_ExodusFiles_h
#define cgmesh_ExodusFiles_h

#include "Core/Status.h"
#include "MeshFiles.h"

#include <string>

class vtkUnstructuredGrid;

namespace cgmesh
{

// True for the extensions handled here.
bool isExodusFileName(const std::string& fileName);

// `names`, when given, receives the block, side set and node set names and the node set ids.
Status readExodusFile(const std::string& fileName, vtkUnstructuredGrid* grid, MeshFileNames* names);

// options.tagArray gives the block and side set ids; empty or missing: one block and one side set,
// both with id 1. options.names, when given, names them and says which point arrays are node sets.
Status writeExodusFile(
  vtkUnstructuredGrid* grid, const std::string& fileName, const WriteOptions& options);

} // namespace cgmesh

#endif
