#pragma once
/// @file Lubricated piston skirt - liner joint (translational clearance joint). Paper
/// §2.1 (eqs. 1-6). Domain alpha in [0, pi] (symmetry about the pin-axis plane), y in [0, L] from
/// the skirt top; thrust panel Omega1 = [0, alpha1], pin-boss relief Omega2 = [alpha1, pi-alpha2]
/// with p = 0 (nodes on its edges included, paper eq. 6), anti-thrust panel Omega3.
///
/// Film (our sign convention of the paper's eq. 2):
///   h(alpha, y) = c + h_profile(y) + h_ovality(alpha) - [e0 + (y - a_p) gamma] cos(alpha),
/// i.e. e0 > 0 moves the piston towards the thrust side (alpha = 0) and gamma > 0 moves the skirt
/// points below the pin (y > a_p) towards the thrust side. dh/dt follows (paper eq. 3).
/// Reynolds equation in the piston frame (liner = surface 2 moving at -u_p along y; skirt =
/// surface 1 at rest): U_sum = -u_p, U_diff = +u_p, i.e. the paper's eq. 1.
#include <memory>
#include <string>
#include <utility>

#include "core/base/worker_pool.hpp"
#include "core/lubrication/film_compliance.hpp"
#include "core/lubrication/film_history.hpp"
#include "core/lubrication/profile_table.hpp"
#include "core/lubrication/reynolds_fem.hpp"

