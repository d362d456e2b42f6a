#include "core/coupling/lubricated_skirt_element.hpp"

#include <algorithm>
#include <cmath>

#include "core/base/input_error.hpp"
#include "core/lubrication/surface_film.hpp"

namespace filmdyn::coupling {

using multibody::BodyState;

LubricatedSkirtElement::LubricatedSkirtElement(lubrication::SkirtConfig config,
                                               multibody::BodyIndex piston, SkirtMounting mounting)
    : JointForceElement("lubricated skirt", multibody::kGround, piston),
      solver_(std::make_unique<lubrication::SkirtSolver>(std::move(config))),
      mount_(mounting) {}

SkirtKinematics LubricatedSkirtElement::Kinematics(const BodyState& piston) const {
  SkirtKinematics k;
  const double th = piston.Angle(), c = std::cos(th), s = std::sin(th);
  const double cg = mount_.com_lateral_offset,
               arm = mount_.skirt_top_to_pin - mount_.skirt_top_to_com;
  k.jac << 1.0, 0.0, cg * s + arm * c,  // e0
      0.0, 0.0, c,                      // γ = sin θ
      0.0, -1.0, cg * c - arm * s;      // s = −Y of the axis at pin height
  const Eigen::Vector3d rates = k.jac * piston.v;
  k.state.e0 = piston.q[0] - cg * c + arm * s;
  k.state.gamma = s;
  k.state.e0_dot = rates[0];
  k.state.gamma_dot = rates[1];
  k.state.piston_velocity = rates[2];
  // The pin's height (the CoM's, less the pin arm along the tilted axis): how far the piston
  // is down the stroke.
  k.state.stroke_position = mount_.pin_y_at_tdc - (piston.q[1] - arm * c - cg * s);
  const lubrication::SkirtGap gap = solver_->MinRigidGap(k.state.e0, k.state.gamma);
  k.min_gap = gap.gap;
  k.min_gap_alpha = gap.alpha;
  k.min_gap_y = gap.y;
  return k;
}

double LubricatedSkirtElement::MinGapAllowed() const {
  const lubrication::SkirtConfig& c = solver_->config();
  return c.compliance.rigid() ? 0.0 : -kElasticPenetration * c.geometry.radial_clearance;
}

void LubricatedSkirtElement::PhaseIn(double law_end_time, double compliance_end_time) {
  phase_in_ = FilmPhaseIn(solver_->config().pressure_viscosity, law_end_time,
                          solver_->config().compliance.rigid(), compliance_end_time);
}

void LubricatedSkirtElement::SolveAt(const lubrication::SkirtState& state) {
  phase_in_.Apply(eval_time_, *solver_);
  factorizations_ += solver_->SolveAt(state, eval_time_).stats.factorizations;
  ++solves_;
  RequireConvergedFilm(solver_->result().stats, "skirt", solver_->config().solver.cavitation,
                       &solver_->result().elastic);
}

Eigen::Vector3d LubricatedSkirtElement::Generalised(const lubrication::SkirtResult& r) const {
  return {r.lateral_force, r.moment_about_pin, r.friction_force};
}

void LubricatedSkirtElement::EvaluateJoint(const multibody::JointForceInput& in, bool want_jacobian,
                                           multibody::JointForceOutput* out) {
  const bool timed = solver_->Transient() || phase_in_.VariesAfter(std::min(in.t, last_.input().t));
  if (last_.Serve(in, timed, want_jacobian, out)) return;
  kin_ = Kinematics(in.body_j);
  eval_time_ = in.t;
  SolveAt(kin_.state);
  result_ = solver_->result();
  const Eigen::Vector3d g = Generalised(result_);
  out->wrench_j = kin_.jac.transpose() * g;
  out->wrench_i << -out->wrench_j[0], -out->wrench_j[1], 0.0;  // ground: force only
  out->jacobian.setZero();
  last_.Keep(in, *out);
  if (!want_jacobian) return;
  // ∂G/∂z by forward differences of the solver, z = (e0, γ, ė0, γ̇, u_p), each increment 1e-4 of
  // its unknown's own scale: the clearance for e0 (over the skirt length for γ), for ė0 the
  // clearance times the sliding's frequency |u_p|/L plus 1 s⁻¹ (the lateral rate at which the
  // sliding's wedge moves the skirt) plus |ė0|, and |u_p| plus the skirt length per second for
  // u_p. Fixed velocity increments (0.1 mm/s laterally) were a third of that rate at 100 rpm: a
  // secant through the film's squeeze response, too coarse for the Newton iteration of a stiff
  // film.
  const lubrication::SkirtGeometry& geo = solver_->config().geometry;
  const double c_p = geo.radial_clearance, L = geo.skirt_length;
  const lubrication::SkirtState& z0 = kin_.state;
  const double u = std::abs(z0.piston_velocity);
  const double dv = 1e-4 * (c_p * (u / L + 1.0) + std::abs(z0.e0_dot));
  const double steps[5] = {1e-4 * c_p, 1e-4 * c_p / L, dv, dv / L, 1e-4 * (u + L)};
  Eigen::Matrix<double, 3, 5> dg;
  for (int k = 0; k < 5; ++k) {
    lubrication::SkirtState z = z0;
    double* entry[5] = {&z.e0, &z.gamma, &z.e0_dot, &z.gamma_dot, &z.piston_velocity};
    *entry[k] += steps[k];
    SolveAt(z);
    dg.col(k) = (Generalised(solver_->result()) - g) / steps[k];
  }
  last_.SolverMovedOn();
  // Chain rule: z_pos = (e0, γ) = f(q), z_vel = (ė0, γ̇, u_p) = J(q) v.
  const double th = in.body_j.Angle(), c = std::cos(th), s = std::sin(th);
  const double cg = mount_.com_lateral_offset,
               arm = mount_.skirt_top_to_pin - mount_.skirt_top_to_com;
  Eigen::Matrix3d djac = Eigen::Matrix3d::Zero();  // ∂J/∂θ
  djac(0, 2) = cg * c - arm * s;
  djac(1, 2) = -s;
  djac(2, 2) = -cg * s - arm * c;
  Eigen::Matrix<double, 5, 3> dz_dq = Eigen::Matrix<double, 5, 3>::Zero();
  dz_dq.row(0) = kin_.jac.row(0);
  dz_dq.row(1) = kin_.jac.row(1);
  dz_dq.block<3, 1>(2, 2) = djac * in.body_j.v;
  Eigen::Matrix<double, 5, 3> dz_dv = Eigen::Matrix<double, 5, 3>::Zero();
  dz_dv.block<3, 3>(2, 0) = kin_.jac;
  Eigen::Matrix3d dq_force = kin_.jac.transpose() * dg * dz_dq;
  dq_force.col(2) += djac.transpose() * g;
  const Eigen::Matrix3d dv_force = kin_.jac.transpose() * dg * dz_dv;
  out->jacobian.block<3, 3>(3, 3) = dq_force;
  out->jacobian.block<3, 3>(3, 9) = dv_force;
  out->jacobian.block<2, 3>(0, 3) = -dq_force.topRows<2>();
  out->jacobian.block<2, 3>(0, 9) = -dv_force.topRows<2>();
  last_.KeepJacobian(*out);
}

void LubricatedSkirtElement::OnStepAccepted(double t, const multibody::SystemState& state) {
  const lubrication::FilmHistory::Entry* from = solver_->history().Before(t);
  const double dt = from != nullptr ? t - from->time : 0.0;
  // The integrator's last evaluation at t (its last Newton iterate, within the Newton tolerance
  // of the accepted state) is what the step was accepted with: book that solve rather than a
  // new one (a third of the film solves).
  if (!last_.SolverHoldsAt(t)) {
    eval_time_ = t;
    SolveAt(Kinematics(state.Body(BodyJ())).state);
  }
  const lubrication::SkirtResult& r = solver_->result();
  books_.Book(t, dt, r.inflow, r.outflow, r.squeeze_rate, r.void_volume, r.stats.fraction_excess,
              r.max_pressure);
  solver_->AcceptStep(t);
  // Evaluations after this step from the new history; the fields are no longer the last's.
  last_.Drop();
}

void LubricatedSkirtElement::TakeSteps(double t, SkirtFilmSample* skirt, BearingFilmSample*) {
  books_.Take(t, &skirt->step_peak_pressure, &skirt->inflow, &skirt->outflow);
}

void LubricatedSkirtElement::RefreshFields() {
  if (!last_.SolverMovedOnFromIt()) return;
  eval_time_ = last_.input().t;
  SolveAt(kin_.state);
  last_.SolverHoldsIt();
}

void LubricatedSkirtElement::ReportFilm(SkirtFilmSample* skirt, BearingFilmSample*) const {
  SkirtFilmSample& f = *skirt;
  f.present = true;
  f.normal_force = result_.lateral_force;
  f.contact_normal_force = result_.contact_lateral_force;
  f.friction_force = result_.friction_force;
  f.moment_about_pin = result_.moment_about_pin;
  // On rigid surfaces a film thinner than the solver's floor is held at the floor: there the
  // geometric gap is the figure (negative where the skirt has passed the liner's wall, which ends
  // the run: the floor would read as a film).
  const bool gap = result_.clamped_nodes > 0 && kin_.min_gap < result_.moft;
  f.moft = gap ? kin_.min_gap : result_.moft;
  f.fpl = result_.friction_power_loss;
  f.max_pressure = result_.max_pressure;
  f.max_contact_pressure = result_.max_contact_pressure;
  f.max_deformation = result_.max_deformation;
  f.contact_friction_force = result_.contact_friction_force;
  f.contact_fpl = AsperityFrictionPower(f.fpl, f.friction_force, f.contact_friction_force);
  f.moft_alpha = gap ? kin_.min_gap_alpha : result_.moft_alpha;
  f.moft_y = gap ? kin_.min_gap_y : result_.moft_y;
  f.min_gap = kin_.min_gap;
  f.min_gap_allowed = MinGapAllowed();
  f.clamped_nodes = result_.clamped_nodes;
  f.e0 = kin_.state.e0;
  f.tilt = kin_.state.gamma;
  f.e0_rate = kin_.state.e0_dot;
  f.tilt_rate = kin_.state.gamma_dot;
  f.speed = kin_.state.piston_velocity;
  f.fraction_excess = result_.stats.fraction_excess;
  f.capped_nodes = result_.stats.capped_nodes;
  f.inflow = result_.inflow;
  f.outflow = result_.outflow;
  f.wetted_fraction = result_.wetted_fraction;
  f.oil = books_.oil;
  f.power = result_.lateral_force * kin_.state.e0_dot +
            result_.moment_about_pin * kin_.state.gamma_dot +
            result_.friction_force * kin_.state.piston_velocity;
}

}  // namespace filmdyn::coupling
