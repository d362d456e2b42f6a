#include "core/coupling/lubricated_big_end_element.hpp"

#include <algorithm>
#include <cmath>

#include "core/base/input_error.hpp"
#include "core/lubrication/surface_film.hpp"

namespace filmdyn::coupling {

using multibody::BodyState;
using multibody::Cross;
using multibody::Perp;
using multibody::Rotation;

namespace {

constexpr double kEpsFloor = 1e-3;  // line-of-centres regularisation (see header)

}  // namespace

LubricatedBigEndElement::LubricatedBigEndElement(lubrication::BearingConfig config,
                                                 multibody::BodyIndex crank,
                                                 multibody::BodyIndex rod, BigEndMounting mounting)
    : JointForceElement("lubricated big end", crank, rod),
      solver_(std::make_unique<lubrication::BearingSolver>(std::move(config))),
      mount_(mounting) {
  // Contact penalty: a film 1e-3 c thinner than at ε_max carries ~the bearing's projected area
  // times 1 GPa (far above any gas load: it only stops a run that is failing anyway).
  const lubrication::BearingGeometry& g = solver_->config().geometry;
  penalty_stiffness_ = 1e9 * 2.0 * g.radius * g.length / (1e-3 * g.radial_clearance);
}

namespace {

// z = (e, ė, ω_journal, ω_bearing), global; bearing_angle = rod angle (feed hole position).
using Cartesian = Eigen::Matrix<double, 6, 1>;

Cartesian CartesianOf(const BodyState& crank, const BodyState& rod, const BigEndMounting& mount) {
  const Eigen::Vector2d a_c = Rotation(crank.Angle()) * mount.journal_point;
  const Eigen::Vector2d a_r = Rotation(rod.Angle()) * mount.bearing_point;
  Cartesian z;
  z.segment<2>(0) = crank.Position() + a_c - rod.Position() - a_r;
  z.segment<2>(2) = crank.Velocity() + crank.AngularVelocity() * Perp(a_c) - rod.Velocity() -
                    rod.AngularVelocity() * Perp(a_r);
  z[4] = crank.AngularVelocity();
  z[5] = rod.AngularVelocity();
  return z;
}

BigEndKinematics FromCartesian(const Cartesian& z, double bearing_angle, double journal_angle,
                               double c, double eps_max) {
  BigEndKinematics k;
  k.ecc = z.segment<2>(0);
  k.ecc_rate = z.segment<2>(2);
  const double rho = k.ecc.norm();
  k.eps_true = rho / c;
  const double rho_reg = std::max(rho, kEpsFloor * c);
  const Eigen::Vector2d n = rho > 0.0 ? Eigen::Vector2d(k.ecc / rho) : Eigen::Vector2d(1.0, 0.0);
  k.state.eps = std::min(rho_reg / c, eps_max);
  k.state.eps_dot = n.dot(k.ecc_rate) / c;
  k.state.line_of_centres_angle = std::atan2(n.y(), n.x());
  k.state.line_of_centres_rate = Cross(k.ecc, k.ecc_rate) / (rho_reg * rho_reg);
  k.state.omega_journal = z[4];
  k.state.omega_bearing = z[5];
  k.state.bearing_angle = bearing_angle;
  k.state.journal_angle = journal_angle;
  return k;
}

}  // namespace

BigEndKinematics LubricatedBigEndElement::Kinematics(const BodyState& crank,
                                                     const BodyState& rod) const {
  BigEndKinematics k = FromCartesian(CartesianOf(crank, rod, mount_), rod.Angle(), crank.Angle(),
                                     solver_->config().geometry.radial_clearance, EpsMax());
  if (supply_pressure_) k.state.supply_pressure = supply_pressure_(crank.Angle());
  return k;
}

void LubricatedBigEndElement::PhaseIn(double law_end_time, double compliance_end_time) {
  phase_in_ = FilmPhaseIn(solver_->config().pressure_viscosity, law_end_time,
                          solver_->config().compliance.rigid(), compliance_end_time);
}

const lubrication::BearingResult& LubricatedBigEndElement::SolveFilm(
    const lubrication::BearingState& state, double t) {
  phase_in_.Apply(t, *solver_);
  return solver_->SolveAt(state, t);
}

Eigen::Vector4d LubricatedBigEndElement::Loads(const Eigen::Matrix<double, 6, 1>& z,
                                               double bearing_angle, BigEndKinematics* kin) {
  const double c = solver_->config().geometry.radial_clearance;
  *kin = FromCartesian(z, bearing_angle, journal_angle_, c, EpsMax());
  if (supply_pressure_) kin->state.supply_pressure = supply_pressure_(journal_angle_);
  factorizations_ += SolveFilm(kin->state, eval_time_).stats.factorizations;
  ++solves_;
  const lubrication::BearingResult& r = solver_->result();
  RequireConvergedFilm(r.stats, "big-end", solver_->config().solver.cavitation, &r.elastic);
  Eigen::Vector4d g(r.force_x, r.force_y, r.friction_torque_journal, r.friction_torque_bearing);
  const double over = kin->eps_true - EpsMax();
  if (over > 0.0) {  // contact penalty along −n
    const Eigen::Vector2d n = kin->ecc / kin->ecc.norm();
    g.head<2>() -= penalty_stiffness_ * over * c * n;
  }
  return g;
}

void LubricatedBigEndElement::EvaluateJoint(const multibody::JointForceInput& in,
                                            bool want_jacobian, multibody::JointForceOutput* out) {
  const bool timed = solver_->Transient() || phase_in_.VariesAfter(std::min(in.t, last_.input().t));
  if (last_.Serve(in, timed, want_jacobian, out)) return;
  const BodyState& crank = in.body_i;
  const BodyState& rod = in.body_j;
  const Eigen::Vector2d a_c = Rotation(crank.Angle()) * mount_.journal_point;
  const Eigen::Vector2d a_r = Rotation(rod.Angle()) * mount_.bearing_point;
  const Cartesian z = CartesianOf(crank, rod, mount_);
  eval_time_ = in.t;
  rod_angle_ = rod.Angle();
  journal_angle_ = crank.Angle();
  loads_ = Loads(z, rod_angle_, &kin_);
  result_ = solver_->result();
  const Eigen::Vector4d& g = loads_;
  const Eigen::Vector2d f = g.head<2>();
  out->wrench_i << f, Cross(a_c, f) + g[2];
  out->wrench_j << -f, -Cross(a_r, f) + g[3];
  out->jacobian.setZero();
  last_.Keep(in, *out);
  if (!want_jacobian) return;
  // ∂g/∂z by forward differences of the solver in the Cartesian unknowns, each increment 1e-4 of
  // its unknown's own scale: the clearance for e, for ė the clearance times the surfaces' angular
  // speeds plus 1 rad/s (the rate at which the film's wedge moves the journal) plus |ė|. A fixed
  // velocity increment was that rate's 2 % at 100 rpm: a secant through the film's squeeze
  // response, too coarse for a Newton iteration whose step is ~100 of the film's damping times.
  const double c = solver_->config().geometry.radial_clearance;
  const double de = 1e-4 * c;
  const double dv = 1e-4 * (c * (std::abs(z[4]) + std::abs(z[5]) + 1.0) + z.segment<2>(2).norm());
  const double steps[6] = {
      de, de, dv, dv, 1e-2 + 1e-6 * std::abs(z[4]), 1e-2 + 1e-6 * std::abs(z[5])};
  Eigen::Matrix<double, 4, 6> dg;
  BigEndKinematics scratch;
  for (int k = 0; k < 6; ++k) {
    Cartesian zp = z;
    zp[k] += steps[k];
    dg.col(k) = (Loads(zp, rod_angle_, &scratch) - g) / steps[k];
  }
  last_.SolverMovedOn();
  // dz/dx for x = (q_crank, q_rod, v_crank, v_rod).
  Eigen::Matrix<double, 6, 12> dz = Eigen::Matrix<double, 6, 12>::Zero();
  dz.block<2, 2>(0, 0).setIdentity();
  dz.block<2, 1>(0, 2) = Perp(a_c);
  dz.block<2, 2>(0, 3) = -Eigen::Matrix2d::Identity();
  dz.block<2, 1>(0, 5) = -Perp(a_r);
  dz.block<2, 1>(2, 2) = -crank.AngularVelocity() * a_c;
  dz.block<2, 1>(2, 5) = rod.AngularVelocity() * a_r;
  dz.block<2, 2>(2, 6).setIdentity();
  dz.block<2, 1>(2, 8) = Perp(a_c);
  dz.block<2, 2>(2, 9) = -Eigen::Matrix2d::Identity();
  dz.block<2, 1>(2, 11) = -Perp(a_r);
  dz(4, 8) = 1.0;
  dz(5, 11) = 1.0;
  // ∂W/∂g.
  Eigen::Matrix<double, 6, 4> dw = Eigen::Matrix<double, 6, 4>::Zero();
  dw(0, 0) = dw(1, 1) = 1.0;
  dw.row(2) << -a_c.y(), a_c.x(), 1.0, 0.0;
  dw(3, 0) = dw(4, 1) = -1.0;
  dw.row(5) << a_r.y(), -a_r.x(), 0.0, 1.0;
  out->jacobian = dw * dg * dz;
  out->jacobian(2, 2) += Cross(Perp(a_c), f);  // moment arms turn with the bodies
  out->jacobian(5, 5) += -Cross(Perp(a_r), f);
  last_.KeepJacobian(*out);
}

void LubricatedBigEndElement::OnStepAccepted(double t, const multibody::SystemState& state) {
  const lubrication::FilmHistory::Entry* from = solver_->history().Before(t);
  const double dt = from != nullptr ? t - from->time : 0.0;
  // The integrator's last evaluation at t (its last Newton iterate, within the Newton tolerance
  // of the accepted state) is what the step was accepted with: book that solve rather than a
  // new one (a third of the film solves).
  if (!last_.SolverHoldsAt(t)) {
    const BigEndKinematics kin = Kinematics(state.Body(BodyI()), state.Body(BodyJ()));
    factorizations_ += SolveFilm(kin.state, t).stats.factorizations;
    ++solves_;
    RequireConvergedFilm(solver_->result().stats, "big-end", solver_->config().solver.cavitation,
                         &solver_->result().elastic);
  }
  const lubrication::BearingResult& r = solver_->result();
  books_.Book(t, dt, r.feed_flow, r.side_flow, r.squeeze_rate, r.void_volume,
              r.stats.fraction_excess, r.max_pressure);
  solver_->AcceptStep(t);
  // Evaluations after this step from the new history; the fields are no longer the last's.
  last_.Drop();
}

void LubricatedBigEndElement::TakeSteps(double t, SkirtFilmSample*, BearingFilmSample* bearing) {
  books_.Take(t, &bearing->step_peak_pressure, &bearing->supply_flow, &bearing->side_flow);
}

void LubricatedBigEndElement::RefreshFields() {
  if (!last_.SolverMovedOnFromIt()) return;
  SolveFilm(kin_.state, last_.input().t);
  ++solves_;
  last_.SolverHoldsIt();
}

namespace {

// The state-derived part of a report: the journal's position (global and rod frame) and ε, ε̇.
void ReportKinematics(const BigEndKinematics& kin, double rod_angle, BearingFilmSample* b) {
  b->present = true;
  b->journal_ecc_global = kin.ecc;
  b->journal_ecc_rod = Rotation(rod_angle).transpose() * kin.ecc;
  b->eps = kin.eps_true;
  b->eps_dot = kin.state.eps_dot;
}

}  // namespace

void LubricatedBigEndElement::ReportMotion(const BodyState& crank, const BodyState& rod,
                                           BearingFilmSample* bearing) const {
  ReportKinematics(Kinematics(crank, rod), rod.Angle(), bearing);
}

void LubricatedBigEndElement::ReportFilm(SkirtFilmSample*, BearingFilmSample* bearing) const {
  BearingFilmSample& b = *bearing;
  ReportKinematics(kin_, rod_angle_, bearing);
  b.eps_max = EpsMax();
  // Past ε_max the film is solved at ε_max (a contact penalty acts beyond it, and the run ends):
  // the film that figure reports less the overlap the solve did not see.
  b.moft = result_.moft -
           solver_->config().geometry.radial_clearance * std::max(0.0, kin_.eps_true - EpsMax());
  b.fpl = result_.friction_power_loss;
  b.max_pressure = result_.max_pressure;
  b.max_contact_pressure = result_.max_contact_pressure;
  b.max_deformation = result_.max_deformation;
  b.friction_force = result_.friction_force_journal;
  b.contact_friction_force = result_.contact_friction_force_journal;
  b.contact_fpl = AsperityFrictionPower(b.fpl, b.friction_force, b.contact_friction_force);
  b.force_on_rod = -loads_.head<2>();
  b.friction_torque_journal = loads_[2];
  b.friction_torque_bearing = loads_[3];
  b.fraction_excess = result_.stats.fraction_excess;
  b.capped_nodes = result_.stats.capped_nodes;
  b.supply_flow = result_.feed_flow;
  b.side_flow = result_.side_flow;
  b.oil = books_.oil;
  b.power = loads_.head<2>().dot(kin_.ecc_rate) + loads_[2] * kin_.state.omega_journal +
            loads_[3] * kin_.state.omega_bearing;
}

}  // namespace filmdyn::coupling
