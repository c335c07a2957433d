#include "vtkCoarseGrainedMeshAdaptation.h"

#include "cgmeshTetQuality.h"
#include "cgmeshVTKConversion.h"

#include "AdaptationDriver.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkCoarseGrainedMeshAdaptation);

namespace
{

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Names of vtkCoarseGrainedMeshAdaptation::ColoringAlgorithms, indexed by value; they are the
// names the driver's colouring registry knows.
const char* const ColoringAlgorithmNames[] = { "greedy", "greedy-lu", "iterative", "recoloring" };

// Names of vtkCoarseGrainedMeshAdaptation::Methods, indexed by value.
const char* const MethodNames[] = { "template", "delaunay" };

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
  vtkNew<vtkIdTypeArray> array;
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(countPerColor.size()));
  for (size_t color = 0; color < countPerColor.size(); ++color)
  {
    array->SetValue(static_cast<vtkIdType>(color), static_cast<vtkIdType>(countPerColor[color]));
  }
  fieldData->AddArray(array);
}

vtkSmartPointer<vtkIntArray> makeCellIntArray(const char* name, const std::vector<int>& values)
{
  auto array = vtkSmartPointer<vtkIntArray>::New();
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  for (size_t cellId = 0; cellId < values.size(); ++cellId)
  {
    array->SetValue(static_cast<vtkIdType>(cellId), values[cellId]);
  }
  return array;
}

// Every child cell receives all cell data of the input tet it came from.
void copyCellDataToChildren(vtkCellData* inputCellData,
  const std::vector<cgmesh::CellId>& parentCell, vtkCellData* outputCellData)
{
  const vtkIdType numberOfCells = static_cast<vtkIdType>(parentCell.size());
  outputCellData->CopyAllocate(inputCellData, numberOfCells);
  vtkNew<vtkIdList> parentIds;
  vtkNew<vtkIdList> childIds;
  parentIds->SetNumberOfIds(numberOfCells);
  childIds->SetNumberOfIds(numberOfCells);
  for (vtkIdType childId = 0; childId < numberOfCells; ++childId)
  {
    parentIds->SetId(childId, static_cast<vtkIdType>(parentCell[childId]));
    childIds->SetId(childId, childId);
  }
  outputCellData->CopyData(inputCellData, parentIds, childIds);
}

// Output point data is the provenance-weighted sum of input point data (exact for linear fields).
void interpolatePointData(vtkPointData* inputPointData, const cgmesh::PointProvenance& provenance,
  vtkPointData* outputPointData)
{
  const vtkIdType numberOfPoints = static_cast<vtkIdType>(provenance.offsets.size()) - 1;
  outputPointData->InterpolateAllocate(inputPointData, numberOfPoints);
  vtkNew<vtkIdList> sourceIds;
  std::vector<double> weights;
  for (vtkIdType pointId = 0; pointId < numberOfPoints; ++pointId)
  {
    const auto begin = provenance.offsets[pointId];
    const auto end = provenance.offsets[pointId + 1];
    sourceIds->SetNumberOfIds(static_cast<vtkIdType>(end - begin));
    weights.resize(static_cast<size_t>(end - begin));
    for (auto source = begin; source < end; ++source)
    {
      sourceIds->SetId(static_cast<vtkIdType>(source - begin), provenance.sources[source]);
      weights[source - begin] = provenance.weights[source];
    }
    outputPointData->InterpolatePoint(inputPointData, pointId, sourceIds, weights.data());
  }
}

// vtkDataSetAttributes never interpolates vtkIdTypeArrays; plain ones (not global or pedigree
// ids, which have no values between points) are interpolated here like other integer arrays:
// the provenance-weighted sum, rounded to the nearest integer.
void interpolateIdTypeArrays(vtkPointData* inputPointData,
  const cgmesh::PointProvenance& provenance, vtkPointData* outputPointData)
{
  const vtkIdType numberOfPoints = static_cast<vtkIdType>(provenance.offsets.size()) - 1;
  for (int index = 0; index < inputPointData->GetNumberOfArrays(); ++index)
  {
    auto* source = vtkIdTypeArray::SafeDownCast(inputPointData->GetAbstractArray(index));
    const int attribute = inputPointData->IsArrayAnAttribute(index);
    if (!source || !source->GetName() || outputPointData->GetAbstractArray(source->GetName()) ||
      attribute == vtkDataSetAttributes::GLOBALIDS ||
      attribute == vtkDataSetAttributes::PEDIGREEIDS)
    {
      continue;
    }
    const int components = source->GetNumberOfComponents();
    vtkNew<vtkIdTypeArray> interpolated;
    interpolated->SetName(source->GetName());
    interpolated->SetNumberOfComponents(components);
    interpolated->SetNumberOfTuples(numberOfPoints);
    for (vtkIdType pointId = 0; pointId < numberOfPoints; ++pointId)
    {
      for (int component = 0; component < components; ++component)
      {
        double value = 0;
        for (auto entry = provenance.offsets[pointId]; entry < provenance.offsets[pointId + 1];
             ++entry)
        {
          value += provenance.weights[entry] *
            static_cast<double>(source->GetTypedComponent(provenance.sources[entry], component));
        }
        interpolated->SetTypedComponent(pointId, component, std::llround(value));
      }
    }
    outputPointData->AddArray(interpolated);
  }
}

