#include "core/lubrication/bearing_solver.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <tuple>

#include "core/base/angles.hpp"
#include "core/base/input_error.hpp"
#include "core/lubrication/film_integrals.hpp"

namespace filmdyn::lubrication {

namespace {
constexpr double kPi = std::numbers::pi;

double WrapTwoPi(double a) {
  a = std::fmod(a, 2.0 * kPi);
  return a < 0.0 ? a + 2.0 * kPi : a;
}
}  // namespace

void BearingConfig::Validate(const std::string& prefix) const {
  RequirePositive(prefix + ".radius", geometry.radius, "m");
  RequirePositive(prefix + ".length", geometry.length, "m");
  RequirePositive(prefix + ".radial_clearance", geometry.radial_clearance, "m");
  if (geometry.radial_clearance >= geometry.radius) {
    throw InputError(prefix + ".radial_clearance", FormatValue(geometry.radial_clearance),
                     "must be smaller than the radius " + FormatValue(geometry.radius) + " [m]");
  }
  RequirePositive(prefix + ".viscosity", viscosity, "Pa*s");
  RequireInRange(prefix + ".mesh.n_theta", mesh.n_theta, 8, 20000);
  RequireInRange(prefix + ".mesh.n_z", mesh.n_z, 2, 5000);
  RequireInRange(prefix + ".mesh.theta_grading", mesh.theta_grading, 1.0, 100.0, false, false, "-");
  RequireInRange(prefix + ".mesh.z_grading", mesh.z_grading, 1.0, 100.0, false, false, "-");
  RequireInRange(prefix + ".solver.max_iterations", solver.max_iterations, 1, 100000);
  RequireNonNegative(prefix + ".feed.pressure", feed.pressure, "Pa");
  ValidateOilFeed(feed, geometry.radius, geometry.length,
                  {.hole_angles = prefix + ".feed.hole_angles",
                   .hole_diameter = prefix + ".feed.hole_diameter",
                   .groove_start = prefix + ".feed.groove_start",
                   .groove_end = prefix + ".feed.groove_end",
                   .groove_width = prefix + ".feed.groove_width",
                   .width = prefix + ".length"});
  ValidateCompliance(compliance, {.layer_thickness = prefix + ".layer_thickness",
                                  .layer_modulus = prefix + ".modulus_bearing",
                                  .layer_poisson = prefix + ".poisson_bearing",
                                  .modulus1 = prefix + ".modulus_journal",
                                  .poisson1 = prefix + ".poisson_journal",
                                  .modulus2 = prefix + ".modulus_bearing",
                                  .poisson2 = prefix + ".poisson_bearing",
                                  .tolerance = prefix + ".elastic_tolerance",
                                  .max_iterations = prefix + ".elastic_max_iterations",
                                  .imported = prefix + ".compliance_file"});
  RequireHalfSpaceSize(compliance, long(mesh.n_theta) * (mesh.n_z + 1), prefix + ".compliance",
                       "the mesh (" + prefix + ".mesh)");
}

void ValidateOilFeed(const OilFeed& feed, double radius, double width, const OilFeedFields& names) {
  if (HasHoles(feed.kind)) {
    if (feed.hole_angles.empty())
      throw InputError(names.hole_angles, "[]", "needs at least one hole angle");
    // A crank pin or a shell has a few feed holes; the checks below and the film's marking of
    // each hole's nodes go over the holes pairwise and node by node.
    constexpr std::size_t kMaxHoles = 64;
    if (feed.hole_angles.size() > kMaxHoles) {
      throw InputError(names.hole_angles, std::to_string(feed.hole_angles.size()) + " holes",
                       "at most " + std::to_string(kMaxHoles) + " holes");
    }
    for (std::size_t k = 0; k < feed.hole_angles.size(); ++k)
      RequireFinite(names.hole_angles + "." + std::to_string(k), feed.hole_angles[k], "rad");
    if (!(feed.hole_diameter > 0.0 && feed.hole_diameter < width)) {
      throw InputError(names.hole_diameter, FormatValue(feed.hole_diameter),
                       "must lie in (0, " + names.width + " = " + FormatValue(width) + ") [m]");
    }
    // Around, a hole wider than half the circumference would overlap itself.
    if (!(feed.hole_diameter < kPi * radius)) {
      throw InputError(names.hole_diameter, FormatValue(feed.hole_diameter),
                       "must be less than half the bearing's circumference, π R = " +
                           FormatValue(kPi * radius) + " [m]");
    }
    // Holes whose circles overlap are one hole given twice: refused.
    const double d = feed.hole_diameter / radius;  // angular diameter
    for (std::size_t a = 0; a < feed.hole_angles.size(); ++a) {
      for (std::size_t b = a + 1; b < feed.hole_angles.size(); ++b) {
        const double gap =
            std::abs(WrapTwoPi(feed.hole_angles[a] - feed.hole_angles[b] + kPi) - kPi);
        if (gap < d) {
          throw InputError(
              names.hole_angles + "." + std::to_string(b), FormatValue(feed.hole_angles[b]),
              "overlaps hole " + std::to_string(a) + " at " + FormatValue(feed.hole_angles[a]) +
                  " rad: holes must be at least one hole diameter apart (" + FormatValue(d) +
                  " rad at this radius)");
        }
      }
    }
  }
  if (HasGroove(feed.kind)) {
    RequireFinite(names.groove_start, feed.groove_start, "rad");
    RequireFinite(names.groove_end, feed.groove_end, "rad");
    if (!(feed.groove_end > feed.groove_start) ||
        feed.groove_end - feed.groove_start > 2.0 * kPi + 1e-9) {
      throw InputError(names.groove_end, FormatValue(feed.groove_end),
                       "must lie after " + names.groove_start + " = " +
                           FormatValue(feed.groove_start) +
                           " [rad] by at most 2π (a whole-circle groove)");
    }
    if (!(feed.groove_width > 0.0 && feed.groove_width < width)) {
      throw InputError(names.groove_width, FormatValue(feed.groove_width),
                       "must lie in (0, " + names.width + " = " + FormatValue(width) + ") [m]");
    }
  }
}

void BearingState::Validate(const std::string& prefix, double eps_limit) const {
  RequireInRange(prefix + ".eps", eps, 0.0, eps_limit, false, true);
  RequireFinite(prefix + ".eps_dot", eps_dot, "1/s");
  RequireFinite(prefix + ".line_of_centres_angle", line_of_centres_angle, "rad");
  RequireFinite(prefix + ".line_of_centres_rate", line_of_centres_rate, "rad/s");
  RequireFinite(prefix + ".omega_journal", omega_journal, "rad/s");
  RequireFinite(prefix + ".omega_bearing", omega_bearing, "rad/s");
  RequireFinite(prefix + ".bearing_angle", bearing_angle, "rad");
  RequireFinite(prefix + ".journal_angle", journal_angle, "rad");
  if (supply_pressure) RequireNonNegative(prefix + ".supply_pressure", *supply_pressure, "Pa");
}

const char* ToString(OilFeedKind kind) {
  switch (kind) {
    case OilFeed::Kind::kLineOfCentres:
      return "line_of_centres";
    case OilFeed::Kind::kShellHoles:
      return "shell_holes";
    case OilFeed::Kind::kPinHoles:
      return "pin_holes";
    case OilFeed::Kind::kGroove:
      return "groove";
    case OilFeed::Kind::kPinHolesAndGroove:
      return "pin_holes_and_groove";
  }
  return "?";
}

std::vector<double> GradedAngles(int n, double ratio) {
  const double beta = (ratio - 1.0) / (ratio + 1.0);
  std::vector<double> theta(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) {
    const double s = static_cast<double>(i) / n;
    theta[static_cast<std::size_t>(i)] = 2.0 * kPi * s + beta * std::sin(2.0 * kPi * s);
  }
  theta.front() = 0.0;
  theta.back() = 2.0 * kPi;
  return theta;
}

std::vector<double> GradedWidth(int n, double length, double ratio, bool half) {
  const double beta = (ratio - 1.0) / (ratio + 1.0);
  const double end = half ? 0.5 : 1.0;
  std::vector<double> z(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) {
    const double s = end * static_cast<double>(i) / n;
    z[static_cast<std::size_t>(i)] = length * (s - beta * std::sin(2.0 * kPi * s) / (2.0 * kPi));
  }
  z.front() = 0.0;
  z.back() = end * length;
  return z;
}

std::vector<double> WidthLines(int n, double length, double ratio, bool half) {
  return ratio == 1.0 ? Linspace(0.0, half ? 0.5 * length : length, n)  // uniform
                      : GradedWidth(n, length, ratio, half);
}

TriMesh BearingSolver::MakeMesh(const BearingGeometry& g, const BearingMeshSpec& spec,
                                bool fix_theta0) {
  const double period = 2.0 * kPi * g.radius;
  std::vector<double> xs;
  if (spec.theta_grading == 1.0) {
    xs = Linspace(0.0, period, spec.n_theta);  // uniform
  } else {
    xs = GradedAngles(spec.n_theta, spec.theta_grading);
    for (double& x : xs) x *= g.radius;
    xs.back() = period;
  }
  xs.pop_back();  // periodic: x = 2 pi R is node column 0
  std::vector<double> zs = WidthLines(spec.n_z, g.length, spec.z_grading, spec.symmetric_half);
  TriMesh m = MakeTensorMesh(std::move(xs), std::move(zs), true, period);
  const int nx = m.nx_nodes(), ny = m.ny_nodes();
  for (int i = 0; i < nx; ++i) {
    m.fixed[m.Node(i, 0)] = 1;                                 // edge z = 0
    if (!spec.symmetric_half) m.fixed[m.Node(i, ny - 1)] = 1;  // edge z = L
  }
  if (fix_theta0)
    for (int j = 0; j < ny; ++j) m.fixed[m.Node(0, j)] = 1;  // film start, p = 0 (eq. 19)
  return m;
}

BearingSolver::BearingSolver(BearingConfig config)
    : config_((config.Validate(), std::move(config))),
      fem_(MakeMesh(config_.geometry, config_.mesh,
                    config_.feed.kind == OilFeed::Kind::kLineOfCentres),
           0, config_.solver) {
  const TriMesh& m = fem_.mesh();
  if (!config_.compliance.rigid()) {
    std::optional<double> mirror;
    if (config_.mesh.symmetric_half) mirror = 0.5 * config_.geometry.length;
    elastic_ =
        ElasticFilm(SurfaceCompliance::Build(config_.compliance, m, mirror), config_.compliance);
  }
  const int n = m.NodeCount();
  theta_.resize(n);
  cos_.resize(n);
  sin_.resize(n);
  for (int k = 0; k < n; ++k) {
    theta_[k] = m.x[k] / config_.geometry.radius;
    cos_[k] = std::cos(theta_[k]);
    sin_[k] = std::sin(theta_[k]);
  }
  if (!config_.mesh.symmetric_half) {
    full_width_.mesh = m;
    full_width_.source.resize(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) full_width_.source[static_cast<std::size_t>(k)] = k;
  } else {
    // Rows 0 … ny−1 of the half (edge to mid-plane), then their mirror images up to the far edge.
    const int ny = m.ny_nodes();
    std::vector<double> ys = m.y_lines;
    for (int j = ny - 2; j >= 0; --j) ys.push_back(config_.geometry.length - m.y_lines[j]);
    full_width_.mesh =
        MakeTensorMesh(m.x_lines, std::move(ys), m.periodic_x, m.x_period);
    const TriMesh& f = full_width_.mesh;
    full_width_.source.resize(static_cast<std::size_t>(f.NodeCount()));
    for (int j = 0; j < f.ny_nodes(); ++j) {
      const int mirrored = j < ny ? j : 2 * (ny - 1) - j;
      for (int i = 0; i < f.nx_nodes(); ++i) {
        full_width_.source[static_cast<std::size_t>(f.Node(i, j))] = m.Node(i, mirrored);
      }
    }
  }
}

const BearingResult& BearingSolver::Solve(const BearingState& state) {
  return SolveStep(state, 0.0);
}

void BearingSolver::MarkSupplyNodes(const BearingState& s) {
  const OilFeed& feed = config_.feed;
  const BearingGeometry& g = config_.geometry;
  const TriMesh& m = fem_.mesh();
  auto& extra = fem_.extra_fixed();
  Eigen::VectorXd& pb = fem_.boundary_pressure();
  std::fill(extra.begin(), extra.end(), 0);
  pb.setZero();
  std::vector<EmbeddedCut>& cuts = fem_.embedded_cuts();
  cuts.clear();
  const double pressure = s.supply_pressure.value_or(feed.pressure);
  const double z_mid = 0.5 * g.length;  // the symmetric half's mid-plane is its last row
  int j_mid = 0;
  for (int j = 0; j < m.ny_nodes(); ++j)
    if (std::abs(m.y_lines[j] - z_mid) < std::abs(m.y_lines[j_mid] - z_mid)) j_mid = j;
  // Angle of a node in the line-of-centres frame (theta from the maximum film at -n) measured
  // from a body-fixed angle: the frame's theta = body angle + body orientation - (phi + pi).
  auto frame_angle = [&](double body_angle, double orientation) {
    return WrapTwoPi(orientation + body_angle - (s.line_of_centres_angle + kPi));
  };
  auto mark = [&](int k) {
    if (m.fixed[k]) return;
    extra[k] = 1;
    pb[k] = pressure;
  };
  const int nx = m.nx_nodes(), ny = m.ny_nodes();
  // Each region is held on the nodes inside it (a region narrower than the mesh on its nearest
  // nodes); its edge between those nodes and their free neighbours is then placed where it
  // cuts the mesh lines (EmbeddedCut: the flow into the film sees the region's true size, at
  // second order, and changes continuously as a region turns over the mesh). `entry(free,
  // held)` is the fraction of the way from the free node (i, j) to the held one where the
  // segment enters the region; a node held only as the nearest, outside it, keeps the plain
  // finite-element boundary. Cut after every region is marked (a node another region holds is
  // not free); an edge two regions cut keeps the nearer crossing.
  using Ij = std::array<int, 2>;
  auto cut_edges = [&](auto&& inside, auto&& entry) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const int held = m.Node(i, j);
        if (!extra[held] || !inside(Ij{i, j})) continue;
        for (Ij nb : {Ij{i - 1, j}, Ij{i + 1, j}, Ij{i, j - 1}, Ij{i, j + 1}}) {
          if (nb[1] < 0 || nb[1] >= ny) continue;
          if (nb[0] < 0 || nb[0] >= nx) {
            if (!m.periodic_x) continue;
            nb[0] = (nb[0] + nx) % nx;
          }
          const int k = m.Node(nb[0], nb[1]);
          if (extra[k] || m.fixed[k]) continue;
          cuts.push_back({k, held, std::clamp(entry(nb, Ij{i, j}), 0.0, 1.0)});
        }
      }
    }
  };
  // The groove: signed distance to its rectangle (negative inside), across the width and around
  // from its two ends in the bearing body (a whole-circle groove has none). Each is linear along
  // a mesh line inside the other's band, so the crossing by interpolation is exact.
  const double span = feed.groove_end - feed.groove_start;
  const bool whole_circle = span >= 2.0 * kPi - 1e-12;
  auto groove_around = [&](const Ij& n) {
    if (whole_circle) return -1e300;
    const double body = WrapTwoPi(theta_[m.Node(n[0], n[1])] + s.line_of_centres_angle + kPi -
                                  s.bearing_angle - feed.groove_start);
    return g.radius *
           (body <= span ? -std::min(body, span - body) : std::min(body - span, 2.0 * kPi - body));
  };
  auto groove_distance = [&](const Ij& n) {
    return std::max(std::abs(m.y_lines[n[1]] - z_mid) - 0.5 * feed.groove_width, groove_around(n));
  };
  if (HasGroove(feed.kind)) {
    for (int j = 0; j < ny; ++j) {
      if (j != j_mid && std::abs(m.y_lines[j] - z_mid) > 0.5 * feed.groove_width) continue;
      // A groove shorter around than the mesh's spacing there holds no node of the row: its
      // nearest node then, as a hole's (a 1° groove fed nothing while no node lay in it).
      int nearest = -1;
      double best = 1e300;
      bool any = false;
      for (int i = 0; i < nx; ++i) {
        const double around = groove_around(Ij{i, j});
        if (around <= 0.0) mark(m.Node(i, j)), any = true;
        if (around < best) best = around, nearest = m.Node(i, j);
      }
      if (!any && nearest >= 0) mark(nearest);
    }
  }
  // The holes: a node's position from a hole's centre, around (signed, the short way) and
  // across.
  const double r_hole = 0.5 * feed.hole_diameter;
  auto hole_offset = [&](double centre, const Ij& n) {
    const double turn = WrapTwoPi(theta_[m.Node(n[0], n[1])] - centre + kPi) - kPi;
    return std::array<double, 2>{g.radius * turn, m.y_lines[n[1]] - z_mid};
  };
  auto in_hole = [&](double centre, const Ij& n) {
    const std::array<double, 2> d = hole_offset(centre, n);
    return d[0] * d[0] + d[1] * d[1] <= r_hole * r_hole;
  };
  // Signed distance from the hole's edge (negative inside), interpolated linearly along an
  // edge for the crossing: a node just inside the circle then has its plain boundary (fraction
  // 1), as the hole's nearest node has when the circle holds none, and the hole's flow stays
  // continuous as a node enters it (the exact intersection would jump there).
  auto hole_distance = [&](double centre, const Ij& n) {
    const std::array<double, 2> d = hole_offset(centre, n);
    return std::hypot(d[0], d[1]) - r_hole;
  };
  std::vector<double> centres;
  if (HasHoles(feed.kind)) {
    const double orientation = HasPinHoles(feed.kind) ? s.journal_angle : s.bearing_angle;
    for (double hole : feed.hole_angles) {
      const double centre = frame_angle(hole, orientation);
      centres.push_back(centre);
      int nearest = -1;
      double best = 1e300;
      for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
          const std::array<double, 2> d = hole_offset(centre, Ij{i, j});
          const double d2 = d[0] * d[0] + d[1] * d[1];
          if (d2 <= r_hole * r_hole) mark(m.Node(i, j));
          if (d2 < best) best = d2, nearest = m.Node(i, j);
        }
      }
      if (nearest >= 0) mark(nearest);
    }
  }
  if (HasGroove(feed.kind)) {
    cut_edges([&](const Ij& n) { return groove_distance(n) <= 0.0; },
              [&](const Ij& out, const Ij& in) {
                const double d_out = groove_distance(out), d_in = groove_distance(in);
                return d_out / (d_out - d_in);
              });
  }
  for (double centre : centres) {
    cut_edges([&](const Ij& n) { return in_hole(centre, n); },
              [&](const Ij& free, const Ij& held) {
                const double d_out = hole_distance(centre, free);
                return d_out / (d_out - hole_distance(centre, held));
              });
  }
  std::sort(cuts.begin(), cuts.end(), [](const EmbeddedCut& x, const EmbeddedCut& y) {
    return std::tie(x.free_node, x.fixed_node, x.fraction) <
           std::tie(y.free_node, y.fixed_node, y.fraction);
  });
  cuts.erase(std::unique(cuts.begin(), cuts.end(),
                         [](const EmbeddedCut& x, const EmbeddedCut& y) {
                           return x.free_node == y.free_node && x.fixed_node == y.fixed_node;
                         }),
             cuts.end());
}

