#pragma once
/// @file The lubricated big-end bearing as a multibody force element (paper §2.2, eqs. 7–14,
/// §3): a revolute clearance joint between the crank pin (journal, body i) and the rod's
/// big-end bore (bearing, body j); the film forces of lubrication::BearingSolver act at both
/// centres (on the journal F through its centre, on the bearing −F through its centre, plus the
/// friction torque on each — the solver's torque pair already balances the e × F couple).
///
/// Kinematics: e = r_journal − r_bearing (eq. 7), ε = |e|/c (eq. 10), ε̇ = n·ė/c (eq. 11),
/// φ = atan2(e_y, e_x), φ̇ = (e × ė)/|e|². φ̇ is singular at e → 0 while ε φ̇ stays bounded, so
/// below |e| = 1e-3 c the line-of-centres frame keeps the direction of e and |e| is floored at
/// 1e-3 c (a 1e-3 c shift of a centred film whose force is ~0 anyway). Everything is smooth in
/// the Cartesian e, ė, in which the Jacobian is differentiated. Beyond ε_max = 1 − 5e-4 (a film
/// of ~0.05 σ) the solver sees ε_max and a stiff contact penalty acts along −n; the run reports a
/// journal–bearing contact failure when an output step lands there.
#include <functional>
#include <memory>

#include "core/coupling/film_joint.hpp"
#include "core/coupling/film_report.hpp"
#include "core/lubrication/bearing_solver.hpp"
#include "core/multibody/force_element.hpp"

namespace filmdyn::coupling {

/// Where the centres are: body-frame points relative to each centre of mass.
struct BigEndMounting {
  Eigen::Vector2d journal_point = Eigen::Vector2d::Zero();  ///< crank pin centre on the crank
  Eigen::Vector2d bearing_point = Eigen::Vector2d::Zero();  ///< bore centre on the rod
};

struct BigEndKinematics {
  lubrication::BearingState state;  ///< what the solver sees (regularised, clamped)
  Eigen::Vector2d ecc = Eigen::Vector2d::Zero(), ecc_rate = Eigen::Vector2d::Zero();  ///< global
  double eps_true = 0.0;  ///< |e|/c, unclamped
};

class LubricatedBigEndElement final : public multibody::JointForceElement,
                                      public FilmReporter {
 public:
  static constexpr double kEpsMax = 1.0 - 5e-4;
  /// With elastic surfaces the journal may pass the rigid bearing's wall while the deformation
  /// keeps the film open: the rigid eccentricity is limited here instead (half a clearance past
  /// the wall, far beyond a linear elastic film's reach).
  static constexpr double kEpsMaxElastic = 1.5;
  /// The eccentricity beyond which the film is not solved and a contact penalty acts.
  double EpsMax() const { return solver_->config().compliance.rigid() ? kEpsMax : kEpsMaxElastic; }

  LubricatedBigEndElement(lubrication::BearingConfig config, multibody::BodyIndex crank,
                          multibody::BodyIndex rod, BigEndMounting mounting);

  void EvaluateJoint(const multibody::JointForceInput& in, bool want_jacobian,
                     multibody::JointForceOutput* out) override;
  bool ProvidesJacobian() const override { return true; }
  /// Own solver and caches only (the surface model is immutable): may run beside the other joint.
  bool Concurrent() const override { return true; }
  /// Mass-conserving cavitation carries the film's void content from step to step.
  bool WantsAcceptedSteps() const override { return solver_->Transient(); }
  /// The void content's local error (JFO: backward Euler, outside the integrator's error
  /// test) kept at the integrator's position tolerance: lubrication::FilmHistory::NextStepLimit.
  double StepLimit(double length_tolerance) const override {
    return solver_->history().NextStepLimit(length_tolerance);
  }
  void OnStepAccepted(double t, const multibody::SystemState& state) override;
  void ReportFilm(SkirtFilmSample* skirt, BearingFilmSample* bearing) const override;
  void TakeSteps(double t, SkirtFilmSample* skirt, BearingFilmSample* bearing) override;

  BigEndKinematics Kinematics(const multibody::BodyState& crank,
                              const multibody::BodyState& rod) const;
  /// The journal's position and eccentricity (journal_ecc_*, eps, eps_dot, present) at the
  /// given body states, as ReportFilm gives them, without a film solve; the film fields of
  /// `bearing` are left alone.
  void ReportMotion(const multibody::BodyState& crank, const multibody::BodyState& rod,
                    BearingFilmSample* bearing) const;
  const lubrication::BearingSolver& solver() const { return *solver_; }
  /// A supply pressure that varies with the crank's orientation [rad] -> [Pa] (a curve over
  /// crank angle); unset: the configuration's constant OilFeed::pressure.
  void SetSupplyPressure(std::function<double(double)> pressure_of_crank_angle) {
    supply_pressure_ = std::move(pressure_of_crank_angle);
  }
  /// Phases the oil's pressure-viscosity law in from t = 0 to `law_end_time` [s]
  /// (PressureLawRamp), and elastic surfaces' compliance to `compliance_end_time` (RunInScale).
  void PhaseIn(double law_end_time, double compliance_end_time);
  /// A cancel honoured inside the film solve (ReynoldsFem::SetStopCheck).
  void SetStopCheck(const StopCheck& check) { solver_->fem().SetStopCheck(check); }
  /// Re-solves at the last state evaluated without a Jacobian if a Jacobian evaluation has left
  /// other fields in the solver since (so fields() belong to the sampled state).
  void RefreshFields();
  const lubrication::BearingResult& last_result() const { return result_; }
  long reynolds_solves() const { return solves_; }
  /// Numeric LDLᵀ factorisations over all solves (the other linear solves reuse a factor).
  long factorizations() const { return factorizations_; }

 private:
  /// The film at `state` and time t, with the pressure law of t.
  const lubrication::BearingResult& SolveFilm(const lubrication::BearingState& state, double t);
  /// (F_x, F_y, T_journal, T_bearing) at Cartesian (e, ė, ω_j, ω_b) + bearing angle.
  Eigen::Vector4d Loads(const Eigen::Matrix<double, 6, 1>& z, double bearing_angle,
                        BigEndKinematics* kin);

  std::unique_ptr<lubrication::BearingSolver> solver_;
  BigEndMounting mount_;
  double penalty_stiffness_ = 0.0;  ///< [N/m]
  double eval_time_ = 0.0;          ///< time of the evaluation in progress (film history)
  double journal_angle_ = 0.0;      ///< crank orientation of that evaluation (pin holes)
  std::function<double(double)> supply_pressure_;
  LastEvaluation last_;
  lubrication::BearingResult result_;
  BigEndKinematics kin_;
  Eigen::Vector4d loads_ = Eigen::Vector4d::Zero();
  double rod_angle_ = 0.0;
  long solves_ = 0, factorizations_ = 0;
  FilmStepBooks books_;  ///< kept at accepted steps when the film conserves oil (JFO)
  FilmPhaseIn phase_in_;
};

}  // namespace filmdyn::coupling
