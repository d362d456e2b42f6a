// Numbers are read and written the same in every locale. Qt's application objects set the C
// library's locale from the environment, so a user whose LANG is German runs FilmDyn under a
// locale whose decimal point is a comma — where the C library's strtod reads "1.5" as 1 and
// printf writes "1,5". Under such a locale (checked to be in effect): the shipped CalculiX
// compliance reads as under "C" (it was refused: "must be a finite number"), as do a pressure
// curve, results.csv converted to display units, a study's base settings (a number stayed a
// number only in "C") and the numbers in messages; the one number reader takes an optional '+'.
#include <QtTest>

#include <clocale>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/base/input_error.hpp"
#include "core/batch/study.hpp"
#include "core/io/pressure_csv.hpp"
#include "core/io/results_writer.hpp"
#include "core/lubrication/imported_compliance.hpp"
#include "core/lubrication/oil.hpp"
#include "tests/comma_locale.hpp"

using namespace filmdyn;

namespace {

const std::string kShellMatrix =
    std::string(FILMDYN_SOURCE_DIR) + "/examples/calculix-bearing-shell/shell_compliance.mtx";

}  // namespace

class TestNumberLocale : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() {
    reference_ = lubrication::ReadImportedCompliance(kShellMatrix);  // under "C"
    const auto locale = testing::FindCommaDecimalLocale(scratch_.path().toStdString());
    QVERIFY2(locale, testing::kNoCommaLocale);
    if (!locale->locpath.empty()) setenv("LOCPATH", locale->locpath.c_str(), 1);
    QVERIFY(std::setlocale(LC_ALL, locale->name.c_str()) != nullptr);
    // The locale is in effect: the C library reads the point as the end of the number.
    QCOMPARE(std::strtod("1.5", nullptr), 1.0);
  }
  void cleanupTestCase() { std::setlocale(LC_ALL, "C"); }

  void theShippedCompliance() {
    const lubrication::ImportedCompliance read = lubrication::ReadImportedCompliance(kShellMatrix);
    QCOMPARE(read.x_lines, reference_.x_lines);
    QCOMPARE(read.y_lines, reference_.y_lines);
    QVERIFY(read.matrix == reference_.matrix);
    QVERIFY(reference_.matrix.cwiseAbs().maxCoeff() > 0.0);
  }

  void aPressureCurve() {
    std::vector<double> angles, pressures;
    for (int k = 0; k <= 72; ++k) {
      angles.push_back(10.0 * k);
      pressures.push_back(1.5e5 + 1234.5 * (k <= 36 ? k : 72 - k));  // periodic
    }
    std::ostringstream out;
    io::WritePressureCsv(out, angles, pressures, "written under a comma locale");
    QVERIFY2(out.str().find("\n10,151234.5\n") != std::string::npos, out.str().c_str());
    std::istringstream in(out.str());
    const engine::PressureCurve curve = io::ReadPressureCsv(in, "curve.csv");
    QCOMPARE(curve.Pressure(30.0 * M_PI / 180.0), 1.5e5 + 3 * 1234.5);
    // A cell with a leading '+' (spreadsheets write one) reads too.
    std::istringstream plus("crank_angle[deg],pressure[Pa]\n" + [&] {
      std::string rows;
      for (int k = 0; k <= 72; ++k) rows += std::to_string(10 * k) + ",+1.5e5\n";
      return rows;
    }());
    QCOMPARE(io::ReadPressureCsv(plus, "plus.csv").Pressure(0.0), 1.5e5);
  }

  void resultsInDisplayUnits() {
    const std::vector<std::string> header = io::ResultsHeader();
    std::string si = header[0];
    for (std::size_t k = 1; k < header.size(); ++k) si += "," + header[k];
    si += "\n";
    for (std::size_t k = 0; k < header.size(); ++k) si += k ? ",0.5" : "0.5";
    si += "\n";
    const std::string shown = io::ResultsCsvInDisplayUnits(si);
    const std::string row = shown.substr(shown.find('\n') + 1);
    QVERIFY2(row.find("0.5") != std::string::npos, row.c_str());
    // Every cell is a number in the C form (a comma would add cells).
    std::size_t cells = 1;
    for (char c : row) cells += c == ',';
    QCOMPARE(cells, header.size());
  }

  void aStudysBaseSettingsStayNumbers() {
    const batch::Study study = batch::ParseStudy(R"({
      "name": "locale",
      "design": "full-factorial",
      "set": {"lubricant.viscosity": 0.0105, "skirt.cavitation": "jfo"},
      "factors": [{"path": "skirt.cold_clearance", "levels": [1.5e-5, 2.5e-5]}]
    })",
                                                 "study.json");
    const nlohmann::json written = nlohmann::json::parse(batch::StudyJson(study));
    QVERIFY2(written["set"]["lubricant.viscosity"].is_number(), written["set"].dump().c_str());
    QCOMPARE(written["set"]["lubricant.viscosity"].get<double>(), 0.0105);
    QVERIFY(written["set"]["skirt.cavitation"].is_string());
  }

  void numbersInMessages() {
    QCOMPARE(FormatValue(1.5), std::string("1.5"));
    const lubrication::VogelLaw law{1e-4, 900.0, 150.5};
    try {
      law.At(140.25, "lubricant.temperature");
      QFAIL("a temperature below the pole must be refused");
    } catch (const InputError& e) {
      const std::string what = e.what();
      QVERIFY2(what.find("140.25 K") != std::string::npos, what.c_str());
      QVERIFY2(what.find("150.5 K") != std::string::npos, what.c_str());
    }
  }

  void theNumberReader() {
    double v = 0.0;
    QVERIFY(ParseNumber("+2.5e-3", v) && v == 2.5e-3);
    QVERIFY(ParseNumber("-0.75", v) && v == -0.75);
    QVERIFY(ParseNumber("1e-310", v) && v == 1e-310);  // below the smallest normal double
    for (const char* bad : {"", "+", "+-1", "++1", "1,5", " 1", "1 ", "0x10", "1.5mm"}) {
      QVERIFY2(!ParseNumber(bad, v), bad);
    }
  }

 private:
  QTemporaryDir scratch_;
  lubrication::ImportedCompliance reference_;
};

QTEST_GUILESS_MAIN(TestNumberLocale)
#include "test_number_locale.moc"