const BearingResult& BearingSolver::SolveAt(const BearingState& state, double t) {
  if (!Transient()) return SolveStep(state, 0.0);
  const FilmHistory::Entry* from = history_.Before(t);
  if (from == nullptr) {
    if (!history_.empty()) return SolveStep(state, 0.0);  // before the start: not stepped to
    // The integration starts from a flooded film, the clearance full of oil; the film at t
    // steps from it over a negligible interval.
    history_.Push(FilmHistory::StartTime(t), {Eigen::VectorXd::Zero(fem_.NodeCount())});
    from = history_.Before(t);
  }
  fem_.void_history() = from->void_content.front();
  return SolveStep(state, t - from->time);
}

void BearingSolver::AcceptStep(double t) {
  if (Transient()) history_.Push(t, {fem_.solution().void_content});
}

Eigen::VectorXd BearingSolver::PredictorInputs(const BearingState& s) const {
  // The film (line-of-centres frame): eps, its rate and the surface speeds; the angles between
  // that frame and the bodies (cosine and sine: smooth through a turn) where the film depends
  // on them: the imported compliance and a shell's feed turn with the bearing, pin holes with
  // the journal; a supply pressure that varies over the cycle.
  std::vector<double> z = {s.eps, s.eps_dot,
                           s.omega_journal + s.omega_bearing - 2.0 * s.line_of_centres_rate,
                           s.omega_journal - s.omega_bearing};
  const OilFeed::Kind feed = config_.feed.kind;
  if (config_.compliance.model == ComplianceModel::kImported ||
      feed == OilFeed::Kind::kShellHoles || HasGroove(feed)) {
    z.push_back(std::cos(s.line_of_centres_angle - s.bearing_angle));
    z.push_back(std::sin(s.line_of_centres_angle - s.bearing_angle));
  }
  if (HasPinHoles(feed)) {
    z.push_back(std::cos(s.line_of_centres_angle - s.journal_angle));
    z.push_back(std::sin(s.line_of_centres_angle - s.journal_angle));
  }
  if (s.supply_pressure) z.push_back(*s.supply_pressure);
  return Eigen::Map<const Eigen::VectorXd>(z.data(), static_cast<Eigen::Index>(z.size()));
}

