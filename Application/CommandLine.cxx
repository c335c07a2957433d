#include "CommandLine.h"

#include "vtkCoarseGrainedMeshAdaptation.h"

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>

namespace cgmesh
{

bool wantsHelp(const std::vector<std::string>& arguments)
{
  for (const std::string& argument : arguments)
  {
    if (argument == "-h" || argument == "--help")
    {
      return true;
    }
  }
  return false;
}

Status parseInt(
  const std::string& text, const std::string& what, int minimum, int maximum, int& value)
{
  errno = 0;
  char* end = nullptr;
  const long parsed = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno == ERANGE || parsed < minimum || parsed > maximum)
  {
    return Status::failure(what + " must be an integer in [" + std::to_string(minimum) + ", " +
      std::to_string(maximum) + "], got '" + text + "'");
  }
  value = static_cast<int>(parsed);
  return Status::success();
}

Status parseDouble(const std::string& text, const std::string& what, double minimum, double& value)
{
  errno = 0;
  char* end = nullptr;
  const double parsed = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(parsed) || parsed < minimum)
  {
    return Status::failure(
      what + " must be a number >= " + std::to_string(minimum) + ", got '" + text + "'");
  }
  value = parsed;
  return Status::success();
}

Status parseCount(
  const std::string& text, const std::string& what, long long minimum, long long& value)
{
  errno = 0;
  char* end = nullptr;
  const long long parsed = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno == ERANGE || parsed < minimum)
  {
    return Status::failure(
      what + " must be an integer >= " + std::to_string(minimum) + ", got '" + text + "'");
  }
  value = parsed;
  return Status::success();
}

