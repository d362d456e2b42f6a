#pragma once
/// @file Lubricated revolute clearance joint (big-end bearing): mesh, film, Reynolds solve and the
/// integrated outputs. Paper §2.2 with the errata for eqs. 17/22 (standard
/// dynamically loaded form, e.g. Hamrock, Schmid & Jacobson, "Fundamentals of Fluid Film
/// Lubrication", 2nd ed., ch. 20; Booker 1965):
///   div(phi h^3/(12 mu) grad p) = (U/2) phi_c dh/dx + (U_rel/2) sigma dphi_s/dx + phi_c dh/dt,
///   x = R theta, U = R (omega_j + omega_b - 2 phi_dot), U_rel = R (omega_j - omega_b),
///   h = c (1 + eps cos theta),  dh/dt = c eps_dot cos theta,
/// theta measured from the maximum film, i.e. from -n where n is the unit vector from the bearing
/// centre to the journal centre (line of centres, angle phi in the global frame), positive
/// counter-clockwise. Default boundary condition: p = 0 on theta = 0 (as the published
/// finite-bearing tables assume; Raimondi & Boyd 1958).
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/lubrication/film_compliance.hpp"
#include "core/lubrication/film_history.hpp"
#include "core/lubrication/film_models.hpp"
#include "core/lubrication/reynolds_fem.hpp"

