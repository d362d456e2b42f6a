#include "core/lubrication/skirt_solver.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "core/base/input_error.hpp"
#include "core/lubrication/film_integrals.hpp"

namespace filmdyn::lubrication {

namespace {
constexpr double kPi = std::numbers::pi;
// Indices of a panel's load directions (SolvePanel): lateral, cos(alpha); tilt, the moment arm
// cos(alpha) (y - a_p).
constexpr int kLateral = 0, kTilt = 1;
}  // namespace

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
  if (supply == SkirtSupply::kStarved) {
    if (solver.cavitation != CavitationModel::kJfo) {
      throw InputError(prefix + ".supply", "\"starved\"",
                       "needs the mass-conserving cavitation model (cavitation = \"jfo\"): the "
                       "Reynolds condition tracks no partial film");
    }
    oil_film_table.Validate(prefix + ".oil_film_table", true);
    if (oil_film_table.empty()) RequirePositive(prefix + ".oil_film", oil_film, "m");
    for (std::size_t k = 0; k < oil_film_table.y.size(); ++k)
      RequirePositive(prefix + ".oil_film_table." + std::to_string(k), oil_film_table.y[k], "m");
  }
  ValidateCompliance(compliance, {.layer_thickness = prefix + ".layer_thickness",
                                  .layer_modulus = prefix + ".modulus_skirt",
                                  .layer_poisson = prefix + ".poisson_skirt",
                                  .modulus1 = prefix + ".modulus_skirt",
                                  .poisson1 = prefix + ".poisson_skirt",
                                  .modulus2 = prefix + ".modulus_liner",
                                  .poisson2 = prefix + ".poisson_liner",
                                  .tolerance = prefix + ".elastic_tolerance",
                                  .max_iterations = prefix + ".elastic_max_iterations",
                                  .imported = prefix + ".compliance_file"});
  RequireHalfSpaceSize(compliance,
                       long(std::max(mesh.n_thrust, mesh.n_anti) + 1) * (mesh.n_axial + 1),
                       prefix + ".compliance", "the mesh (" + prefix + ".mesh)");
}

void SkirtState::Validate(const std::string& prefix) const {
  RequireFinite(prefix + ".e0", e0, "m");
  RequireFinite(prefix + ".gamma", gamma, "rad");
  RequireFinite(prefix + ".e0_dot", e0_dot, "m/s");
  RequireFinite(prefix + ".gamma_dot", gamma_dot, "rad/s");
  RequireFinite(prefix + ".piston_velocity", piston_velocity, "m/s");
  RequireFinite(prefix + ".stroke_position", stroke_position, "m");
}

const char* ToString(SkirtSupply supply) {
  return supply == SkirtSupply::kFlooded ? "flooded" : "starved";
}

namespace {

// An imported skirt grid that closes around the circumference (its x lines from 0 to 2 pi R
// less one spacing, x = R alpha) is periodic: the thrust panel's mirror image (alpha < 0) lies
// across alpha = 0. A grid over a part of the skirt is not.
double ImportedPeriod(const ComplianceSpec& spec, double radius) {
  if (spec.model != ComplianceModel::kImported || !spec.imported) return 0.0;
  const std::vector<double>& x = spec.imported->x_lines;
  if (x.size() < 3) return 0.0;
  double widest = 0.0;
  for (std::size_t i = 1; i < x.size(); ++i) widest = std::max(widest, x[i] - x[i - 1]);
  const double circumference = 2.0 * kPi * radius;
  const double closing = circumference - (x.back() - x.front());
  return closing > 0.0 && closing <= 1.01 * widest ? circumference : 0.0;
}

}  // namespace

