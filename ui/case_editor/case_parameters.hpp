#pragma once
/// @file The inputs of an EngineCase as the editor shows them: one row per number, integer or
/// choice of core's case schema (core/engine/case_schema.hpp) with its dotted path, label,
/// display unit, factor to SI, help and check, and one table per number list or pair of lists
/// (CaseListTable). Nothing is retyped here: a field added to the schema appears in the editor
/// with core's range or core's choices. The joints' models are the one exception: the run-model
/// selector sets them (RunModels below), not a row.
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
  /// A name of a file the case refers to (FieldKind::kText, e.g. a compliance file), edited as
  /// text: the value is field->text, the unit empty, and get, set and check are empty.
  bool text = false;
  const engine::CaseField* field = nullptr;  ///< core's schema row (help, SI unit, range)
  std::function<double(const engine::EngineCase&)> get;  ///< SI
  std::function<void(engine::EngineCase&, double)> set;  ///< SI
  /// Throws filmdyn::InputError (core's helpers) when the SI value is not allowed.
  std::function<void(const std::string& field, double si_value)> check;
};

/// Every scalar parameter (numbers, integers, choices, the joints' file names), in editor order.
const std::vector<CaseParameter>& CaseParameters();
/// The parameter with this dotted path, or nullptr.
const CaseParameter* FindCaseParameter(const std::string& path);

/// A table of the editor over the schema's number lists that go together: the lists of one group
/// that core names by one symbol (CaseField::symbol, e.g. "skirt profile" for skirt.profile_y and
/// skirt.profile_h) are the columns, in schema order, one row per index; a list with a symbol of
/// its own is a table of one column. No rows in every column means none (core's default: a round
/// skirt, a constant pressure or film). Core's complaints about any column are the table's issue.
struct CaseListTable {
  CaseGroup group;
  /// Its key in the editor's issues (CaseIssues): the first column's path.
  std::string key;
  /// The part of the columns' labels before ": " ("Skirt profile", "Supply holes").
  QString title;
  std::vector<const engine::CaseField*> columns;
};

/// Every list table, in schema order.
const std::vector<CaseListTable>& CaseListTables();
/// The table with a column at this path, or holding the element a core field name points at
/// ("skirt.profile_y.2", "big_end.supply_pressure_values[3].crank_angle"); nullptr for any other
/// field.
const CaseListTable* FindCaseListTable(const std::string& field);
/// A column's header: its label after the table's title, and the display unit
/// ("axial position y [mm]").
QString CaseListColumnTitle(const engine::CaseField& field);
/// Why a run of `c` does not read the list table, from the choice that decides it as core's film
/// joints and checks do (CheckBigEndSupply, CheckSkirtSupply): the supply holes only for
/// "shell_holes" or "pin_holes", a supply-pressure curve only with holes or a groove, the liner's
/// oil film only for a "starved" skirt. Empty when the table is used. A supply-pressure curve with
/// rows under "line_of_centres" counts as used: core refuses it, so its table stays editable.
QString ListUnusedReason(const CaseListTable& table, const engine::EngineCase& c);

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
