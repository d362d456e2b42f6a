// The pressure-curve CSV reader and the periodic interpolation: good files, and every kind of bad
// file rejected with an error naming the file, line and column.
#include <QtTest>

#include <cmath>
#include <numbers>
#include <sstream>

#include "core/base/input_error.hpp"
#include "core/io/pressure_csv.hpp"

using namespace filmdyn;

namespace {
std::string Table(double step, double last, double (*p)(double)) {
  std::ostringstream out;
  out.precision(17);
  out << "crank_angle[deg],pressure[Pa]\n";
  for (double a = 0; a <= last + 1e-9; a += step) out << a << "," << p(a) << "\n";
  return out.str();
}
double Smooth(double a) { return 2e5 + 1e5 * std::cos(a * std::numbers::pi / 360.0); }
engine::PressureCurve Read(const std::string& text) {
  std::istringstream in(text);
  return io::ReadPressureCsv(in, "curve.csv");
}
// Throws InputError whose message contains `needle`.
bool Rejects(const std::string& text, const std::string& needle) {
  try {
    Read(text);
  } catch (const InputError& e) {
    if (std::string(e.what()).find(needle) != std::string::npos) return true;
    qWarning("message was: %s", e.what());
    return false;
  }
  return false;
}
}  // namespace

class TestPressureCsv : public QObject {
  Q_OBJECT
 private slots:
  void readsAndInterpolatesPeriodically() {
    const auto curve = Read("# comment line\n" + Table(2.0, 720.0, Smooth));
    const double deg = std::numbers::pi / 180;
    QVERIFY(std::abs(curve.Pressure(100 * deg) - Smooth(100)) < 1e-9 * Smooth(100));
    QVERIFY(std::abs(curve.Pressure(101 * deg) - Smooth(101)) < 1e-4 * Smooth(101));
    // Periodic: 721 °CA is 1 °CA of the next cycle, −1 is 719.
    QVERIFY(std::abs(curve.Pressure(721 * deg) - curve.Pressure(1 * deg)) < 1e-9);
    QVERIFY(std::abs(curve.Pressure(-1 * deg) - curve.Pressure(719 * deg)) < 1e-9);
    // Slope consistent with the values.
    const double h = 1e-6;
    const double numeric =
        (curve.Pressure(200 * deg + h) - curve.Pressure(200 * deg - h)) / (2 * h);
    QVERIFY(std::abs(curve.Slope(200 * deg) - numeric) < 1e-5 * std::abs(numeric) + 1e-6);
  }
  void wrapAroundWithoutPointAt720() {
    const auto curve = Read(Table(1.0, 719.0, Smooth));
    QVERIFY(std::abs(curve.Pressure(719.5 * std::numbers::pi / 180) - Smooth(719.5)) < 10.0);
  }
  void rejectsBadFiles() {
    QVERIFY(Rejects("angle,p\n0,1\n", "header"));
    QVERIFY(Rejects("crank_angle[deg],pressure[Pa]\n0,1e5\n", "at least 8 points"));
    QVERIFY(Rejects(Table(2.0, 400.0, Smooth), "cover 0–720"));  // stops at 400 °CA
    QVERIFY(Rejects(Table(20.0, 720.0, Smooth), "gaps of at most 10"));
    QVERIFY(Rejects("crank_angle[deg],pressure[Pa]\n0,1e5\n1,abc\n", "curve.csv:3 pressure[Pa]"));
    QVERIFY(Rejects("crank_angle[deg],pressure[Pa]\n0,1e5\n1,nan\n", "curve.csv:3"));
    QVERIFY(Rejects("crank_angle[deg],pressure[Pa]\n0,-5\n", "absolute pressure"));
    QVERIFY(Rejects("crank_angle[deg],pressure[Pa]\n0,1e5\n800,1e5\n", "[0, 720]"));
    // A value just outside the range is shown with the digits that make it so.
    QVERIFY(Rejects("crank_angle[deg],pressure[Pa]\n0,1e5\n720.0000000000001,1e5\n",
                    "= 720.0000000000001: must lie in [0, 720]"));
    QVERIFY(Rejects("crank_angle[deg],pressure[Pa]\n0,1e5,3\n", "two columns"));
    // A point's error names its line in the file (comments and the header counted): it named
    // the point's index, "curve.csv[1].crank_angle", one less than the data row.
    QVERIFY(Rejects(
        "# a comment\ncrank_angle[deg],pressure[Pa]\n0,1e5\n0,1e5\n1,2\n2,3\n3,4\n4,5\n5,6\n6,7\n",
        "curve.csv:4 crank_angle[deg] = 0 °CA: crank angles must increase strictly"));
    std::string gap = Table(2.0, 720.0, Smooth);
    const auto cut = gap.find("\n40,");  // 40 … 56 °CA left out: a gap of 20 °CA
    gap.erase(cut, gap.find("\n58,") - cut);
    QVERIFY(Rejects(gap, "curve.csv:22 crank_angle[deg] = 58 °CA: 20 °CA after the point before"));
    QVERIFY(Rejects("", "header"));
    // A UTF-8 byte-order mark before the header (spreadsheets write one) is read past.
    const auto with_mark = Read("\xEF\xBB\xBF" + Table(2.0, 720.0, Smooth));
    QVERIFY(std::abs(with_mark.Pressure(0.0) - Smooth(0)) < 1e-9 * Smooth(0));
    // p(720) must repeat p(0).
    std::string text = Table(5.0, 715.0, Smooth) + "720,9e6\n";
    QVERIFY(Rejects(text, "must repeat"));
  }
};

QTEST_GUILESS_MAIN(TestPressureCsv)
#include "test_pressure_csv.moc"