namespace filmdyn::lubrication {

struct SkirtGeometry {
  double radius = 0.0;            ///< piston (liner) radius R [m]
  double skirt_length = 0.0;      ///< L_skirt [m]
  double radial_clearance = 0.0;  ///< c_p [m]
  double pin_position = 0.0;      ///< a_p: pin axis below the skirt top [m]
  double alpha1 = 0.0;            ///< half-width of the thrust panel [rad]
  double alpha2 = 0.0;            ///< half-width of the anti-thrust panel [rad]
  Table1D profile;  ///< axial profile: y from skirt top [m] -> extra radial gap [m] (barrel)
  Table1D ovality;  ///< optional: alpha [rad] -> extra radial gap [m]
};

struct SkirtMeshSpec {
  int n_thrust = 30;  ///< elements over Omega1 (circumferential)
  int n_relief = 2;   ///< elements over Omega2
  int n_anti = 30;    ///< elements over Omega3
  int n_axial = 40;   ///< elements over the skirt length
};

struct SkirtConfig {
  SkirtGeometry geometry;
  double viscosity = 0.0;                ///< at zero gauge pressure [Pa s]
  PressureViscosity pressure_viscosity;  ///< how it rises with the film pressure (oil.hpp)
  CrossLaw shear_thinning;               ///< how it falls with the film's shear rate (oil.hpp)
  /// Bulk modulus [Pa] of a compressible oil in a transient mass-conserving film
  /// (ReynoldsParams::bulk_modulus); 0 = incompressible.
  double bulk_modulus = 0.0;
  DensityLaw density_law = DensityLaw::kLinear;  ///< ReynoldsParams::density_law
  SkirtMeshSpec mesh;
  ReynoldsOptions solver{.cold_start = ReynoldsOptions::ColdStart::kUnconstrained};
  /// Roughness factors; nullptr = smooth. Surface 1 = skirt, surface 2 = liner.
  std::shared_ptr<const FilmFactorModel> film;
  /// Films thinner than this are clamped (reported in the result) so the solve never fails on
  /// a penetrating state proposed by an integrator [m].
  double min_film = 1e-9;
  /// Oil supply. Starved (mass-conserving cavitation only): the liner carries an oil layer of
  /// thickness h_oil at its own speed into the skirt's leading edge (the lower edge while the
  /// piston moves toward the crank, the upper one on the way back). Its flow |u_p| h_oil enters
  /// as a partial film that moves at the mean surface speed |u_p|/2, i.e. with the film
  /// content theta h_T = 2 h_oil (full when h_oil >= h_T/2; h_T the mean gap, h for smooth
  /// surfaces and from H = 3 on: NodalFilmFactors::mean_gap_excess). h_oil is `oil_film`, or the
  /// table `oil_film_table` over the liner position of that edge (from the skirt top's position at
  /// top dead centre, + toward the crank).
  SkirtSupply supply = SkirtSupply::kFlooded;
  double oil_film = 0.0;   ///< [m]
  Table1D oil_film_table;  ///< liner position [m] -> h_oil [m]; empty = oil_film
  /// Elastic surfaces (film_compliance.hpp): the skirt's surface layer for the elastic layer;
  /// surface 1 = skirt, 2 = liner for the half-space (each panel with its mirror image, the
  /// panels apart: the relief between them carries no film). Rigid by default.
  ComplianceSpec compliance;
  void Validate(const std::string& prefix = "skirt") const;
};

/// Secondary-motion state of the piston at one instant.
struct SkirtState {
  double e0 = 0.0, gamma = 0.0;          ///< lateral displacement [m], tilt [rad]
  double e0_dot = 0.0, gamma_dot = 0.0;  ///< [m/s], [rad/s]
  double piston_velocity = 0.0;          ///< u_p along +y (towards the crank) [m/s]
  /// The skirt top's displacement from its top-dead-centre position, + toward the crank [m]
  /// (where the leading edge meets the liner's oil film, SkirtConfig::oil_film_table).
  double stroke_position = 0.0;
  void Validate(const std::string& prefix = "skirt_state") const;
};

/// Outputs of one solve: both halves of the skirt (x2 of the solved half domain). Forces act ON
/// THE PISTON; lateral = along +e0 (towards the thrust side); moments are the generalised forces
/// conjugate to gamma (virtual work), about the pin axis.
struct SkirtResult {
  ReynoldsStats stats;
  double lateral_force = 0.0;              ///< hydrodynamic + asperity [N]
  double contact_lateral_force = 0.0;      ///< asperity part [N]
  double moment_about_pin = 0.0;           ///< normal pressure + friction parts [N m]
  double friction_moment_about_pin = 0.0;  ///< friction part [N m]
  double friction_force = 0.0;             ///< along +y (opposes u_p) [N]
  double contact_friction_force = 0.0;     ///< asperity part [N]
  double friction_power_loss = 0.0;        ///< |F_f u_p| [W]
  double moft = 0.0;                       ///< over the lubricated panels [m]
  double moft_alpha = 0.0, moft_y = 0.0;   ///< where [rad], [m]
  double max_pressure = 0.0, max_contact_pressure = 0.0;  ///< [Pa]
  double cavitated_fraction = 0.0;                        ///< of the panel area [-]
  int clamped_nodes = 0;                                  ///< nodes where h < min_film was clamped
  /// Oil through the panels' boundaries (skirt edges and relief edges), both halves: what
  /// enters at the nodes with a net inflow and leaves at those with a net outflow [m^3/s].
  double inflow = 0.0, outflow = 0.0;
  /// Oil-covered share of the panels' area: the mean fluid fraction (JFO), the uncavitated
  /// share (Reynolds) [-].
  double wetted_fraction = 1.0;
  /// The oil balance's storage terms (as BearingResult), both halves [m^3/s], [m^3].
  double squeeze_rate = 0.0, void_volume = 0.0;
  /// Elastic surfaces: the largest film opening [m] and the panels' coupled solves (merged:
  /// counts add, the worst residual, the first failure's message).
  double max_deformation = 0.0;
  ElasticSolveStats elastic;
};

/// Smallest geometric film (before any clamping) over the lubricated panels, and where.
struct SkirtGap {
  double gap = 0.0;    ///< [m]; <= 0: the skirt is in the liner there
  double alpha = 0.0;  ///< [rad] from the thrust side
  double y = 0.0;      ///< [m] from the skirt top
};

/// Construct once per skirt (mesh + symbolic factorisation), then Solve() per time step.
///
/// The pin-boss relief Omega2 (p = 0, no film) separates the thrust panel Omega1 and the
/// anti-thrust panel Omega3 completely: their Reynolds problems share no unknown. Each panel is
/// therefore its own ReynoldsFem (two half-size factorisations instead of one, each with its own
/// active set and factor reuse), and with SetThreads(2) the two are solved side by side. The
/// results do not depend on the thread count (each panel's partial integrals are summed in panel
/// order). fields(), film_thickness() and mesh() describe the whole skirt (relief included, with
/// p = p_c = 0 there).
class SkirtSolver {
 public:
  explicit SkirtSolver(SkirtConfig config);
  ~SkirtSolver();
  /// Quasi-static solve (the skirt calculator; JFO without history).
  const SkirtResult& Solve(const SkirtState& state);
  /// A solve at time t of a time integration; with JFO cavitation it steps from the history's
  /// latest accepted state before t (as BearingSolver::SolveAt).
  const SkirtResult& SolveAt(const SkirtState& state, double t);
  /// The last solve (SolveAt at t) is the film of an accepted step at t: recorded in history().
  void AcceptStep(double t);
  const FilmHistory& history() const { return history_; }
  bool Transient() const { return config_.solver.cavitation == CavitationModel::kJfo; }
  const SkirtResult& result() const { return result_; }
  /// Whole-skirt fields of the last solve (gathered from the panels on the first call after it).
  const ReynoldsSolution& fields() const;
  /// The film (deformed with elastic surfaces) [m].
  const Eigen::VectorXd& film_thickness() const;
  /// The surfaces' deformation per node [m] (zero on the relief and with rigid surfaces).
  const Eigen::VectorXd& deformation() const;
  /// The share of the surfaces' compliance applied, in [0, 1] (an engine run phases it in).
  void SetComplianceScale(double share);
  const TriMesh& mesh() const { return mesh_; }
  const SkirtConfig& config() const { return config_; }
  /// Replaces the configuration's pressure-viscosity law (an engine run phases it in).
  void SetPressureViscosity(PressureViscosity law) { config_.pressure_viscosity = std::move(law); }
  /// alpha [rad] of each node (x = R alpha).
  const std::vector<double>& alpha() const { return alpha_; }
  /// The smallest rigid gap over the panels' nodes at this lateral position and tilt, and
  /// where (the film SolveAt would start from, before it is held at min_film).
  SkirtGap MinRigidGap(double e0, double gamma) const;
  /// The rigid gap at node k (paper eq. 2, our sign): static_gap - (e0 + arm gamma) cos(alpha)
  /// [m].
  double RigidGap(int k, double e0, double gamma) const {
    return h_static_[k] - (e0 + arm_[k] * gamma) * cos_[k];
  }
  /// Per node: the gap of the centred skirt (clearance, profile, ovality) [m], the arm y - a_p
  /// from the pin [m], cos(alpha).
  const Eigen::VectorXd& static_gap() const { return h_static_; }
  const Eigen::VectorXd& arm() const { return arm_; }
  const Eigen::VectorXd& cos_alpha() const { return cos_; }
  /// 1 (default): the panels one after the other; 2: side by side.
  void SetThreads(int threads);
  /// The stop check of both panels' solves (ReynoldsFem::SetStopCheck).
  void SetStopCheck(const StopCheck& check);

  /// The lubricated panels: 0 = thrust (Omega1), 1 = anti-thrust (Omega3).
  static constexpr int kPanels = 2;
  const ReynoldsFem& panel(int k) const;
  /// Whole-skirt node of each node of panel k.
  const std::vector<int>& panel_nodes(int k) const;

  static TriMesh MakeMesh(const SkirtGeometry& g, const SkirtMeshSpec& spec);

 private:
  struct Panel;
  void SolvePanel(Panel& panel, const SkirtState& s, double time_step);
  const SkirtResult& SolveStep(const SkirtState& state, double time_step);
  std::vector<Eigen::VectorXd> VoidContent() const;

  SkirtConfig config_;
  TriMesh mesh_;
  std::vector<double> alpha_;
  Eigen::VectorXd h_, hdot_, cos_, h_static_, arm_;
  std::vector<std::unique_ptr<Panel>> panels_;
  std::unique_ptr<WorkerPool> pool_;
  mutable ReynoldsSolution fields_;  // a cache of the panels' fields, see fields()
  mutable Eigen::VectorXd film_, deformation_;  // the same for the film and the deformation
  mutable bool fields_stale_ = false;
  SkirtResult result_;
  FilmHistory history_;
};

}  // namespace filmdyn::lubrication