TriMesh SkirtSolver::MakeMesh(const SkirtGeometry& g, const SkirtMeshSpec& spec) {
  // Node lines through the kinks of the profile and ovality tables (ConformingLines), so that
  // the piecewise-linear film thickness is exact on the mesh and refining it converges at the
  // scheme's order (the error estimate's halved companion mesh relies on that).
  const double a1 = g.alpha1, a2 = kPi - g.alpha2;
  std::vector<double> alpha = ConformingLines(0.0, a1, spec.n_thrust, g.ovality.x);
  const auto mid = ConformingLines(a1, a2, spec.n_relief, g.ovality.x);
  const auto anti = ConformingLines(a2, kPi, spec.n_anti, g.ovality.x);
  alpha.insert(alpha.end(), mid.begin() + 1, mid.end());
  alpha.insert(alpha.end(), anti.begin() + 1, anti.end());
  std::vector<double> xs(alpha.size());
  for (size_t i = 0; i < alpha.size(); ++i) xs[i] = g.radius * alpha[i];
  TriMesh m = MakeTensorMesh(std::move(xs),
                             ConformingLines(0.0, g.skirt_length, spec.n_axial, g.profile.x),
                             false, 0);
  const int nx = m.nx_nodes(), ny = m.ny_nodes();
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const bool relief = i >= spec.n_thrust && i <= spec.n_thrust + spec.n_relief;  // eq. 6
      if (relief || j == 0 || j == ny - 1) m.fixed[m.Node(i, j)] = 1;
    }
  }
  return m;
}

// One lubricated panel: its own mesh and Reynolds solver, the per-node data it needs, and the
// integrals of the last solve (summed over the panels in panel order).
struct SkirtSolver::Panel {
  std::unique_ptr<ReynoldsFem> fem;
  std::vector<int> node;  // whole-skirt node of each panel node
  Eigen::VectorXd cos, weight;
  std::vector<double> alpha;
  ReynoldsStats stats;
  FilmIntegrals integrals;
  ElasticFilm elastic;  // rigid unless the surfaces are elastic
  ElasticSolveStats elastic_stats;
};

SkirtSolver::SkirtSolver(SkirtConfig config)
    : config_((config.Validate(), std::move(config))),
      mesh_(MakeMesh(config_.geometry, config_.mesh)) {
  const TriMesh& m = mesh_;
  const int n = m.NodeCount();
  const SkirtGeometry& g = config_.geometry;
  alpha_.resize(n);
  cos_.resize(n);
  h_static_.resize(n);
  arm_.resize(n);
  h_.resize(n);
  hdot_.resize(n);
  for (int k = 0; k < n; ++k) {
    alpha_[k] = m.x[k] / g.radius;
    cos_[k] = std::cos(alpha_[k]);
    h_static_[k] = g.radial_clearance + g.profile(m.y[k]) + g.ovality(alpha_[k]);
    arm_[k] = m.y[k] - g.pin_position;
  }
  // Panel node columns: thrust [0, n_thrust], anti-thrust [n_thrust + n_relief, nx - 1]; the
  // columns on the relief edges are p = 0 (eq. 6), as in the whole mesh.
  const SkirtMeshSpec& spec = config_.mesh;
  const int nx = m.nx_nodes(), ny = m.ny_nodes();
  const int first[kPanels] = {0, spec.n_thrust + spec.n_relief};
  const int last[kPanels] = {spec.n_thrust, nx - 1};
  for (int p = 0; p < kPanels; ++p) {
    auto panel = std::make_unique<Panel>();
    std::vector<double> xs(m.x_lines.begin() + first[p], m.x_lines.begin() + last[p] + 1);
    TriMesh sub = MakeTensorMesh(std::move(xs), m.y_lines, false, 0.0);
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i <= last[p] - first[p]; ++i) {
        const int full = m.Node(first[p] + i, j);
        panel->node.push_back(full);  // sub.Node(i, j) == panel->node.size() - 1
        sub.fixed[sub.Node(i, j)] = m.fixed[full];
      }
    }
    const int pn = sub.NodeCount();
    panel->cos.resize(pn);
    panel->weight.resize(pn);
    panel->alpha.resize(pn);
    for (int k = 0; k < pn; ++k) {
      const int full = panel->node[k];
      panel->cos[k] = cos_[full];
      panel->weight[k] = cos_[full] * arm_[full];
      panel->alpha[k] = alpha_[full];
    }
    panel->fem = std::make_unique<ReynoldsFem>(std::move(sub), 1, config_.solver);
    if (!config_.compliance.rigid()) {
      // Each panel is half of its film: the other half is its mirror image about the thrust
      // (alpha = 0) or anti-thrust (alpha = pi) plane.
      const double mirror = p == 0 ? 0.0 : kPi * g.radius;
      panel->elastic = ElasticFilm(
          SurfaceCompliance::Build(config_.compliance, panel->fem->mesh(), std::nullopt, mirror,
                                   ImportedPeriod(config_.compliance, g.radius)),
          config_.compliance);
    }
    panels_.push_back(std::move(panel));
  }
  fields_.pressure = Eigen::VectorXd::Zero(n);
  fields_.contact_pressure = Eigen::VectorXd::Zero(n);
  fields_.fluid_fraction = Eigen::VectorXd::Ones(n);
  fields_.residual = Eigen::VectorXd::Zero(n);
  fields_.cavitated.assign(n, 0);
  film_ = Eigen::VectorXd::Zero(n);
  deformation_ = Eigen::VectorXd::Zero(n);
}

