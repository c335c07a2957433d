// Awkward and bad inputs through vtkCoarseGrainedMeshAdaptation. Every case gives either a valid
// conforming refinement, or a failed RequestData with a vtkErrorMacro message and an empty output;
// in both the input object keeps its points, cells, arrays and MTime.
#include "FilterTestSupport.h"

#include "CubeGenerator.h"
#include "cgmeshVTKConversion.h"

#include "vtkAbstractArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCoarseGrainedMeshAdaptation.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVariant.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <initializer_list>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace
{

using Vector = std::array<double, 3>;

// Counts errors and warnings and keeps their text (and keeps VTK from printing them).
class MessageObserver : public vtkCommand
{
public:
  static MessageObserver* New() { return new MessageObserver; }
  void Execute(vtkObject*, unsigned long eventId, void* callData) override
  {
    (eventId == vtkCommand::ErrorEvent ? this->Errors : this->Warnings)++;
    this->Text += callData ? static_cast<const char*>(callData) : "";
    this->Text += "\n";
  }
  int Errors = 0;
  int Warnings = 0;
  std::string Text;
};

// A deep copy and the MTime of the input, taken before the filter runs.
struct InputSnapshot
{
  vtkNew<vtkUnstructuredGrid> Copy;
  vtkMTimeType Time = 0;

  explicit InputSnapshot(vtkUnstructuredGrid* input)
  {
    this->Copy->DeepCopy(input);
    this->Time = input->GetMTime();
  }
};

void checkInputUnchanged(
  vtkUnstructuredGrid* input, const InputSnapshot& snapshot, const std::string& caseName)
{
  CGMESH_CHECK(input->GetMTime() == snapshot.Time, caseName << ": the input's MTime changed");
  CGMESH_CHECK(input->GetNumberOfPoints() == snapshot.Copy->GetNumberOfPoints() &&
      input->GetNumberOfCells() == snapshot.Copy->GetNumberOfCells(),
    caseName << ": the input's point or cell count changed");
  CGMESH_CHECK(input->GetFieldData()->GetNumberOfArrays() ==
      snapshot.Copy->GetFieldData()->GetNumberOfArrays(),
    caseName << ": the input's field data changed");
  if (input->GetNumberOfPoints() == 0 || input->GetNumberOfCells() == 0)
  {
    return; // identicalGrids needs points and cells
  }
  std::string difference;
  CGMESH_CHECK(cgmesh_test::identicalGrids(input, snapshot.Copy, difference),
    caseName << ": the input was modified: " << difference);
}

// One filter run on `input` (4 partitions, 1 iteration, factor 0.5, 2 threads unless changed),
// with its messages observed and a snapshot of the input.
struct FilterRun
{
  vtkUnstructuredGrid* Input;
  std::string CaseName;
  InputSnapshot Snapshot;
  vtkNew<vtkCoarseGrainedMeshAdaptation> Filter;
  vtkNew<MessageObserver> Messages;
  int UpdateResult = -1;

  FilterRun(vtkUnstructuredGrid* input, std::string caseName)
    : Input(input)
    , CaseName(std::move(caseName))
    , Snapshot(input)
  {
    this->Filter->SetInputData(input);
    this->Filter->SetNumberOfPartitions(4);
    this->Filter->SetNumberOfIterations(1);
    this->Filter->SetEdgeLengthFactor(0.5);
    this->Filter->SetNumberOfThreads(2);
    for (vtkObject* object : { static_cast<vtkObject*>(this->Filter.Get()),
           static_cast<vtkObject*>(this->Filter->GetExecutive()) })
    {
      object->AddObserver(vtkCommand::ErrorEvent, this->Messages);
      object->AddObserver(vtkCommand::WarningEvent, this->Messages);
    }
  }

  vtkUnstructuredGrid* output() { return this->Filter->GetOutput(); }
  bool said(const std::string& text) const
  {
    return this->Messages->Text.find(text) != std::string::npos;
  }

  void update()
  {
    this->UpdateResult = this->Filter->GetExecutive()->Update();
    checkInputUnchanged(this->Input, this->Snapshot, this->CaseName);
  }
};

// RequestData fails with an error whose text holds every phrase, and the output is empty.
void expectError(FilterRun& run, std::initializer_list<const char*> phrases)
{
  run.update();
  const std::string& name = run.CaseName;
  CGMESH_CHECK(run.UpdateResult == 0, name << ": Update succeeded");
  CGMESH_CHECK(run.Messages->Errors > 0, name << ": no error reported");
  for (const char* phrase : phrases)
  {
    CGMESH_CHECK(run.said(phrase),
      name << ": the error does not say '" << phrase << "': " << run.Messages->Text);
  }
  CGMESH_CHECK(run.output()->GetNumberOfCells() == 0 && run.output()->GetNumberOfPoints() == 0,
    name << ": the output is not empty after an error");
}

// The output is a valid, conforming, positively oriented mesh of `expectedVolume` (1e-9 relative)
// without duplicate or unused points.
void checkValidMesh(vtkUnstructuredGrid* output, double expectedVolume, const std::string& name)
{
  const cgmesh::MeshReport report = cgmesh_test::inspectGrid(output, std::string());
  CGMESH_CHECK(report.isValid(), name << ": " << report.describeProblems());
  CGMESH_CHECK(report.invertedTets == 0 && report.misorientedFacePairs == 0,
    name << ": " << report.invertedTets << " inverted tets, " << report.misorientedFacePairs
         << " misoriented face pairs");
  CGMESH_CHECK(report.degenerateTets == 0, name << ": " << report.degenerateTets << " degenerate");
  CGMESH_CHECK(report.duplicatePoints == 0 && report.unusedPoints == 0,
    name << ": " << report.duplicatePoints << " duplicate, " << report.unusedPoints << " unused");
  CGMESH_CHECK(std::abs(report.volume - expectedVolume) <= 1e-9 * std::abs(expectedVolume),
    name << ": volume " << report.volume << ", expected " << expectedVolume);
}

// The run succeeds without errors and refines the input into a valid mesh of `expectedVolume`.
void expectRefinement(FilterRun& run, double expectedVolume)
{
  run.update();
  const std::string& name = run.CaseName;
  CGMESH_CHECK(run.UpdateResult == 1 && run.Messages->Errors == 0,
    name << ": the run failed: " << run.Messages->Text);
  vtkUnstructuredGrid* output = run.output();
  CGMESH_CHECK(output->GetNumberOfCells() > run.Input->GetNumberOfCells(),
    name << ": " << run.Input->GetNumberOfCells() << " -> " << output->GetNumberOfCells()
         << " cells, not refined");
  if (output->GetNumberOfCells() > 0)
  {
    checkValidMesh(output, expectedVolume, name);
  }
}

//------------------------------------------------------------------------------
// Input meshes

std::string typeName(int type)
{
  vtkSmartPointer<vtkDataArray> array;
  array.TakeReference(vtkDataArray::CreateDataArray(type));
  return array->GetDataTypeAsString();
}

Vector pointOf(vtkUnstructuredGrid* grid, vtkIdType pointId)
{
  Vector point;
  grid->GetPoint(pointId, point.data());
  return point;
}

Vector cellCentroid(vtkUnstructuredGrid* grid, vtkIdType cellId)
{
  const vtkIdType* pointIds;
  vtkIdType count;
  grid->GetCellPoints(cellId, count, pointIds);
  Vector centroid{ 0, 0, 0 };
  for (vtkIdType corner = 0; corner < count; ++corner)
  {
    const Vector point = pointOf(grid, pointIds[corner]);
    for (int axis = 0; axis < 3; ++axis)
      centroid[axis] += point[axis] / static_cast<double>(count);
  }
  return centroid;
}

double linearValue(const Vector& point)
{
  return point[0] + 2 * point[1] + 3 * point[2];
}

// The point array LinearField = x + 2y + 3z that cgmesh_test::checkLinearField checks.
void addLinearField(vtkUnstructuredGrid* grid)
{
  vtkNew<vtkDoubleArray> field;
  field->SetName("LinearField");
  field->SetNumberOfValues(grid->GetNumberOfPoints());
  for (vtkIdType pointId = 0; pointId < grid->GetNumberOfPoints(); ++pointId)
    field->SetValue(pointId, linearValue(pointOf(grid, pointId)));
  grid->GetPointData()->AddArray(field);
}

cgmesh::TetMesh kuhnCube(int cellsPerSide, double scale = 1.0)
{
  cgmesh::TetMesh mesh;
  const cgmesh::Status status = cgmesh::generateKuhnCube(cellsPerSide, mesh);
  CGMESH_CHECK(status.ok(), status.message());
  for (double& coordinate : mesh.coordinates)
    coordinate *= scale;
  return mesh;
}

vtkSmartPointer<vtkUnstructuredGrid> toGrid(const cgmesh::TetMesh& mesh)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  cgmesh::convertToUnstructuredGrid(mesh, grid);
  addLinearField(grid);
  return grid;
}

