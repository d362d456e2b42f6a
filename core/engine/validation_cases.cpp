#include "core/engine/validation_cases.hpp"

#include <cmath>
#include <functional>
#include <numbers>
#include <string>

#include "core/base/angles.hpp"
#include "core/engine/crank_train.hpp"
#include "core/engine/slider_crank_reference.hpp"
#include "core/multibody/integrator.hpp"

namespace filmdyn::engine {

namespace {

using multibody::Integrator;
using multibody::IntegratorConfig;
using multibody::SystemState;
constexpr double kPi = std::numbers::pi;

PressureCurve FiringCurve(double peak) {
  std::vector<double> a, p;
  for (int k = 0; k < 720; ++k) {
    a.push_back(k * kRadiansPerDegree);
    p.push_back(1e5 + peak * std::exp(-std::pow((k - 372.0) / 25.0, 2)));
  }
  return PressureCurve(a, p, "validation curve");
}

void CrankTrainRows(double rpm, double peak, std::vector<verification::ValidationRow>* rows) {
  EngineCase c;
  CrankTrain train = BuildCrankTrain(c, rpm, FiringCurve(peak));
  Integrator integrator(*train.system, IntegratorConfig{.relative_tolerance = 1e-9});
  integrator.Initialize(0.0, train.initial_state);
  const double omega = train.layout.omega, cycle = 4 * kPi / omega;
  using Get = std::function<double(const CrankTrainSample&)>;
  using GetRef = std::function<double(const SliderCrankReference&)>;
  struct Quantity {
    const char* name;
    Get ours;
    GetRef exact;
    double tolerance;
    double peak = 0, deviation = 0;
  };
  std::vector<Quantity> q = {
      {"piston acceleration", [](auto& s) { return s.piston_acceleration; },
       [](auto& e) { return e.piston_acceleration; }, 1e-6},
      {"rod angular acceleration", [](auto& s) { return s.rod_angular_acceleration; },
       [](auto& e) { return e.rod_angular_acceleration; }, 1e-6},
      {"liner side force", [](auto& s) { return s.liner_force_on_piston.x(); },
       [](auto& e) { return e.liner_force_x; }, 1e-5},
      {"big-end force x", [](auto& s) { return s.big_end_force_on_rod.x(); },
       [](auto& e) { return e.big_end_force.x(); }, 1e-5},
      {"big-end force y", [](auto& s) { return s.big_end_force_on_rod.y(); },
       [](auto& e) { return e.big_end_force.y(); }, 1e-5},
  };
  double raw_peak = 0, raw_deviation = 0;
  for (int k = 1; k <= 720; ++k) {
    const double t = cycle + k * cycle / 720;  // second cycle
    const SystemState s = integrator.AdvanceTo(t);
    const CrankTrainSample sample = SampleCrankTrain(train, c, t, s);
    const SliderCrankReference exact =
        ExactSliderCrank(c.geometry, omega * t, omega, sample.gas_force);
    for (Quantity& x : q) {
      x.peak = std::max(x.peak, std::abs(x.exact(exact)));
      x.deviation = std::max(x.deviation, std::abs(x.ours(sample) - x.exact(exact)));
    }
    const double raw_y =
        multibody::PointPosition(s.Body(train.layout.piston), train.layout.piston_pin_point).y();
    raw_peak = std::max(raw_peak, std::abs(exact.piston_position));
    raw_deviation = std::max(raw_deviation, std::abs(raw_y - exact.piston_position));
  }
  const std::string speed = std::to_string(static_cast<int>(rpm)) + " rpm, " +
                            std::to_string(static_cast<int>(peak / 1e5)) + " bar peak";
  rows->push_back({"multibody", "crank train " + speed + ": integrated piston position",
                   "exact offset slider crank (closed form)", raw_peak + raw_deviation, raw_peak,
                   1e-6, true});
  for (const Quantity& x : q) {
    const bool kinematic = x.tolerance < 1e-5;
    rows->push_back({"multibody", "crank train " + speed + ": " + x.name,
                     kinematic ? "exact offset slider crank (closed form)"
                               : "Newton-Euler free bodies (closed form)",
                     x.peak + x.deviation, x.peak, x.tolerance, true});
  }
}

}  // namespace

std::vector<verification::ValidationRow> CrankTrainValidationRows() {
  std::vector<verification::ValidationRow> rows;
  CrankTrainRows(1000, 6e6, &rows);
  CrankTrainRows(6000, 7e6, &rows);
  return rows;
}

}  // namespace filmdyn::engine
