#pragma once
/// @file Force elements: anything that adds generalised applied forces Q (eq. 36) —
/// gravity, the gas force, and the lubricated clearance joints (which the paper models as
/// "force constraints" instead of kinematic ones, §3).
#include <Eigen/Dense>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/multibody/system_state.hpp"

namespace filmdyn::multibody {

/// Derivatives of the generalised forces, ∂Q/∂q and ∂Q/∂v (both 3n × 3n). Elements add into them.
struct ForceJacobian {
  Eigen::MatrixXd dq;
  Eigen::MatrixXd dv;
  void Reset(int num_coordinates) {
    dq.setZero(num_coordinates, num_coordinates);
    dv.setZero(num_coordinates, num_coordinates);
  }
};

/// An evaluation that failed at a trial state in a way a smaller step may cure (e.g. a film
/// solve that did not converge there): the integrator retries the step smaller and, when it gives
/// up, reports this message with its own. The message names the element and the failure.
class EvaluationFailure : public std::runtime_error {
 public:
  /// `contact_joint`: the joint whose surfaces meet when that is the failure (empty otherwise).
  explicit EvaluationFailure(const std::string& what, std::string contact_joint = {})
      : std::runtime_error(what), contact_joint_(std::move(contact_joint)) {}
  const std::string& ContactJoint() const { return contact_joint_; }

 private:
  std::string contact_joint_;
};

class ForceElement {
 public:
  explicit ForceElement(std::string name) : name_(std::move(name)) {}
  virtual ~ForceElement() = default;

  const std::string& Name() const { return name_; }
  /// Bodies whose states the element reads; the integrator differentiates the element by finite
  /// differences over exactly these bodies when ProvidesJacobian() is false.
  virtual std::vector<BodyIndex> Bodies() const = 0;
  /// Adds the element's generalised forces (F_x, F_y, M_z about each centre of mass, global) to
  /// q_force (size 3n). When `jacobian` is non-null and ProvidesJacobian(), also adds ∂Q/∂q, ∂Q/∂v.
  virtual void AddForces(double t, const SystemState& state, Eigen::Ref<Eigen::VectorXd> q_force,
                         ForceJacobian* jacobian) = 0;
  virtual bool ProvidesJacobian() const { return false; }
  /// True when AddForces is expensive and reads and writes nothing but the element's own
  /// members (and the arguments): the system may then evaluate it on a helper thread,
  /// concurrently with other such elements (MultibodySystem::SetThreads). Default: false.
  virtual bool Concurrent() const { return false; }
  /// Called once per accepted integrator step, at its end (t, state), when
  /// WantsAcceptedSteps(): for elements with a history (e.g. a film's cavitation content).
  virtual void OnStepAccepted(double /*t*/, const SystemState& /*state*/) {}
  /// True when the element needs OnStepAccepted (it costs the integrator a step-by-step loop).
  virtual bool WantsAcceptedSteps() const { return false; }
  /// After OnStepAccepted: the largest next step that keeps the local error of the element's own
  /// history (e.g. a film's void content, advanced at first order outside the integrator's error
  /// test) within `length_tolerance` [m], the integrator's position tolerance; 0 = no limit.
  virtual double StepLimit(double /*length_tolerance*/) const { return 0.0; }

 private:
  std::string name_;
};

/// Uniform gravity acting on every body: F = m·g at the centre of mass.
class Gravity final : public ForceElement {
 public:
  Gravity(std::vector<double> masses, Eigen::Vector2d g)
      : ForceElement("gravity"), masses_(std::move(masses)), g_(g) {}
  std::vector<BodyIndex> Bodies() const override { return {}; }
  void AddForces(double t, const SystemState& state, Eigen::Ref<Eigen::VectorXd> q_force,
                 ForceJacobian* jacobian) override;
  bool ProvidesJacobian() const override { return true; }  // constant: zero derivatives

 private:
  std::vector<double> masses_;
  Eigen::Vector2d g_;
};

/// States of the two bodies a joint force element connects (either may be the ground).
struct JointForceInput {
  double t = 0.0;
  BodyState body_i;
  BodyState body_j;
};

/// Whether a joint given `a` gets the same result as given `b`: both bodies' positions and
/// velocities equal, and the time too when `timed` (a film with a history, whose result depends
/// on the step it is taken from, or a law being phased in). A joint caches its last result by it.
inline bool SameJointInput(const JointForceInput& a, const JointForceInput& b, bool timed) {
  return (!timed || a.t == b.t) && a.body_i.q == b.body_i.q && a.body_i.v == b.body_i.v &&
         a.body_j.q == b.body_j.q && a.body_j.v == b.body_j.v;
}

/// Wrenches on both bodies and, optionally, their derivatives.
struct JointForceOutput {
  Eigen::Vector3d wrench_i = Eigen::Vector3d::Zero();  ///< (F_x, F_y, M_z about CoM_i), global
  Eigen::Vector3d wrench_j = Eigen::Vector3d::Zero();  ///< (F_x, F_y, M_z about CoM_j), global
  /// Rows: wrench_i, wrench_j; columns: q_i, q_j, v_i, v_j (each 3). Filled only when
  /// the element ProvidesJacobian() and the caller asked for it.
  Eigen::Matrix<double, 6, 12> jacobian = Eigen::Matrix<double, 6, 12>::Zero();
};

/// The interface the lubricated clearance joints implement (skirt–liner, big-end bearing): given
/// both bodies' states, the forces and moments on both, with state derivatives where available
/// (e.g. the squeeze-film damping ∂F/∂v, which is what makes the film stiff).
class JointForceElement : public ForceElement {
 public:
  JointForceElement(std::string name, BodyIndex body_i, BodyIndex body_j)
      : ForceElement(std::move(name)), body_i_(body_i), body_j_(body_j) {}
  BodyIndex BodyI() const { return body_i_; }
  BodyIndex BodyJ() const { return body_j_; }

  /// Computes the wrenches; fills out->jacobian when want_jacobian && ProvidesJacobian().
  virtual void EvaluateJoint(const JointForceInput& in, bool want_jacobian,
                             JointForceOutput* out) = 0;

  std::vector<BodyIndex> Bodies() const override;
  void AddForces(double t, const SystemState& state, Eigen::Ref<Eigen::VectorXd> q_force,
                 ForceJacobian* jacobian) final;

 private:
  BodyIndex body_i_;
  BodyIndex body_j_;
};

/// A joint element's Jacobian (rows wrench_i, wrench_j; columns q_i, q_j, v_i, v_j) by central
/// differences of its wrenches, step h·max(1,|x|) (a check for element authors).
Eigen::Matrix<double, 6, 12> JointJacobianByDifferences(JointForceElement& element,
                                                        const JointForceInput& in, double h);
/// Largest |analytic − finite-difference| entry of a joint element's Jacobian, relative to the
/// largest analytic entry (JointJacobianByDifferences).
double JointJacobianMismatch(JointForceElement& element, const JointForceInput& in,
                             double h = 1e-7);

}  // namespace filmdyn::multibody
