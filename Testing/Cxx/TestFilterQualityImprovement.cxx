// Quality improvement through the VTK filter on the bundled nine-material FinFET (64 partitions,
// one iteration with an edge length factor of 1, which splits about half of the edges, so that the
// templates leave poorly shaped tets to improve). With ImproveQuality on, at 1 and 2 threads: the
// output is valid and conforming, volume, boundary area, the volume of every material and the
// material-interface area are conserved, the output does not depend on the thread count, the worst
// mean ratio is higher than with ImproveQuality off, and NearFormerInterface marks some tets.
// Improving the input first (ImproveInput, the default) against improving only after refinement:
// both conforming with every material conserved, and the first no worse.
//   TestFilterQualityImprovement FINFET.vtu
#include "FilterTestSupport.h"

#include "Core/TetQuality.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

namespace
{

const char* const MaterialArray = "Material";

// The measure the improvement raises (TetQuality.h): worst tet and tets below the target 0.5.
struct MeanRatioFigures
{
  double worst = 1.0;
  vtkIdType belowTarget = 0;
};

MeanRatioFigures measureMeanRatio(vtkUnstructuredGrid* grid)
{
  MeanRatioFigures figures;
  for (vtkIdType cellId = 0; cellId < grid->GetNumberOfCells(); ++cellId)
  {
    const vtkIdType* pointIds;
    vtkIdType count;
    grid->GetCellPoints(cellId, count, pointIds);
    double corners[4][3];
    for (int corner = 0; corner < 4; ++corner)
      grid->GetPoint(pointIds[corner], corners[corner]);
    const double quality = cgmesh::meanRatio(corners[0], corners[1], corners[2], corners[3]);
    figures.worst = std::min(figures.worst, quality);
    figures.belowTarget += quality < 0.5 ? 1 : 0;
  }
  return figures;
}

bool relativelyEqual(double first, double second)
{
  return std::abs(first - second) <= 1e-9 * std::max(std::abs(first), std::abs(second));
}

// Volume of every material and the area between materials, as in the input.
void checkRegionsConserved(vtkUnstructuredGrid* input, vtkUnstructuredGrid* output)
{
  const cgmesh::MeshReport inputReport = cgmesh_test::inspectGrid(input, MaterialArray);
  const cgmesh::MeshReport report = cgmesh_test::inspectGrid(output, MaterialArray);
  CGMESH_CHECK(
    report.regionVolumes.size() == inputReport.regionVolumes.size(), "materials lost or added");
  for (const auto& region : inputReport.regionVolumes)
  {
    const auto found = report.regionVolumes.find(region.first);
    CGMESH_CHECK(
      found != report.regionVolumes.end() && relativelyEqual(found->second, region.second),
      "material " << region.first << ": volume not conserved");
  }
  CGMESH_CHECK(relativelyEqual(report.regionInterfaceArea, inputReport.regionInterfaceArea),
    "material-interface area " << report.regionInterfaceArea << " != input "
                               << inputReport.regionInterfaceArea);
}

// NearFormerInterface is a 0/1 cell array that marks some tets, not all.
void checkNearFormerInterface(vtkUnstructuredGrid* output)
{
  vtkDataArray* near = output->GetCellData()->GetArray("NearFormerInterface");
  CGMESH_CHECK(near && near->GetNumberOfTuples() == output->GetNumberOfCells(),
    "cell array NearFormerInterface missing or of the wrong size");
  vtkIdType marked = 0;
  for (vtkIdType cellId = 0; near && cellId < near->GetNumberOfTuples(); ++cellId)
  {
    const double value = near->GetComponent(cellId, 0);
    CGMESH_CHECK(value == 0 || value == 1, "NearFormerInterface value " << value);
    marked += value == 1 ? 1 : 0;
  }
  CGMESH_CHECK(marked > 0 && marked < output->GetNumberOfCells(),
    marked << " of " << output->GetNumberOfCells() << " tets near former interfaces");
}

double improvementOperations(vtkUnstructuredGrid* output)
{
  return cgmesh_test::fieldValue(output, "EdgeRemovals") +
    cgmesh_test::fieldValue(output, "FaceSwaps") + cgmesh_test::fieldValue(output, "VertexMoves");
}

cgmesh_test::FilterSettings finFetSettings(
  bool improveQuality, int threads, bool improveInput = true)
{
  cgmesh_test::FilterSettings settings;
  settings.numberOfPartitions = 64;
  settings.numberOfIterations = 1;
  settings.edgeLengthFactor = 1.0;
  settings.regionArrayName = MaterialArray;
  settings.improveQuality = improveQuality;
  settings.improveInput = improveInput;
  settings.numberOfThreads = threads;
  return settings;
}

void test_improvement(vtkUnstructuredGrid* input)
{
  vtkSmartPointer<vtkUnstructuredGrid> improved =
    cgmesh_test::runFilter(input, finFetSettings(true, 1));
  vtkSmartPointer<vtkUnstructuredGrid> improvedTwoThreads =
    cgmesh_test::runFilter(input, finFetSettings(true, 2));
  vtkSmartPointer<vtkUnstructuredGrid> templatesOnly =
    cgmesh_test::runFilter(input, finFetSettings(false, 1));
  if (!improved || !improvedTwoThreads || !templatesOnly)
    return;
  cgmesh_test::checkConformity(input, improved);
  cgmesh_test::checkOutputArrays(improved);
  checkRegionsConserved(input, improved);
  checkNearFormerInterface(improved);
  checkNearFormerInterface(templatesOnly);
  std::string difference;
  CGMESH_CHECK(cgmesh_test::identicalGrids(improved, improvedTwoThreads, difference),
    "threads 1 and 2 differ: " << difference);

  CGMESH_CHECK(improvementOperations(improved) > 0, "ImproveQuality on changed nothing");
  CGMESH_CHECK(improvementOperations(templatesOnly) == 0, "ImproveQuality off changed the mesh");
  const MeanRatioFigures after = measureMeanRatio(improved);
  const MeanRatioFigures before = measureMeanRatio(templatesOnly);
  CGMESH_CHECK(after.worst > before.worst,
    "worst mean ratio " << after.worst << " not above " << before.worst << " without improvement");
  CGMESH_CHECK(2 * after.belowTarget <= before.belowTarget,
    after.belowTarget << " tets below mean ratio 0.5, " << before.belowTarget << " without");
  std::cout << "worst mean ratio " << before.worst << " -> " << after.worst << ", tets below 0.5 "
            << before.belowTarget << " -> " << after.belowTarget << "\n";

  // Improving only after refinement (ImproveInput off) keeps the same invariants; improving the
  // input first leaves no more tets below the target and no worse a worst tet.
  vtkSmartPointer<vtkUnstructuredGrid> afterOnly =
    cgmesh_test::runFilter(input, finFetSettings(true, 2, false));
  if (!afterOnly)
    return;
  cgmesh_test::checkConformity(input, afterOnly);
  checkRegionsConserved(input, afterOnly);
  const MeanRatioFigures refinedOnly = measureMeanRatio(afterOnly);
  std::cout << "improving after refinement only: worst mean ratio " << refinedOnly.worst
            << ", tets below 0.5 " << refinedOnly.belowTarget << "\n";
  CGMESH_CHECK(after.belowTarget <= refinedOnly.belowTarget,
    after.belowTarget << " tets below mean ratio 0.5 with the input improved, "
                      << refinedOnly.belowTarget << " without");
  CGMESH_CHECK(after.worst >= refinedOnly.worst,
    "worst mean ratio " << after.worst << " with the input improved, " << refinedOnly.worst
                        << " without");
}

} // namespace

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::cerr << "usage: TestFilterQualityImprovement FINFET.vtu\n";
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
  test_improvement(input);
  if (cgmesh_test::FailureCount > 0)
  {
    std::cerr << cgmesh_test::FailureCount << " checks failed\n";
    return EXIT_FAILURE;
  }
  std::cout << "quality improvement: all checks passed\n";
  return EXIT_SUCCESS;
}
