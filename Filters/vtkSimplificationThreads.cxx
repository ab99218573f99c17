// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSimplificationThreads.h"

#include "vtkAlgorithm.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace vtkSimplification
{

namespace
{
/**
 * Threads that live for one filter execution and share the chunks of every ParallelFor with
 * the calling thread. VTK 9.2's STDThread backend starts its threads anew for each For (about
 * 0.1 ms for two threads here), and the filters that work in rounds call it hundreds of times.
 * Waking a sleeping thread through the kernel costs 40-60 us here, so both sides poll a while
 * before they sleep: a worker polls for the next loop for about a millisecond, the caller for
 * the workers' last chunks for about 0.1 ms; loops that follow each other closely then start
 * in about a microsecond. (Polling is a plain load: a PAUSE loop makes virtual machines
 * deschedule the polling CPU, which stalled loops by milliseconds.) Chunks go to whichever
 * thread asks first; the filters write disjoint data per index, so the result does not depend
 * on it.
 */
class WorkerPool
{
public:
  using Body = std::function<void(std::int64_t, std::int64_t)>;

  explicit WorkerPool(int threads)
  {
    for (int i = 1; i < threads; ++i)
    {
      this->Workers.emplace_back([this, i] {
        CurrentPool = this;
        CurrentIndex = i;
        this->Serve();
      });
    }
  }

  /// The calling thread's index: 1, 2, ... for the workers, 0 for the thread that calls For
  /// (also when it is a worker of another pool).
  int Worker() const { return CurrentPool == this ? CurrentIndex : 0; }

  ~WorkerPool()
  {
    {
      std::lock_guard<std::mutex> lock(this->Mutex);
      this->Stopping = true;
      this->Generation.fetch_add(1, std::memory_order_release);
    }
    this->Wake.notify_all();
    for (std::thread& worker : this->Workers)
    {
      worker.join();
    }
  }

  /// Runs body over [0, n) in chunks of about 64 us of the estimated work (4 to 64 per thread):
  /// fine enough that the threads finish together, though the machine may slow one down.
  void For(std::int64_t n, std::int64_t work, const Body& body)
  {
    const std::int64_t threads = static_cast<std::int64_t>(this->Workers.size()) + 1;
    this->Job = &body;
    this->Size = n;
    this->Chunks = std::min(n, std::max(4 * threads, std::min(64 * threads, work >> 16)));
    this->Next = 0;
    this->Busy.store(static_cast<int>(this->Workers.size()), std::memory_order_relaxed);
    {
      // Under the lock, so that a worker about to sleep either sees the new generation or is
      // counted in Sleepers before it is read below.
      std::lock_guard<std::mutex> lock(this->Mutex);
      this->Generation.fetch_add(1, std::memory_order_release);
    }
    if (this->Sleepers.load() > 0)
    {
      this->Wake.notify_all();
    }
    this->Work();
    for (int polls = 1; polls < CallerPolls && !this->Finished(); ++polls)
    {
      if (polls % 1024 == 0)
      {
        std::this_thread::yield();
      }
    }
    if (!this->Finished())
    {
      std::unique_lock<std::mutex> lock(this->Mutex);
      this->CallerWaiting = true;
      this->Done.wait(lock, [this] { return this->Finished(); });
      this->CallerWaiting = false;
    }
  }

private:
  bool Finished() const { return this->Busy.load(std::memory_order_acquire) == 0; }

  void Work()
  {
    for (std::int64_t chunk = this->Next++; chunk < this->Chunks; chunk = this->Next++)
    {
      (*this->Job)(this->Size * chunk / this->Chunks, this->Size * (chunk + 1) / this->Chunks);
    }
  }

  void Serve()
  {
    std::uint64_t seen = 0;
    for (;;)
    {
      for (int polls = 1; polls < WorkerPolls && this->Generation.load(std::memory_order_acquire) == seen; ++polls)
      {
        if (polls % 1024 == 0)
        {
          std::this_thread::yield(); // lets the caller run if the two share a CPU
        }
      }
      if (this->Generation.load(std::memory_order_acquire) == seen)
      {
        std::unique_lock<std::mutex> lock(this->Mutex);
        ++this->Sleepers;
        this->Wake.wait(lock, [&] { return this->Generation.load() != seen; });
        --this->Sleepers;
      }
      seen = this->Generation.load(std::memory_order_acquire);
      if (this->Stopping.load())
      {
        return;
      }
      this->Work();
      if (this->Busy.fetch_sub(1, std::memory_order_acq_rel) == 1)
      {
        std::lock_guard<std::mutex> lock(this->Mutex);
        if (this->CallerWaiting)
        {
          this->Done.notify_one();
        }
      }
    }
  }

  static thread_local const WorkerPool* CurrentPool;
  static thread_local int CurrentIndex;
  static constexpr int WorkerPolls = 1 << 20; // about a millisecond
  static constexpr int CallerPolls = 1 << 17;
  std::vector<std::thread> Workers;
  std::mutex Mutex;
  std::condition_variable Wake, Done;
  const Body* Job = nullptr;
  std::int64_t Size = 0, Chunks = 0;
  std::atomic<std::int64_t> Next{ 0 };
  std::atomic<int> Busy{ 0 }, Sleepers{ 0 };
  std::atomic<std::uint64_t> Generation{ 0 };
  std::atomic<bool> Stopping{ false };
  bool CallerWaiting = false; // guarded by Mutex
};
thread_local const WorkerPool* WorkerPool::CurrentPool = nullptr;
thread_local int WorkerPool::CurrentIndex = 0;
}

meshsimp::ExecutionContext MakeExecutionContext(vtkAlgorithm* algorithm, int numberOfThreads)
{
  meshsimp::ExecutionContext context;
  const int threads = ResolveThreadCount(numberOfThreads);
  if (threads > 1)
  {
    context.Threads = threads;
    // Work is estimated in nanoseconds (ExecutionContext). The threads start with the first
    // loop of a millisecond or more, so small inputs never pay for them (about 0.1 ms); then
    // loops of 30 us or more are shared (a polled start costs about 1 us, see WorkerPool).
    constexpr std::int64_t StartWork = 1 << 20, LoopWork = 1 << 15;
    auto pool = std::make_shared<std::unique_ptr<WorkerPool>>();
    context.ParallelFor = [pool, threads](
                            std::int64_t n, std::int64_t work, const WorkerPool::Body& body) {
      if (work < (*pool ? LoopWork : StartWork))
      {
        body(0, n); // too little work to pay for the threads
        return;
      }
      if (!*pool)
      {
        *pool = std::make_unique<WorkerPool>(threads);
      }
      (*pool)->For(n, work, body);
    };
    context.Worker = [pool] { return *pool ? (*pool)->Worker() : 0; };
  }
  context.Progress = [algorithm](double progress) {
    algorithm->UpdateProgress(progress);
    return !algorithm->CheckAbort();
  };
  return context;
}

int ResolveThreadCount(int numberOfThreads)
{
  return numberOfThreads > 0 ? numberOfThreads
                             : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

}
