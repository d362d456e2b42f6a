// The Study page with a real study: `filmdyn study` (the real executable) runs six points — the
// Ideal model and a coarse Only-LBRBE with film fields, each at three speeds — then one point's
// summary is marked failed and one folder emptied (pending). The page reads the folder, shows
// every point with its factors, state and figures (the failed point's reason as tooltip), sorts
// numerically with empty cells last, draws any figure against any factor (a click on a point
// selects its row, the selected row is marked in the plot), and opens a point's run in the
// results view with the values of its results.csv and its film fields; a pending point has no
// run to open, a folder without study.json is refused naming it.
#include <QCategoryAxis>
#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QFont>
#include <QHeaderView>
#include <QLabel>
#include <QProcess>
#include <QPushButton>
#include <QScatterSeries>
#include <QScrollBar>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTableView>
#include <QTemporaryDir>
#include <QValueAxis>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <memory>

#include "core/engine/engine_case.hpp"
#include "core/io/run_comparison.hpp"
#include "ui/main_window.hpp"
#include "ui/plots/plot_panel.hpp"
#include "ui/plots/study_charts.hpp"
#include "ui/runs/run_table.hpp"
#include "ui/study/study_view.hpp"

using filmdyn::ui::MainWindow;
using filmdyn::ui::StudyView;

namespace {

// Ideal and a coarse Only-LBRBE (with fields) at 2000, 4000 and 6000 rpm.
const char kStudy[] = R"({
  "name": "gui",
  "design": "full-factorial",
  "fields": true,
  "set": {"big_end.mesh_theta": 24, "big_end.mesh_z": 6, "solver.error_estimate": 0,
          "solver.max_cycles": 2},
  "factors": [
    {"path": "model", "levels": ["ideal", "only-lbrbe"]},
    {"path": "operating.rpm", "levels": [2000, 4000, 6000]}
  ]
})";

int FigureIndex(const std::string& key) {
  const auto& figures = filmdyn::io::ComparisonFigures();
  for (std::size_t k = 0; k < figures.size(); ++k) {
    if (figures[k].key == key) return int(k);
  }
  return -1;
}

int ColumnNamed(QTableView* table, const QString& name) {
  for (int c = 0; c < table->model()->columnCount(); ++c) {
    if (table->model()->headerData(c, Qt::Horizontal).toString() == name) return c;
  }
  return -1;
}

QString Cell(QTableView* table, int row, int column) {
  return table->model()->index(row, column).data().toString();
}

QByteArray ReadAll(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

void Save(QWidget* widget, const QString& name) {
  const QString dir = qEnvironmentVariable("FILMDYN_SCREENSHOT_DIR");
  if (dir.isEmpty()) return;
  QDir().mkpath(dir);
  QVERIFY(widget->grab().toImage().save(QDir(dir).filePath(name)));
}

}  // namespace

class TestStudyView : public QObject {
  Q_OBJECT

  QTemporaryDir dir_;
  QString study_;  // the study folder

 private slots:
  void initTestCase() {
    QVERIFY(dir_.isValid());
    QFile file(dir_.filePath("gui.json"));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(kStudy);
    file.close();
    study_ = dir_.filePath("study");
    QProcess process;
    process.start(FILMDYN_EXECUTABLE,
                  {"study", dir_.filePath("gui.json"), "--out", study_, "--quiet", "--jobs", "2"});
    QVERIFY(process.waitForFinished(600000));
    QVERIFY2(process.exitCode() == 0, process.readAllStandardError().constData());
    // Point 3 (Ideal, 6000 rpm) marked failed with a reason; point 2 emptied (pending).
    const QString summary = QDir(study_).filePath("point-0003/summary.json");
    QByteArray text = ReadAll(summary);
    QVERIFY(text.contains("\"status\": \"completed\""));
    text.replace("\"status\": \"completed\"", "\"status\": \"failed\"");
    text.replace("\"message\": \"\"", "\"message\": \"test: a broken point\"");
    QFile out(summary);
    QVERIFY(out.open(QIODevice::WriteOnly | QIODevice::Truncate));
    out.write(text);
    out.close();
    QVERIFY(QDir(QDir(study_).filePath("point-0002")).removeRecursively());
    // Point 6 (Only-LBRBE, 6000 rpm): its peak big-end film pressure marked a spike between the
    // output samples (as a mass-conserving film's impact is).
    const QString six = QDir(study_).filePath("point-0006/summary.json");
    text = ReadAll(six);
    QVERIFY(text.contains("\"bearing_peak_pressure[Pa]\": {"));
    text.replace("\"bearing_peak_pressure[Pa]\": {",
                 "\"bearing_peak_pressure[Pa]\": {\"max_spike\": true, ");
    QFile out6(six);
    QVERIFY(out6.open(QIODevice::WriteOnly | QIODevice::Truncate));
    out6.write(text);
    out6.close();
  }