namespace
{

// Options that take no value; they are stored with an empty value.
const std::set<std::string> RefineFlags = { "--partition-by-region", "--no-improve" };

// Splits arguments into positionals, "--name value" / "--name=value" options and the value-less
// `flags`.
Status splitArguments(const std::vector<std::string>& arguments,
  std::vector<std::string>& positionals, std::map<std::string, std::string>& options,
  const std::set<std::string>& flags = {})
{
  for (size_t index = 0; index < arguments.size(); ++index)
  {
    const std::string& argument = arguments[index];
    if (argument.rfind("--", 0) != 0)
    {
      positionals.push_back(argument);
      continue;
    }
    std::string name = argument;
    std::string value;
    const size_t equals = argument.find('=');
    if (flags.count(argument.substr(0, equals)))
    {
      if (equals != std::string::npos)
        return Status::failure("option " + argument.substr(0, equals) + " takes no value");
    }
    else if (equals != std::string::npos)
    {
      name = argument.substr(0, equals);
      value = argument.substr(equals + 1);
    }
    else if (index + 1 < arguments.size())
    {
      value = arguments[++index];
    }
    else
    {
      return Status::failure("option " + name + " needs a value");
    }
    if (options.count(name))
    {
      return Status::failure("option " + name + " given twice");
    }
    options[name] = value;
  }
  return Status::success();
}

Status checkPositionalCount(
  const std::vector<std::string>& positionals, size_t expected, const std::string& usage)
{
  if (positionals.size() != expected)
  {
    return Status::failure("expected " + usage + " (see --help)");
  }
  return Status::success();
}

Status parseColoringName(const std::string& text, std::string& coloring)
{
  if (vtkCoarseGrainedMeshAdaptation::ColoringAlgorithmFromName(text.c_str()) >= 0)
  {
    coloring = text;
    return Status::success();
  }
  std::string knownNames;
  for (int algorithm = vtkCoarseGrainedMeshAdaptation::GREEDY;
       algorithm <= vtkCoarseGrainedMeshAdaptation::RECOLORING; ++algorithm)
  {
    knownNames += std::string(knownNames.empty() ? "" : ", ") +
      vtkCoarseGrainedMeshAdaptation::ColoringAlgorithmToName(algorithm);
  }
  return Status::failure(
    "unknown colouring '" + text + "' for --coloring (use " + knownNames + ")");
}

Status parseMethodName(const std::string& text, std::string& method)
{
  if (vtkCoarseGrainedMeshAdaptation::MethodFromName(text.c_str()) < 0)
    return Status::failure("unknown method '" + text + "' for --method (use template, delaunay)");
  method = text;
  return Status::success();
}

// Each method's size options are an error with the other method, rather than silently unused.
Status checkMethodOptions(const std::map<std::string, std::string>& options)
{
  const auto method = options.find("--method");
  const bool delaunay = method != options.end() && method->second == "delaunay";
  const std::vector<const char*> templateOptions = { "--max-edge-length", "--edge-length-factor" };
  const std::vector<const char*> delaunayOptions = { "--max-volume", "--volume-factor",
    "--radius-edge-ratio" };
  for (const char* name : delaunay ? templateOptions : delaunayOptions)
  {
    if (options.count(name))
      return Status::failure(
        std::string(name) + " needs --method " + (delaunay ? "template" : "delaunay"));
  }
  if (options.count("--max-volume") && options.count("--volume-factor"))
    return Status::failure("give either --max-volume or --volume-factor, not both");
  return Status::success();
}

// Options that only make sense together, or that exclude each other.
Status checkRefineOptionCombinations(const std::map<std::string, std::string>& options)
{
  if (options.count("--max-edge-length") && options.count("--edge-length-factor"))
    return Status::failure("give either --max-edge-length or --edge-length-factor, not both");
  const Status methodStatus = checkMethodOptions(options);
  if (!methodStatus.ok())
    return methodStatus;
  const bool byRegion = options.count("--partition-by-region") > 0;
  if (byRegion && options.count("--partitions"))
    return Status::failure("give either --partitions or --partition-by-region, not both");
  if (options.count("--partitions-per-region") && !byRegion)
    return Status::failure("--partitions-per-region needs --partition-by-region");
  if (byRegion && !options.count("--region-array"))
    return Status::failure("--partition-by-region needs --region-array NAME");
  if (options.count("--no-improve") && options.count("--improve-passes"))
    return Status::failure("give either --no-improve or --improve-passes, not both");
  return Status::success();
}

Status applyRefineOption(const std::string& name, const std::string& value, RefineArguments& parsed)
{
  if (name == "--partitions")
    return parseInt(value, name, 1, INT_MAX, parsed.numberOfPartitions);
  if (name == "--iterations")
    return parseInt(value, name, 1, INT_MAX, parsed.numberOfIterations);
  if (name == "--method")
    return parseMethodName(value, parsed.method);
  if (name == "--max-edge-length")
    return parseDouble(value, name, 0.0, parsed.maximumEdgeLength);
  if (name == "--edge-length-factor")
    return parseDouble(value, name, 0.0, parsed.edgeLengthFactor);
  if (name == "--max-volume")
    return parseDouble(value, name, 0.0, parsed.maximumVolume);
  if (name == "--volume-factor")
    return parseDouble(value, name, 0.0, parsed.volumeFactor);
  if (name == "--radius-edge-ratio")
    return parseDouble(value, name, 1.0, parsed.radiusEdgeRatio);
  if (name == "--threads")
    return parseInt(value, name, 0, INT_MAX, parsed.numberOfThreads);
  if (name == "--region-array")
  {
    parsed.regionArrayName = value;
    return Status::success();
  }
  if (name == "--coloring")
    return parseColoringName(value, parsed.coloring);
  if (name == "--partition-by-region")
  {
    parsed.partitionByRegion = true;
    return Status::success();
  }
  if (name == "--partitions-per-region")
    return parseInt(value, name, 1, INT_MAX, parsed.partitionsPerRegion);
  if (name == "--no-improve")
  {
    parsed.improveQuality = false;
    return Status::success();
  }
  if (name == "--improve-passes")
    return parseInt(value, name, 0, 20, parsed.improvementPasses);
  if (name == "--max-cells")
    return parseCount(value, name, 0, parsed.maximumNumberOfCells);
  if (name == "--stats")
  {
    parsed.statsFile = value;
    return Status::success();
  }
  return Status::failure("unknown option " + name + " (see --help)");
}

} // namespace

