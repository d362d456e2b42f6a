#include "app/commands/run_common.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>

#include "core/base/input_error.hpp"
#include "core/io/pressure_csv.hpp"
#include "core/io/run_comparison.hpp"
#include "core/io/run_warnings.hpp"
#include "ui/plots/plot_export.hpp"

namespace filmdyn::cli {

namespace {
std::atomic<bool> g_interrupted{false};
extern "C" void OnInterrupt(int) { g_interrupted = true; }
}  // namespace

double TimeLimitOption(const Args& args) {
  const std::optional<double> limit = args.Double("time-limit");
  if (!limit) return 0.0;
  RequirePositive("--time-limit", *limit, "s (leave the option out for no limit)");
  return *limit;
}

engine::RunConfig BuildRunConfig(const io::LoadedCase& loaded, engine::Model model, double rpm,
                                 const std::optional<std::string>& pressure_csv,
                                 double time_limit) {
  RequireInRange("--rpm", rpm, 0.0, 30000.0, true, false, "rpm");
  engine::PressureCurve pressure = pressure_csv ? io::ReadPressureCsvFile(*pressure_csv)
                                                : io::PressureCurveForSpeed(loaded, rpm);
  engine::RunConfig config =
      engine::MakeRunConfig(loaded.value, model, rpm, std::move(pressure), loaded.directory);
  if (time_limit != 0.0) {
    RequirePositive("--time-limit", time_limit, "s");
    config.wall_time_limit = time_limit;
  }
  return config;
}

std::string WriteRunPlots(const std::filesystem::path& folder, const engine::RunConfig& config,
                          const engine::RunResult& result, const std::vector<io::OutputRow>& rows) {
  QString error;
  ui::PlotRun run = ui::PlotRunFromRows(1, config.engine_case, engine::ModelName(config.model),
                                        config.rpm, rows, io::MotionRows(result, config.model));
  // A run that did not complete says so in every chart's legend: what is drawn is not a
  // periodic cycle (or not a whole one).
  if (result.status == engine::RunStatus::kNotConverged) {
    run.label += QStringLiteral(" (not periodic)");
  } else if (result.status != engine::RunStatus::kCompleted) {
    run.label += QStringLiteral(" (%1: incomplete%2)")
                     .arg(QString::fromStdString(engine::StatusName(result.status)),
                          result.reported_cycle == 0 ? QStringLiteral(", run-in only") : QString());
  }
  ui::ExportStandardPlots({run}, QString::fromStdString((folder / "plots").string()), &error);
  return error.toStdString();
}

void PrintRunWarnings(const engine::RunConfig& config, const engine::RunResult& result,
                      const std::string& prefix, std::ostream& out) {
  for (const io::RunWarning& w : io::RunWarnings(config, result)) {
    out << prefix << ": warning: " << w.message << "\n";
  }
}

OptionSpec CaseSetOption() {
  return {"set", "KEY=VALUE", "override a case field by its dotted JSON path (a list: KEY=[a,b])",
          true};
}

io::LoadedCase LoadCaseArgument(const Args& args, std::ostream* notes) {
  const std::string case_path = args.positional().empty() ? "" : args.positional()[0];
  io::LoadedCase loaded = io::LoadCase(case_path, args.Values("set"));
  if (notes) {
    for (const std::string& note : loaded.notes) *notes << "filmdyn: note: " << note << "\n";
  }
  return loaded;
}

batch::SweepJob SweepJobFor(const io::LoadedCase& loaded, engine::Model model, double rpm,
                            double time_limit, bool write_fields,
                            const std::filesystem::path& parent) {
  batch::SweepJob job;
  job.config = BuildRunConfig(loaded, model, rpm, std::nullopt, time_limit);
  job.case_name = loaded.value.name;
  job.write_fields = write_fields;
  job.output_folder = parent / io::DefaultOutputFolder(loaded.value.name, model, rpm).filename();
  return job;
}

std::string RpmText(double rpm) {
  std::ostringstream out;
  out << rpm;
  return out.str();
}

std::unique_ptr<io::OutputFolder> PrepareBatchFolders(const std::filesystem::path& out,
                                                      std::vector<batch::SweepJob>& jobs,
                                                      bool explicit_out, bool overwrite,
                                                      const std::string& points_option) {
  const io::OutputFolder::Reuse reuse = io::OutputFolder::ReuseFor(explicit_out, overwrite);
  const bool replace = reuse == io::OutputFolder::Reuse::kReplace;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    for (std::size_t k = 0; k < i; ++k) {
      if (jobs[k].output_folder == jobs[i].output_folder) {
        throw InputError(points_option,
                         engine::ModelName(jobs[i].config.model) + " at " +
                             RpmText(jobs[i].config.rpm) + " rpm",
                         "is given twice; each run of a batch must differ in model or speed");
      }
    }
  }
  auto folder = std::make_unique<io::OutputFolder>(out, reuse, "--out");
  for (batch::SweepJob& job : jobs) {
    if (!replace && io::OutputFolder::HoldsEarlierRun(job.output_folder)) {
      io::OutputFolder::RefuseEarlierRun(job.output_folder, "--out");
    }
    job.overwrite = replace;
  }
  return folder;
}

