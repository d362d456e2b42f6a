#pragma once
/// @file Implicit, error-controlled time integration of eq. 39: SUNDIALS CVODE, variable-order
/// BDF (orders 1–5) with Newton iterations on a dense direct linear solver and our own Jacobian
/// (MultibodySystem::AccelerationJacobian). Why this choice: docs/validation/multibody.md.
#include <initializer_list>
#include <memory>
#include <stdexcept>
#include <string>

#include "core/multibody/multibody_system.hpp"

namespace filmdyn::multibody {

struct IntegratorConfig {
  /// Relative local error of velocities and angular velocities. Positions and angles are held
  /// at their absolute tolerances alone: their coordinates are measured from the global origin,
  /// whose distance says nothing about the accuracy a film between two bodies needs.
  double relative_tolerance = 1e-7;
  double position_tolerance = 1e-10;         ///< absolute, [m]
  double angle_tolerance = 1e-9;             ///< absolute, [rad]
  double velocity_tolerance = 1e-7;          ///< absolute, [m/s]
  double angular_velocity_tolerance = 1e-6;  ///< absolute, [rad/s]
  double max_step = 0.0;                     ///< [s]; 0 = unlimited
  int max_order = 5;
  long max_steps_per_output = 200000;

  /// A copy with every error tolerance (relative and absolute) multiplied by `factor`.
  IntegratorConfig ScaledTolerances(double factor) const {
    IntegratorConfig c = *this;
    for (double* tol : {&c.relative_tolerance, &c.position_tolerance, &c.angle_tolerance,
                        &c.velocity_tolerance, &c.angular_velocity_tolerance}) {
      *tol *= factor;
    }
    return c;
  }
};

/// Counters of the integration so far (Drake SimulatorStatus / MuJoCo warnings spirit).
struct SolverStats {
  long steps = 0;
  long rejected_steps = 0;  ///< local error test failures
  long newton_iterations = 0;
  long newton_failures = 0;  ///< nonlinear convergence failures (step retried smaller)
  long rhs_evaluations = 0;  ///< evaluations of eq. 39 (each calls every force element)
  long jacobian_evaluations = 0;
  double last_step = 0.0;  ///< [s]
  int last_order = 0;
};

/// The integration stopped because its tolerances ask for more accuracy than double precision
/// gives at the time reached (CVODE's CV_TOO_MUCH_ACC): the remedy is looser tolerances.
class TolerancesTooTight : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The integration stopped while the last evaluation it retried failed because a joint's
/// surfaces meet (EvaluationFailure::ContactJoint): no smaller step cures it.
class SurfacesInContact : public std::runtime_error {
 public:
  SurfacesInContact(const std::string& what, std::string joint)
      : std::runtime_error(what), joint_(std::move(joint)) {}
  const std::string& Joint() const { return joint_; }

 private:
  std::string joint_;
};

/// Integrates a MultibodySystem; the system must outlive the integrator.
class Integrator {
 public:
  Integrator(MultibodySystem& system, IntegratorConfig config);
  ~Integrator();
  Integrator(const Integrator&) = delete;
  Integrator& operator=(const Integrator&) = delete;

  /// Starts at (t0, state); the state should be consistent (MultibodySystem::Assemble).
  void Initialize(double t0, const SystemState& state);
  /// Advances to t_out (interpolating inside the last step) and returns the state there.
  /// Throws std::runtime_error with CVODE's reason when the integration cannot continue
  /// (TolerancesTooTight when they ask for more than double precision gives, SurfacesInContact
  /// when the evaluations failed last because a joint's surfaces meet).
  SystemState AdvanceTo(double t_out);
  /// Changes the error tolerances (relative and absolute) from the next step on; the other
  /// fields of `config` are ignored.
  void SetTolerances(const IntegratorConfig& config);
  double Time() const { return t_; }
  SolverStats Stats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  double t_ = 0.0;
};

}  // namespace filmdyn::multibody
