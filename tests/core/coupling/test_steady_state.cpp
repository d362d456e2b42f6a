// The periodic-steady-state criterion: a decaying transient on top of a periodic signal is
// declared converged exactly when its cycle-to-cycle change falls below 1 % of the range.
#include <QtTest>
#include <cmath>

#include "core/coupling/steady_state.hpp"
#include "core/base/input_error.hpp"

using filmdyn::coupling::PeriodicSteadyState;

namespace {

// x(t) = sin(phi) + A·exp(-t/tau): change between cycles c and c-1 at phase phi is
// A·exp(-t/tau)·(1 - exp(T/tau)) in magnitude, maximal at the start of the cycle.
void FeedCycle(PeriodicSteadyState& monitor, int cycle, double amplitude, double decay_per_cycle) {
  const int n = monitor.samples_per_cycle();
  for (int k = 0; k < n; ++k) {
    const double t = cycle + double(k) / n;
    const double phase = 2 * M_PI * k / n;
    monitor.Record(k, {std::sin(phase) + amplitude * std::exp(-decay_per_cycle * t), 5.0});
  }
}

}  // namespace

class TestSteadyState : public QObject {
  Q_OBJECT
 private slots:
  void convergesWhenChangeFallsBelowTolerance() {
    PeriodicSteadyState monitor({{"e0", 0.0, ""}, {"flat", 1e-9, ""}}, 360, 0.01);
    const double amplitude = 1.0, decay = 1.0;
    int converged_at = -1;
    for (int cycle = 0; cycle < 20 && converged_at < 0; ++cycle) {
      FeedCycle(monitor, cycle, amplitude, decay);
      const auto verdict = monitor.EndCycle();
      QCOMPARE(verdict.cycle, cycle + 1);
      QCOMPARE(verdict.compared, cycle > 0);
      if (verdict.converged) converged_at = cycle;
    }
    // Expectation: the max change between cycles c-1 and c is A(e-1)e^{-c} (at the first sample);
    // the range of cycle c is 2 (sine) plus the transient's drop within the cycle. Ratio:
    // c=4: 0.0315/2.01 = 0.016 > 1 %; c=5: 0.0116/2.004 = 0.0058 ≤ 1 % → converged at c = 5.
    QCOMPARE(converged_at, 5);
  }

  void flatQuantityUsesItsFloor() {
    PeriodicSteadyState monitor({{"x", 1e-3, ""}}, 10, 0.01);
    for (int cycle = 0; cycle < 2; ++cycle) {
      for (int k = 0; k < 10; ++k) monitor.Record(k, {1.0 + cycle * 1e-6});
      const auto verdict = monitor.EndCycle();
      if (cycle == 1) {
        QVERIFY(verdict.converged);  // 1e-6 change vs 1e-3 floor = 0.1 %
        QVERIFY(std::abs(verdict.relative_change[0] - 1e-3) < 1e-9);
      }
    }
  }

  void nanOrIncompleteCycleNeverConverges() {
    PeriodicSteadyState monitor({{"x", 1.0, ""}}, 4, 0.01);
    for (int k = 0; k < 4; ++k) monitor.Record(k, {0.0});
    monitor.EndCycle();
    for (int k = 0; k < 4; ++k) monitor.Record(k, {k == 2 ? std::nan("") : 0.0});
    QVERIFY(!monitor.EndCycle().converged);
    for (int k = 0; k < 3; ++k) monitor.Record(k, {0.0});  // one sample missing
    QVERIFY(!monitor.EndCycle().converged);
  }

  void reportsWorstQuantity() {
    PeriodicSteadyState monitor({{"a", 0.0, ""}, {"b", 0.0, ""}}, 4, 0.01);
    for (int k = 0; k < 4; ++k) monitor.Record(k, {double(k), double(k)});
    monitor.EndCycle();
    for (int k = 0; k < 4; ++k) monitor.Record(k, {double(k) + 0.001, double(k) + 0.3});
    const auto verdict = monitor.EndCycle();
    QVERIFY(!verdict.converged);
    QCOMPARE(verdict.worst_quantity, std::string("b"));
    QVERIFY(std::abs(verdict.worst_relative_change - 0.1) < 1e-12);
  }

  void badSettingsAreInputErrors() {
    QVERIFY_THROWS_EXCEPTION(filmdyn::InputError, PeriodicSteadyState({{"x", 0, ""}}, 1, 0.01));
    QVERIFY_THROWS_EXCEPTION(filmdyn::InputError, PeriodicSteadyState({{"x", 0, ""}}, 10, 0.0));
    QVERIFY_THROWS_EXCEPTION(filmdyn::InputError, PeriodicSteadyState({{"x", 0, ""}}, 10, NAN));
  }
};

QTEST_GUILESS_MAIN(TestSteadyState)
#include "test_steady_state.moc"
