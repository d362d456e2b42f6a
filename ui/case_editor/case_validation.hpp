#pragma once
/// @file Validation of a whole EngineCase for the editor: every problem with the dotted path of the
/// offending value and core's InputError message. Each field is checked against its range (a
/// choice: its names) in core's case schema, then core's cross-field rules
/// (engine::CheckCaseConsistency) and core's PressureCurve constructor run, and finally core's case
/// reader (io::CaseFromJson) checks the whole case: the GUI accepts exactly what `filmdyn run`
/// accepts.
#include <map>
#include <string>

#include "core/base/input_error.hpp"
#include "core/engine/engine_case.hpp"

namespace filmdyn::ui {

/// Dotted path (as in case_parameters / the case file) → reason. Paths of tables use the table
/// key: a list table's (CaseListTable::key, e.g. "skirt.profile_y" for the whole profile) and
/// "pressure_curves[i]" (i = index in engine_case.pressure_curves).
using CaseIssues = std::map<std::string, std::string>;

CaseIssues ValidateCase(const engine::EngineCase& engine_case);

/// Core's message for a case field as the editor shows the field: its value and every
/// "<number> [<SI unit>]" quantity of the rule in the field's display unit, e.g.
/// "big_end.journal_radius = 15.2 mm: must be smaller than big_end.bearing_radius = 15 mm"
/// (core says 0.0152 and 0.015 [m]). Other messages as they are.
std::string InDisplayUnits(const InputError& error);

/// Why the case cannot run (first issue, or "no pressure curve ..."), empty when it can.
std::string RunBlocker(const engine::EngineCase& engine_case, const CaseIssues& issues);

}  // namespace filmdyn::ui
