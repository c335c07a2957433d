// Argument parsing for the cgmesh command-line driver: typed option values with range checks and
// one-line error messages.
#ifndef cgmesh_CommandLine_h
#define cgmesh_CommandLine_h

#include "Status.h"

#include <string>
#include <vector>

namespace cgmesh
{

struct RefineArguments
{
  std::string inputFile;
  std::string outputFile;
  int numberOfPartitions = 1024;
  int numberOfIterations = 1;
  double maximumEdgeLength = 0;  // used when > 0
  double edgeLengthFactor = 0.5; // fraction of the input's mean edge length
  int numberOfThreads = 0;       // 0 = all cores
  std::string regionArrayName;
  std::string coloring = "greedy-lu"; // a vtkCoarseGrainedMeshAdaptation colouring name
  bool partitionByRegion = false;     // cut along the regions of regionArrayName
  int partitionsPerRegion = 1;        // with partitionByRegion
  std::string statsFile;              // JSON statistics, written when not empty
};

struct GenerateArguments
{
  std::string shape;        // "cube" or "finfet"
  int cellsPerSide = 0;     // cube
  int targetCells = 837584; // finfet: about this many tetrahedra
  std::string outputFile;
};

struct CheckArguments
{
  std::string inputFile;
  std::string regionArrayName;
};

// True when the arguments ask for help (-h or --help anywhere).
bool wantsHelp(const std::vector<std::string>& arguments);

// Each parser reads the arguments after the command name.
Status parseRefineArguments(const std::vector<std::string>& arguments, RefineArguments& parsed);
Status parseGenerateArguments(const std::vector<std::string>& arguments, GenerateArguments& parsed);
Status parseCheckArguments(const std::vector<std::string>& arguments, CheckArguments& parsed);

// Strict number parsing: the whole text must be a number within [minimum, maximum].
Status parseInt(
  const std::string& text, const std::string& what, int minimum, int maximum, int& value);
Status parseDouble(const std::string& text, const std::string& what, double minimum, double& value);

} // namespace cgmesh

#endif