vtkSmartPointer<vtkUnstructuredGrid> makeGrid(
  const std::vector<Vector>& points, int cellType, const std::vector<std::vector<vtkIdType>>& cells)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> gridPoints;
  for (const Vector& point : points)
    gridPoints->InsertNextPoint(point.data());
  grid->SetPoints(gridPoints);
  for (const auto& cell : cells)
    grid->InsertNextCell(cellType, static_cast<vtkIdType>(cell.size()), cell.data());
  return grid;
}

const std::vector<Vector> UnitTetCorners = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };

// Every tet of a Kuhn cube with its own four points: 24 tets per cube cell, no node shared.
cgmesh::TetMesh explodedCube(int cellsPerSide)
{
  const cgmesh::TetMesh cube = kuhnCube(cellsPerSide);
  cgmesh::TetMesh mesh;
  for (const cgmesh::Tet& tet : cube.tets)
  {
    cgmesh::Tet ownTet;
    for (int corner = 0; corner < 4; ++corner)
    {
      ownTet[corner] = mesh.numberOfPoints();
      const double* point = cube.point(tet[corner]);
      mesh.coordinates.insert(mesh.coordinates.end(), point, point + 3);
    }
    mesh.tets.push_back(ownTet);
  }
  return mesh;
}

// Two unit cubes side by side in x whose touching faces have their own copies of the points.
cgmesh::TetMesh touchingCubes(int cellsPerSide)
{
  cgmesh::TetMesh mesh = kuhnCube(cellsPerSide);
  const cgmesh::TetMesh second = kuhnCube(cellsPerSide);
  const cgmesh::PointId offset = mesh.numberOfPoints();
  for (cgmesh::PointId p = 0; p < second.numberOfPoints(); ++p)
  {
    const double* point = second.point(p);
    mesh.coordinates.insert(mesh.coordinates.end(), { point[0] + 1.0, point[1], point[2] });
  }
  for (cgmesh::Tet tet : second.tets)
  {
    for (cgmesh::PointId& p : tet)
      p += offset;
    mesh.tets.push_back(tet);
  }
  return mesh;
}

