#include "core/multibody/integrator.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <cmath>
#include <exception>
#include <stdexcept>

#include "core/base/input_error.hpp"

namespace filmdyn::multibody {

struct Integrator::Impl {
  MultibodySystem* system = nullptr;
  IntegratorConfig config;
  SUNContext context = nullptr;
  void* cvode = nullptr;
  N_Vector y = nullptr;
  SUNMatrix matrix = nullptr;
  SUNLinearSolver solver = nullptr;
  int n = 0;  // coordinates
  std::exception_ptr error;
  std::string cvode_message;
  std::string last_failure;  // the last EvaluationFailure CVODE recovered from (or not)
  std::string last_failure_contact;  // its joint whose surfaces meet, if that was the failure
  SystemState scratch;
  SystemState accepted;  // the end of the last accepted step (AdvanceTo, step by step)
  double applied_max_step = 0.0;  // CVODE's largest step now (0: none)

  ~Impl() {
    if (solver) SUNLinSolFree(solver);
    if (matrix) SUNMatDestroy(matrix);
    if (y) N_VDestroy(y);
    if (cvode) CVodeFree(&cvode);
    if (context) SUNContext_Free(&context);
  }

  void Unpack(N_Vector v, SystemState* state) const {
    const double* data = N_VGetArrayPointer(v);
    state->q = Eigen::Map<const Eigen::VectorXd>(data, n);
    state->v = Eigen::Map<const Eigen::VectorXd>(data + n, n);
  }

  static int Rhs(double t, N_Vector y, N_Vector ydot, void* user) {
    auto* self = static_cast<Impl*>(user);
    try {
      self->Unpack(y, &self->scratch);
      const DynamicsEvaluation eval = self->system->Evaluate(t, self->scratch);
      double* out = N_VGetArrayPointer(ydot);
      Eigen::Map<Eigen::VectorXd>(out, self->n) = self->scratch.v;
      Eigen::Map<Eigen::VectorXd>(out + self->n, self->n) = eval.acceleration;
      return eval.acceleration.allFinite() ? 0 : 1;  // recoverable: CVODE retries smaller
    } catch (const EvaluationFailure& failure) {
      self->last_failure = failure.what();
      self->last_failure_contact = failure.ContactJoint();
      return 1;
    } catch (...) {
      self->error = std::current_exception();
      return -1;
    }
  }

  static int Jacobian(double t, N_Vector y, N_Vector /*fy*/, SUNMatrix jac, void* user, N_Vector,
                      N_Vector, N_Vector) {
    auto* self = static_cast<Impl*>(user);
    try {
      self->Unpack(y, &self->scratch);
      Eigen::MatrixXd d_acc_dq, d_acc_dv;
      self->system->AccelerationJacobian(t, self->scratch, &d_acc_dq, &d_acc_dv);
      const int n = self->n;
      SUNMatZero(jac);
      for (int c = 0; c < n; ++c) {
        SM_ELEMENT_D(jac, c, n + c) = 1.0;  // d q̇/dv = I
        for (int r = 0; r < n; ++r) {
          SM_ELEMENT_D(jac, n + r, c) = d_acc_dq(r, c);
          SM_ELEMENT_D(jac, n + r, n + c) = d_acc_dv(r, c);
        }
      }
      return 0;
    } catch (const EvaluationFailure& failure) {
      self->last_failure = failure.what();
      self->last_failure_contact = failure.ContactJoint();
      return 1;  // recoverable: CVODE retries the step smaller
    } catch (...) {
      self->error = std::current_exception();
      return -1;
    }
  }

  // Error weights. Positions and angles: 1/atol, their absolute tolerances alone. Body
  // coordinates are measured from the global origin, so a relative part rtol·|q| would loosen a
  // coordinate by its distance from the origin (1e-8 m for a rod 0.1 m from the crank axis at
  // rtol 1e-7, a hundred times the position tolerance), while a lubricated joint responds to
  // differences of that size between two bodies' coordinates; with it the default case's
  // minimum big-end film scattered by ±1 % with the step sequence (docs/validation/errors.md).
  // Velocities and angular velocities: 1/(rtol·|v| + atol).
  static int ErrorWeights(N_Vector y, N_Vector ewt, void* user) {
    auto* self = static_cast<Impl*>(user);
    const double* in = N_VGetArrayPointer(y);
    double* out = N_VGetArrayPointer(ewt);
    const IntegratorConfig& c = self->config;
    for (int k = 0; k < 2 * self->n; ++k) {
      const bool angle = k % 3 == 2;
      if (k < self->n) {
        out[k] = 1.0 / (angle ? c.angle_tolerance : c.position_tolerance);
      } else {
        const double atol = angle ? c.angular_velocity_tolerance : c.velocity_tolerance;
        out[k] = 1.0 / (c.relative_tolerance * std::abs(in[k]) + atol);
      }
    }
    return 0;
  }

  static void ErrorHandler(int /*code*/, const char* /*module*/, const char* function, char* msg,
                           void* user) {
    auto* self = static_cast<Impl*>(user);
    self->cvode_message = std::string(function) + ": " + msg;
  }

