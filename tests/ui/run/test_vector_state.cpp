// A QApplication leaves the vector registers' upper halves dirty on some CPUs (Intel from
// Skylake on): every later SSE instruction of the numerical core then runs with a false
// dependency, measured 4x slower on an Ice Lake Xeon. core/base/vector_unit.hpp clears the state
// before each solve. This test times one SSE loop (compiled as the core is, SSE2) back to back:
// before the QApplication, after it, and after ResetVectorUnitState — and requires the last to
// run near the first's speed (ratio < 2; the dirty state costs ~4x where it matters, nothing on
// other CPUs). Ratios of back-to-back timings (best of seven passes, the test runs alone), not
// absolute times.
#include <QApplication>
#include <QtTest>
#include <chrono>
#include <cmath>
#include <vector>

#include "core/base/vector_unit.hpp"

namespace {

double g_sink = 0;

// Best of seven ~15 ms passes of scalar SSE arithmetic [s].
double TimeLoop() {
  std::vector<double> a(2000), b(2000);
  for (int i = 0; i < 2000; ++i) a[i] = i * 1e-3, b[i] = 1.0 / (i + 1);
  double best = 1e300;
  for (int pass = 0; pass < 7; ++pass) {
    const auto t0 = std::chrono::steady_clock::now();
    double s = 0;
    for (int r = 0; r < 4000; ++r) {
      for (int i = 0; i < 2000; ++i) s += a[i] * b[i] + std::sqrt(a[i] + r);
    }
    g_sink += s;
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
                              .count());
  }
  return best;
}

}  // namespace

class TestVectorState : public QObject {
  Q_OBJECT
 private slots:
  void solverThreadsRunAtFullSpeedAfterAQApplication() {
    const double before = TimeLoop();
    int argc = 1;
    char name[] = "test";
    char* argv[] = {name, nullptr};
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    const double dirty = TimeLoop();
    filmdyn::ResetVectorUnitState();
    const double after = TimeLoop();
    qInfo("SSE loop: %.1f ms before the QApplication, %.1f ms after it (x%.2f), %.1f ms after "
          "the reset (x%.2f)",
          1e3 * before, 1e3 * dirty, dirty / before, 1e3 * after, after / before);
    QVERIFY2(after < 2.0 * before, "the vector state reset did not restore the loop's speed");
    QVERIFY(g_sink != 0);
  }
};

QTEST_APPLESS_MAIN(TestVectorState)
#include "test_vector_state.moc"
