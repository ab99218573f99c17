// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file MeshFileCheckText.h
 * @brief What the format checks (MeshFileChecks.h, one file per format) share: a file's size,
 * the words and numbers of a line, and a word quoted for a message. Private to the checks.
 */
#ifndef MeshSimplification_MeshFileCheckText_h
#define MeshSimplification_MeshFileCheckText_h

#include <cstdint>
#include <string>
#include <vector>

namespace meshfiles
{
namespace detail
{

/// The size of a file in bytes, 0 when it cannot be read.
std::uintmax_t FileSize(const std::string& path);

/// A whole decimal integer, nothing around it (a leading '+' allowed).
bool ParseInteger(const std::string& text, long long& value);

/// A whole decimal integer as ParseInteger reads it, not negative.
bool ParseCount(const std::string& text, long long& value);

/// A whole number as strtod reads it (nan and inf included).
bool IsNumber(const std::string& text);

/// A word for a message: quoted, at most 40 characters, unprintable bytes as '?'.
std::string Quote(const std::string& word);

/// The text in lower case, byte by byte (tolower).
std::string Lower(std::string text);

/// The words of a line split at blanks (isspace).
std::vector<std::string> SplitBlanks(const std::string& line);

} // namespace detail
} // namespace meshfiles

#endif
