#include "core/base/worker_pool.hpp"

#include <algorithm>

namespace filmdyn {

WorkerPool::WorkerPool(int threads) {
  for (int k = 1; k < std::max(1, threads); ++k) helpers_.emplace_back([this] { HelperLoop(); });
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  start_.notify_all();
  for (std::thread& helper : helpers_) helper.join();
}

void WorkerPool::Drain() {
  std::unique_lock lock(mutex_);
  while (next_ < count_) {
    const int index = next_++;
    const std::function<void(int)>& task = *task_;
    lock.unlock();
    std::exception_ptr error;
    try {
      task(index);
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    errors_[index] = error;
    if (++finished_ == count_) done_.notify_all();
  }
}

void WorkerPool::HelperLoop() {
  std::uint64_t seen = 0;
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      start_.wait(lock, [&] { return stop_ || batch_ != seen; });
      if (stop_) return;
      seen = batch_;
    }
    Drain();
  }
}

void WorkerPool::Run(int count, const std::function<void(int)>& task) {
  if (count <= 0) return;
  if (helpers_.empty() || count == 1) {  // inline: no hand-over cost
    std::exception_ptr first;
    for (int k = 0; k < count; ++k) {
      try {
        task(k);
      } catch (...) {
        if (!first) first = std::current_exception();
      }
    }
    if (first) std::rethrow_exception(first);
    return;
  }
  {
    std::lock_guard lock(mutex_);
    task_ = &task;
    count_ = count;
    next_ = finished_ = 0;
    errors_.assign(count, nullptr);
    ++batch_;
  }
  start_.notify_all();
  Drain();
  std::unique_lock lock(mutex_);
  done_.wait(lock, [&] { return finished_ == count_; });
  task_ = nullptr;
  for (const std::exception_ptr& error : errors_) {
    if (error) std::rethrow_exception(error);
  }
}

}  // namespace filmdyn
