// Argument parsing for the cgmesh command-line driver: typed option values with range checks and
// one-line error messages.
#ifndef cgmesh_CommandLine_h
#define cgmesh_CommandLine_h

#include "AdaptationOptions.h"
#include "Core/Status.h"
#include "MeshFiles.h"

#include <string>
#include <vector>

namespace cgmesh
{

struct RefineArguments
{
  std::string inputFile;
  std::string outputFile;
  AdaptationOptions options; // the parameter table's defaults, overridden by the options given
  std::string statsFile;     // JSON statistics, written when not empty
  Compression compression = DefaultCompression;
  double mshVersion = 4.1; // a Gmsh OUT's format: 4.1 or 2.2
};

struct GenerateArguments
{
  std::string shape;          // "cube" or "finfet"
  int cellsPerSide = 0;       // cube
  int targetCells = 837584;   // finfet: about this many tetrahedra
  bool materialNames = false; // finfet: the names as a string array in the field data
  std::string outputFile;
  Compression compression = DefaultCompression;
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
  Compression compression = DefaultCompression;
  bool tetsAlongHilbertCurve = true; // --tet-order hilbert (default) or input
};

struct CheckArguments
{
  std::string inputFile;
  std::string regionArrayName;
};

// True when the arguments ask for help (-h or --help anywhere).
bool wantsHelp(const std::vector<std::string>& arguments);

// The option lines of `cgmesh refine --help`, from the parameter table.
std::string refineOptionsHelp();

// The `--compression NAME` lines of a command's --help, with the measured write speeds.
std::string compressionHelp();

// Each parser reads the arguments after the command name.
Status parseRefineArguments(const std::vector<std::string>& arguments, RefineArguments& parsed);
Status parseGenerateArguments(const std::vector<std::string>& arguments, GenerateArguments& parsed);
Status parseTetGenArguments(const std::vector<std::string>& arguments, TetGenArguments& parsed);
Status parseCheckArguments(const std::vector<std::string>& arguments, CheckArguments& parsed);

// Strict number parsing: the whole text must be a number within [minimum, maximum].
Status parseInt(
  const std::string& text, const std::string& what, int minimum, int maximum, int& value);
Status parseDouble(const std::string& text, const std::string& what, double minimum, double& value);
// As parseDouble, but the number must be greater than 0.
Status parsePositiveDouble(const std::string& text, const std::string& what, double& value);
// Strict parsing of a 64-bit count: the whole text must be an integer >= minimum.
Status parseCount(
  const std::string& text, const std::string& what, long long minimum, long long& value);

} // namespace cgmesh

#endif
