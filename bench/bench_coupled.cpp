// Coupled run timing (docs/performance.md, "Coupled run"): the default case, Skirt-LBRBE at
// 6000 rpm on the default meshes, from the start through the periodic steady state and the
// reported cycle; wall time, steps, Reynolds solves, time per solve; a tight-tolerance run for
// the accuracy check; the price of the paper's explicit 1e-7 s scheme at our cost per step.
// --jfo-ratio: --versus skirt.cavitation=jfo --versus big_end.cavitation=jfo (docs/performance.md,
// "Mass-conserving cavitation").
// --versus key=value (repeatable): the same run again with these fields set, back to back, and
// the ratio of the wall times (e.g. elastic surfaces: docs/performance.md, "Elastic surfaces").
// Run on demand:
//   build/bench/bench_coupled [model] [rpm] [--no-tight] [--coarse] [--profile] [--jfo-ratio]
//   [--versus key=value ...]
//   [--threads 1|2] [--vtol m/s] [--atol rad] [--wtol rad/s] [--set key=value ...]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/engine/run_job.hpp"
#include "core/io/case_file.hpp"

using namespace filmdyn;

namespace {

bool g_coarse = false;
bool g_profile = false;
bool g_jfo_ratio = false;
int g_threads = 0;  // --threads; 0 = RunJob's automatic choice
// Tolerance overrides (--vtol, --atol, --wtol); 0 = the case's.
double g_velocity_tolerance = 0.0, g_angle_tolerance = 0.0, g_angular_velocity_tolerance = 0.0;

// Where the work goes within the cycle: integrator steps, Reynolds solves and wall time per
// 30 °CA bin, printed per cycle.
struct CycleProfile {
  static constexpr int kBins = 24;
  int cycle = 0;
  long steps[kBins] = {}, solves[kBins] = {};
  double wall[kBins] = {};
  long last_steps = 0, last_solves = 0;
  double last_wall = 0.0;
  void Print() const {
    std::printf("  cycle %d, per 30 °CA bin (start angle: steps / solves / ms):\n", cycle);
    for (int b = 0; b < kBins; ++b) {
      std::printf("   %3d: %5ld / %5ld / %6.0f%s", 30 * b, steps[b], solves[b], 1e3 * wall[b],
                  b % 4 == 3 ? "\n" : "");
    }
  }
  bool Record(const engine::RunProgress& p) {
    if (p.run_in) {  // not a cycle's work (negative angles): only move the baseline on
      last_steps = p.steps;
      last_solves = p.reynolds_solves;
      last_wall = p.elapsed;
      return true;
    }
    if (p.cycle != cycle) {
      if (cycle > 0) Print();
      *this = CycleProfile{.cycle = p.cycle,
                           .last_steps = last_steps,
                           .last_solves = last_solves,
                           .last_wall = last_wall};
    }
    const int b = std::min(kBins - 1, static_cast<int>(p.crank_angle_deg / 30.0));
    steps[b] += p.steps - last_steps;
    solves[b] += p.reynolds_solves - last_solves;
    wall[b] += p.elapsed - last_wall;
    last_steps = p.steps;
    last_solves = p.reynolds_solves;
    last_wall = p.elapsed;
    return true;
  }
};

struct Figures {
  double max_e0 = 0, max_gamma = 0, min_skirt_moft = 1e9, min_bearing_moft = 1e9, max_eps = 0;
  double max_skirt_force = 0, mean_skirt_fpl = 0, mean_bearing_fpl = 0, max_bigend_force = 0;
};

Figures FiguresOf(const engine::RunResult& r) {
  Figures f;
  for (const auto& s : r.samples) {
    f.max_e0 = std::max(f.max_e0, std::abs(s.piston_lateral));
    f.max_gamma = std::max(f.max_gamma, std::abs(s.piston_tilt));
    if (s.skirt.present) f.min_skirt_moft = std::min(f.min_skirt_moft, s.skirt.moft);
    if (s.bearing.present) f.min_bearing_moft = std::min(f.min_bearing_moft, s.bearing.moft);
    f.max_eps = std::max(f.max_eps, s.bearing.eps);
    f.max_skirt_force = std::max(f.max_skirt_force, std::abs(s.liner_force_on_piston.x()));
    f.max_bigend_force = std::max(f.max_bigend_force, s.big_end_force_on_rod.norm());
    f.mean_skirt_fpl += s.skirt.fpl / r.samples.size();
    f.mean_bearing_fpl += s.bearing.fpl / r.samples.size();
  }
  return f;
}

engine::RunResult Run(const io::LoadedCase& loaded, engine::Model model, double rpm, double rtol,
                      double ptol, const char* label) {
  engine::EngineCase c = loaded.value;
  if (g_coarse) {  // the test meshes (tests/core/coupling)
    c.skirt.mesh_thrust = c.skirt.mesh_anti = 10;
    c.skirt.mesh_axial = 12;
    c.big_end.mesh_theta = 24;
    c.big_end.mesh_z = 6;
  }
  c.solver.relative_tolerance = rtol;
  c.solver.position_tolerance = ptol;
  engine::RunConfig config = engine::MakeRunConfig(
      c, model, rpm, io::PressureCurveForSpeed(loaded, rpm), loaded.directory);
  // Overrides of the derived absolute tolerances, scaled like the position tolerance (so the
  // tight run stays 100 x tighter).
  const double scale = ptol / loaded.value.solver.position_tolerance;
  config.threads = g_threads;
  if (g_velocity_tolerance > 0) config.integrator.velocity_tolerance = g_velocity_tolerance * scale;
  if (g_angle_tolerance > 0) config.integrator.angle_tolerance = g_angle_tolerance * scale;
  if (g_angular_velocity_tolerance > 0)
    config.integrator.angular_velocity_tolerance = g_angular_velocity_tolerance * scale;
  CycleProfile profile;
  engine::RunMonitor monitor;
  if (g_profile) monitor = [&profile](const engine::RunProgress& p) { return profile.Record(p); };
  const engine::RunResult r = engine::RunJob(config, monitor);
  if (g_profile) profile.Print();
  const Figures f = FiguresOf(r);
  std::printf(
      "%-6s rtol %.0e ptol %.0e: %s%s%s, %d cycles, wall %.2f s, steps %ld (rejected %ld, Newton "
      "%ld, Newton failures %ld, Jacobians %ld), Reynolds solves %ld (%ld factorisations), %.3f "
      "ms per step, %.1f us per solve (incl. element overhead)\n",
      label, rtol, ptol, engine::StatusName(r.status).c_str(), r.message.empty() ? "" : ": ",
      r.message.c_str(), r.cycles, r.wall_time, r.stats.steps, r.stats.rejected_steps,
      r.stats.newton_iterations, r.stats.newton_failures, r.stats.jacobian_evaluations,
      r.reynolds_solves, r.reynolds_factorizations, 1e3 * r.wall_time / std::max(1L, r.stats.steps),
      1e6 * r.wall_time / std::max(1L, r.reynolds_solves));
  std::printf(
      "       max e0 %.4f um, max gamma %.4e rad, min skirt MOFT %.4f um, min bearing MOFT %.4f "
      "um, max eps %.5f, last change %.4f (%s)\n",
      f.max_e0 * 1e6, f.max_gamma, f.min_skirt_moft * 1e6, f.min_bearing_moft * 1e6, f.max_eps,
      r.cycle_change, r.worst_quantity.c_str());
  std::printf(
      "       max |skirt normal| %.1f N, mean skirt FPL %.1f W, max |big-end force| %.1f N, mean "
      "bearing FPL %.1f W\n",
      f.max_skirt_force, f.mean_skirt_fpl, f.max_bigend_force, f.mean_bearing_fpl);
  return r;
}

double RelDiff(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }

}  // namespace

