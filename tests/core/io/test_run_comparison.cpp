// The sweep comparison reads the main figures of each run from its summary.json.
#include <QTemporaryDir>
#include <QtTest>
#include <fstream>
#include <sstream>
#include <tuple>

#include "core/io/run_comparison.hpp"

namespace {

void WriteSummary(const std::filesystem::path& folder, const std::string& text) {
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "summary.json") << text;
}

int FigureIndex(const std::string& key) {
  const auto& figures = filmdyn::io::ComparisonFigures();
  for (std::size_t i = 0; i < figures.size(); ++i) {
    if (figures[i].key == key) return int(i);
  }
  return -1;
}

}  // namespace

class TestRunComparison : public QObject {
  Q_OBJECT
 private slots:
  void readsFiguresFromSummary() {
    QTemporaryDir dir;
    const std::filesystem::path folder = dir.filePath("c-skirt-lbrbe-6000").toStdString();
    WriteSummary(folder, R"({"model": "skirt-lbrbe", "rpm": 6000, "status": "completed",
      "cycles": 4, "wall_time_s": 7.5,
      "extremes": {"piston_lateral[m]": {"min": -2.0e-5, "max": 1.5e-5},
                   "skirt_moft[m]": {"min": 1.2e-6, "max": 2.0e-5},
                   "bearing_eps[-]": {"min": 0.1, "max": 0.93}},
      "mean_fpl_w": {"skirt": 120.5, "bearing": null},
      "kpis": {"skirt": {"min_moft[m]": 1.2e-6, "min_moft_crank_angle[deg]": 400,
                         "min_moft_position_angle[deg]": 0, "peak_pressure[Pa]": 5e6,
                         "peak_contact_pressure[Pa]": 0, "mean_fpl[W]": 120.5,
                         "slap_energy_max[J]": 7.5e-5, "slap_energy_max_crank_angle[deg]": 358,
                         "slap_energy_sum[J]": 2.25e-4, "slap_events": []}},
      "discretisation_error": {"status": "estimated", "worst_relative": 0.028}})");
    const auto row = filmdyn::io::ReadComparisonRow(folder);
    QCOMPARE(row.folder, std::string("c-skirt-lbrbe-6000"));
    QCOMPARE(row.model, std::string("skirt-lbrbe"));
    QCOMPARE(row.rpm, 6000.0);
    QCOMPARE(row.cycles, 4);
    QCOMPARE(*row.figures[FigureIndex("max_abs_piston_lateral[m]")], 2.0e-5);
    QCOMPARE(*row.figures[FigureIndex("min_skirt_moft[m]")], 1.2e-6);
    QCOMPARE(*row.figures[FigureIndex("max_bearing_eps[-]")], 0.93);
    QCOMPARE(*row.figures[FigureIndex("mean_skirt_fpl[W]")], 120.5);
    QVERIFY(!row.figures[FigureIndex("mean_bearing_fpl[W]")].has_value());  // null
    QVERIFY(!row.figures[FigureIndex("min_bearing_moft[m]")].has_value());  // absent
    QCOMPARE(*row.figures[FigureIndex("max_discretisation_error[-]")], 0.028);
    // The piston slap from the KPIs.
    QCOMPARE(*row.figures[FigureIndex("max_slap_energy[J]")], 7.5e-5);
    QCOMPARE(*row.figures[FigureIndex("slap_energy_sum[J]")], 2.25e-4);
    // No oil account (a Reynolds film): no oil per cycle to compare.
    QVERIFY(!row.figures[FigureIndex("skirt_oil_per_cycle[m^3]")].has_value());

