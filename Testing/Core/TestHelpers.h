// SPDX-License-Identifier: BSD-3-Clause
// Minimal checking for the core unit tests: no framework, one executable per test file, each
// named test a function; a failed check prints where and makes the executable fail.
#ifndef MeshSimplification_TestHelpers_h
#define MeshSimplification_TestHelpers_h

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <thread>
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

/// The chunk index of the running Threaded body (0 on the calling thread).
inline int& ThreadedWorker()
{
  thread_local int index = 0;
  return index;
}

/// An execution context (meshsimp::ExecutionContext; a template so that this header needs no
/// core include) whose ParallelFor runs count real threads, one contiguous chunk each, and
/// tells each its index: results must not depend on the thread count.
template <typename Context>
Context Threaded(int count)
{
  Context context;
  context.Threads = count;
  context.Worker = [] { return ThreadedWorker(); };
  context.ParallelFor = [count](std::int64_t n, std::int64_t,
                          const std::function<void(std::int64_t, std::int64_t)>& body) {
    std::vector<std::thread> threads;
    const std::int64_t chunk = (n + count - 1) / count;
    for (std::int64_t begin = 0; begin < n; begin += chunk)
    {
      threads.emplace_back([&body, begin, end = std::min(n, begin + chunk), index = static_cast<int>(begin / chunk)] {
        ThreadedWorker() = index;
        body(begin, end);
      });
    }
    for (std::thread& thread : threads)
    {
      thread.join();
    }
  };
  return context;
}

/// Like Threaded, but the threads take chunks of chunkSize items in turn as they finish (as the
/// plugin's pool does), so a thread runs many chunks and its index comes from Worker.
template <typename Context>
Context Chunked(int count, std::int64_t chunkSize)
{
  Context context = Threaded<Context>(count);
  context.ParallelFor = [count, chunkSize](std::int64_t n, std::int64_t,
                          const std::function<void(std::int64_t, std::int64_t)>& body) {
    std::atomic<std::int64_t> next{ 0 };
    auto work = [&](int index) {
      ThreadedWorker() = index;
      for (std::int64_t begin = next.fetch_add(chunkSize); begin < n; begin = next.fetch_add(chunkSize))
      {
        body(begin, std::min(n, begin + chunkSize));
      }
    };
    std::vector<std::thread> threads;
    for (int index = 1; index < count; ++index)
    {
      threads.emplace_back(work, index);
    }
    work(0);
    for (std::thread& thread : threads)
    {
      thread.join();
    }
  };
  return context;
}

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
