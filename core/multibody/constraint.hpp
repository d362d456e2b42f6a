#pragma once
/// @file Ideal (holonomic, possibly rheonomic) joint constraints Φ(q_i, q_j, t) = 0 between two
/// bodies, either of which may be the ground. Each constraint supplies the blocks of
/// eqs. 33–39 (Nikravesh 1988 ch. 6): Φ, Φ_q, Φ_t and γ of eq. 38.
#include <Eigen/Dense>
#include <string>

#include "core/multibody/planar.hpp"

namespace filmdyn::multibody {

/// Constraint rows evaluated at one state.
struct ConstraintBlock {
  Eigen::VectorXd phi;                 ///< Φ (rows)
  Eigen::Matrix<double, -1, 3> jac_i;  ///< ∂Φ/∂q_i (rows × 3)
  Eigen::Matrix<double, -1, 3> jac_j;  ///< ∂Φ/∂q_j (rows × 3)
  Eigen::VectorXd phi_t;               ///< ∂Φ/∂t
  Eigen::VectorXd gamma;  ///< γ = −(Φ_q q̇)_q q̇ − 2Φ_qt q̇ − Φ_tt (eq. 38)

  void Resize(int rows) {
    phi.setZero(rows);
    jac_i.setZero(rows, 3);
    jac_j.setZero(rows, 3);
    phi_t.setZero(rows);
    gamma.setZero(rows);
  }
};

/// Generalised reaction of one joint on both bodies: (F_x, F_y, M_z about the centre of mass),
/// global frame, = −Φ_qk^T λ (eq. 35; García de Jalón & Bayo 1994).
struct JointReaction {
  Eigen::Vector3d on_i = Eigen::Vector3d::Zero();
  Eigen::Vector3d on_j = Eigen::Vector3d::Zero();
};

class Constraint {
 public:
  Constraint(std::string name, BodyIndex body_i, BodyIndex body_j)
      : name_(std::move(name)), body_i_(body_i), body_j_(body_j) {}
  virtual ~Constraint() = default;

  const std::string& Name() const { return name_; }
  BodyIndex BodyI() const { return body_i_; }
  BodyIndex BodyJ() const { return body_j_; }
  virtual int Rows() const = 0;
  /// Fills `out` (already sized to Rows()) at time t for the states of bodies i and j.
  virtual void Evaluate(double t, const BodyState& i, const BodyState& j,
                        ConstraintBlock* out) const = 0;

 private:
  std::string name_;
  BodyIndex body_i_;
  BodyIndex body_j_;
};

}  // namespace filmdyn::multibody
