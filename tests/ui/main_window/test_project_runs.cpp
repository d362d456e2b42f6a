// Runs you can tell apart and keep: real runs of the main window get automatic labels saying
// what differs from the base run (μ for a viscosity change), names and notes the user gives
// them, an order and a base run; saving the project writes them beside the case, and reopening
// it restores names, notes, order, hidden runs, the base, every sample bit for bit and the film
// fields; a reopened run exports again; a damaged runs folder opens the case and says which
// run could not be restored and why.
#include <QAction>
#include <QChart>
#include <QDir>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QLineSeries>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <cstring>

#include "core/io/run_summary.hpp"
#include "tests/ui/legends_name.hpp"
#include "ui/case_editor/case_document.hpp"
#include "ui/case_editor/case_parameters.hpp"
#include "ui/main_window.hpp"
#include "ui/plots/plot_panel.hpp"
#include "ui/run/run_controller.hpp"
#include "ui/runs/run_store.hpp"
#include "ui/runs/run_table.hpp"

using filmdyn::ui::MainWindow;
using filmdyn::ui::RunHandle;
using filmdyn::ui::RunTable;

namespace {

// Starts a real run of the window's case after `change` and waits for it to end.
RunHandle RunWith(MainWindow& window,
                  const std::function<void(filmdyn::engine::EngineCase&)>& change) {
  QSignalSpy finished(window.runController(), &filmdyn::ui::RunController::runFinished);
  auto c = window.document()->engineCase();
  change(c);
  window.document()->edit(c, "test set-up");
  if (!window.runAction()->isEnabled()) return nullptr;
  window.runAction()->trigger();
  if (!finished.wait(600000)) return nullptr;
  return finished.last().first().value<RunHandle>();
}

// The plots name the run: in the legend above them (on screen) and in each exported plot's own.
bool LegendsName(MainWindow& window, const QString& label) {
  return filmdyn::test::LegendsName(*window.plotPanel(), label);
}

void Save(QWidget* widget, const QString& name) {
  const QString dir = qEnvironmentVariable("FILMDYN_SCREENSHOT_DIR");
  if (dir.isEmpty()) return;
  QDir().mkpath(dir);
  QVERIFY(widget->grab().toImage().save(QDir(dir).filePath(name)));
}

QByteArray ReadAll(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// Bit for bit, NaN included.
bool SameBits(const std::vector<filmdyn::ui::RunSample>& a,
              const std::vector<filmdyn::ui::RunSample>& b) {
  if (a.size() != b.size()) return false;
  for (size_t k = 0; k < a.size(); ++k) {
    if (std::memcmp(a[k].values.data(), b[k].values.data(), sizeof(double) * a[k].values.size()) !=
        0)
      return false;
  }
  return true;
}

}  // namespace

class TestProjectRuns : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName("FilmDynTest");
    QCoreApplication::setApplicationName("test_project_runs");
    QSettings().clear();
  }

  void labelsNamesNotesOrderAndSaveReopen() {
    QTemporaryDir dir;
    const QString project = dir.filePath("study.json");
    auto window = std::make_unique<MainWindow>();
    window->resize(1600, 1000);
    window->show();
    QVERIFY(QTest::qWaitForWindowExposed(window.get()));
    RunTable* table = window->runTable();

    // Two runs differing in viscosity.
    const RunHandle a = RunWith(*window, [](auto& c) {
      filmdyn::ui::ApplyRunModel(c, "ideal");
      c.operating.rpm = 6000;
    });
    QVERIFY(a);
    const RunHandle b = RunWith(*window, [](auto& c) { c.lubricant.viscosity = 0.01; });
    QVERIFY(b);
    QCOMPARE(a->label(), QString("Ideal 6000 rpm"));
    QCOMPARE(b->label(), QString("μ 10 mPa·s"));
    QCOMPARE(table->item(1, RunTable::kRun)->text(), QString("μ 10 mPa·s"));
    QCOMPARE(table->item(0, RunTable::kDifferences)->text(), QString("base run"));
    QCOMPARE(table->item(1, RunTable::kDifferences)->text(), QString("μ 10 mPa·s"));
    QVERIFY(LegendsName(*window, "μ 10 mPa·s"));

    // A lubricated run with film fields (coarse: 4 °CA output, one cycle after a short run-in).
    const RunHandle c = RunWith(*window, [](auto& c) {
      filmdyn::ui::ApplyRunModel(c, "only-lbrbe");
      c.operating.rpm = 4000;
      c.solver.output_interval = 4.0 * M_PI / 180.0;
      c.solver.max_cycles = 1;
      c.solver.run_in_angle = M_PI / 2;
      c.solver.error_estimate = 0;
    });
    QVERIFY(c);
    qInfo("lubricated run: %s %s", qPrintable(filmdyn::ui::RunStatusText(c->status())),
          qPrintable(c->reason()));
    QVERIFY(c->status() == filmdyn::ui::RunStatus::kFinished);
    QVERIFY(c->fields() && !c->fields()->empty());
    QVERIFY(c->label().contains("model Only-LBRBE"));
    QVERIFY(c->label().contains("4000 rpm"));
    // The label keeps to the first differences, physics before numerical settings; the table
    // lists them all.
    QCOMPARE(c->label(), QString("model Only-LBRBE · μ 10 mPa·s · 4000 rpm · +4 more"));
    QVERIFY(table->item(2, RunTable::kDifferences)->text().endsWith("error estimate 0"));
    QVERIFY(table->item(2, RunTable::kDifferences)->toolTip().contains("max cycles: 30 → 1"));

    // Renaming: the table and the label follow; a name another run has is refused.
    table->item(1, RunTable::kRun)->setText("thin oil");
    QCOMPARE(b->label(), QString("thin oil"));
    QCOMPARE(table->item(1, RunTable::kRun)->text(), QString("thin oil"));
    QVERIFY(LegendsName(*window, "thin oil"));
    QString error;
    QVERIFY(!table->renameRun(a->id(), "thin oil", &error));
    QVERIFY(error.contains("thin oil"));
    QCOMPARE(a->label(), QString("Ideal 6000 rpm"));

    // Notes: the first line in the cell, marked as cut, all of it in the tooltip.
    table->setRunNotes(a->id(), "reference\nTable I values, 6000 rpm");
    QCOMPARE(table->item(0, RunTable::kNotes)->text(), QString("reference …"));
    QCOMPARE(table->item(0, RunTable::kNotes)->toolTip(),
             QString("reference\nTable I values, 6000 rpm"));

    // Order: the lubricated run up one place.
    QSignalSpy order(table, &RunTable::orderChanged);
    table->moveRun(c->id(), -1);
    QCOMPARE(order.count(), 1);
    QCOMPARE(table->runs()[1], c);
    QCOMPARE(table->item(1, RunTable::kRun)->text(), c->label());
    // The keys move the selected run too: down and back up.
    window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(window.get()));
    table->setFocus();
    table->selectRow(1);
    QTest::keyClick(table, Qt::Key_Down, Qt::AltModifier);
    QCOMPARE(table->runs()[2], c);
    QTest::keyClick(table, Qt::Key_Up, Qt::AltModifier);
    QCOMPARE(table->runs()[1], c);
    QCOMPARE(order.count(), 3);

    // Hidden and base.
    table->setRunVisible(a->id(), false);
    QVERIFY(!window->plotPanel()->isRunVisible(a->id()));
    const QString c_label = c->label();
    QVERIFY(window->runStateLabel()->text().startsWith(c_label + " — finished"));
    table->setBaseRun(b->id());
    QCOMPARE(table->baseRunId(), b->id());
    QCOMPARE(a->label(), QString("μ 20 mPa·s"));
    // The toolbar's line on the last run follows its label (it kept the old one).
    QVERIFY(c->label() != c_label);
    QVERIFY2(window->runStateLabel()->text().startsWith(c->label() + " — finished"),
             qPrintable(window->runStateLabel()->text()));
    QCOMPARE(table->item(2, RunTable::kDifferences)->text(), QString("base run"));
    window->workspace()->setCurrentIndex(1);
    table->selectRow(0);
    QTest::qWait(200);
    Save(window.get(), "run_table_identity.png");
    // The table shows four runs whole at the default split of a 1000 px window (it showed three
    // and a half).
    QVERIFY2(table->viewport()->height() >= 4 * table->rowHeight(0),
             qPrintable(QString("%1 px for rows of %2")
                            .arg(table->viewport()->height())
                            .arg(table->rowHeight(0))));

    // Save: the case and, beside it, the runs.
    QVERIFY2(window->saveProjectAs(project, &error), qPrintable(error));
    const QString runs_dir = filmdyn::ui::RunsFolderFor(project);
    QCOMPARE(runs_dir, dir.filePath("study.runs"));
    QVERIFY(QFile::exists(runs_dir + "/runs.json"));
    const QString c_folder = c->storedFolder();
    QVERIFY(QFile::exists(c_folder + "/results.csv"));
    QVERIFY(QFile::exists(c_folder + "/summary.json"));
    QVERIFY(QFile::exists(c_folder + "/fields/bearing.h5"));
    QVERIFY(QFile::exists(c_folder + "/fields/bearing.xdmf"));
    QVERIFY(QFile::exists(c_folder + "/motion.csv"));
    QVERIFY(c->motion().size() > 7 * c->samples().size());

    struct Kept {
      QString name, label, notes;
      bool visible;
      std::vector<filmdyn::ui::RunSample> samples, motion;
    };
    std::vector<Kept> kept;
    for (const RunHandle& run : table->runs()) {
      kept.push_back({run->name(), run->label(), run->notes(), table->isRunVisible(run->id()),
                      run->samples(), run->motion()});
    }
    const auto original_fields = c->fields();
    const QByteArray original_csv = c->resultsCsv();
    const auto original_stats = c->statistics();
    // One cycle (solver.max_cycles = 1): no scatter over cycles, and none restored.
    const auto original_scatter = c->cycleScatter();
    QVERIFY(!original_scatter.has_value());
    window->close();
    window.reset();

    // Reopen.
    MainWindow again;
    again.show();
    QVERIFY(QTest::qWaitForWindowExposed(&again));
    QVERIFY2(again.openProject(project, &error), qPrintable(error));
    RunTable* t = again.runTable();
    QCOMPARE(int(t->runs().size()), 3);
    for (size_t k = 0; k < kept.size(); ++k) {
      const RunHandle& run = t->runs()[k];
      QVERIFY2(run->restoreError().isEmpty(), qPrintable(run->restoreError()));
      QCOMPARE(run->name(), kept[k].name);
      QCOMPARE(run->label(), kept[k].label);
      QCOMPARE(run->notes(), kept[k].notes);
      QCOMPARE(t->isRunVisible(run->id()), kept[k].visible);
      QCOMPARE(again.plotPanel()->isRunVisible(run->id()), kept[k].visible);
      QVERIFY2(SameBits(run->samples(), kept[k].samples), qPrintable(run->label()));
      QVERIFY2(SameBits(run->motion(), kept[k].motion), qPrintable(run->label()));
      QCOMPARE(run->status(), filmdyn::ui::RunStatus::kFinished);
    }
    QCOMPARE(t->baseRunId(), t->runs()[2]->id());
    QCOMPARE(t->runs()[2]->label(), QString("thin oil"));
    QVERIFY(LegendsName(again, "thin oil"));

    // The lubricated run: figures, statistics and fields as before.
    const RunHandle rc = t->runs()[1];
    QCOMPARE(rc->statistics().at("cycles"), original_stats.at("cycles"));
    QCOMPARE(rc->statistics().at("steps"), original_stats.at("steps"));
    QCOMPARE(rc->cycleScatter().has_value(), original_scatter.has_value());
    const auto fields = rc->fields();
    QVERIFY(fields != nullptr);
    QCOMPARE(fields->crank_angle_deg, original_fields->crank_angle_deg);
    QCOMPARE(fields->joints.size(), original_fields->joints.size());
    QVERIFY(!original_fields->joints.back().load.empty());
    for (size_t j = 0; j < fields->joints.size(); ++j) {
      const auto& got = fields->joints[j];
      const auto& want = original_fields->joints[j];
      QCOMPARE(got.name, want.name);
      QCOMPARE(got.mesh.triangles, want.mesh.triangles);
      QCOMPARE(got.mesh.points.size(), want.mesh.points.size());
      for (size_t n = 0; n < got.mesh.points.size(); ++n) {
        for (int x = 0; x < 3; ++x)
          QVERIFY(std::abs(got.mesh.points[n][size_t(x)] - want.mesh.points[n][size_t(x)]) < 1e-12);
      }
      QCOMPARE(got.angle_lines.size(), want.angle_lines.size());
      for (size_t i = 0; i < got.angle_lines.size(); ++i)
        QVERIFY(std::abs(got.angle_lines[i] - want.angle_lines[i]) < 1e-9);
      QCOMPARE(got.axial_lines, want.axial_lines);
      QCOMPARE(got.frames.size(), want.frames.size());
      for (size_t k = 0; k < got.frames.size(); ++k) {
        QCOMPARE(got.frames[k].size(), want.frames[k].size());
        for (size_t a = 0; a < got.frames[k].size(); ++a) {
          QCOMPARE(got.frames[k][a].first, want.frames[k][a].first);
          const auto& gv = got.frames[k][a].second;
          const auto& wv = want.frames[k][a].second;
          QCOMPARE(gv.size(), wv.size());
          for (size_t n = 0; n < gv.size(); ++n) {
            // The field files keep nodal arrays in single precision (core/io/field_series.hpp).
            QCOMPARE(gv[n], double(float(wv[n])));
          }
        }
        QVERIFY(std::abs(std::remainder(got.Rotation(k) - want.Rotation(k), 2 * M_PI)) < 1e-12);
      }
      // The big end's load arrows, from results.csv (10 significant digits).
      QCOMPARE(got.load.size(), want.load.size());
      for (size_t k = 0; k < got.load.size(); ++k) {
        for (int x = 0; x < 2; ++x) {
          QVERIFY(std::abs(got.load[k][size_t(x)] - want.load[k][size_t(x)]) <=
                  1e-8 * (1.0 + std::abs(want.load[k][size_t(x)])));
        }
      }
    }

    // A reopened run exports again, byte for byte as before.
    QCOMPARE(rc->resultsCsv(), original_csv);
    QTemporaryDir out;
    QVERIFY2(again.exportRunFolder(rc, out.path(), &error), qPrintable(error));
    QCOMPARE(ReadAll(out.filePath("results.csv")), original_csv);
    QCOMPARE(ReadAll(out.filePath("summary.json")), ReadAll(c_folder + "/summary.json"));
    QCOMPARE(ReadAll(out.filePath("fields/bearing.h5")), ReadAll(c_folder + "/fields/bearing.h5"));
    // A copy that cannot be completed (here "fields" is a file of the user's) leaves a summary
    // that says so, not a folder that reads as a whole run.
    QTemporaryDir blocked;
    {
      QFile in_the_way(blocked.filePath("fields"));
      QVERIFY(in_the_way.open(QIODevice::WriteOnly));
    }
    QVERIFY(!again.exportRunFolder(rc, blocked.path(), &error));
    qInfo("refused: %s", qPrintable(error));
    const filmdyn::io::RunSummary marked =
        filmdyn::io::ReadSummaryJson(blocked.filePath("summary.json").toStdString());
    QCOMPARE(QString::fromStdString(marked.status), QString("failed"));
    QVERIFY(!marked.complete);
    QVERIFY2(QString::fromStdString(marked.message).contains("could not be copied"),
             marked.message.c_str());

    // Saving again keeps the stored folders; a removed run's folder goes, and so do the files a
    // save stopped midway left (a run folder without its samples file, listed nowhere); a run's
    // complete files that no index lists (a lost index) stay.
    const QString a_folder = t->runs()[0]->storedFolder();
    const QDir runs_folder(filmdyn::ui::RunsFolderFor(project));
    QVERIFY(runs_folder.mkpath("run-97") && runs_folder.mkpath("run-98"));
    for (const char* file : {"run-97/results.csv", "run-98/results.csv", "run-98.samples.csv"}) {
      QFile f(runs_folder.filePath(file));
      QVERIFY(f.open(QIODevice::WriteOnly));
    }
    again.removeRun(t->runs()[0]->id());
    QVERIFY2(again.saveProjectAs(project, &error), qPrintable(error));
    QVERIFY(!QFileInfo::exists(a_folder + ".samples.csv"));
    QVERIFY(!QFileInfo::exists(runs_folder.filePath("run-97")));
    QVERIFY(QFileInfo::exists(runs_folder.filePath("run-98/results.csv")));
    QVERIFY(QFileInfo::exists(runs_folder.filePath("run-98.samples.csv")));
    QVERIFY(QFile::exists(c_folder + "/fields/bearing.h5"));
    again.close();

    // A damaged runs folder: the case opens; the damaged run says why; the others are back.
    QFile::remove(c_folder + "/summary.json");
    {
      MainWindow damaged;
      QVERIFY2(damaged.openProject(project, &error), qPrintable(error));
      RunTable* d = damaged.runTable();
      QCOMPARE(int(d->runs().size()), 2);
      const RunHandle broken = d->runs()[0];
      QVERIFY(broken->restoreError().contains("summary.json"));
      QCOMPARE(d->item(0, RunTable::kStatus)->text(), QString("not restored"));
      QCOMPARE(d->item(0, RunTable::kCycles)->text(), QString("–"));  // unknown, not 0
      QCOMPARE(d->item(0, RunTable::kWall)->text(), QString("–"));
      QVERIFY(d->item(0, RunTable::kReason)->text().contains("summary.json"));
      QVERIFY(damaged.statusBar()->currentMessage().contains("summary.json"));
      QVERIFY(d->runs()[1]->restoreError().isEmpty());
      QCOMPARE(d->runs()[1]->label(), QString("thin oil"));
      damaged.workspace()->setCurrentIndex(1);
      damaged.show();
      QVERIFY(QTest::qWaitForWindowExposed(&damaged));
      Save(&damaged, "run_table_not_restored.png");
      // Saving keeps the run that could not be read back, listed as it was saved (its name and
      // notes, its folder), so that a repair or a later version still finds it.
      QVERIFY2(damaged.saveProjectAs(project, &error), qPrintable(error));
      QVERIFY2(damaged.statusBar()->currentMessage().contains("kept as they were saved"),
               qPrintable(damaged.statusBar()->currentMessage()));
      QVERIFY(QFile::exists(c_folder + "/fields/bearing.h5"));
    }
    for (int reopen = 0; reopen < 2; ++reopen) {  // and again after a second save
      MainWindow again_damaged;
      QVERIFY2(again_damaged.openProject(project, &error), qPrintable(error));
      QCOMPARE(int(again_damaged.runTable()->runs().size()), 2);
      QVERIFY(again_damaged.runTable()->runs()[0]->restoreError().contains("summary.json"));
      QVERIFY(QFile::exists(c_folder + "/fields/bearing.h5"));
      QVERIFY2(again_damaged.saveProjectAs(project, &error), qPrintable(error));
    }
    QVERIFY(QFile::exists(c_folder + "/fields/bearing.h5"));

    // A runs index this version cannot read (damaged here; or a newer FilmDyn's): no run is
    // restored, and a save leaves the index and every run folder as they are (it used to write
    // an empty index and delete them all).
    QFile index(runs_dir + "/runs.json");
    QVERIFY(index.open(QIODevice::WriteOnly | QIODevice::Truncate));
    index.write("{ not json");
    index.close();
    {
      MainWindow damaged;
      QVERIFY2(damaged.openProject(project, &error), qPrintable(error));
      QCOMPARE(int(damaged.runTable()->runs().size()), 0);
      QVERIFY(damaged.statusBar()->currentMessage().contains("runs.json"));
      QCOMPARE(damaged.document()->filePath(), project);
      QVERIFY(!damaged.saveProjectAs(project, &error));
      QVERIFY2(error.contains("not its runs") && error.contains("runs.json cannot be read") &&
                   error.contains("another name"),
               qPrintable(error));
      QCOMPARE(ReadAll(runs_dir + "/runs.json"), QByteArray("{ not json"));
      QVERIFY(QFile::exists(c_folder + "/fields/bearing.h5"));
      QVERIFY(QFile::exists(c_folder + "/results.csv"));
    }
  }
};

QTEST_MAIN(TestProjectRuns)
#include "test_project_runs.moc"
