#include "core/lubrication/validation_cases.hpp"

#include <fmt/format.h>
#include <cmath>
#include <numbers>
#include <string>

#include <boost/math/quadrature/gauss.hpp>

#include "core/base/angles.hpp"
#include "core/lubrication/bearing_calculator.hpp"

namespace filmdyn::lubrication {

namespace {
constexpr double kPi = std::numbers::pi;

std::string Fmt(double v) { return fmt::format("{:g}", v); }
}  // namespace

const std::vector<RaimondiBoydPoint>& RaimondiBoydTable() {
  // Raimondi & Boyd (1958), "A solution for the finite journal bearing and its application to
  // analysis and design", ASLE Trans. 1, 159-209, Table for the full (360 deg) bearing, as
  // reproduced in Shigley's Mechanical Engineering Design (Budynas & Nisbett), Table 12-4.
  // The L/D = 1 S and (R/c) f columns match an independent transcription (MathWorks Answers
  // 707318). Columns: L/D, eps, S, phi [deg], (R/c) f, Q/(R c N L), Q_s/Q.
  static const std::vector<RaimondiBoydPoint> table = {
      {1.0, 0.1, 1.33, 79.5, 26.4, 3.37, 0.150},    {1.0, 0.2, 0.631, 74.02, 12.8, 3.59, 0.280},
      {1.0, 0.4, 0.264, 63.10, 5.79, 3.99, 0.497},  {1.0, 0.6, 0.121, 50.58, 3.22, 4.33, 0.680},
      {1.0, 0.8, 0.0446, 36.24, 1.70, 4.62, 0.842}, {1.0, 0.9, 0.0188, 26.45, 1.05, 4.74, 0.919},
      {0.5, 0.1, 4.31, 81.62, 85.6, 3.43, 0.173},   {0.5, 0.2, 2.03, 74.94, 40.9, 3.72, 0.318},
      {0.5, 0.4, 0.779, 61.45, 17.0, 4.29, 0.552},  {0.5, 0.6, 0.319, 48.14, 8.10, 4.85, 0.730},
      {0.5, 0.8, 0.0923, 33.31, 3.26, 5.41, 0.874}, {0.5, 0.9, 0.0313, 23.66, 1.60, 5.69, 0.939},
      {0.25, 0.1, 16.2, 82.31, 322.0, 3.45, 0.180}, {0.25, 0.2, 7.57, 75.18, 153.0, 3.76, 0.330},
      {0.25, 0.4, 2.83, 60.86, 61.1, 4.37, 0.567},  {0.25, 0.6, 1.07, 46.95, 26.7, 4.99, 0.746},
      {0.25, 0.8, 0.261, 31.04, 8.80, 5.60, 0.884}, {0.25, 0.9, 0.0736, 21.88, 3.50, 5.91, 0.945},
  };
  return table;
}

SteadyBearingPoint SolveSteadyBearing(double l_over_d, double eps, const BearingMeshSpec& mesh,
                                      CavitationModel cavitation) {
  BearingCalcInput in;
  in.radius = 0.025;
  in.length = 2.0 * in.radius * l_over_d;
  in.radial_clearance = 25e-6;
  in.viscosity = 0.01;
  in.speed_rpm = 3000.0;
  in.mesh = mesh;
  in.cavitation = cavitation;
  in.eps = eps;
  const BearingCalcResult r = RunBearingCalculator(in);
  return {r.sommerfeld,         r.attitude_deg,        r.friction_variable,
          r.side_flow_variable, r.inlet_flow_variable, r.last_stats};
}

// Short-bearing (Ocvirk & DuBois 1953) half-Sommerfeld load components, e.g. Hamrock, Schmid &
// Jacobson (2004) eqs. 10.38-10.41: W_r = mu U L^3 eps^2 / (c^2 (1-eps^2)^2),
// W_t = pi mu U L^3 eps / (4 c^2 (1-eps^2)^1.5), U = R omega, tan(phi) = pi sqrt(1-eps^2)/(4 eps).
// With P = W/(2RL), N = omega/(2 pi): S = (R/c)^2 mu N / P = (D/L)^2 (1-eps^2)^2 /
// (pi eps sqrt(pi^2 (1-eps^2) + 16 eps^2)).
double OcvirkSommerfeld(double l_over_d, double eps) {
  const double e2 = 1.0 - eps * eps;
  return e2 * e2 / (l_over_d * l_over_d * kPi * eps * std::sqrt(kPi * kPi * e2 + 16 * eps * eps));
}

double OcvirkAttitudeDeg(double eps) {
  return std::atan2(kPi * std::sqrt(1.0 - eps * eps), 4.0 * eps) * kDegreesPerRadian;
}

// Short-bearing squeeze (Booker 1965, Hamrock et al. ch. 20): d/dz(h^3/(12 mu) dp/dz) =
// c eps_dot cos(theta) gives p = 6 mu c eps_dot cos(theta) (z^2 - L^2/4) / h^3, and the load
// along the line of centres is mu eps_dot L^3 R / c^2 times int cos^2/(1 + eps cos)^3 over the
// region where p > 0 (theta in (pi/2, 3pi/2) for eps_dot > 0) or over 2 pi for the full film.
double SqueezeIntegralFull(double eps) {
  return kPi * (1.0 + 2.0 * eps * eps) / std::pow(1.0 - eps * eps, 2.5);
}

double SqueezeIntegralHalf(double eps) {
  // Composite 8-point Gauss-Legendre (Boost.Math) on 256 panels: the integrand is smooth.
  const int panels = 256;
  const double a = 0.5 * kPi, b = 1.5 * kPi, hp = (b - a) / panels;
  auto integrand = [eps](double t) {
    const double c = std::cos(t);
    return c * c / std::pow(1.0 + eps * c, 3);
  };
  double sum = 0.0;
  for (int i = 0; i < panels; ++i) {
    sum += boost::math::quadrature::gauss<double, 8>::integrate(integrand, a + i * hp,
                                                                a + (i + 1) * hp);
  }
  return sum;
}

// Pocketed slider, JFO closed form (our derivation for the configuration of Fowell et al. 2007):
// piecewise-constant film, flow per unit width q = U h/2 - h^3/(12 mu) dp/dx constant where the
// film is full, p linear on each full-film segment. With cavitation (p = 0) from the pocket
// entry x_a to x_c and reformation in the pocket at x_c:
//   inlet  [0, x_a]:   q = U h0/2 + h0^3 p_in / (12 mu x_a)
//   outlet [x_b, L]:   p_b = p_out + 12 mu (q - U h0/2)(L - x_b)/h0^3
//   pocket [x_c, x_b]: x_b - x_c = h1^3 p_b / (12 mu (U h1/2 - q))
// and in the cavitated zone theta = 2 q / (U h1). Valid when x_a < x_c < x_b (checked).
PocketSliderSolution PocketSliderAnalytic(const PocketSliderCase& c) {
  const double mu12 = 12.0 * c.viscosity;
  PocketSliderSolution s;
  s.q = 0.5 * c.speed * c.h0 + std::pow(c.h0, 3) * c.p_ends / (mu12 * c.pocket_start);
  s.p_exit = c.p_ends +
             mu12 * (s.q - 0.5 * c.speed * c.h0) * (c.length - c.pocket_end) / std::pow(c.h0, 3);
  s.x_reform = c.pocket_end - std::pow(c.h1, 3) * s.p_exit / (mu12 * (0.5 * c.speed * c.h1 - s.q));
  s.fluid_fraction = 2.0 * s.q / (c.speed * c.h1);
  return s;
}

PocketSliderFem PocketSliderNumeric(const PocketSliderCase& c, int n, CavitationModel model) {
  const double width = 1e-4;
  ReynoldsOptions opt;
  opt.cavitation = model;
  ReynoldsFem fem(MakeStripMesh(c.length, n, width), 0, opt);
  const TriMesh& m = fem.mesh();
  const int nx = m.nx_nodes();
  for (int k = 0; k < m.NodeCount(); ++k) {
    const bool pocket = m.x[k] > c.pocket_start && m.x[k] < c.pocket_end;
    fem.film_thickness()[k] = pocket ? c.h1 : c.h0;
    fem.film_rate()[k] = 0.0;
    fem.boundary_pressure()[k] = m.fixed[k] ? c.p_ends : 0.0;
  }
  ReynoldsParams params;
  params.viscosity = c.viscosity;
  params.u_sum = c.speed;  // one surface moving at U, the other at rest
  params.u_diff = c.speed;
  const ReynoldsSolution& sol = fem.Solve(params);
  PocketSliderFem out;
  out.stats = sol.stats;
  double q_in = 0.0, q_out = 0.0;
  for (int j = 0; j < 2; ++j) {
    q_in += sol.residual[m.Node(0, j)];
    q_out -= sol.residual[m.Node(nx - 1, j)];
  }
  // Boundary flows from the nodal residuals (reaction fluxes). The Galerkin Reynolds form puts
  // the Couette term in non-divergence form, so its boundary flux U h/2 is added explicitly;
  // the JFO finite-volume transport already contains it.
  const double couette = model == CavitationModel::kJfo ? 0.0 : 0.5 * c.speed * c.h0;
  out.sol.q = q_in / width + couette;
  out.outflow_q = q_out / width + couette;
  // Pressure at the pocket exit, start of the reformed film, minimum fluid fraction.
  double best = 1e300, theta_min = 1.0, x_reform = c.pocket_start;
  for (int i = 0; i < nx; ++i) {
    const int k = m.Node(i, 0);
    if (std::abs(m.x[k] - c.pocket_end) < best) {
      best = std::abs(m.x[k] - c.pocket_end);
      out.sol.p_exit = sol.pressure[k];
    }
    theta_min = std::min(theta_min, sol.fluid_fraction[k]);
    if (sol.cavitated[k] && m.x[k] < c.pocket_end && i + 1 < nx) x_reform = m.x[m.Node(i + 1, 0)];
  }
  out.sol.x_reform = x_reform;
  out.sol.fluid_fraction = theta_min;
  return out;
}

double HoleInStripFlow(double gap, double viscosity, double width, double hole_radius,
                       double pressure) {
  const double pi = std::numbers::pi;
  return 2.0 * pi * gap * gap * gap / (12.0 * viscosity) * pressure /
         std::log(2.0 * width / (pi * hole_radius));
}

double GrooveInStripFlow(double gap, double viscosity, double width, double groove_width,
                         double circumference, double pressure) {
  return 2.0 * circumference * gap * gap * gap / (12.0 * viscosity) * pressure /
         (0.5 * (width - groove_width));
}

std::vector<verification::ValidationRow> LubricationValidationRows() {
  using verification::ValidationRow;
  std::vector<ValidationRow> rows;
  // Converged mesh for the table (see docs/validation/lubrication.md): symmetric half, 240 x 20
  // (= 240 x 40 over the full width).
  const BearingMeshSpec fine{240, 20, true};
  const std::string rb = "Raimondi & Boyd 1958 (Shigley Table 12-4)";
  for (const auto& p : RaimondiBoydTable()) {
    const SteadyBearingPoint r = SolveSteadyBearing(p.l_over_d, p.eps, fine);
    const std::string tag = "L/D=" + Fmt(p.l_over_d) + " eps=" + Fmt(p.eps);
    rows.push_back(
        {"bearing", "Sommerfeld number " + tag, rb, r.sommerfeld, p.sommerfeld, 0.02, true});
    rows.push_back(
        {"bearing", "attitude angle [deg] " + tag, rb, r.attitude_deg, p.attitude_deg, 1.5, false});
    rows.push_back(
        {"bearing", "inlet flow Q/(RcNL) " + tag, rb, r.inlet_flow_var, p.flow_var, 0.02, true});
  }
  // Short-bearing limit: L/D = 1/16 against Ocvirk (the difference is O((L/D)^2)).
  const BearingMeshSpec short_mesh{240, 12, true};
  for (double eps : {0.3, 0.6}) {
    const SteadyBearingPoint r = SolveSteadyBearing(1.0 / 16.0, eps, short_mesh);
    const std::string tag = "L/D=1/16 eps=" + Fmt(eps);
    rows.push_back({"bearing", "Sommerfeld number " + tag, "Ocvirk & DuBois 1953 short bearing",
                    r.sommerfeld, OcvirkSommerfeld(1.0 / 16.0, eps), 0.03, true});
    rows.push_back({"bearing", "attitude angle [deg] " + tag, "Ocvirk & DuBois 1953 short bearing",
                    r.attitude_deg, OcvirkAttitudeDeg(eps), 1.5, false});
  }
  // Pure squeeze, short bearing (L/D = 1/16), eps = 0.5, eps_dot = 1/s.
  {
    for (CavitationModel model : {CavitationModel::kNone, CavitationModel::kReynolds}) {
      BearingConfig cfg;
      cfg.geometry = {0.025, 0.05 / 16.0, 25e-6};
      cfg.viscosity = 0.01;
      cfg.mesh = {240, 12, true};
      cfg.solver.cavitation = model;
      BearingSolver solver(cfg);
      BearingState st;
      st.eps = 0.5;
      st.eps_dot = 1.0;
      const BearingResult& r = solver.Solve(st);
      const double scale = cfg.viscosity * st.eps_dot * std::pow(cfg.geometry.length, 3) *
                           cfg.geometry.radius / std::pow(cfg.geometry.radial_clearance, 2);
      const bool full = model == CavitationModel::kNone;
      rows.push_back({"bearing",
                      std::string("pure squeeze load, ") + (full ? "full film" : "Reynolds") +
                          " L/D=1/16 eps=0.5",
                      full ? "short-bearing squeeze closed form"
                           : "short-bearing squeeze, positive half (quadrature)",
                      -r.force_n / scale,
                      full ? SqueezeIntegralFull(0.5) : SqueezeIntegralHalf(0.5), 0.03, true});
    }
  }
  // JFO on the pocketed slider.
  {
    const PocketSliderCase c;
    const PocketSliderSolution ref = PocketSliderAnalytic(c);
    const PocketSliderFem jfo = PocketSliderNumeric(c, 4000, CavitationModel::kJfo);
    const std::string src = "pocketed slider (Fowell et al. 2007), JFO closed form";
    rows.push_back(
        {"jfo", "pocket slider flow per width [m^2/s]", src, jfo.sol.q, ref.q, 0.01, true});
    rows.push_back({"jfo", "pocket slider pressure at pocket exit [Pa]", src, jfo.sol.p_exit,
                    ref.p_exit, 0.02, true});
    rows.push_back({"jfo", "pocket slider reformation point [mm]", src, jfo.sol.x_reform * 1e3,
                    ref.x_reform * 1e3, 0.02, false});
    rows.push_back({"jfo", "pocket slider cavity fluid fraction", src, jfo.sol.fluid_fraction,
                    ref.fluid_fraction, 0.02, true});
    rows.push_back({"jfo", "pocket slider mass balance (out - in)/in", "mass conservation",
                    (jfo.outflow_q - jfo.sol.q) / jfo.sol.q, 0.0, 1e-8, false});
  }
  // A flooded bearing whose film starts at the maximum gap and ruptures once: the JFO film's full
  // region is the Reynolds film's, and its centred Couette flux the Galerkin wedge term, so the
  // two carry the same load on the same (coarse) mesh.
  {
    const BearingMeshSpec mesh{60, 10, false};
    const SteadyBearingPoint r = SolveSteadyBearing(0.5, 0.8, mesh);
    const SteadyBearingPoint j = SolveSteadyBearing(0.5, 0.8, mesh, CavitationModel::kJfo);
    rows.push_back({"jfo", "flooded bearing S, 60x10 mesh, eps=0.8",
                    "the Reynolds film's on the same mesh", j.sommerfeld, r.sommerfeld, 1e-8,
                    true});
  }
  // Supplies whose edges fall between the mesh lines: a 4 mm hole (off the nodes) and a 3.3 mm
  // groove (rows 2.5 mm apart) in a still film, 25 mm wide, 25 mm radius, 25 um gap, 0.3 MPa.
  {
    const double R = 0.025, L = 0.025, c = 25e-6, mu = 0.01, p_s = 3e5;
    BearingConfig cfg;
    cfg.geometry = {R, L, c};
    cfg.viscosity = mu;
    cfg.mesh = {126, 20, false};  // square elements of 1.25 mm
    cfg.feed.pressure = p_s;
    cfg.feed.kind = OilFeedKind::kShellHoles;
    cfg.feed.hole_angles = {0.031};
    cfg.feed.hole_diameter = 4e-3;
    BearingSolver hole(cfg);
    rows.push_back({"bearing", "supply hole flow, 4 mm hole, still film, 126x20 mesh",
                    "strip with a round source, conformal map (closed form)",
                    hole.Solve(BearingState{}).feed_flow, HoleInStripFlow(c, mu, L, 2e-3, p_s),
                    0.02, true});
    cfg.mesh = {63, 10, false};  // rows 2.5 mm apart
    cfg.feed.kind = OilFeedKind::kGroove;
    cfg.feed.groove_width = 3.3e-3;
    BearingSolver groove(cfg);
    rows.push_back(
        {"bearing", "supply groove flow, 3.3 mm groove between rows, still film",
         "linear pressure fall to the edges (closed form)", groove.Solve(BearingState{}).feed_flow,
         GrooveInStripFlow(c, mu, L, 3.3e-3, 2.0 * std::numbers::pi * R, p_s), 1e-8, true});
  }
  // LCP exactness: complementarity residual of a cavitated bearing solve.
  {
    const SteadyBearingPoint r = SolveSteadyBearing(1.0, 0.6, BearingMeshSpec{50, 10, false});
    rows.push_back({"bearing", "LCP complementarity residual, 50x10 mesh, eps=0.6",
                    "exact complementarity (0)", r.stats.complementarity_residual, 0.0, 1e-10,
                    false});
  }
  return rows;
}

}  // namespace filmdyn::lubrication