  // Opening another study while the points of the one before are read does not wait for that
  // read (it held the window): its rows are dropped, and the folder open now is what shows.
  void openingAnotherStudyDropsTheReadUnderWay() {
    const QString other = dir_.filePath("study-b");
    QCOMPARE(QProcess::execute("cp", {"-a", study_, other}), 0);
    QVERIFY(QDir(QDir(other).filePath("point-0005")).removeRecursively());
    StudyView view;
    QSignalSpy loaded(&view, &StudyView::loaded);
    QString error;
    QVERIFY2(view.openFolder(study_, &error), qPrintable(error));
    QVERIFY(view.isLoading());
    QVERIFY2(view.openFolder(other, &error), qPrintable(error));
    QVERIFY(loaded.wait(30000));
    QTRY_VERIFY_WITH_TIMEOUT(!view.isLoading(), 30000);
    QCOMPARE(loaded.count(), 1);
    QVERIFY(view.row(5) != nullptr && view.row(4) != nullptr);
    QCOMPARE(int(view.row(5)->state), int(filmdyn::batch::PointState::kPending));
    QCOMPARE(int(view.row(4)->state), int(filmdyn::batch::PointState::kDone));
  }

  void aFolderWithoutAStudyIsRefusedNamingTheFile() {
    StudyView view;
    QString error;
    QVERIFY(!view.openFolder(dir_.path(), &error));
    QVERIFY2(error.contains("study.json"), qPrintable(error));
    QVERIFY(view.folder().isEmpty());
  }

