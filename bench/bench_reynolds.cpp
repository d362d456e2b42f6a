// Reynolds solve timings (docs/performance.md, "Reynolds solve"): time per solve on both default
// meshes, split into assembly, numeric factorisation(s) and the complementarity logic, next to a
// bare CHOLMOD simplicial LDL^T factorise + solve of the same matrix in the same run; plus Eigen
// vs CHOLMOD backends on the default and a fine mesh. Run on demand (never a timed test):
//   build-lub/bench/bench_reynolds [repeats]
#include <Eigen/CholmodSupport>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <numbers>
#include <vector>

#include "core/base/angles.hpp"
#include "core/lubrication/bearing_solver.hpp"
#include "core/lubrication/skirt_solver.hpp"

using namespace filmdyn::lubrication;
using Clock = std::chrono::steady_clock;

namespace {

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct Split {
  double total = 0, assembly = 0, factorization = 0, complementarity = 0, iterations = 0;
  double mean_total = 0, mean_iterations = 0;  // means include the rare active-set changes
};

// Median over `repeats` of one call of `solve` (returns the stats of that call).
Split TimeSolves(int repeats, const std::function<ReynoldsStats(int)>& solve) {
  std::vector<double> tot, as, fa, co, it;
  for (int i = 0; i < repeats; ++i) {
    const auto t0 = Clock::now();
    const ReynoldsStats st = solve(i);
    tot.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
    as.push_back(st.assembly_s);
    fa.push_back(st.factorization_s);
    co.push_back(st.complementarity_s);
    it.push_back(st.iterations);
  }
  double mt = 0, mi = 0;
  for (size_t i = 0; i < tot.size(); ++i) mt += tot[i] / tot.size(), mi += it[i] / it.size();
  return {Median(tot), Median(as), Median(fa), Median(co), Median(it), mt, mi};
}

// Bare CHOLMOD simplicial LDL^T of the assembled matrix with the fixed rows/columns replaced by
// unit rows (the matrix the first active-set iteration factorises), pattern analysed once.
double BareCholmod(const ReynoldsFem& fem, const std::vector<std::uint8_t>& fixed, int repeats) {
  Eigen::SparseMatrix<double> a = fem.stiffness_lower();
  for (int c = 0; c < a.outerSize(); ++c) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, c); it; ++it) {
      if (it.row() != it.col() && (fixed[it.row()] || fixed[it.col()])) it.valueRef() = 0.0;
    }
  }
  Eigen::CholmodSimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> ldlt;
  ldlt.analyzePattern(a);
  Eigen::VectorXd b = Eigen::VectorXd::Ones(a.rows()), x;
  std::vector<double> t;
  for (int i = 0; i < repeats; ++i) {
    const auto t0 = Clock::now();
    ldlt.factorize(a);
    x = ldlt.solve(b);
    t.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
  }
  return Median(t);
}

void Report(const char* name, const Split& s, double bare) {
  std::printf(
      "  %-32s median %8.1f us (assembly %6.1f, factorisation %7.1f, complementarity %6.1f; "
      "%4.1f it.) = %5.2f x bare | mean %8.1f us, %5.2f it. = %5.2f x bare\n",
      name, 1e6 * s.total, 1e6 * s.assembly, 1e6 * s.factorization, 1e6 * s.complementarity,
      s.iterations, s.total / bare, 1e6 * s.mean_total, s.mean_iterations, s.mean_total / bare);
}

BearingConfig Bearing(BearingMeshSpec mesh, LdltBackend backend) {
  BearingConfig cfg;
  cfg.geometry = {0.024, 0.022, 25e-6};  // big-end-like: D = 48 mm, L = 22 mm
  cfg.viscosity = 0.01;
  cfg.mesh = mesh;
  cfg.solver.backend = backend;
  return cfg;
}

SkirtConfig Skirt(LdltBackend backend) {
  SkirtConfig cfg;
  auto& g = cfg.geometry;
  g.radius = 0.0415;
  g.skirt_length = 0.032;
  g.radial_clearance = 20e-6;
  g.pin_position = 0.014;
  g.alpha1 = g.alpha2 = 46.0 * filmdyn::kRadiansPerDegree;
  g.profile = {{0.0, 0.008, 0.016, 0.024, 0.032}, {25e-6, 6e-6, 0.0, 4e-6, 15e-6}};
  cfg.viscosity = 0.008;
  cfg.solver.backend = backend;
  return cfg;
}

