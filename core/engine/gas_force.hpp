#pragma once
/// @file The gas force on the piston crown: F = (p_cyl(φ) − p_crankcase)·π R_l², along
/// the cylinder axis toward the crank, its line of action the piston axis. φ is read from the
/// crank body's angle, so the element works for imposed and free crank speeds alike.
#include "core/engine/pressure_curve.hpp"
#include "core/multibody/force_element.hpp"

namespace filmdyn::engine {

class GasForce final : public multibody::ForceElement {
 public:
  /// axis_point_piston: a point on the piston axis in the piston's body frame [m].
  GasForce(PressureCurve curve, double crankcase_pressure, double bore_radius,
           multibody::BodyIndex crank, double crank_angle_offset, multibody::BodyIndex piston,
           Eigen::Vector2d axis_point_piston);
  std::vector<multibody::BodyIndex> Bodies() const override { return {crank_, piston_}; }
  void AddForces(double t, const multibody::SystemState& state, Eigen::Ref<Eigen::VectorXd> q_force,
                 multibody::ForceJacobian* jacobian) override;

  /// Crank angle [rad] of a state (unwrapped).
  double CrankAngle(const multibody::SystemState& state) const;
  /// Cylinder pressure [Pa] and gas force magnitude [N] (+ toward the crank) at a crank angle.
  double CylinderPressure(double crank_angle) const { return curve_.Pressure(crank_angle); }
  double Force(double crank_angle) const;
  const PressureCurve& Curve() const { return curve_; }

 private:
  PressureCurve curve_;
  double crankcase_pressure_;
  double area_;
  multibody::BodyIndex crank_;
  double crank_angle_offset_;
  multibody::BodyIndex piston_;
  Eigen::Vector2d axis_point_;
};

}  // namespace filmdyn::engine
