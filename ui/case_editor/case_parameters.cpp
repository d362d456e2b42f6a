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
      return t.columns.front()->SameListTable(field);
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
  // Core decides, for the table's first column as for any field (engine::UnusedReason), in the
  // choices' titles as the editor shows them.
  const std::string unused = engine::UnusedReason(c, table.key, engine::ChoiceWording::kTitles);
  if (unused.empty()) return {};
  return QObject::tr("Not used: %1.").arg(QString::fromStdString(unused));
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
