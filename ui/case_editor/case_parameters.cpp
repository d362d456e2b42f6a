#include "ui/case_editor/case_parameters.hpp"

#include <QObject>
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
    if (!number && !choice) continue;
    CaseParameter p;
    p.group = field.group;
    p.path = field.path;
    p.label = QString::fromStdString(field.label);
    p.field = &field;
    if (choice) {
      p.choice = true;
    } else {
      p.unit = QString::fromStdString(field.display_unit);
      p.to_si = field.display_scale;
      p.integer = field.kind == engine::FieldKind::kInteger;
      p.get = field.get;
      p.set = field.set;
      p.check = [&field](const std::string& name, double si) { field.Check(si, name); };
    }
    rows.push_back(std::move(p));
  }
  return rows;
}

}  // namespace

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
