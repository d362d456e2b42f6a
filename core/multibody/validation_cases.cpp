#include "core/multibody/validation_cases.hpp"

#include <cmath>
#include <functional>
#include <string>

#include "core/multibody/integrator.hpp"
#include "core/multibody/joints.hpp"

namespace filmdyn::multibody {

namespace {

verification::ValidationRow PendulumRow() {
  const double mass = 1.3, inertia = 0.02, arm = 0.25, theta0 = 1.2, g = 9.81;
  MultibodySystem sys;
  sys.AddBody(Body{"bob", mass, inertia});
  sys.AddConstraint(std::make_unique<RevoluteJoint>("pivot", kGround, Eigen::Vector2d::Zero(), 0,
                                                    Eigen::Vector2d(0.0, arm)));
  sys.AddForceElement(std::make_unique<Gravity>(sys.Masses(), Eigen::Vector2d(0, -g)));
  sys.SetBaumgarte({20.0, 20.0});
  SystemState s(1);
  s.q << arm * std::sin(theta0), -arm * std::cos(theta0), theta0;
  sys.Assemble(0.0, &s);
  Integrator integrator(sys, IntegratorConfig{.relative_tolerance = 1e-10});
  integrator.Initialize(0.0, s);
  const double pivot_inertia = inertia + mass * arm * arm;
  const double period = 4.0 * std::sqrt(pivot_inertia / (mass * g * arm)) *
                        std::comp_ellint_1(std::sin(theta0 / 2.0));
  const SystemState end = integrator.AdvanceTo(period / 2);
  return {"multibody",
          "compound pendulum, 69 deg amplitude: angle after half a period [rad]",
          "complete elliptic integral K(sin(theta0/2))",
          end.q[2],
          -theta0,
          1e-6,
          true};
}

}  // namespace

std::vector<verification::ValidationRow> MultibodyValidationRows() {
  return {PendulumRow()};
}

}  // namespace filmdyn::multibody
