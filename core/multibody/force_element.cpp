#include "core/multibody/force_element.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace filmdyn::multibody {

void Gravity::AddForces(double /*t*/, const SystemState& state, Eigen::Ref<Eigen::VectorXd> q_force,
                        ForceJacobian* /*jacobian*/) {
  assert(static_cast<int>(masses_.size()) == state.NumBodies());
  for (int k = 0; k < state.NumBodies(); ++k) {
    q_force.segment<2>(3 * k) += masses_[k] * g_;
  }
}

std::vector<BodyIndex> JointForceElement::Bodies() const {
  std::vector<BodyIndex> bodies;
  if (body_i_ != kGround) bodies.push_back(body_i_);
  if (body_j_ != kGround) bodies.push_back(body_j_);
  return bodies;
}

void JointForceElement::AddForces(double t, const SystemState& state,
                                  Eigen::Ref<Eigen::VectorXd> q_force, ForceJacobian* jacobian) {
  JointForceInput in;
  in.t = t;
  in.body_i = state.Body(body_i_);
  in.body_j = state.Body(body_j_);
  JointForceOutput out;
  const bool want = jacobian != nullptr && ProvidesJacobian();
  EvaluateJoint(in, want, &out);
  const BodyIndex bodies[2] = {body_i_, body_j_};
  const Eigen::Vector3d* wrenches[2] = {&out.wrench_i, &out.wrench_j};
  for (int a = 0; a < 2; ++a) {
    if (bodies[a] != kGround) q_force.segment<3>(3 * bodies[a]) += *wrenches[a];
  }
  if (!want) return;
  for (int a = 0; a < 2; ++a) {
    if (bodies[a] == kGround) continue;
    for (int b = 0; b < 2; ++b) {
      if (bodies[b] == kGround) continue;
      jacobian->dq.block<3, 3>(3 * bodies[a], 3 * bodies[b]) +=
          out.jacobian.block<3, 3>(3 * a, 3 * b);
      jacobian->dv.block<3, 3>(3 * bodies[a], 3 * bodies[b]) +=
          out.jacobian.block<3, 3>(3 * a, 6 + 3 * b);
    }
  }
}

Eigen::Matrix<double, 6, 12> JointJacobianByDifferences(JointForceElement& element,
                                                        const JointForceInput& in, double h) {
  Eigen::Matrix<double, 6, 12> numeric;
  for (int c = 0; c < 12; ++c) {
    JointForceInput plus = in, minus = in;
    auto entry = [c](JointForceInput& x) -> double& {
      BodyState& body = (c % 6) < 3 ? x.body_i : x.body_j;
      return c < 6 ? body.q[c % 3] : body.v[c % 3];
    };
    const double step = h * std::max(1.0, std::abs(entry(plus)));
    entry(plus) += step;
    entry(minus) -= step;
    JointForceOutput fp, fm;
    element.EvaluateJoint(plus, false, &fp);
    element.EvaluateJoint(minus, false, &fm);
    numeric.block<3, 1>(0, c) = (fp.wrench_i - fm.wrench_i) / (2 * step);
    numeric.block<3, 1>(3, c) = (fp.wrench_j - fm.wrench_j) / (2 * step);
  }
  return numeric;
}

double JointJacobianMismatch(JointForceElement& element, const JointForceInput& in, double h) {
  JointForceOutput analytic;
  element.EvaluateJoint(in, true, &analytic);
  const Eigen::Matrix<double, 6, 12> numeric = JointJacobianByDifferences(element, in, h);
  const double scale = std::max(analytic.jacobian.cwiseAbs().maxCoeff(), 1e-300);
  return (analytic.jacobian - numeric).cwiseAbs().maxCoeff() / scale;
}

}  // namespace filmdyn::multibody
