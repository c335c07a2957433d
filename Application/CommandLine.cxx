#include "CommandLine.h"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <filesystem>
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

namespace
{

// A finite number spelling the whole text.
bool readNumber(const std::string& text, double& value)
{
  errno = 0;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return !text.empty() && *end == '\0' && errno != ERANGE && std::isfinite(value);
}

// "0.5", not std::to_string's "0.500000".
std::string numberText(double value)
{
  std::ostringstream text;
  text << value;
  return text.str();
}

} // namespace

Status parseDouble(const std::string& text, const std::string& what, double minimum, double& value)
{
  double parsed = 0;
  if (!readNumber(text, parsed) || parsed < minimum)
  {
    return Status::failure(
      what + " must be a number >= " + numberText(minimum) + ", got '" + text + "'");
  }
  value = parsed;
  return Status::success();
}

Status parsePositiveDouble(const std::string& text, const std::string& what, double& value)
{
  double parsed = 0;
  if (!readNumber(text, parsed) || !(parsed > 0))
  {
    return Status::failure(what + " must be a number > 0, got '" + text + "'");
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

// The options a command knows: those that take a value and the value-less flags.
struct OptionNames
{
  std::set<std::string> withValue;
  std::set<std::string> flags;

  bool knows(const std::string& name) const { return withValue.count(name) || flags.count(name); }
};

// Every option of `cgmesh refine`: the parameter table's (Boolean parameters are flags), --stats
// and --compression.
OptionNames refineOptionNames()
{
  OptionNames names{ { "--stats", "--compression", "--msh-version" }, {} };
  for (const ParameterSpec& spec : parameterTable())
  {
    (spec.kind == ParameterKind::Boolean ? names.flags : names.withValue).insert(spec.flag);
  }
  return names;
}

// An option rather than a positional argument: a dash and more, but not a (negative) number.
bool looksLikeOption(const std::string& argument)
{
  double number = 0;
  return argument.size() > 1 && argument[0] == '-' && !readNumber(argument, number);
}

// Edits (insertions, deletions, substitutions) that turn `from` into `to`.
std::size_t editDistance(const std::string& from, const std::string& to)
{
  std::vector<std::size_t> previous(to.size() + 1), current(to.size() + 1);
  for (std::size_t j = 0; j <= to.size(); ++j)
    previous[j] = j;
  for (std::size_t i = 1; i <= from.size(); ++i)
  {
    current[0] = i;
    for (std::size_t j = 1; j <= to.size(); ++j)
    {
      const std::size_t substitution = previous[j - 1] + (from[i - 1] == to[j - 1] ? 0 : 1);
      current[j] = std::min({ previous[j] + 1, current[j - 1] + 1, substitution });
    }
    std::swap(previous, current);
  }
  return previous[to.size()];
}

// The known options that score lowest, when there is one; `score` says how far a candidate is.
template <typename Score>
std::string uniqueBest(const OptionNames& known, std::size_t limit, Score score)
{
  std::size_t best = limit + 1;
  std::vector<std::string> closest;
  for (const auto* names : { &known.withValue, &known.flags })
  {
    for (const std::string& candidate : *names)
    {
      const std::size_t value = score(candidate);
      if (value < best)
        closest.clear();
      if (value <= best)
      {
        best = value;
        closest.push_back(candidate);
      }
    }
  }
  return closest.size() == 1 && best <= limit ? closest.front() : std::string();
}

// The option a mistyped `name` most likely meant: the one fewest edits away (at most 1 + a
// quarter of the length), else the one sharing the longest start (at least "--" and four more).
std::string likelyOption(const std::string& name, const OptionNames& known)
{
  const std::string near = uniqueBest(known, 1 + name.size() / 4,
    [&name](const std::string& candidate) { return editDistance(name, candidate); });
  if (!near.empty())
    return near;
  // Scored as Longest - shared, so that the longest shared start scores lowest.
  constexpr std::size_t MinimumShared = 6, Longest = 1000;
  return uniqueBest(known, Longest - MinimumShared,
    [&](const std::string& candidate)
    {
      const auto mismatch =
        std::mismatch(name.begin(), name.end(), candidate.begin(), candidate.end());
      return Longest - std::min<std::size_t>(Longest, mismatch.first - name.begin());
    });
}

// "unknown option '--no-improv' (did you mean '--no-improve'?)".
Status unknownOption(const std::string& name, const OptionNames& known)
{
  const std::string likely = likelyOption(name, known);
  const std::string hint = likely.empty() ? "see --help" : "did you mean '" + likely + "'?";
  return Status::failure("unknown option '" + name + "' (" + hint + ")");
}

// Splits arguments into positionals and "--name value" / "--name=value" options (flags take no
// value and are stored with an empty one). Every option is checked against `known` here, before
// the positionals are counted, so that a mistyped option is named as such. After "--" every
// argument is positional.
Status splitArguments(const std::vector<std::string>& arguments, const OptionNames& known,
  std::vector<std::string>& positionals, std::map<std::string, std::string>& options)
{
  bool optionsEnded = false;
  for (size_t index = 0; index < arguments.size(); ++index)
  {
    const std::string& argument = arguments[index];
    if (!optionsEnded && argument == "--")
    {
      optionsEnded = true;
      continue;
    }
    if (optionsEnded || !looksLikeOption(argument))
    {
      positionals.push_back(argument);
      continue;
    }
    const size_t equals = argument.find('=');
    const std::string name = argument.substr(0, equals);
    std::string value;
    if (!known.knows(name))
      return unknownOption(name, known);
    if (known.flags.count(name))
    {
      if (equals != std::string::npos)
        return Status::failure("option " + name + " takes no value");
    }
    else if (equals != std::string::npos)
      value = argument.substr(equals + 1);
    // The next argument is the value, unless it is another option: then the value is missing.
    else if (index + 1 < arguments.size() && !known.knows(arguments[index + 1]))
      value = arguments[++index];
    else
      return Status::failure("option " + name + " needs a value");
    if (options.count(name))
      return Status::failure("option " + name + " given twice");
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
  if (options.count("--size-array"))
    for (const char* bound :
      { "--max-edge-length", "--edge-length-factor", "--max-volume", "--volume-factor" })
      if (options.count(bound))
        return Status::failure(std::string("give either --size-array or ") + bound +
          ": the size field replaces the threshold and the volume bound");
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
  const auto regionArray = options.find("--region-array");
  if (byRegion && (regionArray == options.end() || regionArray->second.empty()))
    return Status::failure("--partition-by-region needs --region-array NAME");
  if (options.count("--no-improve") && options.count("--improve-passes"))
    return Status::failure("give either --no-improve or --improve-passes, not both");
  return Status::success();
}

// A factor of 0 leaves no threshold or volume bound, which the filter refuses: on the command line
// that is a bad value rather than a failed run.
bool mustBePositive(const ParameterSpec& spec)
{
  const std::string flag = spec.flag;
  return flag == "--edge-length-factor" || flag == "--volume-factor";
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
      status = mustBePositive(spec) ? parsePositiveDouble(value, spec.flag, number)
                                    : parseDouble(value, spec.flag, spec.minimum, number);
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

// OUT's compression when --compression is not given: only .vtu files are ever compressed.
Compression defaultCompressionFor(const std::string& outputFile)
{
  return isXMLFileName(outputFile) ? DefaultCompression : Compression::None;
}

// --compression NAME: a .vtu writer setting; legacy .vtk files are always uncompressed.
Status parseCompression(
  const std::string& text, const std::string& outputFile, Compression& compression)
{
  if (!compressionFromName(text, compression))
    return Status::failure(
      "unknown compression '" + text + "' for --compression (use none, lz4, zlib)");
  if (!isXMLFileName(outputFile) && compression != Compression::None)
    return Status::failure("--compression " + text +
      " needs a .vtu output: legacy .vtk files are written as uncompressed binary, and other "
      "formats have no compression setting");
  return Status::success();
}

Status applyRefineOption(const std::string& name, const std::string& value, RefineArguments& parsed)
{
  if (name == "--stats")
  {
    parsed.statsFile = value;
    return Status::success();
  }
  if (name == "--compression")
    return parseCompression(value, parsed.outputFile, parsed.compression);
  if (name == "--msh-version")
  {
    if (value != "4.1" && value != "2.2")
      return Status::failure(
        "unknown Gmsh format '" + value + "' for --msh-version (use 4.1 or 2.2)");
    if (std::filesystem::path(parsed.outputFile).extension() != ".msh")
      return Status::failure("--msh-version " + value +
        " needs a .msh output: only Gmsh files have a format version to choose");
    parsed.mshVersion = std::stod(value);
    return Status::success();
  }
  const ParameterSpec* spec = findParameterByFlag(name);
  if (!spec)
    return Status::failure("unknown option '" + name + "' (see --help)");
  return applyParameter(*spec, value, parsed.options);
}

} // namespace

Status parseRefineArguments(const std::vector<std::string>& arguments, RefineArguments& parsed)
{
  std::vector<std::string> positionals;
  std::map<std::string, std::string> options;
  Status status = splitArguments(arguments, refineOptionNames(), positionals, options);
  if (!status.ok())
    return status;
  status = checkPositionalCount(positionals, 2, "IN and OUT");
  if (!status.ok())
    return status;
  parsed.inputFile = positionals[0];
  parsed.outputFile = positionals[1];
  parsed.compression = defaultCompressionFor(parsed.outputFile);
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
    if (mustBePositive(spec))
      text += ", > 0";
    else if (spec.kind == ParameterKind::Integer || spec.kind == ParameterKind::Real ||
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

std::string compressionHelp()
{
  return "  --compression NAME      compression of the arrays of a .vtu OUT, written as appended "
         "raw\n"
         "                          binary data (.vtk files are always uncompressed binary):\n"
         "                          none (default), lz4 or zlib (level 1); meshio reads none\n"
         "                          and zlib (and .vtk files), not lz4. Writing 1.9 M tets\n"
         "                          on a 2-core VM:\n"
         "                            none    0.27 s   7.2 M tets/s   134 MB\n"
         "                            lz4     0.31 s   6.1 M tets/s    66 MB\n"
         "                            zlib    1.63 s   1.2 M tets/s    47 MB\n";
}

namespace
{

// generate's --cells: the FinFET shapes only.
Status parseGenerateOption(
  const std::string& name, const std::string& value, GenerateArguments& parsed)
{
  if (name == "--compression")
    return parseCompression(value, parsed.outputFile, parsed.compression);
  if (parsed.shape == "cube")
    return Status::failure("option " + name + " is for finfet and finfet-grid, not cube");
  if (name == "--material-names")
  {
    parsed.materialNames = true;
    return Status::success();
  }
  return parseInt(value, "--cells", 1000, 500000000, parsed.targetCells);
}

Status parseTetGenOption(const std::string& name, const std::string& value, TetGenArguments& parsed)
{
  if (name == "--max-volume")
    return parsePositiveDouble(value, name, parsed.maximumVolume);
  if (name == "--radius-edge-ratio")
    return parseDouble(value, name, 1.0, parsed.radiusEdgeRatio);
  if (name == "--compression")
    return parseCompression(value, parsed.outputFile, parsed.compression);
  if (name == "--tet-order")
  {
    if (value != "hilbert" && value != "input")
      return Status::failure("--tet-order must be 'hilbert' or 'input', not '" + value + "'");
    parsed.tetsAlongHilbertCurve = value == "hilbert";
    return Status::success();
  }
  (name == "--region-array" ? parsed.regionArrayName : parsed.statsFile) = value;
  return Status::success();
}

} // namespace

Status parseGenerateArguments(const std::vector<std::string>& arguments, GenerateArguments& parsed)
{
  std::vector<std::string> positionals;
  std::map<std::string, std::string> options;
  Status status = splitArguments(
    arguments, { { "--cells", "--compression" }, { "--material-names" } }, positionals, options);
  if (!status.ok())
    return status;
  if (positionals.empty())
    return Status::failure("expected 'cube N OUT.vtu', 'finfet OUT.vtu [--cells N]' or "
                           "'finfet-grid OUT.vtu [--cells N]'");
  parsed.shape = positionals[0];
  if (parsed.shape == "cube")
  {
    status = checkPositionalCount(positionals, 3, "cube N OUT.vtu");
    if (status.ok())
      status = parseInt(positionals[1], "N", 1, 1000, parsed.cellsPerSide);
  }
  else if (parsed.shape == "finfet" || parsed.shape == "finfet-grid")
    status = checkPositionalCount(positionals, 2, parsed.shape + " OUT.vtu [--cells N]");
  else
    return Status::failure(
      "unknown shape '" + parsed.shape + "' (use 'cube', 'finfet' or 'finfet-grid')");
  if (!status.ok())
    return status;
  parsed.outputFile = positionals.back();
  parsed.compression = defaultCompressionFor(parsed.outputFile);
  for (auto option = options.begin(); status.ok() && option != options.end(); ++option)
    status = parseGenerateOption(option->first, option->second, parsed);
  return status;
}

Status parseTetGenArguments(const std::vector<std::string>& arguments, TetGenArguments& parsed)
{
  std::vector<std::string> positionals;
  std::map<std::string, std::string> options;
  const OptionNames known{ { "--max-volume", "--radius-edge-ratio", "--region-array", "--stats",
                             "--compression", "--tet-order" },
    {} };
  Status status = splitArguments(arguments, known, positionals, options);
  if (!status.ok())
    return status;
  status = checkPositionalCount(positionals, 2, "IN and OUT");
  if (!status.ok())
    return status;
  parsed.inputFile = positionals[0];
  parsed.outputFile = positionals[1];
  parsed.compression = defaultCompressionFor(parsed.outputFile);
  if (!options.count("--max-volume"))
    return Status::failure("--max-volume V is required");
  for (auto option = options.begin(); status.ok() && option != options.end(); ++option)
    status = parseTetGenOption(option->first, option->second, parsed);
  return status;
}

Status parseCheckArguments(const std::vector<std::string>& arguments, CheckArguments& parsed)
{
  std::vector<std::string> positionals;
  std::map<std::string, std::string> options;
  Status status = splitArguments(arguments, { { "--region-array" }, {} }, positionals, options);
  if (!status.ok())
    return status;
  status = checkPositionalCount(positionals, 1, "IN");
  if (!status.ok())
    return status;
  parsed.inputFile = positionals[0];
  if (options.count("--region-array"))
    parsed.regionArrayName = options["--region-array"];
  return Status::success();
}

} // namespace cgmesh
