// Piston skirt solver: sign conventions, symmetry, closed-form squeeze on a parallel film,
// friction direction, clamped penetrating states, and the two-panel solve against one Reynolds
// problem on the whole skirt mesh (serial and side by side).
#include <QtTest>

#include <cmath>
#include <numbers>

#include "core/lubrication/skirt_solver.hpp"

using namespace filmdyn::lubrication;

namespace {
constexpr double kPi = std::numbers::pi;
SkirtConfig Skirt(Table1D profile = {{0.0, 0.016, 0.032}, {20e-6, 0.0, 15e-6}}) {
  SkirtConfig cfg;
  auto& g = cfg.geometry;
  g.radius = 0.0415;
  g.skirt_length = 0.032;
  g.radial_clearance = 20e-6;
  g.pin_position = 0.016;
  g.alpha1 = g.alpha2 = 46.0 * kPi / 180.0;
  g.profile = std::move(profile);
  cfg.viscosity = 0.008;
  return cfg;
}
}  // namespace

class TestSkirt : public QObject {
  Q_OBJECT
 private slots:
  void thrustSideSqueezePushesBack() {
    SkirtSolver solver(Skirt());
    SkirtState s;
    s.e0 = 10e-6;
    s.e0_dot = 0.01;  // moving towards the thrust side
    const SkirtResult& r = solver.Solve(s);
    QCOMPARE(r.stats.status, SolveStatus::kConverged);
    QVERIFY(r.lateral_force < 0.0);
    QVERIFY(r.stats.complementarity_residual < 1e-12);
    QVERIFY(std::abs(r.moft_alpha) < 1e-12);  // thinnest film on the thrust axis
    QVERIFY(r.cavitated_fraction > 0.2);      // the anti-thrust panel separates
  }

  void panelsReproduceTheWholeSkirtSolve() {
    // The skirt solves Omega1 and Omega3 as two problems because Omega2 (p = 0) decouples them.
    // Reference: one ReynoldsFem on the whole mesh (relief nodes fixed) with the same film. The
    // pressures and the lateral force and moment must agree to round-off, over a sequence (the
    // panels keep their own active sets and factors), with one and with two threads.
    const SkirtConfig cfg = Skirt();
    SkirtSolver serial(cfg), threaded(cfg);
    threaded.SetThreads(2);
    ReynoldsFem whole(SkirtSolver::MakeMesh(cfg.geometry, cfg.mesh), 1, cfg.solver);
    const TriMesh& m = serial.mesh();
    QCOMPARE(m.NodeCount(), whole.NodeCount());
    int panel_nodes = 0;
    for (int k = 0; k < SkirtSolver::kPanels; ++k) panel_nodes += serial.panel(k).NodeCount();
    QCOMPARE(panel_nodes, (31 + 31) * 41);  // the relief's interior column belongs to neither
    Eigen::VectorXd cosa(m.NodeCount()), arm(m.NodeCount());
    for (int k = 0; k < m.NodeCount(); ++k) {
      cosa[k] = std::cos(serial.alpha()[k]);
      arm[k] = m.y[k] - cfg.geometry.pin_position;
    }
    for (int step = 0; step < 12; ++step) {
      SkirtState s;
      s.e0 = 9e-6 * std::cos(0.4 * step);
      s.gamma = 3e-4 * std::sin(0.3 * step);
      s.e0_dot = 0.02 * std::sin(0.4 * step);
      s.gamma_dot = 0.3 * std::cos(0.3 * step);
      s.piston_velocity = 12.0 * std::cos(0.25 * step + 0.1);
      const SkirtResult a = serial.Solve(s);
      const SkirtResult& b = threaded.Solve(s);
      whole.film_thickness() = serial.film_thickness();
      for (int k = 0; k < m.NodeCount(); ++k) {
        whole.film_rate()[k] = -(s.e0_dot + arm[k] * s.gamma_dot) * cosa[k];
      }
      ReynoldsParams params;
      params.viscosity = cfg.viscosity;
      params.u_sum = -s.piston_velocity;
      params.u_diff = s.piston_velocity;
      const ReynoldsSolution& w = whole.Solve(params);
      QCOMPARE(w.stats.status, SolveStatus::kConverged);
      const double pmax = w.pressure.maxCoeff();
      QVERIFY(pmax > 0.0);
      QVERIFY((serial.fields().pressure - w.pressure).cwiseAbs().maxCoeff() < 1e-8 * pmax);
      const double lateral = -2.0 * whole.IntegrateProduct(w.pressure, cosa);
      QVERIFY2(std::abs(a.lateral_force - lateral) < 1e-8 * std::abs(lateral),
               qPrintable(QString("%1 vs %2").arg(a.lateral_force).arg(lateral)));
      // Two threads: the same numbers bit for bit.
      QVERIFY(b.lateral_force == a.lateral_force && b.moment_about_pin == a.moment_about_pin &&
              b.friction_force == a.friction_force && b.moft == a.moft);
      QVERIFY(threaded.fields().pressure == serial.fields().pressure);
    }
  }

