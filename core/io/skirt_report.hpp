#pragma once
/// @file The outputs of the steady skirt calculator (`filmdyn skirt`, the GUI's skirt
/// calculator): one list of quantities — key, unit, words, value — from which the JSON object,
/// the text table, the map's CSV columns and the GUI's result table are all made. Keys and signs
/// in docs/skirt-calculator.md.
#include <filesystem>
#include <functional>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "core/lubrication/skirt_calculator.hpp"

namespace filmdyn::io {

/// One reported quantity of a skirt point.
struct SkirtQuantity {
  std::string key;          ///< JSON key and CSV column stem, e.g. "normal_force"
  std::string unit;         ///< SI unit as in results.csv headers, e.g. "N", "N*m", "-"
  std::string label;        ///< short name for axes and table headers, e.g. "Normal force"
  std::string description;  ///< words for the text table and the GUI
  std::function<double(const lubrication::SkirtPoint&)> value;
  /// Display: scale from SI and its unit (e.g. 1e6 and "µm" for a film thickness).
  double display_scale = 1.0;
  std::string display_unit;
};

/// Every quantity, in report order (state first, then forces, moments, film).
const std::vector<SkirtQuantity>& SkirtQuantities();

/// The point as one JSON object: every quantity by key (SI) plus "units" (key → unit).
nlohmann::json SkirtPointJson(const lubrication::SkirtPoint& point);

/// The point as a readable table in display units, one quantity per line.
std::string SkirtPointTable(const lubrication::SkirtPoint& point);

/// The map's CSV: a header "key[unit]" per quantity, one row per point, SI, full precision.
std::string SkirtMapCsv(const std::vector<lubrication::SkirtPoint>& points);

/// The film fields of the solver's last solve as a one-frame field series
/// (`<folder>/skirt.h5` + `skirt.xdmf`, the layout of a run's fields/, crank angle 0).
void WriteSkirtFields(const std::filesystem::path& folder, const lubrication::SkirtSolver& skirt);

}  // namespace filmdyn::io
