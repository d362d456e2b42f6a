#include "core/base/worker_pool.hpp"

#include "core/base/vector_unit.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

namespace filmdyn {

namespace {
// Set by the ThreadSanitizer build (scripts/check-sanitizers.sh): Debian's oneTBB is not
// instrumented, so TSan would report every task TBB hands between its threads as a race.
#ifdef FILMDYN_PLAIN_THREADS
constexpr bool kPlainThreads = true;
#else
constexpr bool kPlainThreads = false;
#endif
}  // namespace

struct WorkerPool::Arena {
  explicit Arena(int threads) : arena(threads) {}
  tbb::task_arena arena;
};

WorkerPool::WorkerPool(int threads) : threads_(std::max(1, threads)) {
  if (threads_ > 1) {
    arena_ = std::make_unique<Arena>(threads_);
    // TBB starts its worker threads on first demand; ask now, so that the first evaluation
    // does not wait for a thread to be created.
    if (!kPlainThreads) arena_->arena.execute([] { tbb::parallel_for(0, 2, [](int) {}); });
  }
}

WorkerPool::~WorkerPool() = default;

void WorkerPool::Run(int count, const std::function<void(int)>& task) {
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(std::max(0, count)));
  auto run_one = [&](int index) {
    ResetVectorUnitState();  // TBB's worker threads may have started with a dirty state
    try {
      task(index);
    } catch (...) {
      errors[static_cast<std::size_t>(index)] = std::current_exception();
    }
  };
  if (!arena_ || count <= 1) {
    for (int index = 0; index < count; ++index) run_one(index);
  } else if (kPlainThreads) {
    // ThreadSanitizer builds only: threads_ − 1 helper std::threads and the caller take the
    // tasks in turn, as the arena's threads_ slots do, so that TSan sees every hand-over
    // (oneTBB's own is inside a library it cannot see).
    std::atomic<int> next{0};
    auto drain = [&] {
      for (int index = next++; index < count; index = next++) run_one(index);
    };
    std::vector<std::thread> helpers;
    for (int t = 1; t < std::min(threads_, count); ++t) helpers.emplace_back(drain);
    drain();
    for (std::thread& helper : helpers) helper.join();
  } else {
    // One task per index (grain 1): the work items are few and large (a Reynolds solve each).
    arena_->arena.execute([&] {
      tbb::parallel_for(
          tbb::blocked_range<int>(0, count, 1),
          [&](const tbb::blocked_range<int>& range) {
            for (int index = range.begin(); index < range.end(); ++index) {
              run_one(index);
            }
          },
          tbb::simple_partitioner());
    });
  }
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }
}

}  // namespace filmdyn
