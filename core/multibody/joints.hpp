#pragma once
/// @file The ideal joints: revolute, prismatic and the driving (prescribed relative angle)
/// constraint. Formulas: Nikravesh (1988) §6.2–6.4, derived again in docs/validation/multibody.md
/// and checked against finite differences in tests/core/multibody/test_joints.cpp.
#include <functional>

#include "core/multibody/constraint.hpp"

namespace filmdyn::multibody {

/// Point s_i of body i coincides with point s_j of body j (2 rows):
/// Φ = r_i + A_i s_i − r_j − A_j s_j. The reaction on body j is λ applied at the joint point.
class RevoluteJoint final : public Constraint {
 public:
  RevoluteJoint(std::string name, BodyIndex body_i, Eigen::Vector2d point_i, BodyIndex body_j,
                Eigen::Vector2d point_j);
  int Rows() const override { return 2; }
  void Evaluate(double t, const BodyState& i, const BodyState& j,
                ConstraintBlock* out) const override;
  const Eigen::Vector2d& PointI() const { return point_i_; }
  const Eigen::Vector2d& PointJ() const { return point_j_; }

 private:
  Eigen::Vector2d point_i_, point_j_;
};

/// Body j slides along an axis fixed in body i without relative rotation (2 rows):
/// row 0: n_i · (r_Pj − r_Pi) = 0 with n_i = A_i · Perp(axis_i) (the lateral offset),
/// row 1: θ_j − θ_i − Δθ_0 = 0.
class PrismaticJoint final : public Constraint {
 public:
  PrismaticJoint(std::string name, BodyIndex body_i, Eigen::Vector2d point_i,
                 Eigen::Vector2d axis_i, BodyIndex body_j, Eigen::Vector2d point_j,
                 double relative_angle = 0.0);
  int Rows() const override { return 2; }
  void Evaluate(double t, const BodyState& i, const BodyState& j,
                ConstraintBlock* out) const override;

 private:
  Eigen::Vector2d point_i_, normal_i_, point_j_;
  double relative_angle_;
};

/// A prescribed relative angle θ_j − θ_i = f(t) and its first two time derivatives.
struct AngleLaw {
  std::function<double(double)> angle;         ///< f(t) [rad]
  std::function<double(double)> rate;          ///< f'(t) [rad/s]
  std::function<double(double)> acceleration;  ///< f''(t) [rad/s²]

  /// f(t) = angle0 + omega·t.
  static AngleLaw ConstantSpeed(double angle0, double omega);
};

/// Driving constraint (1 row): θ_j − θ_i − f(t) = 0.
class DrivingConstraint final : public Constraint {
 public:
  DrivingConstraint(std::string name, BodyIndex body_i, BodyIndex body_j, AngleLaw law);
  int Rows() const override { return 1; }
  void Evaluate(double t, const BodyState& i, const BodyState& j,
                ConstraintBlock* out) const override;
  const AngleLaw& Law() const { return law_; }

 private:
  AngleLaw law_;
};

}  // namespace filmdyn::multibody
