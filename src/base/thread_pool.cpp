#include "base/thread_pool.hpp"

namespace hocav {

ThreadPool::ThreadPool(int threads) {
  for (int i = 1; i < threads; ++i) workers_.emplace_back([this] { worker(); });
}

ThreadPool::~ThreadPool() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (auto& thread : workers_) thread.join();
}

void ThreadPool::work_on_current_loop() {
  for (std::size_t i = next_.fetch_add(1); i < count_; i = next_.fetch_add(1)) (*work_)(i);
}

void ThreadPool::run(std::size_t count, const std::function<void(std::size_t)>& work) {
  if (workers_.empty()) {
    for (std::size_t i = 0; i < count; ++i) work(i);
    return;
  }
  {
    std::lock_guard lock(mutex_);
    work_ = &work;
    count_ = count;
    next_ = 0;
    open_ = true;
    ++generation_;
  }
  wake_.notify_all();
  work_on_current_loop();
  // Every item is taken: a worker that has not joined yet stays out, so the caller waits only for
  // the items the joined ones are still on, not for a late thread to wake.
  std::unique_lock lock(mutex_);
  open_ = false;
  done_.wait(lock, [this] { return joined_ == 0; });
}

void ThreadPool::worker() {
  std::size_t seen = 0;
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_) return;
      seen = generation_;
      if (!open_) continue;  // the caller took every item before this thread woke
      ++joined_;
    }
    work_on_current_loop();
    {
      std::lock_guard lock(mutex_);
      --joined_;
    }
    done_.notify_one();
  }
}

}  // namespace hocav
