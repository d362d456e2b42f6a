// The film integrals both joints share (IntegrateFilm) against closed forms on a flat rectangular
// film: uniform pressure -> p A, linear pressure -> exact first moment and the Poiseuille shear,
// linear thickness -> MOFT at the known node, half the nodes cavitated -> half the area (JFO:
// weighted by 1 - theta), pure Couette film -> mu U A / h on both surfaces, boundary friction
// mu_f p_c A against the sliding, the symmetry factor, the part-by-part and element-by-element
// friction sums against each other, and the checks on the caller's fields.
#include <QtTest>

#include <array>
#include <cmath>
#include <stdexcept>

#include "core/lubrication/film_integrals.hpp"
#include "core/lubrication/surface_film.hpp"

using namespace filmdyn::lubrication;

namespace {
constexpr double kLength = 0.02;  // x [m]
constexpr double kWidth = 0.01;   // y [m]
constexpr double kArea = kLength * kWidth;
constexpr double kMu = 0.01;  // [Pa s]

// Flat rectangle [0, kLength] x [0, kWidth], nx x ny elements. fix_x_ends: p prescribed on the
// columns x = 0 and x = kLength only (the y edges keep the natural dp/dy = 0); else on every
// edge.
TriMesh Rectangle(int nx, int ny, bool fix_x_ends) {
  TriMesh m = MakeTensorMesh(Linspace(0.0, kLength, nx), Linspace(0.0, kWidth, ny), false, 0.0);
  for (int j = 0; j < m.ny_nodes(); ++j) {
    for (int i = 0; i < m.nx_nodes(); ++i) {
      const bool x_end = i == 0 || i == m.nx_nodes() - 1;
      const bool y_end = j == 0 || j == m.ny_nodes() - 1;
      if (x_end || (!fix_x_ends && y_end)) m.fixed[m.Node(i, j)] = 1;
    }
  }
  return m;
}

// Smooth surfaces (every factor at its classical value) with a boundary friction coefficient.
class SmoothWithBoundaryFriction final : public FilmFactorModel {
 public:
  explicit SmoothWithBoundaryFriction(double mu_f) : mu_f_(mu_f) {}
  NodalFilmFactors At(double) const override { return {}; }
  double sigma() const override { return 0.0; }
  double boundary_friction() const override { return mu_f_; }

 private:
  double mu_f_;
};

ReynoldsParams Sliding(double u1, double u2, const FilmFactorModel* film = nullptr) {
  ReynoldsParams params;
  params.viscosity = kMu;
  params.u_sum = u1 + u2;
  params.u_diff = u1 - u2;
  params.film = film;
  return params;
}

Eigen::VectorXd Ones(const ReynoldsFem& fem) { return Eigen::VectorXd::Ones(fem.NodeCount()); }

Eigen::VectorXd X(const ReynoldsFem& fem) {
  return Eigen::Map<const Eigen::VectorXd>(fem.mesh().x.data(), fem.NodeCount());
}

bool Near(double a, double b, double rel) { return std::abs(a - b) <= rel * std::abs(b); }
}  // namespace

