// The case editor's list tables beyond typing: a CSV file written here is imported into the big
// end's supply-pressure curve (degrees and MPa in the file, radians and Pa in the case) as one
// undoable edit; export and import round-trip to the digits written; a bad file (a non-number,
// the wrong number of cells, NaN, no header, another header) changes nothing and its message
// names the file, the line, the value and what is allowed; a table no run reads under the chosen
// supply (the holes with "line_of_centres" or a groove, the liner oil film of a flooded skirt) is
// greyed with the reason and enabled again with another choice; editing a table, a choice or a
// number drops its "assumed" note, and undo brings it back. With FILMDYN_SCREENSHOT_DIR set it
// saves the big-end tab with its CSV buttons and a greyed block (case_list_csv.png).
#include <QComboBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableView>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>
#include <cmath>
#include <vector>

#include "core/engine/case_schema.hpp"
#include "core/io/case_file.hpp"
#include "editor_test_util.hpp"
#include "ui/case_editor/array_table_model.hpp"
#include "ui/case_editor/case_document.hpp"
#include "ui/case_editor/case_editor.hpp"
#include "ui/case_editor/case_parameters.hpp"
#include "ui/case_editor/parameter_table_model.hpp"
#include "ui/main_window.hpp"

using editor_test::ListButton;
using editor_test::TypeIntoCell;
using filmdyn::ui::ArrayTableModel;
using filmdyn::ui::CaseGroup;
using filmdyn::ui::MainWindow;
using filmdyn::ui::ParameterTableModel;

namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr const char* kCurve = "big_end.supply_pressure_values";
constexpr const char* kHoles = "big_end.supply_hole_angles";

void WriteFile(const QString& path, const QByteArray& text) {
  QFile file(path);
  QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
  QCOMPARE(file.write(text), text.size());
}

QByteArray ReadFile(const QString& path) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) return {};
  return file.readAll();
}

// A supply-pressure curve over the cycle every 10 °CA, pressures with four decimals in MPa: the
// CSV text a user would prepare, and the values it means (display units).
struct CurveFile {
  QByteArray text;
  std::vector<double> angles_deg, pressures_mpa;
};

CurveFile SupplyCurveFile() {
  CurveFile f;
  f.text =
      "# oil gallery pressure measured on the test bench\n"
      // The header files exported before the crank angle was labelled °CA: still read.
      "crank angle [°],gauge pressure [MPa]\n";
  for (int a = 0; a < 720; a += 10) {
    const QString p = QString::number(0.3 + 0.1 * std::sin(2 * a * kDeg), 'f', 4);
    f.text += QString("%1,%2\n").arg(a).arg(p).toUtf8();
    f.angles_deg.push_back(a);
    f.pressures_mpa.push_back(p.toDouble());
  }
  return f;
}

QString NoteOf(MainWindow& window, CaseGroup group, const std::string& path) {
  ParameterTableModel* model = window.caseEditor()->parameterModel(group);
  return model->index(model->rowOf(path), ParameterTableModel::kNote).data().toString();
}

// A scalar row greyed as unused: grey text and a "not used: ..." note.
bool Greyed(MainWindow& window, CaseGroup group, const std::string& path) {
  ParameterTableModel* model = window.caseEditor()->parameterModel(group);
  const QModelIndex value = model->index(model->rowOf(path), ParameterTableModel::kValue);
  const QVariant brush = value.data(Qt::ForegroundRole);
  return brush.isValid() && brush.value<QBrush>().color() == QColor(150, 150, 150) &&
         NoteOf(window, group, path).startsWith("not used: ");
}

}  // namespace