  void theTableShowsEveryPointSortedNumericallyWithEmptyCellsLast() {
    StudyView view;
    QSignalSpy loaded(&view, &StudyView::loaded);
    QString error;
    QVERIFY2(view.openFolder(study_, &error), qPrintable(error));
    QVERIFY(loaded.count() == 1 || loaded.wait(30000));
    QTableView* table = view.table();
    QCOMPARE(table->model()->rowCount(), 6);
    const int model = ColumnNamed(table, "model");
    const int rpm = ColumnNamed(table, "operating.rpm [rpm]");
    const int state = ColumnNamed(table, "state");
    const int moft = ColumnNamed(table, "min bearing MOFT [µm]");
    QVERIFY(model > 0 && rpm > model && state > rpm && moft > state);
    // Headers name the case path and the figure as the study file and study.csv do; their
    // tooltips say what they are.
    const QString rpm_tip =
        table->model()->headerData(rpm, Qt::Horizontal, Qt::ToolTipRole).toString();
    QVERIFY2(rpm_tip.endsWith("(operating.rpm)") && rpm_tip.size() > 20, qPrintable(rpm_tip));
    QCOMPARE(table->model()->headerData(moft, Qt::Horizontal, Qt::ToolTipRole).toString(),
             QString("min_bearing_moft[m]"));
    // The run model by its title, as the run page names it (the study file's token "ideal").
    QCOMPARE(Cell(table, 0, model), QString("Ideal"));
    QCOMPARE(Cell(table, 3, model), QString("Only-LBRBE"));
    QCOMPARE(Cell(table, 4, rpm), QString("4000"));
    QCOMPARE(Cell(table, 1, state), QString("pending"));
    QVERIFY(Cell(table, 2, state).startsWith("failed"));
    QCOMPARE(table->model()->index(2, state).data(Qt::ToolTipRole).toString(),
             QString("test: a broken point"));
    // A completed run is "done", not "done (completed)".
    QCOMPARE(Cell(table, 3, state), QString("done"));
    // Forces in kN as the run page plots them, each column in common decimals (about 4
    // significant digits for its largest value: 2634.1 N → "2.634", not "2634.1" beside "2489").
    const int fn = ColumnNamed(table, "max abs skirt F_n [kN]");
    QVERIFY(fn > state);
    const QString fn_done = Cell(table, 0, fn);
    QVERIFY2(fn_done.size() > 2 && fn_done.split('.').value(1).size() == 3, qPrintable(fn_done));
    for (int r : {3, 4, 5}) {
      QCOMPARE(Cell(table, r, fn).split('.').value(1).size(), 3);
      const double kn = Cell(table, r, fn).toDouble();
      QVERIFY2(kn > 0.1 && kn < 100, qPrintable(Cell(table, r, fn)));
    }
    // The failed point's figures are the part of the cycle its run computed: greyed, italic, and
    // the tooltip says so (the charts leave them out).
    const QModelIndex partial = table->model()->index(2, fn);
    QVERIFY(partial.data().toString() != "–");
    QVERIFY(partial.data(Qt::FontRole).value<QFont>().italic());
    QVERIFY2(partial.data(Qt::ToolTipRole).toString().startsWith("Partial: the run failed"),
             qPrintable(partial.data(Qt::ToolTipRole).toString()));
    QVERIFY(!table->model()->index(3, fn).data(Qt::FontRole).value<QFont>().italic());
    // MOFT in µm as study.csv has it in m.
    const double moft4 = Cell(table, 3, moft).toDouble();
    QVERIFY2(moft4 > 0.1 && moft4 < 20, qPrintable(Cell(table, 3, moft)));
    QCOMPARE(view.findChild<QLabel*>("study_counts")->text(),
             QString("6 points, 4 done, 1 failed, 1 pending"));
    // Point 6's spike is left out of the table, and the cell's tooltip and the last column say
    // why; point 5 keeps its peak pressure.
    const int peak = ColumnNamed(table, "peak big-end film pressure [MPa]");
    const int notes = ColumnNamed(table, "reason, notes");
    QVERIFY(peak > moft && notes > peak);
    QVERIFY(Cell(table, 4, peak).toDouble() > 0.0);
    QCOMPARE(Cell(table, 5, peak), QString("–"));
    const QString why = table->model()->index(5, peak).data(Qt::ToolTipRole).toString();
    QVERIFY2(why.startsWith("peak big-end film pressure left out: a spike the output samples do "
                            "not resolve"),
             qPrintable(why));
    QCOMPARE(Cell(table, 5, notes), why);
    QCOMPARE(Cell(table, 4, notes), QString());
    view.resize(1200, 600);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    table->horizontalScrollBar()->setValue(table->horizontalScrollBar()->maximum());
    QCoreApplication::processEvents();
    Save(&view, "study-notes.png");

    for (Qt::SortOrder order : {Qt::AscendingOrder, Qt::DescendingOrder}) {
      table->sortByColumn(moft, order);
      QStringList cells;
      for (int r = 0; r < 6; ++r) cells << Cell(table, r, moft);
      // Only-LBRBE points (4–6) have a bearing film; the Ideal ones none ("–"), listed last.
      for (int r = 3; r < 6; ++r) QCOMPARE(cells[r], QString("–"));
      for (int r = 0; r + 1 < 3; ++r) {
        const double a = cells[r].toDouble(), b = cells[r + 1].toDouble();
        QVERIFY2(order == Qt::AscendingOrder ? a <= b : a >= b, qPrintable(cells.join(" ")));
      }
    }
    // The speed column sorts as numbers (2000 < 4000 < 6000, not as text).
    table->sortByColumn(rpm, Qt::DescendingOrder);
    QCOMPARE(Cell(table, 0, rpm), QString("6000"));
    QCOMPARE(Cell(table, 5, rpm), QString("2000"));
  }