class TestFilmIntegrals : public QObject {
  Q_OBJECT
 private slots:
  void uniformPressureGivesPressureTimesArea() {
    // p = p0 on every edge and no source: the Reynolds solution is p = p0 everywhere.
    ReynoldsFem fem(Rectangle(8, 5, false), 0, {});
    const double p0 = 2e5, h0 = 10e-6;
    fem.film_thickness().setConstant(h0);
    fem.film_rate().setZero();
    fem.boundary_pressure().setConstant(p0);
    const ReynoldsSolution& sol = fem.Solve(Sliding(0.0, 0.0));
    QVERIFY((sol.pressure.array() - p0).abs().maxCoeff() < 1e-12 * p0);
    const Eigen::VectorXd ones = Ones(fem), x = X(fem);
    const std::array<const Eigen::VectorXd*, 2> directions = {&ones, &x};
    const FilmIntegrals fi =
        IntegrateFilm(fem, sol, Sliding(0.0, 0.0), {.load_directions = directions});
    QVERIFY(Near(fi.load[0], p0 * kArea, 1e-12));
    QVERIFY(Near(fi.load[1], p0 * kWidth * kLength * kLength / 2.0, 1e-12));  // int x dA exact
    QCOMPARE(fi.contact_load[0], 0.0);
    QVERIFY(Near(fi.film_area, kArea, 1e-14));
    QCOMPARE(fi.CavitatedFraction(), 0.0);
    QVERIFY(Near(fi.max_pressure, p0, 1e-12));
    QCOMPARE(fi.max_contact_pressure, 0.0);
    // No gradient, no sliding: no friction.
    QVERIFY(std::abs(fi.friction.surface1) < 1e-12 * p0 * h0 * kArea / kLength);
    QVERIFY(std::abs(fi.element_friction.force) < 1e-12 * p0 * h0 * kArea / kLength);

    // A uniform asperity pressure on top: it adds to the load and is reported as its part.
    ReynoldsSolution fields = sol;
    const double pc0 = 5e4;
    fields.contact_pressure.setConstant(pc0);
    const FilmIntegrals fc =
        IntegrateFilm(fem, fields, Sliding(0.0, 0.0), {.load_directions = directions});
    QVERIFY(Near(fc.load[0], (p0 + pc0) * kArea, 1e-12));
    QVERIFY(Near(fc.contact_load[0], pc0 * kArea, 1e-12));
    QVERIFY(Near(fc.contact_load[1], pc0 * kWidth * kLength * kLength / 2.0, 1e-12));
    QCOMPARE(fc.max_contact_pressure, pc0);

    // The symmetry factor scales every integral, not the extremes or the fraction.
    const FilmIntegrals f2 = IntegrateFilm(fem, fields, Sliding(0.0, 0.0),
                                           {.load_directions = directions, .symmetry = 2.0});
    QCOMPARE(f2.load[0], 2.0 * fc.load[0]);
    QCOMPARE(f2.contact_load[1], 2.0 * fc.contact_load[1]);
    QCOMPARE(f2.film_area, 2.0 * fc.film_area);
    QCOMPARE(f2.max_pressure, fc.max_pressure);
    QCOMPARE(f2.moft, fc.moft);
  }

  void linearPressureGivesPoiseuilleShear() {
    // p = p0 at x = 0, 0 at x = L, dp/dy = 0 on the sides: p = p0 (1 - x/L), reproduced exactly
    // by P1 elements. Load int p dA = p0 A/2; the shear on each surface is -(h/2) dp/dx = h p0/(2L)
    // (eq. 31 with Phi_fp = 1, no sliding), so the friction is h p0 A/(2L) on both.
    ReynoldsFem fem(Rectangle(10, 4, true), 0, {});
    const double p0 = 1e5, h0 = 20e-6;
    fem.film_thickness().setConstant(h0);
    fem.film_rate().setZero();
    for (int k = 0; k < fem.NodeCount(); ++k) {
      fem.boundary_pressure()[k] = fem.mesh().x[k] == 0.0 ? p0 : 0.0;
    }
    const ReynoldsSolution& sol = fem.Solve(Sliding(0.0, 0.0));
    const Eigen::VectorXd ones = Ones(fem), x = X(fem);
    const std::array<const Eigen::VectorXd*, 2> directions = {&ones, &x};
    const FilmIntegrals fi =
        IntegrateFilm(fem, sol, Sliding(0.0, 0.0), {.load_directions = directions});
    QVERIFY(Near(fi.load[0], p0 * kArea / 2.0, 1e-10));
    QVERIFY(Near(fi.load[1], p0 * kWidth * kLength * kLength / 6.0, 1e-10));  // int x (1-x/L)
    const double shear = h0 * p0 * kArea / (2.0 * kLength);
    QVERIFY2(Near(fi.friction.surface1, shear, 1e-10),
             qPrintable(QString("%1 vs %2").arg(fi.friction.surface1).arg(shear)));
    QVERIFY(Near(fi.friction.poiseuille, -shear, 1e-10));
    QVERIFY(Near(fi.friction.surface2, shear, 1e-10));
    QVERIFY(Near(fi.element_friction.force, shear, 1e-10));
    QCOMPARE(fi.element_friction.contact_force, 0.0);
    QVERIFY(Near(fi.max_pressure, p0, 1e-14));
    QCOMPARE(fi.max_pressure_node, 0);  // the first node of the p0 column
  }