//------------------------------------------------------------------------------
// Empty and tiny inputs

void test_emptyGrid()
{
  vtkNew<vtkUnstructuredGrid> empty;
  vtkSmartPointer<vtkUnstructuredGrid> pointsOnly = makeGrid(UnitTetCorners, VTK_TETRA, {});
  for (vtkUnstructuredGrid* input : { static_cast<vtkUnstructuredGrid*>(empty), pointsOnly.Get() })
  {
    FilterRun run(input, input == empty ? "empty grid" : "points without cells");
    run.update();
    CGMESH_CHECK(run.UpdateResult == 1 && run.Messages->Errors == 0,
      run.CaseName << ": an error: " << run.Messages->Text);
    CGMESH_CHECK(run.said("no cells"), run.CaseName << ": no warning: " << run.Messages->Text);
    CGMESH_CHECK(run.output()->GetNumberOfCells() == 0, run.CaseName << ": output not empty");
  }
}

void test_oneTet()
{
  vtkSmartPointer<vtkUnstructuredGrid> input =
    makeGrid(UnitTetCorners, VTK_TETRA, { { 0, 1, 2, 3 } });
  addLinearField(input);
  FilterRun run(input, "one tet");
  expectRefinement(run, 1.0 / 6.0);
  cgmesh_test::checkLinearField(run.output());
}

void test_morePartitionsThanCells()
{
  vtkSmartPointer<vtkUnstructuredGrid> input = toGrid(kuhnCube(1)); // 6 tets
  FilterRun run(input, "1024 partitions of 6 tets");
  run.Filter->SetNumberOfPartitions(1024);
  expectRefinement(run, 1.0);
  CGMESH_CHECK(
    run.said("1024"), "no warning about the reduced partition count: " << run.Messages->Text);
  CGMESH_CHECK(cgmesh_test::fieldValue(run.output(), "NumberOfPartitions") <= 6,
    "more partitions than input tets");
}

void test_onePartition()
{
  vtkSmartPointer<vtkUnstructuredGrid> input = cgmesh_test::makeCubeWithTestArrays(3);
  FilterRun run(input, "one partition");
  run.Filter->SetNumberOfPartitions(1);
  expectRefinement(run, 1.0);
  cgmesh_test::checkConformity(input, run.output());
  cgmesh_test::checkDataTransfer(input, run.output());
  CGMESH_CHECK(cgmesh_test::fieldValue(run.output(), "NumberOfColors") == 1,
    "one partition needs more than one colour");
}

//------------------------------------------------------------------------------
// Cell types

