#include "core/engine/run_job.hpp"

#include <chrono>
#include <cmath>
#include <numbers>

#include "core/input_error.hpp"

namespace filmdyn::engine {

Model ParseModel(const std::string& text) {
  if (text == "ideal") return Model::kIdeal;
  if (text == "only-skirt") return Model::kOnlySkirt;
  if (text == "only-lbrbe") return Model::kOnlyLbrbe;
  if (text == "skirt-lbrbe") return Model::kSkirtLbrbe;
  throw InputError("--model", text, "must be one of skirt-lbrbe, only-skirt, only-lbrbe, ideal");
}

std::string ModelName(Model model) {
  switch (model) {
    case Model::kIdeal:
      return "ideal";
    case Model::kOnlySkirt:
      return "only-skirt";
    case Model::kOnlyLbrbe:
      return "only-lbrbe";
    case Model::kSkirtLbrbe:
      return "skirt-lbrbe";
  }
  return "?";
}

void ApplyModel(Model model, EngineCase* c) {
  const bool skirt = model == Model::kOnlySkirt || model == Model::kSkirtLbrbe;
  const bool big_end = model == Model::kOnlyLbrbe || model == Model::kSkirtLbrbe;
  c->skirt.model = skirt ? JointModel::kLubricated : JointModel::kIdeal;
  c->big_end.model = big_end ? JointModel::kLubricated : JointModel::kIdeal;
}

std::string StatusName(RunStatus status) {
  switch (status) {
    case RunStatus::kCompleted:
      return "completed";
    case RunStatus::kNotConverged:
      return "not-converged";
    case RunStatus::kCancelled:
      return "cancelled";
    case RunStatus::kTimeLimit:
      return "time-limit";
    case RunStatus::kFailed:
      return "failed";
  }
  return "?";
}

RunConfig MakeRunConfig(const EngineCase& engine_case, Model model, double rpm,
                        PressureCurve pressure) {
  RunConfig config;
  config.engine_case = engine_case;
  ApplyModel(model, &config.engine_case);
  config.model = model;
  config.rpm = rpm;
  config.pressure = std::move(pressure);
  const SolverCase& s = engine_case.solver;
  config.integrator.relative_tolerance = s.relative_tolerance;
  config.integrator.position_tolerance = s.position_tolerance;
  // Angles, velocities: the same relative accuracy on the engine's scales (stroke ~0.1 m,
  // piston speed ~ 30 m/s, rates ~1e3 rad/s).
  config.integrator.angle_tolerance = s.position_tolerance * 10.0;
  config.integrator.velocity_tolerance = s.position_tolerance * 1e3;
  config.integrator.angular_velocity_tolerance = s.position_tolerance * 1e4;
  return config;
}

namespace {

// Quantities whose cycle-to-cycle change decides the periodic steady state (issue 5 adds e0, γ,
// ε and the MOFTs through the samples' secondary-motion fields).
std::vector<double> Monitored(const CrankTrainSample& s) {
  return {s.piston_lateral,
          s.piston_tilt,
          s.liner_force_on_piston.x(),
          s.big_end_force_on_rod.x(),
          s.big_end_force_on_rod.y(),
          s.crank_torque};
}

double CycleChange(const std::vector<CrankTrainSample>& a, const std::vector<CrankTrainSample>& b) {
  if (a.size() != b.size() || a.empty()) return INFINITY;
  const std::size_t m = Monitored(a[0]).size();
  double worst = 0.0;
  for (std::size_t q = 0; q < m; ++q) {
    double lo = INFINITY, hi = -INFINITY, change = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) {
      const double x = Monitored(a[k])[q], y = Monitored(b[k])[q];
      lo = std::min(lo, y);
      hi = std::max(hi, y);
      change = std::max(change, std::abs(x - y));
    }
    const double range = hi - lo;
    if (range > 1e-12)
      worst = std::max(worst, change / range);  // constant quantities: skip
    else
      worst = std::max(worst, change > 1e-12 ? 1.0 : 0.0);
  }
  return worst;
}

}  // namespace