  void linearThicknessPutsMoftAtKnownNode() {
    // h decreases along x and increases along y: the thinnest film is at (L, 0).
    ReynoldsFem fem(Rectangle(8, 5, false), 0, {});
    const double h0 = 5e-6;
    for (int k = 0; k < fem.NodeCount(); ++k) {
      fem.film_thickness()[k] = h0 + 1e-3 * (kLength - fem.mesh().x[k]) + 4e-4 * fem.mesh().y[k];
    }
    fem.film_rate().setZero();
    fem.boundary_pressure().setZero();
    const ReynoldsSolution& sol = fem.Solve(Sliding(5.0, 0.0));
    const FilmIntegrals fi = IntegrateFilm(fem, sol, Sliding(5.0, 0.0), {});
    const int expected = fem.mesh().Node(fem.mesh().nx_nodes() - 1, 0);
    QCOMPARE(fi.moft_node, expected);
    QCOMPARE(fi.moft, h0);

    // The peak pressure and its node are those of the field given.
    ReynoldsSolution fields = sol;
    fields.pressure.setZero();
    fields.pressure[17] = 3e6;
    fields.pressure[23] = 1e6;
    const FilmIntegrals fp = IntegrateFilm(fem, fields, Sliding(5.0, 0.0), {});
    QCOMPARE(fp.max_pressure, 3e6);
    QCOMPARE(fp.max_pressure_node, 17);
    fields.pressure.setConstant(-1.0);  // kNone cavitation: no positive pressure at all
    const FilmIntegrals fn = IntegrateFilm(fem, fields, Sliding(5.0, 0.0), {});
    QCOMPARE(fn.max_pressure, 0.0);
    QCOMPARE(fn.max_pressure_node, -1);
  }

  void halfTheNodesCavitated() {
    // 9 element columns, 10 node columns: cavitating the first 5 columns (half the nodes) covers
    // their dual cells, 0.5 + 4 element widths = half the area (the lumped areas of a column sum
    // to its dual-cell width times the film width).
    for (const CavitationModel model : {CavitationModel::kReynolds, CavitationModel::kJfo}) {
      ReynoldsOptions options;
      options.cavitation = model;
      ReynoldsFem fem(Rectangle(9, 6, false), 0, options);
      fem.film_thickness().setConstant(10e-6);
      fem.film_rate().setZero();
      fem.boundary_pressure().setZero();
      ReynoldsSolution fields = fem.Solve(Sliding(0.0, 0.0));
      const TriMesh& m = fem.mesh();
      for (int k = 0; k < m.NodeCount(); ++k) {
        const bool left = k % m.nx_nodes() < 5;
        fields.cavitated[k] = left ? 1 : 0;
        fields.fluid_fraction[k] = left ? 0.25 : 1.0;  // read only with JFO cavitation
      }
      const FilmIntegrals fi = IntegrateFilm(fem, fields, Sliding(0.0, 0.0), {.symmetry = 2.0});
      const double expected = model == CavitationModel::kJfo ? 0.5 * (1.0 - 0.25) : 0.5;
      QVERIFY2(Near(fi.CavitatedFraction(), expected, 1e-14),
               qPrintable(QString("%1 vs %2").arg(fi.CavitatedFraction()).arg(expected)));
      QVERIFY(Near(fi.film_area, 2.0 * kArea, 1e-14));
    }
  }

