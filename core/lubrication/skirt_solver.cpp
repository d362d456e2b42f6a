#include "core/lubrication/skirt_solver.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/input_error.hpp"

namespace filmdyn::lubrication {

namespace {
constexpr double kPi = std::numbers::pi;
}

void SkirtConfig::Validate(const std::string& prefix) const {
  const SkirtGeometry& g = geometry;
  RequirePositive(prefix + ".radius", g.radius, "m");
  RequirePositive(prefix + ".skirt_length", g.skirt_length, "m");
  RequirePositive(prefix + ".radial_clearance", g.radial_clearance, "m");
  RequireFinite(prefix + ".pin_position", g.pin_position, "m");
  RequireInRange(prefix + ".alpha1", g.alpha1, 0.0, kPi, true, true, "rad");
  RequireInRange(prefix + ".alpha2", g.alpha2, 0.0, kPi - g.alpha1, true, true, "rad");
  g.profile.Validate(prefix + ".profile", false);
  g.ovality.Validate(prefix + ".ovality", true);
  RequirePositive(prefix + ".viscosity", viscosity, "Pa*s");
  RequireInRange(prefix + ".mesh.n_thrust", mesh.n_thrust, 1, 10000);
  RequireInRange(prefix + ".mesh.n_relief", mesh.n_relief, 1, 10000);
  RequireInRange(prefix + ".mesh.n_anti", mesh.n_anti, 1, 10000);
  RequireInRange(prefix + ".mesh.n_axial", mesh.n_axial, 2, 10000);
  RequirePositive(prefix + ".min_film", min_film, "m");
  RequireInRange(prefix + ".solver.max_iterations", solver.max_iterations, 1, 100000);
}

void SkirtState::Validate(const std::string& prefix) const {
  RequireFinite(prefix + ".e0", e0, "m");
  RequireFinite(prefix + ".gamma", gamma, "rad");
  RequireFinite(prefix + ".e0_dot", e0_dot, "m/s");
  RequireFinite(prefix + ".gamma_dot", gamma_dot, "rad/s");
  RequireFinite(prefix + ".piston_velocity", piston_velocity, "m/s");
}

TriMesh SkirtSolver::MakeMesh(const SkirtGeometry& g, const SkirtMeshSpec& spec) {
  const double a1 = g.alpha1, a2 = kPi - g.alpha2;
  std::vector<double> alpha = Linspace(0.0, a1, spec.n_thrust);
  const auto mid = Linspace(a1, a2, spec.n_relief);
  const auto anti = Linspace(a2, kPi, spec.n_anti);
  alpha.insert(alpha.end(), mid.begin() + 1, mid.end());
  alpha.insert(alpha.end(), anti.begin() + 1, anti.end());
  std::vector<double> xs(alpha.size());
  for (size_t i = 0; i < alpha.size(); ++i) xs[i] = g.radius * alpha[i];
  TriMesh m = MakeTensorMesh(std::move(xs), Linspace(0.0, g.skirt_length, spec.n_axial), false, 0);
  const int nx = m.nx_nodes(), ny = m.ny_nodes();
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const bool relief = i >= spec.n_thrust && i <= spec.n_thrust + spec.n_relief;  // eq. 6
      if (relief || j == 0 || j == ny - 1) m.fixed[m.Node(i, j)] = 1;
    }
  }
  return m;
}

SkirtSolver::SkirtSolver(SkirtConfig config)
    : config_((config.Validate(), std::move(config))),
      fem_(MakeMesh(config_.geometry, config_.mesh), 1, config_.solver) {
  const TriMesh& m = fem_.mesh();
  const int n = m.NodeCount();
  const SkirtGeometry& g = config_.geometry;
  alpha_.resize(n);
  cos_.resize(n);
  h_static_.resize(n);
  arm_.resize(n);
  ptot_.resize(n);
  weight_.resize(n);
  for (int k = 0; k < n; ++k) {
    alpha_[k] = m.x[k] / g.radius;
    cos_[k] = std::cos(alpha_[k]);
    h_static_[k] = g.radial_clearance + g.profile(m.y[k]) + g.ovality(alpha_[k]);
    arm_[k] = m.y[k] - g.pin_position;
  }
}

