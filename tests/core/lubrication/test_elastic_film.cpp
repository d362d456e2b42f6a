// Elastic surfaces (film_compliance.hpp): Love's rectangle against Johnson's published values and
// an independent quadrature, the half-space compliance's assembly (superposition over the
// mesh's cells, the mirror of a symmetric half), the coupled film solve's fixed point (h =
// h_rigid + C p at every converged solution), the infinitely stiff limit against the rigid
// solver, the elastic-layer bearing against an independent finite-difference solution
// written here, over eps 0.2-0.9 at two layer compliances and with Barus', Roelands' and Cross'
// laws, the mass-conserving film on elastic surfaces against the Reynolds one where no film
// reforms (second order in the mesh), and a pressure law the rigid film cannot carry, reached
// from the elastic isoviscous film.
#include <sys/stat.h>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <numbers>
#include <tuple>
#include <vector>

#include "core/base/input_error.hpp"
#include "core/lubrication/bearing_calculator.hpp"
#include "core/lubrication/bearing_solver.hpp"
#include "core/lubrication/ehd_validation.hpp"
#include "core/lubrication/film_compliance.hpp"
#include "core/lubrication/imported_compliance.hpp"
#include "core/lubrication/oil_validation.hpp"
#include "core/lubrication/skirt_solver.hpp"

using namespace filmdyn;
using namespace filmdyn::lubrication;

namespace {
constexpr double kPi = std::numbers::pi;

// Integral of 1/r over [0, a] x [0, b] seen from the corner (0, 0), in polar coordinates by
// composite Simpson over the angle: int_0^atan(b/a) a / cos(t) dt + int_atan(b/a)^(pi/2)
// b / sin(t) dt (the radial integral of 1/r * r dr is the distance to the far side).
double CornerIntegralPolar(double a, double b, int n) {
  auto simpson = [n](auto f, double lo, double hi) {
    const double h = (hi - lo) / n;
    double s = f(lo) + f(hi);
    for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * f(lo + i * h);
    return s * h / 3.0;
  };
  const double split = std::atan2(b, a);
  return simpson([a](double t) { return a / std::cos(t); }, 0.0, split) +
         simpson([b](double t) { return b / std::sin(t); }, split, 0.5 * kPi);
}

struct FdBearing {
  double load = 0.0, attitude_deg = 0.0, max_deformation = 0.0;
};

// Independent solution of the elastic-layer bearing: finite differences (second order,
// conservative, face conductivities from the means of the neighbouring nodes) of
//   (1/R^2) d/dth (h^3 dp/dth) + d/dz (h^3 dp/dz) = 6 mu omega dh/dth,
//   h(th, z) = c (1 + eps cos th) + layer p(th, z),
// on th in [0, 2 pi] with p = 0 at th = 0 = 2 pi and at the edges, half width with dp/dz = 0
// at the mid-plane, Swift-Stieber cavitation p >= 0 by projected nonlinear Gauss-Seidel: each
// node's update uses the films of the current iterate (its own included), under-relaxed, until
// the largest change is below 1e-10 of the peak.
FdBearing SolveFd(double radius, double width, double clearance, double mu, double omega,
                  double eps, double layer, int nth, int nz,
                  const std::function<double(double p, double h)>& fluidity = {}) {
  const double dth = 2.0 * kPi / nth, dz = 0.5 * width / nz;
  auto idx = [nth](int i, int j) { return j * (nth + 1) + i; };
  std::vector<double> p((nth + 1) * (nz + 1), 0.0), hr(nth + 1);
  for (int i = 0; i <= nth; ++i) hr[i] = clearance * (1.0 + eps * std::cos(i * dth));
  auto film = [&](int i, int j) { return hr[i] + layer * p[idx(i, j)]; };
  // mu / mu(p, h) times h^3: the oil's laws enter the conductivity only (the Couette flow
  // carries no viscosity).
  auto k = [&](int i, int j) {
    const double h = film(i, j);
    return std::pow(h, 3) * (fluidity ? fluidity(p[idx(i, j)], h) : 1.0);
  };
  const double w = layer > 1e-13 ? 0.9 : 1.5;
  for (int sweep = 0; sweep < 400000; ++sweep) {
    double change = 0.0, pmax = 0.0;
    for (int j = 0; j < nz; ++j) {  // j = nz: the edge, p = 0
      for (int i = 1; i < nth; ++i) {
        const int c = idx(i, j);
        const int sj = j == 0 ? 1 : j - 1;  // z = 0: the mirror node j = -1 equals j = 1
        const double kc = k(i, j);
        const double ke = 0.5 * (kc + k(i + 1, j)) / (radius * radius * dth * dth);
        const double kw = 0.5 * (kc + k(i - 1, j)) / (radius * radius * dth * dth);
        const double kn = 0.5 * (kc + k(i, j + 1)) / (dz * dz);
        const double ks = 0.5 * (kc + k(i, sj)) / (dz * dz);
        const double rhs = 6.0 * mu * omega * (film(i + 1, j) - film(i - 1, j)) / (2.0 * dth);
        const double gs = (ke * p[idx(i + 1, j)] + kw * p[idx(i - 1, j)] + kn * p[idx(i, j + 1)] +
                           ks * p[idx(i, sj)] - rhs) /
                          (ke + kw + kn + ks);
        const double next = std::max(0.0, p[c] + w * (gs - p[c]));
        change = std::max(change, std::abs(next - p[c]));
        p[c] = next;
        pmax = std::max(pmax, next);
      }
    }
    if (sweep > 10 && change <= 1e-10 * pmax) break;
  }
  double fn = 0.0, ft = 0.0, pmax = 0.0;
  for (int j = 0; j <= nz; ++j) {
    const double wz = (j == 0 || j == nz) ? 0.5 : 1.0;
    for (int i = 0; i < nth; ++i) {
      const double v = p[idx(i, j)];
      fn += wz * v * std::cos(i * dth);
      ft += wz * v * std::sin(i * dth);
      pmax = std::max(pmax, v);
    }
  }
  const double area = radius * dth * dz * 2.0;
  return {std::hypot(fn, ft) * area, std::atan2(ft, -fn) * 180.0 / kPi, layer * pmax};
}

BearingConfig LayerBearing(double layer_modulus, int n_theta, int n_z) {
  BearingConfig cfg;
  cfg.geometry = {0.025, 0.02, 25e-6};
  cfg.viscosity = 0.01;
  cfg.mesh = {n_theta, n_z, true};
  cfg.compliance.model = ComplianceModel::kElasticLayer;
  cfg.compliance.layer_thickness = 1e-3;
  cfg.compliance.layer_modulus = layer_modulus;
  cfg.compliance.layer_poisson = 0.3;
  return cfg;
}

SkirtConfig ElasticSkirt(ComplianceModel model, double modulus) {
  SkirtConfig cfg;
  auto& g = cfg.geometry;
  g.radius = 0.0415;
  g.skirt_length = 0.032;
  g.radial_clearance = 20e-6;
  g.pin_position = 0.016;
  g.alpha1 = g.alpha2 = 46.0 * kPi / 180.0;
  g.profile = {{0.0, 0.016, 0.032}, {20e-6, 0.0, 15e-6}};
  cfg.viscosity = 0.008;
  cfg.mesh = {12, 2, 12, 16};
  cfg.compliance.model = model;
  cfg.compliance.layer_thickness = 2e-3;
  cfg.compliance.layer_modulus = cfg.compliance.modulus1 = modulus;
  cfg.compliance.modulus2 = modulus;
  return cfg;
}

SkirtState SlappingSkirt() {
  SkirtState s;
  s.e0 = 15e-6;
  s.gamma = 2e-4;
  s.e0_dot = 0.02;
  s.piston_velocity = 12.0;
  return s;
}

// An "FE" compliance of a bearing surface written here: a periodic grid of nx x ny nodes over
// the whole bearing (x = R psi, y across the width), C_ij = the half-space deflection at node i
// per unit force spread over node j's cell (Love's rectangle / (pi E* A_j)), symmetrised.
ImportedCompliance HalfSpaceBearingSurface(double radius, double width, int nx, int ny,
                                           double e_star) {
  ImportedCompliance c;
  const double period = 2.0 * kPi * radius;
  for (int i = 0; i < nx; ++i) c.x_lines.push_back(period * i / nx);
  c.y_lines = Linspace(0.0, width, ny - 1);
  const double dx = period / nx, dy = width / (ny - 1);
  const int m = nx * ny;
  c.matrix.resize(m, m);
  for (int r = 0; r < m; ++r) {
    const double xr = c.x_lines[r % nx], yr = c.y_lines[r / nx];
    for (int q = 0; q < m; ++q) {
      double ddx = c.x_lines[q % nx] - xr;
      ddx -= period * std::round(ddx / period);
      const int jq = q / nx;
      const double y1 = jq == 0 ? 0.0 : c.y_lines[jq] - 0.5 * dy;
      const double y2 = jq == ny - 1 ? width : c.y_lines[jq] + 0.5 * dy;
      const double area = dx * (y2 - y1);
      c.matrix(r, q) = e_star / kPi *
                       BoussinesqRectangle(ddx - 0.5 * dx, ddx + 0.5 * dx, y1 - yr, y2 - yr) / area;
    }
  }
  c.matrix = 0.5 * (c.matrix + c.matrix.transpose()).eval();
  return c;
}

}  // namespace

