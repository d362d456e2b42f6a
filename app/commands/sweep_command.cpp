// `filmdyn sweep`: several runs (speeds × models) in parallel, one folder each (results.csv,
// summary.json, plots/), plus a comparison: comparison.csv, comparison.md and overlay plots.
// The runs are computed by core (engine::SweepRunner); plots are drawn here on the main thread.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>

#include "app/commands/commands.hpp"
#include "app/commands/run_common.hpp"
#include "core/engine/sweep.hpp"
#include "core/input_error.hpp"
#include "core/io/run_comparison.hpp"
#include "ui/plots/plot_export.hpp"
#include "ui/run/sample_conversion.hpp"

namespace filmdyn::cli {

namespace {

std::vector<std::string> SplitList(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    if (!item.empty()) items.push_back(item);
  }
  return items;
}

std::string RpmText(double rpm) {
  std::ostringstream out;
  out << rpm;
  return out.str();
}

}  // namespace

Command MakeSweepCommand() {
  Command command;
  command.name = "sweep";
  command.summary = "several runs (speeds x models) in parallel, with a comparison table and plots";
  command.positional_usage = "[CASE.json]";
  command.max_positional = 1;
  command.needs_gui_application = true;
  command.options = {
      {"rpm", "N1,N2,...", "crank speeds [rpm] (default: 1000,2000,4000,6000)"},
      {"models", "M1,M2,...", "skirt-lbrbe, only-skirt, only-lbrbe, ideal (default: the case's)"},
      {"jobs", "N", "runs computed at the same time (default: number of cores)"},
      {"out", "DIR", "folder of the sweep (default: ./results/sweep-<case>)"},
      {"set", "KEY=VALUE", "override a case field by its dotted JSON path", true},
      {"time-limit", "S", "wall-time limit of each run [s], keeping what was computed"},
      {"no-fields", "", "do not write the runs' fields/ (VTU/PVD per output step)"},
      {"quiet", "", "no progress on stderr"}};
  command.details =
      "Each run writes <DIR>/<case>-<model>-<rpm>/ like `filmdyn run`; the sweep adds\n"
      "<DIR>/comparison.csv (SI), <DIR>/comparison.md (display units) and <DIR>/plots/ with all\n"
      "runs overlaid. Ctrl-C stops every run cleanly with its partial results written.\n"
      "Example:\n  filmdyn sweep --rpm 1000,2000,4000,6000 --models skirt-lbrbe --jobs 2";
  command.run = [](const Args& args, Streams& streams) {
    const std::string case_path = args.positional().empty() ? "" : args.positional()[0];
    const io::LoadedCase loaded = io::LoadCase(case_path, args.Values("set"));
    const engine::EngineCase& c = loaded.value;

    const std::vector<double> speeds =
        ParseDoubleList("--rpm", args.Value("rpm").value_or("1000,2000,4000,6000"));
    std::vector<engine::Model> models;
    if (const auto list = args.Value("models")) {
      for (const auto& name : SplitList(*list)) models.push_back(engine::ParseModel(name));
      if (models.empty()) throw InputError("--models", "'" + *list + "'", "names no model");
    } else {
      models.push_back(ModelFromCase(c));
    }
    const long jobs =
        args.Integer("jobs").value_or(std::max(1u, std::thread::hardware_concurrency()));
    if (jobs < 1 || jobs > 256) {
      throw InputError("--jobs", std::to_string(jobs), "must be an integer in [1, 256]");
    }
    const double time_limit = args.Double("time-limit").value_or(0.0);
    const std::filesystem::path out = args.Value("out")
                                          ? std::filesystem::path(*args.Value("out"))
                                          : std::filesystem::path("results") / ("sweep-" + c.name);

    // Every configuration is built (and checked) before anything starts. Each run evaluates its
    // two film joints side by side only when the cores allow it beside the other runs.
    const long at_once = std::min<long>(jobs, static_cast<long>(models.size() * speeds.size()));
    const long cores = std::max(1u, std::thread::hardware_concurrency());
    std::vector<engine::SweepJob> sweep_jobs;
    for (engine::Model model : models) {
      for (double rpm : speeds) {
        engine::SweepJob job;
        job.config = BuildRunConfig(loaded, model, rpm, std::nullopt, time_limit);
        job.config.threads = cores >= 2 * at_once ? 2 : 1;
        job.case_name = c.name;
        job.write_fields = !args.Has("no-fields");
        job.output_folder = out / (c.name + "-" + engine::ModelName(model) + "-" + RpmText(rpm));
        sweep_jobs.push_back(std::move(job));
      }
    }
    std::filesystem::create_directories(out);

    const bool quiet = args.Has("quiet");
    const InterruptGuard interrupt;
    engine::SweepRunner runner(std::move(sweep_jobs), static_cast<int>(jobs), interrupt.flag());
    std::vector<ui::RunHandle> finished_runs;
    std::vector<std::filesystem::path> folders;
    int incomplete = 0, done = 0;
    for (int index; (index = runner.WaitNext(std::chrono::milliseconds(250))) != -1;) {
      if (index == -2) {
        if (!quiet) {
          const auto fractions = runner.Fractions();
          double total = 0;
          for (double f : fractions) total += f;
          char line[120];
          std::snprintf(line, sizeof line, "\rsweep: %d/%d runs done, %3.0f %% overall ", done,
                        runner.size(), 100.0 * total / std::max<std::size_t>(1, fractions.size()));
          streams.err << line << std::flush;
        }
        continue;
      }
      ++done;
      const engine::SweepJob& job = runner.job(index);
      const engine::SweepOutcome& outcome = runner.outcome(index);
      const std::string label =
          engine::ModelName(job.config.model) + " " + RpmText(job.config.rpm) + " rpm";
      if (!quiet) streams.err << "\n";
      if (!outcome.error.empty()) {
        ++incomplete;
        streams.err << "sweep: " << label << ": failed: " << outcome.error << "\n";
        continue;
      }
      folders.push_back(job.output_folder);
      if (const std::string error = WriteRunPlots(job.output_folder, job.config, outcome.rows);
          !error.empty()) {
        streams.err << "sweep: " << label << ": plots not written: " << error << "\n";
      }
      finished_runs.push_back(ui::FinishedRun(
          index + 1, {job.config.engine_case, engine::ModelName(job.config.model), job.config.rpm},
          ui::RunSamplesFromRows(outcome.rows)));
      const bool complete = outcome.result.status == engine::RunStatus::kCompleted;
      if (!complete) ++incomplete;
      streams.err << "sweep: " << label << ": " << engine::StatusName(outcome.result.status) << ", "
                  << outcome.result.cycles << " cycles, " << outcome.result.wall_time << " s"
                  << (complete ? "" : " — " + outcome.result.message) << "\n";
    }

    // The comparison, from the folders' summary.json files, in the order runs were requested.
    std::sort(folders.begin(), folders.end());
    std::vector<io::ComparisonRow> rows;
    for (const auto& folder : folders) rows.push_back(io::ReadComparisonRow(folder));
    std::sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) {
      return a.model != b.model ? a.model < b.model : a.rpm < b.rpm;
    });
    {
      std::ofstream csv(out / "comparison.csv");
      io::WriteComparisonCsv(csv, rows);
      if (!csv) throw std::runtime_error("cannot write " + (out / "comparison.csv").string());
    }
    const std::string table = io::ComparisonMarkdown(rows);
    std::ofstream(out / "comparison.md") << "# Sweep of " << c.name << "\n\n" << table;
    QString plot_error;
    ui::ExportStandardPlots(finished_runs, QString::fromStdString((out / "plots").string()),
                            &plot_error);
    if (!plot_error.isEmpty()) {
      streams.err << "sweep: comparison plots not written: " << plot_error.toStdString() << "\n";
    }
    streams.out << table;
    streams.err << "sweep: " << done << " runs, " << incomplete << " incomplete; results in "
                << out.string() << "\n";
    return incomplete == 0 ? 0 : 1;
  };
  return command;
}

}  // namespace filmdyn::cli
