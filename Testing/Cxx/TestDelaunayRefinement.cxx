// Delaunay refinement through the VTK filter at 1 and 2 threads: a valid conforming output with
// the volume, the boundary area, every region's volume and the material-interface area of the
// input, linear point data interpolated exactly, the Delaunay field data present and consistent,
// and bit-identical output for both thread counts.
//   TestDelaunayRefinement cube N PARTITIONS VOLUME_FACTOR
//   TestDelaunayRefinement file MESH.vtu REGION_ARRAY PARTITIONS VOLUME_FACTOR
#include "FilterTestSupport.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkPointData.h"
#include "vtkStringArray.h"
#include "vtkTetra.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{

struct TestCase
{
  vtkSmartPointer<vtkUnstructuredGrid> input;
  std::string regionArrayName; // the cube's "Material" (two halves) or the file's array
  int numberOfPartitions = 1;
  double volumeFactor = 0.1;
};

bool relativelyEqual(double first, double second, double tolerance)
{
  return std::abs(first - second) <= tolerance * std::max(std::abs(first), std::abs(second));
}

bool readTestCase(const std::vector<std::string>& arguments, TestCase& testCase)
{
  if (arguments.size() == 4 && arguments[0] == "cube")
  {
    testCase.input = cgmesh_test::makeCubeWithTestArrays(std::atoi(arguments[1].c_str()));
    testCase.regionArrayName = "Material";
    testCase.numberOfPartitions = std::atoi(arguments[2].c_str());
    testCase.volumeFactor = std::atof(arguments[3].c_str());
    return true;
  }
  if (arguments.size() == 5 && arguments[0] == "file")
  {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(arguments[1].c_str());
    reader->Update();
    testCase.input = reader->GetOutput();
    testCase.regionArrayName = arguments[2];
    testCase.numberOfPartitions = std::atoi(arguments[3].c_str());
    testCase.volumeFactor = std::atof(arguments[4].c_str());
    return testCase.input && testCase.input->GetNumberOfCells() > 0;
  }
  return false;
}

vtkSmartPointer<vtkUnstructuredGrid> runDelaunay(const TestCase& testCase, int threads)
{
  cgmesh_test::FilterSettings settings;
  settings.method = vtkCoarseGrainedMeshAdaptation::DELAUNAY;
  settings.numberOfIterations = 1;
  settings.numberOfPartitions = testCase.numberOfPartitions;
  settings.volumeFactor = testCase.volumeFactor;
  settings.regionArrayName = testCase.regionArrayName;
  settings.numberOfThreads = threads;
  const auto start = std::chrono::steady_clock::now();
  vtkSmartPointer<vtkUnstructuredGrid> output = cgmesh_test::runFilter(testCase.input, settings);
  std::cout << threads << " thread(s): "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
            << " s\n";
  return output;
}

// Each region keeps its volume and the interfaces between regions keep their area: TetGen must
// neither move a material interface nor let a region grow into its neighbour.
void checkRegions(const TestCase& testCase, vtkUnstructuredGrid* output)
{
  const cgmesh::MeshReport before =
    cgmesh_test::inspectGrid(testCase.input, testCase.regionArrayName);
  const cgmesh::MeshReport after = cgmesh_test::inspectGrid(output, testCase.regionArrayName);
  CGMESH_CHECK(before.regionVolumes.size() > 1, "the test mesh needs two regions or more");
  CGMESH_CHECK(before.regionVolumes.size() == after.regionVolumes.size(), "regions lost or added");
  for (const auto& region : before.regionVolumes)
  {
    const auto found = after.regionVolumes.find(region.first);
    const double volume = found == after.regionVolumes.end() ? 0 : found->second;
    CGMESH_CHECK(relativelyEqual(volume, region.second, 1e-9),
      "region " << region.first << ": volume " << volume << " != input " << region.second);
  }
  CGMESH_CHECK(relativelyEqual(after.regionInterfaceArea, before.regionInterfaceArea, 1e-9),
    "material-interface area " << after.regionInterfaceArea << " != input "
                               << before.regionInterfaceArea);
}

