// Point data of the refined mesh from the input's, through each new point's provenance (the
// input points it comes from, with weights): fields are interpolated, labels are kept only where
// the sources agree.
#ifndef cgmeshPointData_h
#define cgmeshPointData_h

#include "Core/Status.h"
#include "Merge/MeshMerge.h"

#include <string>
#include <vector>

class vtkPointData;

namespace cgmesh
{

// Floating-point arrays get the provenance-weighted sum (exact for linear fields), unless named in
// `labelArrays`; so do the integer arrays named in `interpolatedArrays`, rounded to the nearest
// integer. Every other integer
// array (global and pedigree ids aside) is a labelling, such as a node set or a contact flag: a
// point takes the value, component by component, that all its sources with a non-zero weight
// share, else 0, so no label appears away from where it was. Global point ids are extended: input
// points keep theirs, new points are numbered on from the largest. Pedigree ids are dropped.
void transferPointData(vtkPointData* input, const PointProvenance& provenance,
  const std::vector<std::string>& interpolatedArrays, const std::vector<std::string>& labelArrays,
  vtkPointData* output);

// Fails, naming the array, when `interpolatedArrays` or `labelArrays` names no point array of
// `input`, when an array is named in both, or when a label array holds a value that is not finite
// (naming the first such point): checked before refining.
Status checkPointArrayRoles(vtkPointData* input, const std::vector<std::string>& interpolatedArrays,
  const std::vector<std::string>& labelArrays);

// Comma-separated names ("a, b"), trimmed; empty entries dropped.
std::vector<std::string> splitNames(const std::string& text);

} // namespace cgmesh

#endif
