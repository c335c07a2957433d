// cgmesh refine IN OUT [options]: runs vtkCoarseGrainedMeshAdaptation on a file.
#include "Commands.h"

#include "CommandLine.h"
#include "MeshFiles.h"
#include "RefineReport.h"
#include "VTKMessages.h"

#include "vtkCoarseGrainedMeshAdaptation.h"
#include "vtkCommand.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <unistd.h>

namespace cgmesh
{

namespace
{

void printRefineUsage()
{
  std::cout
    << "usage: cgmesh refine IN OUT [--partitions N | --partition-by-region\n"
       "                     [--partitions-per-region N]] [--iterations K]\n"
       "                     [--method template] [--max-edge-length L | --edge-length-factor F]\n"
       "                     [--method delaunay [--max-volume V | --volume-factor F]\n"
       "                      [--radius-edge-ratio Q]] [--threads T]\n"
       "                     [--no-improve | --improve-passes N] [--max-cells N]\n"
       "                     [--region-array NAME] [--coloring NAME] [--stats FILE.json]\n"
       "\n"
       "Refines the tetrahedral mesh IN (.vtu or .vtk) and writes OUT (.vtu or .vtk).\n"
       "\n"
       "  --partitions N          number of METIS partitions (default 1024)\n"
       "  --partition-by-region   cut along the regions of --region-array instead, each region\n"
       "                          on its own: no partition holds two regions\n"
       "  --partitions-per-region N\n"
       "                          with --partition-by-region: METIS partitions per region\n"
       "                          (default 1)\n"
       "  --iterations K          refinement passes (default 1)\n"
       "  --method NAME           refinement of each partition (default template):\n"
       "                            template  split long edges by conforming templates\n"
       "                            delaunay  templates on interfaces, TetGen inside partitions\n"
       "  --max-edge-length L     template: split edges longer than L (absolute length)\n"
       "  --edge-length-factor F  template: split edges longer than F x mean input edge length\n"
       "                          (default 0.5)\n"
       "  --max-volume V          delaunay: TetGen volume bound (switch a), absolute\n"
       "  --volume-factor F       delaunay: volume bound V = F x mean input tet volume\n"
       "                          (default 0.1). Interface edges are split by templates down\n"
       "                          to (6 sqrt(2) V)^(1/3), the edge of the regular tet of volume\n"
       "                          V; TetGen (switches r Y q a) refines partition interiors with\n"
       "                          their boundary kept; a partition where TetGen fails is\n"
       "                          refined by templates instead (a warning names it)\n"
       "  --radius-edge-ratio Q   delaunay: TetGen radius-edge quality bound (switch q), >= 1\n"
       "                          (default 2)\n"
       "  --no-improve            skip the quality improvement that follows refinement\n"
       "  --improve-passes N      passes of edge removal, face swaps and Laplacian smoothing\n"
       "                          per partition in each of the two improvement sweeps, 0..20\n"
       "                          (default 2). Tets whose mean ratio 12 (3V)^(2/3) / sum of\n"
       "                          squared edge lengths (1 = regular) is below 0.5 are worked\n"
       "                          on; a change is kept only when the worst mean ratio rises.\n"
       "                          Partition-interface, boundary and material-interface\n"
       "                          vertices stay fixed; a second sweep over box partitions\n"
       "                          improves the tets around the former partition interfaces\n"
       "  --threads T             OpenMP threads, 0 = all cores (default 0)\n"
       "  --max-cells N           size guard (MaximumNumberOfCells): refuse, with an error and\n"
       "                          no output file, a refinement forecast to produce more than N\n"
       "                          tetrahedra, before it allocates them; 0 = no limit\n"
       "                          (default 100000000)\n"
       "  --region-array NAME     cell array with material/region ids\n"
       "  --coloring NAME         colouring of the partition graph (default greedy-lu):\n"
       "                            greedy      first fit, serial, unbalanced\n"
       "                            greedy-lu   least-used permissible colour, serial, balanced\n"
       "                            iterative   speculative parallel colouring, conflict rounds\n"
       "                            recoloring  parallel rebalancing of an initial colouring\n"
       "  --stats FILE.json       write counts, colour populations, Delaunay figures,\n"
       "                          improvement counts, the quality summary and phase timings\n"
       "                          as JSON\n"
       "\n"
       "The table and the stats file hold the quality of all tets, of the interior tets and of\n"
       "the tets near former partition interfaces (cell array NearFormerInterface): tet count,\n"
       "minimum and 1st percentile of MinDihedralAngle (degrees), 99th percentile of EdgeRatio.\n";
}

double secondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void configureFilter(const RefineArguments& arguments, vtkCoarseGrainedMeshAdaptation* filter)
{
  filter->SetNumberOfPartitions(arguments.numberOfPartitions);
  filter->SetNumberOfIterations(arguments.numberOfIterations);
  // The parser accepted only names the filter knows.
  filter->SetMethod(vtkCoarseGrainedMeshAdaptation::MethodFromName(arguments.method.c_str()));
  filter->SetMaximumEdgeLength(arguments.maximumEdgeLength);
  filter->SetEdgeLengthFactor(arguments.edgeLengthFactor);
  filter->SetMaximumVolume(arguments.maximumVolume);
  filter->SetVolumeFactor(arguments.volumeFactor);
  filter->SetRadiusEdgeRatio(arguments.radiusEdgeRatio);
  filter->SetNumberOfThreads(arguments.numberOfThreads);
  filter->SetRegionArrayName(
    arguments.regionArrayName.empty() ? nullptr : arguments.regionArrayName.c_str());
  filter->SetColoringAlgorithm(
    vtkCoarseGrainedMeshAdaptation::ColoringAlgorithmFromName(arguments.coloring.c_str()));
  filter->SetPartitionByRegion(arguments.partitionByRegion);
  filter->SetPartitionsPerRegion(arguments.partitionsPerRegion);
  filter->SetImproveQuality(arguments.improveQuality);
  filter->SetNumberOfImprovementPasses(arguments.improvementPasses);
  filter->SetMaximumNumberOfCells(static_cast<vtkIdType>(arguments.maximumNumberOfCells));
}

// Draws the filter's progress as a bar on stderr; only on a terminal, so logs and pipes stay clean.
class ProgressBar : public vtkCommand
{
public:
  static ProgressBar* New() { return new ProgressBar; }
  void Execute(vtkObject*, unsigned long, void* callData) override
  {
    const double fraction = *static_cast<double*>(callData);
    const int width = 40;
    const int filled = static_cast<int>(fraction * width + 0.5);
    if (filled == this->LastFilled)
    {
      return;
    }
    this->LastFilled = filled;
    std::cerr << "\r[" << std::string(filled, '#') << std::string(width - filled, ' ') << "] "
              << static_cast<int>(100 * fraction + 0.5) << "%" << (fraction >= 1.0 ? "\n" : "")
              << std::flush;
  }

private:
  int LastFilled = -1;
};

// Runs the filter on `input`; on success `output` holds the refined grid.
Status refineGrid(
  const RefineArguments& arguments, vtkUnstructuredGrid* input, vtkUnstructuredGrid* output)
{
  vtkNew<vtkCoarseGrainedMeshAdaptation> filter;
  vtkNew<VTKMessageCollector> messages;
  messages->watch(filter);
  configureFilter(arguments, filter);
  if (::isatty(STDERR_FILENO))
  {
    vtkNew<ProgressBar> progressBar;
    filter->AddObserver(vtkCommand::ProgressEvent, progressBar);
  }
  filter->SetInputData(input);
  filter->Update();
  for (const std::string& warning : messages->warnings())
  {
    std::cerr << "cgmesh: warning: " << warning << "\n";
  }
  if (!messages->errors().empty())
  {
    return Status::failure(messages->errors().front());
  }
  output->ShallowCopy(filter->GetOutput());
  if (output->GetNumberOfCells() == 0 && input->GetNumberOfCells() > 0)
  {
    return Status::failure("the refinement produced no cells");
  }
  return Status::success();
}

// Timings and the thread count differ from run to run; they go to the table and the stats file,
// not into OUT, so that OUT is byte-identical for every thread count.
void removeRunDependentFieldData(vtkUnstructuredGrid* grid)
{
  vtkFieldData* fieldData = grid->GetFieldData();
  for (int index = fieldData->GetNumberOfArrays() - 1; index >= 0; --index)
  {
    const std::string name = fieldData->GetArrayName(index) ? fieldData->GetArrayName(index) : "";
    const std::string suffix = "Seconds";
    const bool isTiming = name.size() > suffix.size() &&
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
    if (isTiming || name == "NumberOfThreads")
      fieldData->RemoveArray(index);
  }
}

} // namespace

int runRefineCommand(const std::vector<std::string>& commandArguments)
{
  RefineArguments arguments;
  const int early =
    startCommand(commandArguments, printRefineUsage, parseRefineArguments, arguments);
  if (early >= 0)
  {
    return early;
  }
  Status status = checkOutputFileName(arguments.outputFile);
  if (!status.ok())
    return reportError(status.message());

  auto start = std::chrono::steady_clock::now();
  vtkNew<vtkUnstructuredGrid> input;
  status = readUnstructuredGrid(arguments.inputFile, input);
  if (!status.ok())
    return reportError(status.message());
  const double readSeconds = secondsSince(start);

  vtkNew<vtkUnstructuredGrid> output;
  status = refineGrid(arguments, input, output);
  if (!status.ok())
    return reportError(status.message());

  RefineStatistics statistics;
  statistics.inputFile = arguments.inputFile;
  statistics.outputFile = arguments.outputFile;
  statistics.inputPoints = input->GetNumberOfPoints();
  statistics.inputCells = input->GetNumberOfCells();
  statistics.numberOfIterations = arguments.numberOfIterations;
  statistics.partitionByRegion = arguments.partitionByRegion;
  statistics.partitionsPerRegion = arguments.partitionsPerRegion;
  statistics.improveQuality = arguments.improveQuality;
  statistics.improvementPasses = arguments.improvementPasses;
  collectFilterStatistics(output, statistics);
  removeRunDependentFieldData(output);

  start = std::chrono::steady_clock::now();
  status = writeUnstructuredGrid(output, arguments.outputFile);
  if (!status.ok())
    return reportError(status.message());
  const double writeSeconds = secondsSince(start);

  statistics.seconds.emplace_back("read", readSeconds);
  statistics.seconds.emplace_back("write", writeSeconds);
  printStatisticsTable(statistics, std::cout);
  if (!arguments.statsFile.empty())
  {
    status = writeStatisticsJson(statistics, arguments.statsFile);
    if (!status.ok())
    {
      std::remove(arguments.outputFile.c_str()); // all-or-nothing: no output without its stats
      return reportError(status.message());
    }
  }
  return 0;
}

} // namespace cgmesh