  void couetteFilmShearIsMuUAOverH() {
    // Constant h, no pressure (p = 0 on every edge, no wedge), full film, smooth surfaces:
    // tau = -mu (U1 - U2)/h on surface 1 and +mu (U1 - U2)/h on surface 2, along either axis.
    const double h0 = 8e-6, u = 7.5;
    for (const int axis : {0, 1}) {
      ReynoldsFem fem(Rectangle(8, 5, false), axis, {});
      fem.film_thickness().setConstant(h0);
      fem.film_rate().setZero();
      fem.boundary_pressure().setZero();
      const ReynoldsSolution& sol = fem.Solve(Sliding(u, 0.0));
      QCOMPARE(sol.pressure.cwiseAbs().maxCoeff(), 0.0);
      const Eigen::VectorXd x = X(fem);
      const double arm_scale = -3.0;
      const std::array<ScaledField, 1> arms = {ScaledField{&x, arm_scale}};
      const FilmIntegrals fi =
          IntegrateFilm(fem, sol, Sliding(u, 0.0), {.friction_arms = arms, .symmetry = 2.0});
      const double couette = kMu * u * kArea / h0;
      QVERIFY2(Near(fi.friction.surface1, -2.0 * couette, 1e-12),
               qPrintable(QString("%1 vs %2").arg(fi.friction.surface1).arg(-2.0 * couette)));
      QVERIFY(Near(fi.friction.surface2, 2.0 * couette, 1e-12));
      QVERIFY(Near(fi.friction.couette_surface1, 2.0 * kArea / h0, 1e-12));
      QVERIFY(Near(fi.element_friction.force, -2.0 * couette, 1e-12));
      // int tau (s x) dA = tau s W L^2/2 (the element mean of x is exact for a linear field).
      QVERIFY(Near(fi.element_friction.moment[0],
                   -2.0 * kMu * u / h0 * arm_scale * kWidth * kLength * kLength / 2.0, 1e-12));
      // Reversed sliding, reversed shear.
      const FilmIntegrals back = IntegrateFilm(fem, sol, Sliding(0.0, u), {});
      QVERIFY(Near(back.friction.surface1, couette, 1e-12));
      QVERIFY(Near(back.element_friction.force, couette, 1e-12));
    }

    // Rough surfaces far apart (H = h/sigma = 8000): the shear-stress factors tend to their
    // smooth values (Phi_f = 1 + O(1/H^2), Phi_fs -> 0, Phi_fp -> 1).
    SurfacePair pair;
    pair.sigma1 = pair.sigma2 = 1e-9 / std::sqrt(2.0);
    pair.E1 = 210e9;
    pair.E2 = 110e9;
    const auto rough = MakeSurfaceFilm(pair);
    ReynoldsFem fem(Rectangle(8, 5, false), 0, {});
    fem.film_thickness().setConstant(h0);
    fem.film_rate().setZero();
    fem.boundary_pressure().setZero();
    const ReynoldsSolution& sol = fem.Solve(Sliding(u, 0.0, rough.get()));
    const FilmIntegrals fr = IntegrateFilm(fem, sol, Sliding(u, 0.0, rough.get()), {});
    QVERIFY(Near(fr.friction.surface1, -kMu * u * kArea / h0, 1e-6));
    QVERIFY(Near(fr.element_friction.force, -kMu * u * kArea / h0, 1e-6));
    QCOMPARE(fr.element_friction.contact_force, 0.0);

    // JFO: the Couette shear scales with the fluid fraction.
    ReynoldsOptions jfo;
    jfo.cavitation = CavitationModel::kJfo;
    ReynoldsFem jfem(Rectangle(8, 5, false), 0, jfo);
    jfem.film_thickness().setConstant(h0);
    jfem.film_rate().setZero();
    jfem.boundary_pressure().setZero();
    ReynoldsSolution fields = jfem.Solve(Sliding(u, 0.0));
    fields.fluid_fraction.setConstant(0.5);
    const FilmIntegrals fj = IntegrateFilm(jfem, fields, Sliding(u, 0.0), {});
    QVERIFY(Near(fj.friction.surface1, -0.5 * kMu * u * kArea / h0, 1e-12));
    QVERIFY(Near(fj.element_friction.force, -0.5 * kMu * u * kArea / h0, 1e-12));
  }

