// cgmesh tetgen IN OUT --max-volume V [...]: serial TetGen refining the whole mesh in one call, the
// baseline the Delaunay method is measured against.
#include "Commands.h"
#include "Core/HilbertCurve.h"
#include "Core/Stopwatch.h"

#include "CommandLine.h"
#include "MeshFiles.h"
#include "RefineReport.h"
#include "WorkerPool.h"
#include "cgmeshTetQuality.h"
#include "cgmeshVTKConversion.h"

#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

#define TETLIBRARY
#include <tetgen.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <numeric>

namespace cgmesh
{

namespace
{

void printTetGenUsage()
{
  std::cout
    << "usage: cgmesh tetgen IN OUT --max-volume V [--radius-edge-ratio Q]\n"
       "                     [--region-array NAME] [--stats FILE.json] [--compression NAME]\n"
       "\n"
       "Refines the whole tetrahedral mesh IN (.vtu or .vtk) with one serial TetGen call and\n"
       "writes OUT: the baseline of 'cgmesh refine --method delaunay'. TetGen runs with the\n"
       "switches rQq<Q>a<V>: refine the given mesh, quality bound Q, volume bound V, and no Y,\n"
       "so TetGen may split boundary faces as a plain TetGen user would let it. Region ids are\n"
       "passed as tetrahedron attributes and written back to the region array. TetGen runs in\n"
       "a worker process, so a TetGen abort is an error message, not a crash. OUT holds the\n"
       "points, the tetrahedra, the region array and the cell arrays EdgeRatio and\n"
       "MinDihedralAngle (degrees); other input arrays are not carried over.\n"
       "\n"
       "  --max-volume V          TetGen volume bound (switch a), required, > 0\n"
       "  --radius-edge-ratio Q   TetGen radius-edge quality bound (switch q), >= 1 (default 2)\n"
       "  --region-array NAME     cell array with material/region ids\n"
       "  --stats FILE.json       write counts and seconds (tetgen, quality, read, write,\n"
       "                          total) as JSON\n"
       "  --tet-order ORDER       the order TetGen receives the tets in: 'hilbert' (default),\n"
       "                          along a Hilbert curve through their centroids, or 'input',\n"
       "                          as in IN (what 'tetgen -r' on IN's files does). TetGen builds\n"
       "                          its face links faster when neighbours come close together:\n"
       "                          3.9 s instead of 6.9 s on the FinFET of 'generate finfet'\n"
    << compressionHelp();
}

std::string tetgenSwitches(const TetGenArguments& arguments)
{
  // r: refine the given mesh; Q: quiet; q: radius-edge bound; a: volume bound.
  char switches[128];
  std::snprintf(switches, sizeof(switches), "rQq%.17ga%.17g", arguments.radiusEdgeRatio,
    arguments.maximumVolume);
  return switches;
}

// TetGen input of the whole mesh; regions, when present, become the one tet attribute. The tets
// go in the input's order or along a Hilbert curve.
void fillTetGenInput(const TetMesh& mesh, bool alongHilbertCurve, tetgenio& in)
{
  std::vector<std::size_t> order(mesh.tets.size());
  std::iota(order.begin(), order.end(), std::size_t{ 0 });
  if (alongHilbertCurve)
  {
    order = tetsAlongHilbertCurve(mesh.tets, [&mesh](PointId p) { return mesh.point(p); });
  }
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(mesh.numberOfPoints());
  in.pointlist = new REAL[mesh.coordinates.size()];
  std::copy(mesh.coordinates.begin(), mesh.coordinates.end(), in.pointlist);
  in.numberofcorners = 4;
  in.numberoftetrahedra = static_cast<int>(mesh.numberOfTets());
  in.tetrahedronlist = new int[4 * mesh.tets.size()];
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
  {
    std::copy(mesh.tets[order[t]].begin(), mesh.tets[order[t]].end(), in.tetrahedronlist + 4 * t);
  }
  if (mesh.hasRegions())
  {
    in.numberoftetrahedronattributes = 1;
    in.tetrahedronattributelist = new REAL[mesh.regions.size()];
    for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    {
      in.tetrahedronattributelist[t] = mesh.regions[order[t]];
    }
  }
}

Status readTetGenOutput(const tetgenio& out, bool withRegions, TetMesh& mesh)
{
  if (out.numberofcorners != 4 || out.firstnumber != 0 || out.numberoftetrahedra < 1 ||
    (withRegions && out.numberoftetrahedronattributes < 1))
  {
    return Status::failure("TetGen returned an incomplete mesh");
  }
  mesh = TetMesh();
  mesh.coordinates.assign(out.pointlist, out.pointlist + 3 * out.numberofpoints);
  mesh.tets.resize(static_cast<std::size_t>(out.numberoftetrahedra));
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
  {
    std::copy_n(out.tetrahedronlist + 4 * t, 4, mesh.tets[t].begin());
  }
  if (withRegions)
  {
    const int stride = out.numberoftetrahedronattributes;
    mesh.regions.resize(mesh.tets.size());
    for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    {
      mesh.regions[t] = static_cast<int>(std::lround(out.tetrahedronattributelist[stride * t]));
    }
  }
  return Status::success();
}

struct TetGenRun
{
  std::int64_t inputPoints = 0;
  std::int64_t inputCells = 0;
  std::string switches;
  double readSeconds = 0;
  double tetgenSeconds = 0; // conversions in and out included
  double qualitySeconds = 0;
  double writeSeconds = 0;
  double totalSeconds = 0;
};

// Converts `input`, runs TetGen on it in a worker process and puts the result into `output`.
Status runTetGen(const TetGenArguments& arguments, vtkUnstructuredGrid* input,
  vtkUnstructuredGrid* output, TetGenRun& run)
{
  const Stopwatch stopwatch;
  TetMesh mesh;
  Status status = convertToTetMesh(input, arguments.regionArrayName, mesh);
  if (!status.ok())
    return status;
  tetgenio in, out;
  fillTetGenInput(mesh, arguments.tetsAlongHilbertCurve, in);
  const bool withRegions = mesh.hasRegions();
  mesh = TetMesh();
  WorkerPool worker(1);
  const std::string failure = worker.runTetGen(0, in, run.switches, out);
  if (!failure.empty())
    return Status::failure("TetGen failed: " + failure);
  status = readTetGenOutput(out, withRegions, mesh);
  if (!status.ok())
    return status;
  convertToUnstructuredGrid(std::move(mesh), output, arguments.regionArrayName);
  run.tetgenSeconds = stopwatch.seconds();
  return Status::success();
}

Status writeTetGenStatistics(
  const TetGenArguments& arguments, vtkUnstructuredGrid* output, const TetGenRun& run)
{
  std::ofstream file(arguments.statsFile);
  file << std::setprecision(17) << "{\n"
       << "  \"input\": {\"file\": " << jsonString(arguments.inputFile)
       << ", \"points\": " << run.inputPoints << ", \"cells\": " << run.inputCells << "},\n"
       << "  \"output\": {\"file\": " << jsonString(arguments.outputFile)
       << ", \"points\": " << output->GetNumberOfPoints()
       << ", \"cells\": " << output->GetNumberOfCells() << "},\n"
       << "  \"method\": \"tetgen\",\n"
       << "  \"switches\": " << jsonString(run.switches) << ",\n"
       << "  \"tetOrder\": \"" << (arguments.tetsAlongHilbertCurve ? "hilbert" : "input") << "\",\n"
       << "  \"volumeBound\": " << arguments.maximumVolume << ",\n"
       << "  \"radiusEdgeRatio\": " << arguments.radiusEdgeRatio << ",\n"
       << "  \"tetgenPoints\": " << output->GetNumberOfPoints() - run.inputPoints << ",\n"
       << "  \"seconds\": {\"tetgen\": " << run.tetgenSeconds
       << ", \"quality\": " << run.qualitySeconds << ", \"read\": " << run.readSeconds
       << ", \"write\": " << run.writeSeconds << ", \"total\": " << run.totalSeconds << "}\n"
       << "}\n";
  file.close();
  if (!file)
    return Status::failure("cannot write statistics file '" + arguments.statsFile + "'");
  return Status::success();
}

void printTetGenTable(vtkUnstructuredGrid* output, const TetGenRun& run, std::ostream& stream)
{
  stream << std::left << std::setw(24) << "input points" << run.inputPoints << "\n"
         << std::setw(24) << "input cells" << run.inputCells << "\n"
         << std::setw(24) << "output points" << output->GetNumberOfPoints() << "\n"
         << std::setw(24) << "output cells" << output->GetNumberOfCells() << "\n"
         << std::setw(24) << "switches" << run.switches << "\n\n"
         << std::setw(24) << "phase"
         << "seconds\n"
         << std::fixed << std::setprecision(4) << std::setw(24) << "read" << run.readSeconds << "\n"
         << std::setw(24) << "tetgen" << run.tetgenSeconds << "\n"
         << std::setw(24) << "quality" << run.qualitySeconds << "\n"
         << std::setw(24) << "write" << run.writeSeconds << "\n"
         << std::setw(24) << "total" << run.totalSeconds << "\n"
         << std::defaultfloat << std::right;
}

} // namespace

int runTetGenCommand(const std::vector<std::string>& commandArguments)
{
  TetGenArguments arguments;
  const int early =
    startCommand(commandArguments, printTetGenUsage, parseTetGenArguments, arguments);
  if (early >= 0)
  {
    return early;
  }
  Status status = checkCommandFiles(arguments.inputFile, arguments.outputFile, arguments.statsFile);
  if (!status.ok())
    return reportFailure(status);

  const Stopwatch stopwatch;
  vtkNew<vtkUnstructuredGrid> input;
  status = readUnstructuredGrid(arguments.inputFile, input);
  if (status.ok() && !arguments.regionArrayName.empty())
    status = checkRegionArray(input, arguments.regionArrayName, arguments.inputFile);
  if (!status.ok())
    return reportError(status.message());
  const vtkIdType nonTetrahedra = countNonTetrahedra(input);
  if (nonTetrahedra > 0)
    return reportError(std::to_string(nonTetrahedra) + " cells are not linear tetrahedra");
  TetGenRun run;
  run.readSeconds = stopwatch.seconds();
  run.inputPoints = input->GetNumberOfPoints();
  run.inputCells = input->GetNumberOfCells();
  run.switches = tetgenSwitches(arguments);

  vtkNew<vtkUnstructuredGrid> output;
  status = runTetGen(arguments, input, output, run);
  if (!status.ok())
    return reportError(status.message());
  const Stopwatch qualityStopwatch;
  status = addTetQualityArrays(output, 0);
  if (!status.ok())
    return reportError(status.message());
  run.qualitySeconds = qualityStopwatch.seconds();

  const Stopwatch writeStopwatch;
  status = writeUnstructuredGrid(output, arguments.outputFile, arguments.compression);
  if (!status.ok())
    return reportError(status.message());
  run.writeSeconds = writeStopwatch.seconds();
  run.totalSeconds = stopwatch.seconds();

  printTetGenTable(output, run, std::cout);
  if (!arguments.statsFile.empty())
  {
    status = writeTetGenStatistics(arguments, output, run);
    if (!status.ok())
    {
      std::remove(arguments.outputFile.c_str()); // all-or-nothing: no output without its stats
      return reportError(status.message());
    }
  }
  return 0;
}

} // namespace cgmesh
