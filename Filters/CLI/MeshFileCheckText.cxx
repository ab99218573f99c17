// SPDX-License-Identifier: BSD-3-Clause
// The helpers the format checks share (MeshFileCheckText.h).
#include "MeshFileCheckText.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace meshfiles
{
namespace detail
{
std::uintmax_t FileSize(const std::string& path)
{
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  return error ? 0 : size;
}

bool ParseInteger(const std::string& text, long long& value)
{
  const char* begin = text.data();
  const char* end = begin + text.size();
  if (begin != end && *begin == '+')
  {
    ++begin;
  }
  const std::from_chars_result parsed = std::from_chars(begin, end, value);
  return begin != end && parsed.ec == std::errc() && parsed.ptr == end;
}

bool ParseCount(const std::string& text, long long& value)
{
  return ParseInteger(text, value) && value >= 0;
}

bool IsNumber(const std::string& text)
{
  const char* begin = text.data();
  const char* end = begin + text.size();
  if (begin != end && *begin == '+')
  {
    ++begin;
  }
  double value;
  const std::from_chars_result parsed = std::from_chars(begin, end, value);
  return begin != end && parsed.ptr == end &&
    (parsed.ec == std::errc() || parsed.ec == std::errc::result_out_of_range);
}

std::string Quote(const std::string& word)
{
  std::string shown = word.substr(0, 40);
  for (char& c : shown)
  {
    c = std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  }
  return "'" + shown + (word.size() > 40 ? "...'" : "'");
}

std::string Lower(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

std::vector<std::string> SplitBlanks(const std::string& line)
{
  std::vector<std::string> words;
  std::size_t at = 0;
  while (true)
  {
    while (at < line.size() && std::isspace(static_cast<unsigned char>(line[at])))
    {
      ++at;
    }
    if (at == line.size())
    {
      return words;
    }
    const std::size_t begin = at;
    while (at < line.size() && !std::isspace(static_cast<unsigned char>(line[at])))
    {
      ++at;
    }
    words.push_back(line.substr(begin, at - begin));
  }
}
} // namespace detail
} // namespace meshfiles
