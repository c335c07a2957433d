#include "CommandLine.h"

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>

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

// The refine options that take no value (Boolean parameters); they are stored with an empty value.
std::set<std::string> refineFlags()
{
  std::set<std::string> flags;
  for (const ParameterSpec& spec : parameterTable())
  {
    if (spec.kind == ParameterKind::Boolean)
    {
      flags.insert(spec.flag);
    }
  }
  return flags;
}

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

// A Choice value by name; the error lists the names.
Status parseChoice(const ParameterSpec& spec, const std::string& text, double& index)
{
  const int found = choiceIndex(spec, text);
  if (found >= 0)
  {
    index = found;
    return Status::success();
  }
  std::string names;
  for (const ParameterChoice& choice : spec.choices)
  {
    names += std::string(names.empty() ? "" : ", ") + choice.name;
  }
  const std::string what = std::string(spec.name) == "Method" ? "method" : "colouring";
  return Status::failure(
    "unknown " + what + " '" + text + "' for " + spec.flag + " (use " + names + ")");
}

// Each method's size options are an error with the other method, rather than silently unused.
Status checkMethodOptions(const std::map<std::string, std::string>& options)
{
  const auto method = options.find("--method");
  const bool delaunay = method != options.end() && method->second == "delaunay";
  for (const ParameterSpec& spec : parameterTable())
  {
    const MethodScope other = delaunay ? MethodScope::Template : MethodScope::Delaunay;
    if (spec.scope == other && options.count(spec.flag))
      return Status::failure(
        std::string(spec.flag) + " needs --method " + (delaunay ? "template" : "delaunay"));
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

// Parses one parameter's value by its kind and range and stores it in `options`.
Status applyParameter(
  const ParameterSpec& spec, const std::string& value, AdaptationOptions& options)
{
  Status status = Status::success();
  double number = 0;
  switch (spec.kind)
  {
    case ParameterKind::Integer:
    {
      int parsed = 0;
      status = parseInt(
        value, spec.flag, static_cast<int>(spec.minimum), static_cast<int>(spec.maximum), parsed);
      number = parsed;
      break;
    }
    case ParameterKind::Count:
    {
      long long parsed = 0;
      status = parseCount(value, spec.flag, static_cast<long long>(spec.minimum), parsed);
      number = static_cast<double>(parsed);
      break;
    }
    case ParameterKind::Real:
      status = parseDouble(value, spec.flag, spec.minimum, number);
      break;
    case ParameterKind::Boolean: // the flag flips the default
      number = spec.defaultValue != 0 ? 0 : 1;
      break;
    case ParameterKind::Choice:
      status = parseChoice(spec, value, number);
      break;
    case ParameterKind::Text:
      setTextValue(spec, value, options);
      return Status::success();
  }
  if (status.ok())
  {
    setNumericValue(spec, number, options);
  }
  return status;
}

Status applyRefineOption(const std::string& name, const std::string& value, RefineArguments& parsed)
{
  if (name == "--stats")
  {
    parsed.statsFile = value;
    return Status::success();
  }
  const ParameterSpec* spec = findParameterByFlag(name);
  if (!spec)
    return Status::failure("unknown option " + name + " (see --help)");
  return applyParameter(*spec, value, parsed.options);
}

} // namespace

Status parseRefineArguments(const std::vector<std::string>& arguments, RefineArguments& parsed)
{
  std::vector<std::string> positionals;
  std::map<std::string, std::string> options;
  Status status = splitArguments(arguments, positionals, options, refineFlags());
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

namespace
{

// `text` wrapped to lines of at most `width` characters, each after `indent` spaces.
std::string wrapped(const std::string& text, std::size_t indent, std::size_t width)
{
  std::istringstream words(text);
  std::string word, line, result;
  while (words >> word)
  {
    if (!line.empty() && indent + line.size() + 1 + word.size() > width)
    {
      result += std::string(indent, ' ') + line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty())
    result += std::string(indent, ' ') + line + "\n";
  return result;
}

std::string defaultText(const ParameterSpec& spec)
{
  const AdaptationOptions defaults;
  if (spec.kind == ParameterKind::Boolean || spec.kind == ParameterKind::Text)
    return "";
  if (spec.kind == ParameterKind::Choice)
    return " (default " + textValue(spec, defaults) + ")";
  std::ostringstream text;
  text << std::setprecision(15) << numericValue(spec, defaults);
  return " (default " + text.str() + ")";
}

} // namespace

std::string refineOptionsHelp()
{
  constexpr std::size_t Column = 26;
  constexpr std::size_t Width = 92;
  std::string help;
  for (const ParameterSpec& spec : parameterTable())
  {
    std::string head = "  " + std::string(spec.flag);
    if (spec.valueName[0] != '\0')
      head += " " + std::string(spec.valueName);
    std::string text = spec.help;
    if (spec.scope != MethodScope::Any)
      text =
        std::string(spec.scope == MethodScope::Template ? "template" : "delaunay") + ": " + text;
    if (spec.kind == ParameterKind::Integer || spec.kind == ParameterKind::Real ||
      spec.kind == ParameterKind::Count)
      text += ", " + rangeText(spec);
    text += defaultText(spec);
    std::string body = wrapped(text, Column, Width);
    if (head.size() + 1 < Column)
      body = head + std::string(Column - head.size(), ' ') + body.substr(Column);
    else
      body = head + "\n" + body;
    help += body;
    for (const ParameterChoice& choice : spec.choices)
    {
      std::string name = std::string(Column + 2, ' ') + choice.name;
      name.resize(std::max(name.size() + 2, Column + 14), ' ');
      help += name + choice.description + "\n";
    }
  }
  return help;
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