SkirtSolver::~SkirtSolver() = default;

void SkirtSolver::SetStopCheck(const StopCheck& check) {
  for (auto& panel : panels_) panel->fem->SetStopCheck(check);
}

void SkirtSolver::SetThreads(int threads) {
  if (threads <= 1) {
    pool_.reset();
  } else if (!pool_) {
    pool_ = std::make_unique<WorkerPool>(2);  // two panels: one helper is all they can use
  }
}

const ReynoldsFem& SkirtSolver::panel(int k) const { return *panels_.at(k)->fem; }

const std::vector<int>& SkirtSolver::panel_nodes(int k) const { return panels_.at(k)->node; }

void SkirtSolver::SolvePanel(Panel& pa, const SkirtState& s, double time_step) {
  ReynoldsFem& fem = *pa.fem;
  const int n = fem.NodeCount();
  Eigen::VectorXd& h = fem.film_thickness();
  Eigen::VectorXd& hdot = fem.film_rate();
  for (int k = 0; k < n; ++k) {
    h[k] = h_[pa.node[k]];
    hdot[k] = hdot_[pa.node[k]];
  }
  if (config_.supply == SkirtSupply::kStarved) {
    // The leading edge (where the liner's oil enters): y = L while the piston moves toward the
    // crank, y = 0 on the way back; a partial film of content theta h_T = 2 h_oil there
    // (SkirtConfig), its fraction taken by the film solve at the gap it solves with (on an
    // elastic skirt the deformed one: the rigid gap may be closed there).
    fem.boundary_fraction().setOnes();
    Eigen::VectorXd& oil_in = fem.boundary_oil();
    oil_in.setZero(n);
    const TriMesh& pm = fem.mesh();
    const double y_lead = s.piston_velocity > 0.0 ? pm.y_lines.back() : pm.y_lines.front();
    if (s.piston_velocity != 0.0) {
      const double at = s.stroke_position + y_lead;
      const double h_oil =
          config_.oil_film_table.empty() ? config_.oil_film : config_.oil_film_table(at);
      for (int k = 0; k < n; ++k)
        if (pm.fixed[k] && pm.y[k] == y_lead) oil_in[k] = 2.0 * h_oil;
    }
  }
  ReynoldsParams params;
  params.viscosity = config_.viscosity;
  params.pressure_viscosity = &config_.pressure_viscosity;
  params.shear_thinning = &config_.shear_thinning;
  params.u_sum = -s.piston_velocity;  // liner moves at -u_p in the piston frame
  params.u_diff = s.piston_velocity;  // U1 - U2, surface 1 = skirt (at rest)
  params.film = config_.film.get();
  params.time_step = time_step;
  params.bulk_modulus = config_.bulk_modulus;
  params.density_law = config_.density_law;
  // The film's inputs for the deformation's predictor (ElasticFilm): the piston's secondary
  // motion and speed, and where a starved skirt's leading edge meets the liner's oil.
  Eigen::VectorXd inputs(config_.supply == SkirtSupply::kStarved ? 6 : 5);
  inputs.head<5>() << s.e0, s.gamma, s.e0_dot, s.gamma_dot, s.piston_velocity;
  if (inputs.size() == 6) inputs[5] = s.stroke_position;
  pa.elastic_stats = pa.elastic.Solve(fem, params, inputs);
  const ReynoldsSolution& sol = fem.solution();
  pa.stats = sol.stats;

  // Normal load: the film pushes the piston surface inwards, -p n with n = (cos a) along +e0.
  // Generalised force on gamma: arm (y - a_p) times the lateral force density. Friction on the
  // skirt (surface 1, at rest; the liner slides at -u_p, so U1 - U2 = u_p) along +y, eq. 31. A
  // rigid rotation d(gamma) moves a skirt point axially by -R cos(alpha) d(gamma), so the
  // friction moment (generalised force on gamma) is int tau (-R cos(alpha)) dA: the element-by-
  // element friction, which carries that arm. x2 for the mirrored half. Every element of a panel
  // carries film (the relief's belong to no panel).
  const std::array<const Eigen::VectorXd*, 2> directions = {&pa.cos, &pa.weight};
  const std::array<ScaledField, 1> arms = {ScaledField{&pa.cos, -config_.geometry.radius}};
  pa.integrals = IntegrateFilm(
      fem, sol, params, {.load_directions = directions, .friction_arms = arms, .symmetry = 2.0});
}

