// The case editor driven through its real widgets: typing into a table cell changes the case (in
// SI), undo/redo restore it, an invalid value is marked with core's reason and blocks Run, the
// skirt profile, ovality and pressure tables edit the arrays, E and ν per surface are edited in
// GPa, pressure CSV export/import round-trips, a project round-trips through save/load (core's
// case file, written atomically), and a choice (a joint's cavitation model) is picked in its
// row's combo box as one undoable edit, saved and shown again on open. Every number list of the
// schema has its table on its tab: the big end's supply-pressure curve and supply-hole angles and
// the skirt's liner oil film are edited in display units and stored in SI, undoable, with core's
// message about a bad curve or hole beside the table, and no rows meaning none.
#include <QAbstractItemView>
#include <QAction>
#include <QApplication>
#include <QChart>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QLineSeries>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QToolTip>
#include <QUndoStack>
#include <QWheelEvent>
#include <QtTest>
#include <algorithm>
#include <cmath>

#include "core/base/input_error.hpp"
#include "core/engine/case_schema.hpp"
#include "core/engine/film_joints.hpp"
#include "core/io/case_file.hpp"
#include "editor_test_util.hpp"
#include "ui/case_editor/array_table_model.hpp"
#include "ui/case_editor/case_document.hpp"
#include "ui/case_editor/case_editor.hpp"
#include "ui/case_editor/case_json.hpp"
#include "ui/case_editor/case_parameters.hpp"
#include "ui/case_editor/field_tooltip.hpp"
#include "ui/case_editor/parameter_table_model.hpp"
#include "ui/main_window.hpp"

using editor_test::ListButton;
using editor_test::OpenAndLeaveCell;
using editor_test::TypeIntoCell;
using filmdyn::ui::ArrayTableModel;
using filmdyn::ui::CaseGroup;
using filmdyn::ui::MainWindow;
using filmdyn::ui::ParameterTableModel;

namespace {

// The case editor's tab (index in "case_tabs") that shows `widget`, or -1.
int TabOf(MainWindow& window, QWidget* widget) {
  auto* tabs = window.caseEditor()->findChild<QTabWidget*>("case_tabs");
  for (int i = 0; i < tabs->count(); ++i) {
    if (tabs->widget(i)->isAncestorOf(widget)) return i;
  }
  return -1;
}

bool Near(double a, double b, double tolerance) { return std::abs(a - b) <= tolerance; }

constexpr double kDeg = M_PI / 180.0;

QModelIndex ValueCell(MainWindow& window, CaseGroup group, const std::string& path) {
  ParameterTableModel* model = window.caseEditor()->parameterModel(group);
  const int row = model->rowOf(path);
  return model->index(row, ParameterTableModel::kValue);
}

}  // namespace

