// Every lubrication row of `filmdyn validate` passes: Raimondi-Boyd S and attitude at L/D =
// 1/4, 1/2, 1 (eps 0.1..0.9, 240 x 20 half mesh) with the inlet flow Q, Ocvirk short bearing, pure
// squeeze, the JFO pocketed slider (flow, pressure, reformation point, fluid fraction, mass
// balance) and the LCP.
#include <QtTest>

#include "core/lubrication/validation_cases.hpp"

using namespace filmdyn::lubrication;

class TestValidationCases : public QObject {
  Q_OBJECT
 private slots:
  void allRowsPass() {
    const auto rows = LubricationValidationRows();
    QVERIFY(rows.size() >= 54 + 4 + 2 + 5 + 1);
    for (const auto& row : rows) {
      QVERIFY2(row.Pass(), qPrintable(QString::fromStdString(row.name) +
                                      QString(": ours %1 reference %2 error %3 > %4")
                                          .arg(row.ours, 0, 'g', 8)
                                          .arg(row.reference, 0, 'g', 8)
                                          .arg(row.Error())
                                          .arg(row.tolerance)));
    }
  }

  void analyticHelpers() {
    // Full-film squeeze integral against its own quadrature-free closed form at eps = 0.
    QVERIFY(std::abs(SqueezeIntegralFull(0.0) - M_PI) < 1e-14);
    QVERIFY(std::abs(SqueezeIntegralHalf(0.0) - 0.5 * M_PI) < 1e-12);
    // Ocvirk: attitude -> 90 deg as eps -> 0.
    QVERIFY(std::abs(OcvirkAttitudeDeg(1e-9) - 90.0) < 1e-6);
    const PocketSliderSolution s = PocketSliderAnalytic(PocketSliderCase{});
    QVERIFY(s.x_reform > 2e-3 && s.x_reform < 5e-3);
    QVERIFY(s.fluid_fraction > 0.0 && s.fluid_fraction < 1.0);
  }

  void swiftStieberIsNotMassConservingOnTheSlider() {
    const PocketSliderCase c;
    const PocketSliderFem r = PocketSliderNumeric(c, 1000, CavitationModel::kReynolds);
    QVERIFY(std::abs(r.outflow_q - r.sol.q) > 1e-4 * r.sol.q);
    const PocketSliderFem j = PocketSliderNumeric(c, 1000, CavitationModel::kJfo);
    QVERIFY(std::abs(j.outflow_q - j.sol.q) < 1e-9 * j.sol.q);
    // JFO converges to the closed form (first order in the mesh: film steps are smeared).
    const PocketSliderSolution ref = PocketSliderAnalytic(c);
    const double e1 =
        std::abs(PocketSliderNumeric(c, 500, CavitationModel::kJfo).sol.p_exit - ref.p_exit);
    const double e2 =
        std::abs(PocketSliderNumeric(c, 2000, CavitationModel::kJfo).sol.p_exit - ref.p_exit);
    QVERIFY(e2 < 0.4 * e1);
    for (const int n : {500, 1000, 2000, 4000, 8000}) {
      const PocketSliderFem f = PocketSliderNumeric(c, n, CavitationModel::kJfo);
      qInfo("%d elements: q %.6g, p exit %.6g Pa (%+.2f %%), reformation %.4g mm, theta %.6g", n,
            f.sol.q, f.sol.p_exit, 100.0 * (f.sol.p_exit / ref.p_exit - 1.0), f.sol.x_reform * 1e3,
            f.sol.fluid_fraction);
    }
  }
};

QTEST_GUILESS_MAIN(TestValidationCases)
#include "test_validation_cases.moc"