void test_mixedGrid()
{
  const std::vector<Vector> points = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 },
    { 0, 0, 1 }, { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 }, { 2, 0, 0 } };
  vtkSmartPointer<vtkUnstructuredGrid> input =
    makeGrid(points, VTK_HEXAHEDRON, { { 0, 1, 2, 3, 4, 5, 6, 7 } });
  const vtkIdType tetrahedra[2][4] = { { 1, 8, 2, 5 }, { 8, 2, 5, 6 } };
  for (const auto& tet : tetrahedra)
    input->InsertNextCell(VTK_TETRA, 4, tet);
  FilterRun run(input, "hexahedron and tets");
  expectError(run, { "1 of its 3 cells", "Tetrahedralize" });
}

void test_quadraticTets()
{
  std::vector<Vector> points = UnitTetCorners;
  const int edges[6][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
  for (const auto& edge : edges)
  {
    const Vector& a = UnitTetCorners[edge[0]];
    const Vector& b = UnitTetCorners[edge[1]];
    points.push_back({ (a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2 });
  }
  vtkSmartPointer<vtkUnstructuredGrid> input =
    makeGrid(points, VTK_QUADRATIC_TETRA, { { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9 } });
  FilterRun run(input, "quadratic tet");
  expectError(run, { "1 of its 1 cells", "Tetrahedralize" });
}

//------------------------------------------------------------------------------
// Bad coordinates and degenerate tets

void test_nonFiniteCoordinates()
{
  const double badValues[] = { std::numeric_limits<double>::quiet_NaN(),
    std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity() };
  for (const double bad : badValues)
  {
    vtkSmartPointer<vtkUnstructuredGrid> input = toGrid(kuhnCube(2));
    double point[3];
    input->GetPoint(5, point);
    point[1] = bad;
    input->GetPoints()->SetPoint(5, point);
    std::ostringstream name;
    name << "coordinate " << bad;
    FilterRun run(input, name.str());
    expectError(run, { "NaN or infinite" });
  }
}

void test_zeroVolumeTets()
{
  cgmesh::TetMesh repeated = kuhnCube(2);
  repeated.tets[3][3] = repeated.tets[3][2];
  vtkSmartPointer<vtkUnstructuredGrid> input = toGrid(repeated);
  FilterRun repeatedRun(input, "tet with a repeated point");
  expectError(repeatedRun, { "zero volume" });

  const std::vector<Vector> flatCorners = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 } };
  vtkSmartPointer<vtkUnstructuredGrid> flat = makeGrid(flatCorners, VTK_TETRA, { { 0, 1, 2, 3 } });
  FilterRun flatRun(flat, "flat tet");
  expectError(flatRun, { "zero volume" });
}

//------------------------------------------------------------------------------
// Orientation and non-conforming input

void test_invertedTets()
{
  for (const int every : { 1, 2 }) // all inverted (Netgen), every other one (DOLFIN)
  {
    cgmesh::TetMesh mesh = kuhnCube(3);
    for (std::size_t tet = 0; tet < mesh.tets.size(); tet += every)
      std::swap(mesh.tets[tet][0], mesh.tets[tet][1]);
    vtkSmartPointer<vtkUnstructuredGrid> input = toGrid(mesh);
    FilterRun run(input, every == 1 ? "all tets inverted" : "every other tet inverted");
    expectRefinement(run, 1.0);
    CGMESH_CHECK(run.said("turned around"),
      run.CaseName << ": no warning about reoriented tets: " << run.Messages->Text);
    cgmesh_test::checkLinearField(run.output());
  }
}

void test_duplicatedPoints()
{
  struct Case
  {
    const char* name;
    cgmesh::TetMesh mesh;
    double volume;
  };
  const Case cases[] = {
    { "every tet with its own points", explodedCube(2), 1.0 },
    { "touching cubes sharing no nodes", touchingCubes(2), 2.0 },
  };
  for (const Case& entry : cases)
  {
    vtkSmartPointer<vtkUnstructuredGrid> input = toGrid(entry.mesh);
    FilterRun run(input, entry.name);
    expectRefinement(run, entry.volume);
    CGMESH_CHECK(run.said("merged"),
      run.CaseName << ": no warning about merged points: " << run.Messages->Text);
    cgmesh_test::checkLinearField(run.output());
  }
}

