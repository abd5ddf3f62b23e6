#include "base/thread_pool.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <vector>

namespace hocav {
namespace {

// Every item is visited once, by a worker of the pool, whatever the count against the block size
// and the threads; below `serial_below` the calling thread takes them all as worker 0.
TEST(RunInBlocks, VisitsEveryItemOnceOnAWorkerOfThePool) {
  for (const int threads : {1, 2, 3})
    for (const std::size_t count : {std::size_t{0}, std::size_t{1}, std::size_t{15}, std::size_t{16}, std::size_t{17}, std::size_t{1000}}) {
      ThreadPool pool(threads);
      std::vector<std::atomic<int>> visits(count);
      std::vector<std::size_t> worker_of(count, 99);
      run_in_blocks(pool, count, 2, [&](std::size_t worker, std::size_t i) {
        ++visits[i];
        worker_of[i] = worker;
      });
      for (std::size_t i = 0; i < count; ++i) {
        EXPECT_EQ(visits[i].load(), 1) << threads << " threads, " << count << " items, item " << i;
        EXPECT_LT(worker_of[i], static_cast<std::size_t>(threads)) << i;
      }
      if (count < 2) {
        for (std::size_t w : worker_of) EXPECT_EQ(w, 0u);
      }
    }
}

// A worker's items never run on two threads at once, so a scratch per worker is safe: each worker
// counts itself in and out of its scratch.
TEST(RunInBlocks, AWorkersItemsRunOneAtATime) {
  ThreadPool pool(3);
  std::vector<std::atomic<int>> inside(3);
  std::atomic<int> overlaps{0};
  run_in_blocks(pool, 20000, 1, [&](std::size_t worker, std::size_t) {
    if (++inside[worker] != 1) ++overlaps;
    --inside[worker];
  });
  EXPECT_EQ(overlaps.load(), 0);
}

// Many short loops in a row, most over before a sleeping worker wakes: each returns with all its
// items done, and a late worker never runs an item of a loop that has returned.
TEST(ThreadPool, ShortLoopsReturnWithEveryItemDone) {
  ThreadPool pool(3);
  std::vector<int> done(3, 0);
  for (int loop = 1; loop <= 20000; ++loop) {
    const std::size_t count = static_cast<std::size_t>(loop % 3) + 1;
    pool.run(count, [&](std::size_t i) { done[i] = loop; });
    for (std::size_t i = 0; i < count; ++i) ASSERT_EQ(done[i], loop) << "loop " << loop << ", item " << i;
  }
}

}  // namespace
}  // namespace hocav
