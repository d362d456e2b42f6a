#include "core/batch/sweep.hpp"

#include <algorithm>
#include <exception>

#include "core/io/field_output.hpp"

namespace filmdyn::batch {

SweepRunner::SweepRunner(std::vector<SweepJob> jobs, int threads, const std::atomic<bool>* cancel)
    : jobs_(std::move(jobs)), outcomes_(jobs_.size()), cancel_(cancel), fractions_(jobs_.size()) {
  for (auto& f : fractions_) f = 0.0;
  const int n = std::clamp(threads, 1, std::max(1, size()));
  workers_.reserve(n);
  for (int i = 0; i < n; ++i) workers_.emplace_back([this] { Work(); });
}

SweepRunner::~SweepRunner() {
  for (auto& worker : workers_) worker.join();
}

void SweepRunner::Work() {
  for (int index = next_job_++; index < size(); index = next_job_++) {
    SweepOutcome outcome;
    try {
      const engine::RunMonitor monitor = [this, index](const engine::RunProgress& p) {
        fractions_[index] = std::min(p.fraction, 1.0);
        return true;
      };
      const SweepJob& job = jobs_[index];
      io::FieldRecorder fields;
      engine::RunConfig config = job.config;
      if (job.write_fields) config.field_callback = fields.Callback();
      outcome.result = engine::RunJob(config, monitor, cancel_);
      outcome.rows =
          io::WriteRunFolder(job.output_folder, job.case_name, job.config, outcome.result);
      fields.Write(job.output_folder / "fields");
    } catch (const std::exception& error) {
      outcome.error = error.what();
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
