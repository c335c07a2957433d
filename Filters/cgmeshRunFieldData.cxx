#include "cgmeshRunFieldData.h"

#include "vtkCoarseGrainedMeshAdaptation.h"

#include "AdaptationDriver.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkLongArray.h"
#include "vtkNew.h"
#include "vtkStringArray.h"

#include <cctype>
#include <cstdint>
#include <string>
#include <vector>

namespace cgmesh
{

void addFieldValue(vtkFieldData* fieldData, const char* name, double value)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->SetNumberOfValues(1);
  array->SetValue(0, value);
  fieldData->AddArray(array);
}

void addFieldValue(vtkFieldData* fieldData, const char* name, int value)
{
  vtkNew<vtkIntArray> array;
  array->SetName(name);
  array->SetNumberOfValues(1);
  array->SetValue(0, value);
  fieldData->AddArray(array);
}

namespace
{

void addFieldString(vtkFieldData* fieldData, const char* name, const char* value)
{
  vtkNew<vtkStringArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  fieldData->AddArray(array);
}

// One tuple per colour.
void addColorPopulation(
  vtkFieldData* fieldData, const char* name, const std::vector<std::int64_t>& countPerColor)
{
  // A plain 64-bit long array: legacy files name a vtkIdTypeArray's type "vtkIdType", which other
  // readers (meshio) do not know.
  vtkNew<vtkLongArray> array;
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(countPerColor.size()));
  for (size_t color = 0; color < countPerColor.size(); ++color)
  {
    array->SetValue(static_cast<vtkIdType>(color), static_cast<long>(countPerColor[color]));
  }
  fieldData->AddArray(array);
}

// The field data some readers refuse (string arrays, an array that may be empty): only with
// Diagnostics on.
void addTextDiagnostics(
  const AdaptationSummary& result, vtkCoarseGrainedMeshAdaptation* filter, vtkFieldData* fieldData)
{
  addFieldString(fieldData, "Method", filter->GetMethodName());
  addFieldString(fieldData, "ColoringAlgorithm", filter->GetColoringAlgorithmName());
  vtkNew<vtkIntArray> fallbackPartitions; // one tuple per fallback, in refinement order
  fallbackPartitions->SetName("FallbackPartitions");
  for (const int partition : result.fallbackPartitions)
  {
    fallbackPartitions->InsertNextValue(partition);
  }
  fieldData->AddArray(fallbackPartitions);
}

} // namespace

