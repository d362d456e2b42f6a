#pragma once
/// @file What both lubricated joints (skirt–liner and big end) keep beside their film solver: the
/// last evaluation, which serves the integrator's repeated requests for one state, and the
/// run-in's phase-in of the pressure law and of elastic surfaces. One definition for both joints.
#include "core/coupling/pressure_law_ramp.hpp"
#include "core/multibody/force_element.hpp"

namespace filmdyn::coupling {

/// A film's phase-in over the run-in: its pressure-viscosity law (PressureLawRamp) and the
/// compliance of elastic surfaces (RunInScale), each from nothing to whole. The journal and the
/// piston meet their films at metres per second in the first steps; rigid surfaces and the
/// isoviscous film take that, the full law and a soft surface would not.
class FilmPhaseIn {
 public:
  FilmPhaseIn() = default;  ///< nothing phased in
  /// The law `full` whole from `law_end_time` [s] on; the compliance whole from
  /// `compliance_end_time` [s] on, or from the start for rigid surfaces.
  FilmPhaseIn(const lubrication::PressureViscosity& full, double law_end_time, bool rigid,
              double compliance_end_time)
      : ramp_(full, law_end_time), compliance_end_time_(rigid ? 0.0 : compliance_end_time) {}

  /// Sets `solver` (SetPressureViscosity, SetComplianceScale) to the law and the compliance of
  /// time t [s].
  template <class Solver>
  void Apply(double t, Solver& solver) {
    if (ramp_.Update(t)) solver.SetPressureViscosity(ramp_.law());
    if (compliance_end_time_ > 0.0) solver.SetComplianceScale(RunInScale(t, compliance_end_time_));
  }
  /// Whether a film solved at t [s] or later still changes with the time alone.
  bool VariesAfter(double t) const { return ramp_.VariesAfter(t) || t < compliance_end_time_; }

 private:
  PressureLawRamp ramp_;
  double compliance_end_time_ = 0.0;  // 0: rigid surfaces, or elastic from the start
};

/// A joint's last evaluation. The integrator asks for one state more than once (its Newton
/// iteration's residual and Jacobian, the booking of an accepted step), and a film solve is what
/// a step costs: a repeat is served from here. Also kept: whether the film solver still holds the
/// evaluation's film (its fields, its flows) or has solved other states since.
class LastEvaluation {
 public:
  /// When `in` is the kept input — its time too when `timed` (a film with a history, a phase-in
  /// under way) — and the kept output has a Jacobian if one is wanted: copies the output to *out
  /// (its Jacobian zero unless wanted) and returns true. Otherwise false, *out left alone.
  bool Serve(const multibody::JointForceInput& in, bool timed, bool want_jacobian,
             multibody::JointForceOutput* out) const {
    if (!valid_ || !multibody::SameJointInput(in, in_, timed) || (want_jacobian && !jacobian_)) {
      return false;
    }
    *out = out_;
    if (!want_jacobian) out->jacobian.setZero();
    return true;
  }
  /// Keeps the wrenches of `out` at `in`, without a Jacobian: the film solver holds their film.
  /// Kept before a Jacobian is computed, so that one that fails leaves a consistent evaluation.
  void Keep(const multibody::JointForceInput& in, const multibody::JointForceOutput& out) {
    in_ = in;
    out_ = out;
    out_.jacobian.setZero();
    valid_ = solver_holds_ = true;
    jacobian_ = false;
  }
  /// Adds the Jacobian of `out` (the kept input's) to the kept output.
  void KeepJacobian(const multibody::JointForceOutput& out) {
    out_.jacobian = out.jacobian;
    jacobian_ = true;
  }
  /// The film solver has solved other states since (a Jacobian's differences).
  void SolverMovedOn() { solver_holds_ = false; }
  /// The film solver holds the kept evaluation's film again (it has been solved again).
  void SolverHoldsIt() { solver_holds_ = valid_; }
  /// Forgets the evaluation: an accepted step has moved the film's history on.
  void Drop() { valid_ = solver_holds_ = jacobian_ = false; }

  /// Whether the film solver holds the film of a kept evaluation at time t [s].
  bool SolverHoldsAt(double t) const { return valid_ && solver_holds_ && in_.t == t; }
  /// Whether an evaluation is kept whose film the solver no longer holds.
  bool SolverMovedOnFromIt() const { return valid_ && !solver_holds_; }
  /// The kept input (the last one kept even after Drop; all zero before any).
  const multibody::JointForceInput& input() const { return in_; }

 private:
  multibody::JointForceInput in_;
  multibody::JointForceOutput out_;
  bool valid_ = false, jacobian_ = false, solver_holds_ = false;
};

}  // namespace filmdyn::coupling
