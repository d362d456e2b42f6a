// Piston skirt solver: sign conventions, symmetry, closed-form squeeze on a parallel film,
// friction direction, clamped penetrating states, and the two-panel solve against one Reynolds
// problem on the whole skirt mesh (serial and side by side).
#include <QtTest>

#include <algorithm>
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

  // Node lines go through the kinks of the profile and ovality tables: the film thickness is
  // then exact at its minimum on any mesh. Evenly spaced lines (7 axial elements of 4.57 mm)
  // would put no node on the profile's crown at 12.3 mm and report a MOFT 1.1 um too thick.
  void meshFollowsTheProfileAndOvalityKinks() {
    SkirtConfig cfg = Skirt({{0.0, 0.0123, 0.032}, {20e-6, 0.0, 15e-6}});
    cfg.geometry.ovality = {{0.3, 2.0}, {0.0, 8e-6}};  // kinks at 0.3 rad (thrust), 2.0 (anti)
    cfg.mesh.n_axial = 7;
    cfg.mesh.n_thrust = 5;
    cfg.mesh.n_anti = 5;
    const TriMesh m = SkirtSolver::MakeMesh(cfg.geometry, cfg.mesh);
    QCOMPARE(m.ny_nodes(), 8);
    QCOMPARE(m.nx_nodes(), 5 + cfg.mesh.n_relief + 5 + 1);
    auto has_line = [](const std::vector<double>& lines, double at) {
      for (double v : lines) {
        if (std::abs(v - at) < 1e-15) return true;
      }
      return false;
    };
    QVERIFY(has_line(m.y_lines, 0.0123));
    QVERIFY(has_line(m.x_lines, 0.3 * cfg.geometry.radius));
    QVERIFY(has_line(m.x_lines, 2.0 * cfg.geometry.radius));
    SkirtSolver solver(cfg);
    SkirtState s;
    s.e0 = 5e-6;  // toward the thrust side: the thinnest film on the thrust axis at the crown
    s.piston_velocity = 5.0;
    const SkirtResult& r = solver.Solve(s);
    QCOMPARE(r.stats.status, SolveStatus::kConverged);
    QVERIFY(std::abs(r.moft - (20e-6 - 5e-6)) < 1e-15);
    QVERIFY(std::abs(r.moft_y - 0.0123) < 1e-15);
  }

  // The line placement itself: every break on a line, n intervals, spacing as even as the
  // breaks allow (the largest spacing is the smallest possible), even spacing without breaks
  // or with fewer intervals than segments.
  void conformingLinesPlaceTheBreaks() {
    const std::vector<double> lines = ConformingLines(0.0, 1.0, 10, {0.25, 0.5, 0.75});
    QCOMPARE(static_cast<int>(lines.size()), 11);
    double widest = 0.0;
    for (std::size_t k = 1; k < lines.size(); ++k) {
      QVERIFY(lines[k] > lines[k - 1]);
      widest = std::max(widest, lines[k] - lines[k - 1]);
    }
    QCOMPARE(widest, 0.25 / 2);  // 3 + 3 + 2 + 2 intervals: no split does better than 1/8
    for (double at : {0.25, 0.5, 0.75}) {
      QVERIFY(std::count(lines.begin(), lines.end(), at) == 1);
    }
    QCOMPARE(ConformingLines(0.0, 1.0, 4, {}), Linspace(0.0, 1.0, 4));
    QCOMPARE(ConformingLines(0.0, 1.0, 4, {0.0, 1.0, -3.0, 7.0}), Linspace(0.0, 1.0, 4));
    QCOMPARE(ConformingLines(0.0, 1.0, 2, {0.2, 0.4, 0.6}), Linspace(0.0, 1.0, 2));
    // A short segment keeps one interval; the rest share the remainder evenly.
    const std::vector<double> uneven = ConformingLines(0.0, 1.0, 5, {0.1});
    QCOMPARE(uneven, (std::vector<double>{0.0, 0.1, 0.325, 0.55, 0.775, 1.0}));
  }
};

QTEST_GUILESS_MAIN(TestSkirt)
#include "test_skirt_solver.moc"
