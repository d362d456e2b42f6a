// The case schema is the one definition of every case field: each scalar field round-trips
// through the case file, `--set` and the GUI's editor cell, every list element through the file,
// every choice (but the joints' models, which the run-model selector sets) through its row of the
// editor, every list is a column of exactly one editor table (a pair core names by one symbol
// being one table) whose key carries core's complaints about it, and at each end of each field's
// range (and just beyond it) the GUI accepts exactly what core's case reader accepts.
#include <QApplication>
#include <QUndoStack>
#include <QtTest>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "core/base/input_error.hpp"
#include "core/engine/case_schema.hpp"
#include "core/io/case_file.hpp"
#include "ui/case_editor/case_document.hpp"
#include "ui/case_editor/case_parameters.hpp"
#include "ui/case_editor/case_validation.hpp"
#include "ui/case_editor/parameter_table_model.hpp"

using namespace filmdyn;

namespace {

engine::EngineCase DefaultCase() { return io::LoadCase({}).value; }

std::string Exact(double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

// Does core's case reader accept the default case with `path` set to `value` (through --set)?
bool CoreAccepts(const std::string& path, double value) {
  nlohmann::json root = io::CaseToJson(DefaultCase());
  try {
    io::ApplyOverride(&root, path + "=" + Exact(value));
    io::CaseFromJson(root);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

// Does the GUI's validation accept it?
bool GuiAccepts(const engine::CaseField& field, double value) {
  engine::EngineCase c = DefaultCase();
  field.set(c, value);
  return ui::ValidateCase(c).empty();
}

// A valid value different from the default (inside the range and the cross-field rules).
double Changed(const engine::CaseField& field, const engine::EngineCase& c) {
  const double v = field.get(c);
  if (field.kind == engine::FieldKind::kInteger) return v + 1 <= field.range.hi ? v + 1 : v - 1;
  for (double factor : {1.001, 0.999, 0.5}) {
    const double candidate =
        v != 0.0 ? v * factor : (std::isfinite(field.range.hi) ? field.range.hi * 1e-3 : factor);
    engine::EngineCase changed = c;
    field.set(changed, candidate);
    if (ui::ValidateCase(changed).empty()) return candidate;
  }
  return std::isfinite(field.range.hi) ? 0.5 * (field.range.lo + field.range.hi) : v + 1.0;
}

}  // namespace

class TestCaseSchema : public QObject {
  Q_OBJECT
 private slots:
  void everyFieldIsInTheFileAndTheEditor() {
    const nlohmann::json file = io::CaseToJson(DefaultCase());
    int scalars = 0;
    for (const engine::CaseField& field : engine::CaseSchema()) {
      // Every field is in the file under its path, with a label, help and (numbers) a unit.
      const nlohmann::json* node = &file;
      std::size_t start = 0;
      for (std::size_t dot; (dot = field.path.find('.', start)), true; start = dot + 1) {
        const std::string key = field.path.substr(start, dot - start);
        QVERIFY2(node->contains(key), field.path.c_str());
        node = &(*node)[key];
        if (dot == std::string::npos) break;
      }
      QVERIFY2(!field.label.empty() && !field.help.empty(), field.path.c_str());
      if (field.kind == engine::FieldKind::kNumber || field.kind == engine::FieldKind::kInteger) {
        ++scalars;
        QVERIFY2(!field.unit.empty() && field.display_scale > 0, field.path.c_str());
        const ui::CaseParameter* row = ui::FindCaseParameter(field.path);
        QVERIFY2(row != nullptr, field.path.c_str());
        QCOMPARE(row->to_si, field.display_scale);
        QCOMPARE(row->integer, field.kind == engine::FieldKind::kInteger);
        QVERIFY(!row->choice);
      } else if (field.kind == engine::FieldKind::kChoice) {
        // Every choice has a row of its tab, but the joints' models (the run-model selector).
        const ui::CaseParameter* row = ui::FindCaseParameter(field.path);
        QCOMPARE(row == nullptr, ui::SetByRunModel(field));
        if (row == nullptr) continue;
        ++scalars;
        QVERIFY2(row->choice && row->field == &field && row->unit.isEmpty(), field.path.c_str());
        QCOMPARE(row->group, field.group);
      } else if (field.kind == engine::FieldKind::kText) {
        // The file names a joint reads have a row of their tab; the case's name does not.
        const ui::CaseParameter* row = ui::FindCaseParameter(field.path);
        QCOMPARE(row == nullptr, field.group == engine::FieldGroup::kCase);
        if (row == nullptr) continue;
        ++scalars;
        QVERIFY2(row->text && !row->choice && row->field == &field, field.path.c_str());
      }
    }
    QCOMPARE(int(ui::CaseParameters().size()), scalars);
    QVERIFY(ui::SetByRunModel(*engine::FindCaseField("skirt.model")));
    QVERIFY(ui::SetByRunModel(*engine::FindCaseField("big_end.model")));
    QVERIFY(ui::FindCaseParameter("big_end.cavitation") != nullptr);
    QVERIFY(ui::FindCaseParameter("skirt.cavitation") != nullptr);
  }

  // A file name typed in its row is the case's (one undo step), greyed with its reason while
  // the joint does not use it.
  void fileNameRowsEditTheCase() {
    ui::CaseDocument document;
    document.reset(DefaultCase());
    ui::ParameterTableModel model(&document, engine::FieldGroup::kSkirt);
    const QModelIndex cell =
        model.index(model.rowOf("skirt.compliance_file"), ui::ParameterTableModel::kValue);
    QVERIFY(cell.isValid());
    QVERIFY(model.flags(cell) & Qt::ItemIsEditable);
    QVERIFY(model.data(cell.siblingAtColumn(ui::ParameterTableModel::kNote), Qt::DisplayRole)
                .toString()
                .startsWith("not used"));
    QVERIFY(model.setData(cell, "fe/skirt.mtx", Qt::EditRole));
    QCOMPARE(document.engineCase().skirt.compliance_file, std::string("fe/skirt.mtx"));
    QCOMPARE(model.data(cell, Qt::DisplayRole).toString(), QString("fe/skirt.mtx"));
    // The whole name in the tooltip (the narrow cell elides it on the left).
    QVERIFY(model.data(cell, Qt::ToolTipRole).toString().startsWith("<qt><p>fe/skirt.mtx</p>"));
    // A note too (a narrow table elides it), as rich text like the rest of the tooltip.
    const QString note_tip =
        model.data(cell.siblingAtColumn(ui::ParameterTableModel::kNote), Qt::ToolTipRole)
            .toString();
    QVERIFY2(note_tip.startsWith("<qt><p>not used: ") && note_tip.contains("skirt.compliance_file"),
             qPrintable(note_tip));
    QVERIFY(document.setChoice("skirt.compliance", "imported"));
    QVERIFY(!model.data(cell.siblingAtColumn(ui::ParameterTableModel::kNote), Qt::DisplayRole)
                 .toString()
                 .startsWith("not used"));
    document.undoStack()->undo();
    document.undoStack()->undo();
    QVERIFY(document.engineCase().skirt.compliance_file.empty());
  }

  void everyChoiceRoundTripsThroughFileSetAndEditor() {
    const engine::EngineCase base = DefaultCase();
    int checked = 0;
    for (const ui::CaseParameter& p : ui::CaseParameters()) {
      if (!p.choice) continue;
      const engine::CaseField& field = *p.field;
      // Each choice's title names it alone: no two alike, none another choice's name.
      for (std::size_t k = 0; k < field.choices.size(); ++k) {
        QCOMPARE(field.ChoiceIndex(field.ChoiceTitle(k)), int(k));
        QCOMPARE(field.ChoiceIndex(field.choices[k]), int(k));
      }
      QCOMPARE(field.ChoiceIndex("no such choice"), -1);
      for (const std::string& name : field.choices) {
        // Does core's case reader accept the default case with this name? (A choice may need
        // another field, e.g. a cavitation model.)
        engine::EngineCase chosen = base;
        field.SetChoice(chosen, name);
        bool core_accepts = true;
        try {
          io::CaseFromJson(io::CaseToJson(chosen));
        } catch (const InputError&) {
          core_accepts = false;
        }
        // The editor cell: the name picked is the name stored, one undo step away, and the GUI
        // accepts it exactly when core does (otherwise the row carries core's reason).
        ui::CaseDocument document;
        document.reset(base);
        ui::ParameterTableModel model(&document, field.group);
        const QModelIndex cell =
            model.index(model.rowOf(field.path), ui::ParameterTableModel::kValue);
        QVERIFY2(cell.isValid(), field.path.c_str());
        QCOMPARE(cell.data(ui::ParameterTableModel::kChoicesRole).toStringList().size(),
                 qsizetype(field.choices.size()));
        QVERIFY(cell.flags() & Qt::ItemIsEditable);
        QVERIFY(model.setData(cell, QString::fromStdString(name), Qt::EditRole));
        QCOMPARE(field.ChoiceName(document.engineCase()), name);
        // The cell shows the choice's title (the combo box offers the titles), and picking the
        // title stores the same name.
        const std::string title = field.ChoiceTitle(std::size_t(field.ChoiceIndex(name)));
        QCOMPARE(cell.data().toString(), QString::fromStdString(title));
        QVERIFY(cell.data(ui::ParameterTableModel::kChoicesRole)
                    .toStringList()
                    .contains(QString::fromStdString(title)));
        QVERIFY(model.setData(cell, QString::fromStdString(title), Qt::EditRole));
        QCOMPARE(field.ChoiceName(document.engineCase()), name);
        QCOMPARE(document.undoStack()->count(), name == field.ChoiceName(base) ? 0 : 1);
        QVERIFY2(document.issues().empty() == core_accepts, (field.path + " = " + name).c_str());
        if (!core_accepts) {
          QVERIFY(!document.runBlocker().isEmpty());
          continue;
        }
        // The file and --set.
        QCOMPARE(field.ChoiceName(io::CaseFromJson(io::CaseToJson(document.engineCase()))), name);
        nlohmann::json root = io::CaseToJson(base);
        io::ApplyOverride(&root, field.path + "=" + name);
        QCOMPARE(field.ChoiceName(io::CaseFromJson(root)), name);
        ++checked;
      }
      // A name core does not know changes nothing (never a crash).
      ui::CaseDocument document;
      document.reset(base);
      ui::ParameterTableModel model(&document, field.group);
      const QModelIndex cell =
          model.index(model.rowOf(field.path), ui::ParameterTableModel::kValue);
      QVERIFY(!model.setData(cell, QString("no-such-model"), Qt::EditRole));
      QVERIFY(!document.isModified());
      QCOMPARE(field.choice(document.engineCase()), field.choice(base));
    }
    QVERIFY(checked >= 4);  // at least the two joints' cavitation models, two names each
  }

  void everyScalarRoundTripsThroughFileSetAndEditor() {
    // Shell holes: a supply pressure then has somewhere to act (the default's film start at the
    // line of centres refuses one).
    engine::EngineCase base = DefaultCase();
    base.big_end.supply = lubrication::OilFeedKind::kShellHoles;
    for (const engine::CaseField& field : engine::CaseSchema()) {
      if (field.kind != engine::FieldKind::kNumber && field.kind != engine::FieldKind::kInteger) {
        continue;
      }
      const double value = Changed(field, base);
      QVERIFY2(value != field.get(base), field.path.c_str());
      // File.
      engine::EngineCase c = base;
      field.set(c, value);
      QCOMPARE(field.get(io::CaseFromJson(io::CaseToJson(c))), value);
      // --set.
      nlohmann::json root = io::CaseToJson(base);
      io::ApplyOverride(&root, field.path + "=" + Exact(value));
      QCOMPARE(field.get(io::CaseFromJson(root)), value);
      // The editor cell: typed in display units, stored in SI.
      ui::CaseDocument document;
      document.reset(base);
      ui::ParameterTableModel model(&document, field.group);
      const int row = model.rowOf(field.path);
      QVERIFY2(row >= 0, field.path.c_str());
      const QModelIndex cell = model.index(row, ui::ParameterTableModel::kValue);
      QVERIFY(model.setData(cell, QString::number(field.ToDisplay(value), 'g', 17), Qt::EditRole));
      const double stored = field.get(document.engineCase());
      // A shifted display unit (°C for K) loses the digits of the shift.
      const double tolerance = 1e-12 * (std::abs(value) + std::abs(field.display_offset));
      QVERIFY2(std::abs(stored - value) <= tolerance, field.path.c_str());
      QVERIFY2(document.issues().empty(), field.path.c_str());
    }
  }

  // A unit that is an integer fraction of SI converts by that integer: a decimal typed in µm is
  // stored as the same decimal written in m more often than by multiplying with 1e-6 (the file
  // reads 8.5e-07, not 8.5000000000000004e-07: 13 % of random 1–6 digit decimals still differ in
  // the last bit, against 36 %), and a value shows in the editor at 15 digits, as written.
  // A typed number: '.' is always the decimal point; a comma is the decimal point of a
  // decimal-comma locale ("1,125" is 1.125 there, not 1125 read with a thousands separator),
  // and a thousands separator in a locale that groups with it.
  void typedNumbersReadTheDecimalComma() {
    const QLocale saved;
    QLocale::setDefault(QLocale(QLocale::German));
    QCOMPARE(ui::ParseUserNumber("1,125"), 1.125);
    QCOMPARE(ui::ParseUserNumber("1.125"), 1.125);
    QCOMPARE(ui::ParseUserNumber(" 0,85 "), 0.85);
    QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
    QCOMPARE(ui::ParseUserNumber("1,125"), 1125.0);
    QCOMPARE(ui::ParseUserNumber("1.125"), 1.125);
    QVERIFY(std::isnan(ui::ParseUserNumber("1,2,3x")));
    QLocale::setDefault(saved);
  }

  void displayUnitsKeepTypedDecimals() {
    QCOMPARE(engine::ScaleFromDisplay(0.615, 1e-6), 6.15e-7);  // × 1e-6 gives 6.150...04e-07
    QCOMPARE(engine::ScaleToDisplay(6.15e-7, 1e-6), 0.615);    // ÷ 1e-6 gives 0.615...01
    QCOMPARE(engine::ScaleFromDisplay(25.05, 1e-3), 0.02505);  // × 1e-3 gives 0.025050...03
    QCOMPARE(engine::ScaleFromDisplay(0.4, 1e6), 4e5);         // MPa: a multiple of SI
    const double degree = M_PI / 180.0;                        // not an integer fraction
    QCOMPARE(engine::ScaleFromDisplay(30.0, degree), 30.0 * degree);
    QCOMPARE(ui::FormatEditNumber(engine::ScaleToDisplay(0.1452345678, 1e-3)),
             QString("145.2345678"));  // the display double is 145.23456779999998
    const engine::CaseField* sigma = engine::FindCaseField("skirt.roughness_skirt");
    QVERIFY(sigma != nullptr && sigma->display_unit == "µm");
    ui::CaseDocument document;
    document.reset(DefaultCase());
    ui::ParameterTableModel model(&document, sigma->group);
    const QModelIndex cell = model.index(model.rowOf(sigma->path), ui::ParameterTableModel::kValue);
    QVERIFY(model.setData(cell, "0.85", Qt::EditRole));
    QCOMPARE(document.engineCase().skirt.roughness_skirt, 8.5e-7);
    QCOMPARE(cell.data(Qt::EditRole).toString(), QString("0.85"));
  }

  void listsRoundTripThroughTheFile() {
    engine::EngineCase c = DefaultCase();
    c.skirt.ovality_alpha = {0.0, 1.5, 3.0};
    c.skirt.ovality_h = {0.0, 4e-6, 1e-6};
    c.skirt.profile_h[1] = 6.5e-6;
    const engine::EngineCase back = io::CaseFromJson(io::CaseToJson(c));
    for (const engine::CaseField& field : engine::CaseSchema()) {
      if (field.kind != engine::FieldKind::kNumberList) continue;
      engine::EngineCase a = c, b = back;
      QVERIFY2(field.list(a) == field.list(b), field.path.c_str());
    }
  }

  void everyListIsAColumnOfOneEditorTable() {
    std::map<std::string, int> columns;
    for (const ui::CaseListTable& table : ui::CaseListTables()) {
      QVERIFY(!table.columns.empty());
      QCOMPARE(table.key, table.columns.front()->path);
      QVERIFY(!table.title.isEmpty());
      for (const engine::CaseField* field : table.columns) {
        QCOMPARE(field->kind, engine::FieldKind::kNumberList);
        QCOMPARE(field->group, table.group);
        QVERIFY2(QString::fromStdString(field->label).startsWith(table.title), field->path.c_str());
        ++columns[field->path];
        // The column, an element of it, a pressure curve's point: all the table's.
        QCOMPARE(ui::FindCaseListTable(field->path), &table);
        QCOMPARE(ui::FindCaseListTable(field->path + ".3"), &table);
        QCOMPARE(ui::FindCaseListTable(field->path + "[3].crank_angle"), &table);
      }
    }
    for (const engine::CaseField& field : engine::CaseSchema()) {
      if (field.kind == engine::FieldKind::kNumberList) {
        QVERIFY2(columns[field.path] == 1, field.path.c_str());
      } else {
        QVERIFY2(ui::FindCaseListTable(field.path) == nullptr, field.path.c_str());
      }
    }
    // The pairs and the single list, in schema order.
    const std::vector<std::vector<std::string>> expected = {
        {"skirt.oil_film_positions", "skirt.oil_film_values"},
        {"skirt.profile_y", "skirt.profile_h"},
        {"skirt.ovality_alpha", "skirt.ovality_h"},
        {"big_end.supply_pressure_angles", "big_end.supply_pressure_values"},
        {"big_end.supply_hole_angles"}};
    QCOMPARE(ui::CaseListTables().size(), expected.size());
    for (size_t t = 0; t < expected.size(); ++t) {
      const ui::CaseListTable& table = ui::CaseListTables()[t];
      QCOMPARE(table.columns.size(), expected[t].size());
      for (size_t k = 0; k < expected[t].size(); ++k) {
        QCOMPARE(table.columns[k]->path, expected[t][k]);
      }
    }
    QCOMPARE(ui::CaseListTables()[3].title, QString("Supply pressure curve"));
    QCOMPARE(ui::CaseListColumnTitle(*engine::FindCaseField("big_end.supply_pressure_values")),
             QString("gauge pressure [MPa]"));
    QVERIFY(ui::FindCaseListTable("skirt.oil_film") == nullptr);  // the scalar beside the table
    QVERIFY(ui::FindCaseListTable("skirt.profile") == nullptr);

    // Core's complaints about a list are the table's issue, naming the field.
    engine::EngineCase c = DefaultCase();
    c.big_end.supply = lubrication::OilFeedKind::kShellHoles;
    c.big_end.supply_pressure_angles = {0.0, 700.0 * M_PI / 180.0};
    c.big_end.supply_pressure_values = {3e5, 3e5};
    ui::CaseIssues issues = ui::ValidateCase(c);
    QCOMPARE(issues.size(), size_t(1));
    QCOMPARE(issues.begin()->first, std::string("big_end.supply_pressure_angles"));
    QVERIFY2(issues.begin()->second.find("big_end.supply_pressure_angles = 2 points") !=
                 std::string::npos,
             issues.begin()->second.c_str());
    // A point's own error names its element, and the table takes it.
    c.big_end.supply_pressure_angles.clear();
    for (int k = 0; k < 72; ++k) c.big_end.supply_pressure_angles.push_back(k * 10.0 * M_PI / 180);
    c.big_end.supply_pressure_values.assign(72, 3e5);
    std::swap(c.big_end.supply_pressure_angles[5], c.big_end.supply_pressure_angles[6]);
    issues = ui::ValidateCase(c);
    QCOMPARE(issues.size(), size_t(1));
    QCOMPARE(issues.begin()->first, std::string("big_end.supply_pressure_angles"));
    QVERIFY2(issues.begin()->second.rfind("big_end.supply_pressure_angles.6 = ", 0) == 0,
             issues.begin()->second.c_str());
    c = DefaultCase();
    c.skirt.oil_film_positions = {0.0};
    c.skirt.oil_film_values = {0.0};
    issues = ui::ValidateCase(c);
    QCOMPARE(issues.size(), size_t(1));
    QCOMPARE(issues.begin()->first, std::string("skirt.oil_film_positions"));
    QVERIFY2(issues.begin()->second.find("skirt.oil_film_values.0") != std::string::npos,
             issues.begin()->second.c_str());
    // The editor's messages quote the values in the cells' units (core's are SI).
    c = DefaultCase();
    c.big_end.journal_radius = 15.2e-3;
    issues = ui::ValidateCase(c);
    QCOMPARE(issues.size(), size_t(1));
    QCOMPARE(issues.begin()->second,
             std::string("big_end.journal_radius = 15.2 mm: must be smaller than "
                         "big_end.bearing_radius = 15 mm"));
    QCOMPARE(ui::InDisplayUnits(InputError("geometry.rod_length", "-0.001",
                                           "must be a finite number in (0, 100] [m]")),
             std::string("geometry.rod_length = -1 mm: must be a finite number in (0, 100000] mm"));
    QCOMPARE(ui::InDisplayUnits(InputError("skirt.profile_h.2", "5e-05", "must be >= 0 [m]")),
             std::string("skirt.profile_h.2 = 50 µm: must be >= 0 µm"));
    // A value just past a closed end in display units: the end is shown so that, typed back, it
    // is allowed (six digits would show 0.2 rad as 11.4592 °CA, itself refused), and the value
    // so that it reads outside.
    const engine::CaseField& interval = *engine::FindCaseField("solver.output_interval");
    try {
      interval.Check(interval.FromDisplay(11.4592));
      QFAIL("11.4592 °CA > 0.2 rad was allowed");
    } catch (const InputError& e) {
      const std::string text = ui::InDisplayUnits(e);
      const auto comma = text.find(", "), close = text.find("] °CA");
      QVERIFY2(text.rfind("solver.output_interval = 11.4592 °CA: ", 0) == 0 &&
                   comma != std::string::npos && close != std::string::npos,
               text.c_str());
      const double upper =
          QString::fromStdString(text.substr(comma + 2, close - comma - 2)).toDouble();
      QVERIFY2(upper < 11.4592, text.c_str());
      interval.Check(interval.FromDisplay(upper));  // typed back: allowed (throws otherwise)
    }
    // Not a case field, or no number: as core says it.
    QCOMPARE(ui::InDisplayUnits(InputError("case", "x", "y")), std::string("case = x: y"));
    QCOMPARE(ui::InDisplayUnits(InputError("big_end.journal_radius", "abc", "must be a number")),
             std::string("big_end.journal_radius = abc: must be a number"));
    // An oil the film cannot use at its temperature is found while editing, not by the run.
    c = DefaultCase();
    c.lubricant.model = lubrication::ViscosityModel::kVogel;
    c.lubricant.vogel_a = 6.9e-5;
    c.lubricant.vogel_b = 1050.0;
    c.lubricant.vogel_c = 380.0;  // the pole above the films' 373.15 K
    issues = ui::ValidateCase(c);
    QCOMPARE(issues.size(), size_t(1));
    QCOMPARE(issues.begin()->first, std::string("skirt.oil.temperature"));
    QVERIFY2(issues.begin()->second.find("pole") != std::string::npos,
             issues.begin()->second.c_str());
  }

  void guiAndCoreAgreeAtEveryBoundary() {
    int checked = 0;
    for (const engine::CaseField& field : engine::CaseSchema()) {
      if (field.kind != engine::FieldKind::kNumber && field.kind != engine::FieldKind::kInteger) {
        continue;
      }
      std::vector<double> probes = {std::numeric_limits<double>::quiet_NaN()};
      for (double bound : {field.range.lo, field.range.hi}) {
        if (!std::isfinite(bound)) continue;
        const double step = field.kind == engine::FieldKind::kInteger
                                ? 1.0
                                : std::max(std::abs(bound) * 1e-9, 1e-300);
        probes.insert(probes.end(), {bound - step, bound, bound + step});
      }
      for (double value : probes) {
        const bool core = CoreAccepts(field.path, value);
        const bool gui = GuiAccepts(field, value);
        QVERIFY2(core == gui, qPrintable(QString("%1 = %2: core %3, GUI %4")
                                             .arg(QString::fromStdString(field.path))
                                             .arg(value, 0, 'g', 17)
                                             .arg(core ? "accepts" : "rejects")
                                             .arg(gui ? "accepts" : "rejects")));
        ++checked;
      }
    }
    QVERIFY(checked > 150);
  }
};

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  TestCaseSchema test;
  return QTest::qExec(&test, argc, argv);
}
#include "test_case_schema.moc"