  void Check(int flag, const char* what) const {
    if (flag >= 0) return;
    const std::string message =
        std::string("CVODE ") + what + " failed (" + std::to_string(flag) + ") " + cvode_message +
        (last_failure.empty() ? "" : "; the last failed evaluation: " + last_failure);
    if (flag == CV_TOO_MUCH_ACC) throw TolerancesTooTight(message);
    if (!last_failure.empty() && !last_failure_contact.empty())
      throw SurfacesInContact(message, last_failure_contact);
    throw std::runtime_error(message);
  }
};

Integrator::Integrator(MultibodySystem& system, IntegratorConfig config)
    : impl_(std::make_unique<Impl>()) {
  impl_->system = &system;
  impl_->config = config;
  impl_->n = system.NumCoordinates();
}

Integrator::~Integrator() = default;

void Integrator::Initialize(double t0, const SystemState& state) {
  Impl& m = *impl_;
  const int size = 2 * m.n;
  if (!m.context) {
    m.Check(SUNContext_Create(nullptr, &m.context), "SUNContext_Create");
    m.y = N_VNew_Serial(size, m.context);
    m.matrix = SUNDenseMatrix(size, size, m.context);
    m.solver = SUNLinSol_Dense(m.y, m.matrix, m.context);
  }
  double* data = N_VGetArrayPointer(m.y);
  Eigen::Map<Eigen::VectorXd>(data, m.n) = state.q;
  Eigen::Map<Eigen::VectorXd>(data + m.n, m.n) = state.v;
  if (m.cvode) CVodeFree(&m.cvode);
  m.cvode = CVodeCreate(CV_BDF, m.context);
  m.Check(CVodeSetErrHandlerFn(m.cvode, &Impl::ErrorHandler, &m), "SetErrHandlerFn");
  m.Check(CVodeInit(m.cvode, &Impl::Rhs, t0, m.y), "CVodeInit");
  m.Check(CVodeSetUserData(m.cvode, &m), "SetUserData");
  m.Check(CVodeWFtolerances(m.cvode, &Impl::ErrorWeights), "WFtolerances");
  m.Check(CVodeSetLinearSolver(m.cvode, m.solver, m.matrix), "SetLinearSolver");
  m.Check(CVodeSetJacFn(m.cvode, &Impl::Jacobian), "SetJacFn");
  m.Check(CVodeSetMaxOrd(m.cvode, m.config.max_order), "SetMaxOrd");
  m.Check(CVodeSetMaxNumSteps(m.cvode, m.config.max_steps_per_output), "SetMaxNumSteps");
  if (m.config.max_step > 0) m.Check(CVodeSetMaxStep(m.cvode, m.config.max_step), "SetMaxStep");
  m.applied_max_step = m.config.max_step;
  m.scratch = state;
  t_ = t0;
}

SystemState Integrator::AdvanceTo(double t_out) {
  Impl& m = *impl_;
  double t_reached = t_;
  m.error = nullptr;
  m.last_failure.clear();
  m.last_failure_contact.clear();
  if (!m.system->WantsAcceptedSteps()) {
    const int flag = CVode(m.cvode, t_out, m.y, &t_reached, CV_NORMAL);
    if (m.error) std::rethrow_exception(m.error);
    m.Check(flag, "step");
  } else {
    // Step by step (what CV_NORMAL does inside): each accepted step's end goes to the elements
    // with a history, then the state at t_out is interpolated inside the last step.
    double t_step = 0.0;
    m.Check(CVodeGetCurrentTime(m.cvode, &t_step), "GetCurrentTime");
    long steps = 0;
    while (t_step < t_out) {
      if (++steps > m.config.max_steps_per_output)
        throw std::runtime_error(
            "CVODE step failed: " + std::to_string(m.config.max_steps_per_output) +
            " steps taken before reaching t = " + FormatValue(t_out));
      const int flag = CVode(m.cvode, t_out, m.y, &t_step, CV_ONE_STEP);
      if (m.error) std::rethrow_exception(m.error);
      m.Check(flag, "step");
      m.Unpack(m.y, &m.accepted);
      m.system->OnStepAccepted(t_step, m.accepted);
      // An element's own limit on the next step (a film history's local error, at the position
      // tolerance), within the configured largest step.
      double h_max = m.system->StepLimit(m.config.position_tolerance);
      if (m.config.max_step > 0.0 && (h_max == 0.0 || m.config.max_step < h_max))
        h_max = m.config.max_step;
      if (h_max != m.applied_max_step) {
        m.Check(CVodeSetMaxStep(m.cvode, h_max), "SetMaxStep");
        m.applied_max_step = h_max;
      }
    }
    m.Check(CVodeGetDky(m.cvode, t_out, 0, m.y), "GetDky");
    t_reached = t_out;
  }
  t_ = t_reached;
  SystemState state;
  m.Unpack(m.y, &state);
  return state;
}

void Integrator::SetTolerances(const IntegratorConfig& config) {
  IntegratorConfig& c = impl_->config;  // ErrorWeights reads these at every step
  c.relative_tolerance = config.relative_tolerance;
  c.position_tolerance = config.position_tolerance;
  c.angle_tolerance = config.angle_tolerance;
  c.velocity_tolerance = config.velocity_tolerance;
  c.angular_velocity_tolerance = config.angular_velocity_tolerance;
}

SolverStats Integrator::Stats() const {
  SolverStats s;
  const Impl& m = *impl_;
  if (!m.cvode) return s;
  CVodeGetNumSteps(m.cvode, &s.steps);
  CVodeGetNumErrTestFails(m.cvode, &s.rejected_steps);
  CVodeGetNumNonlinSolvIters(m.cvode, &s.newton_iterations);
  CVodeGetNumNonlinSolvConvFails(m.cvode, &s.newton_failures);
  CVodeGetNumRhsEvals(m.cvode, &s.rhs_evaluations);
  CVodeGetNumJacEvals(m.cvode, &s.jacobian_evaluations);
  CVodeGetLastStep(m.cvode, &s.last_step);
  CVodeGetLastOrder(m.cvode, &s.last_order);
  return s;
}

}  // namespace filmdyn::multibody
