#include "core/engine/gas_force.hpp"

#include <numbers>

namespace filmdyn::engine {

using multibody::BodyState;

GasForce::GasForce(PressureCurve curve, double crankcase_pressure, double bore_radius,
                   multibody::BodyIndex crank, double crank_angle_offset,
                   multibody::BodyIndex piston, Eigen::Vector2d axis_point_piston)
    : ForceElement("gas force"),
      curve_(std::move(curve)),
      crankcase_pressure_(crankcase_pressure),
      area_(std::numbers::pi * bore_radius * bore_radius),
      crank_(crank),
      crank_angle_offset_(crank_angle_offset),
      piston_(piston),
      axis_point_(axis_point_piston) {}

double GasForce::CrankAngle(const multibody::SystemState& state) const {
  return state.Body(crank_).Angle() - crank_angle_offset_;
}

double GasForce::Force(double crank_angle) const {
  return (curve_.Pressure(crank_angle) - crankcase_pressure_) * area_;
}

void GasForce::AddForces(double /*t*/, const multibody::SystemState& state,
                         Eigen::Ref<Eigen::VectorXd> q_force,
                         multibody::ForceJacobian* /*jacobian*/) {
  const BodyState piston = state.Body(piston_);
  const Eigen::Vector2d force(0.0, -Force(CrankAngle(state)));  // −Y: toward the crank
  const Eigen::Vector2d arm = multibody::Rotation(piston.Angle()) * axis_point_;
  q_force.segment<2>(3 * piston_) += force;
  q_force[3 * piston_ + 2] += multibody::Cross(arm, force);
}

}  // namespace filmdyn::engine