void addFieldData(const cgmesh::AdaptationResult& result, vtkCoarseGrainedMeshAdaptation* filter,
  double qualitySeconds, double totalSeconds, vtkFieldData* fieldData)
{
  addFieldValue(fieldData, "NumberOfColors", result.numberOfColors);
  addFieldValue(fieldData, "NumberOfPartitions", result.numberOfPartitions);
  addFieldValue(fieldData, "NumberOfThreads", result.numberOfThreads);
  addFieldValue(fieldData, "EdgeLengthThreshold", result.edgeLengthThreshold);
  addFieldString(fieldData, "Method", filter->GetMethodName());
  addFieldValue(fieldData, "VolumeBound", result.volumeBound);
  addFieldValue(fieldData, "DelaunayFallbacks", static_cast<double>(result.delaunayFallbacks));
  addFieldValue(fieldData, "TetGenPoints", static_cast<double>(result.tetgenPoints));
  vtkNew<vtkIntArray> fallbackPartitions; // one tuple per fallback, in refinement order
  fallbackPartitions->SetName("FallbackPartitions");
  for (const int partition : result.fallbackPartitions)
  {
    fallbackPartitions->InsertNextValue(partition);
  }
  fieldData->AddArray(fallbackPartitions);
  addFieldString(fieldData, "ColoringAlgorithm", filter->GetColoringAlgorithmName());
  addColorPopulation(fieldData, "PartitionsPerColor", result.partitionsPerColor);
  addColorPopulation(fieldData, "CellsPerColor", result.cellsPerColor);
  addFieldValue(fieldData, "ColorBalance", result.colorBalance);
  addFieldValue(fieldData, "EdgeRemovals", static_cast<double>(result.edgeRemovals));
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
  const cgmesh::PhaseSeconds& seconds = result.seconds;
  addFieldValue(fieldData, "PartitionSeconds", seconds.partition);
  addFieldValue(fieldData, "GraphSeconds", seconds.graph);
  addFieldValue(fieldData, "ColorSeconds", seconds.color);
  addFieldValue(fieldData, "HealSeconds", seconds.heal);
  addFieldValue(fieldData, "AdaptSeconds", seconds.adapt);
  addFieldValue(fieldData, "PostSeconds", seconds.post);
  addFieldValue(fieldData, "ImproveSeconds", seconds.improve);
  addFieldValue(fieldData, "MergeSeconds", seconds.merge);
  addFieldValue(fieldData, "QualitySeconds", qualitySeconds);
  addFieldValue(fieldData, "TotalSeconds", totalSeconds);
}

