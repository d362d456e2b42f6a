// The differences between two runs' inputs: identical inputs have none; each kind of field
// (number with its display unit, integer, text, joint model, table, pressure curves, the model
// and the speed) is found and worded compactly in display units; every schema field has a short
// label.
#include <QtTest>

#include "core/engine/case_diff.hpp"
#include "core/engine/case_schema.hpp"
#include "core/io/case_file.hpp"

using namespace filmdyn;
using engine::CaseDifference;
using engine::RunInputs;

namespace {

RunInputs Default() { return {io::LoadCase({}).value, "skirt-lbrbe", 6000.0}; }

QString Text(const std::vector<CaseDifference>& d) {
  return QString::fromStdString(engine::FormatDifferences(d));
}

}  // namespace

class TestCaseDiff : public QObject {
  Q_OBJECT
 private slots:
  void identicalInputsDifferInNothing() {
    const RunInputs a = Default();
    QVERIFY(engine::DiffRunInputs(a, a).empty());
    QCOMPARE(Text(engine::DiffRunInputs(a, a)), QString());
    // The case's own speed is the run's when the run gives none.
    RunInputs b = a;
    b.rpm = 0;
    b.engine_case.operating.rpm = 6000;
    QVERIFY(engine::DiffRunInputs(a, b).empty());
  }

  void numberInDisplayUnits() {
    const RunInputs a = Default();
    RunInputs b = a;
    b.engine_case.lubricant.viscosity = 0.01;
    const auto d = engine::DiffRunInputs(a, b);
    QCOMPARE(int(d.size()), 1);
    QCOMPARE(QString::fromStdString(d[0].path), QString("lubricant.viscosity"));
    QCOMPARE(QString::fromStdString(d[0].label), QString("μ"));
    QCOMPARE(QString::fromStdString(d[0].value_a), QString("20 mPa·s"));
    QCOMPARE(QString::fromStdString(d[0].value_b), QString("10 mPa·s"));
    QCOMPARE(Text(d), QString("μ 10 mPa·s"));
    // Micrometres, no trailing zeros; close values get the digits that tell them apart.
    b = a;
    b.engine_case.big_end.journal_radius = 14.97e-3;
    b.engine_case.skirt.roughness_skirt = 0.7e-6;
    QCOMPARE(Text(engine::DiffRunInputs(a, b)), QString("σ_skirt 0.7 µm · R_j 14.97 mm"));
    b = a;
    b.engine_case.lubricant.viscosity = 0.020001;
    QCOMPARE(Text(engine::DiffRunInputs(a, b)), QString("μ 20.001 mPa·s"));
    // Dimensionless: no unit.
    b = a;
    b.engine_case.skirt.boundary_friction = 0.1;
    QCOMPARE(Text(engine::DiffRunInputs(a, b)), QString("μ_f skirt 0.1"));
  }

  void speedModelIntegerText() {
    const RunInputs a = Default();
    RunInputs b = a;
    b.rpm = 4000;
    QCOMPARE(Text(engine::DiffRunInputs(a, b)), QString("4000 rpm"));
    b.engine_case.lubricant.viscosity = 0.01;
    QCOMPARE(Text(engine::DiffRunInputs(a, b)), QString("μ 10 mPa·s · 4000 rpm"));
    b = a;
    b.model = "only-skirt";
    auto d = engine::DiffRunInputs(a, b);
    QCOMPARE(int(d.size()), 1);  // the joint model fields follow the model: not repeated
    QCOMPARE(Text(d), QString("model Only-Skirt"));
    QCOMPARE(QString::fromStdString(d[0].value_a), QString("Skirt-LBRBE"));
    b = a;
    b.engine_case.solver.max_cycles = 12;
    QCOMPARE(Text(engine::DiffRunInputs(a, b)), QString("max cycles 12"));
    b = a;
    b.engine_case.name = "variant";
    QCOMPARE(Text(engine::DiffRunInputs(a, b)), QString("name “variant”"));
    b.engine_case.name = "a name much longer than a label should carry";
    QCOMPARE(Text(engine::DiffRunInputs(a, b)), QString("name changed"));
    // Without models, the joints' model fields are the difference.
    RunInputs ca{a.engine_case, "", 0}, cb{a.engine_case, "", 0};
    cb.engine_case.skirt.model = engine::JointModel::kLubricated;
    ca.engine_case.skirt.model = engine::JointModel::kIdeal;
    QCOMPARE(Text(engine::DiffRunInputs(ca, cb)), QString("skirt joint lubricated"));
  }

  void tablesAndCurves() {
    const RunInputs a = Default();
    RunInputs b = a;
    b.engine_case.skirt.profile_h[0] = 30e-6;
    b.engine_case.skirt.profile_y[4] = 27e-3;
    auto d = engine::DiffRunInputs(a, b);
    QCOMPARE(int(d.size()), 1);  // one table, one difference
    QCOMPARE(QString::fromStdString(d[0].path), QString("skirt.profile"));
    QCOMPARE(Text(d), QString("skirt profile changed"));
    b = a;
    b.engine_case.skirt.ovality_alpha = {0.0, 1.0};
    b.engine_case.skirt.ovality_h = {0.0, 5e-6};
    d = engine::DiffRunInputs(a, b);
    QCOMPARE(Text(d), QString("skirt ovality changed"));
    QCOMPARE(QString::fromStdString(d[0].value_a), QString("0 points"));
    QCOMPARE(QString::fromStdString(d[0].value_b), QString("2 points"));
    b = a;
    QVERIFY(!b.engine_case.pressure_curves.empty());
    b.engine_case.pressure_curves[0].rpm += 10;
    QCOMPARE(Text(engine::DiffRunInputs(a, b)), QString("cylinder pressure changed"));
  }

  void everyFieldHasAShortLabel() {
    for (const engine::CaseField& f : engine::CaseSchema()) {
      if (f.path == "operating.rpm") {
        QVERIFY(f.symbol.empty());
        continue;
      }
      QVERIFY2(!f.symbol.empty() && f.symbol != f.label, f.path.c_str());
      QVERIFY2(f.symbol.size() <= 24, f.path.c_str());
    }
  }

  void significantDigits() {
    QCOMPARE(QString::fromStdString(engine::FormatSignificant(10.0, 3)), QString("10"));
    QCOMPARE(QString::fromStdString(engine::FormatSignificant(0.615, 3)), QString("0.615"));
    QCOMPARE(QString::fromStdString(engine::FormatSignificant(14.96, 3)), QString("15"));
    QCOMPARE(QString::fromStdString(engine::FormatSignificant(0.01 / 1e-3, 6)), QString("10"));
    QCOMPARE(QString::fromStdString(engine::FormatSignificant(10000.0, 3)), QString("10000"));
    QCOMPARE(QString::fromStdString(engine::FormatSignificant(1e-10, 3)), QString("1e-10"));
    QCOMPARE(QString::fromStdString(engine::FormatSignificant(-0.0001, 3)), QString("-0.0001"));
    QCOMPARE(QString::fromStdString(engine::FormatSignificant(0.0, 3)), QString("0"));
  }
};

QTEST_GUILESS_MAIN(TestCaseDiff)
#include "test_case_diff.moc"
