#include "Parameters.h"

#include "AdaptationOptions.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <sstream>
#include <type_traits>

namespace cgmesh
{

const ParameterSpec* findParameter(const std::string& name)
{
  for (const ParameterSpec& spec : parameterTable())
  {
    if (name == spec.name)
    {
      return &spec;
    }
  }
  return nullptr;
}

const ParameterSpec* findParameterByFlag(const std::string& flag)
{
  for (const ParameterSpec& spec : parameterTable())
  {
    if (flag == spec.flag)
    {
      return &spec;
    }
  }
  return nullptr;
}

void applyDefaults(AdaptationOptions& options)
{
  for (const ParameterSpec& spec : parameterTable())
  {
    if (spec.kind == ParameterKind::Text)
    {
      setTextValue(spec, spec.defaultText, options);
    }
    else
    {
      setNumericValue(spec, spec.defaultValue, options);
    }
  }
}

int choiceIndex(const ParameterSpec& spec, const std::string& name)
{
  for (std::size_t index = 0; index < spec.choices.size(); ++index)
  {
    if (name == spec.choices[index].name)
    {
      return static_cast<int>(index);
    }
  }
  return -1;
}

double numericValue(const ParameterSpec& spec, const AdaptationOptions& options)
{
  return std::visit(
    [&](auto member) -> double
    {
      using Value = std::decay_t<decltype(options.*member)>;
      if constexpr (std::is_same_v<Value, std::string>)
      {
        return spec.kind == ParameterKind::Choice ? choiceIndex(spec, options.*member) : 0.0;
      }
      else
      {
        return static_cast<double>(options.*member);
      }
    },
    spec.field);
}

bool setNumericValue(const ParameterSpec& spec, double value, AdaptationOptions& options)
{
  if (spec.kind == ParameterKind::Text || std::isnan(value))
  {
    return false;
  }
  double clamped = std::min(std::max(value, spec.minimum), spec.maximum);
  if (spec.kind != ParameterKind::Real)
  {
    clamped = std::round(clamped);
  }
  const bool changed = numericValue(spec, options) != clamped;
  std::visit(
    [&](auto member)
    {
      using Value = std::decay_t<decltype(options.*member)>;
      if constexpr (std::is_same_v<Value, std::string>)
      {
        options.*member = spec.choices[static_cast<std::size_t>(clamped)].name;
      }
      else if constexpr (std::is_enum_v<Value>)
      {
        options.*member = static_cast<Value>(static_cast<int>(clamped));
      }
      else
      {
        options.*member = static_cast<Value>(clamped);
      }
    },
    spec.field);
  return changed;
}

std::string textValue(const ParameterSpec& spec, const AdaptationOptions& options)
{
  if (spec.kind == ParameterKind::Choice)
  {
    const int index = static_cast<int>(numericValue(spec, options));
    return index >= 0 ? spec.choices[index].name : std::string();
  }
  const auto* member = std::get_if<std::string AdaptationOptions::*>(&spec.field);
  return member ? options.**member : std::string();
}

bool setTextValue(const ParameterSpec& spec, const std::string& value, AdaptationOptions& options)
{
  const auto* member = std::get_if<std::string AdaptationOptions::*>(&spec.field);
  if (spec.kind != ParameterKind::Text || !member || options.**member == value)
  {
    return false;
  }
  options.** member = value;
  return true;
}

std::string rangeText(const ParameterSpec& spec)
{
  std::ostringstream text;
  const bool bounded = spec.maximum != Unbounded && spec.maximum < INT_MAX;
  if (bounded)
  {
    text << "[" << spec.minimum << ", " << spec.maximum << "]";
  }
  else
  {
    text << ">= " << spec.minimum;
  }
  return text.str();
}

} // namespace cgmesh
