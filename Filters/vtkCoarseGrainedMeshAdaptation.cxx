#include "vtkCoarseGrainedMeshAdaptation.h"

#include "cgmeshAdaptedGrid.h"
#include "cgmeshDistributed.h"
#include "cgmeshMaterialLabels.h"
#include "cgmeshPointData.h"
#include "cgmeshRunFieldData.h"
#include "cgmeshTetQuality.h"
#include "cgmeshTriangleCells.h"
#include "cgmeshVTKConversion.h"

#include "AdaptationDriver.h"
#include "Core/Stopwatch.h"
#include "ParallelFor.h"

#include "vtkCellData.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
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

// Whether the input has cell arrays other than the one named `regionArray`.
bool hasCellArraysBesides(vtkUnstructuredGrid* input, const std::string& regionArray)
{
  vtkCellData* cellData = input->GetCellData();
  for (int a = 0; a < cellData->GetNumberOfArrays(); ++a)
  {
    const char* name = cellData->GetArrayName(a);
    if (regionArray.empty() || !name || regionArray != name)
    {
      return true;
    }
  }
  return false;
}

// The filter's parameters, with the progress and abort hooks of this run. Provenance is needed to
// interpolate point data and to find the children of triangles.
cgmesh::AdaptationOptions makeOptions(vtkCoarseGrainedMeshAdaptation* filter,
  const cgmesh::AdaptationOptions& parameters, vtkUnstructuredGrid* input,
  const cgmesh::TriangleCells* triangles)
{
  cgmesh::AdaptationOptions options = parameters;
  options.pointProvenance = input->GetPointData()->GetNumberOfArrays() > 0 || triangles;
  options.cellDataByParent = triangles || hasCellArraysBesides(input, options.regionArrayName);
  // A sliver-laden input may be meshed anew with its tagged triangles split and merged within
  // their surface classes; their children are then found by position (fillAdaptedGrid).
  if (triangles)
  {
    options.surfaceClasses = cgmesh::surfaceClassesOf(input, *triangles);
  }
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

// The box widget's box [origin, origin + length] as RefinementBox's text "x0,y0,z0,x1,y1,z1",
// written with 17 significant digits so that it reads back as the same doubles; or an error
// naming the properties when the box is not one, a RefinementBox text gives a box too, or the
// method is not Template.
std::string refinementBoxOfWidget(const double origin[3], const double length[3],
  const cgmesh::AdaptationOptions& options, std::string& box)
{
  const auto join = [](const double* values, int count)
  {
    std::string text;
    for (int i = 0; i < count; ++i)
    {
      char number[32];
      std::snprintf(number, sizeof(number), "%.17g", values[i]);
      text += (i > 0 ? "," : "") + std::string(number);
    }
    return text;
  };
  if (options.method != cgmesh::RefinementMethod::Template)
  {
    return "RefinementBoxEnabled: the refinement box works with the Template method only; switch "
           "it off for the Delaunay method";
  }
  if (!options.refinementBox.empty())
  {
    return "RefinementBoxEnabled and RefinementBox '" + options.refinementBox +
      "' both give a refinement box; switch RefinementBoxEnabled off or empty RefinementBox";
  }
  double corners[6];
  bool valid = true;
  for (int axis = 0; axis < 3; ++axis)
  {
    corners[axis] = origin[axis];
    corners[3 + axis] = origin[axis] + length[axis];
    valid = valid && length[axis] >= 0 && std::isfinite(corners[axis]) &&
      std::isfinite(corners[3 + axis]);
  }
  if (!valid)
  {
    return "The refinement box of RefinementBoxOrigin (" + join(origin, 3) +
      ") and RefinementBoxLength (" + join(length, 3) +
      ") is not a box: every value must be finite and no length negative";
  }
  box = join(corners, 6);
  return std::string();
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
  double LastInputSeconds = 0;
  double LastOutputSeconds = 0;
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
double vtkCoarseGrainedMeshAdaptation::GetLastInputSeconds() const
{
  return this->Internals->LastInputSeconds;
}

//------------------------------------------------------------------------------
double vtkCoarseGrainedMeshAdaptation::GetLastOutputSeconds() const
{
  return this->Internals->LastOutputSeconds;
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
struct vtkCoarseGrainedMeshAdaptation::PieceRun
{
  vtkSmartPointer<vtkUnstructuredGrid> input; // this process's cells, triangles included
  vtkSmartPointer<vtkUnstructuredGrid> tets;  // the input without its triangles
  cgmesh::TriangleCells triangles;
  bool withTriangles = false;
  cgmesh::TetMesh mesh;
  cgmesh::AdaptationResult result;
};

//------------------------------------------------------------------------------
bool vtkCoarseGrainedMeshAdaptation::SeparateTriangles(PieceRun& run)
{
  if (!this->CheckInput(run.input))
  {
    return false;
  }
  // Triangles tag faces of the tets: the tets are adapted, the triangles follow their faces.
  run.tets = run.input;
  run.withTriangles = cgmesh::hasTriangles(run.input);
  if (run.withTriangles)
  {
    run.tets = vtkSmartPointer<vtkUnstructuredGrid>::New();
    cgmesh::separateTriangles(run.input, run.tets, run.triangles);
    if (run.tets->GetNumberOfCells() == 0)
    {
      vtkErrorMacro(<< "The input holds triangles but no tetrahedra: there is no volume mesh to "
                       "refine.");
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkCoarseGrainedMeshAdaptation::ConvertPiece(
  PieceRun& run, const std::vector<std::string>& materialLabels, bool distributed)
{
  const std::string regionArrayName = this->ResolveRegionArrayName(run.input);
  const cgmesh::ParallelFor parallelFor =
    cgmesh::parallelForOn(cgmesh::resolveThreadCount(this->Internals->Parameters.numberOfThreads));
  cgmesh::Status status = cgmesh::convertToTetMesh(
    run.tets, regionArrayName, run.mesh, this->ResolveSizeArrayName(run.input), parallelFor);
  if (!status.ok())
  {
    vtkErrorMacro(<< "Cannot read the input: " << status.message() << ".");
    return false;
  }
  // Without a region array, the input's integer cell arrays guard the material interfaces.
  if (regionArrayName.empty() && !materialLabels.empty())
  {
    status = cgmesh::combineMaterialLabels(run.tets, materialLabels, parallelFor, run.mesh);
    if (!status.ok())
    {
      vtkErrorMacro(<< "Cannot read the input's material labels: " << status.message() << ".");
      return false;
    }
  }
  if (run.withTriangles && !(status = cgmesh::checkTriangleCells(run.mesh, run.triangles)).ok())
  {
    vtkErrorMacro(<< "Cannot refine the input's triangles: " << status.message() << "."
                  << (distributed ? " Across processes a triangle must be in the piece that "
                                    "holds its tetrahedron; RedistributeDataSet places each cell "
                                    "by itself and can separate them."
                                  : ""));
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkCoarseGrainedMeshAdaptation::AdaptPiece(PieceRun& run,
  const cgmesh::AdaptationOptions& options, vtkUnstructuredGrid* output, bool distributed)
{
  const cgmesh::Status status = cgmesh::adaptMesh(run.mesh, options, run.result);
  this->Internals->LastSummary = run.result.summary;
  this->Internals->LastOutputSeconds = 0;
  this->Internals->LastQualitySeconds = 0;
  this->Internals->HasRun = true;
  reportWarnings(this, run.result.summary);
  if (!status.ok())
  {
    vtkErrorMacro(<< "Mesh adaptation failed: " << status.message());
    return false;
  }
  if (run.result.summary.aborted)
  {
    return true;
  }

  cgmesh::AdaptedGridInput adapted;
  adapted.grid = run.input;
  adapted.mesh = &run.mesh;
  adapted.triangles = run.withTriangles ? &run.triangles : nullptr;
  adapted.interpolatedPointArrays = this->Internals->Parameters.interpolatedPointArrays;
  adapted.labelPointArrays = this->Internals->Parameters.labelPointArrays;
  const cgmesh::Stopwatch outputStopwatch;
  cgmesh::fillAdaptedGrid(adapted, run.result, output,
    distributed ? cgmesh::ResultArrays::Copy : cgmesh::ResultArrays::HandOver);
  this->Internals->LastOutputSeconds = outputStopwatch.seconds();
  this->UpdateProgress(0.9);
  const cgmesh::Stopwatch qualityStopwatch;
  const cgmesh::Status quality =
    cgmesh::addTetQualityArrays(output, run.result.summary.plan.threads);
  if (!quality.ok())
  {
    output->Initialize();
    vtkErrorMacro(<< "Quality arrays failed: " << quality.message());
    return false;
  }
  this->Internals->LastQualitySeconds = qualityStopwatch.seconds();
  return true;
}

//------------------------------------------------------------------------------
void vtkCoarseGrainedMeshAdaptation::NumberAcrossProcesses(const cgmesh::ProcessGroup& group,
  const PieceRun& run, int ghostLevels, vtkUnstructuredGrid* output)
{
  const cgmesh::Stopwatch stopwatch;
  // Input points keep the ids their input carried; the others are numbered across processes.
  std::vector<long long> keptIds;
  vtkDataArray* inputIds = run.input->GetPointData()->GetGlobalIds();
  const auto& inputPoints = run.result.provenance.inputPoints;
  if (inputIds && inputIds->GetNumberOfComponents() == 1 &&
    static_cast<cgmesh::PointId>(inputPoints.size()) == run.result.mesh.numberOfPoints())
  {
    keptIds.resize(inputPoints.size());
    for (std::size_t p = 0; p < inputPoints.size(); ++p)
    {
      keptIds[p] = inputPoints[p] >= 0
        ? static_cast<long long>(inputIds->GetComponent(inputPoints[p], 0))
        : -1;
    }
  }
  const cgmesh::GlobalNumbering numbering =
    cgmesh::numberAcrossProcesses(group, run.result.mesh, keptIds, output->GetNumberOfCells());

  vtkSmartPointer<vtkDataArray> pointIds = output->GetPointData()->GetGlobalIds();
  if (!pointIds)
  {
    pointIds = vtkSmartPointer<vtkIdTypeArray>::New();
    pointIds->SetName("GlobalPointIds");
  }
  pointIds->SetNumberOfComponents(1);
  pointIds->SetNumberOfTuples(output->GetNumberOfPoints());
  for (vtkIdType p = 0; p < output->GetNumberOfPoints(); ++p)
  {
    pointIds->SetComponent(p, 0, static_cast<double>(numbering.pointIds[p]));
  }
  output->GetPointData()->SetGlobalIds(pointIds);
  vtkNew<vtkIdTypeArray> cellIds;
  cellIds->SetName("GlobalCellIds");
  cellIds->SetNumberOfTuples(output->GetNumberOfCells());
  for (vtkIdType c = 0; c < output->GetNumberOfCells(); ++c)
  {
    cellIds->SetValue(c, numbering.firstCellId + c);
  }
  output->GetCellData()->SetGlobalIds(cellIds);

  const double numberingSeconds = stopwatch.seconds();

  const cgmesh::Stopwatch ghostStopwatch;
  if (ghostLevels > 0)
  {
    vtkSmartPointer<vtkUnstructuredGrid> withGhosts =
      cgmesh::addGhostCells(group, output, ghostLevels);
    if (withGhosts != output)
    {
      output->ShallowCopy(withGhosts);
    }
  }
  vtkFieldData* fieldData = output->GetFieldData();
  cgmesh::addFieldValue(fieldData, "NumberOfProcesses", group.size());
  cgmesh::addFieldValue(
    fieldData, "ProcessSharedPoints", static_cast<double>(numbering.sharedPoints));
  cgmesh::addFieldValue(
    fieldData, "ProcessExchangeBytes", static_cast<double>(numbering.exchangedBytes));
  cgmesh::addFieldValue(fieldData, "ProcessNumberingSeconds", numberingSeconds);
  cgmesh::addFieldValue(fieldData, "GhostCellSeconds", ghostStopwatch.seconds());
}

//------------------------------------------------------------------------------
int vtkCoarseGrainedMeshAdaptation::RequestData(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  const cgmesh::Stopwatch stopwatch;
  this->Internals->HasRun = false;
  this->Internals->MaterialLabelArrays.clear();
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  output->Initialize();
  PieceRun run;
  run.input = vtkUnstructuredGrid::GetData(inputVector[0], 0);
  if (!run.input)
  {
    run.input = vtkSmartPointer<vtkUnstructuredGrid>::New();
  }

  // Under ParaView's MPI every process holds a piece of the mesh. Each refines its own; the steps
  // that involve the others are collective, and every process reaches each of them, so that one
  // process's error stops them all there.
  const std::unique_ptr<cgmesh::ProcessGroup> group = cgmesh::ProcessGroup::ofGlobalController();
  if (group)
  {
    std::string note;
    run.input = cgmesh::prepareDistributedPiece(*group, run.input, note);
    if (!note.empty() && group->rank() == 0)
    {
      vtkWarningMacro(<< note);
    }
  }
  const bool hasPiece = run.input->GetNumberOfCells() > 0;
  if ((group ? group->sum(hasPiece ? 1LL : 0LL) : hasPiece ? 1 : 0) == 0)
  {
    vtkWarningMacro(<< "The input has no cells; the output is empty.");
    return 1;
  }
  // Whether this step passed: in one process `ok`; across processes, whether it passed on all.
  const auto passed = [&](bool ok, const char* step)
  {
    if (!group)
    {
      return ok;
    }
    const int failed = group->firstFailure(ok);
    if (failed >= 0 && ok)
    {
      vtkErrorMacro(<< "Mesh adaptation stopped on all " << group->size() << " processes: process "
                    << failed << " failed while " << step << " (its error says why).");
    }
    return failed < 0;
  };

  if (!passed(!hasPiece || this->SeparateTriangles(run), "checking its piece of the input"))
  {
    return 0;
  }
  std::vector<std::string> labels;
  if (this->ResolveRegionArrayName(run.input).empty())
  {
    if (hasPiece)
    {
      labels = cgmesh::findMaterialLabelArrays(run.tets);
    }
    if (group)
    {
      labels = cgmesh::unionAcrossProcesses(*group, labels);
    }
    for (const std::string& name : labels)
    {
      this->Internals->MaterialLabelArrays +=
        (this->Internals->MaterialLabelArrays.empty() ? "" : ",") + name;
    }
  }
  if (!passed(!hasPiece || this->ConvertPiece(run, labels, group != nullptr),
        "reading its piece of the input"))
  {
    return 0;
  }
  this->Internals->LastInputSeconds = stopwatch.seconds();

  cgmesh::AdaptationOptions options = makeOptions(
    this, this->Internals->Parameters, run.input, run.withTriangles ? &run.triangles : nullptr);
  if (this->RefinementBoxEnabled)
  {
    // The same on every process: no exchange needed.
    std::string box;
    const std::string error =
      refinementBoxOfWidget(this->RefinementBoxOrigin, this->RefinementBoxLength, options, box);
    if (!error.empty())
    {
      vtkErrorMacro(<< error << ".");
      return 0;
    }
    options.refinementBox = box;
  }
  if (group)
  {
    const std::string unsupported =
      cgmesh::unsupportedAcrossProcesses(options, !this->ResolveSizeArrayName(run.input).empty());
    if (!unsupported.empty())
    {
      vtkErrorMacro(<< unsupported << "."); // the same on every process: no exchange needed
      return 0;
    }
    cgmesh::resolveDistributedOptions(*group, run.mesh, options);
  }
  if (!passed(!hasPiece || this->AdaptPiece(run, options, output, group != nullptr),
        "refining its piece"))
  {
    output->Initialize();
    return 0;
  }
  const bool aborted = hasPiece && run.result.summary.aborted;
  if (group ? group->sum(aborted ? 1LL : 0LL) > 0 : aborted)
  {
    output->Initialize();
    vtkWarningMacro(<< "Mesh adaptation was aborted; the output is empty.");
    return 1;
  }

  if (group)
  {
    const int ghostLevels = outputVector->GetInformationObject(0)->Get(
      vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS());
    this->NumberAcrossProcesses(*group, run, ghostLevels, output);
  }
  if (hasPiece)
  {
    this->Internals->LastTotalSeconds = stopwatch.seconds();
    cgmesh::addRunFieldData(run.result.summary, this, output->GetFieldData());
  }
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
  os << indent << "RefinementBoxEnabled: " << this->RefinementBoxEnabled << "\n";
  os << indent << "RefinementBoxOrigin: " << this->RefinementBoxOrigin[0] << ", "
     << this->RefinementBoxOrigin[1] << ", " << this->RefinementBoxOrigin[2] << "\n";
  os << indent << "RefinementBoxLength: " << this->RefinementBoxLength[0] << ", "
     << this->RefinementBoxLength[1] << ", " << this->RefinementBoxLength[2] << "\n";
}
