// The ideal joints' Φ_q and γ (eq. 38) against finite differences of Φ along a trajectory, and
// the joint force element plumbing (wrench mapping, Jacobian check helper).
#include <QtTest>

#include <random>

#include "core/multibody/force_element.hpp"
#include "core/multibody/joints.hpp"

using namespace filmdyn::multibody;

namespace {

BodyState RandomBody(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  BodyState b;
  b.q << 0.3 * u(rng), 0.3 * u(rng), 3.0 * u(rng);
  b.v << 5.0 * u(rng), 5.0 * u(rng), 50.0 * u(rng);
  return b;
}

// Max relative error of Φ_q (central differences) and of γ = Φ_q a − Φ̈ (second difference of Φ
// along q(t) = q0 + v t + a t²/2).
void CheckConstraint(const Constraint& con, std::mt19937& rng, double* jac_error,
                     double* gamma_error) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const BodyState bi = RandomBody(rng), bj = RandomBody(rng);
  Eigen::Vector3d ai, aj;
  ai << 100 * u(rng), 100 * u(rng), 1000 * u(rng);
  aj << 100 * u(rng), 100 * u(rng), 1000 * u(rng);
  const double t0 = 0.01;
  ConstraintBlock block;
  block.Resize(con.Rows());
  con.Evaluate(t0, bi, bj, &block);
  auto phi_at = [&](const BodyState& x, const BodyState& y, double t) {
    ConstraintBlock b;
    b.Resize(con.Rows());
    con.Evaluate(t, x, y, &b);
    return Eigen::VectorXd(b.phi);
  };
  *jac_error = 0.0;
  const double h = 1e-6;
  for (int k = 0; k < 6; ++k) {
    BodyState xp = bi, xm = bi, yp = bj, ym = bj;
    (k < 3 ? xp.q[k] : yp.q[k - 3]) += h;
    (k < 3 ? xm.q[k] : ym.q[k - 3]) -= h;
    const Eigen::VectorXd numeric = (phi_at(xp, yp, t0) - phi_at(xm, ym, t0)) / (2 * h);
    const Eigen::VectorXd analytic =
        k < 3 ? Eigen::VectorXd(block.jac_i.col(k)) : Eigen::VectorXd(block.jac_j.col(k - 3));
    *jac_error = std::max(*jac_error, (numeric - analytic).cwiseAbs().maxCoeff() /
                                          std::max(1.0, analytic.cwiseAbs().maxCoeff()));
  }
  auto at_time = [](const BodyState& b, const Eigen::Vector3d& a, double dt) {
    BodyState x = b;
    x.q = b.q + b.v * dt + 0.5 * a * dt * dt;
    x.v = b.v + a * dt;
    return x;
  };
  const double dt = 1e-5;
  const Eigen::VectorXd phi_ddot =
      (phi_at(at_time(bi, ai, dt), at_time(bj, aj, dt), t0 + dt) - 2.0 * block.phi +
       phi_at(at_time(bi, ai, -dt), at_time(bj, aj, -dt), t0 - dt)) /
      (dt * dt);
  const Eigen::VectorXd gamma_numeric = block.jac_i * ai + block.jac_j * aj - phi_ddot;
  *gamma_error = (gamma_numeric - block.gamma).cwiseAbs().maxCoeff() /
                 std::max(1.0, block.gamma.cwiseAbs().maxCoeff());
}

// A linear spring–damper between two body points, with its analytic Jacobian (test element).
class SpringDamper final : public JointForceElement {
 public:
  SpringDamper(BodyIndex i, BodyIndex j, double k, double c)
      : JointForceElement("spring", i, j), k_(k), c_(c) {}
  bool ProvidesJacobian() const override { return true; }
  void EvaluateJoint(const JointForceInput& in, bool want, JointForceOutput* out) override {
    // Force on j: −k (r_j − r_i) − c (v_j − v_i) at the centres of mass (no moments).
    const Eigen::Vector2d f = -k_ * (in.body_j.Position() - in.body_i.Position()) -
                              c_ * (in.body_j.Velocity() - in.body_i.Velocity());
    out->wrench_j << f, 0.0;
    out->wrench_i << -f, 0.0;
    if (!want) return;
    out->jacobian.setZero();
    for (int a = 0; a < 2; ++a) {
      // rows of wrench_j (3..4) w.r.t. q_i (0..1), q_j (3..4), v_i (6..7), v_j (9..10)
      out->jacobian(3 + a, 0 + a) = k_;
      out->jacobian(3 + a, 3 + a) = -k_;
      out->jacobian(3 + a, 6 + a) = c_;
      out->jacobian(3 + a, 9 + a) = -c_;
      out->jacobian(0 + a, 0 + a) = -k_;
      out->jacobian(0 + a, 3 + a) = k_;
      out->jacobian(0 + a, 6 + a) = -c_;
      out->jacobian(0 + a, 9 + a) = c_;
    }
  }

