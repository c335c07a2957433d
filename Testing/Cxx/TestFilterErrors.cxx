// Error paths and properties of vtkCoarseGrainedMeshAdaptation: non-tetrahedral input, a missing
// region array, partitioning by region without one, empty input, ParaView's "None" region choice,
// defaults, clamping (improvement passes included), the colouring setters, PrintSelf, and the box
// widget's properties against the same box as text.
#include "FilterTestSupport.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCoarseGrainedMeshAdaptation.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>
#include <string>
#include <utility>

namespace
{

// Counts errors and warnings and keeps the last message (and keeps VTK from printing them).
class MessageCounter : public vtkCommand
{
public:
  static MessageCounter* New() { return new MessageCounter; }
  void Execute(vtkObject*, unsigned long eventId, void* callData) override
  {
    (eventId == vtkCommand::ErrorEvent ? this->Errors : this->Warnings)++;
    this->AllMessages += callData ? static_cast<const char*>(callData) : "";
    this->AllMessages += "\n";
  }
  int Errors = 0;
  int Warnings = 0;
  std::string AllMessages;
};

struct FilterRun
{
  vtkNew<vtkCoarseGrainedMeshAdaptation> Filter;
  vtkNew<MessageCounter> Messages;
  int UpdateResult = 0;

  explicit FilterRun(vtkUnstructuredGrid* input)
  {
    this->Filter->SetInputData(input);
    this->Filter->SetNumberOfPartitions(4);
    for (vtkObject* object : { static_cast<vtkObject*>(this->Filter.Get()),
           static_cast<vtkObject*>(this->Filter->GetExecutive()) })
    {
      object->AddObserver(vtkCommand::ErrorEvent, this->Messages);
      object->AddObserver(vtkCommand::WarningEvent, this->Messages);
    }
  }
  void update() { this->UpdateResult = this->Filter->GetExecutive()->Update(); }
  vtkIdType outputCells() { return this->Filter->GetOutput()->GetNumberOfCells(); }
};

// One hexahedron next to one tetrahedron.
vtkSmartPointer<vtkUnstructuredGrid> makeMixedGrid()
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  const double coordinates[9][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 },
    { 0, 0, 1 }, { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 }, { 2, 0, 0 } };
  for (const auto& point : coordinates)
    points->InsertNextPoint(point);
  grid->SetPoints(points);
  const vtkIdType hexahedron[8] = { 0, 1, 2, 3, 4, 5, 6, 7 };
  const vtkIdType tetrahedron[4] = { 1, 8, 2, 5 };
  grid->InsertNextCell(VTK_HEXAHEDRON, 8, hexahedron);
  grid->InsertNextCell(VTK_TETRA, 4, tetrahedron);
  return grid;
}

void test_nonTetrahedralInput()
{
  vtkSmartPointer<vtkUnstructuredGrid> input = makeMixedGrid();
  const vtkMTimeType inputTime = input->GetMTime();
  FilterRun run(input);
  run.update();
  CGMESH_CHECK(run.Messages->Errors > 0, "no error for a hexahedron in the input");
  CGMESH_CHECK(run.Messages->AllMessages.find("Tetrahedralize") != std::string::npos,
    "the error does not point to Tetrahedralize: " << run.Messages->AllMessages);
  CGMESH_CHECK(run.Messages->AllMessages.find("1 of its 2 cells") != std::string::npos &&
      run.Messages->AllMessages.find("1 Hexahedron") != std::string::npos,
    "the error does not count the non-tetrahedral cells: " << run.Messages->AllMessages);
  CGMESH_CHECK(run.UpdateResult == 0, "Update succeeded on non-tetrahedral input");
  CGMESH_CHECK(run.outputCells() == 0, "output not empty after an error");
  CGMESH_CHECK(
    input->GetMTime() == inputTime && input->GetNumberOfCells() == 2, "the input was modified");
}

