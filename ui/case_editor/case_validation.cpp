#include "ui/case_editor/case_validation.hpp"

#include <cmath>
#include <numbers>

#include "core/base/input_error.hpp"
#include "core/engine/case_schema.hpp"
#include "core/engine/pressure_curve.hpp"
#include "core/io/case_file.hpp"
#include "ui/case_editor/case_parameters.hpp"

namespace filmdyn::ui {

namespace {

std::string PressureCurveKey(size_t index) {
  return "pressure_curves[" + std::to_string(index) + "]";
}

// The editor's key of a core field path: tables are one key each (a list table's key, e.g.
// "skirt.profile_y" for skirt.profile_h.3 too; "pressure_curves[i]"), every other field its own
// path.
std::string EditorKey(std::string key) {
  if (key.rfind("pressure_curves", 0) == 0) {
    // "pressure_curves.2.pressure" → "pressure_curves[2]".
    const size_t digit = key.find_first_of("0123456789");
    const size_t end = key.find_first_not_of("0123456789", digit);
    if (digit != std::string::npos)
      return PressureCurveKey(std::stoul(key.substr(digit, end - digit)));
  } else if (const CaseListTable* table = FindCaseListTable(key)) {
    return table->key;
  }
  return key;
}

}  // namespace

CaseIssues ValidateCase(const engine::EngineCase& c) {
  CaseIssues issues;
  // Every field against its own range: core's schema.
  engine::EngineCase copy = c;
  for (const engine::CaseField& field : engine::CaseSchema()) {
    try {
      if (field.kind == engine::FieldKind::kNumber || field.kind == engine::FieldKind::kInteger) {
        field.Check(field.get(c));
      } else if (field.kind == engine::FieldKind::kChoice) {
        const int k = field.choice(c);
        if (k < 0 || k >= int(field.choices.size())) {
          throw InputError(field.path, std::to_string(k), "must be " + field.ChoicesText(true));
        }
      } else if (field.kind == engine::FieldKind::kNumberList) {
        const std::vector<double>& values = field.list(copy);
        for (size_t k = 0; k < values.size(); ++k) {
          field.Check(values[k], field.path + "." + std::to_string(k));
        }
      }
    } catch (const InputError& e) {
      issues.emplace(EditorKey(field.path), e.what());
    }
  }
  // The rules that tie fields together: core's one function.
  try {
    engine::CheckCaseConsistency(c);
  } catch (const InputError& e) {
    issues.emplace(EditorKey(e.field()), e.what());
  }
  // Pressure curves: core's own checks (PressureCurve constructor), one speed once.
  for (size_t i = 0; i < c.pressure_curves.size(); ++i) {
    const auto& curve = c.pressure_curves[i];
    const std::string key = PressureCurveKey(i);
    try {
      RequirePositive(key + ".rpm", curve.rpm, "rpm");
      for (size_t j = 0; j < i; ++j) {
        if (c.pressure_curves[j].rpm == curve.rpm) {
          throw InputError(key + ".rpm", FormatValue(curve.rpm), "a curve for this speed exists");
        }
      }
      if (curve.file.empty()) {
        std::vector<double> angles;
        angles.reserve(curve.crank_angle_deg.size());
        for (double a : curve.crank_angle_deg) angles.push_back(a * std::numbers::pi / 180.0);
        engine::PressureCurve checked(angles, curve.pressure, key);
      }
    } catch (const InputError& e) {
      issues[key] = e.what();
    }
  }
  // Core's own reader checks everything once more (the case file's rules as a whole).
  if (issues.empty()) {
    try {
      io::CaseFromJson(io::CaseToJson(c));
    } catch (const InputError& e) {
      issues[EditorKey(e.field())] = e.what();
    } catch (const std::exception& e) {
      issues["case"] = e.what();
    }
  }
  return issues;
}

std::string RunBlocker(const engine::EngineCase& c, const CaseIssues& issues) {
  if (!issues.empty()) return issues.begin()->second;
  if (c.pressure_curves.empty()) {
    return "no cylinder-pressure curve: add or import one on the Pressure tab";
  }
  return {};
}

}  // namespace filmdyn::ui
