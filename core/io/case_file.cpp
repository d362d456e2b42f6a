#include "core/io/case_file.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <numbers>
#include <set>
#include <sstream>

#include "core/base/input_error.hpp"
#include "core/io/pressure_csv.hpp"
#include "core/io/resources.hpp"

namespace filmdyn::io {

using engine::EngineCase;
using engine::JointModel;
using nlohmann::json;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Allowed range of a number: lo < x (or ≤), x ≤ hi.
struct Range {
  double lo = -kInf, hi = kInf;
  bool lo_open = false;
  const char* unit = "";
  bool hi_open = false;
};
Range Positive(const char* unit) { return {0.0, kInf, true, unit}; }
Range NonNegative(const char* unit) { return {0.0, kInf, false, unit}; }
Range Between(double lo, double hi, const char* unit) { return {lo, hi, false, unit}; }
// Elastic constants of one surface (E' = 2/[(1−ν₁²)/E₁ + (1−ν₂²)/E₂] needs E > 0 and ν in
// (−1, 0.5)).
Range YoungsModulus() { return {0.0, 1e13, true, "Pa"}; }
Range PoissonRatio() { return {-1.0, 0.5, true, "-", true}; }

void Check(const std::string& path, double value, const Range& r) {
  if (r.lo == -kInf && r.hi == kInf) {
    RequireFinite(path, value, r.unit);
  } else if (r.hi == kInf && r.lo == 0.0) {
    r.lo_open ? RequirePositive(path, value, r.unit) : RequireNonNegative(path, value, r.unit);
  } else {
    RequireInRange(path, value, r.lo, r.hi, r.lo_open, r.hi_open, r.unit);
  }
}

/// The one list of case fields (everything but the pressure curves and the notes).
template <class V>
void VisitCase(V& v, EngineCase& c) {
  v.Text("name", c.name);
  v.Text("description", c.description);
  auto& g = c.geometry;
  v.Number("geometry.crank_radius", g.crank_radius, Positive("m"));
  v.Number("geometry.rod_length", g.rod_length, Positive("m"));
  v.Number("geometry.crank_com_radius", g.crank_com_radius, NonNegative("m"));
  v.Number("geometry.crank_mass", g.crank_mass, Positive("kg"));
  v.Number("geometry.crank_inertia", g.crank_inertia, Positive("kg*m^2"));
  v.Number("geometry.rod_com_from_big_end", g.rod_com_from_big_end, NonNegative("m"));
  v.Number("geometry.rod_mass", g.rod_mass, Positive("kg"));
  v.Number("geometry.rod_inertia", g.rod_inertia, Positive("kg*m^2"));
  v.Number("geometry.piston_mass", g.piston_mass, Positive("kg"));
  v.Number("geometry.piston_inertia", g.piston_inertia, Positive("kg*m^2"));
  v.Number("geometry.pin_offset", g.pin_offset, Between(-0.01, 0.01, "m"));
  v.Number("geometry.piston_com_lateral_offset", g.piston_com_lateral_offset,
           Between(-0.01, 0.01, "m"));
  v.Number("geometry.skirt_top_to_pin", g.skirt_top_to_pin, Between(-0.2, 0.2, "m"));
  v.Number("geometry.skirt_top_to_com", g.skirt_top_to_com, Between(-0.2, 0.2, "m"));
  v.Number("geometry.liner_radius", g.liner_radius, Positive("m"));
  v.Number("geometry.compression_ratio", g.compression_ratio, Range{1.0, 40.0, true, "-"});
  v.Number("geometry.gravity", g.gravity, Between(0.0, 100.0, "m/s^2"));
  auto& s = c.skirt;
  v.Model("skirt.model", s.model);
  v.Number("skirt.piston_radius", s.piston_radius, Positive("m"));
  v.Number("skirt.length", s.length, Positive("m"));
  v.Number("skirt.thrust_half_width", s.thrust_half_width,
           Range{0.0, std::numbers::pi / 2, true, "rad"});
  v.Number("skirt.anti_thrust_half_width", s.anti_thrust_half_width,
           Range{0.0, std::numbers::pi / 2, true, "rad"});
  v.Number("skirt.roughness_skirt", s.roughness_skirt, Positive("m"));
  v.Number("skirt.roughness_liner", s.roughness_liner, Positive("m"));
  v.Number("skirt.peklenik", s.peklenik, Between(1.0 / 9.0, 9.0, "-"));
  v.Number("skirt.modulus_skirt", s.modulus_skirt, YoungsModulus());
  v.Number("skirt.poisson_skirt", s.poisson_skirt, PoissonRatio());
  v.Number("skirt.modulus_liner", s.modulus_liner, YoungsModulus());
  v.Number("skirt.poisson_liner", s.poisson_liner, PoissonRatio());
  v.Number("skirt.boundary_friction", s.boundary_friction, Between(0.0, 1.0, "-"));
  // FEM mesh (paper Table II defaults 30, 2, 30 circumferential x 40 axial).
  v.Integer("skirt.mesh_thrust", s.mesh_thrust, 2, 2000);
  v.Integer("skirt.mesh_relief", s.mesh_relief, 1, 2000);
  v.Integer("skirt.mesh_anti", s.mesh_anti, 2, 2000);
  v.Integer("skirt.mesh_axial", s.mesh_axial, 2, 2000);
  v.Vector("skirt.profile_y", s.profile_y, NonNegative("m"));
  v.Vector("skirt.profile_h", s.profile_h, NonNegative("m"));
  // Ovality (empty = round skirt); order and sizes are checked in CheckConsistency.
  v.Vector("skirt.ovality_alpha", s.ovality_alpha, Between(0.0, std::numbers::pi, "rad"));
  v.Vector("skirt.ovality_h", s.ovality_h, NonNegative("m"));
  auto& b = c.big_end;
  v.Model("big_end.model", b.model);
  v.Number("big_end.bearing_radius", b.bearing_radius, Positive("m"));
  v.Number("big_end.journal_radius", b.journal_radius, Positive("m"));
  v.Number("big_end.width", b.width, Positive("m"));
  v.Number("big_end.roughness_journal", b.roughness_journal, Positive("m"));
  v.Number("big_end.roughness_bearing", b.roughness_bearing, Positive("m"));
  v.Number("big_end.peklenik", b.peklenik, Between(1.0 / 9.0, 9.0, "-"));
  v.Number("big_end.modulus_journal", b.modulus_journal, YoungsModulus());
  v.Number("big_end.poisson_journal", b.poisson_journal, PoissonRatio());
  v.Number("big_end.modulus_bearing", b.modulus_bearing, YoungsModulus());
  v.Number("big_end.poisson_bearing", b.poisson_bearing, PoissonRatio());
  v.Number("big_end.boundary_friction", b.boundary_friction, Between(0.0, 1.0, "-"));
  // FEM mesh (paper Table II defaults 50 around x 10 across).
  v.Integer("big_end.mesh_theta", b.mesh_theta, 8, 5000);
  v.Integer("big_end.mesh_z", b.mesh_z, 2, 2000);
  v.Number("big_end.oil_feed_pressure", b.oil_feed_pressure, NonNegative("Pa"));
  v.Number("lubricant.viscosity", c.lubricant.viscosity, Positive("Pa*s"));
  v.Number("lubricant.greenwood_tripp_k", c.lubricant.greenwood_tripp_k, Positive("-"));
  v.Number("operating.rpm", c.operating.rpm, Range{0.0, 30000.0, true, "rpm"});
  v.Number("operating.crankcase_pressure", c.operating.crankcase_pressure, NonNegative("Pa"));
  v.Number("operating.start_crank_angle", c.operating.start_crank_angle,
           Between(0.0, 4 * std::numbers::pi, "rad"));
  auto& o = c.solver;
  v.Number("solver.baumgarte_alpha", o.baumgarte_alpha, NonNegative("1/s"));
  v.Number("solver.baumgarte_beta", o.baumgarte_beta, NonNegative("1/s"));
  v.Number("solver.relative_tolerance", o.relative_tolerance, Range{1e-14, 1e-2, false, "-"});
  v.Number("solver.position_tolerance", o.position_tolerance, Range{1e-16, 1e-3, false, "m"});
  v.Number("solver.output_interval", o.output_interval, Range{1e-4, 0.2, false, "rad"});
  v.Number("solver.steady_state_tolerance", o.steady_state_tolerance, Positive("-"));
  v.Integer("solver.max_cycles", o.max_cycles, 1, 10000);
  v.Number("solver.run_in_angle", o.run_in_angle, Between(0.0, 8 * std::numbers::pi, "rad"));
}

const char* ModelName(JointModel m) { return m == JointModel::kIdeal ? "ideal" : "lubricated"; }

const json* Find(const json& root, const std::string& path) {
  const json* node = &root;
  std::size_t start = 0;
  while (true) {
    const auto dot = path.find('.', start);
    const std::string key = path.substr(start, dot - start);
    if (!node->is_object() || !node->contains(key)) return nullptr;
    node = &(*node)[key];
    if (dot == std::string::npos) return node;
    start = dot + 1;
  }
}

std::string Dump(const json& j) { return j.dump(); }

struct Reader {
  const json& root;
  std::set<std::string> seen;
  const json* Get(const std::string& path) {
    seen.insert(path);
    return Find(root, path);
  }
  void Text(const std::string& path, std::string& value) {
    if (const json* j = Get(path)) {
      if (!j->is_string()) throw InputError(path, Dump(*j), "must be a string");
      value = j->get<std::string>();
    }
  }
  double ToNumber(const std::string& path, const json& j) {
    // NaN/inf cannot be written in JSON; accept the strings "nan"/"inf" only to reject them
    // with the usual message.
    if (j.is_number()) return j.get<double>();
    if (j.is_string()) {
      const std::string text = j.get<std::string>();
      if (text == "nan" || text == "NaN") return std::numeric_limits<double>::quiet_NaN();
      if (text == "inf" || text == "-inf") return text[0] == '-' ? -kInf : kInf;
    }
    throw InputError(path, Dump(j), "must be a number");
  }
  void Number(const std::string& path, double& value, const Range& range) {
    if (const json* j = Get(path)) value = ToNumber(path, *j);
    Check(path, value, range);
  }
  void Integer(const std::string& path, int& value, int lo, int hi) {
    if (const json* j = Get(path)) {
      const double x = ToNumber(path, *j);
      if (!std::isfinite(x) || x != std::floor(x) || x < lo || x > hi) {
        throw InputError(
            path, FormatValue(x),
            "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
      }
      value = static_cast<int>(x);
    }
  }
  void Model(const std::string& path, JointModel& value) {
    if (const json* j = Get(path)) {
      const std::string text = j->is_string() ? j->get<std::string>() : Dump(*j);
      if (text == "ideal") {
        value = JointModel::kIdeal;
      } else if (text == "lubricated") {
        value = JointModel::kLubricated;
      } else {
        throw InputError(path, text, "must be \"ideal\" or \"lubricated\"");
      }
    }
  }
  void Vector(const std::string& path, std::vector<double>& value, const Range& range) {
    if (const json* j = Get(path)) {
      if (!j->is_array()) throw InputError(path, Dump(*j), "must be an array of numbers");
      value.clear();
      for (std::size_t k = 0; k < j->size(); ++k) {
        value.push_back(ToNumber(path + "." + std::to_string(k), (*j)[k]));
      }
    }
    for (std::size_t k = 0; k < value.size(); ++k) {
      Check(path + "." + std::to_string(k), value[k], range);
    }
  }
};

struct Writer {
  json root = json::object();
  json& At(const std::string& path) {
    json* node = &root;
    std::size_t start = 0;
    while (true) {
      const auto dot = path.find('.', start);
      node = &(*node)[path.substr(start, dot - start)];
      if (dot == std::string::npos) return *node;
      start = dot + 1;
    }
  }
  void Text(const std::string& path, std::string& value) { At(path) = value; }
  void Number(const std::string& path, double& value, const Range&) { At(path) = value; }
  void Integer(const std::string& path, int& value, int, int) { At(path) = value; }
  void Model(const std::string& path, JointModel& value) { At(path) = ModelName(value); }
  void Vector(const std::string& path, std::vector<double>& value, const Range&) {
    At(path) = value;
  }
};

// Every key path in the JSON (objects only; arrays are leaves).
void LeafPaths(const json& node, const std::string& prefix, std::vector<std::string>* out) {
  for (auto it = node.begin(); it != node.end(); ++it) {
    const std::string path = prefix.empty() ? it.key() : prefix + "." + it.key();
    if (it->is_object() && path != "assumed") {  // "assumed" keys are dotted paths themselves
      LeafPaths(*it, path, out);
    } else {
      out->push_back(path);
    }
  }
}

void CheckConsistency(const EngineCase& c) {
  const auto& g = c.geometry;
  if (g.rod_length <= g.crank_radius + std::abs(g.pin_offset)) {
    throw InputError("geometry.rod_length", FormatValue(g.rod_length),
                     "must exceed geometry.crank_radius + |geometry.pin_offset| = " +
                         FormatValue(g.crank_radius + std::abs(g.pin_offset)) + " [m]");
  }
  if (g.rod_com_from_big_end > g.rod_length) {
    throw InputError("geometry.rod_com_from_big_end", FormatValue(g.rod_com_from_big_end),
                     "must lie on the rod: <= geometry.rod_length [m]");
  }
  if (c.skirt.piston_radius >= g.liner_radius) {
    throw InputError(
        "skirt.piston_radius", FormatValue(c.skirt.piston_radius),
        "must be smaller than geometry.liner_radius = " + FormatValue(g.liner_radius) + " [m]");
  }
  if (c.big_end.journal_radius >= c.big_end.bearing_radius) {
    throw InputError("big_end.journal_radius", FormatValue(c.big_end.journal_radius),
                     "must be smaller than big_end.bearing_radius = " +
                         FormatValue(c.big_end.bearing_radius) + " [m]");
  }
  if (c.skirt.thrust_half_width + c.skirt.anti_thrust_half_width >= std::numbers::pi) {
    throw InputError("skirt.anti_thrust_half_width", FormatValue(c.skirt.anti_thrust_half_width),
                     "thrust + anti-thrust half widths must be < π [rad]");
  }
  if (c.skirt.profile_y.size() != c.skirt.profile_h.size() || c.skirt.profile_y.size() < 2) {
    throw InputError("skirt.profile_h", std::to_string(c.skirt.profile_h.size()) + " values",
                     "needs as many values as skirt.profile_y (at least 2)");
  }
  for (std::size_t k = 1; k < c.skirt.profile_y.size(); ++k) {
    if (c.skirt.profile_y[k] <= c.skirt.profile_y[k - 1]) {
      throw InputError("skirt.profile_y." + std::to_string(k), FormatValue(c.skirt.profile_y[k]),
                       "must increase strictly [m]");
    }
  }
  const auto& alpha = c.skirt.ovality_alpha;
  if (alpha.size() != c.skirt.ovality_h.size()) {
    throw InputError("skirt.ovality_h", std::to_string(c.skirt.ovality_h.size()) + " values",
                     "needs as many values as skirt.ovality_alpha (" +
                         std::to_string(alpha.size()) + "; both empty = no ovality)");
  }
  for (std::size_t k = 1; k < alpha.size(); ++k) {
    if (alpha[k] <= alpha[k - 1]) {
      throw InputError("skirt.ovality_alpha." + std::to_string(k), FormatValue(alpha[k]),
                       "must increase strictly [rad]");
    }
  }
}

engine::PressureCurveSource CurveFromJson(const json& j, const std::string& path) {
  if (!j.is_object()) throw InputError(path, Dump(j), "must be an object {rpm, file | table}");
  engine::PressureCurveSource source;
  Reader r{j, {}};
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (it.key() != "rpm" && it.key() != "file" && it.key() != "crank_angle_deg" &&
        it.key() != "pressure") {
      throw InputError(path + "." + it.key(), Dump(*it),
                       "unknown field (allowed: rpm, file, crank_angle_deg, pressure)");
    }
  }
  if (!j.contains("rpm")) throw InputError(path + ".rpm", "missing", "required [rpm]");
  source.rpm = r.ToNumber(path + ".rpm", j["rpm"]);
  RequireInRange(path + ".rpm", source.rpm, 0.0, 30000.0, true, false, "rpm");
  if (j.contains("file")) {
    if (!j["file"].is_string())
      throw InputError(path + ".file", Dump(j["file"]), "must be a string");
    source.file = j["file"].get<std::string>();
  } else {
    Reader inner{j, {}};
    inner.Vector("crank_angle_deg", source.crank_angle_deg, Between(0.0, 720.0, "deg"));
    inner.Vector("pressure", source.pressure, NonNegative("Pa"));
    if (source.crank_angle_deg.empty()) {
      throw InputError(path, Dump(j), "needs \"file\" or the arrays crank_angle_deg and pressure");
    }
  }
  return source;
}

}  // namespace

