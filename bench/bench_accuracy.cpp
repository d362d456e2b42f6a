// Speed at equal accuracy (docs/performance.md, "Speed at equal accuracy"): the default case,
// Skirt-LBRBE at 6000 rpm, from the assembled start through the run-in, the periodic steady state
// and the reported cycle, with its error estimate, no fields. Accuracy = the five figures a
// designer reads first — min MOFT of both joints, max eps, mean FPL of both joints — against
// their mesh- and tolerance-converged values:
//   reference = Richardson extrapolation (order 2) of the default meshes refined 2x and 4x in
//   every count, at the case's tolerances, plus the tolerance correction measured on the 2x
//   meshes with every tolerance 10x tighter.
// Then, back to back: the default run (its figures as computed and Richardson-extrapolated from
// its own error estimate), the cheapest uniform big-end mesh N x N/5 that reaches 1 % on all five
// figures as computed (N = 100, 150, 200, ...), and the paper's scheme (1e-7 s fixed explicit
// steps, one coupled evaluation each) priced at that uniform mesh's measured cost per
// evaluation. Run on demand:
//   build/bench/bench_accuracy [--rpm N] [--max-uniform N] [--threads 1|2]
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <stdexcept>
#include <string>

#include "core/engine/error_estimate.hpp"
#include "core/engine/run_job.hpp"
#include "core/io/case_file.hpp"

using namespace filmdyn;