// Cells other than tetrahedra and triangles (a line tagging an edge, as Gmsh meshes come): the
// error names the types and points to Extract Cells By Type, not to Tetrahedralize, which would
// not remove them.
void test_lineInput()
{
  vtkSmartPointer<vtkUnstructuredGrid> input = cgmesh_test::makeCubeWithTestArrays(1);
  const vtkIdType line[2] = { 0, 1 };
  input->InsertNextCell(VTK_LINE, 2, line);
  input->GetCellData()->Initialize();
  const vtkIdType cells = input->GetNumberOfCells();
  FilterRun run(input);
  run.update();
  const std::string& messages = run.Messages->AllMessages;
  CGMESH_CHECK(run.UpdateResult == 0 && run.outputCells() == 0, "a line was accepted");
  CGMESH_CHECK(messages.find("1 of its " + std::to_string(cells) + " cells") != std::string::npos &&
      messages.find("1 Line") != std::string::npos &&
      messages.find("Extract Cells By Type (Tetra, Triangle)") != std::string::npos &&
      messages.find("Tetrahedralize") == std::string::npos,
    "the error does not name the line and the filter that removes it: " << messages);
  CGMESH_CHECK(input->GetNumberOfCells() == cells, "the input was modified");
}

// Triangles must tag faces of the tets: one along the cube's diagonal (no face, and degenerate) is
// refused with the error naming its cell and points, and the input is left as it was.
void test_triangleInput()
{
  vtkSmartPointer<vtkUnstructuredGrid> input = cgmesh_test::makeCubeWithTestArrays(2);
  const vtkIdType tets = input->GetNumberOfCells();
  const vtkIdType corners[3] = { 0, 13, 26 }; // a corner, the centre, the opposite corner
  input->InsertNextCell(VTK_TRIANGLE, 3, corners);
  FilterRun refused(input);
  refused.update();
  const std::string& messages = refused.Messages->AllMessages;
  CGMESH_CHECK(refused.UpdateResult == 0 && refused.outputCells() == 0,
    "a triangle that is no face was accepted");
  CGMESH_CHECK(messages.find("1 of the input's 1 triangles are not faces") != std::string::npos &&
      messages.find("cell " + std::to_string(tets) + " (points 0, 13, 26)") != std::string::npos,
    "the error does not name the triangle: " << messages);
  CGMESH_CHECK(input->GetNumberOfCells() == tets + 1, "the input was modified");
}

void test_missingRegionArray()
{
  vtkSmartPointer<vtkUnstructuredGrid> input = cgmesh_test::makeCubeWithTestArrays(2);
  FilterRun run(input);
  run.Filter->SetRegionArrayName("NoSuchArray");
  run.update();
  CGMESH_CHECK(run.Messages->Errors > 0, "no error for a missing region array");
  CGMESH_CHECK(run.outputCells() == 0, "output not empty after a missing region array");
}

void test_partitionByRegionWithoutRegionArray()
{
  vtkSmartPointer<vtkUnstructuredGrid> input = cgmesh_test::makeCubeWithTestArrays(2);
  for (const char* name : { static_cast<const char*>(nullptr), "None" })
  {
    FilterRun run(input);
    run.Filter->SetRegionArrayName(name);
    run.Filter->PartitionByRegionOn();
    run.update();
    CGMESH_CHECK(run.Messages->Errors > 0, "no error for PartitionByRegion without regions");
    CGMESH_CHECK(run.Messages->AllMessages.find("RegionArrayName") != std::string::npos,
      "the error does not name RegionArrayName: " << run.Messages->AllMessages);
    CGMESH_CHECK(run.UpdateResult == 0 && run.outputCells() == 0,
      "PartitionByRegion without regions produced output");
  }
}

void test_regionArrayChoices()
{
  vtkSmartPointer<vtkUnstructuredGrid> input = cgmesh_test::makeCubeWithTestArrays(2);
  for (const char* name : { "None", "", "Material" })
  {
    FilterRun run(input);
    run.Filter->SetRegionArrayName(name);
    run.update();
    CGMESH_CHECK(run.Messages->Errors == 0 && run.outputCells() > 0,
      "region array '" << name << "' rejected: " << run.Messages->AllMessages);
  }
}

