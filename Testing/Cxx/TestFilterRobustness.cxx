// Awkward and bad inputs through vtkCoarseGrainedMeshAdaptation. Every case gives either a valid
// conforming refinement, or a failed RequestData with a vtkErrorMacro message and an empty output;
// in both the input object keeps its points, cells, arrays and MTime. Attached data of every type:
// TestFilterAttachedData.
#include "FilterRunChecks.h"

#include "CubeGenerator.h"
#include "cgmeshVTKConversion.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCoarseGrainedMeshAdaptation.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace
{

using namespace cgmesh_test;

//------------------------------------------------------------------------------
// Input meshes

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
  if (cgmesh_test::FailureCount > 0)
  {
    std::cerr << cgmesh_test::FailureCount << " checks failed\n";
    return EXIT_FAILURE;
  }
  std::cout << "all robustness checks passed\n";
  return EXIT_SUCCESS;
}