cgmesh::AdaptationOptions makeOptions(vtkCoarseGrainedMeshAdaptation* filter)
{
  cgmesh::AdaptationOptions options;
  options.numberOfPartitions = filter->GetNumberOfPartitions();
  options.numberOfIterations = filter->GetNumberOfIterations();
  options.method = filter->GetMethod() == vtkCoarseGrainedMeshAdaptation::DELAUNAY
    ? cgmesh::RefinementMethod::Delaunay
    : cgmesh::RefinementMethod::Template;
  options.maximumEdgeLength = filter->GetMaximumEdgeLength();
  options.edgeLengthFactor = filter->GetEdgeLengthFactor();
  options.maximumVolume = filter->GetMaximumVolume();
  options.volumeFactor = filter->GetVolumeFactor();
  options.radiusEdgeRatio = filter->GetRadiusEdgeRatio();
  options.numberOfThreads = filter->GetNumberOfThreads();
  options.coloring = filter->GetColoringAlgorithmName();
  options.partitionByRegion = filter->GetPartitionByRegion();
  options.partitionsPerRegion = filter->GetPartitionsPerRegion();
  options.improveQuality = filter->GetImproveQuality();
  options.improvementPasses = filter->GetNumberOfImprovementPasses();
  options.maximumNumberOfCells = static_cast<std::int64_t>(filter->GetMaximumNumberOfCells());
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
void reportWarnings(vtkCoarseGrainedMeshAdaptation* filter, const cgmesh::AdaptationResult& result)
{
  std::size_t fallbackWarnings = 0;
  for (const std::string& warning : result.warnings)
  {
    // The driver words every fallback warning "partition P: Delaunay refinement failed (...".
    const bool isFallback = warning.find(": Delaunay refinement failed") != std::string::npos;
    if (isFallback && ++fallbackWarnings > MaximumFallbackWarnings)
    {
      continue;
    }
    vtkWarningWithObjectMacro(filter, << warning);
  }
  if (fallbackWarnings > MaximumFallbackWarnings)
  {
    vtkWarningWithObjectMacro(filter, << "Delaunay refinement fell back to templates in "
                                      << fallbackWarnings << " partition refinements; "
                                      << fallbackWarnings - MaximumFallbackWarnings
                                      << " of these warnings are not shown.");
  }
}

void fillOutput(
  vtkUnstructuredGrid* input, const cgmesh::AdaptationResult& result, vtkUnstructuredGrid* output)
{
  cgmesh::convertToUnstructuredGrid(result.mesh, output);
  copyCellDataToChildren(input->GetCellData(), result.parentCell, output->GetCellData());
  interpolatePointData(input->GetPointData(), result.provenance, output->GetPointData());
  interpolateIdTypeArrays(input->GetPointData(), result.provenance, output->GetPointData());
  output->GetCellData()->AddArray(makeCellIntArray("PartitionId", result.partitionOfCell));
  output->GetCellData()->AddArray(makeCellIntArray("ColorId", result.colorOfCell));
  vtkNew<vtkUnsignedCharArray> nearFormerInterface;
  nearFormerInterface->SetName("NearFormerInterface");
  nearFormerInterface->SetNumberOfValues(static_cast<vtkIdType>(result.nearFormerInterface.size()));
  for (size_t cellId = 0; cellId < result.nearFormerInterface.size(); ++cellId)
  {
    nearFormerInterface->SetValue(
      static_cast<vtkIdType>(cellId), result.nearFormerInterface[cellId] ? 1 : 0);
  }
  output->GetCellData()->AddArray(nearFormerInterface);
}

} // namespace

//------------------------------------------------------------------------------
vtkCoarseGrainedMeshAdaptation::vtkCoarseGrainedMeshAdaptation()
  : NumberOfPartitions(1024)
  , NumberOfIterations(1)
  , Method(TEMPLATE)
  , MaximumEdgeLength(0.0)
  , EdgeLengthFactor(0.5)
  , MaximumVolume(0.0)
  , VolumeFactor(0.1)
  , RadiusEdgeRatio(2.0)
  , NumberOfThreads(0)
  , RegionArrayName(nullptr)
  , ColoringAlgorithm(GREEDY_LEAST_USED)
  , PartitionByRegion(false)
  , PartitionsPerRegion(1)
  , ImproveQuality(true)
  , NumberOfImprovementPasses(2)
  , MaximumNumberOfCells(100000000)
{
}

//------------------------------------------------------------------------------
vtkCoarseGrainedMeshAdaptation::~vtkCoarseGrainedMeshAdaptation()
{
  this->SetRegionArrayName(nullptr);
}

//------------------------------------------------------------------------------
const char* vtkCoarseGrainedMeshAdaptation::ColoringAlgorithmToName(int algorithm)
{
  return (algorithm >= GREEDY && algorithm <= RECOLORING) ? ColoringAlgorithmNames[algorithm]
                                                          : nullptr;
}