// The share of `grid`'s edges (each once) whose length lies within [h/sqrt2, sqrt2 h], h the mean
// of its ends' `sizes` (the measure of EdgesWithinSizeBounds, to its 1e-12 tolerance).
double shareOfEdgesWithin(vtkUnstructuredGrid* grid, vtkDataArray* sizes)
{
  std::set<std::pair<vtkIdType, vtkIdType>> edges;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    grid->GetCellPoints(c, count, ids);
    for (vtkIdType i = 0; i < count; ++i)
    {
      for (vtkIdType j = i + 1; j < count; ++j)
      {
        edges.emplace(std::min(ids[i], ids[j]), std::max(ids[i], ids[j]));
      }
    }
  }
  std::size_t inside = 0;
  for (const auto& [a, b] : edges)
  {
    double pa[3], pb[3];
    grid->GetPoint(a, pa);
    grid->GetPoint(b, pb);
    const double length = std::sqrt(vtkMath::Distance2BetweenPoints(pa, pb));
    const double ratio = length / (0.5 * (sizes->GetComponent(a, 0) + sizes->GetComponent(b, 0)));
    inside += ratio >= std::sqrt(0.5) * (1 - 1e-12) && ratio <= std::sqrt(2.0) * (1 + 1e-12);
  }
  return edges.empty() ? 0.0 : static_cast<double>(inside) / static_cast<double>(edges.size());
}

