// Integer tags read from cell and point arrays, as the mesh file writers store them: Gmsh physical
// groups, Exodus ids, TetGen markers. Header-only, for the Gmsh module links none of the command
// line's sources.
#ifndef cgmesh_FileTags_h
#define cgmesh_FileTags_h

#include "vtkDataArray.h"

#include <algorithm>
#include <cmath>

namespace cgmesh
{

// The value of tuple `id` of `array` rounded to an integer; `fallback` when there is no array.
inline int tagValue(vtkDataArray* array, vtkIdType id, int fallback = 0)
{
  return array ? static_cast<int>(std::lround(array->GetComponent(id, 0))) : fallback;
}

// What to add to every value of `tags` so that all are positive, as Gmsh physical groups and Exodus
// ids must be: 0 when they already are, or when there is no array (every cell then gets tag 1).
inline int positiveTagShift(vtkDataArray* tags)
{
  int shift = 0;
  for (vtkIdType id = 0; tags && id < tags->GetNumberOfTuples(); ++id)
    shift = std::max(shift, 1 - tagValue(tags, id));
  return shift;
}

} // namespace cgmesh

#endif