const SkirtResult& SkirtSolver::Solve(const SkirtState& s) {
  s.Validate();
  const SkirtGeometry& g = config_.geometry;
  const TriMesh& m = fem_.mesh();
  const int n = m.NodeCount();
  Eigen::VectorXd& h = fem_.film_thickness();
  Eigen::VectorXd& hdot = fem_.film_rate();
  SkirtResult& r = result_;
  r = SkirtResult{};
  for (int k = 0; k < n; ++k) {
    h[k] = h_static_[k] - (s.e0 + arm_[k] * s.gamma) * cos_[k];  // paper eq. 2, our sign
    hdot[k] = -(s.e0_dot + arm_[k] * s.gamma_dot) * cos_[k];     // paper eq. 3
    if (h[k] < config_.min_film) {
      h[k] = config_.min_film;
      ++r.clamped_nodes;
    }
  }
  ReynoldsParams params;
  params.viscosity = config_.viscosity;
  params.u_sum = -s.piston_velocity;  // liner moves at -u_p in the piston frame
  params.u_diff = s.piston_velocity;  // U1 - U2, surface 1 = skirt (at rest)
  params.film = config_.film.get();
  const ReynoldsSolution& sol = fem_.Solve(params);
  r.stats = sol.stats;

  // Normal load: film pushes the piston surface inwards, -p n with n = (cos a) along +e0; x2 for
  // the mirrored half. Generalised force on gamma: arm (y - a_p) times the lateral force density.
  ptot_ = sol.pressure + sol.contact_pressure;
  r.lateral_force = -2.0 * fem_.IntegrateProduct(ptot_, cos_);
  r.contact_lateral_force = -2.0 * fem_.IntegrateProduct(sol.contact_pressure, cos_);
  weight_ = cos_.cwiseProduct(arm_);
  const double normal_moment = -2.0 * fem_.IntegrateProduct(ptot_, weight_);

  // Friction on the skirt (surface 1, at rest; liner slides at -u_p): Patir & Cheng 1979 /
  // paper eq. 31  tau = -mu u_p/h (Phi_f + Phi_fs) - Phi_fp h/2 dp/dy, plus -mu_f p_c sign(u_p).
  // A rigid rotation d(gamma) moves a skirt point axially by -R cos(alpha) d(gamma), so the
  // friction moment (generalised force on gamma) is -int tau R cos(alpha) dA.
  const auto& fac = fem_.factors();
  const double mu = config_.viscosity, up = s.piston_velocity;
  const double mu_f = config_.film ? config_.film->boundary_friction() : 0.0;
  const double sgn = (up > 0) - (up < 0);
  const bool jfo = config_.solver.cavitation == CavitationModel::kJfo;
  double force = 0.0, moment = 0.0, contact = 0.0;
  for (const auto& e : fem_.elements()) {
    double cpl = 0.0, hfp = 0.0, dpdy = 0.0, pc = 0.0, cs = 0.0;
    for (int a = 0; a < 3; ++a) {
      const int k = e.node[a];
      const double theta_f = jfo ? sol.fluid_fraction[k] : 1.0;
      cpl += theta_f * (fac[k].shear_f + fac[k].shear_fs) / h[k];
      hfp += fac[k].shear_fp * h[k];
      dpdy += e.dndy[a] * sol.pressure[k];
      pc += sol.contact_pressure[k];
      cs += cos_[k];
    }
    // Elements inside the pin-boss relief (all three nodes in Omega2) carry no film.
    const bool relief =
        m.fixed[e.node[0]] && m.fixed[e.node[1]] && m.fixed[e.node[2]] &&
        alpha_[e.node[0]] > g.alpha1 - 1e-12 && alpha_[e.node[0]] < kPi - g.alpha2 + 1e-12 &&
        alpha_[e.node[1]] > g.alpha1 - 1e-12 && alpha_[e.node[1]] < kPi - g.alpha2 + 1e-12 &&
        alpha_[e.node[2]] > g.alpha1 - 1e-12 && alpha_[e.node[2]] < kPi - g.alpha2 + 1e-12;
    if (relief) continue;
    const double tau_area = -mu * up * e.area * cpl / 3.0 - e.area * 0.5 * (hfp / 3.0) * dpdy -
                            sgn * mu_f * e.area * pc / 3.0;
    force += tau_area;
    moment += -tau_area * g.radius * cs / 3.0;
    contact += -sgn * mu_f * e.area * pc / 3.0;
  }
  r.friction_force = 2.0 * force;
  r.contact_friction_force = 2.0 * contact;
  r.friction_moment_about_pin = 2.0 * moment;
  r.moment_about_pin = normal_moment + r.friction_moment_about_pin;
  r.friction_power_loss = std::abs(r.friction_force * up);

  r.moft = 1e300;
  const auto& area = fem_.lumped_area();
  double cav_area = 0.0, panel_area = 0.0;
  for (int k = 0; k < n; ++k) {
    const bool relief = alpha_[k] > g.alpha1 + 1e-12 && alpha_[k] < kPi - g.alpha2 - 1e-12;
    if (relief) continue;
    if (h[k] < r.moft) {
      r.moft = h[k];
      r.moft_alpha = alpha_[k];
      r.moft_y = m.y[k];
    }
    r.max_pressure = std::max(r.max_pressure, sol.pressure[k]);
    r.max_contact_pressure = std::max(r.max_contact_pressure, sol.contact_pressure[k]);
    panel_area += area[k];
    if (sol.cavitated[k]) cav_area += area[k] * (jfo ? 1.0 - sol.fluid_fraction[k] : 1.0);
  }
  r.cavitated_fraction = panel_area > 0 ? cav_area / panel_area : 0.0;
  return r;
}

}  // namespace filmdyn::lubrication