// A size array as a point or a cell array refines and reports EdgeLengthRatio, the graded field
// per point (TargetEdgeLength) and the share of edges within it; bad ones are refused with the
// array and the first bad value named.
void test_sizeArrays()
{
  vtkSmartPointer<vtkUnstructuredGrid> input = cgmesh_test::makeCubeWithTestArrays(3);
  vtkNew<vtkDoubleArray> pointSizes;
  pointSizes->SetName("PointSize");
  for (vtkIdType p = 0; p < input->GetNumberOfPoints(); ++p)
  {
    pointSizes->InsertNextValue(0.05 + 0.2 * input->GetPoint(p)[0]);
  }
  input->GetPointData()->AddArray(pointSizes);
  vtkNew<vtkDoubleArray> cellSizes;
  cellSizes->SetName("CellSize");
  for (vtkIdType c = 0; c < input->GetNumberOfCells(); ++c)
  {
    cellSizes->InsertNextValue(0.15);
  }
  input->GetCellData()->AddArray(cellSizes);
  for (const char* name : { "PointSize", "CellSize" })
  {
    FilterRun run(input);
    run.Filter->SetSizeArrayName(name);
    run.Filter->SetNumberOfIterations(8);
    run.update();
    vtkUnstructuredGrid* output = run.Filter->GetOutput();
    CGMESH_CHECK(run.Messages->Errors == 0 && run.outputCells() > input->GetNumberOfCells(),
      "size array " << name << " did not refine: " << run.Messages->AllMessages);
    vtkDataArray* ratios = output->GetCellData()->GetArray("EdgeLengthRatio");
    CGMESH_CHECK(ratios && ratios->GetNumberOfTuples() == output->GetNumberOfCells(),
      "no EdgeLengthRatio per cell with size array " << name);
    // Every edge is at most sqrt(2) h at its midpoint, so the longest edge over the corners'
    // mean h stays below about sqrt(2) (the mean and the midpoint's h differ by the gradient).
    CGMESH_CHECK(ratios && ratios->GetRange()[1] < 1.6,
      "EdgeLengthRatio up to " << (ratios ? ratios->GetRange()[1] : 0) << " with " << name);
    vtkDataArray* within = output->GetFieldData()->GetArray("EdgesWithinSizeBounds");
    CGMESH_CHECK(within && within->GetComponent(0, 0) > 0.5 && within->GetComponent(0, 0) <= 1,
      "EdgesWithinSizeBounds missing or implausible with " << name);
    // The graded field per output point: the share of edges within bounds, measured again from
    // the output's edges and TargetEdgeLength, is the one reported.
    vtkDataArray* target = output->GetPointData()->GetArray("TargetEdgeLength");
    CGMESH_CHECK(target && target->GetNumberOfTuples() == output->GetNumberOfPoints(),
      "no TargetEdgeLength per point with size array " << name);
    if (target && within)
    {
      const double measured = shareOfEdgesWithin(output, target);
      CGMESH_CHECK(std::abs(measured - within->GetComponent(0, 0)) < 1e-12,
        "edges within TargetEdgeLength's bounds "
          << measured << ", reported " << within->GetComponent(0, 0) << " with " << name);
    }
  }

  vtkNew<vtkDoubleArray> negative;
  negative->DeepCopy(pointSizes);
  negative->SetName("Negative");
  negative->SetValue(5, -1.0);
  input->GetPointData()->AddArray(negative);
  vtkNew<vtkDoubleArray> vectors;
  vectors->SetName("Vectors");
  vectors->SetNumberOfComponents(3);
  vectors->SetNumberOfTuples(input->GetNumberOfPoints());
  vectors->Fill(1.0);
  input->GetPointData()->AddArray(vectors);
  const std::pair<const char*, const char*> badArrays[] = { { "NoSuchSize", "LinearField" },
    { "Negative", "point 5 is -1" }, { "Vectors", "3 components" } };
  for (const auto& bad : badArrays)
  {
    FilterRun run(input);
    run.Filter->SetSizeArrayName(bad.first);
    run.update();
    CGMESH_CHECK(run.Messages->Errors > 0 && run.outputCells() == 0,
      "size array " << bad.first << " accepted");
    CGMESH_CHECK(run.Messages->AllMessages.find(bad.first) != std::string::npos &&
        run.Messages->AllMessages.find(bad.second) != std::string::npos,
      "the error for " << bad.first << " lacks '" << bad.second
                       << "': " << run.Messages->AllMessages);
  }
  // The Delaunay method takes the field too (TetGen's switch m), and its volume bound is unused.
  FilterRun delaunay(input);
  delaunay.Filter->SetSizeArrayName("PointSize");
  delaunay.Filter->SetMethodToDelaunay();
  delaunay.update();
  vtkDataArray* delaunayWithin =
    delaunay.Filter->GetOutput()->GetFieldData()->GetArray("EdgesWithinSizeBounds");
  vtkDataArray* delaunayBound =
    delaunay.Filter->GetOutput()->GetFieldData()->GetArray("VolumeBound");
  CGMESH_CHECK(delaunay.Messages->Errors == 0 &&
      delaunay.outputCells() > input->GetNumberOfCells() && delaunayWithin &&
      delaunayWithin->GetComponent(0, 0) > 0.5 && delaunayBound &&
      delaunayBound->GetComponent(0, 0) == 0,
    "Delaunay with a size field: " << delaunay.Messages->AllMessages);
}

