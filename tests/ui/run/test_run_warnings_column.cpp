// The run table's Warnings column on a real run: core's run job through the GUI's backend into a
// run record (as the worker thread does it), then the table row. A big end with rough surfaces
// runs below h/σ = 1 at 6000 rpm: the cell names the film ratio in red and its tooltip holds
// every warning's message; a run without warnings shows "–". Beside it, the discretisation-error
// cell's tooltip names both crank angles of a minimum film the meshes put at different places.
#include <QDir>
#include <QTemporaryDir>
#include <QtTest>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "core/io/case_file.hpp"
#include "core/io/run_summary.hpp"
#include "tests/ui/tooltip_screenshot.hpp"
#include "ui/run/run_backend.hpp"
#include "ui/run/run_record.hpp"
#include "ui/runs/run_table.hpp"

using namespace filmdyn;

namespace {

ui::RunRequest RoughBigEnd() {
  ui::RunRequest request;
  request.engine_case =
      io::LoadCase({}, {"big_end.roughness_journal=1.5e-6", "big_end.roughness_bearing=1.5e-6",
                        "solver.error_estimate=0", "solver.output_interval=0.0349065850398866"})
          .value;
  request.model = "only-lbrbe";
  request.rpm = 6000.0;
  return request;
}

// With FILMDYN_SCREENSHOT_DIR set: the first row's discretisation-error cell and its tooltip, cut
// from the screen into `name` there, for review. True when not set or saved.
bool SaveErrorTooltip(ui::RunTable* table, const QString& name) {
  const QString dir = qEnvironmentVariable("FILMDYN_SCREENSHOT_DIR");
  if (dir.isEmpty()) return true;
  table->resize(1500, 120);
  table->show();
  QTableWidgetItem* cell = table->item(0, ui::RunTable::kError);
  table->scrollToItem(cell, QAbstractItemView::PositionAtCenter);
  if (!QTest::qWaitForWindowExposed(table)) return false;
  QDir().mkpath(dir);
  const bool saved = test::SaveCellToolTip(table, table->visualItemRect(cell), cell->toolTip(),
                                           QDir(dir).filePath(name));
  table->hide();
  return saved;
}

}  // namespace

class TestRunWarningsColumn : public QObject {
  Q_OBJECT
 private slots:
  void errorTooltipNamesWhereTheMeshesPutTheMinimum() {
    auto run = std::make_shared<ui::RunRecord>(1, RoughBigEnd());
    engine::ErrorEstimate e;
    e.status = "estimated";
    engine::FigureError moft;
    moft.figure = engine::HeadlineFigureFor("bearing_moft_min[m]", 0.93e-6);
    moft.coarse_value = 0.894e-6;
    moft.error = -0.091e-6;
    moft.relative = 0.098;
    constexpr double kDeg = std::numbers::pi / 180.0;
    moft.crank_angle = (3 * 720.0 + 392.0) * kDeg;
    moft.extrapolated_crank_angle = (3 * 720.0 + 48.0) * kDeg;
    moft.extreme_elsewhere = true;
    e.figures = {moft};
    e.worst_relative = 0.098;
    e.worst_label = moft.figure.label;
    run->ReportErrorEstimate(e);
    run->finish(ui::RunStatus::kFinished, {});
    ui::RunTable table;
    table.updateRun(run);
    const QString tip = table.item(0, ui::RunTable::kError)->toolTip();
    QVERIFY2(tip.contains("min big-end MOFT: 0.93 µm, −9.8 % → 0.839 µm (at 392 °CA, "
                          "extrapolated at 48 °CA)"),
             qPrintable(tip));
    QVERIFY2(tip.contains("the meshes disagree on where the min big-end MOFT lies"),
             qPrintable(tip));
    QVERIFY(SaveErrorTooltip(&table, "run_error_tooltip_elsewhere.png"));
    // Where they agree, no crank angles.
    moft.extreme_elsewhere = false;
    e.figures = {moft};
    run->ReportErrorEstimate(e);
    table.updateRun(run);
    QVERIFY(!table.item(0, ui::RunTable::kError)->toolTip().contains("extrapolated at"));
    QVERIFY(!table.item(0, ui::RunTable::kError)->toolTip().contains("over cycles"));
  }