class TestElasticFilm : public QObject {
  Q_OBJECT
 private slots:
  void loveRectangleMatchesJohnsonAndAQuadrature() {
    // Johnson, Contact Mechanics (1985) §3.2: a square of side 2a under uniform p deflects its
    // centre by 2.24 p a (1 - nu^2)/E and its corners by 1.12 (= 8 ln(1 + sqrt 2)/pi and half).
    const double a = 1.7e-3;
    const double centre = BoussinesqRectangle(-a, a, -a, a) / kPi / a;
    const double corner = BoussinesqRectangle(0.0, 2.0 * a, 0.0, 2.0 * a) / kPi / a;
    QVERIFY(std::abs(centre - 2.24) < 0.005);
    QVERIFY(std::abs(corner - 1.12) < 0.003);
    QVERIFY(std::abs(centre - 8.0 * std::log(1.0 + std::sqrt(2.0)) / kPi) < 1e-13);
    // Points inside, on the edge and outside a rectangle, by superposing corner integrals from
    // an independent polar quadrature (inside: four rectangles meeting at the point; outside:
    // differences of rectangles reaching the point).
    const double x1 = -1e-3, x2 = 3e-3, y1 = -0.5e-3, y2 = 2e-3;
    auto by_quadrature = [&](double px, double py) {
      auto quad = [](double u, double v) {  // signed corner integral over [0, u] x [0, v]
        if (u == 0.0 || v == 0.0) return 0.0;
        const double s = (u > 0) == (v > 0) ? 1.0 : -1.0;
        return s * CornerIntegralPolar(std::abs(u), std::abs(v), 4000);
      };
      return quad(x2 - px, y2 - py) - quad(x1 - px, y2 - py) - quad(x2 - px, y1 - py) +
             quad(x1 - px, y1 - py);
    };
    for (const auto& [px, py] : std::vector<std::pair<double, double>>{
             {0.0, 0.0}, {2.5e-3, 1.9e-3}, {-1e-3, 0.0}, {5e-3, 4e-3}, {-4e-3, 1e-3}}) {
      const double closed = BoussinesqRectangle(x1 - px, x2 - px, y1 - py, y2 - py);
      const double quad = by_quadrature(px, py);
      QVERIFY2(std::abs(closed - quad) <= 1e-9 * std::abs(quad),
               qPrintable(QString("at (%1, %2): %3 vs %4").arg(px).arg(py).arg(closed).arg(quad)));
    }
  }

  void halfSpaceComplianceSuperposesOverTheCells() {
    // The cells tile the mesh, so a uniform pressure deflects each node as Love's rectangle
    // over the whole domain (to rounding); a symmetric half with its mirror as the whole.
    const TriMesh full =
        MakeTensorMesh(Linspace(0.0, 0.03, 17), {0.0, 0.002, 0.005, 0.01, 0.016, 0.02}, false, 0.0);
    ComplianceSpec spec;
    spec.model = ComplianceModel::kHalfSpace;
    spec.modulus1 = 210e9;
    spec.modulus2 = 110e9;
    spec.poisson1 = 0.3;
    spec.poisson2 = 0.33;
    const double e_star = CompositeCompliance(210e9, 0.3, 110e9, 0.33);
    const SurfaceCompliance c = SurfaceCompliance::Build(spec, full, std::nullopt);
    Eigen::VectorXd delta;
    const double p = 5e7;
    c.Apply(Eigen::VectorXd::Constant(full.NodeCount(), p), delta);
    for (int k = 0; k < full.NodeCount(); ++k) {
      const double want =
          p * e_star / kPi *
          BoussinesqRectangle(-full.x[k], 0.03 - full.x[k], -full.y[k], 0.02 - full.y[k]);
      QVERIFY(std::abs(delta[k] - want) <= 1e-12 * want);
    }
    const TriMesh half =
        MakeTensorMesh(Linspace(0.0, 0.03, 17), {0.0, 0.002, 0.005, 0.01}, false, 0.0);
    const SurfaceCompliance ch = SurfaceCompliance::Build(spec, half, 0.01);
    ch.Apply(Eigen::VectorXd::Constant(half.NodeCount(), p), delta);
    for (int k = 0; k < half.NodeCount(); ++k) {
      const double want =
          p * e_star / kPi *
          BoussinesqRectangle(-half.x[k], 0.03 - half.x[k], -half.y[k], 0.02 - half.y[k]);
      QVERIFY(std::abs(delta[k] - want) <= 1e-12 * want);
    }
    // Mirrored in x about x = 0 and in y about y = 0.01: the whole film [-0.03, 0.03] x [0, 0.02].
    const SurfaceCompliance cxy = SurfaceCompliance::Build(spec, half, 0.01, 0.0);
    cxy.Apply(Eigen::VectorXd::Constant(half.NodeCount(), p), delta);
    for (int k = 0; k < half.NodeCount(); ++k) {
      const double want =
          p * e_star / kPi *
          BoussinesqRectangle(-0.03 - half.x[k], 0.03 - half.x[k], -half.y[k], 0.02 - half.y[k]);
      QVERIFY(std::abs(delta[k] - want) <= 1e-12 * want);
    }
    // Reciprocity on a uniform mesh: between nodes with whole (equal) cells the matrix is
    // symmetric (the border's half cells are not).
    const TriMesh uniform =
        MakeTensorMesh(Linspace(0.0, 0.01, 8), Linspace(0.0, 0.004, 4), false, 0.0);
    const Eigen::MatrixXd m = SurfaceCompliance::Build(spec, uniform, std::nullopt).dense();
    auto inner = [&](int k) {
      return uniform.x[k] > 0.0 && uniform.x[k] < 0.01 - 1e-12 && uniform.y[k] > 0.0 &&
             uniform.y[k] < 0.004 - 1e-12;
    };
    for (int a = 0; a < uniform.NodeCount(); ++a)
      for (int b = 0; b < uniform.NodeCount(); ++b)
        if (inner(a) && inner(b)) QVERIFY(std::abs(m(a, b) - m(b, a)) <= 1e-12 * m(a, a));
  }