// The box widget's properties refine exactly as the same box given as RefinementBox text does,
// and only inside it. Both ways at once, a negative length, a non-finite corner and the Delaunay
// method are errors that name what is wrong, give no output and leave the input as it was.
void test_refinementBoxWidget()
{
  vtkSmartPointer<vtkUnstructuredGrid> input = cgmesh_test::makeCubeWithTestArrays(6);
  const vtkIdType inputCells = input->GetNumberOfCells();
  const vtkMTimeType inputTime = input->GetMTime();
  FilterRun whole(input);
  whole.update();
  FilterRun text(input);
  text.Filter->SetRefinementBox("0.25,0,0,0.5,1,0.5");
  text.update();
  FilterRun widget(input);
  CGMESH_CHECK(!widget.Filter->GetRefinementBoxEnabled() &&
      widget.Filter->GetRefinementBoxOrigin()[0] == 0 &&
      widget.Filter->GetRefinementBoxLength()[2] == 1,
    "box widget defaults");
  widget.Filter->RefinementBoxEnabledOn();
  widget.Filter->SetRefinementBoxOrigin(0.25, 0, 0);
  widget.Filter->SetRefinementBoxLength(0.25, 1, 0.5);
  widget.update();
  std::string difference;
  CGMESH_CHECK(
    whole.Messages->Errors == 0 && text.Messages->Errors == 0 && widget.Messages->Errors == 0,
    "box runs failed: " << text.Messages->AllMessages << widget.Messages->AllMessages);
  CGMESH_CHECK(widget.outputCells() > inputCells && widget.outputCells() < whole.outputCells(),
    "the widget's box refined " << widget.outputCells() << " cells of " << inputCells
                                << " (everywhere: " << whole.outputCells() << ")");
  CGMESH_CHECK(
    cgmesh_test::identicalGrids(text.Filter->GetOutput(), widget.Filter->GetOutput(), difference),
    "the widget's box and the same box as text differ: " << difference);

  struct BadBox
  {
    const char* text;
    double origin[3], length[3];
    bool delaunay;
    const char* expected;
  };
  const double nan = std::nan("");
  const BadBox cases[] = { { "0,0,0,1,1,1", { 0, 0, 0 }, { 1, 1, 1 }, false, "both give" },
    { "", { 0, 0, 0 }, { 0.5, -0.1, 1 }, false,
      "RefinementBoxLength (0.5,-0.10000000000000001,1)" },
    { "", { nan, 0, 0 }, { 1, 1, 1 }, false, "RefinementBoxOrigin (nan,0,0)" },
    { "", { 0, 0, 0 }, { 1, 1, 1 }, true,
      "RefinementBoxEnabled: the refinement box works with "
      "the Template method only" } };
  for (const BadBox& bad : cases)
  {
    FilterRun run(input);
    run.Filter->SetRefinementBox(bad.text);
    run.Filter->RefinementBoxEnabledOn();
    run.Filter->SetRefinementBoxOrigin(bad.origin);
    run.Filter->SetRefinementBoxLength(bad.length);
    if (bad.delaunay)
    {
      run.Filter->SetMethodToDelaunay();
    }
    run.update();
    CGMESH_CHECK(run.Messages->Errors > 0 && run.outputCells() == 0 &&
        run.Messages->AllMessages.find(bad.expected) != std::string::npos,
      "bad box (" << bad.expected << "): " << run.Messages->AllMessages);
  }
  CGMESH_CHECK(input->GetNumberOfCells() == inputCells && input->GetMTime() == inputTime,
    "the box runs changed their input");
}

void test_emptyInput()
{
  vtkNew<vtkUnstructuredGrid> input;
  FilterRun run(input);
  run.update();
  CGMESH_CHECK(run.Messages->Errors == 0, "empty input is not an error");
  CGMESH_CHECK(run.Messages->Warnings > 0, "no warning for empty input");
  CGMESH_CHECK(run.outputCells() == 0, "output of empty input not empty");
}

// Sets AbortExecute from the first progress report after the start, as ParaView's abort does.
class AbortOnProgress : public vtkCommand
{
public:
  static AbortOnProgress* New() { return new AbortOnProgress; }
  void Execute(vtkObject* caller, unsigned long, void* callData) override
  {
    const double progress = *static_cast<double*>(callData);
    if (progress > 0.0 && progress < 0.85)
      vtkAlgorithm::SafeDownCast(caller)->SetAbortExecute(1);
  }
};