EngineCase CaseFromJson(const json& root) {
  if (!root.is_object())
    throw InputError("case", Dump(root).substr(0, 40), "must be a JSON object");
  EngineCase c;
  Reader reader{root, {}};
  VisitCase(reader, c);
  reader.seen.insert("pressure_curves");
  reader.seen.insert("assumed");
  reader.seen.insert("filmdyn_case_version");
  std::vector<std::string> leaves;
  LeafPaths(root, "", &leaves);
  for (const std::string& path : leaves) {
    if (!reader.seen.count(path)) {
      const json* node = Find(root, path);
      if (path == "skirt.composite_modulus" || path == "big_end.composite_modulus") {
        throw InputError(path, node ? Dump(*node) : "?",
                         "replaced by E and ν per surface (skirt.modulus_skirt, poisson_skirt, "
                         "modulus_liner, poisson_liner; big_end.modulus_journal, "
                         "poisson_journal, modulus_bearing, poisson_bearing; docs/case-file.md)");
      }
      throw InputError(path, node ? Dump(*node).substr(0, 60) : "?",
                       "unknown field (see docs/case-file.md)");
    }
  }
  if (root.contains("pressure_curves")) {
    const json& curves = root["pressure_curves"];
    if (!curves.is_array()) throw InputError("pressure_curves", Dump(curves), "must be an array");
    for (std::size_t k = 0; k < curves.size(); ++k) {
      c.pressure_curves.push_back(CurveFromJson(curves[k], "pressure_curves." + std::to_string(k)));
    }
  }
  if (root.contains("assumed")) {
    const json& notes = root["assumed"];
    if (!notes.is_object()) throw InputError("assumed", Dump(notes), "must be an object");
    for (auto it = notes.begin(); it != notes.end(); ++it) {
      if (!reader.seen.count(it.key())) {
        throw InputError("assumed." + it.key(), Dump(*it), "names no field of the case");
      }
      if (!it->is_string()) throw InputError("assumed." + it.key(), Dump(*it), "must be a reason");
      c.assumed[it.key()] = it->get<std::string>();
    }
  }
  CheckConsistency(c);
  return c;
}