void addRunFieldData(
  const AdaptationSummary& result, vtkCoarseGrainedMeshAdaptation* filter, vtkFieldData* fieldData)
{
  addFieldValue(fieldData, "NumberOfColors", result.numberOfColors);
  addFieldValue(fieldData, "NumberOfPartitions", result.plan.partitions);
  addFieldValue(fieldData, "NumberOfThreads", result.plan.threads);
  addFieldValue(fieldData, "EdgeLengthThreshold", result.plan.edgeLengthThreshold);
  addFieldValue(fieldData, "MethodIndex", filter->GetMethod());
  addFieldValue(fieldData, "VolumeBound", result.plan.volumeBound);
  addFieldValue(fieldData, "DelaunayFallbacks", static_cast<double>(result.delaunayFallbacks));
  addFieldValue(fieldData, "TetGenPoints", static_cast<double>(result.tetgenPoints));
  addFieldValue(fieldData, "IterationsRun", result.iterationsRun);
  addFieldValue(fieldData, "RefinementConverged", result.refinementConverged ? 1 : 0);
  addFieldValue(fieldData, "TetGenRetries", static_cast<double>(result.tetgenRetries));
  addFieldValue(
    fieldData, "TetGenWithoutQualityBound", static_cast<double>(result.tetgenWithoutQualityBound));
  addFieldValue(fieldData, "TetGenRemeshed", static_cast<double>(result.tetgenRemeshed));
  addFieldValue(fieldData, "SweepRemeshedBoxes", static_cast<double>(result.sweepRemeshedBoxes));
  addFieldValue(fieldData, "SweepDroppedPoints", static_cast<double>(result.sweepDroppedPoints));
  addFieldValue(fieldData, "SweepRemeshFailures", static_cast<double>(result.sweepRemeshFailures));
  addFieldValue(fieldData, "InputRemeshedBoxes", static_cast<double>(result.inputRemeshedBoxes));
  addFieldValue(fieldData, "InputDroppedPoints", static_cast<double>(result.inputDroppedPoints));
  addFieldValue(fieldData, "InputRemeshFailures", static_cast<double>(result.inputRemeshFailures));
  addFieldValue(fieldData, "ColoringAlgorithmIndex", filter->GetColoringAlgorithm());
  // The partitioner used: Automatic resolved to METIS or Hilbert.
  addFieldValue(fieldData, "PartitionerIndex", static_cast<int>(result.plan.partitioner));
  if (result.plan.sizeField)
  {
    addFieldValue(fieldData, "EdgesWithinSizeBounds", result.edgeSizes.shareWithinBounds);
    vtkNew<vtkLongArray> histogram; // edges by length / h, bins split at 1/2, 1/sqrt2, 1, sqrt2, 2
    histogram->SetName("EdgeSizeRatioHistogram");
    for (const std::int64_t count : result.edgeSizes.histogram)
    {
      histogram->InsertNextValue(static_cast<long>(count));
    }
    fieldData->AddArray(histogram);
  }
  if (filter->GetDiagnostics())
  {
    addTextDiagnostics(result, filter, fieldData);
  }
  addColorPopulation(fieldData, "PartitionsPerColor", result.partitionsPerColor);
  addColorPopulation(fieldData, "CellsPerColor", result.cellsPerColor);
  addFieldValue(fieldData, "ColorBalance", result.colorBalance);
  addFieldValue(fieldData, "EdgeRemovals", static_cast<double>(result.edgeRemovals));
  addFieldValue(fieldData, "EdgeCollapses", static_cast<double>(result.edgeCollapses));
  addFieldValue(fieldData, "FaceSwaps", static_cast<double>(result.faceSwaps));
  addFieldValue(fieldData, "VertexMoves", static_cast<double>(result.vertexMoves));
  // Per-partition task times and the colouring: the data for makespan models of the colour loop.
  vtkNew<vtkDoubleArray> taskSeconds; // entry iteration * NumberOfPartitions + partition
  taskSeconds->SetName("PartitionTaskSeconds");
  for (const double seconds : result.partitionTaskSeconds)
  {
    taskSeconds->InsertNextValue(seconds);
  }
  fieldData->AddArray(taskSeconds);
  vtkNew<vtkIntArray> colorOfPartition;
  colorOfPartition->SetName("ColorOfPartition");
  for (const int color : result.colorOfPartition)
  {
    colorOfPartition->InsertNextValue(color);
  }
  fieldData->AddArray(colorOfPartition);
  // One array per phase ("PrepareSeconds", "PartitionSeconds", ...), then the filter's own.
  for (int phase = 0; phase < static_cast<int>(Phase::Count); ++phase)
  {
    std::string name = phaseName(static_cast<Phase>(phase));
    name[0] = static_cast<char>(std::toupper(name[0]));
    addFieldValue(fieldData, (name + "Seconds").c_str(), result.seconds[static_cast<Phase>(phase)]);
  }
  addFieldValue(fieldData, "InputSeconds", filter->GetLastInputSeconds());
  addFieldValue(fieldData, "OutputSeconds", filter->GetLastOutputSeconds());
  addFieldValue(fieldData, "QualitySeconds", filter->GetLastQualitySeconds());
  addFieldValue(fieldData, "TotalSeconds", filter->GetLastTotalSeconds());
}

} // namespace cgmesh