// Two boxes meshed independently ([0,1]^3 with 2 cells per side, [1,2]x[0,1]^2 with 4): their
// x = 1 faces share nine grid points but no face, so the boxes are kept apart, with a warning
// that counts the coincident points and names the first, and each is refined on its own.
void test_touchingPartsWithIndependentMeshes()
{
  auto lines = [](double from, double to, int cells)
  {
    std::vector<double> values;
    for (int i = 0; i <= cells; ++i)
      values.push_back(i == cells ? to : from + (to - from) * i / cells);
    return values;
  };
  cgmesh::TetMesh coarse, fine;
  CGMESH_CHECK(
    cgmesh::generateKuhnGrid({ lines(0, 1, 2), lines(0, 1, 2), lines(0, 1, 2) }, coarse).ok(),
    "coarse box");
  CGMESH_CHECK(
    cgmesh::generateKuhnGrid({ lines(1, 2, 4), lines(0, 1, 4), lines(0, 1, 4) }, fine).ok(),
    "fine box");
  cgmesh::TetMesh mesh = coarse;
  const cgmesh::PointId offset = mesh.numberOfPoints();
  mesh.coordinates.insert(mesh.coordinates.end(), fine.coordinates.begin(), fine.coordinates.end());
  for (cgmesh::Tet tet : fine.tets)
  {
    for (cgmesh::PointId& p : tet)
      p += offset;
    mesh.tets.push_back(tet);
  }
  vtkSmartPointer<vtkUnstructuredGrid> input = toGrid(mesh);
  for (bool delaunay : { false, true })
  {
    FilterRun run(input, delaunay ? "touching boxes, Delaunay" : "touching boxes, Template");
    if (delaunay)
    {
      run.Filter->SetMethodToDelaunay();
      run.Filter->SetVolumeFactor(0.1);
    }
    run.update();
    CGMESH_CHECK(run.UpdateResult == 1 && run.Messages->Errors == 0,
      run.CaseName << ": the run failed: " << run.Messages->Text);
    CGMESH_CHECK(run.said("kept 9 coincident points apart (the first is point 27 at (1, 0, 0))"),
      run.CaseName << ": no warning about the points kept apart: " << run.Messages->Text);
    CGMESH_CHECK(!run.said("merged") && !run.said("Delaunay refinement failed"),
      run.CaseName << ": unexpected warnings: " << run.Messages->Text);
    const cgmesh::MeshReport report = cgmesh_test::inspectGrid(run.output(), std::string());
    CGMESH_CHECK(report.numberOfTets > 4 * static_cast<cgmesh::CellId>(mesh.tets.size()),
      run.CaseName << ": hardly refined, " << report.numberOfTets << " tets");
    CGMESH_CHECK(report.overSharedFaces == 0 && report.misorientedFacePairs == 0 &&
        report.invertedTets == 0 && report.degenerateTets == 0 && report.unusedPoints == 0,
      run.CaseName << ": " << report.describeProblems());
    CGMESH_CHECK(
      std::abs(report.volume - 2.0) <= 1e-12, run.CaseName << ": volume " << report.volume);
    // Both sides of the contact stay boundary: 6 + 6.
    CGMESH_CHECK(std::abs(report.boundaryArea - 12.0) <= 1e-12,
      run.CaseName << ": boundary area " << report.boundaryArea);
    cgmesh_test::checkLinearField(run.output());
  }
}

//------------------------------------------------------------------------------
// Region arrays

// A cell array "Region" of `type` holding values[slab], the slab of the cell centroid along x.
void addRegionArray(vtkUnstructuredGrid* grid, int type, const std::vector<double>& values)
{
  vtkSmartPointer<vtkDataArray> regions;
  regions.TakeReference(vtkDataArray::CreateDataArray(type));
  regions->SetName("Region");
  regions->SetNumberOfTuples(grid->GetNumberOfCells());
  for (vtkIdType cellId = 0; cellId < grid->GetNumberOfCells(); ++cellId)
  {
    const double x = cellCentroid(grid, cellId)[0];
    const auto slab = std::min(values.size() - 1, static_cast<std::size_t>(x * values.size()));
    regions->SetComponent(cellId, 0, values[slab]);
  }
  grid->GetCellData()->AddArray(regions);
}

void checkRegionVolumes(vtkUnstructuredGrid* input, vtkUnstructuredGrid* output,
  const std::vector<double>& values, const std::string& name)
{
  const auto before = cgmesh_test::inspectGrid(input, "Region").regionVolumes;
  const auto after = cgmesh_test::inspectGrid(output, "Region").regionVolumes;
  CGMESH_CHECK(before.size() == values.size() && after.size() == before.size(),
    name << ": " << before.size() << " regions in, " << after.size() << " out");
  for (const auto& region : before)
  {
    const auto found = after.find(region.first);
    const double volume = found == after.end() ? 0.0 : found->second;
    CGMESH_CHECK(std::abs(volume - region.second) <= 1e-9 * region.second,
      name << ": region " << region.first << " volume " << volume << ", expected "
           << region.second);
  }
  vtkDataArray* outputRegions = output->GetCellData()->GetArray("Region");
  CGMESH_CHECK(outputRegions &&
      outputRegions->GetDataType() == input->GetCellData()->GetArray("Region")->GetDataType(),
    name << ": the region array lost its type");
}

