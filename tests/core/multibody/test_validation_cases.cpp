// The `filmdyn validate` rows of the multibody engine all pass, and are real comparisons (a row
// with a wrong reference would fail).
#include <QtTest>

#include "core/multibody/validation_cases.hpp"

class TestValidationCases : public QObject {
  Q_OBJECT
 private slots:
  void allRowsPass() {
    const auto rows = filmdyn::multibody::MultibodyValidationRows();
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
#include "test_validation_cases.moc"
