#include "core/lubrication/skirt_validation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/base/angles.hpp"

namespace filmdyn::lubrication {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kLift = 1e-3;  // ovality that lifts the anti-thrust panel off (slider case)

// The skirt of the limits: the paper's panel width, a skirt-size piston.
SkirtConfig LimitSkirt(double skirt_length, Table1D profile) {
  SkirtConfig cfg;
  SkirtGeometry& g = cfg.geometry;
  g.radius = 0.0415;
  g.skirt_length = skirt_length;
  g.radial_clearance = 20e-6;
  g.pin_position = 0.5 * skirt_length;
  g.alpha1 = g.alpha2 = 46.0 * kRadiansPerDegree;
  g.profile = std::move(profile);
  cfg.viscosity = 0.008;
  return cfg;
}

// |a - b| / max(|a|, |b|): 0 when both are 0.
double Mismatch(double a, double b) {
  const double scale = std::max(std::abs(a), std::abs(b));
  return scale > 0.0 ? std::abs(a - b) / scale : 0.0;
}

// Largest relative mismatch between the results of a state and of its image under a symmetry of
// the skirt: the lateral force and the moment change sign when `flip_force` / `flip_moment`, the
// friction force when `flip_friction`; the MOFT never does.
double SymmetryMismatch(const SkirtResult& a, const SkirtResult& b, bool flip_force,
                        bool flip_moment, bool flip_friction) {
  const double sf = flip_force ? -1.0 : 1.0, sm = flip_moment ? -1.0 : 1.0;
  const double sv = flip_friction ? -1.0 : 1.0;
  return std::max({Mismatch(a.lateral_force, sf * b.lateral_force),
                   Mismatch(a.moment_about_pin, sm * b.moment_about_pin),
                   Mismatch(a.friction_force, sv * b.friction_force), Mismatch(a.moft, b.moft)});
}
}  // namespace

double InclinedSliderLoad(double viscosity, double speed, double length, double h_outlet,
                          double h_inlet) {
  if (!(h_outlet > 0.0 && h_inlet > h_outlet)) {
    throw std::logic_error("InclinedSliderLoad: needs h_inlet > h_outlet > 0");
  }
  const double k = h_inlet / h_outlet;
  return 6.0 * viscosity * std::abs(speed) * length * length /
         (h_outlet * h_outlet * (k - 1.0) * (k - 1.0)) *
         (std::log(k) - 2.0 * (k - 1.0) / (k + 1.0));
}

double LongSkirtSqueezeForcePerLength(double viscosity, double radius, double clearance,
                                      double alpha1, double e0_dot) {
  // F' = -2 int_0^alpha1 p cos(a) R da with p = (12 mu R^2 e0_dot / c^3)(cos a - cos alpha1):
  // int_0^alpha1 (cos^2 a - cos alpha1 cos a) da = (alpha1 - sin alpha1 cos alpha1) / 2.
  return -12.0 * viscosity * std::pow(radius, 3) * e0_dot / std::pow(clearance, 3) *
         (alpha1 - std::sin(alpha1) * std::cos(alpha1));
}

SkirtLimitCase SliderLimitCase(double skirt_length, int n_axial) {
  const double h0 = 20e-6, h1 = 40e-6;
  SkirtLimitCase c;
  c.config = LimitSkirt(skirt_length, {{0.0, skirt_length}, {0.0, h1 - h0}});
  SkirtGeometry& g = c.config.geometry;
  g.radial_clearance = h0;
  g.ovality = {{g.alpha1, kPi - g.alpha2}, {0.0, kLift}};
  c.config.mesh.n_thrust = static_cast<int>(std::ceil(8.0 * g.radius * g.alpha1 / skirt_length));
  c.config.mesh.n_anti = 4;
  c.config.mesh.n_axial = n_axial;
  c.state.piston_velocity = 10.0;
  const double mu = c.config.viscosity, u = c.state.piston_velocity;
  c.reference =
      -2.0 * g.radius * std::sin(g.alpha1) * InclinedSliderLoad(mu, u, skirt_length, h0, h1) +
      2.0 * g.radius * std::sin(g.alpha2) *
          InclinedSliderLoad(mu, u, skirt_length, h0 + kLift, h1 + kLift);
  return c;
}

SkirtLimitCase SqueezeLimitCase(double skirt_length, int n_thrust) {
  SkirtLimitCase c;
  c.config = LimitSkirt(skirt_length, {{0.0}, {0.0}});
  const SkirtGeometry& g = c.config.geometry;
  c.config.mesh.n_thrust = n_thrust;
  c.config.mesh.n_anti = 4;  // separated: p = 0 there
  c.config.mesh.n_axial =
      std::max(2, static_cast<int>(std::lround(n_thrust * skirt_length / (g.radius * g.alpha1))));
  c.state.e0_dot = 5e-3;
  c.reference =
      skirt_length * LongSkirtSqueezeForcePerLength(c.config.viscosity, g.radius,
                                                    g.radial_clearance, g.alpha1, c.state.e0_dot);
  return c;
}