  void convergedFilmIsTheRigidFilmPlusTheDeformation() {
    // At every converged solution h = h_rigid + C (p + p_c) to the stated tolerance (here
    // recomputed from the fields, not taken from the solver's statistics), for both models.
    for (const ComplianceModel model :
         {ComplianceModel::kElasticLayer, ComplianceModel::kHalfSpace}) {
      BearingConfig cfg = LayerBearing(5e9, 90, 12);
      cfg.compliance.model = model;
      cfg.compliance.modulus1 = 210e9;
      cfg.compliance.modulus2 = 110e9;
      BearingSolver solver(cfg);
      BearingState s;
      s.omega_journal = 314.0;
      for (const double eps : {0.3, 0.8, 0.97}) {
        s.eps = eps;
        const BearingResult& r = solver.Solve(s);
        QVERIFY2(r.elastic.converged, qPrintable(QString::fromStdString(r.elastic.message)));
        const Eigen::VectorXd& h = solver.film_thickness();
        Eigen::VectorXd load = solver.fields().pressure + solver.fields().contact_pressure, cp;
        SurfaceCompliance::Build(cfg.compliance, solver.mesh(), 0.01).Apply(load, cp);
        double worst = 0.0;
        for (int k = 0; k < h.size(); ++k) {
          const double rigid = 25e-6 * (1.0 + eps * std::cos(solver.mesh().x[k] / 0.025));
          worst = std::max(worst, std::abs(h[k] - rigid - cp[k]));
        }
        QVERIFY2(worst <= cfg.compliance.tolerance * h.minCoeff(),
                 qPrintable(QString("%1 eps %2: %3 m").arg(ToString(model)).arg(eps).arg(worst)));
        QVERIFY(r.max_deformation > 0.0);
        QCOMPARE(r.max_deformation, solver.deformation().maxCoeff());
      }
    }
  }

  void infinitelyStiffSurfacesReproduceTheRigidBearing() {
    BearingState s;
    s.omega_journal = 314.0;
    for (const ComplianceModel model :
         {ComplianceModel::kElasticLayer, ComplianceModel::kHalfSpace}) {
      BearingConfig cfg = LayerBearing(1e30, 60, 8);
      cfg.compliance.model = model;
      cfg.compliance.modulus1 = cfg.compliance.modulus2 = 1e30;
      BearingConfig rigid_cfg = cfg;
      rigid_cfg.compliance = {};
      BearingSolver elastic(cfg), rigid(rigid_cfg);
      for (const double eps : {0.5, 0.95}) {
        s.eps = eps;
        const BearingResult a = elastic.Solve(s);
        const BearingResult& b = rigid.Solve(s);
        for (const auto& [x, y] : std::vector<std::pair<double, double>>{
                 {a.load, b.load},
                 {a.attitude_deg, b.attitude_deg},
                 {a.friction_torque_journal, b.friction_torque_journal},
                 {a.moft, b.moft},
                 {a.side_flow, b.side_flow},
                 {a.max_pressure, b.max_pressure}}) {
          QVERIFY2(std::abs(x - y) <= 1e-10 * std::abs(y),
                   qPrintable(QString("%1 vs %2").arg(x).arg(y)));
        }
      }
    }
  }

  // A pressure law the rigid film cannot carry: at eps 0.9 the rigid bearing's isoviscous
  // pressure passes Barus' limit 1/alpha (alpha = 1e-7 1/Pa), so no finite pressure exists and
  // the continuation in the compliance, which starts from the rigid film, fails. From the
  // elastic isoviscous film the law's strength is raised to its full value instead: the solve
  // converges (h = h_rigid + C p within its tolerance, no node at the law's limit) and agrees
  // with the independent finite-difference solution.
  void pressureLawTheRigidFilmCannotCarryIsReachedFromTheIsoviscousFilm() {
    const double omega = 314.0, alpha = 1e-7, modulus = 5e9;
    BearingState s;
    s.omega_journal = omega;
    s.eps = 0.9;
    BearingConfig cfg = LayerBearing(modulus, 192, 16);
    cfg.pressure_viscosity = PressureViscosity::Barus(alpha);
    BearingConfig rigid_cfg = cfg;
    rigid_cfg.compliance = {};
    BearingSolver rigid(rigid_cfg), elastic(cfg);
    const BearingResult a = rigid.Solve(s);
    qInfo("rigid: %d nodes at the law's limit", a.stats.capped_nodes);
    QVERIFY(a.stats.capped_nodes > 0);
    const BearingResult& r = elastic.Solve(s);
    QVERIFY2(r.elastic.converged, qPrintable(QString::fromStdString(r.elastic.message)));
    QCOMPARE(r.stats.capped_nodes, 0);
    const Eigen::VectorXd& h = elastic.film_thickness();
    Eigen::VectorXd load = elastic.fields().pressure + elastic.fields().contact_pressure, cp;
    SurfaceCompliance::Build(cfg.compliance, elastic.mesh(), 0.01).Apply(load, cp);
    double worst = 0.0;
    for (int k = 0; k < h.size(); ++k) {
      const double rigid_h = 25e-6 * (1.0 + s.eps * std::cos(elastic.mesh().x[k] / 0.025));
      worst = std::max(worst, std::abs(h[k] - rigid_h - cp[k]));
    }
    QVERIFY(worst <= cfg.compliance.tolerance * h.minCoeff());
    const FdBearing fd =
        SolveFd(0.025, 0.02, 25e-6, 0.01, omega, s.eps, LayerCompliance(1e-3, modulus, 0.3), 160,
                16, [&](double p, double) { return std::exp(-alpha * std::max(p, 0.0)); });
    qInfo(
        "elastic: load %.6g vs %.6g N (%+.3f %%), peak %.4g MPa, deformation %.3g vs %.3g um, "
        "fixed point %.2e m",
        r.load, fd.load, 100 * (r.load / fd.load - 1.0), r.max_pressure * 1e-6,
        r.max_deformation * 1e6, fd.max_deformation * 1e6, worst);
    QVERIFY(std::abs(r.load / fd.load - 1.0) < 0.01);
  }