int main(int argc, char** argv) try {
  // Positional [model] [rpm], options anywhere.
  std::vector<std::string> positional, sets, versus;
  bool tight = true;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> const char* {
      if (i + 1 >= argc) throw std::invalid_argument(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--no-tight") {
      tight = false;
    } else if (arg == "--coarse") {
      g_coarse = true;
    } else if (arg == "--profile") {
      g_profile = true;
    } else if (arg == "--jfo-ratio") {
      g_jfo_ratio = true;
    } else if (arg == "--threads") {
      g_threads = std::atoi(value());
    } else if (arg == "--vtol") {
      g_velocity_tolerance = std::atof(value());
    } else if (arg == "--atol") {
      g_angle_tolerance = std::atof(value());
    } else if (arg == "--wtol") {
      g_angular_velocity_tolerance = std::atof(value());
    } else if (arg == "--set") {
      sets.push_back(value());
    } else if (arg == "--versus") {
      versus.push_back(value());
    } else if (arg.rfind("--", 0) == 0) {
      throw std::invalid_argument("unknown option " + arg);
    } else {
      positional.push_back(arg);
    }
  }
  const engine::Model model =
      engine::ParseModel(positional.size() > 0 ? positional[0] : "skirt-lbrbe");
  const double rpm = positional.size() > 1 ? std::atof(positional[1].c_str()) : 6000.0;
  const io::LoadedCase loaded = io::LoadCase("", sets);
  const engine::SolverCase& s = loaded.value.solver;
  const engine::RunResult base =
      Run(loaded, model, rpm, s.relative_tolerance, s.position_tolerance, "case");
  // The paper's scheme: 1e-7 s fixed steps over the same simulated time, priced per step at our
  // measured cost of one coupled evaluation (both Reynolds solves + eq. 39).
  const double simulated = base.cycles * 4.0 * M_PI / (rpm * M_PI / 30.0);
  const double per_eval =
      base.wall_time / std::max(1L, base.stats.rhs_evaluations + 1);  // incl. Jacobian share
  const double explicit_steps = simulated / 1e-7;
  const double per_cycle_steps = 4.0 * M_PI / (rpm * M_PI / 30.0) / 1e-7;
  std::printf(
      "paper scheme: %.3g steps per 720 °CA, %.3g steps for our %d cycles; at %.1f us per coupled "
      "evaluation (one per explicit step) = %.0f s, i.e. %.0f x our %.2f s\n",
      per_cycle_steps, explicit_steps, base.cycles, per_eval * 1e6, explicit_steps * per_eval,
      explicit_steps * per_eval / base.wall_time, base.wall_time);
  // --jfo-ratio: the versus run with mass-conserving cavitation in both joints.
  if (g_jfo_ratio) {
    versus.push_back("skirt.cavitation=jfo");
    versus.push_back("big_end.cavitation=jfo");
  }
  if (!versus.empty()) {
    std::vector<std::string> other_sets = sets;
    other_sets.insert(other_sets.end(), versus.begin(), versus.end());
    const io::LoadedCase other_case = io::LoadCase("", other_sets);
    const engine::RunResult other =
        Run(other_case, model, rpm, s.relative_tolerance, s.position_tolerance, "versus");
    std::printf(
        "versus / case: %s; wall time %.2f (%.2f s / %.2f s), steps %.2f, cycles %d / %d, per "
        "cycle %.2f\n",
        engine::StatusName(other.status).c_str(), other.wall_time / base.wall_time, other.wall_time,
        base.wall_time, static_cast<double>(other.stats.steps) / std::max(1L, base.stats.steps),
        other.cycles, base.cycles,
        (other.wall_time / other.cycles) / (base.wall_time / base.cycles));
  }
  if (!tight) return 0;
  const engine::RunResult ref =
      Run(loaded, model, rpm, s.relative_tolerance * 1e-2, s.position_tolerance * 1e-2, "tight");
  const Figures a = FiguresOf(base), b = FiguresOf(ref);
  std::printf("tight: min bearing MOFT %.5f um, max eps %.6f\n", b.min_bearing_moft * 1e6,
              b.max_eps);
  std::printf(
      "vs tight: max e0 %.2f %%, max gamma %.2f %%, min skirt MOFT %.2f %%, min bearing MOFT "
      "%.2f %%, max eps %.2f %%\n",
      100 * RelDiff(a.max_e0, b.max_e0), 100 * RelDiff(a.max_gamma, b.max_gamma),
      100 * RelDiff(a.min_skirt_moft, b.min_skirt_moft),
      100 * RelDiff(a.min_bearing_moft, b.min_bearing_moft), 100 * RelDiff(a.max_eps, b.max_eps));
  return 0;
} catch (const std::exception& error) {
  std::fprintf(stderr, "bench_coupled: %s\n", error.what());
  return 2;
}
