// Checks of `cgmesh refine` around the filter run: a size forecast over all iterations before the
// first one, and a warning when a run refined nothing.
#ifndef cgmesh_RefineChecks_h
#define cgmesh_RefineChecks_h

#include "AdaptationOptions.h"
#include "Core/Status.h"
#include "RefineReport.h"

#include <string>

class vtkUnstructuredGrid;

namespace cgmesh
{

// Template method, two or more iterations: fails with a SizeLimit status when a lower bound of the
// tets the last iteration makes exceeds MaximumNumberOfCells. The filter's own guard forecasts one
// iteration at a time, so without this a run that is refused in a late iteration has spent the
// time and memory of the earlier ones. Succeeds whenever it cannot tell (the filter then reports).
Status checkSizeBeforeRefining(vtkUnstructuredGrid* input, const AdaptationOptions& options);

// A one-line warning, with the threshold and the longest edge (the volume bound for Delaunay),
// when the run added no point; empty otherwise.
std::string nothingRefinedWarning(
  vtkUnstructuredGrid* input, const AdaptationOptions& options, const RefineStatistics& statistics);

} // namespace cgmesh

#endif