//------------------------------------------------------------------------------
int vtkCoarseGrainedMeshAdaptation::ColoringAlgorithmFromName(const char* name)
{
  for (int algorithm = GREEDY; name && algorithm <= RECOLORING; ++algorithm)
  {
    if (std::strcmp(name, ColoringAlgorithmNames[algorithm]) == 0)
    {
      return algorithm;
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
const char* vtkCoarseGrainedMeshAdaptation::MethodToName(int method)
{
  return (method >= TEMPLATE && method <= DELAUNAY) ? MethodNames[method] : nullptr;
}

//------------------------------------------------------------------------------
int vtkCoarseGrainedMeshAdaptation::MethodFromName(const char* name)
{
  for (int method = TEMPLATE; name && method <= DELAUNAY; ++method)
  {
    if (std::strcmp(name, MethodNames[method]) == 0)
    {
      return method;
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
std::string vtkCoarseGrainedMeshAdaptation::ResolveRegionArrayName(vtkUnstructuredGrid* input) const
{
  if (!this->RegionArrayName || this->RegionArrayName[0] == '\0')
  {
    return std::string();
  }
  // "None" is ParaView's "no array" entry, unless the input really has an array of that name.
  if (std::strcmp(this->RegionArrayName, "None") == 0 &&
    !input->GetCellData()->GetAbstractArray("None"))
  {
    return std::string();
  }
  return this->RegionArrayName;
}

//------------------------------------------------------------------------------
bool vtkCoarseGrainedMeshAdaptation::CheckInput(vtkUnstructuredGrid* input)
{
  const vtkIdType nonTetrahedra = cgmesh::countNonTetrahedra(input);
  if (nonTetrahedra > 0)
  {
    vtkErrorMacro(<< "The input must hold only linear tetrahedra, but " << nonTetrahedra
                  << " of its " << input->GetNumberOfCells()
                  << " cells are of other types. Apply ParaView's Tetrahedralize filter first.");
    return false;
  }
  if (this->PartitionByRegion && this->ResolveRegionArrayName(input).empty())
  {
    vtkErrorMacro(<< "PartitionByRegion needs a region array: set RegionArrayName to the cell "
                     "array of material/region ids to cut along.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkCoarseGrainedMeshAdaptation::RequestData(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  const auto start = Clock::now();
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

  cgmesh::TetMesh inputMesh;
  cgmesh::Status status =
    cgmesh::convertToTetMesh(input, this->ResolveRegionArrayName(input), inputMesh);
  if (!status.ok())
  {
    vtkErrorMacro(<< "Cannot read the input: " << status.message() << ".");
    return 0;
  }

  cgmesh::AdaptationResult result;
  status = cgmesh::adaptMesh(inputMesh, makeOptions(this), result);
  reportWarnings(this, result);
  if (!status.ok())
  {
    vtkErrorMacro(<< "Mesh adaptation failed: " << status.message());
    return 0;
  }
  if (result.aborted)
  {
    vtkWarningMacro(<< "Mesh adaptation was aborted; the output is empty.");
    return 1;
  }

  fillOutput(input, result, output);
  this->UpdateProgress(0.9);
  const double qualitySeconds = cgmesh::addTetQualityArrays(output, result.numberOfThreads);
  addFieldData(result, this, qualitySeconds, secondsSince(start), output->GetFieldData());
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkCoarseGrainedMeshAdaptation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfPartitions: " << this->NumberOfPartitions << "\n";
  os << indent << "NumberOfIterations: " << this->NumberOfIterations << "\n";
  os << indent << "Method: " << this->Method << " (" << this->GetMethodName() << ")\n";
  os << indent << "MaximumEdgeLength: " << this->MaximumEdgeLength << "\n";
  os << indent << "EdgeLengthFactor: " << this->EdgeLengthFactor << "\n";
  os << indent << "MaximumVolume: " << this->MaximumVolume << "\n";
  os << indent << "VolumeFactor: " << this->VolumeFactor << "\n";
  os << indent << "RadiusEdgeRatio: " << this->RadiusEdgeRatio << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "RegionArrayName: " << (this->RegionArrayName ? this->RegionArrayName : "(none)")
     << "\n";
  os << indent << "ColoringAlgorithm: " << this->ColoringAlgorithm << " ("
     << this->GetColoringAlgorithmName() << ")\n";
  os << indent << "PartitionByRegion: " << (this->PartitionByRegion ? "on" : "off") << "\n";
  os << indent << "PartitionsPerRegion: " << this->PartitionsPerRegion << "\n";
  os << indent << "ImproveQuality: " << (this->ImproveQuality ? "on" : "off") << "\n";
  os << indent << "NumberOfImprovementPasses: " << this->NumberOfImprovementPasses << "\n";
  os << indent << "MaximumNumberOfCells: " << this->MaximumNumberOfCells
     << (this->MaximumNumberOfCells == 0 ? " (no limit)" : "") << "\n";
}
