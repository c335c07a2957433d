// Partitioning along material regions through the VTK filter on the bundled FinFET (nine
// materials), with 1 and 4 partitions per region: no partition holds two materials, the volume of
// every material is conserved, the output is valid and does not depend on the thread count.
//   TestPartitionByRegion FINFET.vtu
#include "FilterTestSupport.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkTetra.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <cmath>
#include <cstdlib>
#include <map>
#include <string>

namespace
{

const char* const MaterialArray = "Material";

// Volume of every material (by its id).
std::map<int, double> materialVolumes(vtkUnstructuredGrid* grid)
{
  std::map<int, double> volumes;
  vtkDataArray* material = grid->GetCellData()->GetArray(MaterialArray);
  CGMESH_CHECK(material, "cell array Material missing");
  for (vtkIdType cellId = 0; material && cellId < grid->GetNumberOfCells(); ++cellId)
  {
    const vtkIdType* pointIds;
    vtkIdType count;
    grid->GetCellPoints(cellId, count, pointIds);
    double corners[4][3];
    for (int corner = 0; corner < 4; ++corner)
      grid->GetPoint(pointIds[corner], corners[corner]);
    volumes[static_cast<int>(material->GetComponent(cellId, 0))] +=
      std::abs(vtkTetra::ComputeVolume(corners[0], corners[1], corners[2], corners[3]));
  }
  return volumes;
}

// Every PartitionId holds cells of one material only; returns the number of partitions seen.
int checkOneMaterialPerPartition(vtkUnstructuredGrid* output)
{
  vtkDataArray* material = output->GetCellData()->GetArray(MaterialArray);
  vtkDataArray* partitionIds = output->GetCellData()->GetArray("PartitionId");
  CGMESH_CHECK(material && partitionIds, "cell arrays Material/PartitionId missing");
  std::map<int, int> materialOfPartition;
  vtkIdType mixedCells = 0;
  for (vtkIdType cellId = 0; material && partitionIds && cellId < output->GetNumberOfCells();
       ++cellId)
  {
    const int partition = static_cast<int>(partitionIds->GetComponent(cellId, 0));
    const int cellMaterial = static_cast<int>(material->GetComponent(cellId, 0));
    const auto inserted = materialOfPartition.emplace(partition, cellMaterial);
    mixedCells += inserted.first->second != cellMaterial ? 1 : 0;
  }
  CGMESH_CHECK(mixedCells == 0, mixedCells << " cells in a partition of another material");
  return static_cast<int>(materialOfPartition.size());
}

void test_partitionByRegion(vtkUnstructuredGrid* input, int partitionsPerRegion)
{
  cgmesh_test::FilterSettings settings;
  settings.numberOfIterations = 1;
  settings.edgeLengthFactor = 0.5;
  settings.regionArrayName = MaterialArray;
  settings.partitionByRegion = true;
  settings.partitionsPerRegion = partitionsPerRegion;
  settings.numberOfThreads = 1;
  vtkSmartPointer<vtkUnstructuredGrid> output = cgmesh_test::runFilter(input, settings);
  settings.numberOfThreads = 2;
  vtkSmartPointer<vtkUnstructuredGrid> twoThreads = cgmesh_test::runFilter(input, settings);
  if (!output || !twoThreads)
    return;
  CGMESH_CHECK(output->GetNumberOfCells() > input->GetNumberOfCells(), "nothing was refined");
  cgmesh_test::checkConformity(input, output);

  const std::map<int, double> inputVolumes = materialVolumes(input);
  const std::map<int, double> outputVolumes = materialVolumes(output);
  CGMESH_CHECK(inputVolumes.size() == outputVolumes.size(), "materials lost or added");
  for (const auto& material : inputVolumes)
  {
    const double outputVolume =
      outputVolumes.count(material.first) ? outputVolumes.at(material.first) : 0;
    CGMESH_CHECK(std::abs(outputVolume - material.second) <= 1e-9 * material.second,
      "material " << material.first << ": volume " << outputVolume << " != input "
                  << material.second);
  }

  const int partitions = checkOneMaterialPerPartition(output);
  const int materials = static_cast<int>(inputVolumes.size());
  CGMESH_CHECK(cgmesh_test::fieldValue(output, "NumberOfPartitions") == partitions,
    "NumberOfPartitions differs from the PartitionIds in use");
  CGMESH_CHECK(partitionsPerRegion == 1
      ? partitions == materials
      : partitions > materials && partitions <= partitionsPerRegion * materials,
    partitions << " partitions for " << materials << " materials and " << partitionsPerRegion
               << " per region");
  std::string difference;
  CGMESH_CHECK(cgmesh_test::identicalGrids(output, twoThreads, difference),
    "threads 1 and 2 differ: " << difference);
  std::cout << partitionsPerRegion << " per region: " << partitions << " partitions, "
            << output->GetNumberOfCells() << " tets\n";
}

} // namespace

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::cerr << "usage: TestPartitionByRegion FINFET.vtu\n";
    return EXIT_FAILURE;
  }
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(argv[1]);
  reader->Update();
  vtkUnstructuredGrid* input = reader->GetOutput();
  if (!input || input->GetNumberOfCells() == 0)
  {
    std::cerr << "cannot read " << argv[1] << "\n";
    return EXIT_FAILURE;
  }
  for (int partitionsPerRegion : { 1, 4 })
    test_partitionByRegion(input, partitionsPerRegion);
  if (cgmesh_test::FailureCount > 0)
  {
    std::cerr << cgmesh_test::FailureCount << " checks failed\n";
    return EXIT_FAILURE;
  }
  std::cout << "partitioning by region: all checks passed\n";
  return EXIT_SUCCESS;
}
