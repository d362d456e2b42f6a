#include "core/engine/case_diff.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/engine/case_schema.hpp"

namespace filmdyn::engine {

namespace {

// Significant digits a value is shown with at most (trailing zeros dropped: 14.97 mm, 10 mPa·s),
// unless two values need more to tell them apart.
constexpr int kDigits = 6;

// The display unit as text follows a value: none for dimensionless quantities.
std::string UnitSuffix(const std::string& display_unit) {
  if (display_unit.empty() || display_unit == "–" || display_unit == "-") return {};
  return " " + display_unit;
}

// The two values in display units with kDigits significant digits, more when they need them to
// differ; integers whole.
std::pair<std::string, std::string> DisplayPair(const CaseField& field, double a, double b) {
  const std::string unit = UnitSuffix(field.display_unit);
  if (field.kind == FieldKind::kInteger) {
    return {fmt::format("{}{}", std::llround(a), unit), fmt::format("{}{}", std::llround(b), unit)};
  }
  const double da = field.ToDisplay(a), db = field.ToDisplay(b);
  std::string ta, tb;
  for (int digits = kDigits; digits <= 17; ++digits) {
    ta = FormatSignificant(da, digits);
    tb = FormatSignificant(db, digits);
    if (ta != tb) break;
  }
  return {ta + unit, tb + unit};
}

std::string Phrase(const std::string& label, const std::string& value) {
  return label.empty() ? value : label + " " + value;
}

// A table's group path: "skirt.profile_y" → "skirt.profile".
std::string GroupPath(const std::string& path) { return path.substr(0, path.rfind('_')); }

std::string PointCount(std::size_t n) { return fmt::format("{} point{}", n, n == 1 ? "" : "s"); }

bool SameCurves(const std::vector<PressureCurveSource>& a,
                const std::vector<PressureCurveSource>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (a[k].rpm != b[k].rpm || a[k].file != b[k].file ||
        a[k].crank_angle_deg != b[k].crank_angle_deg || a[k].pressure != b[k].pressure) {
      return false;
    }
  }
  return true;
}

}  // namespace

std::string FormatSignificant(double value, int digits) {
  if (!std::isfinite(value)) return fmt::format("{}", value);
  if (value == 0.0) return "0";
  const int exponent = int(std::floor(std::log10(std::abs(value))));
  if (exponent < -4 || exponent >= 9) return fmt::format("{:.{}g}", value, digits);
  std::string text = fmt::format("{:.{}f}", value, std::max(0, digits - 1 - exponent));
  if (text.find('.') != std::string::npos) {
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') text.pop_back();
  }
  return text == "-0" ? "0" : text;
}

std::string ModelTitle(const std::string& model_key) {
  if (model_key == "ideal") return "Ideal";
  if (model_key == "only-skirt") return "Only-Skirt";
  if (model_key == "only-lbrbe") return "Only-LBRBE";
  if (model_key == "skirt-lbrbe") return "Skirt-LBRBE";
  return model_key;
}

std::vector<CaseDifference> DiffRunInputs(const RunInputs& a, const RunInputs& b) {
  std::vector<CaseDifference> out;
  const bool models_given = !a.model.empty() || !b.model.empty();
  if (models_given && a.model != b.model) {
    const std::string ta = ModelTitle(a.model), tb = ModelTitle(b.model);
    out.push_back({"model", "model", ta, tb, Phrase("model", tb)});
  }
  // The schema's accessors take a mutable case; these copies are only read. The run's speed
  // stands in for the case's.
  EngineCase ca = a.engine_case, cb = b.engine_case;
  if (a.rpm > 0) ca.operating.rpm = a.rpm;
  if (b.rpm > 0) cb.operating.rpm = b.rpm;
  std::vector<std::string> tables_done;
  for (const CaseField& field : CaseSchema()) {
    switch (field.kind) {
      case FieldKind::kNumber:
      case FieldKind::kInteger: {
        if (field.SameValue(ca, cb)) break;
        const double va = field.get(ca), vb = field.get(cb);
        auto [ta, tb] = DisplayPair(field, va, vb);
        out.push_back({field.path, field.symbol, ta, tb, Phrase(field.symbol, tb)});
        break;
      }
      case FieldKind::kText: {
        if (field.SameValue(ca, cb)) break;
        const std::string& ta = field.text(ca);
        const std::string& tb = field.text(cb);
        // Free text can be long: the label says it changed, the values hold it.
        const bool short_text = tb.size() <= 24 && tb.find('\n') == std::string::npos;
        out.push_back({field.path, field.symbol, ta, tb,
                       short_text && !tb.empty() ? Phrase(field.symbol, "“" + tb + "”")
                                                 : field.symbol + " changed"});
        break;
      }
      case FieldKind::kChoice: {
        // The joint models are said by the run model's name when one is given.
        const bool joint_model = field.path == "skirt.model" || field.path == "big_end.model";
        if (models_given && joint_model) break;
        if (field.SameValue(ca, cb)) break;
        const std::string& nb = field.ChoiceName(cb);
        out.push_back(
            {field.path, field.symbol, field.ChoiceName(ca), nb, Phrase(field.symbol, nb)});
        break;
      }
      case FieldKind::kNumberList: {
        // The lists of one table (profile y and h) are one difference: "skirt profile changed".
        const std::string group = GroupPath(field.path);
        if (std::find(tables_done.begin(), tables_done.end(), group) != tables_done.end()) break;
        bool differs = false;
        std::size_t na = 0, nb = 0;
        for (const CaseField& member : CaseSchema()) {
          if (member.kind != FieldKind::kNumberList || GroupPath(member.path) != group) continue;
          const std::vector<double>& la = member.list(ca);
          const std::vector<double>& lb = member.list(cb);
          differs = differs || !member.SameValue(ca, cb);
          na = std::max(na, la.size());
          nb = std::max(nb, lb.size());
        }
        if (!differs) break;
        tables_done.push_back(group);
        out.push_back(
            {group, field.symbol, PointCount(na), PointCount(nb), field.symbol + " changed"});
        break;
      }
    }
  }
  if (!SameCurves(a.engine_case.pressure_curves, b.engine_case.pressure_curves)) {
    out.push_back({"pressure_curves", "cylinder pressure",
                   fmt::format("{} curve{}", a.engine_case.pressure_curves.size(),
                               a.engine_case.pressure_curves.size() == 1 ? "" : "s"),
                   fmt::format("{} curve{}", b.engine_case.pressure_curves.size(),
                               b.engine_case.pressure_curves.size() == 1 ? "" : "s"),
                   "cylinder pressure changed"});
  }
  return out;
}

std::string FormatDifferences(const std::vector<CaseDifference>& differences,
                              std::string_view separator) {
  std::string text;
  for (const CaseDifference& d : differences) {
    if (!text.empty()) text += separator;
    text += d.text;
  }
  return text;
}

}  // namespace filmdyn::engine