    std::ostringstream csv;
    filmdyn::io::WriteComparisonCsv(csv, {row});
    const QString text = QString::fromStdString(csv.str());
    QVERIFY(text.startsWith("run,model,rpm[rpm],status,cycles[-],wall_time[s],"));
    QCOMPARE(text.count('\n'), 2);
    const QString markdown = QString::fromStdString(filmdyn::io::ComparisonMarkdown({row}));
    QVERIFY(markdown.contains("| skirt-lbrbe | 6000 | completed | 4 | 7.5 | 20 |"));  // µm
    // Every row of the Markdown table has the same number of cells.
    const auto lines = markdown.trimmed().split('\n');
    for (const auto& line : lines) QCOMPARE(line.count('|'), lines.first().count('|'));
  }

  // An ideal joint's clearance motion and film figures are not zeros to compare but absent: an
  // ideal run's results.csv carries 0 in those columns (a centred journal, no piston motion).
  void idealJointsHaveNoFilmFigures() {
    QTemporaryDir dir;
    const std::string extremes = R"("extremes": {
        "piston_lateral[m]": {"min": 0, "max": 0}, "piston_tilt[rad]": {"min": 0, "max": 0},
        "skirt_moft[m]": {"min": 0, "max": 0}, "bearing_eps[-]": {"min": 0, "max": 0},
        "bearing_moft[m]": {"min": 0, "max": 0},
        "skirt_normal_force[N]": {"min": -1800, "max": 1879},
        "bigend_force_x[N]": {"min": -5758, "max": 10}})";
    for (const auto& [model, skirt_film, big_end_film] :
         std::vector<std::tuple<std::string, bool, bool>>{
             {"ideal", false, false}, {"only-skirt", true, false}, {"only-lbrbe", false, true}}) {
      const std::filesystem::path folder =
          dir.filePath(QString::fromStdString(model)).toStdString();
      WriteSummary(folder, R"({"model": ")" + model +
                               R"(", "rpm": 6000, "status": "completed", "cycles": 2, )" +
                               extremes + "}");
      const auto row = filmdyn::io::ReadComparisonRow(folder);
      for (const char* key :
           {"max_abs_piston_lateral[m]", "max_abs_piston_tilt[rad]", "min_skirt_moft[m]"}) {
        QVERIFY2(row.figures[FigureIndex(key)].has_value() == skirt_film,
                 qPrintable(QString::fromStdString(model + " " + key)));
      }
      for (const char* key : {"max_bearing_eps[-]", "min_bearing_moft[m]"}) {
        QVERIFY2(row.figures[FigureIndex(key)].has_value() == big_end_film,
                 qPrintable(QString::fromStdString(model + " " + key)));
      }
      // The joints' reactions exist for ideal joints too.
      QCOMPARE(*row.figures[FigureIndex("max_abs_skirt_normal_force[N]")], 1879.0);
      QCOMPARE(*row.figures[FigureIndex("max_abs_bigend_force_x[N]")], 5758.0);
    }
  }

  // A mass-conserving film's oil per cycle (its KPI, kept with an oil account) is compared; a
  // Reynolds film's sampled flows are not.
  void oilPerCycleOfMassConservingFilms() {
    QTemporaryDir dir;
    const std::filesystem::path folder = dir.filePath("oil").toStdString();
    WriteSummary(folder, R"({"model": "skirt-lbrbe", "rpm": 6000, "status": "completed",
      "cycles": 2, "wall_time_s": 9.0, "extremes": {},
      "kpis": {"skirt": {"min_moft[m]": 1.8e-5, "oil_in_per_cycle[m^3]": 3.0e-6,
                         "oil_out_per_cycle[m^3]": 3.0e-6, "oil_balance[-]": null,
                         "mean_wetted_fraction[-]": 0.93},
               "big_end": {"min_moft[m]": 1.4e-6, "oil_in_per_cycle[m^3]": 1.2874e-7,
                           "oil_out_per_cycle[m^3]": 1.2873e-7, "oil_balance[-]": 2e-14}}})");
    const auto row = filmdyn::io::ReadComparisonRow(folder);
    QCOMPARE(*row.figures[FigureIndex("bearing_oil_per_cycle[m^3]")], 1.2874e-7);
    QVERIFY(!row.figures[FigureIndex("skirt_oil_per_cycle[m^3]")].has_value());
    // A Reynolds skirt's "wetted" share is its uncavitated share: not compared either.
    QVERIFY(!row.figures[FigureIndex("mean_skirt_wetted_fraction[-]")].has_value());
    const QString markdown = QString::fromStdString(filmdyn::io::ComparisonMarkdown({row}));
    QVERIFY2(markdown.contains("big-end oil per cycle [mm³]") && markdown.contains("| 128.7 |"),
             qPrintable(markdown));
    // A mass-conserving (here starved) skirt: its oil and its mean wetted fraction, in %.
    const std::filesystem::path starved = dir.filePath("starved").toStdString();
    WriteSummary(starved, R"({"model": "only-skirt", "rpm": 6000, "status": "completed",
      "cycles": 2, "wall_time_s": 9.0, "extremes": {},
      "kpis": {"skirt": {"min_moft[m]": 1.7e-6, "oil_in_per_cycle[m^3]": 1.62e-7,
                         "oil_out_per_cycle[m^3]": 1.62e-7, "oil_balance[-]": -6e-14,
                         "mean_wetted_fraction[-]": 0.351}}})");
    const auto fed = filmdyn::io::ReadComparisonRow(starved);
    QCOMPARE(*fed.figures[FigureIndex("mean_skirt_wetted_fraction[-]")], 0.351);
    QCOMPARE(*fed.figures[FigureIndex("skirt_oil_per_cycle[m^3]")], 1.62e-7);
    const QString table = QString::fromStdString(filmdyn::io::ComparisonMarkdown({fed}));
    QVERIFY2(table.contains("mean skirt wetted fraction [%]") && table.contains("| 35.1 |"),
             qPrintable(table));
  }

  // A peak film pressure the run warns is a spike between its output samples (unresolved_peak)
  // is no figure to compare (its sampled height depends on the output interval): the comparison
  // leaves it out and says why, in comparison.csv's last column and below comparison.md's table;
  // the other joint's peak and every other figure stay.
  void peakBetweenSamplesIsLeftOutWithANote() {
    QTemporaryDir dir;
    const std::filesystem::path folder = dir.filePath("jfo").toStdString();
    WriteSummary(folder, R"({"model": "skirt-lbrbe", "rpm": 6000, "status": "completed",
      "cycles": 3, "wall_time_s": 11.0,
      "extremes": {"skirt_peak_pressure[Pa]": {"min": 0, "max": 5.7e6},
                   "bearing_peak_pressure[Pa]": {"min": 0, "max": 1.848e9},
                   "bearing_eps[-]": {"min": 0.1, "max": 0.97},
                   "bigend_force_x[N]": {"min": -8.5e4, "max": 5.7e3, "min_spike": true},
                   "bigend_force_y[N]": {"min": -1.1e4, "max": 9.0e3, "min_spike": true}},
      "warnings": [{"code": "high_eccentricity", "joint": "big_end", "value": 0.97,
                    "limit": 0.95},
                   {"code": "unresolved_peak", "joint": "big_end", "value": 10.1,
                    "limit": 1.5, "message": "peak big-end film pressure …"}]})");
    const auto row = filmdyn::io::ReadComparisonRow(folder);
    QVERIFY(!row.figures[FigureIndex("max_bearing_peak_pressure[Pa]")].has_value());
    QCOMPARE(*row.figures[FigureIndex("max_skirt_peak_pressure[Pa]")], 5.7e6);
    QCOMPARE(*row.figures[FigureIndex("max_bearing_eps[-]")], 0.97);
    // An extreme the summary marks a spike (the impact's force) is left out too: the larger
    // magnitude of F_x and of F_y is the marked min.
    QVERIFY(!row.figures[FigureIndex("max_abs_bigend_force_x[N]")].has_value());
    QVERIFY(!row.figures[FigureIndex("max_abs_bigend_force_y[N]")].has_value());
    QCOMPARE(row.notes.size(), std::size_t(3));  // in the figures' order
    QCOMPARE(row.notes[0], std::string("max abs big-end F_x left out: a spike the output samples "
                                       "do not resolve (its sampled height depends on the "
                                       "output interval)"));
    QVERIFY(QString::fromStdString(row.notes[1]).startsWith("max abs big-end F_y left out"));
    QVERIFY(QString::fromStdString(row.notes[2]).startsWith("peak big-end film pressure left out"));

    std::ostringstream csv;
    filmdyn::io::WriteComparisonCsv(csv, {row});
    const QStringList lines = QString::fromStdString(csv.str()).trimmed().split('\n');
    QCOMPARE(lines.size(), 2);
    QVERIFY(lines[0].endsWith(",notes"));
    QVERIFY(lines[1].endsWith(
        "," + QString::fromStdString(filmdyn::io::NotesText(row.notes))));  // no comma: unquoted
    QCOMPARE(filmdyn::io::NotesText(row.notes),
             row.notes[0] + "; " + row.notes[1] + "; " + row.notes[2]);
    // The cell itself is empty: the two commas around it.
    const int column = int(lines[0].split(',').indexOf("max_bearing_peak_pressure[Pa]"));
    QVERIFY(column > 0);
    QCOMPARE(lines[1].split(',')[column], QString());
    const QString markdown = QString::fromStdString(filmdyn::io::ComparisonMarkdown({row}));
    QVERIFY(markdown.contains("Notes:\n\n- jfo: max abs big-end F_x left out"));
    QVERIFY(markdown.contains("\n- jfo: peak big-end film pressure left out"));
    QVERIFY(!markdown.contains("1848") && !markdown.contains("8.5e+04"));

    // The skirt's spike leaves out the skirt's peak; a run without the warning keeps its peaks
    // and has no notes.
    const std::filesystem::path skirt = dir.filePath("starved").toStdString();
    WriteSummary(skirt, R"({"model": "only-skirt", "rpm": 2000, "status": "completed",
      "extremes": {"skirt_peak_pressure[Pa]": {"min": 0, "max": 9.2e7}},
      "warnings": [{"code": "unresolved_peak", "joint": "skirt", "value": 3.0, "limit": 1.5}]})");
    const auto starved = filmdyn::io::ReadComparisonRow(skirt);
    QVERIFY(!starved.figures[FigureIndex("max_skirt_peak_pressure[Pa]")].has_value());
    QVERIFY(QString::fromStdString(starved.notes.at(0)).startsWith("peak skirt film pressure"));
    const std::filesystem::path plain = dir.filePath("reynolds").toStdString();
    WriteSummary(plain, R"({"model": "only-skirt", "rpm": 2000, "status": "completed",
      "extremes": {"skirt_peak_pressure[Pa]": {"min": 0, "max": 9.2e7},
                   "skirt_normal_force[N]": {"min": -2.4e3, "max": 1.8e3, "max_spike": true}}})");
    const auto reynolds = filmdyn::io::ReadComparisonRow(plain);
    QCOMPARE(*reynolds.figures[FigureIndex("max_skirt_peak_pressure[Pa]")], 9.2e7);
    // The larger magnitude (the min) is resolved: a spike at the smaller extreme does not matter.
    QCOMPARE(*reynolds.figures[FigureIndex("max_abs_skirt_normal_force[N]")], 2.4e3);
    QVERIFY(reynolds.notes.empty());
    std::ostringstream both;
    filmdyn::io::WriteComparisonCsv(both, {reynolds, row});
    QVERIFY(QString::fromStdString(both.str()).split('\n')[1].endsWith(","));  // empty notes
  }

  void missingOrBrokenSummaryNamesTheFile() {
    QTemporaryDir dir;
    const std::filesystem::path missing = dir.filePath("nothing").toStdString();
    try {
      filmdyn::io::ReadComparisonRow(missing);
      QFAIL("no error");
    } catch (const std::runtime_error& error) {
      QVERIFY(QString(error.what()).contains("nothing/summary.json"));
    }
    const std::filesystem::path broken = dir.filePath("broken").toStdString();
    WriteSummary(broken, "{ not json");
    QVERIFY_THROWS_EXCEPTION(std::runtime_error, filmdyn::io::ReadComparisonRow(broken));
  }
};

QTEST_GUILESS_MAIN(TestRunComparison)
#include "test_run_comparison.moc"
