// The whole main window on a real X server after real runs (core's run job: Ideal model at 6000
// and 4000 rpm overlaid, then a coupled Skirt-LBRBE run with its pressure fields): every page
// draws, the plots hold both runs, the run table compares them; a run with JFO cavitation on the
// big end (picked in the case editor) shows its fluid fraction; the big-end tab shows its supply
// tables (holes, supply-pressure curve) below the rows. With FILMDYN_SCREENSHOT_DIR set it also
// saves the pictures used in docs/ (scripts/screenshots.sh).
#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QGuiApplication>
#include <QImage>
#include <QLabel>
#include <QScreen>
#include <QSettings>
#include <QSlider>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableView>
#include <QToolTip>
#include <QtTest>
#include <cmath>

#include "core/engine/case_schema.hpp"
#include "tests/ui/tooltip_screenshot.hpp"
#include "ui/case_editor/array_table_model.hpp"
#include "ui/case_editor/case_document.hpp"
#include "ui/case_editor/case_editor.hpp"
#include "ui/case_editor/case_parameters.hpp"
#include "ui/case_editor/parameter_table_model.hpp"
#include "ui/fields/field_view.hpp"
#include "ui/main_window.hpp"
#include "ui/plots/plot_panel.hpp"
#include "ui/run/run_controller.hpp"
#include "ui/runs/run_table.hpp"
#include "ui/vtk/vtk_view_widget.hpp"

using filmdyn::ui::MainWindow;
using filmdyn::ui::RunHandle;

namespace {

void Save(QWidget* widget, const QString& name) {
  const QImage image = widget->grab().toImage();
  QVERIFY(!image.isNull());
  const QString dir = qEnvironmentVariable("FILMDYN_SCREENSHOT_DIR");
  if (!dir.isEmpty()) {
    QDir().mkpath(dir);
    QVERIFY(image.save(QDir(dir).filePath(name)));
    qInfo("wrote %s", qPrintable(QDir(dir).filePath(name)));
  }
}

}  // namespace

