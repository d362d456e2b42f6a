#include "ui/case_editor/case_validation.hpp"

#include <cmath>
#include <numbers>

#include "core/engine/pressure_curve.hpp"
#include "core/base/input_error.hpp"
#include "core/io/case_file.hpp"
#include "ui/case_editor/case_parameters.hpp"

namespace filmdyn::ui {

namespace {

std::string PressureCurveKey(size_t index) {
  return "pressure_curves[" + std::to_string(index) + "]";
}

}  // namespace

CaseIssues ValidateCase(const engine::EngineCase& c) {
  CaseIssues issues;
  for (const CaseParameter& p : CaseParameters()) {
    try {
      p.check(p.path, p.get(c));
    } catch (const InputError& e) {
      issues[p.path] = e.what();
    }
  }
  // Cross-field rules.
  const double clearance = c.big_end.bearing_radius - c.big_end.journal_radius;
  if (!issues.count("big_end.journal_radius") && !issues.count("big_end.bearing_radius") &&
      !(clearance > 0)) {
    issues["big_end.journal_radius"] =
        InputError("big_end.journal_radius", FormatValue(c.big_end.journal_radius),
                   "must be < big_end.bearing_radius = " + FormatValue(c.big_end.bearing_radius) +
                       " [m] (radial clearance R_b - R_j > 0)")
            .what();
  }
  if (!issues.count("skirt.piston_radius") && !issues.count("geometry.liner_radius") &&
      !(c.skirt.piston_radius < c.geometry.liner_radius)) {
    issues["skirt.piston_radius"] =
        InputError("skirt.piston_radius", FormatValue(c.skirt.piston_radius),
                   "must be < geometry.liner_radius = " + FormatValue(c.geometry.liner_radius) +
                       " [m] (skirt clearance > 0)")
            .what();
  }
  if (!issues.count("geometry.rod_length") && !issues.count("geometry.crank_radius") &&
      !(c.geometry.rod_length > c.geometry.crank_radius)) {
    issues["geometry.rod_length"] =
        InputError("geometry.rod_length", FormatValue(c.geometry.rod_length),
                   "must be > geometry.crank_radius [m]")
            .what();
  }
  if (c.skirt.thrust_half_width + c.skirt.anti_thrust_half_width > std::numbers::pi) {
    issues["skirt.anti_thrust_half_width"] =
        InputError("skirt.anti_thrust_half_width", FormatValue(c.skirt.anti_thrust_half_width),
                   "alpha_1 + alpha_2 must be <= pi [rad]")
            .what();
  }
  // Skirt profile: positions strictly increasing within [0, L_skirt], drops finite.
  const auto& y = c.skirt.profile_y;
  const auto& h = c.skirt.profile_h;
  try {
    if (y.size() != h.size() || y.size() < 2) {
      throw InputError("skirt.profile", std::to_string(y.size()) + " rows",
                       "needs at least 2 rows of (y, h)");
    }
    for (size_t i = 0; i < y.size(); ++i) {
      const std::string row = "skirt.profile[" + std::to_string(i) + "]";
      RequireInRange(row + ".y", y[i], 0.0, c.skirt.length * (1 + 1e-9), false, false, "m");
      RequireFinite(row + ".h", h[i], "m");
      if (i > 0 && !(y[i] > y[i - 1])) {
        throw InputError(row + ".y", FormatValue(y[i]), "must be > the previous row's y [m]");
      }
    }
  } catch (const InputError& e) {
    issues["skirt.profile"] = e.what();
  }
  // Skirt ovality: none, or angles strictly increasing within [0, π], gaps finite and ≥ 0.
  const auto& alpha = c.skirt.ovality_alpha;
  const auto& gap = c.skirt.ovality_h;
  try {
    if (alpha.size() != gap.size()) {
      throw InputError("skirt.ovality", std::to_string(alpha.size()) + " angles",
                       "needs one gap per angle (" + std::to_string(gap.size()) + " gaps)");
    }
    for (size_t i = 0; i < alpha.size(); ++i) {
      const std::string row = "skirt.ovality[" + std::to_string(i) + "]";
      RequireInRange(row + ".alpha", alpha[i], 0.0, std::numbers::pi, false, false, "rad");
      RequireNonNegative(row + ".h", gap[i], "m");
      if (i > 0 && !(alpha[i] > alpha[i - 1])) {
        throw InputError(row + ".alpha", FormatValue(alpha[i]),
                         "must be > the previous row's alpha [rad]");
      }
    }
  } catch (const InputError& e) {
    issues["skirt.ovality"] = e.what();
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
  // Core's own reader checks everything once more (its ranges win where they are stricter).
  if (issues.empty()) {
    try {
      io::CaseFromJson(io::CaseToJson(c));
    } catch (const InputError& e) {
      std::string key = e.field();
      if (key.rfind("pressure_curves", 0) == 0) {
        // "pressure_curves.2.pressure" or "pressure_curves[2]..." → the table key.
        const size_t digit = key.find_first_of("0123456789");
        const size_t end = key.find_first_not_of("0123456789", digit);
        if (digit != std::string::npos)
          key = "pressure_curves[" + key.substr(digit, end - digit) + "]";
      } else if (key.rfind("skirt.profile", 0) == 0) {
        key = "skirt.profile";
      } else if (key.rfind("skirt.ovality", 0) == 0) {
        key = "skirt.ovality";
      }
      issues[key] = e.what();
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