void test_regionArrays()
{
  const std::vector<std::vector<double>> valueSets = { { 92, 93, 94 }, { 10, 20 }, { -7, -1, 3 } };
  for (const int type : { VTK_INT, VTK_FLOAT, VTK_DOUBLE, VTK_UNSIGNED_CHAR })
  {
    for (const auto& values : valueSets)
    {
      if (type == VTK_UNSIGNED_CHAR && values.front() < 0)
        continue;
      vtkSmartPointer<vtkUnstructuredGrid> input = toGrid(kuhnCube(3));
      addRegionArray(input, type, values);
      for (const bool byRegion : { false, true })
      {
        std::ostringstream name;
        name << "region values from " << values.front() << " in a " << typeName(type) << " array"
             << (byRegion ? ", partitioned by region" : "");
        FilterRun run(input, name.str());
        run.Filter->SetRegionArrayName("Region");
        run.Filter->SetPartitionByRegion(byRegion);
        expectRefinement(run, 1.0);
        checkRegionVolumes(input, run.output(), values, run.CaseName);
      }
    }
  }
}

void test_badRegionArrays()
{
  vtkSmartPointer<vtkUnstructuredGrid> input = toGrid(kuhnCube(2));
  FilterRun missing(input, "missing region array");
  missing.Filter->SetRegionArrayName("NoSuchArray");
  expectError(missing, { "NoSuchArray", "not a cell array" });

  vtkNew<vtkStringArray> names;
  names->SetName("Names");
  for (vtkIdType cellId = 0; cellId < input->GetNumberOfCells(); ++cellId)
    names->InsertNextValue("cell");
  input->GetCellData()->AddArray(names);
  FilterRun strings(input, "string region array");
  strings.Filter->SetRegionArrayName("Names");
  expectError(strings, { "Names", "not numeric" });
}

//------------------------------------------------------------------------------
// Scale and size guard

void test_extremeScales()
{
  for (const double scale : { 1e-6, 1e6 })
  {
    vtkSmartPointer<vtkUnstructuredGrid> input = toGrid(kuhnCube(3, scale));
    std::ostringstream name;
    name << "extent " << scale;
    FilterRun run(input, name.str());
    expectRefinement(run, scale * scale * scale);
    CGMESH_CHECK(run.output()->GetNumberOfCells() == 8 * input->GetNumberOfCells(),
      run.CaseName << ": " << run.output()->GetNumberOfCells() << " cells, not 8 x "
                   << input->GetNumberOfCells() << " as at unit scale");
  }
}

void test_sizeGuard()
{
  vtkNew<vtkCoarseGrainedMeshAdaptation> defaults;
  CGMESH_CHECK(defaults->GetMaximumNumberOfCells() == 100000000, "MaximumNumberOfCells default");
  defaults->SetMaximumNumberOfCells(-5);
  CGMESH_CHECK(defaults->GetMaximumNumberOfCells() == 0, "MaximumNumberOfCells not clamped to 0");
  std::ostringstream printed;
  defaults->Print(printed);
  CGMESH_CHECK(printed.str().find("MaximumNumberOfCells: 0 (no limit)") != std::string::npos,
    "PrintSelf omits MaximumNumberOfCells");

  vtkSmartPointer<vtkUnstructuredGrid> input = toGrid(kuhnCube(4)); // 384 tets, 3,072 refined
  FilterRun guarded(input, "size guard of 1000 cells");
  guarded.Filter->SetMaximumNumberOfCells(1000);
  expectError(guarded, { "limit of 1000", "MaximumNumberOfCells" });

  FilterRun unlimited(input, "no size guard");
  unlimited.Filter->SetMaximumNumberOfCells(0);
  expectRefinement(unlimited, 1.0);
}

//------------------------------------------------------------------------------
// Attached data

const int NumericTypes[] = { VTK_CHAR, VTK_SIGNED_CHAR, VTK_UNSIGNED_CHAR, VTK_SHORT,
  VTK_UNSIGNED_SHORT, VTK_INT, VTK_UNSIGNED_INT, VTK_LONG, VTK_UNSIGNED_LONG, VTK_LONG_LONG,
  VTK_UNSIGNED_LONG_LONG, VTK_FLOAT, VTK_DOUBLE, VTK_ID_TYPE };

std::string arrayName(const char* kind, int type, int components)
{
  return std::string(kind) + "_" + typeName(type) + "_" + std::to_string(components);
}