  // A mass-conserving film on elastic surfaces is the Reynolds film where no film reforms. The
  // steady bearing's film starts full at its largest gap, ruptures where it diverges and meets
  // that full inlet again; with rigid surfaces (a gap varying around only) the two models'
  // discretisations coincide on this uniform mesh and so do their pressures, to round-off. The
  // deformation makes the gap vary across the width too, where the JFO film's Couette flow
  // (face fluxes along the mesh's lines) and the Reynolds film's (a Galerkin integral over the
  // triangles) differ at second order: the two loads and peak pressures converge to each other
  // at that order as the mesh is refined, the cavitated zones within a node of each other.
  void massConservingFilmOnElasticSurfacesIsTheReynoldsFilm() {
    BearingState s;
    s.omega_journal = 314.0;
    for (const ComplianceModel model :
         {ComplianceModel::kElasticLayer, ComplianceModel::kHalfSpace}) {
      std::vector<double> diffs;
      for (const int n : {1, 2, 4}) {
        BearingConfig cfg = LayerBearing(5e9, 48 * n, 8 * n);
        cfg.compliance.model = model;
        cfg.compliance.modulus1 = 210e9;
        cfg.compliance.modulus2 = 20e9;
        cfg.compliance.tolerance = 1e-7;  // the deformation's own error far below the difference
        BearingConfig jfo_cfg = cfg;
        jfo_cfg.solver.cavitation = CavitationModel::kJfo;
        BearingSolver reynolds(cfg), jfo(jfo_cfg);
        double worst = 0.0;
        for (const double eps : {0.5, 0.8, 0.95}) {
          s.eps = eps;
          const BearingResult a = reynolds.Solve(s);
          const BearingResult& b = jfo.Solve(s);
          QVERIFY(a.elastic.converged && b.elastic.converged);
          const double load = std::abs(b.load / a.load - 1.0);
          const double peak = std::abs(b.max_pressure / a.max_pressure - 1.0);
          // The same cavitated zone: the JFO film's partial nodes are the Reynolds film's
          // zero-pressure ones but for at most one node along each line around, where the two
          // discretisations put the rupture (fixed nodes, at zero pressure and full, left out).
          const Eigen::VectorXd& theta = jfo.fields().fluid_fraction;
          const Eigen::VectorXd& p = reynolds.fields().pressure;
          int partial = 0, differ = 0;
          for (int k = 0; k < theta.size(); ++k) {
            if (jfo.mesh().fixed[k]) continue;
            partial += theta[k] < 1.0;
            differ += (theta[k] < 1.0) != (p[k] <= 0.0);
          }
          qInfo(
              "%s, %d x %d, eps %.2f: load %.6g vs %.6g N (%.2e), peak %.2e, largest "
              "deformation %.3g um, %d partial nodes, %d differ",
              ToString(model), 48 * n, 8 * n, eps, b.load, a.load, load, peak,
              b.max_deformation * 1e6, partial, differ);
          QVERIFY(partial > 0);  // the film does rupture
          QVERIFY(differ <= 8 * n + 1);
          worst = std::max({worst, load, peak});
        }
        diffs.push_back(worst);
      }
      // Measured (layer / half-space): see docs/validation/ehd.md.
      QVERIFY2(diffs[0] < 1e-2 && diffs[1] < diffs[0] / 3.0 && diffs[2] < diffs[1] / 3.0,
               qPrintable(QString("%1 %2 %3").arg(diffs[0]).arg(diffs[1]).arg(diffs[2])));
    }
  }

  void starvedElasticSkirtTakesItsSupplyAtTheDeformedGap() {
    // A starved skirt's leading edge holds the liner's oil, 2 h_oil per unit area (a fraction
    // 2 h_oil / h_T of the gap there). On an elastic skirt the gap is the deformed one, which
    // the film solve iterates on: the fraction must follow it, else the supply is the oil
    // scaled by deformed / rigid gap (and a rigid gap past the liner gave a negative fraction,
    // that emptied cells downstream of it far below zero oil).
    // Half-spaces: they deform at the edge too, under the pressure next to it (an elastic layer
    // deforms with the local pressure only, zero on the edge).
    SkirtConfig cfg = ElasticSkirt(ComplianceModel::kHalfSpace, 5e9);
    cfg.solver.cavitation = CavitationModel::kJfo;
    cfg.supply = SkirtSupply::kStarved;
    cfg.oil_film = 4e-6;
    SkirtSolver solver(cfg);
    const SkirtState state = SlappingSkirt();
    const SkirtResult r = solver.Solve(state);
    QVERIFY2(r.elastic.converged, r.elastic.message.c_str());
    SkirtConfig rigid_cfg = cfg;
    rigid_cfg.compliance = {};
    SkirtSolver rigid(rigid_cfg);
    rigid.Solve(state);
    const Eigen::VectorXd& h_rigid = rigid.film_thickness();
    int edge_nodes = 0, partial = 0;
    double worst = 0.0, moved = 0.0;
    for (int p = 0; p < 2; ++p) {
      const ReynoldsFem& fem = solver.panel(p);
      const std::vector<int>& nodes = solver.panel_nodes(p);
      const TriMesh& m = fem.mesh();
      for (int k = 0; k < fem.NodeCount(); ++k) {
        if (!(m.fixed[k] && m.y[k] == m.y_lines.back())) continue;  // moving toward the crank
        ++edge_nodes;
        const double h_t = fem.mean_gap()[k];
        const double oil = fem.solution().fluid_fraction[k] * h_t;
        worst = std::max(worst, std::abs(oil - std::min(h_t, 2.0 * cfg.oil_film)) / h_t);
        if (oil < h_t) {  // partial: where the fraction depends on the gap
          ++partial;
          moved = std::max(moved, std::abs(fem.film_thickness()[k] - h_rigid[nodes[k]]));
        }
      }
    }
    qInfo(
        "leading edge: %d nodes, %d partial, deformed there by up to %.3g um; oil against "
        "2 h_oil: %.2g of the gap",
        edge_nodes, partial, moved * 1e6, worst);
    QVERIFY(edge_nodes > 0 && partial > 0);
    QVERIFY(moved > 0.01 * 2.0 * cfg.oil_film);  // the deformation matters there
    QVERIFY(worst < 1e-12);
    QVERIFY(r.stats.fraction_excess < 1e-12);
  }

  // The skirt: each panel's film is the rigid film plus the compliance (with the panel's mirror
  // image about its thrust plane, built here separately) times its load; infinitely stiff
  // surfaces give the rigid skirt's forces to 1e-10.
  void elasticSkirtPanelsHoldTheirFixedPointAndTheStiffLimit() {
    for (const ComplianceModel model :
         {ComplianceModel::kElasticLayer, ComplianceModel::kHalfSpace}) {
      const SkirtConfig cfg = ElasticSkirt(model, 5e9);
      SkirtSolver solver(cfg);
      const SkirtResult r = solver.Solve(SlappingSkirt());
      QVERIFY2(r.elastic.converged, r.elastic.message.c_str());
      QVERIFY(r.max_deformation > 0.05e-6);
      SkirtConfig rigid_cfg = cfg;
      rigid_cfg.compliance = {};
      SkirtSolver rigid(rigid_cfg);
      const SkirtResult rr = rigid.Solve(SlappingSkirt());
      const Eigen::VectorXd& h_rigid = rigid.film_thickness();
      for (int p = 0; p < 2; ++p) {
        const ReynoldsFem& fem = solver.panel(p);
        const std::vector<int>& nodes = solver.panel_nodes(p);
        const double mirror = p == 0 ? 0.0 : kPi * cfg.geometry.radius;
        Eigen::VectorXd cp;
        SurfaceCompliance::Build(cfg.compliance, fem.mesh(), std::nullopt, mirror)
            .Apply(fem.solution().pressure + fem.solution().contact_pressure, cp);
        double worst = 0.0;
        for (int k = 0; k < fem.NodeCount(); ++k)
          worst = std::max(worst, std::abs(fem.film_thickness()[k] - h_rigid[nodes[k]] - cp[k]));
        QVERIFY2(worst <= cfg.compliance.tolerance * fem.film_thickness().minCoeff(),
                 qPrintable(QString("%1 panel %2: %3 m").arg(ToString(model)).arg(p).arg(worst)));
      }
      // The whole-skirt film is the rigid one plus the deformation.
      QVERIFY((solver.film_thickness() - h_rigid - solver.deformation()).cwiseAbs().maxCoeff() <
              1e-18);
      qInfo("%s skirt, E 5 GPa: deformation %.3g um, lateral force %.5g N (rigid %.5g N)",
            ToString(model), r.max_deformation * 1e6, r.lateral_force, rr.lateral_force);
      SkirtSolver stiff(ElasticSkirt(model, 1e30));
      const SkirtResult rs = stiff.Solve(SlappingSkirt());
      for (const auto& [x, y] :
           std::vector<std::pair<double, double>>{{rs.lateral_force, rr.lateral_force},
                                                  {rs.moment_about_pin, rr.moment_about_pin},
                                                  {rs.friction_force, rr.friction_force},
                                                  {rs.moft, rr.moft}}) {
        QVERIFY2(std::abs(x - y) <= 1e-10 * std::abs(y),
                 qPrintable(QString("%1 vs %2").arg(x).arg(y)));
      }
    }
  }