void test_abort()
{
  vtkSmartPointer<vtkUnstructuredGrid> input = cgmesh_test::makeCubeWithTestArrays(6);
  FilterRun run(input);
  run.Filter->SetNumberOfPartitions(64);
  vtkNew<AbortOnProgress> abort;
  run.Filter->AddObserver(vtkCommand::ProgressEvent, abort);
  run.update();
  CGMESH_CHECK(run.Messages->Errors == 0, "an abort is not an error");
  CGMESH_CHECK(run.Messages->AllMessages.find("aborted") != std::string::npos,
    "no message for an aborted run: " << run.Messages->AllMessages);
  CGMESH_CHECK(run.outputCells() == 0, "output of an aborted run not empty");
}

// Sets AbortExecute from the first progress report a second after the start: by then the run
// below waits on a TetGen worker that hangs (the pool's test hook), and only the progress the
// filter reports again while it waits gives ParaView, or this observer, a chance to abort.
class AbortOnProgressAfterASecond : public vtkCommand
{
public:
  static AbortOnProgressAfterASecond* New() { return new AbortOnProgressAfterASecond; }
  void Execute(vtkObject* caller, unsigned long, void*) override
  {
    if (std::chrono::steady_clock::now() - this->Start > std::chrono::seconds(1))
      vtkAlgorithm::SafeDownCast(caller)->SetAbortExecute(1);
  }
  const std::chrono::steady_clock::time_point Start = std::chrono::steady_clock::now();
};

void test_abortDuringTetGenCall()
{
  CGMESH_CHECK(setenv("CGMESH_TEST_STALL_TETGEN_WORKER", "0", 1) == 0, "setenv");
  vtkSmartPointer<vtkUnstructuredGrid> input = cgmesh_test::makeCubeWithTestArrays(6);
  FilterRun run(input);
  run.Filter->SetMethod(vtkCoarseGrainedMeshAdaptation::DELAUNAY);
  run.Filter->SetNumberOfPartitions(8);
  run.Filter->SetNumberOfThreads(1);
  vtkNew<AbortOnProgressAfterASecond> abort;
  run.Filter->AddObserver(vtkCommand::ProgressEvent, abort);
  run.update();
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - abort->Start).count();
  unsetenv("CGMESH_TEST_STALL_TETGEN_WORKER");
  // Without the progress reported again, the call would run to its time limit (at least 20 s)
  // and the partitions fall back to templates.
  CGMESH_CHECK(seconds < 8.0, "the abort took " << seconds << " s");
  CGMESH_CHECK(run.Messages->Errors == 0, "an abort is not an error");
  CGMESH_CHECK(run.Messages->AllMessages.find("aborted") != std::string::npos,
    "no message for an aborted run: " << run.Messages->AllMessages);
  CGMESH_CHECK(run.Messages->AllMessages.find("refined by templates") == std::string::npos,
    "an aborted call reported as a fallback: " << run.Messages->AllMessages);
  CGMESH_CHECK(run.outputCells() == 0, "output of an aborted run not empty");
}

