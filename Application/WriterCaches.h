// Fills the caches that vtkXMLUnstructuredGridWriter reads before it writes a grid.
//
// The writer asks the grid for its distinct cell types and every data array for its range, for
// the file's RangeMin/RangeMax. VTK 9.2 computes the first at about 250 ns per cell and a range at
// about 25 ns per value: 0.7 s of the 1.0 s an LZ4 write of 1.9 M tets took. VTK caches both
// results; the values filled in here are the ones it would compute, from plain loops. The only
// trace in the file: an array with a cached range is written as an empty element with a closing
// tag instead of a self-closing one (the writer opens an element for arrays carrying information).
#ifndef cgmesh_WriterCaches_h
#define cgmesh_WriterCaches_h

#include "vtkSmartPointer.h"

class vtkUnstructuredGrid;

namespace cgmesh
{

// A shallow copy of `grid` with the distinct cell types and the ranges of its one-component point,
// cell and field data arrays cached (on the shared arrays). Arrays with NaN values, several
// components (the points) or non-contiguous memory are left for VTK to compute.
vtkSmartPointer<vtkUnstructuredGrid> gridWithWriterCaches(vtkUnstructuredGrid* grid);

} // namespace cgmesh

#endif
