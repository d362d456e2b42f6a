// The ideal crank train built on the general multibody engine against closed forms: exact
// offset slider-crank kinematics (≤ 1e-6 relative), the liner side force and big-end reaction
// against an independent Newton–Euler solution (≤ 1e-5 relative) at several speeds and gas loads,
// and bounded constraint drift over 100 cycles.
#include <QtTest>

#include <cmath>
#include <numbers>

#include "core/engine/crank_train.hpp"
#include "core/engine/slider_crank_reference.hpp"
#include "core/multibody/integrator.hpp"

using namespace filmdyn;
using namespace filmdyn::engine;

namespace {

constexpr double kPi = std::numbers::pi;

PressureCurve ConstantCurve(double p) {
  std::vector<double> a, v;
  for (int k = 0; k < 144; ++k) {
    a.push_back(k * 4 * kPi / 144);
    v.push_back(p);
  }
  return PressureCurve(a, v, "test");
}

// A combustion-like curve: 1 bar + a Gaussian peak of `peak` Pa at 372 °CA.
PressureCurve FiringCurve(double peak) {
  std::vector<double> a, v;
  for (int k = 0; k < 720; ++k) {
    const double deg = k;
    a.push_back(deg * kPi / 180);
    v.push_back(1e5 + peak * std::exp(-std::pow((deg - 372.0) / 25.0, 2)));
  }
  return PressureCurve(a, v, "test");
}

struct Comparison {
  double raw = 0.0;  // integrator state itself (before the output projection): x, ẋ, θ, θ̇
  double kinematics = 0.0;  // worst relative error of the six kinematic quantities
  double forces = 0.0;      // worst relative error of side force and big-end force
  double moment = 0.0, torque = 0.0;
};

// Runs `cycles` cycles and compares every `step_deg` of the last one.
Comparison Compare(EngineCase c, double rpm, PressureCurve curve, int cycles = 1,
                   double rtol = 1e-9) {
  CrankTrain train = BuildCrankTrain(c, rpm, std::move(curve));
  multibody::Integrator integrator(*train.system,
                                   multibody::IntegratorConfig{.relative_tolerance = rtol});
  integrator.Initialize(0.0, train.initial_state);
  const double omega = train.layout.omega;
  const double cycle = 4 * kPi / omega;
  std::vector<CrankTrainSample> ours;
  std::vector<SliderCrankReference> exact;
  std::vector<Eigen::Vector4d> raw;  // pin y, pin ẏ, rod θ, rod θ̇ from the integrated state
  for (int k = 0; k <= 144; ++k) {
    const double t = (cycles - 1) * cycle + k * cycle / 144;
    const multibody::SystemState s = t > 0 ? integrator.AdvanceTo(t) : train.initial_state;
    ours.push_back(SampleCrankTrain(train, c, t, s));
    const multibody::BodyState piston = s.Body(train.layout.piston), rod = s.Body(train.layout.rod);
    raw.push_back({multibody::PointPosition(piston, train.layout.piston_pin_point).y(),
                   multibody::PointVelocity(piston, train.layout.piston_pin_point).y(), rod.Angle(),
                   rod.AngularVelocity()});
    exact.push_back(ExactSliderCrank(c.geometry, omega * t, omega, ours.back().gas_force));
  }
  // Errors relative to each quantity's largest magnitude over the cycle (pointwise relative
  // errors are undefined at zero crossings).
  auto worst = [&](auto get_ours, auto get_exact) {
    double scale = 0, err = 0;
    for (std::size_t k = 0; k < ours.size(); ++k) {
      scale = std::max(scale, std::abs(get_exact(exact[k])));
      err = std::max(err, std::abs(get_ours(ours[k]) - get_exact(exact[k])));
    }
    return err / scale;
  };
  auto worst_raw = [&](int i, auto get_exact) {
    double scale = 0, err = 0;
    for (std::size_t k = 0; k < raw.size(); ++k) {
      scale = std::max(scale, std::abs(get_exact(exact[k])));
      err = std::max(err, std::abs(raw[k][i] - get_exact(exact[k])));
    }
    return err / scale;
  };
  Comparison r;
  r.raw = std::max({worst_raw(0, [](auto& e) { return e.piston_position; }),
                    worst_raw(1, [](auto& e) { return e.piston_velocity; }),
                    worst_raw(2, [](auto& e) { return e.rod_angle; }),
                    worst_raw(3, [](auto& e) { return e.rod_angular_velocity; })});
  r.kinematics = std::max(
      {worst([](auto& s) { return s.piston_position; }, [](auto& e) { return e.piston_position; }),
       worst([](auto& s) { return s.piston_velocity; }, [](auto& e) { return e.piston_velocity; }),
       worst([](auto& s) { return s.piston_acceleration; },
             [](auto& e) { return e.piston_acceleration; }),
       worst([](auto& s) { return s.rod_angle; }, [](auto& e) { return e.rod_angle; }),
       worst([](auto& s) { return s.rod_angular_velocity; },
             [](auto& e) { return e.rod_angular_velocity; }),
       worst([](auto& s) { return s.rod_angular_acceleration; },
             [](auto& e) { return e.rod_angular_acceleration; })});
  r.forces = std::max({worst([](auto& s) { return s.liner_force_on_piston.x(); },
                             [](auto& e) { return e.liner_force_x; }),
                       worst([](auto& s) { return s.big_end_force_on_rod.x(); },
                             [](auto& e) { return e.big_end_force.x(); }),
                       worst([](auto& s) { return s.big_end_force_on_rod.y(); },
                             [](auto& e) { return e.big_end_force.y(); })});
  r.moment = worst([](auto& s) { return s.liner_moment_about_pin; },
                   [](auto& e) { return e.liner_moment_about_pin; });
  r.torque = worst([](auto& s) { return s.crank_torque; }, [](auto& e) { return e.crank_torque; });
  return r;
}

}  // namespace

