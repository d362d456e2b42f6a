#include "ui/case_editor/case_parameters.hpp"

#include <QCoreApplication>
#include <QObject>
#include <algorithm>
#include <utility>

#include "core/engine/case_schema.hpp"

namespace filmdyn::ui {

using engine::EngineCase;
using engine::JointModel;

QString CaseGroupTitle(CaseGroup group) {
  return QObject::tr(engine::FieldGroupTitle(group).c_str());
}

namespace {

// The editor's rows: every scalar field of core's schema (numbers, integers, and the choices the
// run-model selector does not set), with its label, display unit, scale and check, or its
// choices; nothing is retyped here.
std::vector<CaseParameter> MakeParameters() {
  std::vector<CaseParameter> rows;
  for (const engine::CaseField& field : engine::CaseSchema()) {
    const bool number =
        field.kind == engine::FieldKind::kNumber || field.kind == engine::FieldKind::kInteger;
    const bool choice = field.kind == engine::FieldKind::kChoice && !SetByRunModel(field);
    // Text in a group's table: the file names a joint reads (the case's own name and
    // description have their place elsewhere).
    const bool text =
        field.kind == engine::FieldKind::kText && field.group != engine::FieldGroup::kCase;
    if (!number && !choice && !text) continue;
    CaseParameter p;
    p.group = field.group;
    p.path = field.path;
    p.label = QString::fromStdString(field.label);
    p.field = &field;
    if (choice) {
      p.choice = true;
    } else if (text) {
      p.text = true;
    } else {
      p.unit = QString::fromStdString(field.display_unit);
      p.to_si = field.display_scale;
      p.integer = field.kind == engine::FieldKind::kInteger;
      p.get = field.get;
      p.set = field.set;
      p.check = [&field](const std::string& name, double si) { field.Check(si, name); };
      if (field.display_offset != 0.0) {
        // The row's "SI" value is shifted so that value / to_si is the display value.
        const double offset = field.display_offset;
        p.get = [&field, offset](const engine::EngineCase& c) { return field.get(c) - offset; };
        p.set = [&field, offset](engine::EngineCase& c, double v) { field.set(c, v + offset); };
        p.check = [&field, offset](const std::string& name, double v) {
          field.Check(v + offset, name);
        };
      }
    }
    rows.push_back(std::move(p));
  }
  return rows;
}

// The label split at its first ": " into the table's title and the column's name.
std::pair<QString, QString> SplitListLabel(const engine::CaseField& field) {
  const QString label = QString::fromStdString(field.label);
  const qsizetype colon = label.indexOf(": ");
  if (colon < 0) return {label, label};
  return {label.left(colon), label.mid(colon + 2)};
}

std::vector<CaseListTable> MakeListTables() {
  std::vector<CaseListTable> tables;
  for (const engine::CaseField& field : engine::CaseSchema()) {
    if (field.kind != engine::FieldKind::kNumberList) continue;
    auto same = std::find_if(tables.begin(), tables.end(), [&field](const CaseListTable& t) {
      const engine::CaseField& first = *t.columns.front();
      return !field.symbol.empty() && first.group == field.group && first.symbol == field.symbol;
    });
    if (same != tables.end()) {
      same->columns.push_back(&field);
      continue;
    }
    tables.push_back({field.group, field.path, SplitListLabel(field).first, {&field}});
  }
  return tables;
}

}  // namespace

const std::vector<CaseListTable>& CaseListTables() {
  static const std::vector<CaseListTable> tables = MakeListTables();
  return tables;
}

const CaseListTable* FindCaseListTable(const std::string& field) {
  for (const CaseListTable& table : CaseListTables()) {
    for (const engine::CaseField* column : table.columns) {
      const std::string& path = column->path;
      if (field.compare(0, path.size(), path) != 0) continue;
      // The column itself, or one of its elements: "path.2", "path[2].crank_angle".
      if (field.size() == path.size() || field[path.size()] == '.' || field[path.size()] == '[') {
        return &table;
      }
    }
  }
  return nullptr;
}

QString CaseListColumnTitle(const engine::CaseField& field) {
  const QString name = SplitListLabel(field).second;
  const QString unit = QString::fromStdString(field.display_unit);
  if (unit.isEmpty() || unit == QStringLiteral("–")) return name;
  return QString("%1 [%2]").arg(name, unit);
}

QString ListUnusedReason(const CaseListTable& table, const engine::EngineCase& c) {
  // The one table of which choice makes which list irrelevant (core: film_joints.cpp and the
  // supply checks of case_schema.cpp).
  struct Rule {
    const char* list;    // CaseListTable::key
    const char* choice;  // the choice field that decides
    std::vector<std::string> used_with;
    const char* why;
    bool unused_only_when_empty;
  };
  static const std::vector<Rule> rules = {
      {"big_end.supply_hole_angles",
       "big_end.supply",
       {"shell_holes", "pin_holes"},
       QT_TRANSLATE_NOOP("CaseEditor",
                         "holes feed the film only with “shell_holes” or “pin_holes”"),
       false},
      {"big_end.supply_pressure_angles",
       "big_end.supply",
       {"shell_holes", "pin_holes", "groove"},
       QT_TRANSLATE_NOOP("CaseEditor", "a supply pressure needs holes or a groove"),
       true},
      {"skirt.oil_film_positions",
       "skirt.supply",
       {"starved"},
       QT_TRANSLATE_NOOP("CaseEditor", "the liner's oil film feeds only a “starved” skirt"),
       false},
  };
  for (const Rule& rule : rules) {
    if (table.key != rule.list) continue;
    const engine::CaseField* field = engine::FindCaseField(rule.choice);
    if (field == nullptr) return {};
    const int k = field->choice(c);
    if (k < 0 || k >= int(field->choices.size())) return {};  // core names the bad choice
    const std::string& name = field->choices[size_t(k)];
    if (std::find(rule.used_with.begin(), rule.used_with.end(), name) != rule.used_with.end()) {
      return {};
    }
    if (rule.unused_only_when_empty) {
      auto& located = const_cast<engine::EngineCase&>(c);  // the accessor only locates the list
      for (const engine::CaseField* column : table.columns) {
        if (!column->list(located).empty()) return {};
      }
    }
    return QObject::tr("Not used while the %1 is “%2”: %3.")
        .arg(QString::fromStdString(field->label).toLower(), QString::fromStdString(name),
             QCoreApplication::translate("CaseEditor", rule.why));
  }
  return {};
}

const std::vector<CaseParameter>& CaseParameters() {
  static const std::vector<CaseParameter> parameters = MakeParameters();
  return parameters;
}

const CaseParameter* FindCaseParameter(const std::string& path) {
  for (const CaseParameter& p : CaseParameters()) {
    if (p.path == path) return &p;
  }
  return nullptr;
}

const std::vector<RunModel>& RunModels() {
  static const std::vector<RunModel> models = {
      {"skirt-lbrbe", "Skirt-LBRBE", JointModel::kLubricated, JointModel::kLubricated},
      {"only-skirt", "Only-Skirt", JointModel::kLubricated, JointModel::kIdeal},
      {"only-lbrbe", "Only-LBRBE", JointModel::kIdeal, JointModel::kLubricated},
      {"ideal", "Ideal", JointModel::kIdeal, JointModel::kIdeal},
  };
  return models;
}

QString RunModelKey(const EngineCase& engine_case) {
  for (const RunModel& m : RunModels()) {
    if (m.skirt == engine_case.skirt.model && m.big_end == engine_case.big_end.model) return m.key;
  }
  return "ideal";
}

void ApplyRunModel(EngineCase& engine_case, const QString& key) {
  for (const RunModel& m : RunModels()) {
    if (m.key == key) {
      engine_case.skirt.model = m.skirt;
      engine_case.big_end.model = m.big_end;
    }
  }
}

bool SetByRunModel(const engine::CaseField& field) {
  if (field.kind != engine::FieldKind::kChoice) return false;
  EngineCase c;
  ApplyRunModel(c, RunModels().front().key);
  const int first = field.choice(c);
  for (const RunModel& m : RunModels()) {
    ApplyRunModel(c, m.key);
    if (field.choice(c) != first) return true;
  }
  return false;
}

}  // namespace filmdyn::ui
