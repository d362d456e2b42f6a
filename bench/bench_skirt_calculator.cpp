// Steady skirt calculator timings (docs/performance.md, "Steady skirt calculator"): one film at a
// state, the equilibrium under light, heavy and contact-only loads, the capacity search of a
// load beyond what the skirt carries, and a 41-point map — on the default case's skirt mesh and
// on the paper's. Run on demand (never a timed test):
//   build/bench/bench_skirt_calculator [repeats]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <vector>

#include "core/base/input_error.hpp"
#include "core/engine/film_joints.hpp"
#include "core/io/case_file.hpp"
#include "core/lubrication/skirt_calculator.hpp"

using namespace filmdyn;
using Clock = std::chrono::steady_clock;

namespace {

double MedianSeconds(int repeats, const std::function<void()>& f) {
  std::vector<double> times;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = Clock::now();
    f();
    times.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  for (const bool paper : {false, true}) {
    engine::EngineCase c = io::LoadCase({}).value;
    if (paper) engine::UsePaperMeshes(&c);
    const lubrication::SkirtConfig config = engine::SkirtConfigFromCase(c);
    std::printf("skirt mesh %d+%d+%dx%d (%s)\n", config.mesh.n_thrust, config.mesh.n_relief,
                config.mesh.n_anti, config.mesh.n_axial, paper ? "the paper's" : "default case");
    const double setup = MedianSeconds(repeats, [&] { lubrication::SkirtCalculator calc(config); });
    std::printf("  set-up (mesh, symbolic factorisation)       %8.2f ms\n", 1e3 * setup);
    lubrication::SkirtCalculator calc(config);
    lubrication::SkirtState s;
    s.e0 = 10e-6, s.gamma = 2e-4, s.piston_velocity = 10.0;
    const double state = MedianSeconds(repeats, [&] { calc.AtState(s); });
    std::printf("  mode 1, a state                             %8.2f ms\n", 1e3 * state);
    struct Load {
      const char* name;
      lubrication::SkirtLoad load;
    };
    for (const Load& l : {Load{"mode 2, 1500 N, 5 N m, 10 m/s  ", {1500.0, 5.0, 10.0}},
                          Load{"mode 2, 30 kN, 10 m/s          ", {30000.0, 0.0, 10.0}},
                          Load{"mode 2, 100 N, no sliding      ", {100.0, 0.0, 0.0}}}) {
      lubrication::SkirtEquilibrium eq;
      const double t = MedianSeconds(repeats, [&] { eq = calc.AtLoad(l.load); });
      std::printf("  %s             %8.2f ms  (%d iterations, %d solves%s)\n", l.name, 1e3 * t,
                  eq.iterations, eq.reynolds_solves, eq.converged ? "" : ", NOT converged");
    }
    std::string message;
    const double beyond = MedianSeconds(repeats, [&] {
      try {
        calc.AtLoad({5e6, 0.0, 10.0});
      } catch (const InputError& e) {
        message = e.allowed();
      }
    });
    std::printf("  mode 2, 5 MN (beyond: capacity search)      %8.2f ms  (%s)\n", 1e3 * beyond,
                message.c_str());
    std::vector<double> e0s;
    for (int i = 0; i <= 40; ++i) e0s.push_back(-20e-6 + 40e-6 * i / 40.0);
    const double map = MedianSeconds(repeats, [&] { calc.Map(e0s, 0.0, 10.0); });
    std::printf("  map, 41 points                              %8.2f ms\n", 1e3 * map);
  }
  return 0;
}
