// cgmesh refine IN OUT [options]: runs vtkCoarseGrainedMeshAdaptation on a file.
#include "Commands.h"

#include "CommandLine.h"
#include "Core/Stopwatch.h"
#include "GmshFiles.h"
#include "MeshFiles.h"
#include "RefineChecks.h"
#include "RefineReport.h"
#include "VTKMessages.h"

#include "vtkCellData.h"
#include "vtkCoarseGrainedMeshAdaptation.h"
#include "vtkCommand.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

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
    << "usage: cgmesh refine IN OUT [options]\n"
       "\n"
       "Refines the tetrahedral mesh IN and writes OUT, each a VTK (.vtu, .vtk), Gmsh (.msh),\n"
       "Medit (.mesh), Exodus II (.exo, .e, .ex2, .g, .gen) or TetGen (.ele or .node, with\n"
       ".face) file. Triangles on boundary and material-interface faces (Gmsh physical\n"
       "surfaces, Exodus side sets) are refined with those faces and keep their tags.\n"
       "Template: edges longer than the threshold are split by conforming templates.\n"
       "Delaunay: interface edges by templates, then TetGen (switches r Y q a) refines\n"
       "partition interiors with their boundary kept; a partition where TetGen fails is\n"
       "refined by templates instead (a warning names it).\n"
       "\n"
    << refineOptionsHelp()
    << "  --stats FILE.json       write counts, colour populations, Delaunay figures,\n"
       "                          improvement counts, the quality summary and phase timings\n"
       "                          as JSON\n"
    << compressionHelp()
    << "  --msh-version V         a Gmsh OUT's format: 4.1 (default) or 2.2\n"
       "\n"
       "Gmsh and Medit files are read and written by Gmsh's library. Their physical groups\n"
       "(Medit references) become the cell array Tag, their elementary entities the cell\n"
       "array Entity; an OUT of these formats takes its groups from Tag, else from meshio's\n"
       "gmsh:physical or medit:ref, else from the region array (or the default material\n"
       "labels), with the input's group names. TetGen files give Tag from the region\n"
       "attribute and the face markers. Exodus files give Tag from the element block and side\n"
       "set ids, and each node set becomes a point array (1 on its nodes), written back as a\n"
       "node set, as is any point array named NodeSet<id>. Other point data and cell arrays\n"
       "stay in VTK files.\n"
       "\n"
       "Before the input is read, OUT and FILE.json must be creatable and differ from IN and\n"
       "from each other. With the template method and several iterations, a run whose last\n"
       "iteration must exceed --max-cells is refused before the first one. A run that adds no\n"
       "point exits 0 with a warning giving the threshold and the longest edge.\n"
       "\n"
       "Improvement works on tets whose mean ratio 12 (3V)^(2/3) / sum of squared edge\n"
       "lengths (1 = regular) is below 0.5 and keeps a change only when the worst mean ratio\n"
       "rises; partition-interface, boundary and material-interface vertices stay fixed.\n"
       "The table and the stats file hold the quality of all tets, of the interior tets and of\n"
       "the tets near former partition interfaces (cell array NearFormerInterface): tet count,\n"
       "minimum and 1st percentile of MinDihedralAngle (degrees), 99th percentile of EdgeRatio.\n";
}

