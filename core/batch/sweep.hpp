#pragma once
/// @file Several runs in parallel (`filmdyn sweep`): a TBB task arena of `threads` slots takes
/// jobs in order; each job is a complete `RunJob` plus its output folder. The caller's thread
/// collects finished jobs one by one (e.g. to render plots, which Qt allows on the main thread
/// only). One cancel flag stops every running job cleanly with its partial results written; the
/// jobs not yet started then never start (SweepOutcome::not_started), their folders untouched.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <filesystem>
#include <mutex>
#include <string>
#include <memory>
#include <vector>

#include "core/engine/run_job.hpp"
#include "core/io/results_writer.hpp"

namespace filmdyn::batch {

struct SweepJob {
  engine::RunConfig config;
  std::string case_name;
  std::filesystem::path output_folder;
  bool write_fields = true;  ///< fields/ (HDF5 + XDMF of the reported cycle) in the output folder
  /// An earlier run's files in output_folder: replaced (true) or the job fails naming the
  /// folder (false; the sweep command checks every folder before it starts).
  bool overwrite = false;
  /// The outcome keeps the run's samples, motion and rows (false: only its status, counters and
  /// figures — a study of thousands of runs reads them back from the folders).
  bool keep_results = true;
};

struct SweepOutcome {
  engine::RunResult result;
  std::vector<io::OutputRow> rows;  ///< as written to results.csv
  std::string error;                ///< non-empty when the job threw (bad input, I/O)
  /// Cancelled before its turn came: the job never started and its output folder (an earlier
  /// run's results in it included) was not touched.
  bool not_started = false;
  bool finished = false;
};

class SweepRunner {
 public:
  /// Starts min(threads, jobs) runs at once. `cancel` may be null.
  SweepRunner(std::vector<SweepJob> jobs, int threads, const std::atomic<bool>* cancel);
  ~SweepRunner();  ///< cancels nothing, waits for the workers
  SweepRunner(const SweepRunner&) = delete;
  SweepRunner& operator=(const SweepRunner&) = delete;

  /// Waits up to `timeout` for another finished job and returns its index; -1 once every job
  /// was returned, -2 on timeout (so the caller can print progress meanwhile).
  int WaitNext(std::chrono::milliseconds timeout);
  const SweepJob& job(int index) const { return jobs_[index]; }
  const SweepOutcome& outcome(int index) const { return outcomes_[index]; }
  int size() const { return static_cast<int>(jobs_.size()); }
  /// Progress of every job in [0, 1] (1 when finished), for a status line.
  std::vector<double> Fractions() const;

 private:
  void Work();
  /// Job `index`, from its folder to its summary, into *outcome; throws what the job throws.
  void Run(int index, SweepOutcome* outcome);

  std::vector<SweepJob> jobs_;
  std::vector<SweepOutcome> outcomes_;
  const std::atomic<bool>* cancel_;
  std::atomic<int> next_job_{0};
  std::vector<std::atomic<double>> fractions_;
  mutable std::mutex mutex_;
  std::condition_variable finished_cv_;
  std::deque<int> finished_;
  int returned_ = 0;
  // The TBB arena and task group running the slots' work loops (kept out of this header: Qt's
  // `emit` macro clashes with TBB's headers in files that include both).
  struct Tasks;
  std::unique_ptr<Tasks> tasks_;
};

}  // namespace filmdyn::batch
