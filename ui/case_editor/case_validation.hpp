#pragma once
/// @file Validation of a whole EngineCase for the editor: every problem with the dotted path of the
/// offending value and core's InputError message. Per-cell checks use core's Require* helpers and
/// core's PressureCurve constructor (every bad cell at once); then core's case reader
/// (io::CaseFromJson) checks the whole case, so the GUI never accepts what `filmdyn run` refuses.
#include <map>
#include <string>

#include "core/engine/engine_case.hpp"

namespace filmdyn::ui {

/// Dotted path (as in case_parameters / the case file) → reason. Paths of tables use the table
/// key: "skirt.profile" and "pressure_curves[i]" (i = index in engine_case.pressure_curves).
using CaseIssues = std::map<std::string, std::string>;

CaseIssues ValidateCase(const engine::EngineCase& engine_case);

/// Why the case cannot run (first issue, or "no pressure curve ..."), empty when it can.
std::string RunBlocker(const engine::EngineCase& engine_case, const CaseIssues& issues);

}  // namespace filmdyn::ui
