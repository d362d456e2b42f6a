#pragma once
/// @file The crank train (crank at imposed constant speed, connecting rod, piston) built from a
/// case on the general multibody engine. Each of the skirt and the big end is an ideal joint or
/// a lubricated force element supplied by a factory; nothing else changes.
///
/// Layout (docs/outputs.md): origin at the main-journal centre, +Y along the cylinder axis toward
/// the head, +X toward the major thrust side, angles counter-clockwise. Crank angle φ = θ_crank;
/// crank pin at L_1(−sin φ, cos φ): the crank turns counter-clockwise, and in the power stroke the
/// rod pushes the piston toward +X. 0 °CA = TDC of intake, 360 °CA = firing TDC.
#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

#include "core/coupling/film_report.hpp"
#include "core/engine/engine_case.hpp"
#include "core/engine/gas_force.hpp"
#include "core/multibody/multibody_system.hpp"

namespace filmdyn::engine {

/// Where everything is: body indices, joint indices (−1 when the joint is not an ideal joint),
/// and body-frame points [m] (relative to each centre of mass).
struct CrankTrainLayout {
  multibody::BodyIndex crank = 0, rod = 1, piston = 2;
  int main_bearing = -1, crank_drive = -1, big_end = -1, piston_pin = -1, liner = -1;
  Eigen::Vector2d crank_main_journal, crank_pin;        ///< on the crank
  Eigen::Vector2d rod_big_end, rod_small_end;           ///< on the rod
  Eigen::Vector2d piston_pin_point, piston_axis_point;  ///< on the piston (axis at CoM height)
  double omega = 0.0;                                   ///< imposed crank speed [rad/s]
};

/// Makes a lubricated joint's force element for a case and layout.
using JointForceFactory = std::function<std::unique_ptr<multibody::JointForceElement>(
    const EngineCase&, const CrankTrainLayout&)>;

struct LubricatedJointFactories {
  JointForceFactory skirt;    ///< connects the ground (liner) and the piston
  JointForceFactory big_end;  ///< connects the crank (journal) and the rod (bearing)
};

struct CrankTrain {
  std::unique_ptr<multibody::MultibodySystem> system;
  CrankTrainLayout layout;
  GasForce* gas_force = nullptr;                            ///< owned by system
  multibody::JointForceElement* skirt_element = nullptr;    ///< owned by system, when lubricated
  multibody::JointForceElement* big_end_element = nullptr;  ///< owned by system, when lubricated
  multibody::SystemState initial_state;                     ///< assembled at t = 0
};

/// Builds the crank train at `rpm` with the given pressure curve. Throws InputError when a joint
/// is lubricated but no factory is given, or when the geometry cannot be assembled.
CrankTrain BuildCrankTrain(const EngineCase& engine_case, double rpm, PressureCurve pressure,
                           const LubricatedJointFactories& factories = {});

/// The film reports of the coupling elements, as the engine's samples carry them.
using SkirtFilmSample = coupling::SkirtFilmSample;
using BearingFilmSample = coupling::BearingFilmSample;

/// Crank-train quantities at one instant (global frame; signs in docs/outputs.md).
struct CrankTrainSample {
  double time = 0.0;                 ///< [s]
  double crank_angle = 0.0;          ///< unwrapped [rad]
  double piston_position = 0.0;      ///< pin Y [m]
  double piston_velocity = 0.0;      ///< [m/s]
  double piston_acceleration = 0.0;  ///< [m/s²]
  double rod_angle = 0.0, rod_angular_velocity = 0.0, rod_angular_acceleration = 0.0;
  double piston_lateral = 0.0, piston_tilt = 0.0;  ///< pin X − C_p, piston θ
  double piston_lateral_velocity = 0.0, piston_tilt_rate = 0.0;
  /// X velocity of the piston's centre of mass [m/s], of the same state as the secondary motion
  /// (the integrated state with a lubricated skirt).
  double piston_com_lateral_velocity = 0.0;
  double cylinder_pressure = 0.0;  ///< [Pa]
  double gas_force = 0.0;          ///< (p − p_cc)·π R_l², + toward the crank [N]
  double gas_power = 0.0;          ///< power of the gas force on the piston [W]
  Eigen::Vector2d liner_force_on_piston = Eigen::Vector2d::Zero();  ///< ideal liner [N]
  double liner_moment_about_pin = 0.0;  ///< ideal liner on piston, about the pin [N·m]
  Eigen::Vector2d big_end_force_on_rod = Eigen::Vector2d::Zero();         ///< crank pin → rod [N]
  Eigen::Vector2d pin_force_on_piston = Eigen::Vector2d::Zero();          ///< rod → piston [N]
  Eigen::Vector2d main_bearing_force_on_crank = Eigen::Vector2d::Zero();  ///< [N]
  double crank_torque = 0.0;          ///< drive torque on the crank [N·m]
  double constraint_violation = 0.0;  ///< max |Φ| of the position rows [m or rad]
  SkirtFilmSample skirt;              ///< lubricated skirt
  BearingFilmSample bearing;          ///< lubricated big end
};

/// The train at an output time t: evaluates the system at `state` and reports every quantity.
/// Call once per output sample, in time order: the film joints hand over the peak pressures of
/// their accepted steps up to t (coupling::StepPeaks), which a second call at t no longer has.
CrankTrainSample SampleCrankTrain(CrankTrain& train, const EngineCase& engine_case, double t,
                                  const multibody::SystemState& state);

/// The motion of the two clearance joints at one instant: the piston's secondary motion and the
/// big-end journal's position and eccentricity rate. Taken from the state alone — no film solve,
/// no force evaluation — so that a run can sample it between its output steps from the
/// integrator's interpolating polynomial (RunResult::motion) and draw the journal orbit and the
/// phase portraits as smooth curves. A joint that is not lubricated has no clearance motion:
/// its `present` flag is false and its values zero.
struct MotionSample {
  double time = 0.0;         ///< [s]
  double crank_angle = 0.0;  ///< unwrapped [rad]
  bool piston_present = false;
  double piston_lateral = 0.0, piston_tilt = 0.0;  ///< as CrankTrainSample [m], [rad]
  double piston_lateral_velocity = 0.0, piston_tilt_rate = 0.0;
  double piston_com_lateral_velocity = 0.0;  ///< X velocity of the piston's centre of mass [m/s]
  bool journal_present = false;
  Eigen::Vector2d journal_ecc_rod = Eigen::Vector2d::Zero();  ///< rod frame [m]
  double eps = 0.0;                                           ///< ε [-]
  double eps_dot = 0.0;                                       ///< dε/dt [1/s]
};

/// The motion at the integrated state `state` (the state the film joints see).
MotionSample SampleMotion(const CrankTrain& train, const EngineCase& engine_case, double t,
                          const multibody::SystemState& state);
/// The motion part of a full sample: the same values SampleMotion gives at its state.
MotionSample MotionOf(const CrankTrainSample& sample);

/// The crank angle within the reported cycle [°CA], [0, 720), rounded to 1e-9 °CA, of an
/// unwrapped crank angle [rad] (results.csv's first column; one rule for every row and figure).
double CycleCrankAngleDeg(double crank_angle);
/// Where a lap of such crank angles [°CA] in time order starts from 0 °CA: the index of the first
/// one after the last pass 720 → 0 at or after `from` (`from` when there is none). A cycle that
/// starts elsewhere than 0 °CA (operating.start_crank_angle) passes it within; fields and plots
/// show it from there.
std::size_t LapStart(const std::vector<double>& crank_angles_deg, std::size_t from = 0);

}  // namespace filmdyn::engine