  void theScatterPlotsAnyFigureAgainstAnyFactorAndSelectsByClick() {
    StudyView view;
    QSignalSpy loaded(&view, &StudyView::loaded);
    QVERIFY(view.openFolder(study_));
    QVERIFY(loaded.count() == 1 || loaded.wait(30000));
    view.resize(1200, 600);
    const int moft = FigureIndex("min_bearing_moft[m]");
    QVERIFY(view.setScatter(1, moft));  // against the speed
    QChart* chart = view.scatterView()->chart();
    QVERIFY(chart != nullptr && !chart->series().isEmpty());
    auto* series = qobject_cast<QScatterSeries*>(chart->series().front());
    QVERIFY(series != nullptr);
    // The three Only-LBRBE points: x the speed, y the table's MOFT.
    QCOMPARE(series->count(), 3);
    QCOMPARE(series->at(0).x(), 2000.0);
    QCOMPARE(series->at(2).x(), 6000.0);
    const int column = ColumnNamed(view.table(), "min bearing MOFT [µm]");
    view.table()->sortByColumn(0, Qt::AscendingOrder);
    for (int k = 0; k < 3; ++k) {
      const double table_value =
          view.table()->model()->index(3 + k, column).data(Qt::UserRole).toDouble();
      QVERIFY2(std::abs(series->at(k).y() - table_value) <= 1e-9 * std::abs(table_value),
               qPrintable(QString("%1 vs %2").arg(series->at(k).y()).arg(table_value)));
    }
    // A click on the middle point selects point 5 (Only-LBRBE, 4000 rpm); the plot marks it.
    emit series->clicked(series->at(1));
    QCOMPARE(view.selectedPoint(), 5);
    QScatterSeries* mark = nullptr;
    for (QAbstractSeries* s : view.scatterView()->chart()->series()) {
      if (s->objectName() == "selected_point") mark = static_cast<QScatterSeries*>(s);
    }
    QVERIFY(mark != nullptr);
    QCOMPARE(mark->count(), 1);
    QCOMPARE(mark->at(0), series->at(1));
    // Another factor: the model as categories; only the done points with the figure.
    QVERIFY(view.setScatter(0, FigureIndex("max_abs_bigend_force_y[N]")));
    series = qobject_cast<QScatterSeries*>(view.scatterView()->chart()->series().front());
    QCOMPARE(series->count(), 4);  // the done points: Ideal 2000 rpm and the three Only-LBRBE
    // The categories are the models' titles.
    QStringList categories;
    for (QAbstractAxis* axis : view.scatterView()->chart()->axes(Qt::Horizontal)) {
      if (auto* c = qobject_cast<QCategoryAxis*>(axis)) categories = c->categoriesLabels();
    }
    QCOMPARE(categories, QStringList({"Ideal", "Only-LBRBE"}));
    // Forces in kN (the figure's display unit).
    QVERIFY2(series->at(0).y() > 1.0 && series->at(0).y() < 100.0,
             qPrintable(QString::number(series->at(0).y())));
    Save(&view, "study-page.png");
  }

