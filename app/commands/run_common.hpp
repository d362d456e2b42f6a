#pragma once
/// @file What `filmdyn run` and `filmdyn sweep` share: building a run's configuration from the
/// loaded case and options, the run's plots, and Ctrl-C handling.
#include <QString>
#include <atomic>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/engine/run_job.hpp"
#include "core/io/case_file.hpp"
#include "core/io/results_writer.hpp"

namespace filmdyn::cli {

/// The model the case's joint settings describe (used when --model/--models is not given).
engine::Model ModelFromCase(const engine::EngineCase& c);

/// A run configuration: the cylinder pressure from `pressure_csv` when given, else the case's
/// curve for `rpm`; `time_limit` [s] (0 = none). Throws InputError naming the option/field.
engine::RunConfig BuildRunConfig(const io::LoadedCase& loaded, engine::Model model, double rpm,
                                 const std::optional<std::string>& pressure_csv, double time_limit);

/// Renders the standard plots of one run (rows as written to results.csv) into
/// `<folder>/plots`. Returns an empty string or the reason it failed.
std::string WriteRunPlots(const std::filesystem::path& folder, const engine::RunConfig& config,
                          const std::vector<io::OutputRow>& rows);

/// Installs a SIGINT handler for its lifetime: Ctrl-C sets flag() so runs stop cleanly with
/// their partial results written.
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
  const std::atomic<bool>* flag() const;

 private:
  void (*previous_)(int);
};

}  // namespace filmdyn::cli
