// The filter's output grid from an adaptation result: the tetrahedra, the children of tagged input
// triangles after them, every input cell array carried from each cell's parent, point data through
// provenance, the per-cell arrays of the run (PartitionId, ColorId, NearFormerInterface,
// EdgeLengthRatio) and, with a size field, the point array TargetEdgeLength.
#ifndef cgmeshAdaptedGrid_h
#define cgmeshAdaptedGrid_h

#include "cgmeshTriangleCells.h"

#include "AdaptationDriver.h"

#include <string>

class vtkUnstructuredGrid;

namespace cgmesh
{

struct AdaptedGridInput
{
  vtkUnstructuredGrid* grid = nullptr;      // the filter's input, triangles included
  const TetMesh* mesh = nullptr;            // its tetrahedra as adapted
  const TriangleCells* triangles = nullptr; // null when the input has only tetrahedra
  std::string interpolatedPointArrays;      // comma-separated integer point arrays to interpolate
  std::string labelPointArrays;             // comma-separated floating-point arrays kept as labels
};

// What fillAdaptedGrid does with the result's mesh and per-tet arrays: hands their storage over to
// the output's arrays (the result is left without them; nothing is copied), or copies them for a
// caller that still needs them.
enum class ResultArrays
{
  HandOver,
  Copy
};

// Fills `output`. The cells of the run's arrays that are triangles get -1 (PartitionId, ColorId),
// 0 (NearFormerInterface) or NaN (EdgeLengthRatio): they were not refined as cells of a partition.
void fillAdaptedGrid(const AdaptedGridInput& input, AdaptationResult& result,
  vtkUnstructuredGrid* output, ResultArrays handling);

} // namespace cgmesh

#endif
