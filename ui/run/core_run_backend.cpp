// The GUI's solver backend: core's run job (core/engine/run_job), the same call `filmdyn run`
// makes; only the monitor differs. The monitor streams every output step into the sink; the
// reported cycle of the result replaces the streamed samples at the end.
#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "core/base/input_error.hpp"
#include "core/engine/run_job.hpp"
#include "core/io/case_file.hpp"
#include "core/io/field_output.hpp"
#include "core/io/results_writer.hpp"
#include "core/io/run_summary.hpp"
#include "core/io/run_warnings.hpp"
#include "core/lubrication/bearing_solver.hpp"
#include "core/lubrication/skirt_solver.hpp"
#include "ui/fields/field_collector.hpp"
#include "ui/run/run_backend.hpp"
#include "ui/run/sample_conversion.hpp"

namespace filmdyn::ui {

void ReportRunCounters(RunSink& sink, const RunCounters& c) {
  sink.Statistic("cycles", c.cycles);
  sink.Statistic("cycles to steady state", c.cycles_to_steady_state);
  sink.Statistic("cycle change", c.cycle_change);
  sink.Statistic("steps", c.steps);
  sink.Statistic("rejected steps", c.rejected_steps);
  sink.Statistic("max constraint violation", c.max_constraint_violation);
  sink.Statistic("Reynolds solves", c.reynolds_solves);
  if (std::isfinite(c.skirt_oil_per_cycle))
    sink.Statistic(kSkirtOilStatistic, c.skirt_oil_per_cycle);
  if (std::isfinite(c.big_end_oil_per_cycle))
    sink.Statistic(kBigEndOilStatistic, c.big_end_oil_per_cycle);
}

RunCounters OilCounters(RunCounters counters, const io::RunKpis& kpis) {
  counters.skirt_oil_per_cycle = io::ReportedOilPerCycle(kpis.skirt).value_or(std::nan(""));
  counters.big_end_oil_per_cycle = io::ReportedOilPerCycle(kpis.big_end).value_or(std::nan(""));
  return counters;
}

namespace {

// results.csv columns from a crank-train sample: core's row (io::RowFromSample, what
// `filmdyn run` writes) through the one row-to-sample mapping, so GUI and files agree.
RunSample ToRunSample(const engine::CrankTrainSample& cs, engine::Model model,
                      double cycle_start_time) {
  return RunSampleFromRow(io::RowFromSample(cs, model, cycle_start_time));
}

engine::PressureCurve CurveForSpeed(const engine::EngineCase& c, double rpm) {
  // Core's rule: the curve at that speed or a blend of the two neighbouring speeds; the editor
  // keeps curves inline (file curves are read into tables when a case is opened).
  io::LoadedCase loaded;
  loaded.value = c;
  loaded.source = "GUI";
  return io::PressureCurveForSpeed(loaded, rpm);
}

}  // namespace

RunBackend CoreRunBackend() {
  return [](const RunRequest& request, const std::atomic<bool>& cancel, RunSink& sink) {
    const engine::Model model = engine::ParseModel(request.model);
    engine::EngineCase c = request.engine_case;
    engine::ApplyModel(model, &c);
    engine::RunConfig config =
        engine::MakeRunConfig(c, model, request.rpm, CurveForSpeed(c, request.rpm),
                              std::filesystem::path(request.case_directory));
    config.heartbeat_interval = engine::kHeartbeatInterval;  // progress through slow steps
    const int steps_per_cycle = std::max(1, int(std::lround(4 * M_PI / c.solver.output_interval)));
    FieldCollector collector(steps_per_cycle);
    // The GUI's frames and core's recorder (for the run folder's fields/, as `filmdyn run`).
    auto recorder = std::make_shared<io::FieldRecorder>();
    // The view's frames beside the recorder's: for the memory check.
    config.field_copies =
        1.0 + std::min(1.0, double(FieldCollector::kMaxFrames) / double(steps_per_cycle));
    if (model != engine::Model::kIdeal) {
      config.field_callback = [&collector,
                               record = recorder->Callback()](const engine::FieldFrame& f) {
        collector.Add(f);
        record(f);
      };
    }
    int cycle = 0;
    const engine::RunMonitor monitor = [&](const engine::RunProgress& p) {
      // The run-in only reports progress; the plots start with the first cycle.
      if (!p.run_in && p.cycle != cycle) {
        cycle = p.cycle;
        sink.BeginCycle(cycle);
      }
      if (p.sample && !p.run_in) sink.Append(ToRunSample(*p.sample, model, p.cycle_start_time));
      RunProgress progress;
      progress.run_in = p.run_in;
      progress.cycle = p.cycle;
      progress.max_cycles = p.max_cycles;
      // < 0 in the run-in; a heartbeat just before a cycle's first sample is at its start.
      progress.cycle_fraction =
          p.run_in ? p.crank_angle_deg / 720.0 : std::max(0.0, p.crank_angle_deg / 720.0);
      progress.crank_angle_deg = engine::CycleCrankAngleDeg(p.crank_angle);
      progress.cycle_change = p.cycle_change;
      progress.fraction = p.fraction;
      progress.remaining = p.remaining;
      sink.Progress(progress);
      return !cancel.load();
    };
    const engine::RunResult result = engine::RunJob(config, monitor, &cancel);
    sink.ReportMotion(RunSamplesFromRows(io::MotionRows(result, model)));
    sink.Report(RunSamplesFromRows(io::ResultRows(result, model)));
    // A cancelled run stays in the run list with its curves and figures; its film fields (one
    // cycle of frames, tens of MB on fine meshes) are dropped, so that runs started and cancelled
    // again and again do not pile up memory.
    const bool cancelled = result.status == engine::RunStatus::kCancelled;
    // Fields only of the reported cycle: a run stopped in its second or later cycle reports the
    // last whole one, whose frames are gone (one cycle is kept: the one it stopped in).
    const bool fields_reported = recorder->Holds(result.samples);
    if (cancelled || !fields_reported) recorder = std::make_shared<io::FieldRecorder>();
    auto shared_config = std::make_shared<engine::RunConfig>(config);
    shared_config->field_callback = nullptr;  // refers to this call's collector
    auto shared_result = std::make_shared<engine::RunResult>(result);
    const std::string case_name = c.name;
    RunWriters writers;
    writers.folder = [shared_config, shared_result, recorder, case_name](const std::string& dir) {
      io::WriteRunFolder(dir, case_name, *shared_config, *shared_result,
                         [&](const std::vector<io::OutputRow>&) {
                           if (recorder->skirt_frames() + recorder->bearing_frames() > 0)
                             recorder->Write(std::filesystem::path(dir) / "fields");
                         });
    };
    writers.fields = [recorder, cancelled, model](const std::string& dir) {
      if (recorder->skirt_frames() + recorder->bearing_frames() == 0) {
        throw std::runtime_error(cancelled ? "a cancelled run keeps no film fields"
                                 : model == engine::Model::kIdeal
                                     ? "this run has no film fields (ideal joints)"
                                     : "this run kept no film fields of its reported "
                                       "output steps");
      }
      recorder->Write(dir);
    };
    writers.csv = [shared_result, model]() {
      std::ostringstream out;
      io::WriteResultsCsv(out, io::ResultRows(*shared_result, model));
      return out.str();
    };
    sink.SetWriters(std::move(writers));
    if (auto fields = collector.Result();
        !cancelled && fields_reported && fields && !fields->empty())
      sink.ReportFields(fields);
    ReportRunCounters(
        sink, OilCounters({double(result.cycles), double(result.cycles_to_steady_state),
                           result.cycle_change, double(result.stats.steps),
                           double(result.stats.rejected_steps), result.max_constraint_violation,
                           double(result.reynolds_solves)},
                          io::RunKpisOf(config, result)));
    sink.ReportErrorEstimate(result.error_estimate);
    sink.ReportCycleScatter(io::ReportedCycleScatter(result));
    sink.ReportWarnings(io::RunWarnings(config, result));
    switch (result.status) {
      case engine::RunStatus::kCompleted:
        return;
      case engine::RunStatus::kCancelled:
        throw RunCancelled();
      case engine::RunStatus::kNotConverged:
        // Results are usable but not periodic: a finished run whose reason says so.
        sink.Warn(result.message);
        return;
      case engine::RunStatus::kTimeLimit:
      case engine::RunStatus::kFailed:
        throw std::runtime_error(result.message);
    }
  };
}

}  // namespace filmdyn::ui