  void elasticLayerBearingMatchesAnIndependentSolution() {
    // Sommerfeld number (the load at given eps) and attitude within 1 % over eps 0.2-0.9, at two
    // layer compliances (1 mm on E = 10 and 5 GPa: the load at eps 0.9 falls 28 and 40 % from
    // the rigid bearing's).
    const double omega = 3000.0 * 2.0 * kPi / 60.0;
    for (const double modulus : {10e9, 5e9}) {
      const double layer = LayerCompliance(1e-3, modulus, 0.3);
      BearingSolver solver(LayerBearing(modulus, 240, 24));
      BearingState s;
      s.omega_journal = omega;
      for (const double eps : {0.2, 0.5, 0.9}) {
        s.eps = eps;
        const BearingResult& r = solver.Solve(s);
        QVERIFY(r.elastic.converged);
        const FdBearing fd = SolveFd(0.025, 0.02, 25e-6, 0.01, omega, eps, layer, 160, 16);
        const double load_err = r.load / fd.load - 1.0;
        const double att_err = r.attitude_deg / fd.attitude_deg - 1.0;
        qInfo(
            "E %.0e eps %.1f: load %.6g vs %.6g (%+.3f %%), attitude %.4f vs %.4f (%+.3f %%), "
            "deformation %.3g vs %.3g m",
            modulus, eps, r.load, fd.load, 100 * load_err, r.attitude_deg, fd.attitude_deg,
            100 * att_err, r.max_deformation, fd.max_deformation);
        QVERIFY(std::abs(load_err) < 0.01);
        QVERIFY(std::abs(att_err) < 0.01);
      }
    }
  }

  // The oil's laws on elastic surfaces: the elastic-layer bearing with Barus' and Roelands'
  // pressure-viscosity laws and with Cross' shear thinning against the finite-difference solution
  // above, its conductivity h^3 mu0 / mu taken from the law's formula written here, node by node
  // (in p itself, not the reduced pressure FilmDyn solves for), at eps 0.5 and 0.8: load within 0.3
  // % and attitude within 0.1 % (measured: 0.06 % and 0.02 %), and each law moving the load by ten
  // times its difference to the independent solution at least (Barus, 5e-8 1/Pa: 2.7 and 27 %;
  // Roelands, z = 0.6: 0.8 and 6.4 %; Cross: 15 and 22 %).
  void elasticLayerBearingWithTheOilsLawsMatchesAnIndependentSolution() {
    const double omega = 3000.0 * 2.0 * kPi / 60.0, modulus = 10e9, alpha = 5e-8;
    const double layer = LayerCompliance(1e-3, modulus, 0.3);
    CrossLaw cross;
    cross.ratio = 0.5;
    cross.critical_rate = 1e6;
    cross.exponent = 1.0;
    const double u = omega * 0.025;  // the journal's surface speed, the bearing at rest
    const double z = 0.6, log_ratio = std::log(0.01 / 6.31e-5), p_r = 1.96e8;  // Roelands
    const char* names[] = {"Barus 5e-8 1/Pa", "Roelands z 0.6", "Cross r 0.5, 1e6 1/s"};
    for (int law = 0; law < 3; ++law) {
      BearingConfig cfg = LayerBearing(modulus, 240, 24);
      std::function<double(double, double)> fluidity;
      if (law == 0) {
        cfg.pressure_viscosity = PressureViscosity::Barus(alpha);
        fluidity = [&](double p, double) { return std::exp(-alpha * std::max(p, 0.0)); };
      } else if (law == 1) {
        cfg.pressure_viscosity = PressureViscosity::Roelands(z, 0.01);
        fluidity = [&](double p, double) {
          return std::exp(-log_ratio * (std::pow(1.0 + std::max(p, 0.0) / p_r, z) - 1.0));
        };
      } else {
        cfg.shear_thinning = cross;
        fluidity = [&](double, double h) {
          const double rate = u / h;
          return 1.0 / (0.5 + 0.5 / (1.0 + rate / 1e6));
        };
      }
      BearingSolver solver(cfg), newtonian(LayerBearing(modulus, 240, 24));
      BearingState s;
      s.omega_journal = omega;
      for (const double eps : {0.5, 0.8}) {
        s.eps = eps;
        const BearingResult& r = solver.Solve(s);
        QVERIFY2(r.elastic.converged, qPrintable(QString::fromStdString(r.elastic.message)));
        const double plain = newtonian.Solve(s).load;
        const FdBearing fd =
            SolveFd(0.025, 0.02, 25e-6, 0.01, omega, eps, layer, 160, 16, fluidity);
        const double load_err = r.load / fd.load - 1.0;
        const double att_err = r.attitude_deg / fd.attitude_deg - 1.0;
        qInfo(
            "%s, eps %.1f: load %.6g vs %.6g (%+.3f %%; Newtonian %.6g), attitude %.4f vs "
            "%.4f (%+.3f %%), deformation %.3g vs %.3g m",
            names[law], eps, r.load, fd.load, 100 * load_err, plain, r.attitude_deg,
            fd.attitude_deg, 100 * att_err, r.max_deformation, fd.max_deformation);
        QVERIFY(std::abs(load_err) < 3e-3);
        QVERIFY(std::abs(att_err) < 1e-3);
        QVERIFY(std::abs(r.load / plain - 1.0) > 10.0 * std::abs(load_err));
      }
    }
  }

  // The rows of `filmdyn validate --suite ehd` all pass; the elastic slider's reference is
  // converged (halving the shooting steps changes its load by less than 1e-9).
  void validationRowsPass() {
    const auto rows = EhdValidationRows();
    QCOMPARE(rows.size(), std::size_t(7));
    for (const auto& row : rows) QVERIFY2(row.Pass(), row.name.c_str());
    const InclinedSlider slider;
    const double layer = LayerCompliance(2e-3, 3e9, 0.3);
    const double fine = ElasticSliderByShooting(slider, layer, 40000).load;
    const double coarse = ElasticSliderByShooting(slider, layer, 20000).load;
    QVERIFY(std::abs(fine / coarse - 1.0) < 1e-9);
    // Mesh convergence of the FEM's load: second order (the error falls ~4x per halving).
    const double e1 = std::abs(SolveElasticSliderFem(slider, 2e-3, 3e9, 0.3, 100).load / fine - 1);
    const double e2 = std::abs(SolveElasticSliderFem(slider, 2e-3, 3e9, 0.3, 200).load / fine - 1);
    const double e4 = std::abs(SolveElasticSliderFem(slider, 2e-3, 3e9, 0.3, 400).load / fine - 1);
    qInfo("elastic slider load error: 100 cells %.3g, 200 %.3g, 400 %.3g", e1, e2, e4);
    QVERIFY(e2 < e1 / 3.0 && e4 < e2 / 3.0);
  }