json CaseToJson(const EngineCase& engine_case) {
  EngineCase c = engine_case;
  Writer writer;
  writer.root["filmdyn_case_version"] = 1;
  VisitCase(writer, c);
  json curves = json::array();
  for (const auto& curve : c.pressure_curves) {
    json j;
    j["rpm"] = curve.rpm;
    if (!curve.file.empty()) {
      j["file"] = curve.file;
    } else {
      j["crank_angle_deg"] = curve.crank_angle_deg;
      j["pressure"] = curve.pressure;
    }
    curves.push_back(j);
  }
  writer.root["pressure_curves"] = curves;
  writer.root["assumed"] = c.assumed;
  return writer.root;
}

void ApplyOverride(json* root, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw InputError("--set", assignment, "must be key=value with a dotted JSON path as key");
  }
  const std::string path = assignment.substr(0, eq), text = assignment.substr(eq + 1);
  json* node = root;
  std::size_t start = 0;
  while (true) {
    const auto dot = path.find('.', start);
    const std::string key = path.substr(start, dot - start);
    if (node->is_array()) {
      std::size_t index = 0;
      const auto [end, error] = std::from_chars(key.data(), key.data() + key.size(), index);
      if (error != std::errc() || end != key.data() + key.size() || index >= node->size()) {
        throw InputError("--set " + path, key, "is not an index of the array");
      }
      node = &(*node)[index];
    } else if (node->is_object() && node->contains(key)) {
      node = &(*node)[key];
    } else {
      throw InputError("--set " + path, text, "no such field in the case (see docs/case-file.md)");
    }
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  if (node->is_number()) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size()) {
      if (text == "nan" || text == "inf" || text == "-inf") {
        *node = text;  // rejected with the field's range by CaseFromJson
        return;
      }
      throw InputError("--set " + path, text, "must be a number");
    }
    *node = value;
  } else if (node->is_string()) {
    *node = text;
  } else if (node->is_boolean()) {
    if (text != "true" && text != "false")
      throw InputError("--set " + path, text, "must be true or false");
    *node = text == "true";
  } else {
    throw InputError("--set " + path, text, "names an object or array, not a scalar field");
  }
}