std::vector<verification::ValidationRow> SkirtValidationRows() {
  using verification::ValidationRow;
  std::vector<ValidationRow> rows;
  // Inclined slider on a panel 67 times as wide as the skirt is long. Tolerance 1 %: the leakage
  // at the relief edges costs 0.73 % per mm of skirt length (0.37 % here) and the 40 axial
  // elements 0.13 % (docs/validation/skirt.md).
  {
    const SkirtLimitCase c = SliderLimitCase(0.5e-3, 40);
    SkirtSolver solver(c.config);
    rows.push_back({"skirt", "inclined slider, L = 0.5 mm, panel 67 L wide: lateral force [N]",
                    "plane inclined slider closed form (K = 2)",
                    solver.Solve(c.state).lateral_force, c.reference, 0.01, true});
  }
  // Long-skirt squeeze: the force added by lengthening the skirt from 0.2 to 0.4 m, per metre.
  // The ends' loss cancels in the difference (to exp(-pi L / (2 R alpha1)) ~ 1e-4); tolerance
  // 0.5 %: the 20 circumferential elements are 0.09 % off.
  {
    const SkirtLimitCase a = SqueezeLimitCase(0.2, 20), b = SqueezeLimitCase(0.4, 20);
    SkirtSolver sa(a.config), sb(b.config);
    const double fa = sa.Solve(a.state).lateral_force, fb = sb.Solve(b.state).lateral_force;
    rows.push_back({"skirt", "long-skirt squeeze, (F(0.4 m) - F(0.2 m)) / 0.2 m [N/m]",
                    "long-skirt squeeze closed form", (fb - fa) / 0.2, b.reference / 0.4, 0.005,
                    true});
  }
  // Symmetries, on the default 62 x 40 mesh: a barrel symmetric about L/2, the pin at L/2,
  // equal panels. Mirroring alpha -> pi - alpha (thrust <-> anti-thrust) or y -> L - y (reversed
  // sliding) maps the problem onto itself, but not the mesh: its diagonals all run one way, so
  // each mirror alone holds only to the discretisation error (second order, 5.1e-4 here,
  // tolerance 2e-3); both together (a point reflection of the mesh) hold to rounding.
  {
    const SkirtConfig cfg = LimitSkirt(0.032, {{0.0, 0.016, 0.032}, {20e-6, 0.0, 20e-6}});
    // A solver per state: every solve from a cold start (no factor reused from another state).
    auto solve = [&cfg](const SkirtState& state) { return SkirtSolver(cfg).Solve(state); };
    SkirtState s;
    s.e0 = 9e-6;
    s.gamma = 2e-4;
    s.e0_dot = 3e-3;
    s.gamma_dot = 0.2;
    s.piston_velocity = 8.0;
    const SkirtResult base = solve(s);
    SkirtState thrust = s;  // alpha -> pi - alpha
    thrust.e0 = -s.e0;
    thrust.gamma = -s.gamma;
    thrust.e0_dot = -s.e0_dot;
    thrust.gamma_dot = -s.gamma_dot;
    SkirtState axial = s;  // y -> L - y
    axial.gamma = -s.gamma;
    axial.gamma_dot = -s.gamma_dot;
    axial.piston_velocity = -s.piston_velocity;
    SkirtState both = s;  // (alpha, y) -> (pi - alpha, L - y)
    both.e0 = -s.e0;
    both.e0_dot = -s.e0_dot;
    both.piston_velocity = -s.piston_velocity;
    // Each row: the largest relative mismatch of lateral force F, moment M, friction force Ff and
    // MOFT.
    rows.push_back({"skirt", "mirror thrust/anti-thrust: mismatch of F, M, Ff, MOFT",
                    "symmetry alpha -> pi - alpha: e0, gamma and their rates negated (0 up to the "
                    "one-way mesh diagonals)",
                    SymmetryMismatch(base, solve(thrust), true, true, false), 0.0, 2e-3, false});
    rows.push_back({"skirt", "mirror top/bottom, reversed sliding: mismatch of F, M, Ff, MOFT",
                    "symmetry y -> L - y: u_p, gamma and its rate negated (0 up to the one-way "
                    "mesh diagonals)",
                    SymmetryMismatch(base, solve(axial), false, true, true), 0.0, 2e-3, false});
    rows.push_back({"skirt", "both mirrors together: mismatch of F, M, Ff, MOFT",
                    "point symmetry (alpha, y) -> (pi - alpha, L - y) of the problem and the mesh: "
                    "u_p, e0 and its rate negated (0)",
                    SymmetryMismatch(base, solve(both), true, false, true), 0.0, 1e-12, false});
  }
  return rows;
}

}  // namespace filmdyn::lubrication