  void boundaryFrictionOpposesSliding() {
    // Couette film plus a uniform asperity pressure: -sgn(U1 - U2) mu_f p_c A on surface 1.
    const SmoothWithBoundaryFriction film(0.12);
    const double h0 = 8e-6, u = -4.0, pc0 = 3e6;
    ReynoldsFem fem(Rectangle(6, 4, false), 0, {});
    fem.film_thickness().setConstant(h0);
    fem.film_rate().setZero();
    fem.boundary_pressure().setZero();
    ReynoldsSolution fields = fem.Solve(Sliding(u, 0.0, &film));
    fields.contact_pressure.setConstant(pc0);
    const FilmIntegrals fi = IntegrateFilm(fem, fields, Sliding(u, 0.0, &film), {});
    const double boundary = 0.12 * pc0 * kArea;  // u < 0: + on surface 1
    const double couette = kMu * u * kArea / h0;
    QVERIFY(Near(fi.element_friction.contact_force, boundary, 1e-12));
    QVERIFY(Near(fi.element_friction.force, -couette + boundary, 1e-12));
    QVERIFY(Near(fi.friction.contact, pc0 * kArea, 1e-12));
    QVERIFY(Near(fi.friction.surface1, -couette + boundary, 1e-12));
    QVERIFY(Near(fi.friction.surface2, couette - boundary, 1e-12));
  }

  void partAndElementSumsAgree() {
    // A rough wedge in mixed lubrication (asperity contact where h < 4 sigma): the friction
    // summed part by part and element by element is the same integral, up to rounding.
    SurfacePair pair;
    pair.sigma1 = 0.4e-6;
    pair.sigma2 = 0.3e-6;
    pair.E1 = 210e9;
    pair.E2 = 110e9;
    const auto rough = MakeSurfaceFilm(pair);
    ReynoldsFem fem(Rectangle(24, 8, false), 0, {});
    for (int k = 0; k < fem.NodeCount(); ++k) {
      fem.film_thickness()[k] = 1.2e-6 + 3e-4 * (kLength - fem.mesh().x[k]);
    }
    fem.film_rate().setZero();
    fem.boundary_pressure().setZero();
    const ReynoldsParams params = Sliding(6.0, 1.0, rough.get());
    const ReynoldsSolution& sol = fem.Solve(params);
    QCOMPARE(sol.stats.status, SolveStatus::kConverged);
    const FilmIntegrals fi = IntegrateFilm(fem, sol, params, {});
    const FilmFriction& f = fi.friction;
    QVERIFY(f.contact > 0.0);
    QVERIFY(f.poiseuille != 0.0);
    const double mu_f = pair.boundary_friction;
    const double scale = kMu * 5.0 * f.couette_surface1 + std::abs(f.poiseuille) + mu_f * f.contact;
    QVERIFY(std::abs(fi.element_friction.force - f.surface1) < 1e-12 * scale);
    QVERIFY(Near(fi.element_friction.contact_force, -mu_f * f.contact, 1e-12));
  }

  void callerMistakesAreLogicErrors() {
    ReynoldsFem fem(Rectangle(4, 3, false), 0, {});
    fem.film_thickness().setConstant(1e-5);
    fem.film_rate().setZero();
    fem.boundary_pressure().setZero();
    const ReynoldsSolution& sol = fem.Solve(Sliding(1.0, 0.0));
    const Eigen::VectorXd ones = Ones(fem), short_field = Eigen::VectorXd::Ones(3);
    const std::array<const Eigen::VectorXd*, 5> too_many = {&ones, &ones, &ones, &ones, &ones};
    QVERIFY_THROWS_EXCEPTION(std::logic_error, IntegrateFilm(fem, sol, Sliding(1.0, 0.0),
                                                             {.load_directions = too_many}));
    const std::array<const Eigen::VectorXd*, 1> wrong_size = {&short_field};
    QVERIFY_THROWS_EXCEPTION(std::logic_error, IntegrateFilm(fem, sol, Sliding(1.0, 0.0),
                                                             {.load_directions = wrong_size}));
    const std::array<ScaledField, 1> no_field = {ScaledField{}};
    QVERIFY_THROWS_EXCEPTION(
        std::logic_error, IntegrateFilm(fem, sol, Sliding(1.0, 0.0), {.friction_arms = no_field}));
    QVERIFY_THROWS_EXCEPTION(std::logic_error,
                             IntegrateFilm(fem, sol, Sliding(1.0, 0.0), {.symmetry = 0.0}));
  }
};

QTEST_GUILESS_MAIN(TestFilmIntegrals)
#include "test_film_integrals.moc"