void BenchBearing(const char* title, BearingMeshSpec mesh, int repeats) {
  std::printf("\nbig-end bearing, %s: %d x %d%s (%d nodes)\n", title, mesh.n_theta, mesh.n_z,
              mesh.symmetric_half ? " half width" : "", mesh.n_theta * (mesh.n_z + 1));
  for (LdltBackend backend : {LdltBackend::kEigenSimplicial, LdltBackend::kCholmodSimplicial,
                              LdltBackend::kCholmodModify}) {
    BearingSolver cold_solver(Bearing(mesh, backend));
    BearingState s;
    s.eps = 0.7;
    s.omega_journal = 600.0;
    s.eps_dot = 2.0;
    s.line_of_centres_rate = 50.0;
    BearingConfig nowarm = Bearing(mesh, backend);
    nowarm.solver.warm_start = false;
    nowarm.solver.reuse_factorization = false;  // a true cold start has no earlier factor
    BearingSolver cold(nowarm);
    const Split c = TimeSolves(repeats, [&](int) { return cold.Solve(s).stats; });
    const double bare = BareCholmod(cold.fem(), cold.mesh().fixed, repeats);
    std::printf(" backend %s; bare CHOLMOD LDL^T factorise+solve %.1f us\n", ToString(backend),
                1e6 * bare);
    Report("cold start (no warm start)", c, bare);
    // A time-stepping sequence: the state moves a little each call (warm-started active set),
    // with the factor reused as CG preconditioner (default) and refactorising every solve.
    for (bool reuse : {true, false}) {
      BearingConfig cfg = Bearing(mesh, backend);
      cfg.solver.reuse_factorization = reuse;
      BearingSolver warm(cfg);
      const Split w = TimeSolves(repeats, [&](int i) {
        BearingState t = s;
        t.eps = 0.7 + 0.1 * std::sin(0.01 * i);
        t.eps_dot = 2.0 * std::cos(0.01 * i);
        return warm.Solve(t).stats;
      });
      Report(reuse ? "sequence, factor reuse (default)" : "sequence, refactorising", w, bare);
    }
  }
}

void BenchSkirt(int repeats) {
  std::printf("\npiston skirt, paper mesh 30+2+30 x 40 (%d nodes)\n", 63 * 41);
  for (LdltBackend backend : {LdltBackend::kEigenSimplicial, LdltBackend::kCholmodSimplicial,
                              LdltBackend::kCholmodModify}) {
    SkirtConfig cfg = Skirt(backend);
    cfg.solver.warm_start = false;
    cfg.solver.reuse_factorization = false;
    SkirtSolver cold(cfg);
    SkirtState s;
    s.e0 = 12e-6;
    s.gamma = 3e-4;
    s.e0_dot = 0.01;
    s.piston_velocity = 10.0;
    const Split c = TimeSolves(repeats, [&](int) { return cold.Solve(s).stats; });
    // The skirt solves its two panels separately (Omega2 decouples them): bare = both panels.
    double bare = 0.0;
    for (int k = 0; k < SkirtSolver::kPanels; ++k) {
      bare += BareCholmod(cold.panel(k), cold.panel(k).mesh().fixed, repeats);
    }
    std::printf(" backend %s; bare CHOLMOD LDL^T factorise+solve of both panels %.1f us\n",
                ToString(backend), 1e6 * bare);
    Report("cold start (no warm start)", c, bare);
    for (bool reuse : {true, false}) {
      SkirtConfig seq = Skirt(backend);
      seq.solver.reuse_factorization = reuse;
      SkirtSolver warm(seq);
      const Split w = TimeSolves(repeats, [&](int i) {
        SkirtState t = s;
        t.e0 = 12e-6 * std::cos(0.01 * i);
        t.gamma = 3e-4 * std::sin(0.01 * i + 0.3);
        t.piston_velocity = 10.0 * std::cos(0.02 * i);
        return warm.Solve(t).stats;
      });
      Report(reuse ? "sequence, factor reuse (default)" : "sequence, refactorising", w, bare);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::max(3, std::atoi(argv[1])) : 200;
  std::printf("bench_reynolds: medians over %d solves (Release build recommended)\n", repeats);
  BenchBearing("paper mesh", {50, 10, false}, repeats);
  BenchSkirt(repeats);
  BenchBearing("converged validation mesh", {240, 20, true}, std::max(3, repeats / 10));
  return 0;
}
