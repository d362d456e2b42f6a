#include "core/multibody/joints.hpp"

#include <cassert>

namespace filmdyn::multibody {

RevoluteJoint::RevoluteJoint(std::string name, BodyIndex body_i, Eigen::Vector2d point_i,
                             BodyIndex body_j, Eigen::Vector2d point_j)
    : Constraint(std::move(name), body_i, body_j), point_i_(point_i), point_j_(point_j) {}

void RevoluteJoint::Evaluate(double /*t*/, const BodyState& i, const BodyState& j,
                             ConstraintBlock* out) const {
  const Eigen::Vector2d a_i = Rotation(i.Angle()) * point_i_;  // A_i s_i
  const Eigen::Vector2d a_j = Rotation(j.Angle()) * point_j_;
  out->phi = i.Position() + a_i - j.Position() - a_j;
  out->jac_i.setZero();
  out->jac_j.setZero();
  out->jac_i.block<2, 2>(0, 0).setIdentity();
  out->jac_i.col(2) = Perp(a_i);
  out->jac_j.block<2, 2>(0, 0) = -Eigen::Matrix2d::Identity();
  out->jac_j.col(2) = -Perp(a_j);
  out->phi_t.setZero();
  // d²(A s)/dt² = Perp(A s) θ̈ − A s θ̇²  ⇒  γ = A_i s_i θ̇_i² − A_j s_j θ̇_j².
  out->gamma = a_i * i.AngularVelocity() * i.AngularVelocity() -
               a_j * j.AngularVelocity() * j.AngularVelocity();
}

PrismaticJoint::PrismaticJoint(std::string name, BodyIndex body_i, Eigen::Vector2d point_i,
                               Eigen::Vector2d axis_i, BodyIndex body_j, Eigen::Vector2d point_j,
                               double relative_angle)
    : Constraint(std::move(name), body_i, body_j),
      point_i_(point_i),
      normal_i_(Perp(axis_i.normalized())),
      point_j_(point_j),
      relative_angle_(relative_angle) {
  assert(axis_i.norm() > 0.0);
}

void PrismaticJoint::Evaluate(double /*t*/, const BodyState& i, const BodyState& j,
                              ConstraintBlock* out) const {
  const Eigen::Matrix2d rot_i = Rotation(i.Angle());
  const Eigen::Vector2d a_i = rot_i * point_i_;
  const Eigen::Vector2d a_j = Rotation(j.Angle()) * point_j_;
  const Eigen::Vector2d n = rot_i * normal_i_;
  const Eigen::Vector2d d = j.Position() + a_j - i.Position() - a_i;
  const double w_i = i.AngularVelocity(), w_j = j.AngularVelocity();
  const Eigen::Vector2d d_dot = j.Velocity() + w_j * Perp(a_j) - i.Velocity() - w_i * Perp(a_i);

  out->jac_i.setZero();
  out->jac_j.setZero();
  // Row 0: lateral offset n·d.
  out->phi[0] = n.dot(d);
  out->jac_i.block<1, 2>(0, 0) = -n.transpose();
  out->jac_i(0, 2) = Perp(n).dot(d) - n.dot(Perp(a_i));
  out->jac_j.block<1, 2>(0, 0) = n.transpose();
  out->jac_j(0, 2) = n.dot(Perp(a_j));
  // Φ̈ = n̈·d + 2ṅ·ḋ + n·d̈ with ṅ = θ̇_i Perp(n), n̈ = θ̈_i Perp(n) − θ̇_i² n; collecting the
  // terms without accelerations gives −γ.
  out->gamma[0] = w_i * w_i * n.dot(d) - 2.0 * w_i * Perp(n).dot(d_dot) + w_j * w_j * n.dot(a_j) -
                  w_i * w_i * n.dot(a_i);
  // Row 1: relative rotation.
  out->phi[1] = j.Angle() - i.Angle() - relative_angle_;
  out->jac_i(1, 2) = -1.0;
  out->jac_j(1, 2) = 1.0;
  out->gamma[1] = 0.0;
  out->phi_t.setZero();
}

AngleLaw AngleLaw::ConstantSpeed(double angle0, double omega) {
  AngleLaw law;
  law.angle = [angle0, omega](double t) { return angle0 + omega * t; };
  law.rate = [omega](double) { return omega; };
  law.acceleration = [](double) { return 0.0; };
  return law;
}

DrivingConstraint::DrivingConstraint(std::string name, BodyIndex body_i, BodyIndex body_j,
                                     AngleLaw law)
    : Constraint(std::move(name), body_i, body_j), law_(std::move(law)) {
  assert(law_.angle && law_.rate && law_.acceleration);
}

void DrivingConstraint::Evaluate(double t, const BodyState& i, const BodyState& j,
                                 ConstraintBlock* out) const {
  out->phi[0] = j.Angle() - i.Angle() - law_.angle(t);
  out->jac_i.setZero();
  out->jac_j.setZero();
  out->jac_i(0, 2) = -1.0;
  out->jac_j(0, 2) = 1.0;
  out->phi_t[0] = -law_.rate(t);
  out->gamma[0] = law_.acceleration(t);  // γ = −Φ_tt
}

}  // namespace filmdyn::multibody