void test_defaultsAndClamping()
{
  vtkNew<vtkCoarseGrainedMeshAdaptation> filter;
  CGMESH_CHECK(filter->GetNumberOfPartitions() == 0, "NumberOfPartitions default (automatic)");
  CGMESH_CHECK(filter->GetNumberOfIterations() == 1, "NumberOfIterations default");
  CGMESH_CHECK(filter->GetMaximumEdgeLength() == 0.0, "MaximumEdgeLength default");
  CGMESH_CHECK(filter->GetEdgeLengthFactor() == 0.5, "EdgeLengthFactor default");
  CGMESH_CHECK(filter->GetNumberOfThreads() == 0, "NumberOfThreads default");
  CGMESH_CHECK(filter->GetRegionArrayName() == nullptr, "RegionArrayName default");
  CGMESH_CHECK(filter->GetColoringAlgorithm() == vtkCoarseGrainedMeshAdaptation::GREEDY_LEAST_USED,
    "ColoringAlgorithm default");
  CGMESH_CHECK(!filter->GetPartitionByRegion(), "PartitionByRegion default");
  CGMESH_CHECK(filter->GetPartitionsPerRegion() == 1, "PartitionsPerRegion default");
  CGMESH_CHECK(filter->GetImproveQuality(), "ImproveQuality default");
  CGMESH_CHECK(filter->GetNumberOfImprovementPasses() == 2, "NumberOfImprovementPasses default");
  filter->SetNumberOfImprovementPasses(-1);
  CGMESH_CHECK(filter->GetNumberOfImprovementPasses() == 0, "improvement passes not clamped to 0");
  filter->SetNumberOfImprovementPasses(50);
  CGMESH_CHECK(
    filter->GetNumberOfImprovementPasses() == 20, "improvement passes not clamped to 20");
  filter->ImproveQualityOff();
  CGMESH_CHECK(!filter->GetImproveQuality(), "ImproveQualityOff");
  filter->SetNumberOfPartitions(-5);
  filter->SetNumberOfIterations(-3);
  filter->SetNumberOfThreads(-1);
  filter->SetPartitionsPerRegion(0);
  CGMESH_CHECK(filter->GetNumberOfPartitions() == 0, "NumberOfPartitions not clamped to 0");
  CGMESH_CHECK(filter->GetNumberOfIterations() == 1, "NumberOfIterations not clamped to 1");
  CGMESH_CHECK(filter->GetNumberOfThreads() == 0, "NumberOfThreads not clamped to 0");
  CGMESH_CHECK(filter->GetPartitionsPerRegion() == 1, "PartitionsPerRegion not clamped to 1");
  std::ostringstream printed;
  filter->Print(printed);
  for (const char* member :
    { "NumberOfPartitions", "NumberOfIterations", "MaximumEdgeLength", "EdgeLengthFactor",
      "NumberOfThreads", "RegionArrayName", "ColoringAlgorithm", "greedy-lu", "PartitionByRegion",
      "PartitionsPerRegion", "ImproveQuality", "NumberOfImprovementPasses" })
  {
    CGMESH_CHECK(printed.str().find(member) != std::string::npos, "PrintSelf omits " << member);
  }
}

void test_coloringSetters()
{
  vtkNew<vtkCoarseGrainedMeshAdaptation> filter;
  filter->SetColoringAlgorithmToGreedy();
  CGMESH_CHECK(std::string(filter->GetColoringAlgorithmName()) == "greedy", "ToGreedy");
  filter->SetColoringAlgorithmToIterative();
  CGMESH_CHECK(std::string(filter->GetColoringAlgorithmName()) == "iterative", "ToIterative");
  filter->SetColoringAlgorithmToRecoloring();
  CGMESH_CHECK(std::string(filter->GetColoringAlgorithmName()) == "recoloring", "ToRecoloring");
  filter->SetColoringAlgorithmToGreedyLeastUsed();
  CGMESH_CHECK(std::string(filter->GetColoringAlgorithmName()) == "greedy-lu", "ToGreedyLeastUsed");
  filter->SetColoringAlgorithm(99);
  CGMESH_CHECK(filter->GetColoringAlgorithm() == vtkCoarseGrainedMeshAdaptation::RECOLORING,
    "ColoringAlgorithm not clamped to the last colouring");
  filter->SetColoringAlgorithm(-5);
  CGMESH_CHECK(filter->GetColoringAlgorithm() == vtkCoarseGrainedMeshAdaptation::GREEDY,
    "ColoringAlgorithm not clamped to the first colouring");
}

} // namespace

int main()
{
  test_nonTetrahedralInput();
  test_lineInput();
  test_triangleInput();
  test_missingRegionArray();
  test_partitionByRegionWithoutRegionArray();
  test_regionArrayChoices();
  test_sizeArrays();
  test_refinementBoxWidget();
  test_emptyInput();
  test_abort();
  test_abortDuringTetGenCall();
  test_defaultsAndClamping();
  test_coloringSetters();
  if (cgmesh_test::FailureCount > 0)
  {
    std::cerr << cgmesh_test::FailureCount << " checks failed\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
