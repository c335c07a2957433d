#include "vtkCoarseGrainedMeshAdaptation.h"

#include "cgmeshAdaptedGrid.h"
#include "cgmeshMaterialLabels.h"
#include "cgmeshPointData.h"
#include "cgmeshTetQuality.h"
#include "cgmeshTriangleCells.h"
#include "cgmeshVTKConversion.h"

#include "AdaptationDriver.h"
#include "Core/Stopwatch.h"

#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkLongArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkCoarseGrainedMeshAdaptation);

namespace
{

// A Choice parameter's name for a value, or nullptr out of range.
const char* choiceName(const char* parameter, int value)
{
  const auto& choices = cgmesh::findParameter(parameter)->choices;
  return value >= 0 && value < static_cast<int>(choices.size()) ? choices[value].name : nullptr;
}

int choiceValue(const char* parameter, const char* name)
{
  return name ? cgmesh::choiceIndex(*cgmesh::findParameter(parameter), name) : -1;
}

// Fallback warnings beyond this many are summed up in one line, so that a mesh on which TetGen
// fails everywhere does not flood the output window.
constexpr std::size_t MaximumFallbackWarnings = 20;

// Share of the progress bar given to adaptMesh; the rest covers array transfer and quality.
constexpr double AdaptationProgressShare = 0.85;

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
void addTextDiagnostics(const cgmesh::AdaptationSummary& result,
  vtkCoarseGrainedMeshAdaptation* filter, vtkFieldData* fieldData)
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

void addFieldData(const cgmesh::AdaptationSummary& result, vtkCoarseGrainedMeshAdaptation* filter,
  double qualitySeconds, double totalSeconds, vtkFieldData* fieldData)
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
  for (int phase = 0; phase < static_cast<int>(cgmesh::Phase::Count); ++phase)
  {
    std::string name = cgmesh::phaseName(static_cast<cgmesh::Phase>(phase));
    name[0] = static_cast<char>(std::toupper(name[0]));
    addFieldValue(
      fieldData, (name + "Seconds").c_str(), result.seconds[static_cast<cgmesh::Phase>(phase)]);
  }
  addFieldValue(fieldData, "QualitySeconds", qualitySeconds);
  addFieldValue(fieldData, "TotalSeconds", totalSeconds);
}

// The filter's parameters, with the progress and abort hooks of this run. Provenance is needed to
// interpolate point data and to find the children of triangles.
cgmesh::AdaptationOptions makeOptions(vtkCoarseGrainedMeshAdaptation* filter,
  const cgmesh::AdaptationOptions& parameters, vtkUnstructuredGrid* input, bool withTriangles)
{
  cgmesh::AdaptationOptions options = parameters;
  options.pointProvenance = input->GetPointData()->GetNumberOfArrays() > 0 || withTriangles;
  // The driver calls both hooks on the calling thread only.
  options.progress = [filter](double fraction, const char*)
  {
    filter->UpdateProgress(AdaptationProgressShare * fraction);
  };
  options.abortRequested = [filter]()
  {
    return filter->CheckAbort();
  };
  return options;
}

// Forwards the driver's warnings; fallback warnings beyond the first few are summed up.
void reportWarnings(
  vtkCoarseGrainedMeshAdaptation* filter, const cgmesh::AdaptationSummary& summary)
{
  std::size_t fallbackWarnings = 0;
  for (const cgmesh::AdaptationWarning& warning : summary.warnings)
  {
    if (warning.kind == cgmesh::WarningKind::DelaunayFallback &&
      ++fallbackWarnings > MaximumFallbackWarnings)
    {
      continue;
    }
    vtkWarningWithObjectMacro(filter, << warning.text);
  }
  if (fallbackWarnings > MaximumFallbackWarnings)
  {
    vtkWarningWithObjectMacro(filter, << "Delaunay refinement fell back to templates in "
                                      << fallbackWarnings << " partition refinements; "
                                      << fallbackWarnings - MaximumFallbackWarnings
                                      << " of these warnings are not shown.");
  }
}

} // namespace