  void aLargeStudysScatterDrawsAMarkedRandomSample() {
    // 2 500 done points (synthetic figures): the plot draws a fixed random 2 000 of them, in the
    // rows' order, and says so.
    const filmdyn::batch::Study study = filmdyn::batch::ParseStudy(
        R"({"design": "latin-hypercube", "points": 2500, "factors": [
            {"path": "operating.rpm", "range": [2000, 6000]}]})",
        "large.json");
    std::vector<filmdyn::batch::StudyRow> rows;
    const int moft = FigureIndex("min_bearing_moft[m]");
    for (const auto& p : filmdyn::batch::DesignPoints(study, filmdyn::engine::EngineCase{})) {
      filmdyn::batch::StudyRow r;
      r.point = p;
      r.state = filmdyn::batch::PointState::kDone;
      r.figures.assign(filmdyn::io::ComparisonFigures().size(), std::nullopt);
      r.figures[size_t(moft)] = 1e-6 * *p.numbers[0] / 1000;
      rows.push_back(r);
    }
    const auto drawn = filmdyn::ui::StudyScatterRows(rows, size_t(moft));
    QCOMPARE(drawn.size(), filmdyn::ui::kMaxScatterDots);
    QVERIFY(std::is_sorted(drawn.begin(), drawn.end()));
    QVERIFY(std::adjacent_find(drawn.begin(), drawn.end()) == drawn.end());
    QVERIFY(drawn.back() < rows.size());
    QVERIFY(drawn == filmdyn::ui::StudyScatterRows(rows, size_t(moft)));  // the same every time
    // Spread over the whole design: each quarter of it holds about a quarter of the sample.
    for (int q = 0; q < 4; ++q) {
      const auto in = std::count_if(drawn.begin(), drawn.end(),
                                    [q](size_t n) { return int(n * 4 / 2500) == q; });
      QVERIFY2(in > 400 && in < 600, qPrintable(QString::number(in)));
    }
    std::unique_ptr<QChart> chart(filmdyn::ui::MakeStudyScatterChart(study, rows, 0, size_t(moft)));
    auto* series = qobject_cast<QScatterSeries*>(chart->series().front());
    QCOMPARE(series->count(), 2000);
    QCOMPARE(series->at(0).x(), *rows[drawn[0]].point.numbers[0]);
    QCOMPARE(chart->title(), QString("a random 2000 of 2500 points"));
  }

  void aPointsRunOpensInTheResultsView() {
    MainWindow window;
    window.resize(1400, 900);
    StudyView* view = window.studyView();
    QSignalSpy loaded(view, &StudyView::loaded);
    QVERIFY(view->openFolder(study_));
    QVERIFY(loaded.count() == 1 || loaded.wait(30000));
    const int runs_before = int(window.runTable()->runs().size());

    // A pending point has nothing to open.
    view->selectPoint(2);
    QSignalSpy status(view, &StudyView::statusMessage);
    view->openRunButton()->click();
    QCOMPARE(int(window.runTable()->runs().size()), runs_before);
    QCOMPARE(status.count(), 1);
    QVERIFY(status.first().first().toString().contains("pending"));

    view->selectPoint(5);
    QVERIFY(view->openRunButton()->isEnabled());
    view->openRunButton()->click();
    QCOMPARE(int(window.runTable()->runs().size()), runs_before + 1);
    const auto run = window.runTable()->runs().back();
    QCOMPARE(run->label(), QString("gui · point 5"));
    QCOMPARE(run->request().model, std::string("only-lbrbe"));
    QCOMPARE(run->request().rpm, 4000.0);
    QCOMPARE(run->request().engine_case.big_end.mesh_theta, 24);
    QCOMPARE(window.workspace()->currentIndex(), 1);  // the results page
    // The samples are results.csv's rows (10 significant digits).
    const QList<QByteArray> lines =
        ReadAll(QDir(study_).filePath("point-0005/results.csv")).trimmed().split('\n');
    const auto samples = run->samples();
    QCOMPARE(int(samples.size()), int(lines.size()) - 1);
    const QList<QByteArray> header = lines[0].split(',');
    const QList<QByteArray> last = lines.back().split(',');
    const int eps = int(header.indexOf("bearing_eps[-]"));
    QVERIFY(eps > 0);
    QCOMPARE(samples.back()[filmdyn::ui::Column::kBearingEps], last[eps].toDouble());
    QVERIFY(!run->motion().empty());
    QVERIFY(run->fields() != nullptr);
    QCOMPARE(run->status(), filmdyn::ui::RunStatus::kFinished);
    // Opening it again selects it rather than adding it twice.
    window.workspace()->setCurrentWidget(view);
    view->openRunButton()->click();
    QCOMPARE(int(window.runTable()->runs().size()), runs_before + 1);
    // The failed point opens as a failed run with its reason.
    view->selectPoint(3);
    view->openRunButton()->click();
    QCOMPARE(int(window.runTable()->runs().size()), runs_before + 2);
    QCOMPARE(window.runTable()->runs().back()->status(), filmdyn::ui::RunStatus::kFailed);
    QCOMPARE(window.runTable()->runs().back()->reason(), QString("test: a broken point"));
  }
};

QTEST_MAIN(TestStudyView)
#include "test_study_view.moc"
