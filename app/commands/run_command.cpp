// `filmdyn run`: one headless run (docs/outputs.md). All the work is in core (io::LoadCase,
// engine::RunJob, io::WriteRunFolder); this file only parses options and prints progress on
// stderr. Ctrl-C, SIGTERM and SIGHUP stop the run cleanly: the cycle computed so far is written,
// marked incomplete.
#include <fmt/format.h>
#include <chrono>
#include <cstdio>

#include "app/commands/commands.hpp"
#include "app/commands/run_common.hpp"
#include "core/base/input_error.hpp"
#include "core/engine/error_estimate.hpp"
#include "core/engine/run_job.hpp"
#include "core/io/case_file.hpp"
#include "core/io/field_output.hpp"
#include "core/io/output_files.hpp"
#include "core/io/results_writer.hpp"
#include "core/io/run_summary.hpp"

namespace filmdyn::cli {

Command MakeRunCommand() {
  Command command;
  command.name = "run";
  command.summary = "headless run of a case; results.csv and summary.json in an output folder";
  command.positional_usage = "[CASE.json]";
  command.max_positional = 1;
  command.needs_gui_application = true;  // plots/ are rendered with Qt Charts (offscreen)
  command.options = {
      {"model", "MODEL", "skirt-lbrbe | only-skirt | only-lbrbe | ideal (default: the case's)"},
      {"rpm", "N", "crank speed [rpm] (default: operating.rpm of the case)"},
      {"out", "DIR", "output folder (default: ./results/<case>-<model>-<rpm>)"},
      CaseSetOption(),
      {"pressure-curve", "FILE.csv", "cylinder pressure: crank_angle[deg],pressure[Pa] (absolute)"},
      {"time-limit", "S", "stop after S seconds of wall time, keeping what was computed"},
      {"threads", "N", "1 or 2: the two film joints side by side (default: 2 on >= 2 cores)"},
      {"no-fields", "", "do not write fields/ (film fields per output step, HDF5 + XDMF)"},
      {"overwrite", "", "--out may hold an earlier run: FilmDyn's files in it are replaced"},
      {"quiet", "", "no progress on stderr"}};
  command.details =
      "Without CASE.json the built-in default case (Table I of Zhao & Shen's coupling-model "
      "paper;\n"
      "docs/case-file.md) is used.\n"
      "Film runs also compute a companion run on meshes with half the elements and report the\n"
      "estimated discretisation error of the headline figures (after the status line,\n"
      "summary.json; warns above 1 %; --set solver.error_estimate=0 turns it off;\n"
      "docs/validation/errors.md). Then the engineering warnings, one line each (film thinner\n"
      "than 3 or 1 roughness heights, big-end eccentricity above 0.95, no periodic steady state,\n"
      "assumed inputs, synthetic pressure; summary.json \"warnings\", docs/outputs.md).\n"
      "Outputs: summary.json says \"running\" until every other file is written, then comes last;\n"
      "each file is written whole or not at all. An --out folder holding an earlier run is\n"
      "refused without --overwrite; the default folder's earlier run is replaced. Ctrl-C,\n"
      "SIGTERM and SIGHUP stop the run with what was computed written, marked incomplete.\n"
      "Examples:\n  filmdyn run --model ideal --rpm 4000\n"
      "  filmdyn run my.json --set geometry.pin_offset=0.001 --out /tmp/r1";
  command.run = [](const Args& args, Streams& streams) {
    const io::LoadedCase loaded = LoadCaseArgument(args, &streams.err);
    const engine::EngineCase& c = loaded.value;
    const engine::Model model =
        args.Value("model") ? engine::ParseModel(*args.Value("model")) : engine::ModelOfCase(c);
    const double rpm = args.Double("rpm").value_or(c.operating.rpm);
    engine::RunConfig config = [&] {
      try {
        return BuildRunConfig(loaded, model, rpm, args.Value("pressure-curve"),
                              TimeLimitOption(args));
      } catch (const InputError& e) {
        // A speed the case's curves do not cover, given as --rpm: name the option typed.
        if (e.field() == "operating.rpm" && args.Value("rpm"))
          throw InputError("--rpm", e.value(), e.allowed());
        throw;
      }
    }();
    config.heartbeat_interval = engine::kHeartbeatInterval;  // the progress line through slow steps
    if (const auto threads = args.Integer("threads")) {
      if (*threads < 1 || *threads > 2) {
        throw InputError("--threads", std::to_string(*threads),
                         "must be 1 or 2 (one thread per film joint)");
      }
      config.threads = static_cast<int>(*threads);
    }
    io::FieldRecorder fields;
    if (!args.Has("no-fields")) fields.Attach(&config);
    engine::CheckRunMemory(config);  // before the output folder is touched
    const bool explicit_out = args.Value("out").has_value();
    const std::filesystem::path out = explicit_out ? std::filesystem::path(*args.Value("out"))
                                                   : io::DefaultOutputFolder(c.name, model, rpm);
    const bool quiet = args.Has("quiet");
    // Locked against a second FilmDyn writer until the end; an earlier run's files are refused
    // (--out without --overwrite) or replaced (the default folder is FilmDyn's own).
    const io::OutputFolder folder(
        out, io::OutputFolder::ReuseFor(explicit_out, args.Has("overwrite")), "--out");
    if (folder.replaced_earlier_run() && !quiet) {
      streams.err << "filmdyn run: replacing the earlier run in " << out.string() << "\n";
    }
    io::MarkRunStarted(out, c.name, config);
    auto last_print = std::chrono::steady_clock::now() - std::chrono::seconds(1);
    const engine::RunMonitor monitor = [&](const engine::RunProgress& p) {
      const auto now = std::chrono::steady_clock::now();
      if (!quiet && now - last_print > std::chrono::milliseconds(200)) {
        last_print = now;
        // The crank angle as results.csv labels it (inside an output step: the one reached);
        // the run-in also says how far cycle 1 is.
        const double angle = engine::CycleCrankAngleDeg(p.crank_angle);
        std::string where =
            p.run_in ? fmt::format("run-in {:5.1f} °CA ({:.0f} °CA before cycle 1)", angle,
                                   -p.crank_angle_deg)
                     : fmt::format("cycle {}/{}  {:5.1f} °CA", p.cycle, p.max_cycles, angle);
        if (p.cycle_change >= 0.0)  // how far from periodic the last cycle was
          where += "  last change " + engine::PercentText(p.cycle_change) + " %";
        streams.err << fmt::format("\r{}  {:3.0f} %  elapsed {:.1f} s  ETA {:.1f} s ", where,
                                   100.0 * std::min(p.fraction, 1.0), p.elapsed, p.remaining)
                    << std::flush;
      }
      return true;
    };
    // The guard spans the writing too: a stop signal (Ctrl-C, a scheduler's time limit) that
    // arrives once the computing is over lets the files be finished, not lost half-written.
    const InterruptGuard interrupt;
    const engine::RunResult result = [&] {
      try {
        return engine::RunJob(config, monitor, interrupt.flag());
      } catch (const std::exception& e) {
        // An input only the run's set-up checks (a film joint's oil or compliance): the folder
        // says the run failed and why, not "running" (a run killed).
        io::MarkRunFailed(out, c.name, config, e.what());
        throw;
      }
    }();
    const bool stopped_while_computing = interrupt.flag()->load();
    if (!quiet) streams.err << "\n";
    io::WriteRunFolder(out, c.name, config, result, [&](const std::vector<io::OutputRow>& rows) {
      const bool wrote = fields.WriteReported(out / "fields", result.samples);
      if (wrote && result.reported_cycle == 0) {
        streams.err << "filmdyn run: fields/ holds one step, the film where the run failed in its "
                       "run-in (the run-in's other film fields are not recorded)\n";
      } else if (!wrote && fields.skirt_frames() + fields.bearing_frames() > 0) {
        streams.err << "filmdyn run: fields/ not written: the run reports its last whole cycle, "
                       "whose film fields were not kept (two cycles of them would not fit in "
                       "this machine's memory)\n";
      } else if (!args.Has("no-fields") && fields.skirt_frames() + fields.bearing_frames() == 0 &&
                 !result.samples.empty() && result.reported_cycle == 0 &&
                 (engine::SkirtLubricated(config.model) ||
                  engine::BigEndLubricated(config.model))) {
        streams.err << "filmdyn run: fields/ not written: the run stopped in its run-in, whose "
                       "film fields are not recorded\n";
      }
      // The same charts the GUI draws, also for an incomplete run (what was computed).
      if (const std::string error = WriteRunPlots(out, config, result, rows); !error.empty()) {
        streams.err << "filmdyn run: plots not written: " << error << "\n";
      }
    });
    if (!stopped_while_computing && interrupt.flag()->load()) {
      streams.err << "filmdyn run: a stop signal arrived while the results were being written; "
                     "they were finished first\n";
    }
    streams.err << "filmdyn run: " << engine::StatusName(result.status) << ", " << result.cycles
                << " cycles, " << result.stats.steps << " steps, " << result.wall_time
                << " s; results in " << out.string() << "\n";
    streams.err << "filmdyn run: " << result.error_estimate.Summary() << "\n";
    // A periodic run's last cycles (a run that is not periodic says so in its warning).
    if (result.status == engine::RunStatus::kCompleted) {
      if (const auto scatter = io::ReportedCycleScatter(result))
        streams.err << "filmdyn run: " << scatter->Summary() << "\n";
    }
    PrintRunWarnings(config, result, "filmdyn run", streams.err);
    if (result.status != engine::RunStatus::kCompleted) {
      // "incomplete (failed)", "(time-limit)", …: the status of the first line, with its reason.
      streams.err << "filmdyn run: incomplete (" << engine::StatusName(result.status)
                  << "): " << result.message << "\n";
      // What results.csv holds when it is not the cycle the run was in.
      if (result.reported_cycle == 0 && !result.samples.empty()) {
        streams.err << "filmdyn run: the results are the part of the run-in computed\n";
      } else if (result.reported_cycle != result.cycles) {
        streams.err << "filmdyn run: the results are cycle " << result.reported_cycle
                    << ", the last whole one\n";
      } else if (result.status == engine::RunStatus::kFailed && !result.samples.empty()) {
        streams.err << "filmdyn run: the results are cycle " << result.reported_cycle
                    << " up to where the run failed\n";
      }
      return 1;
    }
    return 0;
  };
  return command;
}

}  // namespace filmdyn::cli
