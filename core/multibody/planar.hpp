#pragma once
/// @file Planar rigid-body kinematics helpers: body states, rotation matrices, the 90° rotation.
/// Conventions (docs/outputs.md): global frame X, Y, Z out of the plane; angles positive
/// counter-clockwise; every body's coordinates (x, y, θ) are those of its centre of mass.
#include <Eigen/Dense>

namespace filmdyn::multibody {

/// Index of a body in a MultibodySystem; kGround is the fixed global frame.
using BodyIndex = int;
inline constexpr BodyIndex kGround = -1;

/// Position (x, y, θ) and velocity (ẋ, ẏ, θ̇) of one body's centre of mass, global frame.
struct BodyState {
  Eigen::Vector3d q = Eigen::Vector3d::Zero();
  Eigen::Vector3d v = Eigen::Vector3d::Zero();

  Eigen::Vector2d Position() const { return q.head<2>(); }
  Eigen::Vector2d Velocity() const { return v.head<2>(); }
  double Angle() const { return q[2]; }
  double AngularVelocity() const { return v[2]; }
};

/// Rotation matrix A(θ) from body to global frame.
inline Eigen::Matrix2d Rotation(double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  Eigen::Matrix2d a;
  a << c, -s, s, c;
  return a;
}

/// The vector rotated by +90°: Perp(a) = R90·a; note dA/dθ·s = Perp(A·s).
inline Eigen::Vector2d Perp(const Eigen::Vector2d& a) { return {-a.y(), a.x()}; }

/// Scalar planar cross product a × b (z component).
inline double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

/// Global position of a body-fixed point s (body frame, relative to the centre of mass).
inline Eigen::Vector2d PointPosition(const BodyState& body, const Eigen::Vector2d& s) {
  return body.Position() + Rotation(body.Angle()) * s;
}

/// Global velocity of a body-fixed point s.
inline Eigen::Vector2d PointVelocity(const BodyState& body, const Eigen::Vector2d& s) {
  return body.Velocity() + body.AngularVelocity() * Perp(Rotation(body.Angle()) * s);
}

}  // namespace filmdyn::multibody
