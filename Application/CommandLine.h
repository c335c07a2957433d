// Argument parsing for the cgmesh command-line driver: typed option values with range checks and
// one-line error messages.
#ifndef cgmesh_CommandLine_h
#define cgmesh_CommandLine_h

#include "Core/Status.h"

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
  std::string method = "template"; // a vtkCoarseGrainedMeshAdaptation method name
  double maximumEdgeLength = 0;    // template: used when > 0
  double edgeLengthFactor = 0.5;   // template: fraction of the input's mean edge length
  double maximumVolume = 0;        // delaunay: used when > 0
  double volumeFactor = 0.1;       // delaunay: fraction of the input's mean tet volume
  double radiusEdgeRatio = 2.0;    // delaunay: TetGen's q
  int numberOfThreads = 0;         // 0 = all cores
  std::string regionArrayName;
  std::string coloring = "greedy-lu";         // a vtkCoarseGrainedMeshAdaptation colouring name
  bool partitionByRegion = false;             // cut along the regions of regionArrayName
  int partitionsPerRegion = 1;                // with partitionByRegion
  bool improveQuality = true;                 // --no-improve turns it off
  int improvementPasses = 2;                  // --improve-passes, in [0, 20]
  long long maximumNumberOfCells = 100000000; // --max-cells, 0 = no limit
  std::string statsFile;                      // JSON statistics, written when not empty
};

struct GenerateArguments
{
  std::string shape;        // "cube" or "finfet"
  int cellsPerSide = 0;     // cube
  int targetCells = 837584; // finfet: about this many tetrahedra
  std::string outputFile;
};

// cgmesh tetgen: serial TetGen on the whole mesh, the baseline of the Delaunay method.
struct TetGenArguments
{
  std::string inputFile;
  std::string outputFile;
  double maximumVolume = 0; // required, > 0
  double radiusEdgeRatio = 2.0;
  std::string regionArrayName;
  std::string statsFile; // JSON statistics, written when not empty
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
Status parseTetGenArguments(const std::vector<std::string>& arguments, TetGenArguments& parsed);
Status parseCheckArguments(const std::vector<std::string>& arguments, CheckArguments& parsed);

// Strict number parsing: the whole text must be a number within [minimum, maximum].
Status parseInt(
  const std::string& text, const std::string& what, int minimum, int maximum, int& value);
Status parseDouble(const std::string& text, const std::string& what, double minimum, double& value);
// Strict parsing of a 64-bit count: the whole text must be an integer >= minimum.
Status parseCount(
  const std::string& text, const std::string& what, long long minimum, long long& value);

} // namespace cgmesh

#endif
