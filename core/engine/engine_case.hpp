#pragma once
/// @file The case: every constant input of a run (Table I of Zhao & Shen plus what the paper does
/// not give), SI units. Plain structs with defaults; the one mapping to and from JSON is
/// core/io/case_file.cpp (VisitCase). Field meanings, units, ranges, sources: docs/case-file.md.
#include <map>
#include <string>
#include <vector>

#include "core/lubrication/film_models.hpp"
#include "core/lubrication/oil.hpp"

namespace filmdyn::engine {

/// How a joint is modelled: ideal (kinematic constraint) or lubricated (film force element).
enum class JointModel { kIdeal, kLubricated };

/// Crank, connecting rod and piston (Table I; layout in docs/outputs.md).
struct CrankTrainGeometry {
  double crank_radius = 39.93e-3;          ///< L_1 [m]
  double rod_length = 129.5e-3;            ///< L_2, big-end to small-end centre [m]
  double crank_com_radius = 20.0e-3;       ///< L_r, main journal to crank CoM [m]
  double crank_mass = 2.0;                 ///< [kg] (assumed; speed is imposed)
  double crank_inertia = 3.0e-3;           ///< about its CoM [kg·m²] (assumed)
  double rod_com_from_big_end = 28.49e-3;  ///< L_c [m]
  double rod_mass = 0.345;                 ///< m_2 [kg]
  double rod_inertia = 9.67e-4;            ///< J_2 about its CoM [kg·m²]
  double piston_mass = 0.264;              ///< m_3 [kg]
  double piston_inertia = 1.29e-4;         ///< J_3 about its CoM [kg·m²]
  double pin_offset = 0.7e-3;  ///< C_p, pin axis from bore axis, + toward thrust side [m]
  double piston_com_lateral_offset = 0.13e-3;  ///< c_g, CoM from bore axis, + toward thrust [m]
  double skirt_top_to_pin = 11.8e-3;           ///< a_p, + toward the crank [m]
  double skirt_top_to_com = -1.737e-3;         ///< b_p, + toward the crank [m]
  double liner_radius = 36.50e-3;              ///< R_l, bore radius; gas force area π R_l² [m]
  double compression_ratio = 10.5;  ///< for the synthetic pressure model only [-] (assumed)
  double gravity = 9.81;            ///< [m/s²], along −Y (cylinder axis vertical, head up)
};

/// Which oil a joint's film carries: the case's (`lubricant.*`) or its own.
enum class OilSource { kLubricant, kOwn };

/// How a joint's film temperature is set: given, or from its heat balance (RunJob iterates the
/// run until share × friction power = ρ c_p Q (T − T_supply), Q the oil leaving the film).
enum class FilmTemperature { kGiven, kHeatBalance };

/// A joint's oil and film temperature.
struct JointOil {
  OilSource source = OilSource::kLubricant;
  lubrication::OilSpec own;
  /// Film temperature [K]: where the viscosity follows temperature (Vogel), the film's; with the
  /// heat balance the start of its iteration.
  double temperature = 373.15;
  FilmTemperature temperature_mode = FilmTemperature::kGiven;
  /// Heat balance: the share of the joint's friction power carried away by its oil flow [-].
  double heat_share = 1.0;
};

/// The piston skirt–liner joint (Table I); the film data are used when the skirt is lubricated.
struct SkirtCase {
  JointModel model = JointModel::kIdeal;
  /// Cold radial clearance between skirt and liner at the skirt's largest diameter (where the
  /// barrel profile is zero), as machined at room temperature [m]. The one input of the skirt's
  /// size: the piston radius is derived from it (PistonRadius). Table I: R_l − R = 25 µm.
  double cold_clearance = 25.0e-6;
  double length = 28.0e-3;                         ///< L_skirt [m]
  double thrust_half_width = 0.802851455917;       ///< α_1 [rad] (46°)
  double anti_thrust_half_width = 0.802851455917;  ///< α_2 [rad] (46°)
  double roughness_skirt = 0.615e-6;               ///< σ_skirt [m]
  double roughness_liner = 0.815e-6;               ///< σ_liner [m]
  double peklenik = 1.0;                           ///< γ of the composite surface [-] (assumed)
  /// Elastic constants per surface; the contact model uses E' = 2/[(1−ν₁²)/E₁ + (1−ν₂²)/E₂]
  /// (Hu et al. 1994): 98.24 GPa for these defaults (assumed: Al-Si on cast iron).
  double modulus_skirt = 75.0e9;    ///< E of the piston skirt [Pa] (assumed: Al-Si alloy)
  double poisson_skirt = 0.33;      ///< ν of the piston skirt [-] (assumed)
  double modulus_liner = 110.0e9;   ///< E of the liner [Pa] (assumed: grey cast iron)
  double poisson_liner = 0.26;      ///< ν of the liner [-] (assumed)
  /// Elastic surfaces (lubrication::ComplianceSpec): rigid (the paper's), the skirt's surface as
  /// an elastic layer of layer_thickness on a rigid body (E_skirt, ν_skirt), skirt and liner
  /// as elastic half-spaces (E_skirt, ν_skirt, E_liner, ν_liner), or imported from an FE model.
  lubrication::ComplianceModel compliance = lubrication::ComplianceModel::kRigid;
  double layer_thickness = 1.0e-3;  ///< elastic layer thickness [m] (assumed: a skirt wall)
  /// Imported compliance: the Matrix Market file (its nodes in the same name with .nodes.csv),
  /// relative to the case file's folder (docs/compliance-files.md); the nodes' alpha from the
  /// thrust axis, y from the skirt top.
  std::string compliance_file;
  double boundary_friction = 0.13;  ///< μ_f [-]
  /// Barrel profile h_skirt(y): axial positions from the skirt top [m] and radial drop [m].
  std::vector<double> profile_y = {0.0, 7.0e-3, 14.0e-3, 21.0e-3, 28.0e-3};
  std::vector<double> profile_h = {20.0e-6, 5.0e-6, 0.0, 5.0e-6, 20.0e-6};
  /// Ovality h_ovality(α): angles from the thrust axis [rad] in [0, π] and extra radial gap [m];
  /// both empty = a round skirt (the default; the paper gives no ovality).
  std::vector<double> ovality_alpha;
  std::vector<double> ovality_h;
  /// FEM mesh: elements over Ω1, Ω2, Ω3 (circumferential) and axially. Default: half the
  /// paper's Table II counts (30, 2, 30, 40): min skirt MOFT within 0.5 % at 6000 rpm, 1.6 % low
  /// at 2000 and 3.3 % at 1000 rpm (docs/validation/errors.md).
  int mesh_thrust = 15, mesh_relief = 2, mesh_anti = 15, mesh_axial = 20;
  /// Film rupture and reformation: Reynolds (Swift–Stieber, the paper's) or mass-conserving JFO.
  lubrication::CavitationModel cavitation = lubrication::CavitationModel::kReynolds;
  /// Oil supply (lubrication::SkirtConfig): fully flooded (the paper's) or starved, fed by the
  /// oil film the ring pack leaves on the liner: a constant thickness, or a table over the liner
  /// position (from the skirt top's position at top dead centre, + toward the crank).
  lubrication::SkirtSupply supply = lubrication::SkirtSupply::kFlooded;
  double oil_film = 5.0e-6;  ///< [m] (assumed: a few µm below the ring pack)
  std::vector<double> oil_film_positions, oil_film_values;  ///< [m], [m]; empty = oil_film
  JointOil oil;                                             ///< the film's oil and temperature
  /// Running temperatures of the piston skirt and the liner [K] and their linear expansion
  /// coefficients [1/K]: the hot radii R (1 + α (T − 293.15 K)) give the running clearance
  /// (SkirtFit). At 293.15 K (the default) the cold dimensions are the running ones.
  double piston_temperature = 293.15, liner_temperature = 293.15;
  double piston_expansion = 21.0e-6;  ///< (assumed: an Al–Si piston alloy)
  double liner_expansion = 11.0e-6;   ///< (assumed: grey cast iron)
};

/// The connecting-rod big-end bearing (Table I); the film data are used when the big end is
/// lubricated.
struct BigEndCase {
  JointModel model = JointModel::kIdeal;
  double bearing_radius = 15.00e-3;     ///< R_b [m]
  double journal_radius = 14.95e-3;     ///< R_j [m]; R_b − R_j is the radial clearance
  double width = 22.0e-3;               ///< b [m]
  double roughness_journal = 0.308e-6;  ///< σ_journal [m]
  double roughness_bearing = 0.408e-6;  ///< σ_bearing [m]
  double peklenik = 1.0;                ///< [-] (assumed)
  /// Elastic constants per surface (E' as for the skirt): 117.21 GPa for these defaults
  /// (assumed: steel journal in an Al-Sn lining).
  double modulus_journal = 210.0e9;  ///< E of the crank-pin journal [Pa] (assumed: steel)
  double poisson_journal = 0.30;     ///< ν of the journal [-] (assumed)
  double modulus_bearing = 70.0e9;   ///< E of the bearing lining [Pa] (assumed: Al-Sn alloy)
  double poisson_bearing = 0.33;     ///< ν of the bearing lining [-] (assumed)
  /// Elastic surfaces (lubrication::ComplianceSpec): rigid (the paper's), the bearing lining as
  /// an elastic layer of layer_thickness on a rigid backing (E_b, ν_b), or journal and bearing as
  /// elastic half-spaces (E_j, ν_j, E_b, ν_b).
  lubrication::ComplianceModel compliance = lubrication::ComplianceModel::kRigid;
  double layer_thickness = 0.3e-3;   ///< lining thickness [m] (assumed: a typical lining)
  /// Imported compliance: the Matrix Market file (its nodes in the same name with .nodes.csv),
  /// relative to the case file's folder (docs/compliance-files.md); the nodes' psi from the rod
  /// axis toward the small end, counter-clockwise.
  std::string compliance_file;
  double boundary_friction = 0.13;   ///< μ_f [-]
  /// Oil supply (lubrication::OilFeed): the film start at the line of centres (the paper's, no
  /// supply hardware), holes in the shell (fixed in the rod) or in the crank pin (turning with
  /// the crank), or a groove in the shell.
  lubrication::OilFeedKind supply = lubrication::OilFeedKind::kLineOfCentres;
  double oil_feed_pressure = 0.0;  ///< supply gauge pressure [Pa] (assumed: none given)
  /// Supply pressure over the cycle: crank angles [rad] in [0, 4π) and gauge pressures [Pa];
  /// both empty = the constant oil_feed_pressure.
  std::vector<double> supply_pressure_angles, supply_pressure_values;
  /// Holes: their angles [rad] — shell holes from the rod axis toward the small end, pin holes
  /// from the crank web's axis toward the pin — counter-clockwise, and their diameter [m].
  std::vector<double> supply_hole_angles = {0.0};  ///< one hole on the rod axis (assumed)
  double supply_hole_diameter = 4.0e-3;            ///< (assumed: a common feed-drilling size)
  /// Groove: from start to end angle [rad] in the rod frame (a whole circle: 0 to 2π), axial
  /// width [m] centred on the bearing's mid-width.
  double groove_start_angle = 0.0, groove_end_angle = 6.283185307179586;
  double groove_width = 2.0e-3;  ///< (assumed)
  /// FEM mesh: elements around 360° and across the width. Default 100 x 10 graded 8:1 around
  /// and 4:1 across (the paper's Table II: 50 x 10 uniform, ~20 % low on the minimum film at
  /// eps ~ 0.97; docs/validation/errors.md).
  int mesh_theta = 100, mesh_z = 10;
  /// Largest / smallest circumferential element, finest at the minimum film (1 = uniform) [-].
  double mesh_theta_grading = 8.0;
  /// Largest (mid-plane) / smallest (edges) axial element (1 = uniform) [-].
  double mesh_z_grading = 4.0;
  /// Film rupture and reformation: Reynolds (Swift–Stieber, the paper's) or mass-conserving JFO.
  lubrication::CavitationModel cavitation = lubrication::CavitationModel::kReynolds;
  JointOil oil;  ///< the film's oil and temperature
  /// Running temperatures of the crank-pin journal and the bearing (rod eye and shell) [K] and
  /// their expansion coefficients [1/K] (BigEndFit); 293.15 K: the cold dimensions.
  double journal_temperature = 293.15, bearing_temperature = 293.15;
  double journal_expansion = 12.0e-6;  ///< (assumed: steel)
  double bearing_expansion = 12.0e-6;  ///< (assumed: a steel rod and steel-backed shell)
};

/// One cylinder-pressure curve: absolute pressure vs crank angle at one speed.
struct PressureCurveSource {
  double rpm = 0.0;                     ///< crank speed the curve belongs to [rpm]
  std::string file;                     ///< CSV path relative to the case file, or empty
  std::vector<double> crank_angle_deg;  ///< inline table [°CA] (when file is empty)
  std::vector<double> pressure;         ///< inline table, absolute [Pa]
};

struct OperatingCase {
  double rpm = 6000.0;                ///< crank speed [rpm]
  double crankcase_pressure = 1.0e5;  ///< absolute [Pa]
  double start_crank_angle = 0.0;     ///< [rad]
};

struct SolverCase {
  double baumgarte_alpha = 1.0e4;                 ///< 𝒢 of eq. 39 [1/s] (Table II)
  double baumgarte_beta = 1.0e4;                  ///< ζ of eq. 39 [1/s] (Table II)
  double relative_tolerance = 1.0e-7;             ///< BDF local error, relative [-]
  double position_tolerance = 1.0e-10;            ///< absolute [m]
  double output_interval = 0.017453292519943295;  ///< [rad of crank] (1 °CA)
  double steady_state_tolerance = 0.01;           ///< cycle-to-cycle change / range [-]
  int max_cycles = 30;                            ///< [-]
  /// Integrated before the first monitored cycle so that the start-up transient of the films
  /// (journal and piston start centred and at rest) has decayed [rad of crank]; default 360 °CA.
  /// Film models only (the Ideal model has no start-up transient).
  double run_in_angle = 6.283185307179586;
  /// The run-in instead of run_in_angle when a lubricated film conserves mass (JFO): its film
  /// starts flooded and its oil content drains over about two cycles, which the run-in's looser
  /// tolerances compute for less than monitored cycles would [rad of crank]; default 1440 °CA.
  double jfo_run_in_angle = 25.132741228718345;
  /// 1: a coarse companion run (meshes with half the elements, same tolerances) estimates the
  /// discretisation error of the headline figures (core/engine/error_estimate.hpp); 0: off.
  int error_estimate = 1;
};

/// The case's oil (lubrication::OilSpec: viscosity model and pressure law; Table I: a constant
/// 0.02 Pa·s), used by both joints unless a joint has its own.
struct LubricantCase : lubrication::OilSpec {
  double greenwood_tripp_k = 1.198e-4;  ///< K of eq. 29 [-]
  /// The joints' heat balances: oil supply temperature [K], density [kg/m³] and specific heat
  /// [J/(kg·K)] of the oil.
  double supply_temperature = 363.15;  ///< (assumed: 90 °C)
  double density = 860.0;  ///< (assumed: engine oils' data sheets give 840–880 kg/m³ at 15 °C)
  double heat_capacity = 2000.0;  ///< (assumed: mineral oils about 1.9–2.1 kJ/(kg·K))
};

struct EngineCase {
  std::string name = "zhao-shen-gasoline";
  std::string description;
  CrankTrainGeometry geometry;
  SkirtCase skirt;
  BigEndCase big_end;
  LubricantCase lubricant;
  OperatingCase operating;
  std::vector<PressureCurveSource> pressure_curves;
  SolverCase solver;
  /// Dotted path → reason, for every value the paper does not give (docs/case-file.md).
  std::map<std::string, std::string> assumed;
};

/// The piston (skirt) radius at its largest diameter, cold: R = R_l − c [m], from the liner radius
/// and the cold skirt clearance (skirt.cold_clearance) — the one place it is derived. For the
/// default case 36.50 mm − 25 µm reproduces Table I's 36.475 mm to the last bit.
inline double PistonRadius(const EngineCase& engine_case) {
  return engine_case.geometry.liner_radius - engine_case.skirt.cold_clearance;
}

/// The cold radial skirt clearance as the film model uses it: R_l − PistonRadius [m], i.e.
/// skirt.cold_clearance rounded so that radius + clearance = liner radius exactly in floating
/// point (both are exact differences of nearby numbers). This keeps the film's geometry
/// consistent and runs bit for bit identical to those of cases that gave the piston radius
/// (25 µm in the file is 2.4999999999997e-5 here, as R_l − R always was). Every use of the
/// clearance (film, steady-state scales, later thermal expansion) starts from here.
inline double SkirtClearance(const EngineCase& engine_case) {
  return engine_case.geometry.liner_radius - PistonRadius(engine_case);
}

/// Temperature of the cold dimensions [K] (20 °C).
inline constexpr double kReferenceTemperature = 293.15;

/// A radius at its running temperature: R (1 + α (T − 293.15 K)) [m]; the cold radius itself at
/// 293.15 K, bit for bit.
inline double HotRadius(double cold_radius, double expansion, double temperature) {
  return cold_radius * (1.0 + expansion * (temperature - kReferenceTemperature));
}

/// A joint's fit at its running temperatures: the outer (bore, bearing) and inner (piston,
/// journal) radii and the radial clearance between them, cold and hot [m].
struct JointFit {
  double outer_radius = 0.0, inner_radius = 0.0;  ///< hot
  double cold_clearance = 0.0, hot_clearance = 0.0;
};
/// The skirt's: liner bore and piston at their temperatures (the clearance at 293.15 K is
/// SkirtClearance, bit for bit).
inline JointFit SkirtFit(const EngineCase& c) {
  JointFit f;
  f.outer_radius =
      HotRadius(c.geometry.liner_radius, c.skirt.liner_expansion, c.skirt.liner_temperature);
  f.inner_radius = HotRadius(PistonRadius(c), c.skirt.piston_expansion, c.skirt.piston_temperature);
  f.cold_clearance = SkirtClearance(c);
  f.hot_clearance = f.outer_radius - f.inner_radius;
  return f;
}
/// The big end's: bearing and journal at their temperatures.
inline JointFit BigEndFit(const EngineCase& c) {
  const BigEndCase& b = c.big_end;
  JointFit f;
  f.outer_radius = HotRadius(b.bearing_radius, b.bearing_expansion, b.bearing_temperature);
  f.inner_radius = HotRadius(b.journal_radius, b.journal_expansion, b.journal_temperature);
  f.cold_clearance = b.bearing_radius - b.journal_radius;
  f.hot_clearance = f.outer_radius - f.inner_radius;
  return f;
}

/// Whether a joint (SkirtCase or BigEndCase) is lubricated by a mass-conserving (JFO) film.
template <typename Joint>
bool IsMassConservingFilm(const Joint& joint) {
  return joint.model == JointModel::kLubricated &&
         joint.cavitation == lubrication::CavitationModel::kJfo;
}
/// Whether a lubricated joint's film is mass-conserving (JFO): the run-in is then
/// SolverCase::jfo_run_in_angle.
inline bool HasMassConservingFilm(const EngineCase& c) {
  return IsMassConservingFilm(c.skirt) || IsMassConservingFilm(c.big_end);
}
/// A run-in shorter than this is none: its time would lie below what the integrator resolves
/// (at 1e-300 rad its first steps were subnormal numbers and a mass-conserving film's solve
/// failed) [rad].
inline constexpr double kShortestRunIn = 1e-9;
/// The run-in a run integrates before its first monitored cycle [rad of crank]: none without a
/// film (ideal joints have no start-up transient), jfo_run_in_angle with a mass-conserving one,
/// else run_in_angle; none below kShortestRunIn.
inline double RunInAngle(const EngineCase& c) {
  if (c.skirt.model != JointModel::kLubricated && c.big_end.model != JointModel::kLubricated)
    return 0.0;
  const double angle = HasMassConservingFilm(c) ? c.solver.jfo_run_in_angle : c.solver.run_in_angle;
  return angle < kShortestRunIn ? 0.0 : angle;
}

}  // namespace filmdyn::engine