const SkirtResult& SkirtSolver::Solve(const SkirtState& state) { return SolveStep(state, 0.0); }

std::vector<Eigen::VectorXd> SkirtSolver::VoidContent() const {
  std::vector<Eigen::VectorXd> v;
  for (const auto& pa : panels_) v.push_back(pa->fem->solution().void_content);
  return v;
}

const SkirtResult& SkirtSolver::SolveAt(const SkirtState& state, double t) {
  if (!Transient()) return SolveStep(state, 0.0);
  const FilmHistory::Entry* from = history_.Before(t);
  if (from == nullptr) {
    if (!history_.empty()) return SolveStep(state, 0.0);  // before the start: not stepped to
    // The integration starts from a flooded film (as BearingSolver::SolveAt).
    std::vector<Eigen::VectorXd> flooded;
    for (const auto& pa : panels_) flooded.push_back(Eigen::VectorXd::Zero(pa->fem->NodeCount()));
    history_.Push(FilmHistory::StartTime(t), std::move(flooded));
    from = history_.Before(t);
  }
  for (size_t p = 0; p < panels_.size(); ++p)
    panels_[p]->fem->void_history() = from->void_content[p];
  return SolveStep(state, t - from->time);
}

void SkirtSolver::AcceptStep(double t) {
  if (Transient()) history_.Push(t, VoidContent());
}

SkirtGap SkirtSolver::MinRigidGap(double e0, double gamma) const {
  SkirtGap best{1e300, 0.0, 0.0};
  for (const auto& pa : panels_)
    for (const int k : pa->node) {
      const double gap = RigidGap(k, e0, gamma);
      if (gap < best.gap) best = {gap, alpha_[k], mesh_.y[k]};
    }
  return best;
}

