// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ParameterTable.h
 * @brief What reads or writes an algorithm's settings by name: the CLI's --set, a filter's
 * PrintSelf, a cache key, the test that the plugin's defaults are the core's.
 *
 * Each parameters struct (OctreeClusteringParameters, ...) lists its settings once, in a static
 * ForEach(parameters, visit) that calls visit(name, member, minimum, maximum, help) for each,
 * with the name the VTK filter and the plugin give it, the range its setter clamps to and one
 * line of help (which the plugin's documentation of the property begins with). The members are
 * numbers, flags or enumerations; these helpers read and write any of them as a double.
 */
#ifndef MeshSimplification_ParameterTable_h
#define MeshSimplification_ParameterTable_h

#include <algorithm>
#include <cmath>
#include <functional>
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

/// One setting as a caller that does not know its member's type sees it: its name, value, range
/// and help, and a setter that clamps to the range and returns the value set.
struct SettingEntry
{
  const char* Name;
  double Value;
  double Minimum, Maximum;
  const char* Help;
  std::function<double(double)> Set;
};
using SettingVisit = std::function<void(const SettingEntry&)>;

/// Calls visit with each setting of parameters (Table: the struct whose ForEach lists them).
template <class Table>
void VisitParameters(Table& parameters, const SettingVisit& visit)
{
  Table::ForEach(parameters, [&](const char* name, auto& member, double minimum, double maximum, const char* help) {
    visit(SettingEntry{ name, AsNumber(member), minimum, maximum, help, [&member, minimum, maximum](double value) {
                         SetFromNumber(member, value, minimum, maximum);
                         return AsNumber(member);
                       } });
  });
}

/// "Name: value" a line for each setting, each line starting with indent (PrintSelf's style).
template <class Table, class Indent>
void PrintParameters(const Table& parameters, std::ostream& os, const Indent& indent)
{
  Table::ForEach(parameters, [&](const char* entry, const auto& member, double, double, const char*) {
    os << indent << entry << ": " << AsNumber(member) << "\n";
  });
}

} // namespace meshsimp

#endif
