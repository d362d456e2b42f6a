// The synthetic single-zone pressure model (docs/pressure-model.md): peak location and level at
// the four shipped speeds, motored symmetry, and the shipped CSVs being exactly what the model
// produces. Set FILMDYN_REGENERATE_RESOURCES=1 to rewrite resources/pressure/*.csv.
#include <QtTest>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "core/engine/synthetic_pressure.hpp"
#include "core/io/pressure_csv.hpp"

using namespace filmdyn;
using namespace filmdyn::engine;

namespace {
std::vector<double> Degrees() {
  std::vector<double> a;
  for (int k = 0; k <= 720; ++k) a.push_back(k);
  return a;
}
std::string CsvFor(double rpm) {
  const auto p = SyntheticCylinderPressure(CrankTrainGeometry{},
                                           SyntheticPressureParameters::ForSpeed(rpm), Degrees());
  std::ostringstream out;
  io::WritePressureCsv(
      out, Degrees(), p,
      "SYNTHETIC cylinder pressure (not measured): FilmDyn single-zone model, " +
          std::to_string(static_cast<int>(rpm)) +
          " rpm, naturally aspirated gasoline, full load;\n"
          "polytropic compression/expansion + Wiebe heat release, geometry of "
          "resources/cases/default.json.\nModel: docs/pressure-model.md. Regenerate: "
          "FILMDYN_REGENERATE_RESOURCES=1 test_engine_synthetic_pressure",
      io::CsvDigits::kTable);
  return out.str();
}
}  // namespace

class TestSyntheticPressure : public QObject {
  Q_OBJECT
 private slots:
  void peakNearFiringTdc_data() {
    QTest::addColumn<double>("rpm");
    for (double rpm : {1000.0, 2000.0, 4000.0, 6000.0}) {
      QTest::newRow(qPrintable(QString::number(rpm))) << rpm;
    }
  }
  void peakNearFiringTdc() {
    QFETCH(double, rpm);
    const auto p = SyntheticCylinderPressure(CrankTrainGeometry{},
                                             SyntheticPressureParameters::ForSpeed(rpm), Degrees());
    const auto peak = std::max_element(p.begin(), p.end());
    const double angle = static_cast<double>(peak - p.begin());
    qInfo("%.0f rpm: peak %.2f MPa at %.0f °CA", rpm, *peak / 1e6, angle);
    QVERIFY(angle >= 370 && angle <= 375);
    QVERIFY(*peak >= 4e6 && *peak <= 7e6);
    // Gas exchange near atmospheric; periodic.
    QVERIFY(p[180] > 0.8e5 && p[180] < 1.1e5);
    QVERIFY(p[630] > 1.0e5 && p[630] < 1.3e5);
    QVERIFY(std::abs(p[0] - p[720]) < 1.0);  // Pa
  }
  void motoredCycleIsSymmetricAboutTdc() {
    // Without heat release and with IVC/EVO mirrored about 360, compression and expansion are
    // the same polytrope: p(360 − x) = p(360 + x); and the peak equals p_ivc·(V_ivc/V_c)^κ.
    SyntheticPressureParameters m = SyntheticPressureParameters::ForSpeed(2000);
    m.heat_release_efficiency = 0.0;
    m.ivc_deg = 220;
    m.evo_deg = 500;
    CrankTrainGeometry g;
    g.pin_offset = 0.0;
    const auto p = SyntheticCylinderPressure(g, m, Degrees());
    for (int x = 0; x < 130; x += 10) QVERIFY(std::abs(p[360 - x] - p[360 + x]) < 1e-6 * p[360]);
    const double ratio = g.compression_ratio;
    QVERIFY(p[360] > m.intake_pressure * std::pow(ratio * 0.85, m.polytropic_exponent));
    QVERIFY(p[360] < m.intake_pressure * std::pow(ratio, m.polytropic_exponent));
  }
  void shippedCurvesAreTheModel() {
    for (int rpm : {1000, 2000, 4000, 6000}) {
      const std::string path = std::string(FILMDYN_SOURCE_DIR) + "/resources/pressure/synthetic_" +
                               std::to_string(rpm) + "rpm.csv";
      const std::string expected = CsvFor(rpm);
      if (qEnvironmentVariableIsSet("FILMDYN_REGENERATE_RESOURCES")) {
        std::ofstream(path) << expected;
      }
      std::ifstream file(path);
      QVERIFY2(file.good(), qPrintable(QString::fromStdString(path)));
      std::ostringstream text;
      text << file.rdbuf();
      QVERIFY2(
          text.str() == expected,
          "shipped CSV differs from the model: regenerate with FILMDYN_REGENERATE_RESOURCES=1");
      std::istringstream in(text.str());
      const PressureCurve curve = io::ReadPressureCsv(in, path);
      QVERIFY(curve.PeakPressure() > 4e6);
    }
  }
};

QTEST_GUILESS_MAIN(TestSyntheticPressure)
#include "test_synthetic_pressure.moc"
