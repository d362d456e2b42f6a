#pragma once
/// @file The lubricated piston skirt–liner joint as a multibody force element (paper §2.1 and
/// §3): a translational clearance joint between the ground (liner) and the piston whose
/// lateral position and tilt are free; the film forces of lubrication::SkirtSolver are applied
/// to the piston's centre of mass.
///
/// Kinematics (exact for the rigid piston; layout in core/engine/crank_train.hpp). A point of the
/// skirt axis at axial coordinate y (from the skirt top, + toward the crank) has the body-frame
/// position s(y) = (−c_g, b_p − y) relative to the CoM, so its lateral (X) position is
///   d(y) = x − c_g cos θ + (y − b_p) sin θ = e0 + (y − a_p) γ,
///   e0 = x − c_g cos θ + (a_p − b_p) sin θ   (axis at pin height; = pin X − C_p cos θ),
///   γ  = sin θ ≈ θ                            (the tilt of eq. 2, + CCW, skirt bottom to thrust),
/// and the skirt slides along the bore with u_p = ṡ, s = −Y of the axis at pin height. The film
/// generalised forces (F on e0, M on γ, F_f on s) map to the CoM wrench by virtual work:
///   Q = J(q)ᵀ (F, M, F_f),  J = ∂(e0, γ, s)/∂(x, y, θ).
/// Jacobian: ∂(F, M, F_f)/∂(e0, γ, ė0, γ̇, u_p) by forward differences of the solver, each
/// increment scaled to its unknown (EvaluateJoint), chained with J and its derivative.
#include <memory>

#include "core/coupling/film_joint.hpp"
#include "core/coupling/film_report.hpp"
#include "core/lubrication/skirt_solver.hpp"
#include "core/multibody/force_element.hpp"

namespace filmdyn::coupling {

/// Body-frame data of the piston the element needs (from the case's geometry).
struct SkirtMounting {
  double com_lateral_offset = 0.0;  ///< c_g: CoM from the bore axis, + toward thrust [m]
  double skirt_top_to_com = 0.0;    ///< b_p [m], + toward the crank
  double skirt_top_to_pin = 0.0;    ///< a_p [m], + toward the crank
  double pin_offset = 0.0;          ///< C_p [m] (reporting only)
  /// Height of the piston pin at top dead centre [m] (global Y): the stroke position, from which
  /// a starved skirt reads the liner's oil film (SkirtState::stroke_position).
  double pin_y_at_tdc = 0.0;
};

/// Secondary-motion coordinates of the piston (the solver's state) and their Jacobians.
struct SkirtKinematics {
  lubrication::SkirtState state;
  Eigen::Matrix3d jac = Eigen::Matrix3d::Zero();  ///< ∂(e0, γ, s)/∂(x, y, θ)
  double min_gap = 0.0;                           ///< smallest rigid gap over the panels' nodes [m]
  double min_gap_alpha = 0.0, min_gap_y = 0.0;    ///< where: α from the thrust axis [rad], y [m]
};

class LubricatedSkirtElement final : public multibody::JointForceElement,
                                     public FilmReporter {
 public:
  /// With elastic surfaces the piston may pass the rigid liner's wall while the deformation
  /// keeps the film open (a thin skirt wall gives way by more than its clearance: the shipped
  /// CalculiX skirt by 34 um against 25 um): the rigid gap may fall to this many radial
  /// clearances below zero, as the big end's eccentricity may reach
  /// LubricatedBigEndElement::kEpsMaxElastic.
  static constexpr double kElasticPenetration = 2.0;
  /// The smallest rigid gap the film is solved at [m] (0: rigid surfaces; below: contact).
  double MinGapAllowed() const;
  /// `piston`: body index; the liner is the ground.
  LubricatedSkirtElement(lubrication::SkirtConfig config, multibody::BodyIndex piston,
                         SkirtMounting mounting);

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

  /// e0, γ, rates and u_p of a piston state, with J.
  SkirtKinematics Kinematics(const multibody::BodyState& piston) const;
  /// The solver; its fields() are those of the last evaluation at the state last passed to
  /// EvaluateJoint without a Jacobian (RefreshFields() guarantees it).
  const lubrication::SkirtSolver& solver() const { return *solver_; }
  void RefreshFields();
  const lubrication::SkirtResult& last_result() const { return result_; }
  /// 2: the skirt's thrust and anti-thrust panels solved side by side (SkirtSolver::SetThreads).
  void SetPanelThreads(int threads) { solver_->SetThreads(threads); }
  /// Phases the oil's pressure-viscosity law in from t = 0 to `law_end_time` [s]
  /// (PressureLawRamp), and elastic surfaces' compliance to `compliance_end_time` (RunInScale).
  void PhaseIn(double law_end_time, double compliance_end_time);
  /// A cancel honoured inside the film solves (ReynoldsFem::SetStopCheck).
  void SetStopCheck(const StopCheck& check) { solver_->SetStopCheck(check); }
  long reynolds_solves() const { return solves_; }
  /// Numeric LDLᵀ factorisations over all solves (the other linear solves reuse a factor).
  long factorizations() const { return factorizations_; }

 private:
  void SolveAt(const lubrication::SkirtState& state);
  Eigen::Vector3d Generalised(const lubrication::SkirtResult& r) const;

  std::unique_ptr<lubrication::SkirtSolver> solver_;
  SkirtMounting mount_;
  double eval_time_ = 0.0;  ///< time of the evaluation in progress (film history)
  LastEvaluation last_;
  lubrication::SkirtResult result_;
  FilmStepBooks books_;  ///< kept at accepted steps when the film conserves oil (JFO)
  FilmPhaseIn phase_in_;
  SkirtKinematics kin_;
  long solves_ = 0, factorizations_ = 0;
};

}  // namespace filmdyn::coupling
