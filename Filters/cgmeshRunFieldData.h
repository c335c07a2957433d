// The field data a run leaves on the filter's output: its counts, plan, colouring, improvement
// figures and seconds per phase, read by the command line's report, benchmarks and scripts.
#ifndef cgmeshRunFieldData_h
#define cgmeshRunFieldData_h

class vtkCoarseGrainedMeshAdaptation;
class vtkFieldData;

namespace cgmesh
{
struct AdaptationSummary;

// One named single-value array.
void addFieldValue(vtkFieldData* fieldData, const char* name, double value);
void addFieldValue(vtkFieldData* fieldData, const char* name, int value);

// The run's figures from `result` and the filter's own (method and colouring, the seconds of the
// input, output and quality arrays, total). Text and possibly empty arrays only with the
// filter's Diagnostics: some readers (meshio) refuse them.
void addRunFieldData(
  const AdaptationSummary& result, vtkCoarseGrainedMeshAdaptation* filter, vtkFieldData* fieldData);

} // namespace cgmesh

#endif