// Component c of the point arrays: 10 (x + 2y + 3z) + c, whole numbers on the Kuhn cube of side
// 2 (coordinates are multiples of 1/2), between 0 and 62 (in range of every type).
double pointValue(const Vector& point, int component)
{
  return 10 * linearValue(point) + component;
}

// Component c of the cell arrays: a value between 0 and 99 that differs between neighbours.
double cellValue(vtkIdType cellId, int component)
{
  return static_cast<double>((7 * cellId + 13 * component) % 100);
}

vtkSmartPointer<vtkDataArray> makeArray(int type, int components, const std::string& name,
  vtkIdType tuples, const std::function<double(vtkIdType, int)>& value)
{
  vtkSmartPointer<vtkDataArray> array;
  array.TakeReference(vtkDataArray::CreateDataArray(type));
  array->SetName(name.c_str());
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  for (vtkIdType tuple = 0; tuple < tuples; ++tuple)
    for (int component = 0; component < components; ++component)
      array->SetComponent(tuple, component, value(tuple, component));
  return array;
}

void addArraysOfEveryType(vtkUnstructuredGrid* grid)
{
  for (const int type : NumericTypes)
  {
    for (const int components : { 1, 3 })
    {
      grid->GetPointData()->AddArray(
        makeArray(type, components, arrayName("Point", type, components), grid->GetNumberOfPoints(),
          [grid](vtkIdType pointId, int component)
          { return pointValue(pointOf(grid, pointId), component); }));
      grid->GetCellData()->AddArray(makeArray(type, components, arrayName("Cell", type, components),
        grid->GetNumberOfCells(), cellValue));
    }
  }
  vtkNew<vtkStringArray> names;
  names->SetName("CellName");
  for (vtkIdType cellId = 0; cellId < grid->GetNumberOfCells(); ++cellId)
    names->InsertNextValue("cell " + std::to_string(cellId));
  grid->GetCellData()->AddArray(names);
}

// Every child carries its parent's (ParentId) values exactly.
void checkCellArraysCopied(vtkUnstructuredGrid* input, vtkUnstructuredGrid* output)
{
  vtkDataArray* parentIds = output->GetCellData()->GetArray("ParentId");
  for (int index = 0; parentIds && index < input->GetCellData()->GetNumberOfArrays(); ++index)
  {
    vtkAbstractArray* source = input->GetCellData()->GetAbstractArray(index);
    vtkAbstractArray* copied = output->GetCellData()->GetAbstractArray(source->GetName());
    CGMESH_CHECK(copied && copied->GetDataType() == source->GetDataType() &&
        copied->GetNumberOfComponents() == source->GetNumberOfComponents() &&
        copied->GetNumberOfTuples() == output->GetNumberOfCells(),
      "cell array " << source->GetName() << " missing or of another type or size");
    if (!copied || copied->GetDataType() != source->GetDataType())
      continue;
    const int components = source->GetNumberOfComponents();
    vtkIdType wrongValues = 0;
    for (vtkIdType cellId = 0; cellId < output->GetNumberOfCells(); ++cellId)
    {
      const auto parent = static_cast<vtkIdType>(parentIds->GetComponent(cellId, 0));
      for (int component = 0; component < components; ++component)
      {
        const bool same = copied->GetVariantValue(cellId * components + component) ==
          source->GetVariantValue(parent * components + component);
        wrongValues += same ? 0 : 1;
      }
    }
    CGMESH_CHECK(wrongValues == 0,
      "cell array " << source->GetName() << ": " << wrongValues << " values not copied exactly");
  }
}

// Interpolated values of a point array against 10 (x + 2y + 3z) + c: floating-point types to
// rounding error, integer types rounded to within 1.
void checkPointArray(vtkUnstructuredGrid* output, int type, int components)
{
  const std::string name = arrayName("Point", type, components);
  vtkDataArray* array = output->GetPointData()->GetArray(name.c_str());
  CGMESH_CHECK(array && array->GetDataType() == type &&
      array->GetNumberOfComponents() == components &&
      array->GetNumberOfTuples() == output->GetNumberOfPoints(),
    "point array " << name << " missing or of another type or size");
  if (!array || array->GetDataType() != type)
    return;
  const bool integral = type != VTK_FLOAT && type != VTK_DOUBLE;
  const double tolerance = type == VTK_DOUBLE ? 1e-12 : type == VTK_FLOAT ? 1e-5 : 1.0;
  vtkIdType wrongValues = 0;
  vtkIdType fractionalValues = 0;
  for (vtkIdType pointId = 0; pointId < output->GetNumberOfPoints(); ++pointId)
  {
    const Vector point = pointOf(output, pointId);
    for (int component = 0; component < components; ++component)
    {
      const double value = array->GetComponent(pointId, component);
      wrongValues += std::abs(value - pointValue(point, component)) <= tolerance ? 0 : 1;
      fractionalValues += integral && value != std::round(value) ? 1 : 0;
    }
  }
  CGMESH_CHECK(wrongValues == 0,
    "point array " << name << ": " << wrongValues << " values off the linear field");
  CGMESH_CHECK(fractionalValues == 0, "point array " << name << ": fractional values");
}