  // An imported compliance written to files and read back is the same matrix (in any node
  // order); on the film's own grid it reproduces the built-in half-space, on a coarser FE grid
  // it agrees to the interpolation's accuracy; the bearing solved with it converges with
  // h = h_rigid + T C T' A (p + p_c).
  void importedComplianceAgreesWithTheBuiltInHalfSpace() {
    QTemporaryDir dir;
    const double radius = 0.025, width = 0.02;
    const double e_star = CompositeCompliance(210e9, 0.3, 110e9, 0.33);
    BearingConfig half = LayerBearing(1.0, 60, 8);
    half.mesh.symmetric_half = false;
    half.compliance.model = ComplianceModel::kHalfSpace;
    half.compliance.modulus1 = 210e9;
    half.compliance.poisson1 = 0.3;
    half.compliance.modulus2 = 110e9;
    half.compliance.poisson2 = 0.33;
    BearingState s;
    s.omega_journal = 314.0;
    s.eps = 0.8;
    const BearingResult built_in = BearingSolver(half).Solve(s);
    QVERIFY(built_in.elastic.converged);
    for (const int nx : {60, 30}) {
      const int ny = nx == 60 ? 9 : 5;
      const ImportedCompliance fe = HalfSpaceBearingSurface(radius, width, nx, ny, e_star);
      const std::string mtx = (dir.path() + "/surface.mtx").toStdString();
      const std::string csv = (dir.path() + "/surface.nodes.csv").toStdString();
      WriteImportedCompliance(fe, mtx, csv);
      const ImportedCompliance back = ReadImportedCompliance(mtx, csv);
      QVERIFY((back.matrix - fe.matrix).cwiseAbs().maxCoeff() <= 1e-15 * fe.matrix.maxCoeff());
      BearingConfig imported = half;
      imported.compliance.model = ComplianceModel::kImported;
      imported.compliance.imported = std::make_shared<const ImportedCompliance>(back);
      BearingSolver solver(imported);
      const BearingResult r = solver.Solve(s);
      QVERIFY2(r.elastic.converged, r.elastic.message.c_str());
      const double load = r.load / built_in.load - 1.0;
      const double deformation = r.max_deformation / built_in.max_deformation - 1.0;
      qInfo(
          "FE grid %d x %d: load %+.4f %%, max deformation %+.4f %% against the built-in "
          "half-space (%.4g N, %.3g um)",
          nx, ny, 100 * load, 100 * deformation, built_in.load, built_in.max_deformation * 1e6);
      const double tol = nx == 60 ? 0.01 : 0.05;
      QVERIFY(std::abs(load) < tol && std::abs(deformation) < tol);
    }
  }

  // The deformation's predictor (a linear model of the last solves over the film's inputs): a
  // slider whose films move smoothly, solved once with its inputs and once without, step for
  // step. Both hold every solve to the tolerance (so the answers agree to about that), and the
  // predicted start saves film solves.
  void predictedDeformationKeepsTheAnswerWithFewerFilmSolves() {
    for (const ComplianceModel model :
         {ComplianceModel::kElasticLayer, ComplianceModel::kHalfSpace}) {
      InclinedSlider slider;
      SliderStrip with = MakeSliderStrip(slider, 120), without = MakeSliderStrip(slider, 120);
      ComplianceSpec spec;
      spec.model = model;
      spec.layer_thickness = 2e-3;
      spec.layer_modulus = 3e9;
      spec.modulus1 = spec.modulus2 = 6e9;
      ElasticFilm a(SurfaceCompliance::Build(spec, with.fem->mesh(), std::nullopt), spec);
      ElasticFilm b(SurfaceCompliance::Build(spec, without.fem->mesh(), std::nullopt), spec);
      const TriMesh& m = with.fem->mesh();
      long solves_a = 0, solves_b = 0;
      double worst = 0.0;
      for (int step = 0; step < 60; ++step) {
        const double t = 0.05 * step;
        const double h_in = 10e-6 * (1.0 + 0.3 * std::sin(t)),
                     h_out = 5e-6 * (1.0 + 0.2 * std::sin(1.7 * t));
        const double speed = 10.0 * (1.0 + 0.2 * std::cos(t));
        for (SliderStrip* strip : {&with, &without}) {
          for (int k = 0; k < m.NodeCount(); ++k)
            strip->fem->film_thickness()[k] = h_in + (h_out - h_in) * m.x[k] / slider.length;
          strip->params.u_sum = strip->params.u_diff = speed;
        }
        const ElasticSolveStats& sa =
            a.Solve(*with.fem, with.params, Eigen::Vector3d(h_in, h_out, speed));
        QVERIFY2(sa.converged, sa.message.c_str());
        solves_a += sa.film_solves;
        const ElasticSolveStats& sb = b.Solve(*without.fem, without.params);
        QVERIFY2(sb.converged, sb.message.c_str());
        solves_b += sb.film_solves;
        const double allowed = std::max(sa.tolerance, sb.tolerance);
        worst =
            std::max(worst, (a.deformation() - b.deformation()).cwiseAbs().maxCoeff() / allowed);
      }
      qInfo(
          "%s: film solves %ld with the predictor, %ld without; deformations differ by at most "
          "%.2f tolerances",
          ToString(model), solves_a, solves_b, worst);
      QVERIFY(worst <= 4.0);
      QVERIFY(solves_a < 0.8 * solves_b);
    }
  }

  // A compliance that moves over the film (an imported grid round a whole bearing, the line of
  // centres turning against it) is predicted through the film's load (C at the new angle times
  // the predicted load): a journal orbiting through 40 states, each solved from the last ones,
  // gives what a fresh solver gives at that state.
  void movingComplianceIsPredictedThroughTheLoad() {
    const double radius = 0.025, width = 0.02;
    BearingConfig cfg = LayerBearing(1.0, 60, 8);
    cfg.mesh.symmetric_half = false;
    cfg.compliance.model = ComplianceModel::kImported;
    cfg.compliance.imported = std::make_shared<const ImportedCompliance>(HalfSpaceBearingSurface(
        radius, width, 30, 5, CompositeCompliance(210e9, 0.3, 110e9, 0.33)));
    BearingSolver warm(cfg);
    long solves = 0;
    double worst = 0.0;
    for (int step = 0; step < 40; ++step) {
      const double t = 0.02 * step;
      BearingState s;
      s.omega_journal = 314.0;
      s.eps = 0.7 + 0.15 * std::sin(3.0 * t);
      s.eps_dot = 0.45 * std::cos(3.0 * t);
      s.line_of_centres_angle = 2.0 * t;
      s.line_of_centres_rate = 2.0;
      s.bearing_angle = -0.5 * t;
      const BearingResult r = warm.Solve(s);
      QVERIFY2(r.elastic.converged, r.elastic.message.c_str());
      solves += r.elastic.film_solves;
      const BearingResult fresh = BearingSolver(cfg).Solve(s);
      QVERIFY2(fresh.elastic.converged, fresh.elastic.message.c_str());
      worst = std::max(worst, std::abs(r.load / fresh.load - 1.0));
    }
    qInfo("orbit of 40 states: %.2f film solves per solve, loads within %.2g of fresh solves",
          solves / 40.0, worst);
    QVERIFY(worst < 1e-3);
    // Measured 3.05 (a fit of the deformation itself, interpolated from the FE grid: 4.22).
    QVERIFY(solves / 40.0 < 3.6);
  }

