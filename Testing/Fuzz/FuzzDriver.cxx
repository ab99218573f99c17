// SPDX-License-Identifier: BSD-3-Clause
// A plain main for a fuzz target (LLVMFuzzerTestOneInput), for compilers without libFuzzer and
// for CI, where a run must be the same every time: every file of the given folders is run as it
// is (the seeds, and the inputs that ever failed), then a fixed count of inputs, each a file
// (one in four, and all without files: random bytes) changed by one to four mutations drawn
// from a fixed seed. A failure aborts
// the process (the target's check, or a sanitizer's finding); with --keep FILE each input is
// written to FILE before it runs, so the one that failed is left there.
//
//   FuzzDriver [--runs N] [--seed S] [--keep FILE] [FOLDER ...]
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace
{
using Input = std::vector<std::uint8_t>;

/// Every file of the folders, in name order.
std::vector<Input> ReadFolders(const std::vector<std::string>& folders)
{
  std::vector<std::filesystem::path> paths;
  for (const std::string& folder : folders)
  {
    for (const auto& entry : std::filesystem::directory_iterator(folder))
    {
      if (entry.is_regular_file() && entry.path().filename().string()[0] != '.' &&
        entry.path().extension() != ".md")
      {
        paths.push_back(entry.path());
      }
    }
  }
  std::sort(paths.begin(), paths.end());
  std::vector<Input> inputs;
  for (const auto& path : paths)
  {
    std::ifstream in(path, std::ios::binary);
    inputs.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  return inputs;
}

/// Changes input by one mutation of the kinds libFuzzer makes: a bit flipped, a byte set to a
/// value parsers care about, bytes erased, inserted or repeated, the end cut, a number replaced
/// by an extreme one, a piece of another input copied in.
void Mutate(Input& input, const std::vector<Input>& corpus, std::mt19937_64& random)
{
  static const char* const numbers[] = { "0", "-1", "2147483647", "4294967296", "nan", "inf",
    "-inf", "1e300", "1e-300", "99999999999999999999", "3", "255", "256" };
  static const std::uint8_t bytes[] = { 0, 0xff, 0x7f, 0x80, '0', '9', ' ', '\n', '<', '>', '"',
    '/', '-', '.' };
  auto below = [&random](std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(random() % n); };
  const std::size_t at = below(input.size() + 1);
  const std::size_t length = 1 + below(std::min<std::size_t>(64, input.size() - std::min(at, input.size()) + 1));
  switch (below(7))
  {
    case 0:
      if (at < input.size())
        input[at] ^= static_cast<std::uint8_t>(1u << below(8));
      break;
    case 1:
      if (at < input.size())
        input[at] = bytes[below(sizeof(bytes))];
      break;
    case 2:
      input.erase(input.begin() + at, input.begin() + std::min(input.size(), at + length));
      break;
    case 3:
    {
      Input piece(input.begin() + std::min(at, input.size()), input.begin() + std::min(input.size(), at + length));
      for (std::size_t k = 0; piece.empty() && k < length; ++k)
        piece.push_back(static_cast<std::uint8_t>(random()));
      input.insert(input.begin() + below(input.size() + 1), piece.begin(), piece.end());
      break;
    }
    case 4:
      input.resize(at);
      break;
    case 5:
    {
      auto digit = std::find_if(input.begin() + at, input.end(), [](std::uint8_t c) { return c >= '0' && c <= '9'; });
      auto end = std::find_if(digit, input.end(), [](std::uint8_t c) { return c < '0' || c > '9'; });
      const std::string number = numbers[below(sizeof(numbers) / sizeof(*numbers))];
      input.insert(input.erase(digit, end), number.begin(), number.end());
      break;
    }
    default:
      if (!corpus.empty())
      {
        const Input& other = corpus[below(corpus.size())];
        const std::size_t from = below(other.size());
        const std::size_t count = std::min<std::size_t>(length, other.size() - from);
        input.insert(input.begin() + std::min(at, input.size()), other.begin() + from, other.begin() + from + count);
      }
  }
}

void RunOne(const Input& input, const std::string& keep)
{
  if (!keep.empty())
  {
    std::ofstream(keep, std::ios::binary).write(reinterpret_cast<const char*>(input.data()),
      static_cast<std::streamsize>(input.size()));
  }
  LLVMFuzzerTestOneInput(input.data(), input.size());
}
}

int main(int argc, char* argv[])
{
  long long runs = 1000;
  unsigned long long seed = 1;
  std::string keep;
  std::vector<std::string> folders;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if ((arg == "--runs" || arg == "--seed" || arg == "--keep") && i + 1 < argc)
    {
      const std::string value = argv[++i];
      if (arg == "--runs")
        runs = std::stoll(value);
      else if (arg == "--seed")
        seed = std::stoull(value);
      else
        keep = value;
    }
    else
    {
      folders.push_back(arg);
    }
  }
  const std::vector<Input> corpus = ReadFolders(folders);
  for (const Input& input : corpus)
  {
    RunOne(input, keep);
  }
  std::mt19937_64 random(seed);
  for (long long run = 0; run < runs; ++run)
  {
    Input input;
    if (corpus.empty() || random() % 4 == 0)
    {
      input.resize(1 + random() % 1024);
      std::generate(input.begin(), input.end(), [&random] { return static_cast<std::uint8_t>(random()); });
    }
    else
    {
      input = corpus[random() % corpus.size()];
    }
    for (int k = 1 + static_cast<int>(random() % 4); k > 0; --k)
    {
      Mutate(input, corpus, random);
    }
    RunOne(input, keep);
  }
  std::printf("%zu inputs from files and %lld mutated: no failure\n", corpus.size(), runs);
  return 0;
}
