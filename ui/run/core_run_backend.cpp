// The GUI's solver backend: core's run job (core/engine/run_job), the same call `filmdyn run`
// makes; only the monitor differs. The monitor streams every output step into the sink; the
// reported cycle of the result replaces the streamed samples at the end.
#include <cmath>
#include <stdexcept>

#include "core/engine/run_job.hpp"
#include "core/input_error.hpp"
#include "core/io/case_file.hpp"
#include "ui/run/run_backend.hpp"

namespace filmdyn::ui {

namespace {

// results.csv columns from a crank-train sample (SPEC §4). The quantities of the lubricated
// joints (MOFT, FPL, friction, journal eccentricity) are not in CrankTrainSample yet: NaN.
RunSample ToRunSample(const engine::CrankTrainSample& cs, double crank_angle_deg) {
  RunSample out;
  out[Column::kCrankAngle] = crank_angle_deg;
  out[Column::kTime] = cs.time;
  out[Column::kPistonLateral] = cs.piston_lateral;
  out[Column::kPistonTilt] = cs.piston_tilt;
  out[Column::kPistonLateralVelocity] = cs.piston_lateral_velocity;
  out[Column::kPistonTiltRate] = cs.piston_tilt_rate;
  out[Column::kSkirtNormalForce] = cs.liner_force_on_piston.x();
  out[Column::kSkirtMoment] = cs.liner_moment_about_pin;
  out[Column::kBigEndForceX] = cs.big_end_force_on_rod.x();
  out[Column::kBigEndForceY] = cs.big_end_force_on_rod.y();
  out[Column::kGasForce] = cs.gas_force;
  return out;
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
        engine::MakeRunConfig(c, model, request.rpm, CurveForSpeed(c, request.rpm));
    int cycle = 0;
    const engine::RunMonitor monitor = [&](const engine::RunProgress& p) {
      if (p.cycle != cycle) {
        cycle = p.cycle;
        sink.BeginCycle(cycle);
      }
      if (p.sample) sink.Append(ToRunSample(*p.sample, p.crank_angle_deg));
      RunProgress progress;
      progress.cycle = p.cycle;
      progress.max_cycles = p.max_cycles;
      progress.cycle_fraction = p.crank_angle_deg / 720.0;
      progress.fraction = p.fraction;
      progress.remaining = p.remaining;
      sink.Progress(progress);
      return !cancel.load();
    };
    const engine::RunResult result = engine::RunJob(config, monitor, &cancel);
    std::vector<RunSample> reported;
    const size_t n = result.samples.size();
    for (size_t k = 0; k < n; ++k) {
      // Crank angle within the cycle from the time (imposed speed, 6·rpm °/s, 0 °CA at t = 0).
      const double deg = std::fmod(result.samples[k].time * 6.0 * request.rpm, 720.0);
      reported.push_back(ToRunSample(result.samples[k], deg > 719.999999 ? 0.0 : deg));
    }
    sink.Report(std::move(reported));
    sink.Statistic("cycles", result.cycles);
    sink.Statistic("cycles to steady state", result.cycles_to_steady_state);
    sink.Statistic("cycle change", result.cycle_change);
    sink.Statistic("steps", double(result.stats.steps));
    sink.Statistic("rejected steps", double(result.stats.rejected_steps));
    sink.Statistic("max constraint violation", result.max_constraint_violation);
    switch (result.status) {
      case engine::RunStatus::kCompleted:
      case engine::RunStatus::kCancelled:
        return;
      case engine::RunStatus::kNotConverged:
        // Results are usable but not periodic: a finished run whose reason says so.
        sink.Statistic("not converged", 1.0);
        throw std::runtime_error(result.message);
      case engine::RunStatus::kTimeLimit:
      case engine::RunStatus::kFailed:
        throw std::runtime_error(result.message);
    }
  };
}

}  // namespace filmdyn::ui