// An integer point array left a labelling: a point where an input point was keeps its value;
// a new one, between points whose values all differ on this field, gets 0.
void checkPointLabels(
  vtkUnstructuredGrid* input, vtkUnstructuredGrid* output, int type, int components)
{
  const std::string name = arrayName("Point", type, components);
  vtkDataArray* before = input->GetPointData()->GetArray(name.c_str());
  vtkDataArray* after = output->GetPointData()->GetArray(name.c_str());
  CGMESH_CHECK(
    after && after->GetDataType() == type && after->GetNumberOfComponents() == components,
    "point array " << name << " missing or of another type");
  if (!after || !before)
    return;
  std::map<std::array<double, 3>, vtkIdType> inputPointAt;
  for (vtkIdType pointId = 0; pointId < input->GetNumberOfPoints(); ++pointId)
  {
    const Vector point = pointOf(input, pointId);
    inputPointAt[{ point[0], point[1], point[2] }] = pointId;
  }
  vtkIdType wrongValues = 0, newPoints = 0;
  for (vtkIdType pointId = 0; pointId < output->GetNumberOfPoints(); ++pointId)
  {
    const Vector point = pointOf(output, pointId);
    const auto found = inputPointAt.find({ point[0], point[1], point[2] });
    newPoints += found == inputPointAt.end() ? 1 : 0;
    for (int component = 0; component < components; ++component)
    {
      const double expected =
        found == inputPointAt.end() ? 0.0 : before->GetComponent(found->second, component);
      wrongValues += after->GetComponent(pointId, component) == expected ? 0 : 1;
    }
  }
  CGMESH_CHECK(newPoints > 0, "point array " << name << ": no new point to check");
  CGMESH_CHECK(wrongValues == 0,
    "point array " << name << ": " << wrongValues << " values not kept as labels");
}

void test_attachedData()
{
  vtkSmartPointer<vtkUnstructuredGrid> input = cgmesh_test::makeCubeWithTestArrays(2);
  addArraysOfEveryType(input);
  // Integer point arrays are labels unless named for interpolation: both ways are checked.
  std::string integerPointArrays;
  for (const int type : NumericTypes)
    for (const int components : { 1, 3 })
      if (type != VTK_FLOAT && type != VTK_DOUBLE)
        integerPointArrays +=
          (integerPointArrays.empty() ? "" : ",") + arrayName("Point", type, components);
  for (const bool interpolated : { true, false })
  {
    FilterRun run(input, interpolated ? "arrays of every type" : "integer point labels");
    run.Filter->SetNumberOfIterations(2);
    run.Filter->SetEdgeLengthFactor(0.25);
    run.Filter->SetInterpolatedPointArrays(interpolated ? integerPointArrays.c_str() : "");
    expectRefinement(run, 1.0);
    vtkUnstructuredGrid* output = run.output();
    if (output->GetNumberOfCells() == 0)
      return;
    CGMESH_CHECK(output->GetNumberOfPoints() > 2 * input->GetNumberOfPoints(), "few new points");
    cgmesh_test::checkDataTransfer(input, output);
    checkCellArraysCopied(input, output);
    for (const int type : NumericTypes)
      for (const int components : { 1, 3 })
        if (interpolated || type == VTK_FLOAT || type == VTK_DOUBLE)
          checkPointArray(output, type, components);
        else
          checkPointLabels(input, output, type, components);
  }
}

} // namespace

int main()
{
  test_emptyGrid();
  test_oneTet();
  test_morePartitionsThanCells();
  test_onePartition();
  test_mixedGrid();
  test_quadraticTets();
  test_nonFiniteCoordinates();
  test_zeroVolumeTets();
  test_invertedTets();
  test_duplicatedPoints();
  test_touchingPartsWithIndependentMeshes();
  test_regionArrays();
  test_badRegionArrays();
  test_extremeScales();
  test_sizeGuard();
  test_attachedData();
  if (cgmesh_test::FailureCount > 0)
  {
    std::cerr << cgmesh_test::FailureCount << " checks failed\n";
    return EXIT_FAILURE;
  }
  std::cout << "all robustness checks passed\n";
  return EXIT_SUCCESS;
}