 private:
  double k_, c_;
};

}  // namespace

class TestJoints : public QObject {
  Q_OBJECT
 private slots:
  void revoluteDerivatives() {
    std::mt19937 rng(1);
    const RevoluteJoint joint("r", 0, {0.02, -0.01}, 1, {-0.03, 0.05});
    for (int trial = 0; trial < 20; ++trial) {
      double je, ge;
      CheckConstraint(joint, rng, &je, &ge);
      QVERIFY2(je < 1e-8, qPrintable(QString("jacobian error %1").arg(je)));
      QVERIFY2(ge < 1e-4, qPrintable(QString("gamma error %1").arg(ge)));
    }
  }
  void prismaticDerivatives() {
    std::mt19937 rng(2);
    const PrismaticJoint joint("p", 0, {0.01, 0.02}, {0.6, 0.8}, 1, {-0.02, 0.01}, 0.3);
    for (int trial = 0; trial < 20; ++trial) {
      double je, ge;
      CheckConstraint(joint, rng, &je, &ge);
      QVERIFY2(je < 1e-8, qPrintable(QString("jacobian error %1").arg(je)));
      QVERIFY2(ge < 1e-4, qPrintable(QString("gamma error %1").arg(ge)));
    }
  }
  void drivingDerivatives() {
    std::mt19937 rng(3);
    AngleLaw law;
    law.angle = [](double t) { return 0.2 + 3.0 * t + 40.0 * t * t; };
    law.rate = [](double t) { return 3.0 + 80.0 * t; };
    law.acceleration = [](double) { return 80.0; };
    const DrivingConstraint joint("d", 0, 1, law);
    for (int trial = 0; trial < 5; ++trial) {
      double je, ge;
      CheckConstraint(joint, rng, &je, &ge);
      QVERIFY(je < 1e-8);
      QVERIFY2(ge < 1e-4, qPrintable(QString("gamma error %1").arg(ge)));
    }
    // Φ_t = −f'(t)
    ConstraintBlock block;
    block.Resize(1);
    joint.Evaluate(0.5, BodyState{}, BodyState{}, &block);
    QCOMPARE(block.phi_t[0], -(3.0 + 40.0));
  }
  void jointElementJacobianHelperDetectsErrors() {
    SpringDamper spring(0, 1, 1e5, 30.0);
    std::mt19937 rng(4);
    JointForceInput in;
    in.body_i = RandomBody(rng);
    in.body_j = RandomBody(rng);
    QVERIFY(JointJacobianMismatch(spring, in) < 1e-6);
    // A wrong Jacobian must be caught: flip one sign.
    class Broken final : public JointForceElement {
     public:
      Broken() : JointForceElement("broken", 0, 1), inner_(0, 1, 1e5, 30.0) {}
      bool ProvidesJacobian() const override { return true; }
      void EvaluateJoint(const JointForceInput& in, bool want, JointForceOutput* out) override {
        inner_.EvaluateJoint(in, want, out);
        out->jacobian(3, 3) *= -1.0;
      }
      SpringDamper inner_;
    } broken;
    QVERIFY(JointJacobianMismatch(broken, in) > 1e-3);
  }
  void jointElementMapsWrenchesToBodies() {
    SpringDamper spring(kGround, 1, 100.0, 0.0);
    SystemState state(2);
    state.q << 0, 0, 0, 0.1, -0.2, 0.0;
    Eigen::VectorXd q_force = Eigen::VectorXd::Zero(6);
    ForceJacobian jac;
    jac.Reset(6);
    spring.AddForces(0.0, state, q_force, &jac);
    QCOMPARE(q_force[3], -10.0);
    QCOMPARE(q_force[4], 20.0);
    QCOMPARE(q_force[0], 0.0);  // body 0 is not connected
    QCOMPARE(jac.dq(3, 3), -100.0);
  }
};

QTEST_GUILESS_MAIN(TestJoints)
#include "test_joints.moc"