const SkirtResult& SkirtSolver::SolveStep(const SkirtState& s, double time_step) {
  s.Validate();
  const int n = mesh_.NodeCount();
  SkirtResult& r = result_;
  r = SkirtResult{};
  for (int k = 0; k < n; ++k) {
    h_[k] = RigidGap(k, s.e0, s.gamma);
    hdot_[k] = -(s.e0_dot + arm_[k] * s.gamma_dot) * cos_[k];     // paper eq. 3
    // Rigid surfaces: a film thinner than min_film is held there (and counted). Elastic ones:
    // the rigid film may close (the piston past the liner's wall) where the deformation opens
    // it; the coupled solve refuses a film it cannot open.
    if (h_[k] < config_.min_film && config_.compliance.rigid()) {
      h_[k] = config_.min_film;
      ++r.clamped_nodes;
    }
  }
  if (pool_) {
    pool_->Run(kPanels, [&](int p) { SolvePanel(*panels_[p], s, time_step); });
  } else {
    for (auto& panel : panels_) SolvePanel(*panel, s, time_step);
  }

  // Whole-skirt results: the panels' sums in panel order. The whole-skirt fields are gathered
  // only when asked for (fields(): output steps), not at every solve.
  ReynoldsStats& st = r.stats;
  double cavitated_area = 0.0, panel_area = 0.0, wetted_area = 0.0;
  r.moft = 1e300;
  for (std::size_t p = 0; p < panels_.size(); ++p) {
    const auto& pa = panels_[p];
    const FilmIntegrals& fi = pa->integrals;
    st.Add(pa->stats);
    const ElasticSolveStats& es = pa->elastic_stats;
    r.max_deformation = std::max(r.max_deformation, es.max_deformation);
    r.elastic.iterations += es.iterations;
    r.elastic.film_solves += es.film_solves;
    r.elastic.krylov_iterations += es.krylov_iterations;
    r.elastic.recycled_steps += es.recycled_steps;
    r.elastic.residual = std::max(r.elastic.residual, es.residual);
    r.elastic.tolerance = std::max(r.elastic.tolerance, es.tolerance);
    if (!es.converged && r.elastic.converged) {
      r.elastic.converged = false;
      r.elastic.message = (p == 0 ? "thrust panel: " : "anti-thrust panel: ") + es.message;
      r.elastic.surfaces_touch = es.surfaces_touch;
    }
    r.lateral_force -= fi.load[kLateral];
    r.contact_lateral_force -= fi.contact_load[kLateral];
    r.friction_force += fi.element_friction.force;
    r.contact_friction_force += fi.element_friction.contact_force;
    r.friction_moment_about_pin += fi.element_friction.moment[0];
    r.moment_about_pin -= fi.load[kTilt];
    if (fi.moft < r.moft) {
      r.moft = fi.moft;
      r.moft_alpha = pa->alpha[fi.moft_node];
      r.moft_y = pa->fem->mesh().y[fi.moft_node];
    }
    r.max_pressure = std::max(r.max_pressure, fi.max_pressure);
    r.max_contact_pressure = std::max(r.max_contact_pressure, fi.max_contact_pressure);
    cavitated_area += fi.cavitated_area;
    panel_area += fi.film_area;
    const ReynoldsSolution& sol = pa->fem->solution();
    wetted_area += 2.0 * sol.wetted_area;  // x2: the mirrored half
    r.squeeze_rate += 2.0 * sol.squeeze_rate;
    r.void_volume += 2.0 * sol.void_volume;
    // The oil through each of the panel's edges, net: its upper edge, its lower edge and the
    // rest of its boundary (the pin-boss relief's edge). Node by node, the reactions along the
    // relief's edge, where the oil slides along the edge, have both signs, and their positive
    // part is no oil entering the film: a gross inflow that falls only in proportion to the cell
    // (docs/validation/errors.md, section 6).
    const TriMesh& pm = pa->fem->mesh();
    double edge[3] = {0.0, 0.0, 0.0};  // top, bottom, relief
    const double y_top = pm.y_lines.front(), y_bottom = pm.y_lines.back();
    for (int k = 0; k < pm.NodeCount(); ++k) {
      if (!pm.fixed[k]) continue;
      const int e = pm.y[k] <= y_top ? 0 : (pm.y[k] >= y_bottom ? 1 : 2);
      edge[e] += sol.residual[k];
    }
    for (double net : edge) {
      r.inflow += 2.0 * std::max(net, 0.0);
      r.outflow += 2.0 * std::max(-net, 0.0);
    }
  }
  fields_stale_ = true;
  r.moment_about_pin += r.friction_moment_about_pin;
  r.friction_power_loss = std::abs(r.friction_force * s.piston_velocity);
  r.cavitated_fraction = panel_area > 0 ? cavitated_area / panel_area : 0.0;
  r.wetted_fraction = panel_area > 0 ? wetted_area / panel_area : 1.0;
  return r;
}

const ReynoldsSolution& SkirtSolver::fields() const {
  if (!fields_stale_) return fields_;
  for (const auto& pa : panels_) {  // relief nodes keep p = p_c = 0
    const ReynoldsSolution& sol = pa->fem->solution();
    for (int k = 0; k < pa->fem->NodeCount(); ++k) {
      const int full = pa->node[k];
      fields_.pressure[full] = sol.pressure[k];
      fields_.contact_pressure[full] = sol.contact_pressure[k];
      fields_.fluid_fraction[full] = sol.fluid_fraction.size() ? sol.fluid_fraction[k] : 1.0;
      fields_.residual[full] = sol.residual.size() ? sol.residual[k] : 0.0;
      fields_.cavitated[full] = sol.cavitated[k];
      const Eigen::VectorXd& d = pa->elastic.deformation();
      deformation_[full] = d.size() ? d[k] : 0.0;
    }
  }
  film_ = h_ + deformation_;
  fields_.stats = result_.stats;
  fields_stale_ = false;
  return fields_;
}

const Eigen::VectorXd& SkirtSolver::film_thickness() const {
  if (config_.compliance.rigid()) return h_;
  fields();
  return film_;
}

const Eigen::VectorXd& SkirtSolver::deformation() const {
  fields();
  return deformation_;
}

void SkirtSolver::SetComplianceScale(double share) {
  for (auto& panel : panels_) panel->elastic.SetScale(share);
}

}  // namespace filmdyn::lubrication