void RefuseSets(const Args& args, std::initializer_list<const char*> keys, const std::string& why) {
  for (const std::string& set : args.Values("set")) {
    const std::string key = set.substr(0, set.find('='));
    for (const char* refused : keys) {
      if (key == refused) {
        throw InputError("--set " + key,
                         set.find('=') == std::string::npos ? set : set.substr(set.find('=') + 1),
                         why);
      }
    }
  }
}

int JobsOption(const Args& args) {
  const long jobs =
      args.Integer("jobs").value_or(std::max(1u, std::thread::hardware_concurrency()));
  if (jobs < 1 || jobs > 256) {
    throw InputError("--jobs", std::to_string(jobs), "must be an integer in [1, 256]");
  }
  return static_cast<int>(jobs);
}

BatchOutcome RunBatch(std::vector<batch::SweepJob> jobs, int parallel, bool quiet,
                      const std::string& prefix, Streams& streams) {
  BatchOutcome batch;
  const long at_once = std::min<long>(parallel, static_cast<long>(jobs.size()));
  const long cores = std::max(1u, std::thread::hardware_concurrency());
  for (batch::SweepJob& job : jobs) job.config.threads = cores >= 2 * at_once ? 2 : 1;
  batch.jobs = jobs;
  batch.runs.resize(jobs.size());
  batch.not_run.resize(jobs.size());
  const InterruptGuard interrupt;
  batch::SweepRunner runner(std::move(jobs), parallel, interrupt.flag());
  int done = 0;
  for (int index; (index = runner.WaitNext(std::chrono::milliseconds(250))) != -1;) {
    if (index == -2) {
      if (!quiet) {
        const auto fractions = runner.Fractions();
        double total = 0;
        for (double f : fractions) total += f;
        streams.err << fmt::format("\r{}: {}/{} runs done, {:3.0f} % overall ", prefix, done,
                                   runner.size(),
                                   100.0 * total / std::max<std::size_t>(1, fractions.size()))
                    << std::flush;
      }
      continue;
    }
    ++done;
    const batch::SweepJob& job = runner.job(index);
    const batch::SweepOutcome& outcome = runner.outcome(index);
    const std::string label =
        engine::ModelName(job.config.model) + " " + RpmText(job.config.rpm) + " rpm";
    if (!quiet) streams.err << "\n";
    if (outcome.not_started) {
      ++batch.incomplete;
      batch.not_run[index] = "not started";
      streams.err << prefix << ": " << label
                  << ": not started (stopped before its turn; its folder is as it was)\n";
      continue;
    }
    if (!outcome.error.empty()) {
      ++batch.incomplete;
      batch.not_run[index] = "failed: " + outcome.error;
      streams.err << prefix << ": " << label << ": failed: " << outcome.error << "\n";
      continue;
    }
    if (const std::string error =
            WriteRunPlots(job.output_folder, job.config, outcome.result, outcome.rows);
        !error.empty()) {
      streams.err << prefix << ": " << label << ": plots not written: " << error << "\n";
    }
    batch.runs[index] = ui::PlotRunFromRows(
        index + 1, job.config.engine_case, engine::ModelName(job.config.model), job.config.rpm,
        outcome.rows, io::MotionRows(outcome.result, job.config.model));
    const bool complete = outcome.result.status == engine::RunStatus::kCompleted;
    if (!complete) ++batch.incomplete;
    streams.err << prefix << ": " << label << ": " << engine::StatusName(outcome.result.status)
                << ", " << outcome.result.cycles << " cycles, " << outcome.result.wall_time << " s"
                << (complete ? "" : " — " + outcome.result.message) << "; "
                << outcome.result.error_estimate.Summary() << "\n";
    PrintRunWarnings(job.config, outcome.result, prefix + ": " + label, streams.err);
  }
  return batch;
}

