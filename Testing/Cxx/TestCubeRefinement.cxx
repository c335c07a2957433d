// Refines a Kuhn cube with 2 iterations and a factor that splits every edge, then checks the exact
// cell count, conformity, data transfer and bit-identical output across thread counts.
//   TestCubeRefinement N PARTITIONS THREADS... [--region-array NAME]
#include "FilterTestSupport.h"

#include "vtkUnstructuredGrid.h"

#include <cstdlib>
#include <string>
#include <vector>

namespace
{

struct TestCase
{
  int cellsPerSide = 10;
  int numberOfPartitions = 1;
  std::vector<int> threadCounts;
  std::string regionArrayName;
};

bool parseTestCase(int argc, char* argv[], TestCase& testCase)
{
  std::vector<std::string> arguments(argv + 1, argv + argc);
  for (size_t index = 0; index + 1 < arguments.size(); ++index)
  {
    if (arguments[index] == "--region-array")
    {
      testCase.regionArrayName = arguments[index + 1];
      arguments.erase(arguments.begin() + index, arguments.begin() + index + 2);
      break;
    }
  }
  if (arguments.size() < 3)
    return false;
  testCase.cellsPerSide = std::atoi(arguments[0].c_str());
  testCase.numberOfPartitions = std::atoi(arguments[1].c_str());
  for (size_t index = 2; index < arguments.size(); ++index)
    testCase.threadCounts.push_back(std::atoi(arguments[index].c_str()));
  return testCase.cellsPerSide > 0 && testCase.numberOfPartitions > 0;
}

// Two iterations that split every edge turn each tet into 8, twice.
void test_refinement(const TestCase& testCase, vtkUnstructuredGrid* input,
  vtkSmartPointer<vtkUnstructuredGrid>& reference)
{
  cgmesh_test::FilterSettings settings;
  settings.numberOfPartitions = testCase.numberOfPartitions;
  settings.numberOfThreads = testCase.threadCounts.front();
  settings.regionArrayName = testCase.regionArrayName;
  reference = cgmesh_test::runFilter(input, settings);
  if (!reference)
    return;
  CGMESH_CHECK(reference->GetNumberOfCells() == 64 * input->GetNumberOfCells(),
    "expected " << 64 * input->GetNumberOfCells() << " tets, got "
                << reference->GetNumberOfCells());
  cgmesh_test::checkConformity(input, reference);
  cgmesh_test::checkDataTransfer(input, reference);
}

void test_threadIndependence(
  const TestCase& testCase, vtkUnstructuredGrid* input, vtkUnstructuredGrid* reference)
{
  for (size_t index = 1; index < testCase.threadCounts.size(); ++index)
  {
    cgmesh_test::FilterSettings settings;
    settings.numberOfPartitions = testCase.numberOfPartitions;
    settings.numberOfThreads = testCase.threadCounts[index];
    settings.regionArrayName = testCase.regionArrayName;
    vtkSmartPointer<vtkUnstructuredGrid> output = cgmesh_test::runFilter(input, settings);
    std::string difference;
    CGMESH_CHECK(output && cgmesh_test::identicalGrids(reference, output, difference),
      "threads " << testCase.threadCounts.front() << " and " << settings.numberOfThreads << ": "
                 << difference);
  }
}

} // namespace

int main(int argc, char* argv[])
{
  TestCase testCase;
  if (!parseTestCase(argc, argv, testCase))
  {
    std::cerr << "usage: TestCubeRefinement N PARTITIONS THREADS... [--region-array NAME]\n";
    return EXIT_FAILURE;
  }
  vtkSmartPointer<vtkUnstructuredGrid> input =
    cgmesh_test::makeCubeWithTestArrays(testCase.cellsPerSide);
  vtkSmartPointer<vtkUnstructuredGrid> reference;
  test_refinement(testCase, input, reference);
  if (reference)
    test_threadIndependence(testCase, input, reference);
  if (cgmesh_test::FailureCount > 0)
  {
    std::cerr << cgmesh_test::FailureCount << " checks failed\n";
    return EXIT_FAILURE;
  }
  std::cout << "cube " << testCase.cellsPerSide << ", " << testCase.numberOfPartitions
            << " partitions: " << reference->GetNumberOfCells() << " tets, all checks passed\n";
  return EXIT_SUCCESS;
}