class TestCaseEditor : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName("FilmDynTest");
    QCoreApplication::setApplicationName("test_case_editor");
    QSettings().clear();
  }

  // What a tooltip shows as a closed bound or a default, typed back into the cell, is allowed:
  // six digits would round a bound at 1/9 or 8 pi outward, so those are shown with every digit.
  void tooltipBoundsAndDefaultsTypedBackAreAllowed() {
    using filmdyn::engine::CaseField;
    using filmdyn::engine::FieldKind;
    const QRegularExpression number(R"([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)");
    int checked = 0;
    for (const CaseField& f : filmdyn::engine::CaseSchema()) {
      if (f.kind != FieldKind::kNumber && f.kind != FieldKind::kNumberList) continue;
      const QString unit = QString::fromStdString(f.display_unit);
      auto without_unit = [&unit](QString text) {
        if (!unit.isEmpty() && text.endsWith(" " + unit)) text.chop(unit.size() + 1);
        return text;
      };
      auto typed_back_allowed = [&f](const QString& text) {
        bool ok = false;
        const double typed = text.toDouble(&ok);
        if (!ok) return false;
        try {
          f.Check(f.FromDisplay(typed));
          return true;
        } catch (const std::exception&) {
          return false;
        }
      };
      const QString range = without_unit(filmdyn::ui::DisplayRangeText(f));
      const qsizetype open = range.indexOf(QRegularExpression("[\\[(]"));
      const qsizetype comma = range.indexOf(", ", open);
      if (open >= 0 && comma > open) {
        if (range[open] == '[') {
          const QString lo = range.mid(open + 1, comma - open - 1);
          QVERIFY2(typed_back_allowed(lo), qPrintable(QString::fromStdString(f.path) + " " + lo));
          ++checked;
        }
        if (range.endsWith(']')) {
          const QString hi = range.mid(comma + 2, range.size() - comma - 3);
          QVERIFY2(typed_back_allowed(hi), qPrintable(QString::fromStdString(f.path) + " " + hi));
          ++checked;
        }
      }
      const QString shown = without_unit(filmdyn::ui::DisplayDefaultText(f));
      for (auto it = number.globalMatch(shown); it.hasNext();) {
        const QString value = it.next().captured();
        QVERIFY2(typed_back_allowed(value),
                 qPrintable(QString::fromStdString(f.path) + " default " + value));
        ++checked;
      }
    }
    QVERIFY(checked > 200);
    // The Patir-Cheng range's lower end, 1/9: six digits (0.111111) would lie below it.
    const QString peklenik =
        filmdyn::ui::DisplayRangeText(*filmdyn::engine::FindCaseField("skirt.peklenik"));
    QVERIFY2(peklenik.startsWith("[0.1111111111111111"), qPrintable(peklenik));
  }

  void startsFromTheDefaultCaseAndCanRun() {
    MainWindow window;
    const auto& c = window.document()->engineCase();
    QCOMPARE(c.name, std::string("zhao-shen-gasoline"));
    QVERIFY2(c.pressure_curves.size() >= 1, "default case has pressure curves");
    QVERIFY2(!c.pressure_curves.front().pressure.empty(), "file curves are loaded inline");
    QVERIFY2(window.document()->issues().empty(),
             window.document()->issues().empty()
                 ? ""
                 : window.document()->issues().begin()->second.c_str());
    QVERIFY(window.runAction()->isEnabled());
    QVERIFY(!window.document()->isModified());
  }

  void editingACellChangesTheCaseInSi() {
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QTableView* table = window.caseEditor()->parameterTable(CaseGroup::kGeometry);
    window.workspace()->setCurrentIndex(0);
    // Geometry tab: the case editor's own tab widget.
    auto* tabs = window.caseEditor()->findChild<QTabWidget*>("case_tabs");
    tabs->setCurrentIndex(1);
    const QModelIndex cell = ValueCell(window, CaseGroup::kGeometry, "geometry.rod_length");
    QVERIFY(cell.isValid());
    QCOMPARE(cell.data().toString(), QString("129.5"));  // shown in mm
    TypeIntoCell(table, cell, "131.25");
    QCOMPARE(window.document()->engineCase().geometry.rod_length, 0.13125);  // stored in m
    QCOMPARE(cell.data().toString(), QString("131.25"));
    QVERIFY(window.document()->isModified());
    QVERIFY(window.windowTitle().contains("*"));

    // µm cell on the skirt tab: σ_skirt 0.615 µm → 0.7 µm.
    tabs->setCurrentIndex(3);
    TypeIntoCell(window.caseEditor()->parameterTable(CaseGroup::kSkirt),
                 ValueCell(window, CaseGroup::kSkirt, "skirt.roughness_skirt"), "0.7");
    QVERIFY(std::abs(window.document()->engineCase().skirt.roughness_skirt - 0.7e-6) < 1e-18);

    // Undo / redo through the stack the Edit menu uses.
    window.document()->undoStack()->undo();
    QVERIFY(std::abs(window.document()->engineCase().skirt.roughness_skirt - 0.615e-6) < 1e-18);
    window.document()->undoStack()->undo();
    QCOMPARE(window.document()->engineCase().geometry.rod_length, 0.1295);
    QVERIFY(!window.document()->isModified());
    window.document()->undoStack()->redo();
    QCOMPARE(window.document()->engineCase().geometry.rod_length, 0.13125);
  }

  void invalidValueIsMarkedAndBlocksRun() {
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    auto* tabs = window.caseEditor()->findChild<QTabWidget*>("case_tabs");
    tabs->setCurrentIndex(4);
    QTableView* table = window.caseEditor()->parameterTable(CaseGroup::kBigEnd);
    const QModelIndex cell = ValueCell(window, CaseGroup::kBigEnd, "big_end.journal_radius");
    QVERIFY(window.runAction()->isEnabled());
    // Journal larger than the bearing: no clearance.
    TypeIntoCell(table, cell, "15.2");
    QVERIFY(cell.data(Qt::BackgroundRole).isValid());
    const QString reason = cell.data(Qt::ToolTipRole).toString();
    QVERIFY2(reason.contains("big_end.journal_radius"), qPrintable(reason));
    QVERIFY2(reason.contains("bearing_radius"), qPrintable(reason));
    QVERIFY(!window.runAction()->isEnabled());
    auto* blocker = window.findChild<QLabel*>("run_blocker");
    QVERIFY(blocker->text().contains("journal_radius"));
    QVERIFY(window.runAction()->toolTip().contains("journal_radius"));
    // The value typed is kept (never lose an edit) and shown.
    QCOMPARE(cell.data().toString(), QString("15.2"));

    // Not a number at all: core's finite-number rule.
    TypeIntoCell(table, ValueCell(window, CaseGroup::kBigEnd, "big_end.width"), "abc");
    const QModelIndex width = ValueCell(window, CaseGroup::kBigEnd, "big_end.width");
    QVERIFY(width.data(Qt::ToolTipRole).toString().contains("big_end.width"));

    TypeIntoCell(table, ValueCell(window, CaseGroup::kBigEnd, "big_end.width"), "22");
    TypeIntoCell(table, cell, "14.95");
    QVERIFY(!cell.data(Qt::BackgroundRole).isValid());
    QVERIFY(window.runAction()->isEnabled());
    QVERIFY(blocker->text().isEmpty());

    // Saving an invalid case is refused with the reason; the edit stays in the editor.
    TypeIntoCell(table, ValueCell(window, CaseGroup::kBigEnd, "big_end.roughness_journal"), "-1");
    QTemporaryDir dir;
    QString error;
    QVERIFY(!window.saveProjectAs(dir.filePath("bad.json"), &error));
    QVERIFY2(error.contains("roughness_journal"), qPrintable(error));
    QVERIFY(!QFile::exists(dir.filePath("bad.json")));
    QCOMPARE(window.document()->engineCase().big_end.roughness_journal, -1e-6);
  }

  // A value with more digits than the cell shows (six significant) keeps them when its cell is
  // opened and left unchanged: the editor starts with the exact value, nothing is edited and no
  // undo step is made; the tooltip gives the exact value. Both kinds of table: a quantity and a
  // list.
  void leavingACellUnchangedKeepsItsExactValue() {
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.workspace()->setCurrentIndex(0);
    auto* tabs = window.caseEditor()->findChild<QTabWidget*>("case_tabs");
    tabs->setCurrentIndex(1);
    filmdyn::ui::CaseDocument* document = window.document();
    const double rod = 0.1452345678;  // m: 145.2345678 mm, shown as 145.235
    document->setParameter("geometry.rod_length", rod);
    const int steps = document->undoStack()->count();
    const QModelIndex cell = ValueCell(window, CaseGroup::kGeometry, "geometry.rod_length");
    QCOMPARE(cell.data().toString(), QString("145.235"));
    QVERIFY2(cell.data(Qt::ToolTipRole).toString().contains("145.2345678 mm (shown rounded)"),
             qPrintable(cell.data(Qt::ToolTipRole).toString()));
    OpenAndLeaveCell(window.caseEditor()->parameterTable(CaseGroup::kGeometry), cell,
                     "145.2345678");
    QCOMPARE(document->engineCase().geometry.rod_length, rod);  // to the bit
    QCOMPARE(document->undoStack()->count(), steps);
    // A value the display does not round has no such line.
    QVERIFY(!ValueCell(window, CaseGroup::kGeometry, "geometry.crank_radius")
                 .data(Qt::ToolTipRole)
                 .toString()
                 .contains("shown rounded"));

    // A list cell: a point of the cylinder-pressure curve in MPa.
    tabs->setCurrentIndex(7);
    auto* pressure = window.caseEditor()->findChild<QTableView*>("pressure_table");
    ArrayTableModel* model = window.caseEditor()->pressureModel();
    const std::size_t curve = std::size_t(window.caseEditor()->currentCurve());
    filmdyn::engine::EngineCase next = document->engineCase();
    next.pressure_curves[curve].pressure[3] = 1234567.891;  // Pa: 1.234567891 MPa
    document->edit(next, "set a point");
    const int list_steps = document->undoStack()->count();
    QCOMPARE(model->index(3, 1).data().toString(), QString("1.23457"));
    OpenAndLeaveCell(pressure, model->index(3, 1), "1.234567891");
    QCOMPARE(document->engineCase().pressure_curves[curve].pressure[3], 1234567.891);
    QCOMPARE(document->undoStack()->count(), list_steps);
    QVERIFY(model->index(3, 1).data(Qt::ToolTipRole).toString().contains("1.234567891"));
  }

  // A whole-number field (a mesh count) given a fraction is not rounded behind the user's back:
  // the edit is refused and the status bar says why; a whole number is taken.
  void aWholeNumberFieldRefusesAFraction() {
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.workspace()->setCurrentIndex(0);
    const filmdyn::engine::CaseField* field = filmdyn::engine::FindCaseField("big_end.mesh_theta");
    QVERIFY(field != nullptr && field->kind == filmdyn::engine::FieldKind::kInteger);
    ParameterTableModel* model = window.caseEditor()->parameterModel(field->group);
    const QModelIndex cell = model->index(model->rowOf(field->path), ParameterTableModel::kValue);
    const double before = field->get(window.document()->engineCase());
    QSignalSpy status(window.caseEditor(), &filmdyn::ui::CaseEditor::statusMessage);
    QVERIFY(!model->setData(cell, "40.6", Qt::EditRole));
    QCOMPARE(field->get(window.document()->engineCase()), before);
    QCOMPARE(status.count(), 1);
    QVERIFY2(status.first().first().toString().contains("40.6 is not a whole number"),
             qPrintable(status.first().first().toString()));
    QVERIFY(model->setData(cell, "40", Qt::EditRole));
    QCOMPARE(field->get(window.document()->engineCase()), 40.0);
  }

  void profileAndPressureTablesEditTheArrays() {
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    auto* tabs = window.caseEditor()->findChild<QTabWidget*>("case_tabs");
    tabs->setCurrentIndex(3);
    QTableView* profile = window.caseEditor()->listTable("skirt.profile_y");
    ArrayTableModel* model = window.caseEditor()->profileModel();
    QCOMPARE(model->rowCount(), 5);
    TypeIntoCell(profile, model->index(0, 1), "25");  // h at the skirt top [µm]
    QVERIFY(std::abs(window.document()->engineCase().skirt.profile_h[0] - 25e-6) < 1e-15);
    // Non-increasing y: the profile table is marked, Run blocked.
    TypeIntoCell(profile, model->index(2, 0), "3");
    QVERIFY(model->index(2, 0).data(Qt::BackgroundRole).isValid());
    QVERIFY(!window.runAction()->isEnabled());
    window.document()->undoStack()->undo();
    QVERIFY(window.runAction()->isEnabled());
    model->insertRowAfter(1);
    QCOMPARE(window.document()->engineCase().skirt.profile_y.size(), size_t(6));
    QCOMPARE(window.document()->engineCase().skirt.profile_y[2], 0.0105);

    // Pressure table: edit one point of the selected curve (MPa → Pa).
    tabs->setCurrentIndex(7);
    auto* pressure = window.caseEditor()->findChild<QTableView*>("pressure_table");
    ArrayTableModel* p_model = window.caseEditor()->pressureModel();
    QVERIFY(p_model->rowCount() > 100);
    const int curve = window.caseEditor()->currentCurve();
    QVERIFY(curve >= 0);
    TypeIntoCell(pressure, p_model->index(3, 1), "0.5");
    QCOMPARE(window.document()->engineCase().pressure_curves[size_t(curve)].pressure[3], 0.5e6);
  }

  void surfaceElasticityAndOvalityEditTheCaseInSi() {
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    auto* tabs = window.caseEditor()->findChild<QTabWidget*>("case_tabs");
    tabs->setCurrentIndex(3);
    QTableView* skirt = window.caseEditor()->parameterTable(CaseGroup::kSkirt);
    // E of the liner, shown in GPa, stored in Pa.
    const QModelIndex liner = ValueCell(window, CaseGroup::kSkirt, "skirt.modulus_liner");
    QCOMPARE(liner.data().toString(), QString("110"));
    TypeIntoCell(skirt, liner, "120");
    QCOMPARE(window.document()->engineCase().skirt.modulus_liner, 120e9);
    QCOMPARE(window.document()->engineCase().skirt.modulus_skirt, 75e9);  // the other surface
    QVERIFY(window.runAction()->isEnabled());
    // ν = 0.5 is outside (−1, 0.5): marked with core's reason, Run blocked.
    const QModelIndex nu = ValueCell(window, CaseGroup::kSkirt, "skirt.poisson_liner");
    TypeIntoCell(skirt, nu, "0.5");
    QVERIFY(nu.data(Qt::BackgroundRole).isValid());
    QVERIFY2(nu.data(Qt::ToolTipRole).toString().contains("skirt.poisson_liner"),
             qPrintable(nu.data(Qt::ToolTipRole).toString()));
    QVERIFY(!window.runAction()->isEnabled());
    window.document()->undoStack()->undo();
    QCOMPARE(window.document()->engineCase().skirt.poisson_liner, 0.26);
    QVERIFY(window.runAction()->isEnabled());
    // The big-end surfaces have their own rows.
    QCOMPARE(ValueCell(window, CaseGroup::kBigEnd, "big_end.modulus_journal").data().toString(),
             QString("210"));
    QCOMPARE(ValueCell(window, CaseGroup::kBigEnd, "big_end.poisson_bearing").data().toString(),
             QString("0.33"));

    // Ovality: empty by default (round skirt); rows in ° and µm, stored in rad and m.
    QTableView* table = window.caseEditor()->listTable("skirt.ovality_h");
    QVERIFY(table != nullptr);
    ArrayTableModel* model = window.caseEditor()->ovalityModel();
    QCOMPARE(model->rowCount(), 0);
    model->insertRowAfter(-1);
    QCOMPARE(model->rowCount(), 1);
    TypeIntoCell(table, model->index(0, 1), "5");
    QVERIFY(std::abs(window.document()->engineCase().skirt.ovality_h[0] - 5e-6) < 1e-18);
    model->insertRowAfter(0);  // a copy of the last row: same angle, not yet valid
    QVERIFY(model->index(1, 0).data(Qt::BackgroundRole).isValid());
    QVERIFY(!window.runAction()->isEnabled());
    TypeIntoCell(table, model->index(1, 0), "90");
    TypeIntoCell(table, model->index(1, 1), "12");
    const auto& c = window.document()->engineCase();
    QCOMPARE(c.skirt.ovality_alpha.size(), size_t(2));
    QVERIFY(std::abs(c.skirt.ovality_alpha[1] - M_PI / 2) < 1e-15);
    QVERIFY(std::abs(c.skirt.ovality_h[1] - 12e-6) < 1e-18);
    QVERIFY(!model->index(1, 0).data(Qt::BackgroundRole).isValid());
    QVERIFY(window.runAction()->isEnabled());
    // The chart beside the table shows the rows in display units.
    auto* series = static_cast<QLineSeries*>(window.caseEditor()->ovalityChart()->series().first());
    QCOMPARE(series->count(), 2);
    QVERIFY(std::abs(series->at(1).x() - 90.0) < 1e-9 && std::abs(series->at(1).y() - 12.0) < 1e-9);
    // Past 180°: marked with the reason, Run blocked.
    TypeIntoCell(table, model->index(1, 0), "200");
    QVERIFY2(model->index(1, 0).data(Qt::ToolTipRole).toString().contains("skirt.ovality"),
             qPrintable(model->index(1, 0).data(Qt::ToolTipRole).toString()));
    QVERIFY(!window.runAction()->isEnabled());
    window.document()->undoStack()->undo();
    QVERIFY(window.runAction()->isEnabled());
  }

  void everyListOfTheSchemaHasItsTableOnItsTab() {
    MainWindow window;
    int lists = 0;
    for (const filmdyn::engine::CaseField& field : filmdyn::engine::CaseSchema()) {
      if (field.kind != filmdyn::engine::FieldKind::kNumberList) continue;
      ++lists;
      QTableView* table = window.caseEditor()->listTable(field.path);
      ArrayTableModel* model = window.caseEditor()->listModel(field.path);
      QVERIFY2(table != nullptr && model != nullptr && table->model() == model, field.path.c_str());
      // On the tab of the field's group, titled by core's label and unit, explained by its
      // schema row.
      QCOMPARE(TabOf(window, table),
               TabOf(window, window.caseEditor()->parameterTable(field.group)));
      const filmdyn::ui::CaseListTable& list = *filmdyn::ui::FindCaseListTable(field.path);
      const int col =
          int(std::find(list.columns.begin(), list.columns.end(), &field) - list.columns.begin());
      const QString header = model->headerData(col, Qt::Horizontal, Qt::DisplayRole).toString();
      QCOMPARE(header, filmdyn::ui::CaseListColumnTitle(field));
      QVERIFY2(header.endsWith("[" + QString::fromStdString(field.display_unit) + "]"),
               qPrintable(header));
      QVERIFY2(QString::fromStdString(field.label).endsWith(header.section(" [", 0, 0)),
               qPrintable(header));
      const QString tip = model->headerData(col, Qt::Horizontal, Qt::ToolTipRole).toString();
      QVERIFY2(tip.contains("In the case file: " + QString::fromStdString(field.path)),
               qPrintable(tip));
      QVERIFY(ListButton(window, field.path, "insert") && ListButton(window, field.path, "remove"));
      QVERIFY(ListButton(window, field.path, "import") && ListButton(window, field.path, "export"));
    }
    QVERIFY(lists >= 9);
    // A pair is one table (with its chart), a single list a table of its own.
    auto* editor = window.caseEditor();
    QCOMPARE(editor->listModel("big_end.supply_pressure_angles"),
             editor->listModel("big_end.supply_pressure_values"));
    QCOMPARE(editor->listModel("big_end.supply_pressure_values")->columnCount(), 2);
    QVERIFY(editor->listChart("big_end.supply_pressure_values") != nullptr);
    QCOMPARE(editor->listModel("skirt.oil_film_positions"),
             editor->listModel("skirt.oil_film_values"));
    QCOMPARE(editor->listModel("big_end.supply_hole_angles")->columnCount(), 1);
    QVERIFY(editor->listChart("big_end.supply_hole_angles") == nullptr);
    QVERIFY(editor->listModel("skirt.oil_film") == nullptr);  // a scalar: its row
    QVERIFY(editor->listModel("big_end.supply_pressure_values") !=
            editor->listModel("big_end.supply_hole_angles"));
  }

  void bigEndSupplyPressureCurveIsEditedInItsTable() {
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.workspace()->setCurrentIndex(0);
    auto* tabs = window.caseEditor()->findChild<QTabWidget*>("case_tabs");
    tabs->setCurrentIndex(4);  // Big-end bearing
    auto* editor = window.caseEditor();
    QTableView* table = editor->listTable("big_end.supply_pressure_values");
    ArrayTableModel* model = editor->listModel("big_end.supply_pressure_values");
    QLabel* issue = editor->listIssue("big_end.supply_pressure_values");
    QVERIFY(table != nullptr && model != nullptr && issue != nullptr);
    QVERIFY(table->isVisible());
    QCOMPARE(TabOf(window, table), 4);
    // Core's columns: crank angle in °CA, gauge pressure in MPa; no rows = the constant pressure.
    QCOMPARE(model->headerData(0, Qt::Horizontal, Qt::DisplayRole).toString(),
             QString("crank angle [°CA]"));
    QCOMPARE(model->headerData(1, Qt::Horizontal, Qt::DisplayRole).toString(),
             QString("gauge pressure [MPa]"));
    QCOMPARE(model->rowCount(), 0);
    QVERIFY(issue->text().isEmpty());

    // Shell holes and a curve over the cycle every 5 °CA at 0.3 MPa.
    QVERIFY(window.document()->setChoice("big_end.supply", "shell_holes"));
    auto c = window.document()->engineCase();
    for (int a = 0; a < 720; a += 5) {
      c.big_end.supply_pressure_angles.push_back(a * kDeg);
      c.big_end.supply_pressure_values.push_back(0.3e6);
    }
    window.document()->edit(c, "supply curve");
    QVERIFY2(window.document()->issues().empty(), qPrintable(window.document()->runBlocker()));
    QCOMPARE(model->rowCount(), 144);
    QCOMPARE(model->index(3, 0).data().toString(), QString("15"));
    QCOMPARE(model->index(3, 1).data().toString(), QString("0.3"));
    auto* series = static_cast<QLineSeries*>(
        editor->listChart("big_end.supply_pressure_values")->series().first());
    QCOMPARE(series->count(), 144);

    // Typed in display units, stored in SI.
    TypeIntoCell(table, model->index(3, 1), "0.45");
    const auto& b = window.document()->engineCase().big_end;
    QVERIFY(Near(b.supply_pressure_values[3], 0.45e6, 1e-6));
    TypeIntoCell(table, model->index(3, 0), "12.5");
    QVERIFY(Near(b.supply_pressure_angles[3], 12.5 * kDeg, 1e-15));
    QVERIFY2(window.document()->issues().empty(), qPrintable(window.document()->runBlocker()));
    QVERIFY(window.runAction()->isEnabled());
    QCOMPARE(series->at(3), QPointF(12.5, 0.45));
    QVERIFY(window.document()->undoStack()->undoText().contains("supply-pressure curve"));
    // Undo restores each edit, redo repeats it.
    window.document()->undoStack()->undo();
    QVERIFY(Near(b.supply_pressure_angles[3], 15 * kDeg, 1e-15));
    QCOMPARE(model->index(3, 0).data().toString(), QString("15"));
    window.document()->undoStack()->undo();
    QCOMPARE(b.supply_pressure_values[3], 0.3e6);
    QCOMPARE(model->index(3, 1).data().toString(), QString("0.3"));
    window.document()->undoStack()->redo();
    QVERIFY(Near(b.supply_pressure_values[3], 0.45e6, 1e-6));
    window.document()->undoStack()->undo();
    window.document()->undoStack()->undo();  // the curve's set-up
    QCOMPARE(model->rowCount(), 0);

    // Two points 700 °CA apart, made with the table's buttons: core's message names the curve,
    // beside the table, in the cells' tooltips and as the run blocker.
    QPushButton* insert = ListButton(window, "big_end.supply_pressure_values", "insert");
    QPushButton* remove = ListButton(window, "big_end.supply_pressure_values", "remove");
    QTest::mouseClick(insert, Qt::LeftButton);
    QCOMPARE(model->rowCount(), 1);
    table->setCurrentIndex(model->index(0, 0));
    QTest::mouseClick(insert, Qt::LeftButton);
    QCOMPARE(model->rowCount(), 2);
    TypeIntoCell(table, model->index(0, 1), "0.3");
    TypeIntoCell(table, model->index(1, 1), "0.3");
    TypeIntoCell(table, model->index(1, 0), "700");
    QCOMPARE(b.supply_pressure_angles.size(), size_t(2));
    QVERIFY(Near(b.supply_pressure_angles[1], 700 * kDeg, 1e-15));
    QCOMPARE(b.supply_pressure_values[1], 0.3e6);
    QVERIFY2(issue->text().contains("big_end.supply_pressure_angles = 2 points"),
             qPrintable(issue->text()));
    QVERIFY(issue->isVisible());
    const QString tip = model->index(1, 0).data(Qt::ToolTipRole).toString();
    QVERIFY2(tip.contains("big_end.supply_pressure_angles"), qPrintable(tip));
    QVERIFY(model->index(0, 1).data(Qt::BackgroundRole).isValid());
    QVERIFY(!window.runAction()->isEnabled());
    QVERIFY(window.findChild<QLabel*>("run_blocker")->text().contains("supply_pressure_angles"));
    if (const QString dir = qEnvironmentVariable("FILMDYN_SCREENSHOT_DIR"); !dir.isEmpty()) {
      QVERIFY(window.grab().save(dir + "/case_big_end_supply_issue.png"));  // for review
    }
    // Both rows removed: both lists empty, the constant supply pressure again.
    table->setCurrentIndex(model->index(1, 0));
    QTest::mouseClick(remove, Qt::LeftButton);
    table->setCurrentIndex(model->index(0, 0));
    QTest::mouseClick(remove, Qt::LeftButton);
    QCOMPARE(model->rowCount(), 0);
    QVERIFY(b.supply_pressure_angles.empty() && b.supply_pressure_values.empty());
    QVERIFY(window.document()->issues().empty());
    QVERIFY(issue->text().isEmpty());
    QVERIFY(window.runAction()->isEnabled());

    // With FILMDYN_SCREENSHOT_DIR set: the tab with two holes and a varying curve, for review.
    if (const QString dir = qEnvironmentVariable("FILMDYN_SCREENSHOT_DIR"); !dir.isEmpty()) {
      window.resize(1600, 1000);
      auto shown = window.document()->engineCase();
      shown.big_end.supply_hole_angles = {0.0, M_PI};
      for (int a = 0; a < 720; a += 10) {
        shown.big_end.supply_pressure_angles.push_back(a * kDeg);
        shown.big_end.supply_pressure_values.push_back(0.3e6 + 0.1e6 * std::sin(2 * a * kDeg));
      }
      window.document()->edit(shown, "supply for the picture");
      QVERIFY(window.document()->issues().empty());
      QTest::qWait(100);
      QVERIFY(window.grab().save(dir + "/case_big_end_supply.png"));
    }
  }

  void bigEndSupplyHoleAnglesAreEditedInTheirList() {
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.workspace()->setCurrentIndex(0);
    window.caseEditor()->findChild<QTabWidget*>("case_tabs")->setCurrentIndex(4);
    auto* editor = window.caseEditor();
    QTableView* table = editor->listTable("big_end.supply_hole_angles");
    ArrayTableModel* model = editor->listModel("big_end.supply_hole_angles");
    QLabel* issue = editor->listIssue("big_end.supply_hole_angles");
    QVERIFY(table != nullptr && table->isVisible());
    QCOMPARE(model->columnCount(), 1);
    QCOMPARE(model->headerData(0, Qt::Horizontal, Qt::DisplayRole).toString(),
             QString("angles [°]"));
    QCOMPARE(model->rowCount(), 1);  // the default's one hole on the rod axis
    QCOMPARE(model->index(0, 0).data().toString(), QString("0"));
    QVERIFY(window.document()->setChoice("big_end.supply", "shell_holes"));
    const auto& b = window.document()->engineCase().big_end;

    TypeIntoCell(table, model->index(0, 0), "90");
    QVERIFY(Near(b.supply_hole_angles[0], M_PI / 2, 1e-15));
    // A second hole, first a copy of the last one: it overlaps, core says which.
    table->setCurrentIndex(model->index(0, 0));
    QTest::mouseClick(ListButton(window, "big_end.supply_hole_angles", "insert"), Qt::LeftButton);
    QCOMPARE(model->rowCount(), 2);
    QVERIFY2(issue->text().contains("big_end.supply_hole_angles.1") &&
                 issue->text().contains("overlaps"),
             qPrintable(issue->text()));
    QVERIFY(model->index(1, 0).data(Qt::BackgroundRole).isValid());
    QVERIFY(!window.runAction()->isEnabled());
    TypeIntoCell(table, model->index(1, 0), "-90");
    QCOMPARE(b.supply_hole_angles.size(), size_t(2));
    QVERIFY(Near(b.supply_hole_angles[1], -M_PI / 2, 1e-15));
    QVERIFY(issue->text().isEmpty());
    QVERIFY(window.runAction()->isEnabled());
    // Undo: the copied angle again, then one hole.
    window.document()->undoStack()->undo();
    QVERIFY(Near(b.supply_hole_angles[1], M_PI / 2, 1e-15));
    window.document()->undoStack()->undo();
    QCOMPARE(model->rowCount(), 1);
    // No hole at all: shell holes need one.
    table->setCurrentIndex(model->index(0, 0));
    QTest::mouseClick(ListButton(window, "big_end.supply_hole_angles", "remove"), Qt::LeftButton);
    QCOMPARE(model->rowCount(), 0);
    QVERIFY2(issue->text().contains("big_end.supply_hole_angles") &&
                 issue->text().contains("at least one hole"),
             qPrintable(issue->text()));
    QVERIFY(!window.runAction()->isEnabled());
    window.document()->undoStack()->undo();
    QVERIFY(window.runAction()->isEnabled());
  }

  // The oil: a Vogel lubricant typed in display units (mPa·s, K) and a film temperature typed in
  // °C, stored in kelvin; the skirt's film then has the law's viscosity at that temperature.
  void oilTemperatureIsTypedInCelsius() {
    MainWindow window;
    window.resize(1600, 1000);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.workspace()->setCurrentIndex(0);
    auto* tabs = window.caseEditor()->findChild<QTabWidget*>("case_tabs");
    QTableView* lubricant = window.caseEditor()->parameterTable(CaseGroup::kLubricant);
    tabs->setCurrentIndex(TabOf(window, lubricant));
    QVERIFY(window.document()->setChoice("lubricant.viscosity_model", "vogel"));
    TypeIntoCell(lubricant, ValueCell(window, CaseGroup::kLubricant, "lubricant.vogel_a"), "0.069");
    TypeIntoCell(lubricant, ValueCell(window, CaseGroup::kLubricant, "lubricant.vogel_b"), "1050");
    TypeIntoCell(lubricant, ValueCell(window, CaseGroup::kLubricant, "lubricant.vogel_c"), "165");
    const auto& c = window.document()->engineCase();
    QVERIFY(Near(c.lubricant.vogel_a, 6.9e-5, 1e-18));
    // The constant viscosity and the pressure laws' constants are greyed, each with its reason.
    const QModelIndex mu = ValueCell(window, CaseGroup::kLubricant, "lubricant.viscosity");
    QCOMPARE(mu.siblingAtColumn(ParameterTableModel::kNote).data().toString(),
             QString("not used: the viscosity follows Vogel's law"));
    QCOMPARE(mu.data(Qt::ForegroundRole).value<QBrush>().color(), QColor(150, 150, 150));
    QVERIFY(ValueCell(window, CaseGroup::kLubricant, "lubricant.barus_alpha")
                .siblingAtColumn(ParameterTableModel::kNote)
                .data()
                .toString()
                .startsWith("not used"));
    QVERIFY(!ValueCell(window, CaseGroup::kLubricant, "lubricant.vogel_a")
                 .data(Qt::ForegroundRole)
                 .isValid());
    QCOMPARE(c.lubricant.vogel_c, 165.0);
    if (const QString dir = qEnvironmentVariable("FILMDYN_SCREENSHOT_DIR"); !dir.isEmpty()) {
      QTest::qWait(100);
      QVERIFY(window.grab().save(dir + "/case_lubricant.png"));
    }
    QTableView* skirt = window.caseEditor()->parameterTable(CaseGroup::kSkirt);
    tabs->setCurrentIndex(TabOf(window, skirt));
    const QModelIndex cell = ValueCell(window, CaseGroup::kSkirt, "skirt.oil.temperature");
    QCOMPARE(cell.data().toString(), QString("100"));  // 373.15 K
    // The joint carries the case's lubricant: its own oil's rows are greyed.
    QCOMPARE(ValueCell(window, CaseGroup::kSkirt, "skirt.oil.vogel_a")
                 .siblingAtColumn(ParameterTableModel::kNote)
                 .data()
                 .toString(),
             QString("not used: the film carries the case's lubricant"));
    TypeIntoCell(skirt, cell, "120");
    QVERIFY(Near(c.skirt.oil.temperature, 393.15, 1e-12));
    QCOMPARE(cell.data().toString(), QString("120"));
    QVERIFY(window.document()->issues().empty());
    const double expected = 6.9e-5 * std::exp(1050.0 / (393.15 - 165.0));
    QVERIFY(Near(filmdyn::engine::SkirtConfigFromCase(c).viscosity, expected, 1e-12 * expected));
    // Below the law's pole (−110 °C = 163.15 K): the run is refused, naming the field.
    TypeIntoCell(skirt, cell, "-110");
    QVERIFY(Near(c.skirt.oil.temperature, 163.15, 1e-12));
    QVERIFY_THROWS_EXCEPTION(filmdyn::InputError, filmdyn::engine::SkirtConfigFromCase(c));
    // Repeated edits of one cell are one undo step: back to the default 100 °C.
    window.document()->undoStack()->undo();
    QVERIFY(Near(c.skirt.oil.temperature, 373.15, 1e-12));
    // Hot parts: the cold clearance's note gives the running clearance (25 − 30.6 + 12.0 µm).
    TypeIntoCell(skirt, ValueCell(window, CaseGroup::kSkirt, "skirt.piston_temperature"), "60");
    TypeIntoCell(skirt, ValueCell(window, CaseGroup::kSkirt, "skirt.liner_temperature"), "50");
    const QModelIndex clearance = ValueCell(window, CaseGroup::kSkirt, "skirt.cold_clearance");
    const QString note = clearance.siblingAtColumn(ParameterTableModel::kNote).data().toString();
    QVERIFY2(note.contains("hot: 6.41 µm"), qPrintable(note));
    if (const QString dir = qEnvironmentVariable("FILMDYN_SCREENSHOT_DIR"); !dir.isEmpty()) {
      skirt->scrollTo(cell);
      QTest::qWait(100);
      QVERIFY(window.grab().save(dir + "/case_skirt_oil.png"));
    }
  }

  void skirtLinerOilFilmIsEditedInItsTable() {
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.workspace()->setCurrentIndex(0);
    window.caseEditor()->findChild<QTabWidget*>("case_tabs")->setCurrentIndex(3);
    auto* editor = window.caseEditor();
    QTableView* table = editor->listTable("skirt.oil_film_values");
    ArrayTableModel* model = editor->listModel("skirt.oil_film_values");
    QLabel* issue = editor->listIssue("skirt.oil_film_values");
    QVERIFY(table != nullptr && table->isVisible());
    QCOMPARE(TabOf(window, table), 3);
    QCOMPARE(model->headerData(0, Qt::Horizontal, Qt::DisplayRole).toString(),
             QString("position [mm]"));
    QCOMPARE(model->headerData(1, Qt::Horizontal, Qt::DisplayRole).toString(),
             QString("thickness [µm]"));
    QCOMPARE(model->rowCount(), 0);  // the constant skirt.oil_film
    const auto& s = window.document()->engineCase().skirt;
    // The table feeds a starved skirt only (greyed for a flooded one), which needs JFO.
    QVERIFY(!editor->listEnabled("skirt.oil_film_values"));
    QVERIFY(window.document()->setChoice("skirt.cavitation", "jfo"));
    QVERIFY(window.document()->setChoice("skirt.supply", "starved"));
    QVERIFY(editor->listEnabled("skirt.oil_film_values"));

    QTest::mouseClick(ListButton(window, "skirt.oil_film_values", "insert"), Qt::LeftButton);
    QCOMPARE(model->rowCount(), 1);
    // A film of 0 µm is not allowed: core's range, beside the table.
    QVERIFY2(issue->text().contains("skirt.oil_film_values"), qPrintable(issue->text()));
    QVERIFY(!window.runAction()->isEnabled());
    TypeIntoCell(table, model->index(0, 1), "8");
    QVERIFY(Near(s.oil_film_values[0], 8e-6, 1e-18));
    QVERIFY(issue->text().isEmpty());
    table->setCurrentIndex(model->index(0, 0));
    QTest::mouseClick(ListButton(window, "skirt.oil_film_values", "insert"), Qt::LeftButton);
    // The copy of the last row repeats its position: positions must increase.
    QVERIFY2(issue->text().contains("skirt.oil_film_positions.1"), qPrintable(issue->text()));
    TypeIntoCell(table, model->index(1, 0), "30");
    TypeIntoCell(table, model->index(1, 1), "3.5");
    QCOMPARE(s.oil_film_positions.size(), size_t(2));
    QVERIFY(Near(s.oil_film_positions[1], 0.03, 1e-15));
    QVERIFY(Near(s.oil_film_values[1], 3.5e-6, 1e-18));
    QVERIFY(window.document()->issues().empty());
    QVERIFY(window.runAction()->isEnabled());
    auto* series =
        static_cast<QLineSeries*>(editor->listChart("skirt.oil_film_values")->series().first());
    QCOMPARE(series->count(), 2);
    QVERIFY(Near(series->at(1).x(), 30.0, 1e-9) && Near(series->at(1).y(), 3.5, 1e-9));
    // Undo restores the thickness, then the position.
    window.document()->undoStack()->undo();
    QVERIFY(Near(s.oil_film_values[1], 8e-6, 1e-18));
    window.document()->undoStack()->undo();
    QCOMPARE(s.oil_film_positions[1], 0.0);
    // Saved and read back by core as the table.
    window.document()->undoStack()->redo();
    window.document()->undoStack()->redo();
    const auto back =
        filmdyn::io::CaseFromJson(filmdyn::io::CaseToJson(window.document()->engineCase()));
    QCOMPARE(back.skirt.oil_film_positions, s.oil_film_positions);
    QCOMPARE(back.skirt.oil_film_values, s.oil_film_values);

    // With FILMDYN_SCREENSHOT_DIR set: the skirt tab with the table, for review.
    if (const QString dir = qEnvironmentVariable("FILMDYN_SCREENSHOT_DIR"); !dir.isEmpty()) {
      window.resize(1600, 1000);
      QTest::qWait(100);
      QVERIFY(window.grab().save(dir + "/case_skirt_oil_film.png"));
    }
  }

  void pressureCsvExportImportRoundTrips() {
    MainWindow window;
    QTemporaryDir dir;
    filmdyn::ui::CaseEditor* editor = window.caseEditor();
    const int curve = editor->currentCurve();
    const auto original = window.document()->engineCase().pressure_curves[size_t(curve)];
    const QString path = dir.filePath(QString("curve_%1rpm.csv").arg(original.rpm));
    editor->exportPressureCsv(path);
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QVERIFY(file.readAll().contains("crank_angle[deg],pressure[Pa]"));
    // Change the curve, then import the file back: the original values return.
    auto changed = window.document()->engineCase();
    changed.pressure_curves[size_t(curve)].pressure[10] *= 2;
    window.document()->edit(changed, "change");
    QSignalSpy imported(editor, &filmdyn::ui::CaseEditor::statusMessage);
    editor->importPressureCsv(path);
    const auto& back = window.document()->engineCase().pressure_curves[size_t(curve)];
    // Bit for bit (the export writes every digit; the degrees are those that convert back to
    // the same radians).
    QVERIFY(back.pressure == original.pressure);
    QVERIFY(back.crank_angle_deg == original.crank_angle_deg);
    QCOMPARE(imported.count(), 1);
    QVERIFY2(imported.first().first().toString().contains("replacing the curve at that speed"),
             qPrintable(imported.first().first().toString()));
    // A decimal speed in the file name is the speed ("1234.5rpm" is not 5 rpm): a new curve.
    const QString decimal = dir.filePath("pressure_1234.5rpm.csv");
    QVERIFY(QFile::copy(path, decimal));
    const std::size_t curves = window.document()->engineCase().pressure_curves.size();
    editor->importPressureCsv(decimal);
    QCOMPARE(window.document()->engineCase().pressure_curves.size(), curves + 1);
    QCOMPARE(window.document()->engineCase().pressure_curves.back().rpm, 1234.5);
    window.document()->undoStack()->undo();
    // A broken CSV is reported (file and line), the case is unchanged.
    const QString bad = dir.filePath("bad.csv");
    QFile out(bad);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write("crank_angle[deg],pressure[Pa]\n0,1e5\n10,oops\n");
    out.close();
    QSignalSpy status(editor, &filmdyn::ui::CaseEditor::statusMessage);
    const auto before = window.document()->engineCase().pressure_curves;
    editor->importPressureCsv(bad);
    QCOMPARE(status.count(), 1);
    QVERIFY2(status.first().first().toString().contains("bad.csv"),
             qPrintable(status.first().first().toString()));
    QCOMPARE(window.document()->engineCase().pressure_curves.size(), before.size());
  }

  void tooltipsExplainEachInputFromTheSchema() {
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    // A scalar: what it is in words, display unit, allowed range and default in display units,
    // and the case-file path as the last line — all from core's schema row.
    const QModelIndex clearance = ValueCell(window, CaseGroup::kSkirt, "skirt.cold_clearance");
    QVERIFY(clearance.isValid());
    QCOMPARE(clearance.data().toString(), QString("25"));  // µm
    const QString tip = clearance.data(Qt::ToolTipRole).toString();
    const filmdyn::engine::CaseField* field =
        filmdyn::engine::FindCaseField("skirt.cold_clearance");
    QVERIFY(field != nullptr && !field->description.empty());
    QVERIFY2(tip.contains(QString::fromStdString(field->description).toHtmlEscaped()),
             qPrintable(tip));
    QVERIFY2(tip.contains("Unit: µm"), qPrintable(tip));
    QVERIFY2(tip.contains("Allowed: (0, 10000] µm"), qPrintable(tip));
    QVERIFY2(tip.contains("Default: 25 µm"), qPrintable(tip));
    QVERIFY2(tip.contains("In the case file: skirt.cold_clearance"), qPrintable(tip));
    QVERIFY(tip.indexOf("In the case file") > tip.indexOf("Default"));
    // scripts/screenshots.sh-style runs keep a picture of the tooltip as a user sees it.
    if (const QString dir = qEnvironmentVariable("FILMDYN_SCREENSHOT_DIR"); !dir.isEmpty()) {
      QTableView* table = window.caseEditor()->parameterTable(CaseGroup::kSkirt);
      window.caseEditor()->findChild<QTabWidget*>("case_tabs")->setCurrentIndex(3);
      const QPoint at = table->viewport()->mapToGlobal(table->visualRect(clearance).center());
      QToolTip::showText(at, tip, table->viewport());
      QWidget* label = nullptr;
      QTRY_VERIFY((label = [] {
                    for (QWidget* w : QApplication::topLevelWidgets()) {
                      if (w->inherits("QTipLabel") && w->isVisible()) return w;
                    }
                    return static_cast<QWidget*>(nullptr);
                  }()) != nullptr);
      QVERIFY(label->grab().save(dir + "/case_tooltip.png"));
      QToolTip::hideText();
    }
    // Every row of every tab explains itself in words; none is just a path.
    for (CaseGroup group :
         {CaseGroup::kGeometry, CaseGroup::kMasses, CaseGroup::kSkirt, CaseGroup::kBigEnd,
          CaseGroup::kLubricant, CaseGroup::kOperating, CaseGroup::kSolver}) {
      ParameterTableModel* model = window.caseEditor()->parameterModel(group);
      QVERIFY(model != nullptr);
      for (int row = 0; row < model->rowCount(); ++row) {
        const filmdyn::engine::CaseField& f = *model->parameter(row).field;
        const QString row_tip = model->index(row, 0).data(Qt::ToolTipRole).toString();
        QVERIFY2(!f.description.empty(), f.path.c_str());
        QVERIFY2(row_tip.contains(QString::fromStdString(f.description).toHtmlEscaped()),
                 f.path.c_str());
        QVERIFY2(row_tip.contains("Default: "), f.path.c_str());
      }
    }
    // Degrees shown for angles: the panel half-width is (0, 90] °, default 46 °.
    const QString angle = ValueCell(window, CaseGroup::kSkirt, "skirt.thrust_half_width")
                              .data(Qt::ToolTipRole)
                              .toString();
    QVERIFY2(angle.contains("Allowed: (0, 90] °") && angle.contains("Default: 46 °"),
             qPrintable(angle));
    // The array tables: the skirt profile's columns explain themselves from the schema too.
    ArrayTableModel* profile = window.caseEditor()->profileModel();
    const QString h_tip = profile->headerData(1, Qt::Horizontal, Qt::ToolTipRole).toString();
    QVERIFY2(h_tip.contains("In the case file: skirt.profile_h") && h_tip.contains("Unit: µm"),
             qPrintable(h_tip));
    QCOMPARE(profile->index(0, 1).data(Qt::ToolTipRole).toString(), h_tip);
    // A bad value: the tooltip is core's reason instead (field, value, allowed values), in the
    // cell's unit.
    auto c = window.document()->engineCase();
    c.skirt.cold_clearance = 0.04;  // more than the bore radius
    window.document()->edit(c, "clearance too large");
    const QString reason = clearance.data(Qt::ToolTipRole).toString();
    QVERIFY2(reason.startsWith("skirt.cold_clearance = 40000 µm: must be a finite number in (0, "),
             qPrintable(reason));
    QVERIFY(!window.runAction()->isEnabled());
  }

  void choosingTheBigEndCavitationModelIsAnUndoableEdit() {
    using filmdyn::lubrication::CavitationModel;
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.workspace()->setCurrentIndex(0);
    auto* tabs = window.caseEditor()->findChild<QTabWidget*>("case_tabs");
    tabs->setCurrentIndex(4);  // Big-end bearing
    QTableView* table = window.caseEditor()->parameterTable(CaseGroup::kBigEnd);
    const QModelIndex cell = ValueCell(window, CaseGroup::kBigEnd, "big_end.cavitation");
    QVERIFY(cell.isValid());
    const filmdyn::engine::CaseField* field = filmdyn::engine::FindCaseField("big_end.cavitation");
    QVERIFY(field != nullptr);
    // The row: core's label, no unit, the chosen name; its editor is a combo box of core's
    // names, open all the time, whose tooltip is the row's (from the schema).
    ParameterTableModel* model = window.caseEditor()->parameterModel(CaseGroup::kBigEnd);
    QCOMPARE(model->index(cell.row(), ParameterTableModel::kQuantity).data().toString(),
             QString::fromStdString(field->label));
    QVERIFY(model->index(cell.row(), ParameterTableModel::kUnit).data().toString().isEmpty());
    QCOMPARE(cell.data().toString(), QString("Reynolds (Swift–Stieber)"));
    auto* combo = qobject_cast<QComboBox*>(table->indexWidget(cell));
    QVERIFY2(combo != nullptr, "no combo box in the cavitation row");
    QVERIFY(combo->isVisible());
    // Each choice by its title (the file's names "reynolds", "jfo").
    QStringList items;
    for (int i = 0; i < combo->count(); ++i) items << combo->itemText(i);
    QCOMPARE(items, QStringList({"Reynolds (Swift–Stieber)", "JFO (mass-conserving)"}));
    QCOMPARE(combo->currentText(), QString("Reynolds (Swift–Stieber)"));
    QVERIFY2(combo->toolTip().contains(QString::fromStdString(field->description).toHtmlEscaped()),
             qPrintable(combo->toolTip()));
    QVERIFY(combo->toolTip().contains("In the case file: big_end.cavitation"));
    // The skirt has its own.
    QVERIFY(qobject_cast<QComboBox*>(window.caseEditor()
                                         ->parameterTable(CaseGroup::kSkirt)
                                         ->indexWidget(ValueCell(window, CaseGroup::kSkirt,
                                                                 "skirt.cavitation"))) != nullptr);

    // The wheel over a combo without the focus scrolls the table, never changes the choice.
    {
      const QPoint centre = combo->rect().center();
      QWheelEvent wheel(centre, combo->mapToGlobal(centre), {}, {0, -120}, Qt::NoButton,
                        Qt::NoModifier, Qt::NoScrollPhase, false);
      QApplication::sendEvent(combo, &wheel);
      QCOMPARE(combo->currentText(), QString("Reynolds (Swift–Stieber)"));
      QVERIFY(!window.document()->isModified());
    }

    // Pick "jfo" as a user does: open the list, click the item.
    const filmdyn::engine::EngineCase before = window.document()->engineCase();
    combo->showPopup();
    QAbstractItemView* list = combo->view();
    QTRY_VERIFY(list->isVisible());
    const QModelIndex jfo = list->model()->index(combo->findText("JFO (mass-conserving)"), 0);
    QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, list->visualRect(jfo).center());
    QTRY_COMPARE(window.document()->engineCase().big_end.cavitation, CavitationModel::kJfo);
    QCOMPARE(cell.data().toString(), QString("JFO (mass-conserving)"));
    QCOMPARE(combo->currentText(), QString("JFO (mass-conserving)"));
    QVERIFY(window.document()->isModified());
    QVERIFY(window.document()->issues().empty());
    QVERIFY(window.runAction()->isEnabled());
    QCOMPARE(window.document()->undoStack()->count(), 1);
    const QString undo_text = window.document()->undoStack()->undoText();
    QVERIFY2(undo_text.contains(QString::fromStdString(field->symbol)) && undo_text.contains("jfo"),
             qPrintable(undo_text));
    // Nothing else changed.
    filmdyn::engine::EngineCase expected = before;
    expected.big_end.cavitation = CavitationModel::kJfo;
    QCOMPARE(filmdyn::ui::CaseToJsonText(window.document()->engineCase()),
             filmdyn::ui::CaseToJsonText(expected));

    // Undo restores the case and the combo; redo sets it again.
    window.document()->undoStack()->undo();
    QCOMPARE(window.document()->engineCase().big_end.cavitation, CavitationModel::kReynolds);
    QCOMPARE(combo->currentText(), QString("Reynolds (Swift–Stieber)"));
    QVERIFY(!window.document()->isModified());
    window.document()->undoStack()->redo();
    QCOMPARE(window.document()->engineCase().big_end.cavitation, CavitationModel::kJfo);
    QCOMPARE(combo->currentText(), QString("JFO (mass-conserving)"));

    // The keyboard picks too (focus in the combo, arrow up): one more undo step.
    combo->setFocus();
    QTest::keyClick(combo, Qt::Key_Up);
    QCOMPARE(window.document()->engineCase().big_end.cavitation, CavitationModel::kReynolds);
    QCOMPARE(window.document()->undoStack()->count(), 2);
    window.document()->undoStack()->undo();
    QCOMPARE(window.document()->engineCase().big_end.cavitation, CavitationModel::kJfo);

    // Saved as core's case file with the name; opened again, the combo shows it.
    QTemporaryDir dir;
    const QString path = dir.filePath("jfo.json");
    QString error;
    QVERIFY2(window.saveProjectAs(path, &error), qPrintable(error));
    QCOMPARE(filmdyn::io::LoadCase(path.toStdString()).value.big_end.cavitation,
             CavitationModel::kJfo);
    MainWindow again;
    QVERIFY2(again.openProject(path, &error), qPrintable(error));
    const QModelIndex reopened = ValueCell(again, CaseGroup::kBigEnd, "big_end.cavitation");
    QCOMPARE(reopened.data().toString(), QString("JFO (mass-conserving)"));
    auto* reopened_combo = qobject_cast<QComboBox*>(
        again.caseEditor()->parameterTable(CaseGroup::kBigEnd)->indexWidget(reopened));
    QVERIFY(reopened_combo != nullptr);
    QCOMPARE(reopened_combo->currentText(), QString("JFO (mass-conserving)"));
    QVERIFY(!again.document()->isModified());
  }

  void olderCaseFileWithThePistonRadiusOpens() {
    // A project saved before the clearance was the input: it opens with the clearance the radius
    // implies, the status bar says the file used the older key, and saving writes the new one.
    QTemporaryDir dir;
    const QString path = dir.filePath("old.json");
    nlohmann::json old = filmdyn::io::CaseToJson(filmdyn::io::LoadCase({}).value);
    old["skirt"].erase("cold_clearance");
    old["skirt"]["piston_radius"] = 0.03647;
    {
      QFile file(path);
      QVERIFY(file.open(QIODevice::WriteOnly));
      file.write(QByteArray::fromStdString(old.dump(2)));
    }
    MainWindow window;
    QString error;
    QVERIFY2(window.openProject(path, &error), qPrintable(error));
    QVERIFY(std::abs(window.document()->engineCase().skirt.cold_clearance - 30e-6) < 1e-15);
    QCOMPARE(ValueCell(window, CaseGroup::kSkirt, "skirt.cold_clearance").data().toString(),
             QString("30"));
    const QString status = window.statusBar()->currentMessage();
    QVERIFY2(status.contains("skirt.piston_radius") && status.contains("skirt.cold_clearance"),
             qPrintable(status));
    QVERIFY2(window.saveProjectAs(path, &error), qPrintable(error));
    const auto saved = filmdyn::io::LoadCase(path.toStdString());
    QVERIFY(saved.notes.empty());
    QCOMPARE(filmdyn::engine::PistonRadius(saved.value), 0.03647);
  }

  // Save As into another folder keeps relative file names naming the same files: a compliance
  // file next to the first case file is named "../a/skirt.csv" from the second folder (it used to
  // keep "skirt.csv", which would then name a file beside the new case, or none). A name of no
  // file (here the big end's) stays as written. Undo gives back the old names.
  void saveAsElsewhereKeepsRelativeFileNames() {
    QTemporaryDir dir;
    QVERIFY(QDir(dir.path()).mkpath("a") && QDir(dir.path()).mkpath("b"));
    QFile compliance(dir.filePath("a/skirt.csv"));
    QVERIFY(compliance.open(QIODevice::WriteOnly));
    compliance.write("# placeholder: only its place matters here\n");
    compliance.close();
    MainWindow window;
    filmdyn::ui::CaseDocument* document = window.document();
    QString error;
    QVERIFY2(window.saveProjectAs(dir.filePath("a/case.json"), &error), qPrintable(error));
    auto c = document->engineCase();
    c.skirt.compliance_file = "skirt.csv";
    c.big_end.compliance_file = "missing.csv";
    document->edit(c, "files");
    QVERIFY2(window.saveProjectAs(dir.filePath("a/case.json"), &error), qPrintable(error));
    QCOMPARE(document->engineCase().skirt.compliance_file,
             std::string("skirt.csv"));  // same folder
    QVERIFY2(window.saveProjectAs(dir.filePath("b/case.json"), &error), qPrintable(error));
    QCOMPARE(document->engineCase().skirt.compliance_file, std::string("../a/skirt.csv"));
    QCOMPARE(document->engineCase().big_end.compliance_file, std::string("missing.csv"));
    QVERIFY(!document->isModified());
    const std::string saved = filmdyn::io::CaseToJson(document->engineCase()).dump();
    QVERIFY(saved.find("../a/skirt.csv") != std::string::npos);
    document->undoStack()->undo();
    QCOMPARE(document->engineCase().skirt.compliance_file, std::string("skirt.csv"));
  }

  void projectRoundTripsThroughSaveAndLoad() {
    QTemporaryDir dir;
    const QString path = dir.filePath("my_engine.json");
    std::string saved_text;
    {
      MainWindow window;
      auto c = window.document()->engineCase();
      c.geometry.rod_length = 0.1321;
      c.skirt.profile_h[1] = 7e-6;
      c.lubricant.viscosity = 0.011;
      c.operating.rpm = 4000;
      c.solver.max_cycles = 12;
      c.skirt.model = filmdyn::engine::JointModel::kIdeal;
      c.big_end.model = filmdyn::engine::JointModel::kLubricated;
      window.document()->edit(c, "several edits");
      QVERIFY(window.document()->isModified());
      QString error;
      QVERIFY2(window.saveProjectAs(path, &error), qPrintable(error));
      QVERIFY(!window.document()->isModified());
      QVERIFY(window.windowTitle().contains("my_engine.json"));
      QCOMPARE(window.recentFiles().first(), QFileInfo(path).absoluteFilePath());
      saved_text = filmdyn::ui::CaseToJsonText(window.document()->engineCase());
    }
    // The file is a case core reads as is (what `filmdyn run my_engine.json` loads).
    const auto loaded = filmdyn::io::LoadCase(path.toStdString());
    QCOMPARE(loaded.value.geometry.rod_length, 0.1321);
    QCOMPARE(loaded.value.solver.max_cycles, 12);

    MainWindow again;
    QString error;
    QVERIFY2(again.openProject(path, &error), qPrintable(error));
    QCOMPARE(filmdyn::ui::CaseToJsonText(again.document()->engineCase()), saved_text);
    QCOMPARE(again.caseEditor()->modelSelector()->currentData().toString(), QString("only-lbrbe"));
    QVERIFY(!again.document()->isModified());
    QCOMPARE(again.document()->filePath(), path);

    // A broken file names the field and leaves the open case untouched.
    QFile bad(dir.filePath("bad.json"));
    QVERIFY(bad.open(QIODevice::WriteOnly));
    bad.write(R"({"geometry": {"rod_length": "long"}})");
    bad.close();
    QVERIFY(!again.openProject(bad.fileName(), &error));
    QVERIFY2(error.contains("geometry.rod_length"), qPrintable(error));
    QCOMPARE(again.document()->filePath(), path);
  }
};

QTEST_MAIN(TestCaseEditor)
#include "test_case_editor.moc"
