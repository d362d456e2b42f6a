#pragma once
/// @file The scalar inputs of an EngineCase as the editor shows them: one row per number, integer
/// or choice of core's case schema (core/engine/case_schema.hpp) with its dotted path, label,
/// display unit, factor to SI, help and check. Nothing is retyped here: a field added to the
/// schema appears in the editor with core's range or core's choices. The joints' models are the
/// one exception: the run-model selector sets them (RunModels below), not a row.
#include <QString>
#include <functional>
#include <string>
#include <vector>

#include "core/engine/case_schema.hpp"
#include "core/engine/engine_case.hpp"

namespace filmdyn::ui {

/// The editor tabs: the schema's field groups.
using CaseGroup = engine::FieldGroup;

/// Title of a group as shown on its editor tab.
QString CaseGroupTitle(CaseGroup group);

struct CaseParameter {
  CaseGroup group;
  std::string path;      ///< dotted case-file key, e.g. "big_end.journal_radius"
  QString label;         ///< with the paper's symbol, e.g. "Journal radius R_j"
  QString unit;          ///< display unit, e.g. "mm"
  double to_si = 1.0;    ///< SI value = display value × to_si
  bool integer = false;  ///< shown and edited as a whole number
  /// One of the names field->choices (FieldKind::kChoice), edited with a combo box: the value is
  /// field->choice / set_choice, the unit empty, and get, set and check are empty.
  bool choice = false;
  const engine::CaseField* field = nullptr;  ///< core's schema row (help, SI unit, range)
  std::function<double(const engine::EngineCase&)> get;  ///< SI
  std::function<void(engine::EngineCase&, double)> set;  ///< SI
  /// Throws filmdyn::InputError (core's helpers) when the SI value is not allowed.
  std::function<void(const std::string& field, double si_value)> check;
};

/// Every scalar parameter (numbers, integers, choices), in editor order.
const std::vector<CaseParameter>& CaseParameters();
/// The parameter with this dotted path, or nullptr.
const CaseParameter* FindCaseParameter(const std::string& path);

/// The run models (Skirt-LBRBE, Only-Skirt, Only-LBRBE, Ideal; docs/case-file.md) and how they
/// set the two joints.
struct RunModel {
  QString key;    ///< CLI spelling: "ideal", "only-skirt", "only-lbrbe", "skirt-lbrbe"
  QString title;  ///< "Ideal", "Only-Skirt", ...
  engine::JointModel skirt;
  engine::JointModel big_end;
};
const std::vector<RunModel>& RunModels();
/// The model key for the case's joint settings.
QString RunModelKey(const engine::EngineCase& engine_case);
void ApplyRunModel(engine::EngineCase& engine_case, const QString& key);
/// Whether the run-model selector sets this schema field (a choice that differs between the run
/// models: the joints' models); such a field has no row of its own.
bool SetByRunModel(const engine::CaseField& field);

}  // namespace filmdyn::ui