std::string WriteComparison(const std::filesystem::path& out, const BatchOutcome& batch,
                            const std::string& title, const std::string& prefix, Streams& streams,
                            const std::vector<int>& indices, const std::string& intro) {
  std::vector<int> chosen = indices;
  if (chosen.empty()) {
    for (int k = 0; k < static_cast<int>(batch.jobs.size()); ++k) chosen.push_back(k);
  }
  std::vector<io::ComparisonRow> rows;
  std::vector<ui::PlotRun> runs;
  for (int k : chosen) {
    const batch::SweepJob& job = batch.jobs[k];
    if (!batch.runs[k]) {
      // No run to read: a row that says why, every figure empty.
      io::ComparisonRow row;
      row.folder = job.output_folder.filename().string();
      row.model = engine::ModelName(job.config.model);
      row.rpm = job.config.rpm;
      const std::string& why = batch.not_run[k];
      row.status = why.rfind("failed", 0) == 0 ? "failed" : "not started";
      row.figures.assign(io::ComparisonFigures().size(), std::nullopt);
      row.notes = {row.folder + ": " + (why.empty() ? std::string("no results") : why)};
      rows.push_back(std::move(row));
      continue;
    }
    rows.push_back(io::ReadComparisonRow(job.output_folder));
    runs.push_back(*batch.runs[k]);
  }
  std::sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) {
    return a.model != b.model ? a.model < b.model : a.rpm < b.rpm;
  });
  std::filesystem::create_directories(out);
  std::ostringstream csv;
  io::WriteComparisonCsv(csv, rows);
  io::WriteFileAtomically(out / "comparison.csv", csv.str());
  const std::string table = io::ComparisonMarkdown(rows);
  io::WriteFileAtomically(out / "comparison.md",
                          "# " + title + "\n\n" + (intro.empty() ? "" : intro + "\n\n") + table);
  QString plot_error;
  ui::ExportStandardPlots(runs, QString::fromStdString((out / "plots").string()), &plot_error);
  if (!plot_error.isEmpty()) {
    streams.err << prefix << ": comparison plots not written: " << plot_error.toStdString() << "\n";
  }
  return table;
}

std::string CaseAndChangesText(const io::LoadedCase& loaded, const std::vector<std::string>& sets) {
  std::string text = "Case: " + (loaded.directory.empty() ? std::string("the embedded default case")
                                                          : loaded.source);
  if (!sets.empty()) text += "; changed for every run: " + io::OverridesText(sets);
  return text + ".";
}

namespace {
constexpr int kStopSignals[3] = {SIGINT, SIGTERM, SIGHUP};
}  // namespace

InterruptGuard::InterruptGuard() {
  g_interrupted = false;
  for (int k = 0; k < 3; ++k) previous_[k] = std::signal(kStopSignals[k], OnInterrupt);
}

InterruptGuard::~InterruptGuard() {
  for (int k = 0; k < 3; ++k) std::signal(kStopSignals[k], previous_[k]);
}

const std::atomic<bool>* InterruptGuard::flag() const { return &g_interrupted; }

}  // namespace filmdyn::cli