// Every parameter of the table, set on the filter by name.
void configureFilter(const AdaptationOptions& options, vtkCoarseGrainedMeshAdaptation* filter)
{
  for (const ParameterSpec& spec : parameterTable())
  {
    if (spec.kind == ParameterKind::Text)
      filter->SetParameterText(spec.name, textValue(spec, options).c_str());
    else
      filter->SetParameterValue(spec.name, numericValue(spec, options));
  }
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

// Runs `filter` on `input`; on success `output` holds the refined grid.
Status refineGrid(const RefineArguments& arguments, vtkCoarseGrainedMeshAdaptation* filter,
  vtkUnstructuredGrid* input, vtkUnstructuredGrid* output)
{
  vtkNew<VTKMessageCollector> messages;
  messages->watch(filter);
  configureFilter(arguments.options, filter);
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

// What can be checked on the input before refining: the region array and the size forecast.
Status checkInput(const RefineArguments& arguments, vtkUnstructuredGrid* input)
{
  const std::string& regionArray = arguments.options.regionArrayName;
  // "None" is ParaView's "no array" entry, unless the input has an array of that name.
  const bool noRegions = regionArray.empty() ||
    (regionArray == "None" && !input->GetCellData()->GetAbstractArray("None"));
  if (!noRegions)
  {
    const Status status = checkRegionArray(input, regionArray, arguments.inputFile);
    if (!status.ok())
      return status;
  }
  return checkSizeBeforeRefining(input, arguments.options);
}

RefineStatistics collectStatistics(const RefineArguments& arguments,
  vtkCoarseGrainedMeshAdaptation* filter, vtkUnstructuredGrid* input, vtkUnstructuredGrid* output)
{
  RefineStatistics statistics;
  statistics.inputFile = arguments.inputFile;
  statistics.outputFile = arguments.outputFile;
  statistics.inputPoints = input->GetNumberOfPoints();
  statistics.inputCells = input->GetNumberOfCells();
  statistics.numberOfIterations = arguments.options.numberOfIterations;
  statistics.partitionByRegion = arguments.options.partitionByRegion;
  statistics.partitionsPerRegion = arguments.options.partitionsPerRegion;
  statistics.improveQuality = arguments.options.improveQuality;
  statistics.improvementPasses = arguments.options.improvementPasses;
  statistics.compression = compressionName(arguments.compression);
  collectFilterStatistics(filter, output, statistics);
  return statistics;
}

// The cell array whose values a Gmsh or Medit OUT takes as its physical groups: Tag (read from such
// a file), meshio's names for them, the region array, else the first default material label.
std::string tagArrayOf(vtkUnstructuredGrid* output, const RefineArguments& arguments,
  vtkCoarseGrainedMeshAdaptation* filter)
{
  for (const char* name : { TagArrayName, "gmsh:physical", "medit:ref" })
  {
    if (output->GetCellData()->GetArray(name))
      return name;
  }
  if (!arguments.options.regionArrayName.empty() &&
    output->GetCellData()->GetArray(arguments.options.regionArrayName.c_str()))
    return arguments.options.regionArrayName;
  const std::string labels = filter->GetMaterialLabelArrays();
  return labels.substr(0, labels.find(','));
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
  Status status = checkCommandFiles(arguments.inputFile, arguments.outputFile, arguments.statsFile);
  if (!status.ok())
    return reportFailure(status);

  Stopwatch stopwatch;
  vtkNew<vtkUnstructuredGrid> input;
  MeshFileNames names;
  status = readUnstructuredGrid(arguments.inputFile, input, &names);
  const double readSeconds = stopwatch.lap();
  if (status.ok())
    status = checkInput(arguments, input);
  if (!status.ok())
    return reportFailure(status);

  vtkNew<vtkCoarseGrainedMeshAdaptation> filter;
  vtkNew<vtkUnstructuredGrid> output;
  status = refineGrid(arguments, filter, input, output);
  if (!status.ok())
    return reportError(inFileNumbers(status.message(), names));

  RefineStatistics statistics = collectStatistics(arguments, filter, input, output);
  const std::string nothingRefined = nothingRefinedWarning(input, arguments.options, statistics);
  if (!nothingRefined.empty())
  {
    std::cerr << "cgmesh: warning: " << nothingRefined << "\n";
    statistics.warnings.push_back({ WarningKind::NothingRefined, -1, nothingRefined });
  }
  removeRunDependentFieldData(output);

  stopwatch.lap();
  WriteOptions writeOptions;
  writeOptions.compression = arguments.compression;
  writeOptions.tagArray = tagArrayOf(output, arguments, filter);
  writeOptions.mshVersion = arguments.mshVersion;
  writeOptions.names = &names;
  status = writeUnstructuredGrid(output, arguments.outputFile, writeOptions);
  if (!status.ok())
    return reportError(status.message());
  const double writeSeconds = stopwatch.lap();

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