// The Delaunay field data; prints the share of tets above the bound (the template-refined layer
// along partition and material interfaces, whose edges stop at the interface edge length).
void checkDelaunayFieldData(const TestCase& testCase, vtkUnstructuredGrid* output)
{
  CGMESH_CHECK(
    cgmesh_test::fieldValue(output, "MethodIndex") == vtkCoarseGrainedMeshAdaptation::DELAUNAY,
    "field data MethodIndex is not Delaunay");
  const double bound = cgmesh_test::fieldValue(output, "VolumeBound");
  const cgmesh::MeshReport inputReport = cgmesh_test::inspectGrid(testCase.input, std::string());
  const double expectedBound =
    testCase.volumeFactor * inputReport.volume / testCase.input->GetNumberOfCells();
  CGMESH_CHECK(relativelyEqual(bound, expectedBound, 1e-6),
    "VolumeBound " << bound << " != factor x mean tet volume " << expectedBound);
  const double fallbacks = cgmesh_test::fieldValue(output, "DelaunayFallbacks");
  vtkDataArray* fallbackPartitions = output->GetFieldData()->GetArray("FallbackPartitions");
  CGMESH_CHECK(!fallbackPartitions, "FallbackPartitions written without Diagnostics");
  // TetGen's aborts on the lattice's degenerate point sets are recovered by the second attempt.
  CGMESH_CHECK(fallbacks == 0, fallbacks << " fallbacks");
  const double retries = cgmesh_test::fieldValue(output, "TetGenRetries");
  CGMESH_CHECK(cgmesh_test::fieldValue(output, "TetGenPoints") > 0, "TetGen inserted no points");

  vtkIdType aboveBound = 0;
  for (vtkIdType cellId = 0; cellId < output->GetNumberOfCells(); ++cellId)
  {
    double corners[4][3];
    for (int corner = 0; corner < 4; ++corner)
      output->GetPoint(output->GetCell(cellId)->GetPointId(corner), corners[corner]);
    const double volume =
      std::abs(vtkTetra::ComputeVolume(corners[0], corners[1], corners[2], corners[3]));
    aboveBound += volume > bound * (1 + 1e-9) ? 1 : 0;
  }
  std::cout << output->GetNumberOfCells() << " tets, " << fallbacks << " fallbacks, " << retries
            << " TetGen retries, " << 100.0 * aboveBound / output->GetNumberOfCells()
            << "% above the bound\n";
}

} // namespace

int main(int argc, char* argv[])
{
  TestCase testCase;
  if (!readTestCase(std::vector<std::string>(argv + 1, argv + argc), testCase))
  {
    std::cerr << "usage: TestDelaunayRefinement cube N PARTITIONS VOLUME_FACTOR\n"
                 "       TestDelaunayRefinement file MESH.vtu REGION_ARRAY PARTITIONS "
                 "VOLUME_FACTOR\n";
    return EXIT_FAILURE;
  }
  vtkSmartPointer<vtkUnstructuredGrid> oneThread = runDelaunay(testCase, 1);
  vtkSmartPointer<vtkUnstructuredGrid> twoThreads = runDelaunay(testCase, 2);
  if (oneThread && twoThreads)
  {
    CGMESH_CHECK(oneThread->GetNumberOfCells() > 2 * testCase.input->GetNumberOfCells(),
      "hardly refined: " << oneThread->GetNumberOfCells() << " tets");
    cgmesh_test::checkConformity(testCase.input, oneThread);
    checkRegions(testCase, oneThread);
    if (testCase.input->GetPointData()->GetArray("LinearField"))
      cgmesh_test::checkLinearField(oneThread);
    cgmesh_test::checkOutputArrays(oneThread);
    checkDelaunayFieldData(testCase, oneThread);
    std::string difference;
    CGMESH_CHECK(cgmesh_test::identicalGrids(oneThread, twoThreads, difference),
      "threads 1 and 2 differ: " << difference);
  }
  if (cgmesh_test::FailureCount > 0)
  {
    std::cerr << cgmesh_test::FailureCount << " checks failed\n";
    return EXIT_FAILURE;
  }
  std::cout << "Delaunay refinement: all checks passed\n";
  return EXIT_SUCCESS;
}
