#pragma once
/// @file A small fixed pool of helper threads for fork-join work inside one evaluation (the
/// film joints of a right-hand side, the two panels of the skirt). The calling thread takes part,
/// so a pool of size 1 has no helper and runs everything inline.
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace filmdyn {

class WorkerPool {
 public:
  /// `threads` >= 1 threads in all (the caller and threads - 1 helpers).
  explicit WorkerPool(int threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int Threads() const { return static_cast<int>(helpers_.size()) + 1; }
  /// Runs task(0) ... task(count - 1), each exactly once, on the caller and the helpers; returns
  /// when all have finished. When tasks throw, the exception of the lowest index is rethrown (the
  /// same one a sequential loop would have thrown first, with all tasks run).
  void Run(int count, const std::function<void(int)>& task);

 private:
  void HelperLoop();
  // Claims and runs tasks of the current batch until none is left.
  void Drain();

  std::vector<std::thread> helpers_;
  std::mutex mutex_;
  std::condition_variable start_, done_;
  std::uint64_t batch_ = 0;  // generation of the current batch
  bool stop_ = false;
  const std::function<void(int)>* task_ = nullptr;
  int count_ = 0, next_ = 0, finished_ = 0;
  std::vector<std::exception_ptr> errors_;
};

}  // namespace filmdyn