LoadedCase LoadCase(const std::filesystem::path& path, const std::vector<std::string>& overrides) {
  LoadedCase loaded;
  std::string text;
  if (path.empty()) {
    const auto resource = ReadResource("cases/default.json");
    if (!resource) throw InputError("case", "default", "the default case is not available");
    text = *resource;
    loaded.source = "embedded:cases/default.json";
  } else {
    std::ifstream file(path);
    if (!file) throw InputError("case", path.string(), "cannot open the file");
    text.assign(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
    loaded.directory = path.parent_path();
    loaded.source = path.string();
  }
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& error) {
    throw InputError(loaded.source, "not JSON", error.what());
  }
  for (const std::string& assignment : overrides) ApplyOverride(&root, assignment);
  loaded.value = CaseFromJson(root);
  return loaded;
}

namespace {

engine::PressureCurve CurveFromSource(const LoadedCase& loaded,
                                      const engine::PressureCurveSource& source,
                                      const std::string& field) {
  if (source.file.empty()) {
    std::vector<double> angles;
    for (double deg : source.crank_angle_deg) angles.push_back(deg * std::numbers::pi / 180.0);
    return engine::PressureCurve(angles, source.pressure, field);
  }
  const std::filesystem::path relative(source.file);
  if (!loaded.directory.empty() || relative.is_absolute()) {
    const std::filesystem::path full =
        relative.is_absolute() ? relative : loaded.directory / relative;
    if (std::filesystem::exists(full)) return ReadPressureCsvFile(full);
  }
  // Not on disk: the embedded resources, addressed relative to resources/cases/.
  const std::string name =
      (std::filesystem::path("cases") / relative).lexically_normal().generic_string();
  if (const auto text = ReadResource(name)) {
    std::istringstream in(*text);
    return ReadPressureCsv(in, "embedded:" + name);
  }
  throw InputError(field + ".file", source.file,
                   "file not found next to the case nor among the built-in resources");
}

}  // namespace

