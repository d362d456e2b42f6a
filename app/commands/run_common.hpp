#pragma once
/// @file What `filmdyn run`, `sweep` and `reproduce` share: building a run's configuration from
/// the loaded case and options, the run's plots, batches of runs with their comparison, and
/// Ctrl-C handling.
#include <QString>
#include <atomic>
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "app/cli/command.hpp"
#include "core/engine/run_job.hpp"
#include "core/batch/sweep.hpp"
#include "core/io/case_file.hpp"
#include "core/io/output_files.hpp"
#include "core/io/results_writer.hpp"
#include "ui/plots/plot_run.hpp"

namespace filmdyn::cli {

/// A run configuration: the cylinder pressure from `pressure_csv` when given, else the case's
/// curve for `rpm`; `time_limit` [s] (0 = none). Throws InputError naming the option/field.
/// The --time-limit option [s]: 0 when not given (no limit); given, it must be > 0 (a 0 would
/// silently mean no limit).
double TimeLimitOption(const Args& args);

engine::RunConfig BuildRunConfig(const io::LoadedCase& loaded, engine::Model model, double rpm,
                                 const std::optional<std::string>& pressure_csv, double time_limit);

/// Renders the standard plots of one run (rows as written to results.csv, with the run's motion
/// between them) into `<folder>/plots`. Returns an empty string or the reason it failed.
std::string WriteRunPlots(const std::filesystem::path& folder, const engine::RunConfig& config,
                          const engine::RunResult& result, const std::vector<io::OutputRow>& rows);

/// Prints the engineering warnings of a finished run (io::RunWarnings, the list summary.json
/// holds), one line each: "<prefix>: warning: <message>".
void PrintRunWarnings(const engine::RunConfig& config, const engine::RunResult& result,
                      const std::string& prefix, std::ostream& out);

/// The --set option of every command that reads a case (LoadCaseArgument applies it).
OptionSpec CaseSetOption();

/// The case named by the command's optional CASE.json positional (the embedded default case
/// without one), with the --set overrides applied; the reader's notes (an older key read as its
/// replacement) go to *notes, one line each. Throws InputError naming the file or field.
io::LoadedCase LoadCaseArgument(const Args& args, std::ostream* notes = nullptr);

/// One run of a sweep or of `reproduce`: its configuration (checked now), written to
/// `parent / <case>-<model>-<rpm>` (the folder name `filmdyn run` uses).
batch::SweepJob SweepJobFor(const io::LoadedCase& loaded, engine::Model model, double rpm,
                             double time_limit, bool write_fields,
                             const std::filesystem::path& parent);

/// "6000", "1500.5": a speed as it appears in folder names and messages.
std::string RpmText(double rpm);

/// The output folders of a batch (sweep, reproduce), checked before any run starts: `out`
/// locked for the batch's lifetime (the returned object), the same run twice (same model and
/// speed) an input error naming `points_option`, and any run folder holding an earlier run
/// refused unless `overwrite` (then each job replaces FilmDyn's files in its folder).
/// `explicit_out`: --out was given; the default folder under results/ is replaced instead.
std::unique_ptr<io::OutputFolder> PrepareBatchFolders(const std::filesystem::path& out,
                                                      std::vector<batch::SweepJob>& jobs,
                                                      bool explicit_out, bool overwrite,
                                                      const std::string& points_option);

/// --jobs: runs computed at the same time (default: the number of cores), checked to [1, 256].
int JobsOption(const Args& args);

/// Throws InputError("--set KEY", value, `why`) for the first --set of one of `keys`: a field
/// the command sets itself for each run, which the --set would not reach.
void RefuseSets(const Args& args, std::initializer_list<const char*> keys, const std::string& why);

/// The runs of a finished batch, in job order.
struct BatchOutcome {
  std::vector<batch::SweepJob> jobs;
  std::vector<std::optional<ui::PlotRun>> runs;  ///< empty where the run could not start
  /// Per job, why it has no run folder to compare: "failed: <error>" (it threw: bad input, a
  /// file it could not write), "not started" (stopped before its turn); empty when it ran.
  std::vector<std::string> not_run;
  int incomplete = 0;  ///< failed, cancelled, time limit, not converged or not started
};

/// Runs `jobs`, `parallel` at a time (each with 2 film threads only when the cores allow it
/// beside the others), Ctrl-C stopping them cleanly; a progress line on stderr unless `quiet`,
/// one line per finished run prefixed `prefix: `, and each run's plots/ written.
BatchOutcome RunBatch(std::vector<batch::SweepJob> jobs, int parallel, bool quiet,
                      const std::string& prefix, Streams& streams);

/// The comparison of the batch's runs `indices` (all when empty) into `out`: comparison.csv (SI),
/// comparison.md (`title`, then `intro` when given — e.g. what the runs share — and the table in
/// display units) and plots/ with the runs overlaid. Returns the table.
std::string WriteComparison(const std::filesystem::path& out, const BatchOutcome& batch,
                            const std::string& title, const std::string& prefix, Streams& streams,
                            const std::vector<int>& indices = {}, const std::string& intro = {});

/// One sentence for a comparison or report: the case the runs start from and the --set changes
/// they share ("Case: the embedded default case; changed for every run: `a = 1`, `b = x`.").
std::string CaseAndChangesText(const io::LoadedCase& loaded, const std::vector<std::string>& sets);

/// Installs handlers of SIGINT (Ctrl-C), SIGTERM and SIGHUP for its lifetime: each sets flag() so
/// runs stop cleanly with their partial results written.
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
  const std::atomic<bool>* flag() const;

 private:
  void (*previous_[3])(int);
};

}  // namespace filmdyn::cli
