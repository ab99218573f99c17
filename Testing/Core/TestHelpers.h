// SPDX-License-Identifier: BSD-3-Clause
// Minimal checking for the core unit tests: no framework, one executable per test file, each
// named test a function; a failed check prints where and makes the executable fail.
#ifndef MeshSimplification_TestHelpers_h
#define MeshSimplification_TestHelpers_h

#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace meshsimp_test
{
inline int& Failures()
{
  static int failures = 0;
  return failures;
}

#define CHECK(condition)                                                                           \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      std::fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #condition);           \
      ++meshsimp_test::Failures();                                                                 \
    }                                                                                              \
  } while (false)

/// Runs the named tests and prints "N passed, M failed".
inline int RunTests(const std::vector<std::pair<std::string, std::function<void()>>>& tests)
{
  int passed = 0, failed = 0;
  for (const auto& test : tests)
  {
    const int before = Failures();
    test.second();
    const bool ok = Failures() == before;
    std::printf("%s %s\n", ok ? "PASS" : "FAIL", test.first.c_str());
    (ok ? passed : failed)++;
  }
  std::printf("%d passed, %d failed\n", passed, failed);
  return failed == 0 ? 0 : 1;
}
}

#endif