engine::PressureCurve PressureCurveForSpeed(const LoadedCase& loaded, double rpm) {
  const auto& curves = loaded.value.pressure_curves;
  if (curves.empty()) {
    throw InputError("pressure_curves", "[]",
                     "the case has no cylinder-pressure curve; "
                     "add one (command line: --pressure-curve FILE.csv)");
  }
  std::vector<std::size_t> order(curves.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return curves[a].rpm < curves[b].rpm; });
  auto field = [](std::size_t k) { return "pressure_curves." + std::to_string(k); };
  for (std::size_t k : order) {
    if (std::abs(curves[k].rpm - rpm) < 1e-9 * rpm)
      return CurveFromSource(loaded, curves[k], field(k));
  }
  for (std::size_t n = 0; n + 1 < order.size(); ++n) {
    const auto& lo = curves[order[n]];
    const auto& hi = curves[order[n + 1]];
    if (lo.rpm < rpm && rpm < hi.rpm) {
      return engine::PressureCurve::Blend(CurveFromSource(loaded, lo, field(order[n])),
                                          CurveFromSource(loaded, hi, field(order[n + 1])),
                                          (rpm - lo.rpm) / (hi.rpm - lo.rpm));
    }
  }
  throw InputError(
      "operating.rpm", FormatValue(rpm),
      "must lie within the speeds of pressure_curves [" + FormatValue(curves[order.front()].rpm) +
          ", " + FormatValue(curves[order.back()].rpm) +
          "] rpm; add a curve for this speed (command line: --pressure-curve FILE.csv)");
}

}  // namespace filmdyn::io