  void parallelFilmSqueezeMatchesClosedForm() {
    // Flat profile, no tilt: axially the pressure of a parallel squeeze film between p = 0 ends,
    // p = 6 mu (-dh/dt)/h^3 y (L - y) per unit circumference when the circumferential flow is
    // negligible. Using a very short skirt makes dp/dalpha small relative to dp/dy; compare the
    // lateral force with the strip integral over the thrust panel (Reynolds: p>0 where dh/dt<0).
    SkirtConfig cfg = Skirt({{0.0}, {0.0}});
    cfg.geometry.skirt_length = 0.001;
    cfg.geometry.pin_position = 0.0005;
    cfg.mesh.n_axial = 40;
    cfg.mesh.n_thrust = cfg.mesh.n_anti = 120;
    SkirtSolver solver(cfg);
    SkirtState s;
    s.e0_dot = 1e-3;
    const SkirtResult& r = solver.Solve(s);
    const double c = cfg.geometry.radial_clearance, L = cfg.geometry.skirt_length;
    const double R = cfg.geometry.radius, a1 = cfg.geometry.alpha1, mu = cfg.viscosity;
    // F = -2 int_0^a1 int_0^L p cos(a) R da dy, p = 6 mu e0_dot cos(a) y (L-y) / c^3.
    const double closed =
        -2.0 * mu * s.e0_dot * L * L * L / (c * c * c) * R * (0.5 * a1 + 0.25 * std::sin(2.0 * a1));
    QVERIFY2(std::abs(r.lateral_force - closed) < 0.01 * std::abs(closed),
             qPrintable(QString("%1 vs %2").arg(r.lateral_force).arg(closed)));
    // Symmetric about the pin (a_p = L/2): no moment (up to the one-way triangle diagonals).
    QVERIFY(std::abs(r.moment_about_pin) < 1e-3 * std::abs(r.lateral_force) * L);
  }

  void frictionOpposesSliding() {
    SkirtSolver solver(Skirt());
    SkirtState s;
    s.e0 = 12e-6;
    s.gamma = 3e-4;
    s.piston_velocity = 12.0;
    const SkirtResult up = solver.Solve(s);
    QVERIFY(up.friction_force < 0.0);
    QVERIFY(std::abs(up.friction_power_loss - std::abs(up.friction_force * 12.0)) < 1e-9);
    s.piston_velocity = -12.0;
    const SkirtResult down = solver.Solve(s);
    QVERIFY(down.friction_force > 0.0);
    QCOMPARE(up.stats.status, SolveStatus::kConverged);
    QCOMPARE(down.stats.status, SolveStatus::kConverged);
  }

  void tiltMovesLoadAlongTheSkirt() {
    SkirtSolver solver(Skirt());
    SkirtState s;
    s.e0 = 5e-6;
    s.gamma = 1e-3;  // lower skirt towards the thrust side: film thinnest at the bottom
    s.piston_velocity = 5.0;
    const SkirtResult& r = solver.Solve(s);
    QVERIFY(r.moft_y > solver.config().geometry.pin_position);
    QVERIFY(std::isfinite(r.moment_about_pin));
  }

  void penetratingStateIsClampedNotCrashed() {
    SkirtSolver solver(Skirt());
    SkirtState s;
    s.e0 = 60e-6;  // beyond the clearance + profile
    s.piston_velocity = 5.0;
    const SkirtResult& r = solver.Solve(s);
    QVERIFY(r.clamped_nodes > 0);
    QVERIFY(std::isfinite(r.lateral_force));
    QCOMPARE(r.moft, solver.config().min_film);
  }

  void jfoRunsOnSkirt() {
    SkirtConfig cfg = Skirt();
    cfg.solver.cavitation = CavitationModel::kJfo;
    SkirtSolver solver(cfg);
    SkirtState s;
    s.e0 = 12e-6;
    s.gamma = -2e-4;
    s.piston_velocity = 8.0;
    const SkirtResult& r = solver.Solve(s);
    QCOMPARE(r.stats.status, SolveStatus::kConverged);
    QVERIFY(r.stats.max_mass_residual < 1e-10);
    QVERIFY(r.lateral_force < 0.0);
  }
};

QTEST_GUILESS_MAIN(TestSkirt)
#include "test_skirt_solver.moc"
