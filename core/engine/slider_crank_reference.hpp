#pragma once
/// @file Closed-form reference for the ideal crank train at constant crank speed, independent of
/// the multibody engine: the exact offset slider-crank kinematics (e.g. Heywood 1988 §2.2 with
/// pin offset) and a Newton–Euler solution of the rod and piston free bodies for the joint
/// forces. Used by tests and `filmdyn validate`. Conventions as in crank_train.hpp.
#include <Eigen/Dense>

#include "core/engine/engine_case.hpp"

namespace filmdyn::engine {

struct SliderCrankReference {
  double piston_position = 0.0, piston_velocity = 0.0, piston_acceleration = 0.0;  ///< pin Y
  double rod_angle = 0.0, rod_angular_velocity = 0.0, rod_angular_acceleration = 0.0;
  double liner_force_x = 0.0;                               ///< liner on piston [N]
  double liner_moment_about_pin = 0.0;                      ///< liner on piston [N·m]
  Eigen::Vector2d big_end_force = Eigen::Vector2d::Zero();  ///< crank pin on rod [N]
  Eigen::Vector2d pin_force = Eigen::Vector2d::Zero();      ///< rod on piston [N]
  double crank_torque = 0.0;                                ///< drive torque on the crank [N·m]
};

/// Stroke of the offset slider crank, the pin's travel between its dead centres (crank and rod
/// in line): sqrt((L₂ + L₁)² − C_p²) − sqrt((L₂ − L₁)² − C_p²) [m].
double Stroke(const CrankTrainGeometry& g);
/// Swept volume of the cylinder: π R_l² × stroke [m³].
double SweptVolume(const CrankTrainGeometry& g);

/// At crank angle phi [rad], speed omega [rad/s] (constant) and gas force [N] (+ toward crank).
SliderCrankReference ExactSliderCrank(const CrankTrainGeometry& g, double phi, double omega,
                                      double gas_force);

}  // namespace filmdyn::engine