namespace filmdyn::lubrication {

struct BearingGeometry {
  double radius = 0.0;            ///< journal radius R [m] (R_b ~ R_j, thin film)
  double length = 0.0;            ///< bearing width b = L [m]
  double radial_clearance = 0.0;  ///< c = R_b - R_j [m]
};

struct BearingMeshSpec {
  int n_theta = 50;             ///< elements around the full 360 deg
  int n_z = 10;                 ///< elements across the width (or the half width)
  bool symmetric_half = false;  ///< mesh z in [0, L/2] with dp/dz = 0 at the mid-plane
  /// Circumferential grading: the ratio of the largest to the smallest element, the smallest at
  /// theta = pi (the minimum film of the line-of-centres frame, where the pressure spike sits),
  /// the largest at theta = 0. 1 = uniform. See GradedAngles.
  double theta_grading = 1.0;
  /// Axial grading: the ratio of the largest element (at the mid-plane) to the smallest (at the
  /// edges, where the pressure falls to zero). 1 = uniform. See GradedWidth.
  double z_grading = 1.0;
};

/// The n + 1 node angles in [0, 2 pi] of a circumferential mesh of n elements graded by `ratio`
/// (largest / smallest element, >= 1): theta(s) = 2 pi s + beta sin(2 pi s), s uniform in
/// [0, 1], beta = (ratio - 1) / (ratio + 1) < 1, so that dtheta/ds = 2 pi (1 + beta cos 2 pi s)
/// is smallest at theta = pi and largest at theta = 0, smooth and periodic (neighbouring
/// elements differ by O(1/n)).
std::vector<double> GradedAngles(int n, double ratio);

/// The n + 1 node positions across a width `length` (or its half [0, length/2] when `half`)
/// graded by `ratio` (largest element at the mid-plane / smallest at the edges, >= 1):
/// z(s) = length (s - beta sin(2 pi s) / (2 pi)), s uniform in [0, 1] (or [0, 1/2]),
/// beta = (ratio - 1) / (ratio + 1).
std::vector<double> GradedWidth(int n, double length, double ratio, bool half);

/// The node lines across the width of a bearing mesh of n elements (or of its half): uniform
/// when `ratio` is 1 (Linspace), else GradedWidth. One definition for the solver's mesh and for
/// whoever judges it (a run's warnings).
std::vector<double> WidthLines(int n, double length, double ratio, bool half);

/// Oil supply: where the film is held at the supply pressure (fixed-pressure nodes, a full film
/// there; with mass-conserving cavitation the oil they pass into the film is the supply flow).
///  - kLineOfCentres (default): p = 0 on theta = 0, the film start following the line of
///    centres (the published finite-bearing tables' assumption; no supply hardware).
///  - kShellHoles: round holes through the bearing shell, fixed in the bearing body.
///  - kPinHoles: round holes in the crank pin (journal), turning with it.
///  - kGroove: a groove in the shell of axial width groove_width centred on the mid-width, from
///    groove_start to groove_end (bearing-body angles, counter-clockwise; a whole-circle groove
///    when the span is 2 pi).
///  - kPinHolesAndGroove: both the pin holes and the shell groove, at the one supply pressure
///    (a pin drilling that passes under a partial groove as the crank turns).
/// A hole holds the nodes inside its circle (diameter hole_diameter, centred on the mid-width),
/// at least the node nearest its centre; a groove at least the mid-width row. Between the held
/// nodes and their free neighbours the region's edge lies where it cuts the mesh lines
/// (EmbeddedCut), not at the held nodes.
struct OilFeed {
  using Kind = OilFeedKind;
  Kind kind = Kind::kLineOfCentres;
  std::vector<double> hole_angles = {0.0};  ///< bearing body (shell) or journal (pin) frame [rad]
  double hole_diameter = 4e-3;              ///< [m]
  double groove_start = 0.0, groove_end = 2.0 * 3.14159265358979323846;  ///< [rad]
  double groove_width = 2e-3;                                            ///< axial [m]
  double pressure = 0.0;  ///< supply gauge pressure (>= 0, relative to cavitation) [Pa]
};

/// The field names ValidateOilFeed's messages use (the solver's own configuration or a case file).
struct OilFeedFields {
  std::string hole_angles, hole_diameter, groove_start, groove_end, groove_width;
  std::string width;  ///< the bearing width the hole and groove must fit in
};

/// The supply hardware's own rules, one definition for the solver and the case: holes (shell or
/// pin) need at least one finite angle, a diameter in (0, width) and must not overlap (centres at
/// least one hole diameter apart around the circumference); a groove ends after it starts by at
/// most 2 pi and has an axial width in (0, width). Throws InputError naming the field.
void ValidateOilFeed(const OilFeed& feed, double radius, double width, const OilFeedFields& names);

struct BearingConfig {
  BearingGeometry geometry;
  double viscosity = 0.0;                ///< at zero gauge pressure [Pa s]
  PressureViscosity pressure_viscosity;  ///< how it rises with the film pressure (oil.hpp)
  CrossLaw shear_thinning;               ///< how it falls with the film's shear rate (oil.hpp)
  /// Bulk modulus [Pa] of a compressible oil in a transient mass-conserving film
  /// (ReynoldsParams::bulk_modulus); 0 = incompressible.
  double bulk_modulus = 0.0;
  DensityLaw density_law = DensityLaw::kLinear;  ///< ReynoldsParams::density_law
  BearingMeshSpec mesh;
  OilFeed feed;
  ReynoldsOptions solver;
  /// Roughness factors (Patir-Cheng / Wu-Zheng / Greenwood-Tripp); nullptr = smooth surfaces.
  /// Surface 1 = journal, surface 2 = bearing.
  std::shared_ptr<const FilmFactorModel> film;
  /// Elastic surfaces (film_compliance.hpp): the bearing lining for the elastic layer; surface 1
  /// = journal, 2 = bearing for the half-space. Rigid by default.
  ComplianceSpec compliance;
  /// Throws filmdyn::InputError naming the field (prefix e.g. "bearing").
  void Validate(const std::string& prefix = "bearing") const;
};

/// Kinematic state of the joint at one instant (all SI, angles in the global frame).
struct BearingState {
  double eps = 0.0;                    ///< eccentricity ratio e/c, in [0, 1)
  double eps_dot = 0.0;                ///< [1/s]
  double line_of_centres_angle = 0.0;  ///< phi: angle of n (bearing centre -> journal) [rad]
  double line_of_centres_rate = 0.0;   ///< phi_dot [rad/s]
  double omega_journal = 0.0;          ///< [rad/s]
  double omega_bearing = 0.0;          ///< [rad/s]
  double bearing_angle = 0.0;          ///< orientation of the bearing body (shell feed) [rad]
  double journal_angle = 0.0;          ///< orientation of the journal body (pin holes) [rad]
  /// The supply pressure at this instant when it varies (a curve over crank angle) [Pa];
  /// none: OilFeed::pressure.
  std::optional<double> supply_pressure;
  /// eps must lie in [0, eps_limit): 1 for rigid surfaces (BearingSolver: kElasticEpsLimit for
  /// elastic ones).
  void Validate(const std::string& prefix = "bearing_state", double eps_limit = 1.0) const;
};

/// Integrated outputs of one solve. Forces act ON THE JOURNAL from the film (hydrodynamic +
/// asperity); "n" along the line of centres (towards the journal centre), "t" = n rotated +90 deg.
struct BearingResult {
  ReynoldsStats stats;
  double force_n = 0.0, force_t = 0.0;                  ///< [N] line-of-centres frame
  double force_x = 0.0, force_y = 0.0;                  ///< [N] global frame
  double contact_force_n = 0.0, contact_force_t = 0.0;  ///< asperity part [N]
  double load = 0.0;                                    ///< |F| [N]
  double attitude_deg = 0.0;  ///< angle from the load line (-F) to the line of centres [deg]
  double friction_torque_journal = 0.0;   ///< torque on the journal about its centre [N m]
  double friction_torque_bearing = 0.0;   ///< torque on the bearing about its centre [N m]
  double friction_power_loss = 0.0;       ///< |T_journal (omega_j - omega_b)| [W]
  /// Friction force on the journal surface along +theta: T_journal / R [N], and its asperity
  /// (boundary-friction, mu_f p_c) part [N]; the rest is the hydrodynamic shear.
  double friction_force_journal = 0.0;
  double contact_friction_force_journal = 0.0;
  double moft = 0.0;                      ///< minimum film thickness [m]
  double moft_theta = 0.0, moft_z = 0.0;  ///< where (theta from max film [rad], z from edge [m])
  double max_pressure = 0.0, max_pressure_theta = 0.0;  ///< [Pa], [rad]
  double max_contact_pressure = 0.0;                    ///< [Pa]
  double cavitated_fraction = 0.0;                      ///< cavitated share of the film area [-]
  double side_flow = 0.0;                               ///< leakage through both edges [m^3/s]
  double feed_flow = 0.0;  ///< net supply of the prescribed-pressure nodes (not edges) [m^3/s]
  /// Flow entering the pressure film [m^3/s] (Raimondi-Boyd's Q): feed hole/groove: feed_flow;
  /// default film start: feed_flow + the Couette flow (U/2) h arriving at theta = 0 from the
  /// (cavitated) upstream side.
  double inlet_flow = 0.0;
  /// The oil balance's storage terms (ReynoldsSolution): feed_flow - side_flow = squeeze_rate -
  /// d(void_volume)/dt in a transient JFO solve [m^3/s], [m^3].
  double squeeze_rate = 0.0;
  double void_volume = 0.0;
  /// Elastic surfaces: the largest deformation (film opening) [m] and the coupled solve's
  /// statistics (rigid: zero, one film solve).
  double max_deformation = 0.0;
  ElasticSolveStats elastic;
};

/// The film surface over the whole width, for output and display: the solver's own mesh, or —
/// when it solves the symmetric half — the half and its mirror image about the mid-plane.
struct FullWidthSurface {
  TriMesh mesh;             ///< x = R theta (periodic), y = z from the edge z = 0 to the width
  std::vector<int> source;  ///< per node of `mesh`: the solver node whose values it shows
};

/// Construct once per bearing (mesh + symbolic factorisation), then Solve() per time step.
class BearingSolver {
 public:
  /// Elastic surfaces: the largest eccentricity ratio solved (the rigid film then closes over
  /// part of the circumference, the deformation must open it).
  static constexpr double kElasticEpsLimit = 2.0;
  explicit BearingSolver(BearingConfig config);
  /// Quasi-static solve (the steady calculator; JFO without history).
  const BearingResult& Solve(const BearingState& state);
  /// A solve at time t of a time integration. With JFO cavitation the film steps from the
  /// history's latest accepted state before t (FilmHistory); the first solve, with no history
  /// yet, starts the history with a flooded film (no void anywhere) just before t and steps
  /// from it. Other models: Solve(state).
  const BearingResult& SolveAt(const BearingState& state, double t);
  /// The last solve (SolveAt at t) is the film of an accepted step at t: recorded in history().
  void AcceptStep(double t);
  const FilmHistory& history() const { return history_; }
  /// True when solves depend on the history (JFO cavitation).
  bool Transient() const { return config_.solver.cavitation == CavitationModel::kJfo; }
  const BearingResult& result() const { return result_; }
  /// Fields of the last solve (pressure, contact pressure, fluid fraction per node).
  const ReynoldsSolution& fields() const { return fem_.solution(); }
  /// The film of the last solve (deformed when the surfaces are elastic) [m].
  const Eigen::VectorXd& film_thickness() const { return fem_.film_thickness(); }
  /// The surfaces' deformation of the last solve per node [m] (zero when rigid).
  const Eigen::VectorXd& deformation() const { return elastic_.deformation(); }
  const TriMesh& mesh() const { return fem_.mesh(); }
  const ReynoldsFem& fem() const { return fem_; }
  ReynoldsFem& fem() { return fem_; }
  const BearingConfig& config() const { return config_; }
  /// Replaces the configuration's pressure-viscosity law (an engine run phases it in).
  void SetPressureViscosity(PressureViscosity law) { config_.pressure_viscosity = std::move(law); }
  /// The share of the surfaces' compliance applied, in [0, 1] (an engine run phases it in).
  void SetComplianceScale(double share) { elastic_.SetScale(share); }
  /// The whole width of the film (the mesh itself unless the symmetric half is solved).
  const FullWidthSurface& full_width() const { return full_width_; }

  /// Mesh of the bearing: x = R theta in [0, 2 pi R) (periodic), y = z from one edge.
  static TriMesh MakeMesh(const BearingGeometry& g, const BearingMeshSpec& spec, bool fix_theta0);

 private:
  const BearingResult& SolveStep(const BearingState& state, double time_step);
  /// Holds the supply's nodes at the supply pressure (extra fixed nodes of this solve).
  void MarkSupplyNodes(const BearingState& state);
  // The film's inputs for the deformation's predictor (ElasticFilm::Solve).
  Eigen::VectorXd PredictorInputs(const BearingState& state) const;

  BearingConfig config_;
  ReynoldsFem fem_;
  ElasticFilm elastic_;
  std::vector<double> theta_;
  BearingResult result_;
  Eigen::VectorXd cos_, sin_;  // load directions of the film integrals
  FullWidthSurface full_width_;
  FilmHistory history_;
};

}  // namespace filmdyn::lubrication