class TestCrankTrain : public QObject {
  Q_OBJECT
 private slots:
  // A lap of crank angles in time order starts after the last pass 720 → 0: a cycle from 0 °CA
  // at its first step; one started at 90 °CA (1 °CA steps) at its 631st, 0 °CA; a run-in's
  // samples taken round 720 °CA twice at the second pass; `from` bounds the search.
  void lapStartsAfterTheLastPassRound720() {
    std::vector<double> from_0, from_90, twice;
    for (int k = 0; k < 720; ++k) {
      from_0.push_back(k);
      from_90.push_back((90 + k) % 720);
    }
    for (int k = 0; k < 1000; ++k) twice.push_back((500 + k) % 720);
    QCOMPARE(engine::LapStart(from_0), std::size_t(0));
    QCOMPARE(engine::LapStart(from_90), std::size_t(630));
    QCOMPARE(from_90[630], 0.0);
    QCOMPARE(engine::LapStart(twice), std::size_t(940));
    QCOMPARE(engine::LapStart(twice, 950), std::size_t(950));
    QCOMPARE(engine::LapStart({}), std::size_t(0));
  }

  void kinematicsMatchExactSliderCrank_data() {
    QTest::addColumn<double>("rpm");
    QTest::addColumn<double>("pin_offset");
    QTest::newRow("1000 rpm, Table I offset") << 1000.0 << 0.7e-3;
    QTest::newRow("6000 rpm, Table I offset") << 6000.0 << 0.7e-3;
    QTest::newRow("6000 rpm, 8 mm offset") << 6000.0 << 8e-3;
    QTest::newRow("3000 rpm, negative offset") << 3000.0 << -5e-3;
  }
  void kinematicsMatchExactSliderCrank() {
    QFETCH(double, rpm);
    QFETCH(double, pin_offset);
    EngineCase c;
    c.geometry.pin_offset = pin_offset;
    const Comparison r = Compare(c, rpm, FiringCurve(6e6));
    qInfo("kinematics worst relative error %.3g (integrated state before projection %.3g)",
          r.kinematics, r.raw);
    QVERIFY(r.kinematics <= 1e-6);
    QVERIFY(r.raw <= 1e-6);
  }
  void offsetIsNotIgnored() {
    // The comparison must detect a wrong offset: build with 8 mm, compare with 0 mm formulas.
    EngineCase c;
    c.geometry.pin_offset = 8e-3;
    CrankTrain train = BuildCrankTrain(c, 3000, ConstantCurve(1e5));
    const CrankTrainSample s = SampleCrankTrain(train, c, 0.0, train.initial_state);
    CrankTrainGeometry g0 = c.geometry;
    g0.pin_offset = 0.0;
    const SliderCrankReference wrong = ExactSliderCrank(g0, 0.0, train.layout.omega, 0.0);
    QVERIFY(std::abs(s.piston_position - wrong.piston_position) > 1e-4);
  }
  void reactionsMatchNewtonEuler_data() {
    QTest::addColumn<double>("rpm");
    QTest::addColumn<double>("peak");
    QTest::newRow("1000 rpm, motored") << 1000.0 << 0.0;
    QTest::newRow("1000 rpm, 6 MPa") << 1000.0 << 6e6;
    QTest::newRow("4000 rpm, 4 MPa") << 4000.0 << 4e6;
    QTest::newRow("6000 rpm, 7 MPa") << 6000.0 << 7e6;
  }
  void reactionsMatchNewtonEuler() {
    QFETCH(double, rpm);
    QFETCH(double, peak);
    EngineCase c;
    const Comparison r = Compare(c, rpm, FiringCurve(peak));
    qInfo("forces %.3g, liner moment %.3g, crank torque %.3g", r.forces, r.moment, r.torque);
    QVERIFY(r.forces <= 1e-5);
    QVERIFY(r.moment <= 1e-5);
    QVERIFY(r.torque <= 1e-5);
  }
  void constantGasLoadNewtonEuler() {
    EngineCase c;
    const Comparison r = Compare(c, 2000, ConstantCurve(3e6));  // 30 bar throughout
    QVERIFY(r.forces <= 1e-5);
  }
  void constraintDriftBoundedOver100Cycles() {
    EngineCase c;
    CrankTrain train = BuildCrankTrain(c, 6000, FiringCurve(6e6));
    multibody::Integrator integrator(*train.system, multibody::IntegratorConfig{});
    integrator.Initialize(0.0, train.initial_state);
    const double cycle = 4 * kPi / train.layout.omega;
    double first = 0, last = 0;
    for (int n = 1; n <= 100; ++n) {
      double worst = 0;
      for (int k = 1; k <= 36; ++k) {
        const double t = (n - 1) * cycle + k * cycle / 36;
        const multibody::SystemState s = integrator.AdvanceTo(t);
        worst = std::max(worst, train.system->PositionViolation(t, s).lpNorm<Eigen::Infinity>());
      }
      if (n == 1) first = worst;
      last = worst;
    }
    const auto stats = integrator.Stats();
    qInfo("max |Φ|: cycle 1 %.3g, cycle 100 %.3g; %ld steps (%.0f per cycle), %ld rejected", first,
          last, stats.steps, stats.steps / 100.0, stats.rejected_steps);
    QVERIFY(last < 1e-8);                // m or rad: 1e-7 of the stroke
    QVERIFY(last < 10 * first + 1e-12);  // bounded, not growing
  }
  void baumgarteSweep() {
    // docs/validation/multibody.md: drift and error vs the Baumgarte coefficients (α = β),
    // 6000 rpm, 20 cycles, default tolerances. Without feedback the drift must grow; with any
    // feedback of at least 1e2 1/s it must stay bounded and the integrated state accurate.
    qInfo(
        "alpha=beta [1/s] | max|Phi| cycle 1 | max|Phi| cycle 20 | pos err/stroke | steps | "
        "rejected");
    for (double coefficient : {0.0, 1e2, 1e3, 1e4, 1e5}) {
      EngineCase c;
      c.solver.baumgarte_alpha = c.solver.baumgarte_beta = coefficient;
      CrankTrain train = BuildCrankTrain(c, 6000, FiringCurve(6e6));
      multibody::Integrator integrator(*train.system, multibody::IntegratorConfig{});
      integrator.Initialize(0.0, train.initial_state);
      const double cycle = 4 * kPi / train.layout.omega, omega = train.layout.omega;
      double first = 0, last = 0, position = 0;
      for (int n = 1; n <= 20; ++n) {
        double worst = 0;
        for (int k = 1; k <= 72; ++k) {
          const double t = (n - 1) * cycle + k * cycle / 72;
          const multibody::SystemState s = integrator.AdvanceTo(t);
          worst = std::max(worst, train.system->PositionViolation(t, s).lpNorm<Eigen::Infinity>());
          if (n == 20) {
            const double y =
                multibody::PointPosition(s.Body(train.layout.piston), train.layout.piston_pin_point)
                    .y();
            position = std::max(
                position,
                std::abs(y - ExactSliderCrank(c.geometry, omega * t, omega, 0).piston_position));
          }
        }
        if (n == 1) first = worst;
        last = worst;
      }
      const auto stats = integrator.Stats();
      qInfo("%8.0e | %9.2e | %9.2e | %9.2e | %6ld | %ld", coefficient, first, last,
            position / (2 * c.geometry.crank_radius), stats.steps, stats.rejected_steps);
      if (coefficient == 0.0) {
        QVERIFY(last > first);  // free drift grows
      } else {
        QVERIFY(last < 1e-7);
        QVERIFY(position < 1e-6 * 2 * c.geometry.crank_radius);
      }
    }
  }
};

QTEST_GUILESS_MAIN(TestCrankTrain)
#include "test_crank_train.moc"
