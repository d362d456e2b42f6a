// `filmdyn sweep`: several runs (speeds × models) in parallel, one folder each (results.csv,
// summary.json, plots/), plus a comparison: comparison.csv, comparison.md and overlay plots.
// The runs are computed by core (batch::SweepRunner); plots are drawn here on the main thread.
#include <algorithm>
#include <sstream>

#include "app/commands/commands.hpp"
#include "app/commands/run_common.hpp"
#include "core/base/input_error.hpp"

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

}  // namespace

Command MakeSweepCommand() {
  Command command;
  command.name = "sweep";
  command.summary = "several runs (speeds x models) in parallel, with a comparison table and plots";
  command.positional_usage = "[CASE.json]";
  command.max_positional = 1;
  command.needs_gui_application = true;
  command.options = {
      {"rpm", "N1,N2,...",
       "crank speeds [rpm] (default: the speeds of the case's pressure curves; the default "
       "case's 1000,2000,4000,6000)"},
      {"models", "M1,M2,...", "skirt-lbrbe, only-skirt, only-lbrbe, ideal (default: the case's)"},
      {"jobs", "N", "runs computed at the same time (default: number of cores)"},
      {"out", "DIR", "folder of the sweep (default: ./results/sweep-<case>)"},
      CaseSetOption(),
      {"time-limit", "S", "wall-time limit of each run [s], keeping what was computed"},
      {"no-fields", "", "do not write the runs' fields/ (HDF5 + XDMF per joint)"},
      {"overwrite", "", "--out may hold an earlier sweep: FilmDyn's files in it are replaced"},
      {"quiet", "", "no progress on stderr"}};
  command.details =
      "Each run writes <DIR>/<case>-<model>-<rpm>/ like `filmdyn run`; the sweep adds\n"
      "<DIR>/comparison.csv (SI), <DIR>/comparison.md (display units) and <DIR>/plots/ with all\n"
      "runs overlaid. Ctrl-C, SIGTERM or SIGHUP stop every run cleanly with its partial results\n"
      "written. A --out folder holding an earlier sweep is refused without --overwrite; the\n"
      "same speed and model given twice is refused.\n"
      "Example:\n  filmdyn sweep --rpm 1000,2000,4000,6000 --models skirt-lbrbe --jobs 2";
  command.run = [](const Args& args, Streams& streams) {
    // What the sweep itself sets for each run: a --set of it would be replaced without a word.
    RefuseSets(args, {"operating.rpm"},
               "is each run's speed in a sweep: give the speeds with --rpm");
    if (args.Has("models")) {
      RefuseSets(args, {"skirt.model", "big_end.model"},
                 "is set by each run's model (--models): leave one of the two out");
    }
    const io::LoadedCase loaded = LoadCaseArgument(args, &streams.err);
    const engine::EngineCase& c = loaded.value;

    // Without --rpm: the speeds the case's cylinder pressure is given at (its pressure curves').
    std::vector<double> speeds;
    if (const auto list = args.Value("rpm")) {
      speeds = ParseDoubleList("--rpm", *list);
    } else {
      for (const engine::PressureCurveSource& curve : c.pressure_curves)
        speeds.push_back(curve.rpm);
      std::sort(speeds.begin(), speeds.end());
      speeds.erase(std::unique(speeds.begin(), speeds.end()), speeds.end());
      if (speeds.empty()) {
        throw InputError("--rpm", "(not given)",
                         "the speeds of the runs: the case has no pressure curve to take them "
                         "from (give --rpm N1,N2,… and the case's pressure_curves)");
      }
    }
    std::vector<engine::Model> models;
    if (const auto list = args.Value("models")) {
      for (const auto& name : SplitList(*list)) models.push_back(engine::ParseModel(name));
      if (models.empty()) throw InputError("--models", "'" + *list + "'", "names no model");
    } else {
      models.push_back(engine::ModelOfCase(c));
    }
    const int jobs = JobsOption(args);
    const double time_limit = TimeLimitOption(args);
    const std::filesystem::path out = args.Value("out")
                                          ? std::filesystem::path(*args.Value("out"))
                                          : std::filesystem::path("results") / ("sweep-" + io::SafeFolderName(c.name));

    // Every configuration is built (and checked) before anything starts.
    std::vector<batch::SweepJob> sweep_jobs;
    for (engine::Model model : models) {
      for (double rpm : speeds) {
        sweep_jobs.push_back(
            SweepJobFor(loaded, model, rpm, time_limit, !args.Has("no-fields"), out));
      }
    }
    const auto folder = PrepareBatchFolders(out, sweep_jobs, args.Value("out").has_value(),
                                            args.Has("overwrite"), "--rpm/--models");

    const BatchOutcome batch =
        RunBatch(std::move(sweep_jobs), jobs, args.Has("quiet"), "sweep", streams);
    const std::string table = WriteComparison(out, batch, "Sweep of " + c.name, "sweep", streams,
                                              {}, CaseAndChangesText(loaded, args.Values("set")));
    streams.out << table;
    streams.err << "sweep: " << batch.runs.size() << " runs, " << batch.incomplete
                << " incomplete; results in " << out.string() << "\n";
    return batch.incomplete == 0 ? 0 : 1;
  };
  return command;
}

}  // namespace filmdyn::cli
