// What a user parameter is: the row type of the parameter table (AdaptationOptions.h) and the
// operations every front end shares: defaults, clamping, lookup by property name or CLI flag, and
// reading and writing a parameter of an AdaptationOptions as a number or a text.
#ifndef cgmesh_Parameters_h
#define cgmesh_Parameters_h

#include <cstdint>
#include <limits>
#include <string>
#include <variant>
#include <vector>

namespace cgmesh
{

struct AdaptationOptions;
enum class RefinementMethod;
enum class PartitionerKind;

enum class ParameterKind
{
  Integer, // int
  Count,   // 64-bit count (exact up to 2^53 through the numeric interface)
  Real,    // double
  Boolean, // on/off; its CLI flag flips the default (--no-improve, --partition-by-region)
  Choice,  // one of `choices`, numbered from 0 as the filter's enums are
  Text     // a name (RegionArrayName)
};

// Which refinement method a parameter belongs to: using it with the other one is an error on the
// command line, and the panel hides it.
enum class MethodScope
{
  Any,
  Template,
  Delaunay
};

struct ParameterChoice
{
  const char* name;        // on the command line and in the field data ("greedy-lu")
  const char* label;       // in the ParaView panel ("Greedy-LU")
  const char* description; // one line for --help
};

// Where the value lives in AdaptationOptions.
using ParameterField = std::variant<int AdaptationOptions::*, std::int64_t AdaptationOptions::*,
  double AdaptationOptions::*, bool AdaptationOptions::*, RefinementMethod AdaptationOptions::*,
  PartitionerKind AdaptationOptions::*, std::string AdaptationOptions::*>;

constexpr double Unbounded = std::numeric_limits<double>::infinity();
// The largest Count the numeric interface (doubles) carries exactly: 2^53.
constexpr double LargestExactCount = 9007199254740992.0;

struct ParameterSpec
{
  const char* name;      // filter property, XML property and Set/Get method stem
  const char* flag;      // command-line option
  const char* valueName; // placeholder in the usage text ("N", "F"); empty for flags
  ParameterKind kind;
  double minimum;          // inclusive; for a Choice 0
  double maximum;          // inclusive; Unbounded when there is none
  double defaultValue;     // for a Choice the index, for a Boolean 0 or 1; unused for Text
  const char* defaultText; // for Text
  MethodScope scope;
  const char* help; // one line: what it does (the default and range are added where shown)
  ParameterField field;
  std::vector<ParameterChoice> choices = {};
};

// Every user parameter, in the order of the panel and of --help.
const std::vector<ParameterSpec>& parameterTable();

// The row of a property name or a command-line flag; nullptr when there is none.
const ParameterSpec* findParameter(const std::string& name);
const ParameterSpec* findParameterByFlag(const std::string& flag);

// Sets every parameter of `options` to its default.
void applyDefaults(AdaptationOptions& options);

// A numeric parameter (all kinds but Text) as a number: a Choice as its index, a Boolean as 0/1.
double numericValue(const ParameterSpec& spec, const AdaptationOptions& options);
// Sets a numeric parameter, clamped to its range (a Choice to its indices, a Boolean to 0/1,
// integers rounded). Returns true when the stored value changed.
bool setNumericValue(const ParameterSpec& spec, double value, AdaptationOptions& options);

// A Text parameter's value, or a Choice's name.
std::string textValue(const ParameterSpec& spec, const AdaptationOptions& options);
// Sets a Text parameter. Returns true when the stored value changed.
bool setTextValue(const ParameterSpec& spec, const std::string& value, AdaptationOptions& options);

// The index of a choice name, or -1.
int choiceIndex(const ParameterSpec& spec, const std::string& name);

// The range as text for messages and --help: "[1, 20]", ">= 0".
std::string rangeText(const ParameterSpec& spec);

} // namespace cgmesh

#endif
