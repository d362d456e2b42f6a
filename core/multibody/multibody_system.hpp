#pragma once
/// @file A general planar multibody system: bodies, ideal joints (Lagrange multipliers) and force
/// elements, with the equations of motion of eq. 39 (Baumgarte 1972 stabilisation):
///
///   [ M    Φ_qᵀ ] [ q̈ ]   [ Q                               ]
///   [ Φ_q  0    ] [ λ  ] = [ γ − 2α(Φ_q q̇ + Φ_t) − β² Φ      ]
///
/// solved through the Schur complement (M is diagonal and positive). The system is constant
/// after assembly (MuJoCo's mjModel); the evolving state is a SystemState.
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/multibody/body.hpp"
#include "core/multibody/constraint.hpp"
#include "core/multibody/force_element.hpp"
#include "core/multibody/system_state.hpp"
#include "core/base/stop.hpp"
#include "core/base/worker_pool.hpp"

namespace filmdyn::multibody {

/// Baumgarte feedback coefficients of eq. 39: α (the paper's 𝒢) [1/s] and β (the paper's ζ) [1/s].
/// The constraint violation then obeys Φ̈ + 2αΦ̇ + β²Φ = 0.
struct BaumgarteParameters {
  double alpha = 1.0e4;  ///< paper Table II
  double beta = 1.0e4;   ///< paper Table II
};

/// Everything eq. 39 yields at one state.
struct DynamicsEvaluation {
  Eigen::VectorXd acceleration;   ///< q̈ (3n)
  Eigen::VectorXd multipliers;    ///< λ (m)
  Eigen::VectorXd applied_force;  ///< Q (3n), sum of all force elements
};

class MultibodySystem {
 public:
  BodyIndex AddBody(Body body);
  /// Adds a joint; returns its index (for Reaction()).
  int AddConstraint(std::unique_ptr<Constraint> constraint);
  /// Adds a force element; the system owns it. Returns a reference valid for the system's life.
  ForceElement& AddForceElement(std::unique_ptr<ForceElement> element);

  void SetBaumgarte(const BaumgarteParameters& parameters) { baumgarte_ = parameters; }
  const BaumgarteParameters& Baumgarte() const { return baumgarte_; }

  int NumBodies() const { return static_cast<int>(bodies_.size()); }
  int NumCoordinates() const { return 3 * NumBodies(); }
  int NumConstraintRows() const { return num_rows_; }
  const Body& GetBody(BodyIndex index) const { return bodies_.at(index); }
  const Constraint& GetConstraint(int index) const { return *constraints_.at(index); }
  int NumConstraints() const { return static_cast<int>(constraints_.size()); }
  ForceElement& GetForceElement(int index) { return *elements_.at(index); }
  int NumForceElements() const { return static_cast<int>(elements_.size()); }
  /// First row of constraint `index` in λ.
  int ConstraintRowOffset(int index) const { return row_offsets_.at(index); }

  /// Threads for evaluating the Concurrent() force elements (the film joints) of one evaluation
  /// side by side; 1 (the default) = sequential. The results do not depend on it, bit for bit:
  /// each element adds into its own zeroed buffer and the buffers are summed in element order.
  void SetThreads(int threads);
  int Threads() const;

  /// Called at the start of every evaluation of the applied forces and of every Jacobian (the
  /// expensive calls: each solves the films); when it returns true they throw
  /// filmdyn::StopRequested (core/base/stop.hpp), so
  /// a cancel or a time limit is honoured within one evaluation, not one output step.
  void SetStopCheck(StopCheck check) { stop_check_ = std::move(check); }
  /// Called with the time of every evaluation of the applied forces, after the stop check and
  /// on the calling thread (not the film joints' worker threads): where the integration stands
  /// inside an output step. It may throw filmdyn::StopRequested to stop it.
  void SetEvaluationObserver(std::function<void(double)> observer) {
    observer_ = std::move(observer);
  }

  /// True when a force element wants OnStepAccepted calls (ForceElement::WantsAcceptedSteps).
  bool WantsAcceptedSteps() const;
  /// Passes an accepted integrator step's end to the elements that want it.
  void OnStepAccepted(double t, const SystemState& state);
  /// After OnStepAccepted: the smallest of the elements' step limits (ForceElement::StepLimit)
  /// [s]; 0 = none.
  double StepLimit(double length_tolerance) const;

  /// Sum of all applied forces Q (3n) at the state.
  Eigen::VectorXd AppliedForces(double t, const SystemState& state);
  /// eq. 39 at the state (force elements evaluated once).
  DynamicsEvaluation Evaluate(double t, const SystemState& state);
  /// eq. 39 with a given Q (no force element called).
  DynamicsEvaluation EvaluateWithForces(double t, const SystemState& state,
                                        const Eigen::VectorXd& applied_force) const;

  /// Φ (position-level violation), Φ̇ = Φ_q q̇ + Φ_t (velocity-level violation).
  Eigen::VectorXd PositionViolation(double t, const SystemState& state) const;
  Eigen::VectorXd VelocityViolation(double t, const SystemState& state) const;

  /// Reaction of joint `index` on both bodies from the multipliers of an evaluation.
  JointReaction Reaction(int index, double t, const SystemState& state,
                         const Eigen::VectorXd& multipliers) const;

  /// Moves q, then v, minimally (least-norm Gauss–Newton) onto Φ = 0 and Φ̇ = 0: the consistent
  /// initial conditions. Throws std::runtime_error when the joints cannot be assembled.
  void Assemble(double t, SystemState* state, double tolerance = 1e-12) const;

  /// Jacobians of q̈(q, v) for the implicit integrator: d q̈/dq and d q̈/dv (3n × 3n each).
  /// Constraint terms by central differences at frozen Q (cheap), force elements through
  /// the projector P = ∂q̈/∂Q with their analytic derivatives, or forward differences over the
  /// element's own bodies when an element has none.
  void AccelerationJacobian(double t, const SystemState& state, Eigen::MatrixXd* d_acc_dq,
                            Eigen::MatrixXd* d_acc_dv);

  /// Masses, one per body (for Gravity).
  std::vector<double> Masses() const;

 private:
  StopCheck stop_check_;
  std::function<void(double)> observer_;
  /// Assembled Φ, Φ_q (m × 3n), Φ_t, γ.
  struct ConstraintSystem {
    Eigen::VectorXd phi, phi_t, gamma;
    Eigen::MatrixXd jac;
  };
  ConstraintSystem AssembleConstraints(double t, const SystemState& state) const;

  std::vector<Body> bodies_;
  std::vector<std::unique_ptr<Constraint>> constraints_;
  std::vector<int> row_offsets_;
  std::vector<std::unique_ptr<ForceElement>> elements_;
  std::unique_ptr<WorkerPool> pool_;  // null: sequential
  int num_rows_ = 0;
  BaumgarteParameters baumgarte_;
};

}  // namespace filmdyn::multibody