namespace {

// The five figures of the accuracy target.
constexpr std::array<const char*, 5> kKeys = {"skirt_moft_min[m]", "skirt_fpl_mean[W]",
                                              "bearing_moft_min[m]", "bearing_eps_max[-]",
                                              "bearing_fpl_mean[W]"};

int g_threads = 0;
double g_rpm = 6000.0;

struct Outcome {
  engine::RunResult result;
  std::map<std::string, double> values, extrapolated;
};

Outcome Run(engine::EngineCase c, const io::LoadedCase& loaded, const char* label) {
  engine::RunConfig config = engine::MakeRunConfig(c, engine::Model::kSkirtLbrbe, g_rpm,
                                                   io::PressureCurveForSpeed(loaded, g_rpm));
  config.threads = g_threads;
  Outcome o;
  o.result = engine::RunJob(config);
  if (o.result.status != engine::RunStatus::kCompleted) {
    throw std::runtime_error(std::string(label) + ": " + o.result.message);
  }
  for (const auto& f : engine::HeadlineFigures(o.result.samples)) o.values[f.key] = f.value;
  o.extrapolated = o.values;
  for (const auto& e : o.result.error_estimate.figures) {
    o.extrapolated[e.figure.key] = e.figure.value + e.error;
  }
  std::printf("%-34s wall %7.2f s (companion %.2f s), steps %ld, rhs evaluations %ld\n", label,
              o.result.wall_time, o.result.error_estimate.coarse_wall_time, o.result.stats.steps,
              o.result.stats.rhs_evaluations);
  return o;
}

engine::EngineCase Refined(engine::EngineCase c, int k) {
  c.skirt.mesh_thrust *= k;
  c.skirt.mesh_relief *= k;
  c.skirt.mesh_anti *= k;
  c.skirt.mesh_axial *= k;
  c.big_end.mesh_theta *= k;
  c.big_end.mesh_z *= k;
  c.solver.error_estimate = 0;
  return c;
}

// Largest relative deviation of the five figures from the reference, and which.
double Worst(const std::map<std::string, double>& v, const std::map<std::string, double>& ref,
             std::string* which) {
  double worst = 0.0;
  for (const char* key : kKeys) {
    const double d = std::abs(v.at(key) / ref.at(key) - 1.0);
    if (d > worst) worst = d, *which = key;
  }
  return worst;
}

void PrintFigures(const char* label, const std::map<std::string, double>& v,
                  const std::map<std::string, double>& ref) {
  std::printf("  %-32s", label);
  for (const char* key : kKeys) {
    std::printf(" %s %+.2f %%", key, 100.0 * (v.at(key) / ref.at(key) - 1.0));
  }
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) try {
  int max_uniform = 400;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> const char* {
      if (i + 1 >= argc) throw std::runtime_error(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--rpm") {
      g_rpm = std::atof(value());
    } else if (arg == "--max-uniform") {
      max_uniform = std::atoi(value());
    } else if (arg == "--threads") {
      g_threads = std::atoi(value());
    } else {
      throw std::runtime_error("unknown option " + arg);
    }
  }
  const io::LoadedCase loaded = io::LoadCase("");
  const engine::EngineCase& base = loaded.value;

  // Reference.
  const Outcome r2 = Run(Refined(base, 2), loaded, "reference: 2x meshes");
  const Outcome r4 = Run(Refined(base, 4), loaded, "reference: 4x meshes");
  engine::EngineCase tight = Refined(base, 2);
  tight.solver.relative_tolerance *= 0.1;
  tight.solver.position_tolerance *= 0.1;
  const Outcome r2t = Run(tight, loaded, "reference: 2x meshes, 10x tighter");
  std::map<std::string, double> ref;
  std::printf("reference (mesh-converged + tolerance correction):\n");
  for (const char* key : kKeys) {
    const double mesh = r4.values.at(key) + (r4.values.at(key) - r2.values.at(key)) / 3.0;
    const double tolerance = r2t.values.at(key) - r2.values.at(key);
    ref[key] = mesh + tolerance;
    std::printf("  %-22s %.6g (2x %.6g, 4x %.6g, tolerance correction %+.3f %%)\n", key,
                ref[key], r2.values.at(key), r4.values.at(key),
                100.0 * tolerance / std::abs(ref[key]));
  }

  // The default run with its estimate.
  const Outcome d = Run(base, loaded, "default meshes, with the estimate");
  std::string which;
  PrintFigures("as computed:", d.values, ref);
  PrintFigures("extrapolated (value + error):", d.extrapolated, ref);
  const double worst_raw = Worst(d.values, ref, &which);
  std::string which_x;
  const double worst_x = Worst(d.extrapolated, ref, &which_x);
  std::printf("  worst: as computed %.2f %% (%s), extrapolated %.2f %% (%s)\n", 100 * worst_raw,
              which.c_str(), 100 * worst_x, which_x.c_str());

  // The cheapest uniform big-end mesh within 1 % as computed.
  for (int n = 100; n <= max_uniform; n += 50) {
    engine::EngineCase u = base;
    u.big_end.mesh_theta = n;
    u.big_end.mesh_z = n / 5 + (n / 5) % 2;  // even: the symmetric half
    u.big_end.mesh_theta_grading = u.big_end.mesh_z_grading = 1.0;
    u.solver.error_estimate = 0;
    const std::string label = "uniform big end " + std::to_string(n) + " x " +
                              std::to_string(u.big_end.mesh_z);
    const Outcome o = Run(u, loaded, label.c_str());
    const double worst = Worst(o.values, ref, &which);
    PrintFigures("as computed:", o.values, ref);
    if (worst <= 0.01) {
      const double cycles_time =
          (o.result.cycles * 4.0 * M_PI + base.solver.run_in_angle) / (g_rpm * M_PI / 30.0);
      const double per_eval = o.result.wall_time / std::max(1L, o.result.stats.rhs_evaluations);
      const double paper = cycles_time / 1e-7 * per_eval;
      std::printf(
          "cheapest uniform within 1 %%: %s, %.2f s = %.1f x the default run (%.2f s); the "
          "paper's 1e-7 s explicit steps (%.3g evaluations at %.1f us) = %.0f s = %.0f x the "
          "default run\n",
          label.c_str(), o.result.wall_time, o.result.wall_time / d.result.wall_time,
          d.result.wall_time, cycles_time / 1e-7, 1e6 * per_eval, paper,
          paper / d.result.wall_time);
      return 0;
    }
    std::printf("  worst %.2f %% (%s): not within 1 %%\n", 100 * worst, which.c_str());
  }
  std::printf("no uniform big-end mesh up to %d elements around is within 1 %%\n", max_uniform);
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "bench_accuracy: %s\n", e.what());
  return 1;
}
