#include "core/io/skirt_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "core/base/angles.hpp"
#include "core/io/field_output.hpp"
#include "core/io/field_series.hpp"

namespace filmdyn::io {

using lubrication::SkirtPoint;

const std::vector<SkirtQuantity>& SkirtQuantities() {
  static const std::vector<SkirtQuantity> quantities = {
      {"e0", "m", "e0", "lateral displacement e0 (+ toward thrust)",
       [](const SkirtPoint& p) { return p.state.e0; }, 1e6, "µm"},
      {"tilt", "rad", "Tilt", "tilt (+ skirt bottom toward thrust)",
       [](const SkirtPoint& p) { return p.state.gamma; }, 1e3, "mrad"},
      {"e0_rate", "m/s", "de0/dt", "lateral velocity de0/dt",
       [](const SkirtPoint& p) { return p.state.e0_dot; }, 1e3, "mm/s"},
      {"tilt_rate", "rad/s", "Tilt rate", "tilt rate",
       [](const SkirtPoint& p) { return p.state.gamma_dot; }, 1.0, "rad/s"},
      {"speed", "m/s", "Speed", "piston speed along the skirt axis (+ toward the crank)",
       [](const SkirtPoint& p) { return p.state.piston_velocity; }, 1.0, "m/s"},
      {"normal_force", "N", "Normal force",
       "normal force on the piston, film + contact (+ toward thrust)",
       [](const SkirtPoint& p) { return p.film.lateral_force; }, 1.0, "N"},
      {"contact_force", "N", "Contact force", "  of which asperity contact",
       [](const SkirtPoint& p) { return p.film.contact_lateral_force; }, 1.0, "N"},
      {"moment_about_pin", "N*m", "Moment about the pin",
       "moment about the pin (+ turns the skirt bottom to thrust)",
       [](const SkirtPoint& p) { return p.film.moment_about_pin; }, 1.0, "N·m"},
      {"normal_moment", "N*m", "Normal moment", "  of which film pressure and asperity contact",
       [](const SkirtPoint& p) { return p.normal_moment; }, 1.0, "N·m"},
      {"friction_moment", "N*m", "Friction moment", "  of which friction",
       [](const SkirtPoint& p) { return p.film.friction_moment_about_pin; }, 1.0, "N·m"},
      {"friction_force", "N", "Friction force", "friction force on the piston (+ toward the crank)",
       [](const SkirtPoint& p) { return p.film.friction_force; }, 1.0, "N"},
      {"contact_friction_force", "N", "Contact friction", "  of which asperity contact",
       [](const SkirtPoint& p) { return p.film.contact_friction_force; }, 1.0, "N"},
      {"friction_power_loss", "W", "Friction power", "friction power loss",
       [](const SkirtPoint& p) { return p.film.friction_power_loss; }, 1.0, "W"},
      {"max_pressure", "Pa", "Peak film pressure", "largest film pressure",
       [](const SkirtPoint& p) { return p.film.max_pressure; }, 1e-6, "MPa"},
      {"max_contact_pressure", "Pa", "Peak contact pressure", "largest asperity contact pressure",
       [](const SkirtPoint& p) { return p.film.max_contact_pressure; }, 1e-6, "MPa"},
      {"moft", "m", "MOFT", "minimum oil film thickness (MOFT)",
       [](const SkirtPoint& p) { return p.film.moft; }, 1e6, "µm"},
      {"moft_alpha", "rad", "MOFT angle", "  where: angle from the thrust side",
       [](const SkirtPoint& p) { return p.film.moft_alpha; }, kDegreesPerRadian, "°"},
      {"moft_y", "m", "MOFT depth", "  where: distance below the skirt top",
       [](const SkirtPoint& p) { return p.film.moft_y; }, 1e3, "mm"},
      {"cavitated_fraction", "-", "Cavitated fraction", "cavitated fraction of the skirt panels",
       [](const SkirtPoint& p) { return p.film.cavitated_fraction; }, 1.0, "-"},
      {"wetted_fraction", "-", "Wetted fraction",
       "oil-covered (wetted) fraction of the skirt panels",
       [](const SkirtPoint& p) { return p.film.wetted_fraction; }, 1.0, "-"}};
  return quantities;
}

nlohmann::json SkirtPointJson(const SkirtPoint& point) {
  nlohmann::json j = nlohmann::json::object();
  nlohmann::json units = nlohmann::json::object();
  for (const SkirtQuantity& q : SkirtQuantities()) {
    j[q.key] = q.value(point);
    units[q.key] = q.unit;
  }
  j["units"] = units;
  return j;
}

std::string SkirtPointTable(const SkirtPoint& point) {
  std::string text;
  for (const SkirtQuantity& q : SkirtQuantities()) {
    text += fmt::format("{:<64} {:>12.6g}\n", q.description + " [" + q.display_unit + "]",
                        q.value(point) * q.display_scale);
  }
  return text;
}

std::string SkirtMapCsv(const std::vector<SkirtPoint>& points) {
  std::string csv;
  const auto& quantities = SkirtQuantities();
  for (std::size_t i = 0; i < quantities.size(); ++i) {
    csv += (i ? "," : "") + quantities[i].key + "[" + quantities[i].unit + "]";
  }
  csv += "\n";
  for (const SkirtPoint& p : points) {
    for (std::size_t i = 0; i < quantities.size(); ++i) {
      csv += fmt::format("{}{:.17g}", i ? "," : "", quantities[i].value(p));
    }
    csv += "\n";
  }
  return csv;
}

void WriteSkirtFields(const std::filesystem::path& folder, const lubrication::SkirtSolver& skirt) {
  const SurfaceField surface = FieldRecorder::SkirtSurface(skirt);
  FieldSeries series;
  series.name = "skirt";
  series.points = surface.points;
  series.triangles = surface.triangles;
  SeriesFrame frame;
  for (const auto& [name, values] : surface.point_data) {
    series.array_names.push_back(name);
    frame.arrays.emplace_back(values.begin(), values.end());
  }
  series.frames.push_back(std::move(frame));
  WriteFieldSeries(folder, series);
}

}  // namespace filmdyn::io