Status parseRefineArguments(const std::vector<std::string>& arguments, RefineArguments& parsed)
{
  std::vector<std::string> positionals;
  std::map<std::string, std::string> options;
  Status status = splitArguments(arguments, positionals, options, RefineFlags);
  if (!status.ok())
    return status;
  status = checkPositionalCount(positionals, 2, "IN and OUT");
  if (!status.ok())
    return status;
  parsed.inputFile = positionals[0];
  parsed.outputFile = positionals[1];
  status = checkRefineOptionCombinations(options);
  if (!status.ok())
    return status;
  for (const auto& option : options)
  {
    status = applyRefineOption(option.first, option.second, parsed);
    if (!status.ok())
      return status;
  }
  return Status::success();
}

Status parseGenerateArguments(const std::vector<std::string>& arguments, GenerateArguments& parsed)
{
  std::vector<std::string> positionals;
  std::map<std::string, std::string> options;
  Status status = splitArguments(arguments, positionals, options);
  if (!status.ok())
    return status;
  if (positionals.empty())
    return Status::failure("expected 'cube N OUT.vtu', 'finfet OUT.vtu [--cells N]' or "
                           "'finfet-grid OUT.vtu [--cells N]'");
  parsed.shape = positionals[0];
  if (parsed.shape == "cube")
  {
    if (!options.empty())
      return Status::failure("unknown option " + options.begin()->first + " (see --help)");
    status = checkPositionalCount(positionals, 3, "cube N OUT.vtu");
    if (!status.ok())
      return status;
    parsed.outputFile = positionals[2];
    return parseInt(positionals[1], "N", 1, 1000, parsed.cellsPerSide);
  }
  if (parsed.shape == "finfet" || parsed.shape == "finfet-grid")
  {
    status = checkPositionalCount(positionals, 2, parsed.shape + " OUT.vtu [--cells N]");
    if (!status.ok())
      return status;
    parsed.outputFile = positionals[1];
    for (const auto& option : options)
    {
      if (option.first != "--cells")
        return Status::failure("unknown option " + option.first + " (see --help)");
      status = parseInt(option.second, "--cells", 1000, 500000000, parsed.targetCells);
      if (!status.ok())
        return status;
    }
    return Status::success();
  }
  return Status::failure(
    "unknown shape '" + parsed.shape + "' (use 'cube', 'finfet' or 'finfet-grid')");
}

Status parseTetGenArguments(const std::vector<std::string>& arguments, TetGenArguments& parsed)
{
  std::vector<std::string> positionals;
  std::map<std::string, std::string> options;
  Status status = splitArguments(arguments, positionals, options);
  if (!status.ok())
    return status;
  status = checkPositionalCount(positionals, 2, "IN and OUT");
  if (!status.ok())
    return status;
  parsed.inputFile = positionals[0];
  parsed.outputFile = positionals[1];
  if (!options.count("--max-volume"))
    return Status::failure("--max-volume V is required");
  for (const auto& option : options)
  {
    const std::string& name = option.first;
    if (name == "--max-volume")
      status = parseDouble(option.second, name, 0.0, parsed.maximumVolume);
    else if (name == "--radius-edge-ratio")
      status = parseDouble(option.second, name, 1.0, parsed.radiusEdgeRatio);
    else if (name == "--region-array")
      parsed.regionArrayName = option.second;
    else if (name == "--stats")
      parsed.statsFile = option.second;
    else
      status = Status::failure("unknown option " + name + " (see --help)");
    if (!status.ok())
      return status;
  }
  if (parsed.maximumVolume <= 0)
    return Status::failure("--max-volume must be positive");
  return Status::success();
}

Status parseCheckArguments(const std::vector<std::string>& arguments, CheckArguments& parsed)
{
  std::vector<std::string> positionals;
  std::map<std::string, std::string> options;
  Status status = splitArguments(arguments, positionals, options);
  if (!status.ok())
    return status;
  status = checkPositionalCount(positionals, 1, "IN");
  if (!status.ok())
    return status;
  parsed.inputFile = positionals[0];
  for (const auto& option : options)
  {
    if (option.first != "--region-array")
      return Status::failure("unknown option " + option.first + " (see --help)");
    parsed.regionArrayName = option.second;
  }
  return Status::success();
}

} // namespace cgmesh