  // The shipped CalculiX example (examples/calculix-bearing-shell): a uniform pressure deflects
  // the shell's middle as the elastic layer of the same lining (its limit under a wide load),
  // and the steady bearing with it agrees with the layer's.
  void shippedCalculixShellAgreesWithTheElasticLayer() {
    const std::string dir = std::string(FILMDYN_SOURCE_DIR) + "/examples/calculix-bearing-shell/";
    auto fe = std::make_shared<const ImportedCompliance>(
        ReadImportedCompliance(dir + "shell_compliance.mtx", dir + "shell_compliance.nodes.csv"));
    QCOMPARE(fe->NodeCount(), 528);
    const double layer = LayerCompliance(1.5e-3, 70e9, 0.33);
    // A film mesh on the FE grid, uniform pressure: the middle row's deflection.
    const TriMesh grid = MakeTensorMesh(fe->x_lines, fe->y_lines, true, 2.0 * kPi * 0.015);
    ComplianceTransfer transfer(fe, grid, std::nullopt, std::nullopt, grid.x_period, "shell");
    Eigen::VectorXd delta;
    transfer.Apply(Eigen::VectorXd::Ones(grid.NodeCount()), delta);
    const double middle = delta[grid.Node(0, grid.ny_nodes() / 2)];
    qInfo("uniform pressure: FE shell %.6g m/Pa, elastic layer %.6g m/Pa", middle, layer);
    QVERIFY(std::abs(middle / layer - 1.0) < 2e-3);
    // The product drops each row's smallest coefficients (those summing to at most
    // kDroppedShare of the row) and skips unloaded nodes: against the whole matrix, on a load
    // that is zero on a third of the nodes, within the bound that rule gives.
    Eigen::VectorXd load = Eigen::VectorXd::Zero(grid.NodeCount());
    for (int k = 0; k < grid.NodeCount(); ++k)
      if (k % 3 != 0) load[k] = 1e6 * (1.0 + std::sin(0.37 * k));
    const std::vector<double> area = LumpedAreas(grid);
    Eigen::VectorXd force(grid.NodeCount());
    for (int k = 0; k < grid.NodeCount(); ++k) force[k] = area[k] * load[k];
    // The grid's nodes are the FE nodes in the reader's order (x fastest).
    Eigen::VectorXd whole = fe->matrix * force;
    transfer.Apply(load, delta);
    const double bound = ComplianceTransfer::kDroppedShare *
                         fe->matrix.cwiseAbs().rowwise().sum().maxCoeff() * force.maxCoeff();
    const double diff = (delta - whole).cwiseAbs().maxCoeff();
    qInfo(
        "sparse product: %.3g of the coefficients kept, max difference %.3g m (bound %.3g m, "
        "deformation %.3g m)",
        transfer.KeptShare(), diff, bound, whole.maxCoeff());
    QVERIFY(diff <= bound);
    QVERIFY(transfer.KeptShare() < 0.5);
    BearingConfig cfg;
    cfg.geometry = {0.015, 0.022, 25e-6};
    cfg.viscosity = 0.01;
    cfg.mesh = {96, 20, false};
    BearingConfig column = cfg;
    cfg.compliance.model = ComplianceModel::kImported;
    cfg.compliance.imported = fe;
    column.compliance.model = ComplianceModel::kElasticLayer;
    column.compliance.layer_thickness = 1.5e-3;
    column.compliance.layer_modulus = 70e9;
    column.compliance.layer_poisson = 0.33;
    BearingSolver imported(cfg), built_in(column);
    BearingState s;
    s.omega_journal = 6000.0 * 2.0 * kPi / 60.0;
    for (const double eps : {0.5, 0.8, 0.95}) {
      s.eps = eps;
      const BearingResult a = imported.Solve(s);
      const BearingResult& b = built_in.Solve(s);
      QVERIFY2(a.elastic.converged, a.elastic.message.c_str());
      qInfo("eps %.2f: load %.5g vs %.5g N (%+.3f %%), max deformation %.4g vs %.4g um (%+.2f %%)",
            eps, a.load, b.load, 100 * (a.load / b.load - 1), a.max_deformation * 1e6,
            b.max_deformation * 1e6, 100 * (a.max_deformation / b.max_deformation - 1));
      QVERIFY(std::abs(a.load / b.load - 1.0) < 0.01);
      QVERIFY(std::abs(a.max_deformation / b.max_deformation - 1.0) < 0.05);
    }
  }

  // A skirt on an imported whole-skirt grid (periodic around the circumference, x = R alpha
  // from the thrust axis): with a diagonal matrix of the layer's compliance over each FE node's
  // area, on a grid through the film's own node lines, the imported skirt is the elastic-layer
  // skirt node for node — which needs the panels' mirror images (across alpha = 0 by the
  // period, across alpha = pi inside the grid) to land where they should.
  void importedWholeSkirtGridMatchesTheLayerOnTheSameLines() {
    SkirtConfig layer = ElasticSkirt(ComplianceModel::kElasticLayer, 5e9);
    layer.geometry.alpha1 = layer.geometry.alpha2 = kPi / 4.0;
    layer.mesh = {15, 30, 15, 16};  // every x line on the pi R / 60 grid, y every 2 mm
    const double c_layer =
        LayerCompliance(layer.compliance.layer_thickness, layer.compliance.layer_modulus, 0.3);
    auto fe = std::make_shared<ImportedCompliance>();
    fe->source = "whole-skirt.mtx";
    const double radius = layer.geometry.radius, dx = kPi * radius / 60.0, dy = 0.002;
    for (int i = 0; i < 120; ++i) fe->x_lines.push_back(i * dx);
    for (int j = 0; j <= 16; ++j) fe->y_lines.push_back(j * dy);
    const int m = fe->NodeCount();
    fe->matrix = Eigen::MatrixXd::Zero(m, m);
    for (int j = 0; j <= 16; ++j)
      for (int i = 0; i < 120; ++i)
        fe->matrix(i + 120 * j, i + 120 * j) = c_layer / (dx * dy * (j == 0 || j == 16 ? 0.5 : 1));
    SkirtConfig imported = layer;
    imported.compliance.model = ComplianceModel::kImported;
    imported.compliance.imported = fe;
    SkirtSolver a(imported), b(layer);
    const SkirtResult ra = a.Solve(SlappingSkirt());
    const SkirtResult& rb = b.Solve(SlappingSkirt());
    QVERIFY2(ra.elastic.converged, ra.elastic.message.c_str());
    qInfo(
        "imported whole-skirt grid vs elastic layer: lateral force %.8g / %.8g N, max "
        "deformation %.6g / %.6g um",
        ra.lateral_force, rb.lateral_force, ra.max_deformation * 1e6, rb.max_deformation * 1e6);
    QVERIFY(rb.max_deformation > 0.05e-6);
    // Both solves hold the film to 1e-4 of its thinnest: the answers agree far closer.
    QVERIFY(std::abs(ra.lateral_force / rb.lateral_force - 1.0) < 1e-5);
    QVERIFY(std::abs(ra.moment_about_pin / rb.moment_about_pin - 1.0) < 1e-5);
    QVERIFY(std::abs(ra.max_deformation / rb.max_deformation - 1.0) < 1e-4);
    // A grid over part of the skirt only (no period) that misses the thrust panel's mirror
    // image is refused, naming the file.
    auto part = std::make_shared<ImportedCompliance>(*fe);
    part->x_lines.resize(60);
    Eigen::MatrixXd pm = Eigen::MatrixXd::Zero(60 * 17, 60 * 17);
    for (int j = 0; j <= 16; ++j)
      for (int i = 0; i < 60; ++i)
        pm(i + 60 * j, i + 60 * j) = fe->matrix(i + 120 * j, i + 120 * j);
    part->matrix = pm;
    imported.compliance.imported = part;
    QVERIFY_THROWS_EXCEPTION(InputError, SkirtSolver{imported});
    try {
      SkirtSolver refused(imported);
    } catch (const InputError& e) {
      QVERIFY2(QString(e.what()).contains("whole-skirt.mtx"), e.what());
    }
  }