const BearingResult& BearingSolver::SolveStep(const BearingState& s, double time_step) {
  // Elastic surfaces: the journal may pass the rigid wall (eps >= 1) where the deformation keeps
  // the film open (ElasticFilm refuses a film it cannot open).
  s.Validate("bearing_state", config_.compliance.rigid() ? 1.0 : kElasticEpsLimit);
  const BearingGeometry& g = config_.geometry;
  const TriMesh& m = fem_.mesh();
  const int n = m.NodeCount();
  const double c = g.radial_clearance, R = g.radius;
  Eigen::VectorXd& h = fem_.film_thickness();
  Eigen::VectorXd& hdot = fem_.film_rate();
  for (int k = 0; k < n; ++k) {
    h[k] = c * (1.0 + s.eps * cos_[k]);  // paper eq. 13
    hdot[k] = c * s.eps_dot * cos_[k];   // rotating line-of-centres frame
  }
  if (config_.feed.kind != OilFeed::Kind::kLineOfCentres) MarkSupplyNodes(s);
  ReynoldsParams params;
  params.viscosity = config_.viscosity;
  params.pressure_viscosity = &config_.pressure_viscosity;
  params.shear_thinning = &config_.shear_thinning;
  params.u_sum = R * (s.omega_journal + s.omega_bearing - 2.0 * s.line_of_centres_rate);
  params.u_diff = R * (s.omega_journal - s.omega_bearing);
  params.film = config_.film.get();
  params.time_step = time_step;
  params.bulk_modulus = config_.bulk_modulus;
  params.density_law = config_.density_law;
  // An imported compliance is fixed in the bearing body: the film's theta = 0 lies at the body
  // angle phi + pi - (bearing orientation).
  elastic_.SetOffset(R * WrapTwoPi(s.line_of_centres_angle + kPi - s.bearing_angle -
                                   config_.compliance.imported_reference_angle));
  const ElasticSolveStats& elastic = elastic_.Solve(fem_, params, PredictorInputs(s));
  const ReynoldsSolution& sol = fem_.solution();

  BearingResult& r = result_;
  r = BearingResult{};
  r.stats = sol.stats;
  r.elastic = elastic;
  r.max_deformation = elastic.max_deformation;
  const double sym = config_.mesh.symmetric_half ? 2.0 : 1.0;
  // Force on the journal: F = -int p r_hat dA with r_hat = cos(theta) a1 + sin(theta) a2 and
  // a1 = -n, a2 = -t  =>  F_n = int p cos(theta) dA, F_t = int p sin(theta) dA. The friction
  // (eq. 31) acts along +x = R theta: surface 1 is the journal, surface 2 the bearing; the
  // torques come from the part-by-part sums (the element-by-element sum agrees to rounding, but
  // that rounding is enough to change the step sequence of a coupled run).
  const std::array<const Eigen::VectorXd*, 2> directions = {&cos_, &sin_};
  const FilmIntegrals fi =
      IntegrateFilm(fem_, sol, params, {.load_directions = directions, .symmetry = sym});
  r.force_n = fi.load[0];
  r.force_t = fi.load[1];
  r.contact_force_n = fi.contact_load[0];
  r.contact_force_t = fi.contact_load[1];
  const double cphi = std::cos(s.line_of_centres_angle), sphi = std::sin(s.line_of_centres_angle);
  r.force_x = r.force_n * cphi - r.force_t * sphi;
  r.force_y = r.force_n * sphi + r.force_t * cphi;
  r.load = std::hypot(r.force_n, r.force_t);
  r.attitude_deg = std::atan2(r.force_t, -r.force_n) * kDegreesPerRadian;
  r.friction_torque_journal = R * fi.friction.surface1;
  r.friction_torque_bearing = R * fi.friction.surface2;
  r.friction_power_loss = std::abs(r.friction_torque_journal * (s.omega_journal - s.omega_bearing));
  // The asperity part of surface1 = -mu u couette1 - poiseuille - sgn(u) mu_f int p_c dA.
  r.friction_force_journal = fi.friction.surface1;
  const double mu_f = params.film ? params.film->boundary_friction() : 0.0;
  const double sgn = (params.u_diff > 0) - (params.u_diff < 0);
  r.contact_friction_force_journal = -sgn * mu_f * fi.friction.contact;

  r.moft = fi.moft;
  if (fi.moft_node >= 0) {
    r.moft_theta = theta_[fi.moft_node];
    r.moft_z = m.y[fi.moft_node];
  }
  r.max_pressure = fi.max_pressure;
  if (fi.max_pressure_node >= 0) r.max_pressure_theta = theta_[fi.max_pressure_node];
  r.max_contact_pressure = fi.max_contact_pressure;
  r.cavitated_fraction = fi.CavitatedFraction();

  // Flows through the edges and the feed.
  const int ny = m.ny_nodes();
  for (int k = 0; k < n; ++k) {
    // Outflow through prescribed-pressure nodes is -w (w = nodal residual of the interior rows).
    // The corner nodes of the film-start line are supply nodes: counted as feed (with their
    // upstream Couette inflow below) Q and Q_s become independent of the axial mesh.
    const int j = k / m.nx_nodes();
    const bool edge = j == 0 || (!config_.mesh.symmetric_half && j == ny - 1);
    const bool line = config_.feed.kind == OilFeed::Kind::kLineOfCentres && k % m.nx_nodes() == 0;
    if (edge && !line)
      r.side_flow -= sol.residual[k];
    else if (m.fixed[k] || fem_.extra_fixed()[k])
      r.feed_flow += sol.residual[k];
  }
  r.inlet_flow = r.feed_flow;
  if (config_.feed.kind == OilFeed::Kind::kLineOfCentres) {
    // Couette flow carried onto the film-start line by the upstream film (dual-cell widths). A
    // mass-conserving film carries the fluid fraction of the node upstream (a cavity's partial
    // film) over the face's centred gap, as its transport does; the Reynolds film a full film.
    const bool partial = Transient() && sol.fluid_fraction.size() == n;
    const int nx = m.nx_nodes();
    for (int j = 0; j < ny; ++j) {
      double w = 0.0;
      if (j > 0) w += 0.5 * (m.y_lines[j] - m.y_lines[j - 1]);
      if (j + 1 < ny) w += 0.5 * (m.y_lines[j + 1] - m.y_lines[j]);
      const int start = m.Node(0, j), up = m.Node(params.u_sum >= 0.0 ? nx - 1 : 1, j);
      const double carried = partial ? sol.fluid_fraction[up] * 0.5 * (h[up] + h[start]) : h[start];
      r.inlet_flow += 0.5 * std::abs(params.u_sum) * carried * w;
    }
  }
  r.side_flow *= sym;
  r.feed_flow *= sym;
  r.inlet_flow *= sym;
  r.squeeze_rate = sym * sol.squeeze_rate;
  r.void_volume = sym * sol.void_volume;
  return r;
}

}  // namespace filmdyn::lubrication
