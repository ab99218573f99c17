// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ParameterTable.h
 * @brief What reads or writes an algorithm's settings by name: the CLI's --set, a filter's
 * PrintSelf, a cache key, the test that the plugin's defaults are the core's.
 *
 * Each parameters struct (OctreeClusteringParameters, ...) lists its settings once, in a static
 * ForEach(parameters, visit) that calls visit(name, member, minimum, maximum) for each, with the
 * name the VTK filter and the plugin give it and the range its setter clamps to. The members are
 * numbers, flags or enumerations; these helpers read and write any of them as a double.
 */
#ifndef MeshSimplification_ParameterTable_h
#define MeshSimplification_ParameterTable_h

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <string>
#include <type_traits>

namespace meshsimp
{

/// The upper bound of a setting without one.
constexpr double Unbounded = std::numeric_limits<double>::max();

/// A setting's value as a number (an enumeration's as its underlying value, a flag as 0 or 1).
template <class T>
double AsNumber(T value)
{
  if constexpr (std::is_enum_v<T>)
  {
    return static_cast<double>(static_cast<std::underlying_type_t<T>>(value));
  }
  else
  {
    return static_cast<double>(value);
  }
}

/// Sets a setting from a finite number clamped to [minimum, maximum] (a flag: nonzero is true;
/// an integer or an enumeration: truncated).
template <class T>
void SetFromNumber(T& member, double value, double minimum, double maximum)
{
  const double clamped = std::min(std::max(value, minimum), maximum);
  if constexpr (std::is_same_v<T, bool>)
  {
    member = value != 0.0;
  }
  else if constexpr (std::is_enum_v<T>)
  {
    member = static_cast<T>(static_cast<std::underlying_type_t<T>>(clamped));
  }
  else
  {
    member = static_cast<T>(clamped);
  }
}

/// How SetParameterByName went.
enum class SetResult
{
  Unknown, // Table has no setting of that name (or the value is not a finite number)
  Same,    // the setting already had that value
  Changed
};

/// Sets the setting of that name in parameters (Table: the struct whose ForEach lists it).
template <class Table>
SetResult SetParameterByName(Table& parameters, const std::string& name, double value)
{
  SetResult result = SetResult::Unknown;
  Table::ForEach(parameters, [&](const char* entry, auto& member, double minimum, double maximum) {
    if (result == SetResult::Unknown && name == entry && std::isfinite(value))
    {
      const auto before = member;
      SetFromNumber(member, value, minimum, maximum);
      result = member == before ? SetResult::Same : SetResult::Changed;
    }
  });
  return result;
}

/// "Name: value" a line for each setting, each line starting with indent (PrintSelf's style).
template <class Table, class Indent>
void PrintParameters(const Table& parameters, std::ostream& os, const Indent& indent)
{
  Table::ForEach(parameters, [&](const char* entry, const auto& member, double, double) {
    os << indent << entry << ": " << AsNumber(member) << "\n";
  });
}

} // namespace meshsimp

#endif