class vtkCoarseGrainedMeshAdaptation::vtkInternals
{
public:
  cgmesh::AdaptationOptions Parameters; // the table's defaults until set
  cgmesh::AdaptationSummary LastSummary;
  double LastQualitySeconds = 0;
  double LastTotalSeconds = 0;
  bool HasRun = false;
  std::string MaterialLabelArrays; // comma-separated, of the last run
};

//------------------------------------------------------------------------------
vtkCoarseGrainedMeshAdaptation::vtkCoarseGrainedMeshAdaptation()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkCoarseGrainedMeshAdaptation::~vtkCoarseGrainedMeshAdaptation()
{
  delete this->Internals;
}

//------------------------------------------------------------------------------
void vtkCoarseGrainedMeshAdaptation::SetParameterValue(const char* name, double value)
{
  const cgmesh::ParameterSpec* spec = name ? cgmesh::findParameter(name) : nullptr;
  if (!spec || spec->kind == cgmesh::ParameterKind::Text)
  {
    vtkErrorMacro(<< "No numeric parameter named " << (name ? name : "(null)") << ".");
    return;
  }
  if (cgmesh::setNumericValue(*spec, value, this->Internals->Parameters))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
double vtkCoarseGrainedMeshAdaptation::GetParameterValue(const char* name)
{
  const cgmesh::ParameterSpec* spec = name ? cgmesh::findParameter(name) : nullptr;
  if (!spec || spec->kind == cgmesh::ParameterKind::Text)
  {
    vtkErrorMacro(<< "No numeric parameter named " << (name ? name : "(null)") << ".");
    return 0;
  }
  return cgmesh::numericValue(*spec, this->Internals->Parameters);
}

//------------------------------------------------------------------------------
void vtkCoarseGrainedMeshAdaptation::SetParameterText(const char* name, const char* value)
{
  const cgmesh::ParameterSpec* spec = name ? cgmesh::findParameter(name) : nullptr;
  if (!spec || spec->kind != cgmesh::ParameterKind::Text)
  {
    vtkErrorMacro(<< "No text parameter named " << (name ? name : "(null)") << ".");
    return;
  }
  if (cgmesh::setTextValue(*spec, value ? value : "", this->Internals->Parameters))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
const char* vtkCoarseGrainedMeshAdaptation::GetParameterText(const char* name)
{
  const cgmesh::ParameterSpec* spec = name ? cgmesh::findParameter(name) : nullptr;
  const auto* field =
    spec ? std::get_if<std::string cgmesh::AdaptationOptions::*>(&spec->field) : nullptr;
  if (!spec || spec->kind != cgmesh::ParameterKind::Text || !field)
  {
    vtkErrorMacro(<< "No text parameter named " << (name ? name : "(null)") << ".");
    return nullptr;
  }
  // An empty text reads as unset, as vtkGetStringMacro's nullptr.
  const std::string& value = this->Internals->Parameters.**field;
  return value.empty() ? nullptr : value.c_str();
}

//------------------------------------------------------------------------------
const cgmesh::AdaptationSummary* vtkCoarseGrainedMeshAdaptation::GetLastSummary() const
{
  return this->Internals->HasRun ? &this->Internals->LastSummary : nullptr;
}

//------------------------------------------------------------------------------
double vtkCoarseGrainedMeshAdaptation::GetLastQualitySeconds() const
{
  return this->Internals->LastQualitySeconds;
}

//------------------------------------------------------------------------------
double vtkCoarseGrainedMeshAdaptation::GetLastTotalSeconds() const
{
  return this->Internals->LastTotalSeconds;
}

//------------------------------------------------------------------------------
const char* vtkCoarseGrainedMeshAdaptation::ColoringAlgorithmToName(int algorithm)
{
  return choiceName("ColoringAlgorithm", algorithm);
}

//------------------------------------------------------------------------------
int vtkCoarseGrainedMeshAdaptation::ColoringAlgorithmFromName(const char* name)
{
  return choiceValue("ColoringAlgorithm", name);
}

//------------------------------------------------------------------------------
const char* vtkCoarseGrainedMeshAdaptation::PartitionerToName(int partitioner)
{
  return choiceName("Partitioner", partitioner);
}

//------------------------------------------------------------------------------
int vtkCoarseGrainedMeshAdaptation::PartitionerFromName(const char* name)
{
  return choiceValue("Partitioner", name);
}

//------------------------------------------------------------------------------
const char* vtkCoarseGrainedMeshAdaptation::GetMaterialLabelArrays() const
{
  return this->Internals->MaterialLabelArrays.c_str();
}

//------------------------------------------------------------------------------
const char* vtkCoarseGrainedMeshAdaptation::MethodToName(int method)
{
  return choiceName("Method", method);
}

//------------------------------------------------------------------------------
int vtkCoarseGrainedMeshAdaptation::MethodFromName(const char* name)
{
  return choiceValue("Method", name);
}

//------------------------------------------------------------------------------
std::string vtkCoarseGrainedMeshAdaptation::ResolveRegionArrayName(vtkUnstructuredGrid* input) const
{
  const std::string& name = this->Internals->Parameters.regionArrayName;
  // "None" is ParaView's "no array" entry, unless the input really has an array of that name.
  if (name == "None" && !input->GetCellData()->GetAbstractArray("None"))
  {
    return std::string();
  }
  return name;
}

//------------------------------------------------------------------------------
std::string vtkCoarseGrainedMeshAdaptation::ResolveSizeArrayName(vtkUnstructuredGrid* input) const
{
  const std::string& name = this->Internals->Parameters.sizeArrayName;
  if (name == "None" && !input->GetPointData()->GetAbstractArray("None") &&
    !input->GetCellData()->GetAbstractArray("None"))
  {
    return std::string();
  }
  return name;
}

//------------------------------------------------------------------------------
bool vtkCoarseGrainedMeshAdaptation::CheckInput(vtkUnstructuredGrid* input)
{
  const vtkIdType unsupported = cgmesh::countNonTetrahedra(input, /*trianglesAccepted=*/true);
  if (unsupported > 0)
  {
    vtkErrorMacro(<< "The input must hold only linear tetrahedra and triangles, but " << unsupported
                  << " of its " << input->GetNumberOfCells() << " cells are of other types: "
                  << cgmesh::describeNonTetrahedra(input, /*trianglesAccepted=*/true));
    return false;
  }
  if (!this->Internals->Parameters.refinementRegions.empty() &&
    this->ResolveRegionArrayName(input).empty())
  {
    vtkErrorMacro(<< "RefinementRegions needs a region array (RegionArrayName): the region ids "
                     "it lists are values of that array.");
    return false;
  }
  if (this->GetPartitionByRegion() && this->ResolveRegionArrayName(input).empty())
  {
    vtkErrorMacro(<< "PartitionByRegion needs a region array: set RegionArrayName to the cell "
                     "array of material/region ids to cut along.");
    return false;
  }
  const cgmesh::Status pointArrays = cgmesh::checkPointArrayRoles(input->GetPointData(),
    cgmesh::splitNames(this->Internals->Parameters.interpolatedPointArrays),
    cgmesh::splitNames(this->Internals->Parameters.labelPointArrays));
  if (!pointArrays.ok())
  {
    vtkErrorMacro(<< pointArrays.message() << ".");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkCoarseGrainedMeshAdaptation::RequestData(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  const cgmesh::Stopwatch stopwatch;
  this->Internals->HasRun = false;
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  output->Initialize();
  if (!input || input->GetNumberOfCells() == 0)
  {
    vtkWarningMacro(<< "The input has no cells; the output is empty.");
    return 1;
  }
  if (!this->CheckInput(input))
  {
    return 0;
  }

  // Triangles tag faces of the tets: the tets are adapted, the triangles follow their faces.
  vtkSmartPointer<vtkUnstructuredGrid> tets = input;
  cgmesh::TriangleCells triangles;
  const bool withTriangles = cgmesh::hasTriangles(input);
  if (withTriangles)
  {
    tets = vtkSmartPointer<vtkUnstructuredGrid>::New();
    cgmesh::separateTriangles(input, tets, triangles);
    if (tets->GetNumberOfCells() == 0)
    {
      vtkErrorMacro(<< "The input holds triangles but no tetrahedra: there is no volume mesh to "
                       "refine.");
      return 0;
    }
  }

  cgmesh::TetMesh inputMesh;
  const std::string regionArrayName = this->ResolveRegionArrayName(input);
  cgmesh::Status status =
    cgmesh::convertToTetMesh(tets, regionArrayName, inputMesh, this->ResolveSizeArrayName(input));
  if (!status.ok())
  {
    vtkErrorMacro(<< "Cannot read the input: " << status.message() << ".");
    return 0;
  }
  // Without a region array, the input's integer cell arrays guard the material interfaces.
  this->Internals->MaterialLabelArrays.clear();
  if (regionArrayName.empty())
  {
    const std::vector<std::string> labels = cgmesh::findMaterialLabelArrays(tets);
    if (!labels.empty())
    {
      cgmesh::combineMaterialLabels(tets, labels, inputMesh);
    }
    for (const std::string& name : labels)
    {
      this->Internals->MaterialLabelArrays +=
        (this->Internals->MaterialLabelArrays.empty() ? "" : ",") + name;
    }
  }
  if (withTriangles && !(status = cgmesh::checkTriangleCells(inputMesh, triangles)).ok())
  {
    vtkErrorMacro(<< "Cannot refine the input's triangles: " << status.message() << ".");
    return 0;
  }

  cgmesh::AdaptationResult result;
  status = cgmesh::adaptMesh(
    inputMesh, makeOptions(this, this->Internals->Parameters, input, withTriangles), result);
  this->Internals->LastSummary = result.summary;
  this->Internals->LastQualitySeconds = 0;
  this->Internals->HasRun = true;
  reportWarnings(this, result.summary);
  if (!status.ok())
  {
    vtkErrorMacro(<< "Mesh adaptation failed: " << status.message());
    return 0;
  }
  if (result.summary.aborted)
  {
    vtkWarningMacro(<< "Mesh adaptation was aborted; the output is empty.");
    return 1;
  }

  cgmesh::AdaptedGridInput adapted;
  adapted.grid = input;
  adapted.mesh = &inputMesh;
  adapted.triangles = withTriangles ? &triangles : nullptr;
  adapted.interpolatedPointArrays = this->Internals->Parameters.interpolatedPointArrays;
  adapted.labelPointArrays = this->Internals->Parameters.labelPointArrays;
  cgmesh::fillAdaptedGrid(adapted, result, output);
  this->UpdateProgress(0.9);
  const cgmesh::Stopwatch qualityStopwatch;
  status = cgmesh::addTetQualityArrays(output, result.summary.plan.threads);
  const double qualitySeconds = qualityStopwatch.seconds();
  if (!status.ok())
  {
    output->Initialize();
    vtkErrorMacro(<< "Quality arrays failed: " << status.message());
    return 0;
  }
  this->Internals->LastQualitySeconds = qualitySeconds;
  this->Internals->LastTotalSeconds = stopwatch.seconds();
  addFieldData(result.summary, this, qualitySeconds, this->Internals->LastTotalSeconds,
    output->GetFieldData());
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkCoarseGrainedMeshAdaptation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  for (const cgmesh::ParameterSpec& spec : cgmesh::parameterTable())
  {
    os << indent << spec.name << ": ";
    if (spec.kind == cgmesh::ParameterKind::Text || spec.kind == cgmesh::ParameterKind::Choice)
    {
      const std::string text = cgmesh::textValue(spec, this->Internals->Parameters);
      os << (text.empty() ? "(none)" : text) << "\n";
    }
    else
    {
      const double value = cgmesh::numericValue(spec, this->Internals->Parameters);
      // A count of 0 is the size guard switched off.
      os << value << (spec.kind == cgmesh::ParameterKind::Count && value == 0 ? " (no limit)" : "")
         << "\n";
    }
  }
}
