// The sweep comparison reads the main figures of each run from its summary.json.
#include <QTemporaryDir>
#include <QtTest>
#include <fstream>
#include <sstream>

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
