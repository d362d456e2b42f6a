#pragma once
/// @file Fork-join work inside one evaluation (the film joints of a right-hand side, the two
/// panels of the skirt) on oneTBB: tasks of a batch run in a task arena of at most `threads`
/// threads, the calling thread taking part. Every parallel level of FilmDyn (sweep runs, film
/// joints, skirt panels) uses TBB's one worker pool, so nested levels share the machine's cores
/// instead of each starting threads of its own. A pool of size 1 runs everything inline.
#include <functional>
#include <memory>

namespace filmdyn {

class WorkerPool {
 public:
  /// `threads` >= 1 threads in all (the caller included).
  explicit WorkerPool(int threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int Threads() const { return threads_; }
  /// Runs task(0) ... task(count - 1), each exactly once; returns when all have finished. When
  /// tasks throw, the exception of the lowest index is rethrown (the same one a sequential loop
  /// would have thrown first, with all tasks run). Results do not depend on the thread count as
  /// long as each task writes only its own outputs.
  void Run(int count, const std::function<void(int)>& task);

 private:
  struct Arena;  // a tbb::task_arena of threads_ slots
  int threads_ = 1;
  std::unique_ptr<Arena> arena_;  // null when threads_ == 1
};

}  // namespace filmdyn