class TestMainWindowAfterRun : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName("FilmDynTest");
    QCoreApplication::setApplicationName("test_main_window_after_run");
    QSettings().clear();
  }

  void pagesAfterTwoRealRuns() {
    MainWindow window;
    window.resize(1600, 1000);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    auto* tabs = window.caseEditor()->findChild<QTabWidget*>("case_tabs");
    window.workspace()->setCurrentIndex(0);
    tabs->setCurrentIndex(1);
    QTest::qWait(100);
    Save(&window, "case_geometry.png");
    tabs->setCurrentIndex(3);
    QTest::qWait(100);
    Save(&window, "case_skirt_profile.png");
    tabs->setCurrentIndex(7);
    QTest::qWait(100);
    Save(&window, "case_pressure_curves.png");

    // Two real runs of the Ideal model (the only one core runs today), overlaid.
    QSignalSpy finished(window.runController(), &filmdyn::ui::RunController::runFinished);
    for (double rpm : {6000.0, 4000.0}) {
      auto c = window.document()->engineCase();
      filmdyn::ui::ApplyRunModel(c, "ideal");
      c.operating.rpm = rpm;
      window.document()->edit(c, "set-up");
      QVERIFY(window.runAction()->isEnabled());
      window.runAction()->trigger();
      QVERIFY(finished.wait(120000));
      const RunHandle run = finished.last().first().value<RunHandle>();
      QCOMPARE(run->status(), filmdyn::ui::RunStatus::kFinished);
      QVERIFY(window.plotPanel()->pointCount(run->id()) > 700);
    }
    QCOMPARE(window.runTable()->rowCount(), 2);
    window.workspace()->setCurrentIndex(1);
    window.runTable()->selectRow(1);
    QTest::qWait(300);
    Save(&window, "run_results.png");

    // Toggling a run hides its series.
    const int first = window.runTable()->runs().front()->id();
    window.runTable()->item(0, filmdyn::ui::RunTable::kShow)->setCheckState(Qt::Unchecked);
    QVERIFY(!window.plotPanel()->isRunVisible(first));
    window.runTable()->item(0, filmdyn::ui::RunTable::kShow)->setCheckState(Qt::Checked);
    QVERIFY(window.plotPanel()->isRunVisible(first));

    // A real coupled run (Skirt-LBRBE, coarse output, two cycles): film quantities stream into
    // the plots and the reported cycle's pressure fields reach the 3D view.
    {
      auto c = window.document()->engineCase();
      filmdyn::ui::ApplyRunModel(c, "skirt-lbrbe");
      c.operating.rpm = 6000;
      c.solver.output_interval = 4.0 * M_PI / 180.0;
      c.solver.max_cycles = 2;
      window.document()->edit(c, "coupled");
      QVERIFY(window.runAction()->isEnabled());
      window.runAction()->trigger();
      QVERIFY(finished.wait(400000));
      const RunHandle run = finished.last().first().value<RunHandle>();
      qInfo("coupled run: %s %s", qPrintable(filmdyn::ui::RunStatusText(run->status())),
            qPrintable(run->reason()));
      QCOMPARE(run->status(), filmdyn::ui::RunStatus::kFinished);
      const auto samples = run->samples();
      QCOMPARE(int(samples.size()), 180);
      QVERIFY(std::isfinite(samples[90][filmdyn::ui::Column::kSkirtMoft]));
      QVERIFY(std::isfinite(samples[90][filmdyn::ui::Column::kBearingMoft]));
      QVERIFY(run->fields() != nullptr);
      QCOMPARE(int(run->fields()->joints.size()), 2);
      // The run table shows the estimated discretisation error, its tooltip every figure.
      QCOMPARE(QString::fromStdString(run->errorEstimate().status), QString("estimated"));
      auto* error_cell = window.runTable()->item(2, filmdyn::ui::RunTable::kError);
      qInfo("error column: %s", qPrintable(error_cell->text()));
      QVERIFY(error_cell->text().contains("%"));
      QVERIFY(error_cell->toolTip().contains("min big-end MOFT"));
      QVERIFY(error_cell->toolTip().contains("min skirt MOFT"));
      // The Ideal runs have no film: nothing to estimate.
      QCOMPARE(window.runTable()->item(0, filmdyn::ui::RunTable::kError)->text(), QString("–"));
      window.runTable()->selectRow(2);
      window.workspace()->setCurrentIndex(1);
      QTest::qWait(300);
      Save(&window, "run_results_coupled.png");
      window.workspace()->setCurrentIndex(2);
      auto* field_view = window.fieldView();
      field_view->slider()->setValue(95);  // 380 °CA, just after firing TDC
      QTest::qWait(500);
      Save(&window, "pressure_fields.png");
    }

    // A run with mass-conserving cavitation (Only-LBRBE, "jfo" picked in the big end's
    // cavitation row): the field view shows where the film is full and where it has broken up,
    // the plots the oil through each film.
    {
      window.workspace()->setCurrentIndex(0);
      tabs->setCurrentIndex(4);
      auto c = window.document()->engineCase();
      filmdyn::ui::ApplyRunModel(c, "only-lbrbe");
      c.solver.error_estimate = 1;              // its tooltip: the mass-conserving film's long note
      c.solver.output_interval = M_PI / 180.0;  // 1 °CA: a sample catches the impact
      window.document()->edit(c, "JFO set-up");
      auto* model = window.caseEditor()->parameterModel(filmdyn::ui::CaseGroup::kBigEnd);
      const QModelIndex cell = model->index(model->rowOf("big_end.cavitation"),
                                            filmdyn::ui::ParameterTableModel::kValue);
      auto* combo = qobject_cast<QComboBox*>(
          window.caseEditor()->parameterTable(filmdyn::ui::CaseGroup::kBigEnd)->indexWidget(cell));
      QVERIFY(combo != nullptr);
      combo->setFocus();
      QTest::keyClick(combo, Qt::Key_Down);  // "reynolds" → "jfo"
      QCOMPARE(window.document()->engineCase().big_end.cavitation,
               filmdyn::lubrication::CavitationModel::kJfo);
      // The lubricant's bulk modulus is in use once a film conserves mass (greyed before).
      QVERIFY(
          filmdyn::engine::UnusedReason(window.document()->engineCase(), "lubricant.bulk_modulus")
              .empty());
      tabs->setCurrentIndex(5);
      QTest::qWait(100);
      Save(&window, "case_lubricant.png");
      tabs->setCurrentIndex(4);
      // For the picture, the supply tables below the rows filled: two shell holes and a
      // supply-pressure curve over the cycle (undone: the run keeps the paper's film start).
      {
        auto shown = window.document()->engineCase();
        shown.big_end.supply = filmdyn::lubrication::OilFeedKind::kShellHoles;
        shown.big_end.supply_hole_angles = {0.0, M_PI};
        for (int a = 0; a < 720; a += 10) {
          const double phi = a * M_PI / 180.0;
          shown.big_end.supply_pressure_angles.push_back(phi);
          shown.big_end.supply_pressure_values.push_back(0.3e6 + 0.05e6 * std::sin(2.0 * phi));
        }
        window.document()->edit(shown, "supply for the picture");
        QVERIFY(window.document()->issues().empty());
        QVERIFY(window.caseEditor()->listModel("big_end.supply_pressure_values")->rowCount() == 72);
        QTest::qWait(100);
        Save(&window, "case_big_end_cavitation.png");
        window.document()->undoStack()->undo();
        QVERIFY(window.document()->engineCase().big_end.supply_pressure_angles.empty());
      }
      // Elastic surfaces: the compliance row's choices; with "elastic_layer" the lining's
      // thickness is in use (greyed with its reason while the surfaces are rigid).
      {
        QVERIFY(!filmdyn::engine::UnusedReason(window.document()->engineCase(),
                                               "big_end.layer_thickness")
                     .empty());
        auto shown = window.document()->engineCase();
        shown.big_end.compliance = filmdyn::lubrication::ComplianceModel::kElasticLayer;
        window.document()->edit(shown, "elastic lining for the picture");
        QVERIFY(filmdyn::engine::UnusedReason(window.document()->engineCase(),
                                              "big_end.layer_thickness")
                    .empty());
        window.caseEditor()
            ->parameterTable(filmdyn::ui::CaseGroup::kBigEnd)
            ->scrollTo(model->index(model->rowOf("big_end.compliance"), 0),
                       QAbstractItemView::PositionAtTop);
        QTest::qWait(100);
        Save(&window, "case_big_end_compliance.png");
        window.document()->undoStack()->undo();
        QCOMPARE(window.document()->engineCase().big_end.compliance,
                 filmdyn::lubrication::ComplianceModel::kRigid);
      }
      // The skirt's compliance from a finite-element model: the file row in use, the layer's
      // thickness greyed with its reason.
      {
        tabs->setCurrentIndex(3);
        auto shown = window.document()->engineCase();
        shown.skirt.compliance = filmdyn::lubrication::ComplianceModel::kImported;
        shown.skirt.compliance_file = "examples/calculix-skirt-shell/skirt_compliance.mtx";
        window.document()->edit(shown, "FE skirt for the picture");
        QVERIFY(
            filmdyn::engine::UnusedReason(window.document()->engineCase(), "skirt.compliance_file")
                .empty());
        QVERIFY(
            !filmdyn::engine::UnusedReason(window.document()->engineCase(), "skirt.layer_thickness")
                 .empty());
        auto* skirt = window.caseEditor()->parameterModel(filmdyn::ui::CaseGroup::kSkirt);
        window.caseEditor()
            ->parameterTable(filmdyn::ui::CaseGroup::kSkirt)
            ->scrollTo(skirt->index(skirt->rowOf("skirt.compliance"), 0),
                       QAbstractItemView::PositionAtTop);
        QTest::qWait(100);
        Save(&window, "case_skirt_compliance.png");
        window.document()->undoStack()->undo();
        QCOMPARE(window.document()->engineCase().skirt.compliance,
                 filmdyn::lubrication::ComplianceModel::kRigid);
        tabs->setCurrentIndex(4);
      }
      QVERIFY(window.runAction()->isEnabled());
      window.runAction()->trigger();
      QVERIFY(finished.wait(400000));
      const RunHandle run = finished.last().first().value<RunHandle>();
      QCOMPARE(run->status(), filmdyn::ui::RunStatus::kFinished);
      QVERIFY(std::isfinite(run->samples()[90][filmdyn::ui::Column::kBearingSupplyFlow]));
      QVERIFY(run->fields() != nullptr);
      QCOMPARE(int(run->fields()->joints.size()), 1);
      QVERIFY(run->fields()->joints[0].HasArray("fluid_fraction"));
      window.runTable()->selectRow(window.runTable()->rowOf(run->id()));
      // The big end's impact at the load reversal falls between the output samples: the run
      // table's warnings say so (the message with the steps' peak in the tooltip).
      const QString warned =
          window.runTable()
              ->item(window.runTable()->rowOf(run->id()), filmdyn::ui::RunTable::kWarnings)
              ->toolTip();
      qInfo("JFO run's warnings: %s", qPrintable(warned));
      QVERIFY2(warned.contains("spike") && warned.contains("integrator's steps"),
               qPrintable(warned));
      // The impact's force, caught by the sample at 361 °CA (the 1 °CA samples of the default
      // meshes; 4 °CA samples miss it), is marked in the table's big-end force column; the
      // Reynolds coupled run's is not.
      const QTableWidgetItem* force = window.runTable()->item(window.runTable()->rowOf(run->id()),
                                                              filmdyn::ui::RunTable::kBigEndForce);
      qInfo("JFO run's big-end force: %s — %s", qPrintable(force->text()),
            qPrintable(force->toolTip()));
      QVERIFY2(force->text().startsWith("⚠ ") &&
                   force->toolTip().startsWith("max big-end force ") &&
                   force->toolTip().contains("spike the output samples do not resolve"),
               qPrintable(force->text()));
      const QTableWidgetItem* reynolds =
          window.runTable()->item(2, filmdyn::ui::RunTable::kBigEndForce);
      QVERIFY2(!reynolds->text().startsWith("⚠") && reynolds->toolTip().isEmpty(),
               qPrintable(reynolds->text()));
      // The estimate's tooltip is rich text, so that Qt wraps its summary (here with the
      // mass-conserving film's note, some 500 characters).
      QTableWidgetItem* error_cell = window.runTable()->item(window.runTable()->rowOf(run->id()),
                                                             filmdyn::ui::RunTable::kError);
      QVERIFY(Qt::mightBeRichText(error_cell->toolTip()));
      QVERIFY2(error_cell->toolTip().contains("outside the range where these meshes' difference"),
               qPrintable(error_cell->toolTip()));
      // One line per figure, a dimensionless one without a unit's gap ("0.97272, −0.075 %").
      QVERIFY2(error_cell->toolTip().contains("max big-end eccentricity ratio: 0.") &&
                   !error_cell->toolTip().contains(" ,"),
               qPrintable(error_cell->toolTip()));
      window.workspace()->setCurrentIndex(1);
      window.runTable()->scrollToItem(force);
      QTest::qWait(300);
      Save(&window, "run_results_jfo.png");
      if (const QString dir = qEnvironmentVariable("FILMDYN_SCREENSHOT_DIR"); !dir.isEmpty()) {
        window.runTable()->scrollToItem(error_cell);
        QVERIFY(filmdyn::test::SaveCellToolTip(
            window.runTable(), window.runTable()->visualItemRect(error_cell), error_cell->toolTip(),
            QDir(dir).filePath("run_error_tooltip.png")));
      }
      window.workspace()->setCurrentIndex(2);
      auto* field_view = window.fieldView();
      field_view->arraySelector()->setCurrentIndex(
          field_view->arraySelector()->findData("fluid_fraction"));
      field_view->setCrankAngle(380.0);
      QCOMPARE(field_view->colourRange(0), std::make_pair(0.0, 1.0));
      QTest::qWait(500);
      Save(&window, "field_view_fluid_fraction.png");
      field_view->arraySelector()->setCurrentIndex(0);
    }

    // An invalid value: the cell is marked, Run is disabled with the reason in the status bar.
    window.workspace()->setCurrentIndex(0);
    tabs->setCurrentIndex(4);
    auto* model = window.caseEditor()->parameterModel(filmdyn::ui::CaseGroup::kBigEnd);
    model->setData(model->index(model->rowOf("big_end.journal_radius"),
                                filmdyn::ui::ParameterTableModel::kValue),
                   "15.2", Qt::EditRole);
    QVERIFY(!window.runAction()->isEnabled());
    // The red cell in view (the table was left scrolled to the compliance rows above).
    window.caseEditor()
        ->parameterTable(filmdyn::ui::CaseGroup::kBigEnd)
        ->scrollTo(model->index(model->rowOf("big_end.journal_radius"), 0),
                   QAbstractItemView::PositionAtCenter);
    QTest::qWait(100);
    Save(&window, "case_validation.png");
  }
};

int main(int argc, char** argv) {
  filmdyn::ui::VtkViewWidget::SetDefaultSurfaceFormat();
  QApplication app(argc, argv);
  TestMainWindowAfterRun test;
  return QTest::qExec(&test, argc, argv);
}
#include "test_main_window_after_run.moc"