RunResult RunJob(const RunConfig& config, const RunMonitor& monitor,
                 const std::atomic<bool>* cancel) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  RunResult result;
  const EngineCase& c = config.engine_case;
  CrankTrain train = BuildCrankTrain(c, config.rpm, config.pressure, config.factories);
  multibody::Integrator integrator(*train.system, config.integrator);
  integrator.Initialize(0.0, train.initial_state);

  const double omega = train.layout.omega;
  const double cycle_time = 4.0 * std::numbers::pi / omega;
  const int steps_per_cycle =
      std::max(1, static_cast<int>(std::lround(4.0 * std::numbers::pi / c.solver.output_interval)));
  const int max_cycles = c.solver.max_cycles;
  std::vector<CrankTrainSample> previous, current;
  double crank_deg = 0.0;
  try {
    for (int cycle = 1; cycle <= max_cycles; ++cycle) {
      current.clear();
      for (int k = 0; k < steps_per_cycle; ++k) {
        const double t = (cycle - 1) * cycle_time + k * cycle_time / steps_per_cycle;
        crank_deg = 720.0 * k / steps_per_cycle;
        const multibody::SystemState state =
            t > 0.0 ? integrator.AdvanceTo(t) : train.initial_state;
        current.push_back(SampleCrankTrain(train, c, t, state));
        result.max_constraint_violation =
            std::max(result.max_constraint_violation, current.back().constraint_violation);
        result.stats = integrator.Stats();
        RunProgress progress;
        progress.cycle = cycle;
        progress.max_cycles = max_cycles;
        progress.crank_angle_deg = crank_deg;
        // Progress assumes a few cycles (ideal: 2); refined when issue 5 knows typical counts.
        const double expected = std::max(2, std::min(max_cycles, cycle + 1));
        progress.fraction = ((cycle - 1) + (k + 1.0) / steps_per_cycle) / expected;
        progress.elapsed = elapsed();
        progress.remaining = progress.elapsed * (1.0 / std::max(progress.fraction, 1e-9) - 1.0);
        progress.sample = &current.back();
        const bool go_on = !monitor || monitor(progress);
        const bool cancelled = cancel && cancel->load();
        if (!go_on || cancelled) {
          result.status = RunStatus::kCancelled;
          result.message = "cancelled at cycle " + std::to_string(cycle) + ", " +
                           std::to_string(crank_deg) + " °CA";
        } else if (config.wall_time_limit > 0 && progress.elapsed > config.wall_time_limit) {
          result.status = RunStatus::kTimeLimit;
          result.message = "wall-time limit reached at cycle " + std::to_string(cycle) + ", " +
                           std::to_string(crank_deg) + " °CA";
        }
        if (result.status == RunStatus::kCancelled || result.status == RunStatus::kTimeLimit) {
          result.cycles = cycle;
          result.samples = previous.empty() ? current : previous;
          result.wall_time = elapsed();
          return result;
        }
      }
      result.cycles = cycle;
      if (!previous.empty()) {
        result.cycle_change = CycleChange(previous, current);
        if (result.cycle_change <= c.solver.steady_state_tolerance) {
          result.cycles_to_steady_state = cycle;
          result.status = RunStatus::kCompleted;
          result.samples = std::move(current);
          result.wall_time = elapsed();
          return result;
        }
      }
      previous = std::move(current);
    }
    result.status = RunStatus::kNotConverged;
    result.message = "no periodic steady state after " + std::to_string(max_cycles) +
                     " cycles (last change " + std::to_string(result.cycle_change) + " of range)";
    result.samples = std::move(previous);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& error) {
    result.status = RunStatus::kFailed;
    result.message = std::string(error.what()) + " (at " + std::to_string(crank_deg) + " °CA)";
    result.samples = current.empty() ? previous : current;
  }
  result.stats = integrator.Stats();
  result.wall_time = elapsed();
  return result;
}

}  // namespace filmdyn::engine