class TestCaseEditorLists : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName("FilmDynTest");
    QCoreApplication::setApplicationName("test_case_editor_lists");
    QSettings().clear();
  }

  void csvImportReplacesTheSupplyCurveAsOneUndoableEdit() {
    MainWindow window;
    auto* editor = window.caseEditor();
    auto* document = window.document();
    ArrayTableModel* model = editor->listModel(kCurve);
    QVERIFY(document->setChoice("big_end.supply", "shell_holes"));
    // An older curve of 144 rows (every 5 °CA at 0.2 MPa) that the file replaces.
    auto c = document->engineCase();
    for (int a = 0; a < 720; a += 5) {
      c.big_end.supply_pressure_angles.push_back(a * kDeg);
      c.big_end.supply_pressure_values.push_back(0.2e6);
    }
    document->edit(c, "older curve");
    const auto old_angles = document->engineCase().big_end.supply_pressure_angles;
    const auto old_values = document->engineCase().big_end.supply_pressure_values;
    QCOMPARE(model->rowCount(), 144);
    const int steps = document->undoStack()->count();

    QTemporaryDir dir;
    const QString path = dir.filePath("gallery.csv");
    const CurveFile file = SupplyCurveFile();
    WriteFile(path, file.text);
    QVERIFY(editor->importListCsv(kCurve, path));
    // Degrees and MPa in the file, radians and Pa in the case; the table shows the file's digits.
    const auto& b = document->engineCase().big_end;
    QCOMPARE(b.supply_pressure_angles.size(), size_t(72));
    QCOMPARE(b.supply_pressure_values.size(), size_t(72));
    for (size_t k = 0; k < 72; ++k) {
      QVERIFY(std::abs(b.supply_pressure_angles[k] - file.angles_deg[k] * M_PI / 180.0) < 1e-14);
      QVERIFY(std::abs(b.supply_pressure_values[k] - file.pressures_mpa[k] * 1e6) < 1e-9);
    }
    QCOMPARE(b.supply_pressure_angles[9], 90 * kDeg);
    QCOMPARE(model->rowCount(), 72);
    QCOMPARE(model->index(9, 0).data().toString(), QString("90"));
    QCOMPARE(model->index(9, 1).data().toString(), QString::number(file.pressures_mpa[9], 'g', 6));
    QVERIFY2(document->issues().empty(), qPrintable(document->runBlocker()));
    QVERIFY(window.runAction()->isEnabled());
    // One undo step, named after the table and the file; undo restores the older curve exactly.
    QCOMPARE(document->undoStack()->count(), steps + 1);
    const QString undo_text = document->undoStack()->undoText();
    QVERIFY2(undo_text.contains("supply-pressure curve") && undo_text.contains("gallery.csv"),
             qPrintable(undo_text));
    document->undoStack()->undo();
    QCOMPARE(document->engineCase().big_end.supply_pressure_angles, old_angles);
    QCOMPARE(document->engineCase().big_end.supply_pressure_values, old_values);
    QCOMPARE(model->rowCount(), 144);
    document->undoStack()->redo();
    QCOMPARE(model->rowCount(), 72);
  }

  void csvExportAndImportRoundTripToTheDigitsWritten() {
    MainWindow window;
    auto* editor = window.caseEditor();
    auto* document = window.document();
    QVERIFY(document->setChoice("big_end.supply", "groove"));
    QTemporaryDir dir;
    const CurveFile file = SupplyCurveFile();
    WriteFile(dir.filePath("in.csv"), file.text);
    QVERIFY(editor->importListCsv(kCurve, dir.filePath("in.csv")));
    const auto imported = document->engineCase().big_end;

    // The export: comment lines saying what the units are, the table's header, the file's
    // numbers to the digit.
    const QString out = dir.filePath("out.csv");
    QVERIFY(editor->exportListCsv(kCurve, out));
    const QList<QByteArray> lines = ReadFile(out).split('\n');
    QVERIFY(lines.size() >= 3 + 72);
    QVERIFY2(lines[0].startsWith("# Supply pressure curve"), lines[0].constData());
    QVERIFY2(lines[1].startsWith("#") &&
                 lines[1].contains("big_end.supply_pressure_angles [rad]") &&
                 lines[1].contains("big_end.supply_pressure_values [Pa]"),
             lines[1].constData());
    QCOMPARE(QString::fromUtf8(lines[2]), QString("crank angle [°CA],gauge pressure [MPa]"));
    for (size_t k = 0; k < 72; ++k) {
      const QList<QByteArray> cells = lines[qsizetype(3 + k)].split(',');
      QCOMPARE(cells.size(), 2);
      QCOMPARE(cells[0].toDouble(), file.angles_deg[k]);
      QCOMPARE(cells[1].toDouble(), file.pressures_mpa[k]);
    }
    // No export leaves a temporary file behind.
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files).size(), 2);

    // Another curve, then the exported file: exactly the imported values again, one undo step.
    auto changed = document->engineCase();
    for (double& p : changed.big_end.supply_pressure_values) p *= 1.5;
    changed.big_end.supply_pressure_angles.pop_back();
    changed.big_end.supply_pressure_values.pop_back();
    document->edit(changed, "another curve");
    QVERIFY(editor->importListCsv(kCurve, out));
    QCOMPARE(document->engineCase().big_end.supply_pressure_angles,
             imported.supply_pressure_angles);
    QCOMPARE(document->engineCase().big_end.supply_pressure_values,
             imported.supply_pressure_values);
    // Exported again: the same file.
    QVERIFY(editor->exportListCsv(kCurve, dir.filePath("again.csv")));
    QCOMPARE(ReadFile(dir.filePath("again.csv")), ReadFile(out));

    // A list of one column (the hole angles, ° in the file, rad in the case) the same way; an
    // export over an existing file replaces it.
    QVERIFY(document->setChoice("big_end.supply", "pin_holes"));
    WriteFile(dir.filePath("holes.csv"), "angles [deg]\n-45\n\"135.5\"\n");
    QVERIFY(editor->importListCsv(kHoles, dir.filePath("holes.csv")));
    const std::vector<double> holes = {-45 * kDeg, 135.5 * kDeg};
    QCOMPARE(document->engineCase().big_end.supply_hole_angles, holes);
    QVERIFY(editor->exportListCsv(kHoles, out));
    QVERIFY2(ReadFile(out).endsWith("angles [°]\n-45\n135.5\n"), ReadFile(out).constData());
  }

  void badCsvChangesNothingAndNamesFileLineAndValue() {
    MainWindow window;
    auto* editor = window.caseEditor();
    auto* document = window.document();
    QVERIFY(document->setChoice("big_end.supply", "shell_holes"));
    QTemporaryDir dir;
    WriteFile(dir.filePath("good.csv"), SupplyCurveFile().text);
    QVERIFY(editor->importListCsv(kCurve, dir.filePath("good.csv")));
    const auto before = document->engineCase().big_end;
    const int steps = document->undoStack()->count();
    QSignalSpy status(editor, &filmdyn::ui::CaseEditor::statusMessage);

    struct Bad {
      QByteArray text;
      QStringList expected;  // what the message must say besides the file's name
    };
    const std::vector<Bad> cases = {
        // A non-number at line 3.
        {"crank angle [°],gauge pressure [MPa]\n0,0.3\n10,abc\n",
         {":3 ", "gauge pressure [MPa]", "\"abc\"", "finite number"}},
        // Three cells in a table of two columns.
        {"# comment\ncrank angle [°],gauge pressure [MPa]\n0,0.3,7\n",
         {":3", "\"0,0.3,7\"", "2 cells: crank angle [°CA], gauge pressure [MPa]"}},
        // Not a number by IEEE: NaN, infinity.
        {"crank angle [°],gauge pressure [MPa]\n0,0.3\n10,nan\n",
         {":3 ", "\"nan\"", "finite number"}},
        {"crank angle [°],gauge pressure [MPa]\n0,0.3\n\n10,-inf\n",
         {":4 ", "\"-inf\"", "finite number"}},
        // Outside the field's range: a negative gauge pressure, in the file's unit.
        {"crank angle [°],gauge pressure [MPa]\n0,0.3\n10,-0.2\n",
         {":3 ", "\"-0.2\"", "allowed values", "MPa"}},
        // Nothing at all, or comments only.
        {"", {"empty", "crank angle [°CA],gauge pressure [MPa]"}},
        {"# only a comment\n\n", {"empty", "crank angle [°CA],gauge pressure [MPa]"}},
        // Another table's header (the cylinder-pressure CSV).
        {"crank_angle[deg],pressure[Pa]\n0,1e5\n",
         {":1 header", "crank_angle[deg],pressure[Pa]", "crank angle [°CA],gauge pressure [MPa]"}},
    };
    for (size_t i = 0; i < cases.size(); ++i) {
      const QString path = dir.filePath(QString("bad%1.csv").arg(i));
      WriteFile(path, cases[i].text);
      status.clear();
      QVERIFY(!editor->importListCsv(kCurve, path));
      QCOMPARE(status.count(), 1);
      const QString message = status.first().first().toString();
      QVERIFY2(message.contains(path), qPrintable(message));
      for (const QString& part : cases[i].expected) {
        QVERIFY2(message.contains(part),
                 qPrintable(QString("%1: no \"%2\" in: %3").arg(i).arg(part, message)));
      }
      // Nothing changed: the same curve, no undo step.
      QCOMPARE(document->engineCase().big_end.supply_pressure_angles,
               before.supply_pressure_angles);
      QCOMPARE(document->engineCase().big_end.supply_pressure_values,
               before.supply_pressure_values);
      QCOMPARE(document->undoStack()->count(), steps);
    }
    // A file that is not there: named, nothing changed.
    status.clear();
    QVERIFY(!editor->importListCsv(kCurve, dir.filePath("missing.csv")));
    QVERIFY2(status.first().first().toString().contains("missing.csv"),
             qPrintable(status.first().first().toString()));
    QCOMPARE(document->undoStack()->count(), steps);
    // An export into a folder that does not exist fails and says where.
    status.clear();
    QVERIFY(!editor->exportListCsv(kCurve, dir.filePath("no/such/folder/out.csv")));
    QVERIFY(status.first().first().toString().contains("out.csv"));
  }

  void unusedListsAreGreyedWithTheReason() {
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    auto* editor = window.caseEditor();
    auto* document = window.document();
    editor->findChild<QTabWidget*>("case_tabs")->setCurrentIndex(4);  // Big-end bearing
    QLabel* hint = editor->listHint(kHoles);
    QVERIFY(hint != nullptr);
    // The default case: the film starts at the line of centres, no hole and no curve is read.
    QCOMPARE(document->engineCase().big_end.supply,
             filmdyn::lubrication::OilFeedKind::kLineOfCentres);
    QVERIFY(!editor->listEnabled(kHoles));
    QVERIFY(!editor->listTable(kHoles)->isEnabled());
    QVERIFY(!ListButton(window, kHoles, "import")->isEnabled());
    QVERIFY(!ListButton(window, kHoles, "insert")->isEnabled());
    QVERIFY(hint->isVisible());
    // In the choices' titles, as the supply's combo box shows them (the file's names are not
    // on screen).
    QVERIFY2(hint->text().contains("film start at the line of centres") &&
                 hint->text().contains("holes in the crank pin") &&
                 !hint->text().contains("line_of_centres") && !hint->text().contains("pin_holes"),
             qPrintable(hint->text()));
    QVERIFY(!editor->listEnabled(kCurve));
    QVERIFY2(editor->listHint(kCurve)->text().contains("holes or a groove"),
             qPrintable(editor->listHint(kCurve)->text()));
    // The supply's scalar rows likewise; the assumed supply pressure says first that it is not
    // read (where its value came from matters once it is).
    const auto big_end = CaseGroup::kBigEnd;
    QVERIFY2(Greyed(window, big_end, "big_end.supply_hole_diameter"),
             qPrintable(NoteOf(window, big_end, "big_end.supply_hole_diameter")));
    QVERIFY(NoteOf(window, big_end, "big_end.supply_hole_diameter")
                .contains("the oil supply is “film start at the line of centres”"));
    QVERIFY(Greyed(window, big_end, "big_end.groove_width"));
    QVERIFY(Greyed(window, big_end, "big_end.groove_start_angle"));
    QVERIFY(document->engineCase().assumed.count("big_end.oil_feed_pressure"));
    QVERIFY2(Greyed(window, big_end, "big_end.oil_feed_pressure"),
             qPrintable(NoteOf(window, big_end, "big_end.oil_feed_pressure")));

    // Crank-pin holes: both tables are read.
    QVERIFY(document->setChoice("big_end.supply", "pin_holes"));
    QVERIFY(!Greyed(window, big_end, "big_end.supply_hole_diameter"));
    QVERIFY(!Greyed(window, big_end, "big_end.oil_feed_pressure"));
    QVERIFY(Greyed(window, big_end, "big_end.groove_width"));
    QVERIFY(editor->listEnabled(kHoles));
    QVERIFY(editor->listTable(kHoles)->isEnabled());
    QVERIFY(ListButton(window, kHoles, "import")->isEnabled());
    QVERIFY(!hint->isVisible());
    QVERIFY(editor->listEnabled(kCurve));
    // A groove: the holes are not.
    QVERIFY(document->setChoice("big_end.supply", "groove"));
    QVERIFY(!editor->listEnabled(kHoles));
    QVERIFY2(hint->isVisible() && hint->text().contains("groove"), qPrintable(hint->text()));
    QVERIFY(editor->listEnabled(kCurve));
    QVERIFY(Greyed(window, big_end, "big_end.supply_hole_diameter"));
    QVERIFY(!Greyed(window, big_end, "big_end.groove_width"));
    QVERIFY(!Greyed(window, big_end, "big_end.oil_feed_pressure"));
    // Pin holes and a groove: both.
    QVERIFY(document->setChoice("big_end.supply", "pin_holes_and_groove"));
    QVERIFY(editor->listEnabled(kHoles));
    QVERIFY(!Greyed(window, big_end, "big_end.supply_hole_diameter"));
    QVERIFY(!Greyed(window, big_end, "big_end.groove_width"));
    QVERIFY(!Greyed(window, big_end, "big_end.groove_start_angle"));
    document->undoStack()->undo();
    QVERIFY(!editor->listEnabled(kHoles));
    // Undo: the crank-pin holes again.
    document->undoStack()->undo();
    QVERIFY(editor->listEnabled(kHoles));
    // Back to the line of centres with a curve: core refuses it, so its table stays editable
    // (to remove the rows) while the holes are greyed.
    QTemporaryDir dir;
    WriteFile(dir.filePath("curve.csv"), SupplyCurveFile().text);
    QVERIFY(editor->importListCsv(kCurve, dir.filePath("curve.csv")));
    // The curve replaces the constant supply pressure.
    QVERIFY2(Greyed(window, big_end, "big_end.oil_feed_pressure") &&
                 NoteOf(window, big_end, "big_end.oil_feed_pressure").contains("curve"),
             qPrintable(NoteOf(window, big_end, "big_end.oil_feed_pressure")));
    QVERIFY(document->setChoice("big_end.supply", "line_of_centres"));
    QVERIFY(!editor->listEnabled(kHoles));
    QVERIFY(editor->listEnabled(kCurve));
    QVERIFY(document->issues().count("big_end.supply"));
    QVERIFY(!window.runAction()->isEnabled());

    // The skirt's liner oil film: read for a starved skirt only.
    const char* film = "skirt.oil_film_values";
    QVERIFY(!editor->listEnabled(film));
    QVERIFY2(editor->listHint(film)->text().contains("flooded") &&
                 editor->listHint(film)->text().contains("“starved (liner oil film)”"),
             qPrintable(editor->listHint(film)->text()));
    QVERIFY(Greyed(window, CaseGroup::kSkirt, "skirt.oil_film"));
    QVERIFY(document->setChoice("skirt.cavitation", "jfo"));
    QVERIFY(document->setChoice("skirt.supply", "starved"));
    QVERIFY(editor->listEnabled(film));
    QVERIFY(editor->listHint(film)->text().isEmpty());
    QVERIFY(!Greyed(window, CaseGroup::kSkirt, "skirt.oil_film"));
    // Tables no choice decides are always enabled.
    QVERIFY(editor->listEnabled("skirt.profile_y") && editor->listEnabled("skirt.ovality_h"));
  }

  // A choice's combo box in a greyed (unused) row is greyed too (its black text read as live),
  // and turns black when a choice elsewhere makes the field used.
  void unusedChoicesAreGreyedLikeTheirRows() {
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    auto check = [&](int* greyed) {
      for (QComboBox* combo : window.caseEditor()->findChildren<QComboBox*>()) {
        const QString path = combo->objectName().mid(QString("choice_").size());
        if (!combo->objectName().startsWith("choice_")) continue;
        const filmdyn::engine::CaseField* f = filmdyn::engine::FindCaseField(path.toStdString());
        QVERIFY2(f, qPrintable(path));
        const bool unused =
            !filmdyn::engine::UnusedReason(window.document()->engineCase(), f->path).empty();
        const QColor text = combo->palette().color(QPalette::Text);
        QVERIFY2(unused == (text == QColor(150, 150, 150)),
                 qPrintable(QString("%1: %2, text %3").arg(path).arg(unused).arg(text.name())));
        *greyed += unused;
      }
    };
    int greyed = 0;
    check(&greyed);
    QVERIFY(greyed > 0);  // the default case leaves some choices unused (a joint's own oil)
    QVERIFY(window.document()->setChoice("skirt.cavitation", "jfo"));
    greyed = 0;
    check(&greyed);
  }

  void editsDropTheAssumedNoteOfWhatTheyChange() {
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    auto* editor = window.caseEditor();
    auto* document = window.document();
    auto* tabs = editor->findChild<QTabWidget*>("case_tabs");
    tabs->setCurrentIndex(3);  // Piston skirt
    // The default case assumes the skirt profile: its block says so.
    const auto& assumed = document->engineCase().assumed;
    QVERIFY(assumed.count("skirt.profile_y") && assumed.count("skirt.profile_h"));
    QLabel* note = editor->listAssumed("skirt.profile_h");
    QVERIFY(note != nullptr && note->isVisible());
    QVERIFY2(note->text().startsWith("assumed: ") &&
                 note->text().contains(QString::fromStdString(assumed.at("skirt.profile_h"))),
             qPrintable(note->text()));

    // One cell typed: the table's notes go (both columns), the others stay.
    TypeIntoCell(editor->listTable("skirt.profile_h"), editor->profileModel()->index(0, 1), "22");
    QCOMPARE(document->engineCase().skirt.profile_h[0], 22e-6);
    QVERIFY(!assumed.count("skirt.profile_y") && !assumed.count("skirt.profile_h"));
    QVERIFY(assumed.count("skirt.ovality_alpha") && assumed.count("skirt.peklenik"));
    QVERIFY(!note->isVisible());
    QVERIFY(note->text().isEmpty());
    // Saved without it: the file no longer calls the user's profile assumed.
    const nlohmann::json saved = filmdyn::io::CaseToJson(document->engineCase());
    QVERIFY(!saved["assumed"].contains("skirt.profile_h"));
    QVERIFY(saved["assumed"].contains("skirt.peklenik"));
    // Undo brings the value and the note back.
    document->undoStack()->undo();
    QVERIFY(assumed.count("skirt.profile_y") && assumed.count("skirt.profile_h"));
    QVERIFY(note->isVisible());

    // An import into the ovality (assumed: round) drops its notes the same way.
    QVERIFY(!editor->listAssumed("skirt.ovality_alpha")->text().isEmpty());
    QTemporaryDir dir;
    WriteFile(dir.filePath("ovality.csv"), "angle α [°],extra gap h [µm]\n0,0\n90,12\n180,0\n");
    QVERIFY(editor->importListCsv("skirt.ovality_alpha", dir.filePath("ovality.csv")));
    QCOMPARE(document->engineCase().skirt.ovality_h[1], 12e-6);
    QVERIFY(!assumed.count("skirt.ovality_alpha") && !assumed.count("skirt.ovality_h"));
    QVERIFY(editor->listAssumed("skirt.ovality_alpha")->text().isEmpty());
    QVERIFY(assumed.count("skirt.profile_h"));

    // A choice row: the big end's supply is assumed (no supply given) until one is picked.
    QVERIFY2(NoteOf(window, CaseGroup::kBigEnd, "big_end.supply").startsWith("assumed: "),
             qPrintable(NoteOf(window, CaseGroup::kBigEnd, "big_end.supply")));
    QVERIFY(document->setChoice("big_end.supply", "shell_holes"));
    QVERIFY(!assumed.count("big_end.supply"));
    QVERIFY(NoteOf(window, CaseGroup::kBigEnd, "big_end.supply").isEmpty());
    // A number: the skirt's Young's modulus.
    QVERIFY(NoteOf(window, CaseGroup::kSkirt, "skirt.modulus_skirt").startsWith("assumed: "));
    document->setParameter("skirt.modulus_skirt", 80e9);
    QVERIFY(NoteOf(window, CaseGroup::kSkirt, "skirt.modulus_skirt").isEmpty());
    document->undoStack()->undo();
    QVERIFY(NoteOf(window, CaseGroup::kSkirt, "skirt.modulus_skirt").startsWith("assumed: "));
  }

  void screenshotOfTheBigEndTab() {
    const QString dir = qEnvironmentVariable("FILMDYN_SCREENSHOT_DIR");
    if (dir.isEmpty()) QSKIP("FILMDYN_SCREENSHOT_DIR not set");
    MainWindow window;
    window.resize(1600, 1000);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.workspace()->setCurrentIndex(0);
    window.caseEditor()->findChild<QTabWidget*>("case_tabs")->setCurrentIndex(4);
    // A groove fed with an imported gallery-pressure curve: the holes' table greyed.
    QVERIFY(window.document()->setChoice("big_end.supply", "groove"));
    QTemporaryDir files;
    WriteFile(files.filePath("gallery.csv"), SupplyCurveFile().text);
    QVERIFY(window.caseEditor()->importListCsv(kCurve, files.filePath("gallery.csv")));
    QVERIFY(window.document()->issues().empty());
    window.statusBar()->clearMessage();  // the import's message names a temporary folder
    QTest::qWait(200);
    QVERIFY(window.grab().save(dir + "/case_list_csv.png"));
  }
};

QTEST_MAIN(TestCaseEditorLists)
#include "test_case_editor_lists.moc"