  // The oil per cycle of a mass-conserving big end, in mm³, beside its other figures; none for
  // the lubricated skirt it does not have, nor for a Reynolds film.
  void tableShowsTheOilPerCycleOfMassConservingFilms() {
    ui::RunRequest request;
    request.engine_case =
        io::LoadCase({}, {"big_end.cavitation=jfo", "big_end.mesh_theta=24", "big_end.mesh_z=6",
                          "solver.error_estimate=0", "solver.max_cycles=1",
                          "solver.output_interval=0.0349065850398866"})
            .value;
    request.model = "only-lbrbe";
    request.rpm = 6000.0;
    auto run = std::make_shared<ui::RunRecord>(1, request);
    const std::atomic<bool> cancel{false};
    ui::CoreRunBackend()(run->request(), cancel, *run);
    run->finish(ui::RunStatus::kFinished, {});
    const auto stats = run->statistics();
    QVERIFY(stats.count(ui::kBigEndOilStatistic) && !stats.count(ui::kSkirtOilStatistic));
    const double oil = stats.at(ui::kBigEndOilStatistic);
    QVERIFY(oil > 0.0);
    ui::RunTable table;
    table.updateRun(run);
    QCOMPARE(table.item(0, ui::RunTable::kBearingOil)->text(), QString::number(oil * 1e9, 'f', 1));
    QCOMPARE(table.item(0, ui::RunTable::kSkirtOil)->text(), QString("–"));
    QCOMPARE(table.horizontalHeaderItem(ui::RunTable::kBearingOil)->text(),
             QString("oil big end [mm³/cycle]"));
    qInfo("big-end oil per cycle: %s mm³",
          qPrintable(table.item(0, ui::RunTable::kBearingOil)->text()));
    // A saved project restores it from the run folder's summary.json (its KPIs).
    QTemporaryDir folder;
    QString error;
    QVERIFY2(run->writeRunFolder(folder.path(), &error), qPrintable(error));
    const io::RunSummary summary =
        io::ReadSummaryJson(std::filesystem::path(folder.filePath("summary.json").toStdString()));
    const ui::RunCounters restored = ui::OilCounters({}, summary.kpis);
    QCOMPARE(restored.big_end_oil_per_cycle, oil);
    QVERIFY(std::isnan(restored.skirt_oil_per_cycle));

    auto reynolds = std::make_shared<ui::RunRecord>(2, RoughBigEnd());
    ui::CoreRunBackend()(reynolds->request(), cancel, *reynolds);
    reynolds->finish(ui::RunStatus::kFinished, {});
    QVERIFY(!reynolds->statistics().count(ui::kBigEndOilStatistic));
    table.updateRun(reynolds);
    QCOMPARE(table.item(1, ui::RunTable::kBearingOil)->text(), QString("–"));
    if (const QString dir = qEnvironmentVariable("FILMDYN_SCREENSHOT_DIR"); !dir.isEmpty()) {
      table.resize(1500, 120);
      table.show();
      table.scrollToItem(table.item(0, ui::RunTable::kBearingOil));
      QVERIFY(QTest::qWaitForWindowExposed(&table));
      QDir().mkpath(dir);
      QVERIFY(table.grab().save(QDir(dir).filePath("run_table_oil.png")));
    }
  }

  void tableShowsTheRunsWarnings() {
    auto run = std::make_shared<ui::RunRecord>(1, RoughBigEnd());
    const std::atomic<bool> cancel{false};
    ui::CoreRunBackend()(run->request(), cancel, *run);
    run->finish(ui::RunStatus::kFinished, {});
    const std::vector<io::RunWarning> warnings = run->engineeringWarnings();
    QVERIFY(!warnings.empty());
    QCOMPARE(warnings.front().code, std::string("asperity_contact"));

    ui::RunTable table;
    table.updateRun(run);
    // The error cell's tooltip also says how far the headline figures moved over the last
    // cycles (the run's summary.json cycle_scatter), which the mesh estimate does not hold.
    QVERIFY(run->cycleScatter().has_value());
    const QString error_tip = table.item(0, ui::RunTable::kError)->toolTip();
    QVERIFY2(error_tip.contains(
                 QString::fromStdString(run->cycleScatter()->Summary()).toHtmlEscaped()) &&
                 error_tip.contains("a lower bound on the time integration"),
             qPrintable(error_tip));
    QVERIFY(SaveErrorTooltip(&table, "run_error_tooltip_cycles.png"));
    const QTableWidgetItem* cell = table.item(0, ui::RunTable::kWarnings);
    QVERIFY(cell);
    QVERIFY2(cell->text().startsWith("⚠ h/σ 0.") && cell->text().contains("< 1 big end"),
             qPrintable(cell->text()));
    QVERIFY(cell->text().contains(QString("+%1").arg(warnings.size() - 1)));
    QCOMPARE(cell->foreground().color(), QColor(180, 0, 0));
    for (const io::RunWarning& w : warnings) {
      QVERIFY(cell->toolTip().contains(QString::fromStdString(w.message).toHtmlEscaped()));
    }
    QCOMPARE(table.horizontalHeaderItem(ui::RunTable::kWarnings)->text(), QString("Warnings"));

    // A run that reported none.
    auto quiet = std::make_shared<ui::RunRecord>(2, RoughBigEnd());
    quiet->finish(ui::RunStatus::kFinished, {});
    table.updateRun(quiet);
    QCOMPARE(table.item(1, ui::RunTable::kWarnings)->text(), QString("–"));
    QVERIFY(table.item(1, ui::RunTable::kWarnings)->toolTip().isEmpty());

    // With FILMDYN_SCREENSHOT_DIR set: the table around the column, for review.
    if (const QString dir = qEnvironmentVariable("FILMDYN_SCREENSHOT_DIR"); !dir.isEmpty()) {
      table.resize(1500, 120);
      table.show();
      table.scrollToItem(table.item(0, ui::RunTable::kWarnings),
                         QAbstractItemView::PositionAtCenter);
      QDir().mkpath(dir);
      QVERIFY(table.grab().toImage().save(QDir(dir).filePath("run_table_warnings.png")));
    }
  }
};

QTEST_MAIN(TestRunWarningsColumn)
#include "test_run_warnings_column.moc"
