#pragma once
/// @file The evolving state of a planar multibody system: q = (x, y, θ) per body, v = q̇.
#include <Eigen/Dense>

#include "core/multibody/planar.hpp"

namespace filmdyn::multibody {

struct SystemState {
  Eigen::VectorXd q;  ///< 3 per body: x [m], y [m], θ [rad] of the centre of mass, global
  Eigen::VectorXd v;  ///< time derivatives of q

  SystemState() = default;
  explicit SystemState(int num_bodies)
      : q(Eigen::VectorXd::Zero(3 * num_bodies)), v(Eigen::VectorXd::Zero(3 * num_bodies)) {}

  int NumBodies() const { return static_cast<int>(q.size() / 3); }

  /// State of one body; the ground (kGround) is at rest at the origin.
  BodyState Body(BodyIndex index) const {
    BodyState body;
    if (index == kGround) return body;
    body.q = q.segment<3>(3 * index);
    body.v = v.segment<3>(3 * index);
    return body;
  }
  void SetBody(BodyIndex index, const BodyState& body) {
    q.segment<3>(3 * index) = body.q;
    v.segment<3>(3 * index) = body.v;
  }
};

}  // namespace filmdyn::multibody
