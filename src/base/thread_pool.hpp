// A fixed set of worker threads for parallel loops: run(count, work) calls work(i) for every i in
// [0, count) across the pool and the calling thread, and returns when all are done. Indices are
// handed out one at a time, so uneven items balance themselves. The calling thread starts at once;
// a worker joins when it wakes, unless the caller has taken every item by then (waking a sleeping
// thread cost about 20 us on these machines: docs/adaptation.md §Threads).
#pragma once

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace hocav {

class ThreadPool {
 public:
  // `threads` counts the caller: 1 runs everything on the calling thread.
  explicit ThreadPool(int threads);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int thread_count() const { return static_cast<int>(workers_.size()) + 1; }
  void run(std::size_t count, const std::function<void(std::size_t)>& work);

 private:
  void work_on_current_loop();
  void worker();

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(std::size_t)>* work_ = nullptr;
  std::size_t count_ = 0;
  std::atomic<std::size_t> next_{0};
  std::size_t generation_ = 0;
  bool open_ = false;  // the current loop still takes workers
  int joined_ = 0;     // workers in the current loop
  bool stopping_ = false;
};

// The default thread count of every command (and of the Python module): every core the machine has.
inline int every_core() { return static_cast<int>(std::max(1u, std::thread::hardware_concurrency())); }

// Calls work(worker, i) for every i in [0, count): each of the pool's workers w takes blocks of
// kBlock consecutive items as it comes free (so each worker may keep its own scratch, and the
// threads seldom write the same cache line), or the calling thread alone takes them all (worker 0)
// when there are fewer than `serial_below`, where waking the threads would cost more than it saves.
// The calling thread starts at once, and a woken thread takes what is left (docs/adaptation.md
// §Threads: a fixed share per thread waited for the thread that woke last). Which worker takes an
// item varies from run to run: work(worker, i) must give the same result whatever the worker.
template <typename Work>
void run_in_blocks(ThreadPool& pool, std::size_t count, std::size_t serial_below, const Work& work) {
  constexpr std::size_t kBlock = 16;
  if (count < serial_below || pool.thread_count() == 1) {
    for (std::size_t i = 0; i < count; ++i) work(0, i);
    return;
  }
  std::atomic<std::size_t> next{0};
  pool.run(static_cast<std::size_t>(pool.thread_count()), [&](std::size_t worker) {
    for (std::size_t begin = next.fetch_add(kBlock); begin < count; begin = next.fetch_add(kBlock))
      for (std::size_t i = begin; i < std::min(count, begin + kBlock); ++i) work(worker, i);
  });
}

// Elements or edges measured per range of run_chunked: enough work to outweigh a task's start.
inline constexpr std::size_t kMeasuredChunk = 1024;

// Calls work(begin, end) for consecutive ranges of `chunk` indices covering [0, count) on the pool's
// threads. The ranges do not depend on the thread count, so work that fills per-index or per-range
// results gives the same results for any count.
template <typename Work>
void run_chunked(ThreadPool& pool, std::size_t count, std::size_t chunk, const Work& work) {
  pool.run((count + chunk - 1) / chunk, [&](std::size_t c) { work(c * chunk, std::min(count, (c + 1) * chunk)); });
}

// Calls work(begin, end, result) as run_chunked does, each range filling a result of its own;
// returns the results in the ranges' order, so the same for any thread count.
template <typename Result, typename Work>
std::vector<Result> results_by_chunk(ThreadPool& pool, std::size_t count, std::size_t chunk, const Work& work) {
  std::vector<Result> results((count + chunk - 1) / chunk);
  run_chunked(pool, count, chunk, [&](std::size_t begin, std::size_t end) { work(begin, end, results[begin / chunk]); });
  return results;
}

// The parts one after the other.
template <typename T>
std::vector<T> joined(const std::vector<std::vector<T>>& parts) {
  std::vector<T> all;
  for (const std::vector<T>& part : parts) all.insert(all.end(), part.begin(), part.end());
  return all;
}

}  // namespace hocav
