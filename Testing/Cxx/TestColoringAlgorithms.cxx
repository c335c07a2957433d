// Every colouring through the VTK filter on the Small cube (N=10, 64 partitions, 1 iteration that
// splits every edge): valid, conforming output that is bit-identical for 1 and 2 threads, the
// colouring's name in the field data, and Greedy-LU and Recoloring better balanced than Greedy.
#include "FilterTestSupport.h"

#include "Coloring/PartitionColoring.h"

#include "vtkFieldData.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

namespace
{

constexpr int CellsPerSide = 10;
constexpr int NumberOfPartitions = 64;

// The colouring recorded in the field data (its index: names are diagnostics, off by default).
std::string storedColoringName(vtkUnstructuredGrid* output)
{
  const char* name = vtkCoarseGrainedMeshAdaptation::ColoringAlgorithmToName(
    static_cast<int>(cgmesh_test::fieldValue(output, "ColoringAlgorithmIndex")));
  return name ? name : std::string();
}

// The filter's enumeration names exactly the colourings the kernels' registry provides.
void test_namesMatchRegistry()
{
  const std::vector<std::string> registered = cgmesh::coloringNames();
  CGMESH_CHECK(registered.size() == vtkCoarseGrainedMeshAdaptation::RECOLORING + 1,
    "the registry has " << registered.size() << " colourings, the filter 4");
  for (int algorithm = vtkCoarseGrainedMeshAdaptation::GREEDY;
       algorithm <= vtkCoarseGrainedMeshAdaptation::RECOLORING; ++algorithm)
  {
    const char* name = vtkCoarseGrainedMeshAdaptation::ColoringAlgorithmToName(algorithm);
    CGMESH_CHECK(name && std::count(registered.begin(), registered.end(), name) == 1,
      "colouring " << algorithm << " (" << (name ? name : "null") << ") not in the registry");
    CGMESH_CHECK(vtkCoarseGrainedMeshAdaptation::ColoringAlgorithmFromName(name) == algorithm,
      "name of colouring " << algorithm << " does not map back");
  }
  CGMESH_CHECK(vtkCoarseGrainedMeshAdaptation::ColoringAlgorithmFromName("Greedy") == -1 &&
      vtkCoarseGrainedMeshAdaptation::ColoringAlgorithmFromName(nullptr) == -1 &&
      vtkCoarseGrainedMeshAdaptation::ColoringAlgorithmToName(4) == nullptr,
    "unknown colouring names or values accepted");
}

// Runs one colouring at 1 and 2 threads and returns its ColorBalance (-1 on failure).
double test_coloring(int algorithm, vtkUnstructuredGrid* input)
{
  const std::string name = vtkCoarseGrainedMeshAdaptation::ColoringAlgorithmToName(algorithm);
  cgmesh_test::FilterSettings settings;
  settings.numberOfPartitions = NumberOfPartitions;
  settings.numberOfIterations = 1;
  settings.coloringAlgorithm = algorithm;
  settings.numberOfThreads = 1;
  vtkSmartPointer<vtkUnstructuredGrid> reference = cgmesh_test::runFilter(input, settings);
  settings.numberOfThreads = 2;
  vtkSmartPointer<vtkUnstructuredGrid> twoThreads = cgmesh_test::runFilter(input, settings);
  if (!reference || !twoThreads)
    return -1;

  CGMESH_CHECK(reference->GetNumberOfCells() == 8 * input->GetNumberOfCells(),
    name << ": expected " << 8 * input->GetNumberOfCells() << " tets, got "
         << reference->GetNumberOfCells());
  cgmesh_test::checkConformity(input, reference);
  cgmesh_test::checkDataTransfer(input, reference);
  CGMESH_CHECK(storedColoringName(reference) == name,
    "field data ColoringAlgorithm is '" << storedColoringName(reference) << "', not " << name);
  CGMESH_CHECK(cgmesh_test::fieldValue(reference, "NumberOfPartitions") == NumberOfPartitions,
    name << ": the partition count changed");
  std::string difference;
  CGMESH_CHECK(cgmesh_test::identicalGrids(reference, twoThreads, difference),
    name << ": threads 1 and 2 differ: " << difference);
  CGMESH_CHECK(cgmesh_test::fieldValue(reference, "ColorBalance") ==
      cgmesh_test::fieldValue(twoThreads, "ColorBalance"),
    name << ": ColorBalance differs between 1 and 2 threads");
  const double balance = cgmesh_test::fieldValue(reference, "ColorBalance");
  std::cout << name << ": " << cgmesh_test::fieldValue(reference, "NumberOfColors")
            << " colours, balance " << balance << "\n";
  return balance;
}

} // namespace

int main()
{
  test_namesMatchRegistry();
  vtkSmartPointer<vtkUnstructuredGrid> input = cgmesh_test::makeCubeWithTestArrays(CellsPerSide);
  std::map<int, double> balance;
  for (int algorithm = vtkCoarseGrainedMeshAdaptation::GREEDY;
       algorithm <= vtkCoarseGrainedMeshAdaptation::RECOLORING; ++algorithm)
  {
    balance[algorithm] = test_coloring(algorithm, input);
  }
  const double greedyBalance = balance[vtkCoarseGrainedMeshAdaptation::GREEDY];
  for (int balanced : { static_cast<int>(vtkCoarseGrainedMeshAdaptation::GREEDY_LEAST_USED),
         static_cast<int>(vtkCoarseGrainedMeshAdaptation::RECOLORING) })
  {
    CGMESH_CHECK(balance[balanced] >= 1.0 && balance[balanced] < greedyBalance,
      vtkCoarseGrainedMeshAdaptation::ColoringAlgorithmToName(balanced)
        << " balance " << balance[balanced] << " is not below greedy's " << greedyBalance);
  }
  if (cgmesh_test::FailureCount > 0)
  {
    std::cerr << cgmesh_test::FailureCount << " checks failed\n";
    return EXIT_FAILURE;
  }
  std::cout << "every colouring: valid, conforming, thread-independent output\n";
  return EXIT_SUCCESS;
}