  void badComplianceFilesNameTheFileAndLine() {
    QTemporaryDir dir;
    const std::string mtx = (dir.path() + "/c.mtx").toStdString();
    const std::string csv = (dir.path() + "/c.nodes.csv").toStdString();
    auto write = [](const std::string& path, const std::string& text) {
      std::ofstream(path) << text;
    };
    auto message = [&]() -> QString {
      try {
        ReadImportedCompliance(mtx, csv);
      } catch (const InputError& e) {
        return QString::fromStdString(e.what());
      }
      return {};
    };
    const std::string nodes = "x[m],y[m]\n0,0\n1,0\n0,1\n1,1\n";
    const std::string good =
        "%%MatrixMarket matrix array real symmetric\n4 4\n2\n0.5\n0.2\n0.1\n2\n0.1\n0.2\n"
        "2\n0.5\n2\n";
    write(csv, nodes);
    write(mtx, good);
    QVERIFY2(message().isEmpty(), qPrintable(message()));
    write(mtx, "%%MatrixMarket matrix array complex symmetric\n4 4\n");
    QVERIFY(message().contains("c.mtx:1") && message().contains("real"));
    write(mtx, "%%MatrixMarket matrix array real symmetric\n% size\n3 3\n");
    QVERIFY2(message().contains("c.mtx:3") && message().contains("4 x 4"), qPrintable(message()));
    write(mtx, "%%MatrixMarket matrix array real symmetric\n4 4\n2\n0.5\nabc\n");
    QVERIFY2(message().contains("c.mtx:5") && message().contains("abc"), qPrintable(message()));
    write(mtx, "%%MatrixMarket matrix coordinate real general\n4 4 2\n1 1 1\n2 1 0.5\n");
    QVERIFY2(message().contains("every entry"), qPrintable(message()));
    write(mtx,
          "%%MatrixMarket matrix array real general\n4 4\n1\n0\n0\n0\n0.5\n1\n0\n0\n0\n0\n1\n"
          "0\n0\n0\n0\n1\n");
    QVERIFY2(message().contains("symmetric"), qPrintable(message()));
    write(mtx, "%%MatrixMarket matrix array real symmetric\n4 4\n1\n2\n0\n0\n1\n0\n0\n1\n0\n1\n");
    QVERIFY2(message().contains("positive definite"), qPrintable(message()));
    write(mtx, good);
    write(csv, "x[m],y[m]\n0,0\n1,0\n0,1\n2,1\n");
    QVERIFY2(message().contains("grid"), qPrintable(message()));
    write(csv, "x,y\n0,0\n1,0\n0,1\n1,1\n");
    QVERIFY2(message().contains("c.nodes.csv:1") && message().contains("x[m],y[m]"),
             qPrintable(message()));
    write(csv, "x[m],y[m]\n0,0\n1,0\n0,nan\n1,1\n");
    QVERIFY2(message().contains("c.nodes.csv:4"), qPrintable(message()));
    // A byte-order mark before the header (some editors write one) is no part of it.
    write(csv, "\xEF\xBB\xBF" + nodes);
    QVERIFY2(message().isEmpty(), qPrintable(message()));
    write(csv, nodes);
    // An entry given twice (which one holds?) and values after the last entry are refused, where
    // the last value used to win silently and the rest be ignored; a value below the smallest
    // normal double is a finite number.
    write(mtx,
          "%%MatrixMarket matrix coordinate real symmetric\n4 4 11\n1 1 2\n2 1 0.5\n3 1 0.2\n"
          "4 1 0.1\n2 2 2\n3 2 0.1\n4 2 0.2\n3 3 2\n4 3 0.5\n4 4 2\n1 1 3\n");
    QVERIFY2(message().contains("c.mtx:13") && message().contains("(1, 1) is given again"),
             qPrintable(message()));
    write(mtx, good + "7\n");
    QVERIFY2(message().contains("c.mtx:13") && message().contains("nothing after the last entry"),
             qPrintable(message()));
    write(mtx, good + "% a comment\n\n");
    QVERIFY2(message().isEmpty(), qPrintable(message()));
    std::string tiny = good;
    tiny.replace(tiny.find("\n0.1\n"), 5, "\n1e-309\n");
    write(mtx, tiny);
    QVERIFY2(message().isEmpty(), qPrintable(message()));
    write(mtx, good);
    // Regular files only: a FIFO would wait for a writer forever (it hung a run that no signal
    // could stop); a folder, a device likewise.
    write(csv, nodes);
    for (const auto& [pipe, name, text] :
         {std::tuple{mtx, "c.mtx", good}, std::tuple{csv, "c.nodes.csv", nodes}}) {
      QFile::remove(QString::fromStdString(pipe));
      QCOMPARE(::mkfifo(pipe.c_str(), 0600), 0);
      QVERIFY2(message().contains(name) && message().contains("is not a regular file"),
               qPrintable(message()));
      QFile::remove(QString::fromStdString(pipe));
      write(pipe, text);
    }
    QFile::remove(QString::fromStdString(csv));
    {  // more nodes than a dense matrix should hold
      std::string many = "x[m],y[m]\n";
      for (int i = 0; i < 101; ++i)
        for (int j = 0; j < 100; ++j) many += std::to_string(i) + "," + std::to_string(j) + "\n";
      write(csv, many);
      QVERIFY2(message().contains("10100 nodes") && message().contains("at most 10000"),
               qPrintable(message()));
    }
    // A film outside the FE surface: a bearing wider than the imported surface (5 mm of 20).
    write(csv, "x[m],y[m]\n0,0\n0.1,0\n0,0.005\n0.1,0.005\n");
    BearingConfig cfg = LayerBearing(1.0, 16, 4);
    cfg.compliance.model = ComplianceModel::kImported;
    cfg.compliance.imported =
        std::make_shared<const ImportedCompliance>(ReadImportedCompliance(mtx, csv));
    try {
      BearingSolver solver(cfg);
      QFAIL("a film outside the FE surface was accepted");
    } catch (const InputError& e) {
      QVERIFY2(QString(e.what()).contains("c.mtx") && QString(e.what()).contains("range"),
               e.what());
    }
  }

  void badComplianceInputNamesTheField() {
    ComplianceSpec spec;
    spec.model = ComplianceModel::kElasticLayer;
    spec.layer_thickness = 1e-3;
    spec.layer_modulus = 70e9;
    const ComplianceFields names{"j.layer_thickness",
                                 "j.modulus",
                                 "j.poisson",
                                 "j.E1",
                                 "j.nu1",
                                 "j.E2",
                                 "j.nu2",
                                 "j.tol",
                                 "j.iter",
                                 "j.file"};
    auto message = [&](const ComplianceSpec& bad) -> QString {
      try {
        ValidateCompliance(bad, names);
      } catch (const InputError& e) {
        return QString::fromStdString(e.what());
      }
      return {};
    };
    ComplianceSpec bad = spec;
    bad.layer_thickness = 0.0;
    QVERIFY(message(bad).contains("j.layer_thickness"));
    bad = spec;
    bad.layer_modulus = -1.0;
    QVERIFY(message(bad).contains("j.modulus"));
    bad = spec;
    bad.layer_poisson = 0.5;
    QVERIFY(message(bad).contains("j.poisson"));
    bad = spec;
    bad.layer_poisson = -1.0;
    QVERIFY(message(bad).contains("j.poisson"));
    bad = spec;
    bad.model = ComplianceModel::kHalfSpace;
    bad.modulus1 = std::nan("");
    QVERIFY(message(bad).contains("j.E1"));
    QVERIFY(message(spec).isEmpty());
  }
};

QTEST_APPLESS_MAIN(TestElasticFilm)
#include "test_elastic_film.moc"
