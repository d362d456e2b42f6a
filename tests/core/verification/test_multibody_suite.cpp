// The `filmdyn validate` rows of the "multibody" suite (the ideal crank train and the general
// multibody engine) all pass, and are real comparisons (a row with a wrong reference would fail).
#include <QtTest>

#include "core/verification/all_suites.hpp"

class TestValidationCases : public QObject {
  Q_OBJECT
 private slots:
  void allRowsPass() {
    const auto rows = filmdyn::verification::RunSuites({"multibody"});
    QVERIFY(rows.size() >= 10);
    for (const auto& row : rows) {
      qInfo("%s: ours %.10g ref %.10g err %.3g tol %.1g", row.name.c_str(), row.ours, row.reference,
            row.Error(), row.tolerance);
      QVERIFY2(row.Pass(), row.name.c_str());
      auto wrong = row;
      wrong.reference *= 1.001;
      QVERIFY(!wrong.Pass());
    }
  }
};

QTEST_GUILESS_MAIN(TestValidationCases)
#include "test_multibody_suite.moc"
