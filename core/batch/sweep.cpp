#include "core/batch/sweep.hpp"

#include <algorithm>
#include <exception>

#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include "core/io/field_output.hpp"
#include "core/io/output_files.hpp"
#include "core/io/results_writer.hpp"

namespace filmdyn::batch {

struct SweepRunner::Tasks {
  explicit Tasks(int slots)
      : slots(slots),
        // The runs execute on TBB's workers while the caller's thread only collects them: allow
        // one worker per slot (on a 2-core machine TBB starts one worker by default). A run's
        // film joints and skirt panels are nested tasks on the same workers: with every slot
        // busy they run inline, so nested levels never add threads.
        parallelism(tbb::global_control::max_allowed_parallelism,
                    std::max<std::size_t>(tbb::info::default_concurrency(),
                                          static_cast<std::size_t>(slots) + 1)),
        arena(slots, 0) {}
  int slots;  // runs at the same time
  tbb::global_control parallelism;
  tbb::task_arena arena;
  tbb::task_group group;  // the slots' work loops, run in `arena`
};

SweepRunner::SweepRunner(std::vector<SweepJob> jobs, int threads, const std::atomic<bool>* cancel)
    : jobs_(std::move(jobs)),
      outcomes_(jobs_.size()),
      cancel_(cancel),
      fractions_(jobs_.size()),
      tasks_(std::make_unique<Tasks>(
          std::clamp(threads, 1, std::max(1, static_cast<int>(jobs_.size()))))) {
  for (auto& f : fractions_) f = 0.0;
  // Jobs are taken in order; each slot works through them until none is left.
  for (int slot = 0; slot < tasks_->slots; ++slot) {
    tasks_->arena.execute([this] { tasks_->group.run([this] { Work(); }); });
  }
}

SweepRunner::~SweepRunner() {
  tasks_->arena.execute([this] { tasks_->group.wait(); });
}

void SweepRunner::Work() {
  for (int index = next_job_++; index < size(); index = next_job_++) {
    SweepOutcome outcome;
    // Cancelled before its turn: nothing of it runs, and its folder (where an earlier run's
    // results may be, to be replaced) is left as it is.
    if (cancel_ && cancel_->load()) {
      outcome.not_started = true;
    } else {
      try {
        Run(index, &outcome);
      } catch (const std::exception& error) {
        outcome.error = error.what();
      }
    }
    outcome.finished = true;
    fractions_[index] = 1.0;
    {
      std::lock_guard lock(mutex_);
      outcomes_[index] = std::move(outcome);
      finished_.push_back(index);
    }
    finished_cv_.notify_all();
  }
}

void SweepRunner::Run(int index, SweepOutcome* outcome) {
  const engine::RunMonitor monitor = [this, index](const engine::RunProgress& p) {
    fractions_[index] = std::min(p.fraction, 1.0);
    return true;
  };
  const SweepJob& job = jobs_[index];
  io::FieldRecorder fields;
  engine::RunConfig config = job.config;
  if (job.write_fields) fields.Attach(&config);
  // Memory for this run with what the running ones already hold, before its folder is used.
  engine::CheckRunMemory(config);
  // Locked for the run; marked "running" until its summary is written last.
  const io::OutputFolder folder(
      job.output_folder,
      job.overwrite ? io::OutputFolder::Reuse::kReplace : io::OutputFolder::Reuse::kRefuse,
      "--out");
  io::MarkRunStarted(job.output_folder, job.case_name, job.config);
  try {
    outcome->result = engine::RunJob(config, monitor, cancel_);
  } catch (const std::exception& e) {
    // The folder says why, not "running" (a run killed).
    io::MarkRunFailed(job.output_folder, job.case_name, job.config, e.what());
    throw;
  }
  outcome->rows = io::WriteRunFolder(job.output_folder, job.case_name, job.config, outcome->result,
                                     [&](const std::vector<io::OutputRow>&) {
                                       fields.WriteReported(job.output_folder / "fields",
                                                            outcome->result.samples);
                                     });
  if (!job.keep_results) {
    outcome->rows = {};
    outcome->result.samples = {};
    outcome->result.motion = {};
  }
}

int SweepRunner::WaitNext(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  if (returned_ == size()) return -1;
  if (!finished_cv_.wait_for(lock, timeout, [this] { return !finished_.empty(); })) return -2;
  const int index = finished_.front();
  finished_.pop_front();
  ++returned_;
  return index;
}

std::vector<double> SweepRunner::Fractions() const {
  std::vector<double> out;
  out.reserve(fractions_.size());
  for (const auto& f : fractions_) out.push_back(f.load());
  return out;
}

}  // namespace filmdyn::batch
