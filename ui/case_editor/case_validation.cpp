#include "ui/case_editor/case_validation.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <regex>

#include "core/base/angles.hpp"
#include "core/base/input_error.hpp"
#include "core/engine/case_schema.hpp"
#include "core/engine/pressure_curve.hpp"
#include "core/io/case_file.hpp"
#include "ui/case_editor/case_parameters.hpp"
#include "ui/case_editor/field_tooltip.hpp"

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

// The field an error names: its own path, or a list's for an element ("x.3").
const engine::CaseField* FieldOf(const std::string& name) {
  if (const engine::CaseField* f = engine::FindCaseField(name)) return f;
  const size_t dot = name.find_last_of('.');
  if (dot != std::string::npos &&
      name.find_first_not_of("0123456789", dot + 1) == std::string::npos)
    return engine::FindCaseField(name.substr(0, dot));
  return nullptr;
}

}  // namespace

std::string InDisplayUnits(const InputError& e) {
  const engine::CaseField* f = FieldOf(e.field());
  if (f == nullptr || f->display_unit.empty() || f->display_unit == f->unit ||
      (f->display_scale == 1.0 && f->display_offset == 0.0))
    return e.what();
  double si = 0.0;
  if (!ParseNumber(e.value(), si) || !std::isfinite(si)) return e.what();
  auto six = [f](double number) { return fmt::format("{:.6g}", f->ToDisplay(number)); };
  // A rule's number (six digits); an interval's closed end as the tooltip shows it (typed back,
  // allowed).
  auto shown = [&six](const std::string& number) {
    double v = 0.0;
    return ParseNumber(number, v) ? six(v) : number;
  };
  auto closed_end = [f, &shown](const std::string& number) {
    double v = 0.0;
    return ParseNumber(number, v) ? DisplayTypable(v, *f).toStdString() : shown(number);
  };
  // The refused value: six digits, or every digit where those would read as allowed.
  const std::string value = DisplayOnItsSide(si, *f, six(si)) + " " + f->display_unit;
  // Every quantity "<number> [<SI unit>]" of the rule, and an interval's two ends before it
  // (not for a unit with a shifted zero: a rule's temperature may be a difference).
  const std::string allowed = e.allowed();
  if (f->display_offset != 0.0) return e.field() + " = " + value + ": " + allowed;
  const std::string unit =
      std::regex_replace(f->unit, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)");
  const std::string number = R"(([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?))";
  const std::regex interval(R"(([\(\[])\s*)" + number + R"(,\s*)" + number + R"(\s*([\)\]])\s*\[)" +
                            unit + R"(\])");
  const std::regex single(number + R"(\s*\[)" + unit + R"(\])");
  std::string out;
  std::smatch m;
  std::string rest = allowed;
  while (std::regex_search(rest, m, interval)) {
    out += m.prefix().str() + m[1].str() +
           (m[1].str() == "[" ? closed_end(m[2].str()) : shown(m[2].str())) + ", " +
           (m[4].str() == "]" ? closed_end(m[3].str()) : shown(m[3].str())) + m[4].str() + " " +
           f->display_unit;
    rest = m.suffix().str();
  }
  rest = out + rest;
  out.clear();
  while (std::regex_search(rest, m, single)) {
    out += m.prefix().str() + shown(m[1].str()) + " " + f->display_unit;
    rest = m.suffix().str();
  }
  out += rest;
  return e.field() + " = " + value + ": " + out;
}

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
      issues.emplace(EditorKey(field.path), InDisplayUnits(e));
    }
  }
  // The rules that tie fields together: core's one function.
  try {
    engine::CheckCaseConsistency(c);
  } catch (const InputError& e) {
    issues.emplace(EditorKey(e.field()), InDisplayUnits(e));
  }
  // Pressure curves: core's own checks (PressureCurve constructor), one speed once.
  for (size_t i = 0; i < c.pressure_curves.size(); ++i) {
    const auto& curve = c.pressure_curves[i];
    const std::string key = PressureCurveKey(i);
    try {
      RequirePositive(key + ".rpm", curve.rpm, "rpm");
      if (curve.file.empty()) {
        std::vector<double> angles;
        angles.reserve(curve.crank_angle_deg.size());
        for (double a : curve.crank_angle_deg) angles.push_back(a * kRadiansPerDegree);
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
      issues[EditorKey(e.field())] = InDisplayUnits(e);
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
