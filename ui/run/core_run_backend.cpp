// The GUI's solver backend. INTERIM: core's run-job API (`filmdyn run`, with the monitor callback
// and the periodic steady-state loop) has not landed yet, so this drives the ideal crank train
// straight from core's building blocks (BuildCrankTrain, Integrator, SampleCrankTrain). Only the
// Ideal model is available; lubricated models fail with a clear reason. Replace the body of
// CoreRunBackend() with a call to core's run API when it exists.
#include <QObject>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/engine/crank_train.hpp"
#include "core/engine/pressure_curve.hpp"
#include "core/input_error.hpp"
#include "core/multibody/integrator.hpp"
#include "ui/run/run_backend.hpp"

namespace filmdyn::ui {

namespace {

constexpr double kPi = std::numbers::pi;

engine::PressureCurve CurveForSpeed(const engine::EngineCase& c, double rpm) {
  for (size_t i = 0; i < c.pressure_curves.size(); ++i) {
    const auto& source = c.pressure_curves[i];
    if (source.rpm != rpm) continue;
    const std::string field = "pressure_curves[" + std::to_string(i) + "]";
    if (!source.file.empty()) {
      throw InputError(field + ".file", source.file,
                       "curves from files need core's case loader (not yet available in the "
                       "GUI); import the CSV on the Cylinder pressure tab instead");
    }
    std::vector<double> angles;
    for (double a : source.crank_angle_deg) angles.push_back(a * kPi / 180.0);
    return engine::PressureCurve(angles, source.pressure, field);
  }
  throw InputError("operating.rpm", FormatValue(rpm),
                   "no cylinder-pressure curve for this speed in pressure_curves");
}

void RunIdeal(const RunRequest& request, const std::atomic<bool>& cancel, RunSink& sink) {
  const engine::EngineCase& c = request.engine_case;
  engine::EngineCase ideal = c;
  ideal.skirt.model = engine::JointModel::kIdeal;
  ideal.big_end.model = engine::JointModel::kIdeal;
  engine::CrankTrain train =
      engine::BuildCrankTrain(ideal, request.rpm, CurveForSpeed(c, request.rpm));
  multibody::IntegratorConfig config;
  config.relative_tolerance = c.solver.relative_tolerance;
  config.position_tolerance = c.solver.position_tolerance;
  multibody::Integrator integrator(*train.system, config);
  integrator.Initialize(0.0, train.initial_state);
  const double omega = train.layout.omega;
  const int steps = std::max(1, int(std::lround(4 * kPi / c.solver.output_interval)));
  const double cycle_time = 4 * kPi / omega;
  // Imposed crank speed and ideal joints: periodic after the first cycle; report the second.
  const int cycles = std::min(2, std::max(1, c.solver.max_cycles));
  for (int n = 1; n <= cycles; ++n) {
    sink.BeginCycle(n);
    for (int k = 0; k <= steps; ++k) {
      if (cancel) return;
      const double t = (n - 1) * cycle_time + k * cycle_time / steps;
      const multibody::SystemState s = t > 0 ? integrator.AdvanceTo(t) : train.initial_state;
      const engine::CrankTrainSample cs = engine::SampleCrankTrain(train, ideal, t, s);
      RunSample out;
      out[Column::kCrankAngle] = 720.0 * k / steps;
      out[Column::kTime] = t;
      out[Column::kPistonLateral] = cs.piston_lateral;
      out[Column::kPistonTilt] = cs.piston_tilt;
      out[Column::kPistonLateralVelocity] = cs.piston_lateral_velocity;
      out[Column::kPistonTiltRate] = cs.piston_tilt_rate;
      out[Column::kSkirtNormalForce] = cs.liner_force_on_piston.x();
      out[Column::kSkirtMoment] = cs.liner_moment_about_pin;
      out[Column::kBigEndForceX] = cs.big_end_force_on_rod.x();
      out[Column::kBigEndForceY] = cs.big_end_force_on_rod.y();
      out[Column::kGasForce] = cs.gas_force;
      sink.Append(out);
      sink.Progress({n, cycles, double(k) / steps, -1});
    }
    const auto stats = integrator.Stats();
    sink.Statistic("steps", double(stats.steps));
    sink.Statistic("rejected steps", double(stats.rejected_steps));
    sink.Statistic("cycles", n);
  }
}

}  // namespace

RunBackend CoreRunBackend() {
  return [](const RunRequest& request, const std::atomic<bool>& cancel, RunSink& sink) {
    if (request.model != "ideal") {
      throw std::runtime_error(
          "the lubricated models (" + request.model +
          ") are not available yet: the coupled solver (issue 5) has not landed; choose Ideal");
    }
    RunIdeal(request, cancel, sink);
  };
}

}  // namespace filmdyn::ui
