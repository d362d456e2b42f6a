#include "core/io/case_file.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

#include "core/base/angles.hpp"
#include "core/base/input_error.hpp"
#include "core/base/input_file.hpp"
#include "core/engine/case_schema.hpp"
#include "core/io/json_input.hpp"
#include "core/io/output_files.hpp"
#include "core/io/pressure_csv.hpp"
#include "core/io/resources.hpp"

namespace filmdyn::io {

using engine::EngineCase;
using engine::JointModel;
using nlohmann::json;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Input limits (docs/case-file.md): a case file is a few KB and a few levels deep.
constexpr int kMaxCaseDepth = 64;
// The version case files are written with (filmdyn_case_version).
constexpr long long kCaseFormatVersion = 1;

// The one list of case fields is the schema (core/engine/case_schema.hpp); V visits each with
// its kind, in schema order.
template <class V>
void VisitCase(V& v, EngineCase& c) {
  for (const engine::CaseField& field : engine::CaseSchema()) {
    switch (field.kind) {
      case engine::FieldKind::kText:
        v.Text(field, field.text(c));
        break;
      case engine::FieldKind::kChoice:
        v.Choice(field, c);
        break;
      case engine::FieldKind::kNumber:
      case engine::FieldKind::kInteger:
        v.Scalar(field, c);
        break;
      case engine::FieldKind::kNumberList:
        v.Vector(field, field.list(c));
        break;
    }
  }
}

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
  std::string prefix;  ///< what errors put before a path: the reader's place in the file
  const json* Get(const std::string& path) {
    seen.insert(path);
    return Find(root, path);
  }
  void Text(const engine::CaseField& field, std::string& value) {
    if (const json* j = Get(field.path)) {
      if (!j->is_string()) throw InputError(field.path, Dump(*j), "must be a string");
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
  void Scalar(const engine::CaseField& field, EngineCase& c) {
    if (const json* j = Get(field.path)) {
      const double x = ToNumber(field.path, *j);
      field.Check(x);
      field.set(c, x);
    } else {
      field.Check(field.get(c));
    }
  }
  void Choice(const engine::CaseField& field, EngineCase& c) {
    if (const json* j = Get(field.path)) {
      field.SetChoice(c, j->is_string() ? j->get<std::string>() : Dump(*j));
    }
  }
  void Vector(const engine::CaseField& field, std::vector<double>& value) {
    Vector(field.path, value,
           [&field](const std::string& element, double x) { field.Check(x, element); });
  }
  template <class Check>
  void Vector(const std::string& path, std::vector<double>& value, const Check& check) {
    if (const json* j = Get(path)) {
      if (!j->is_array()) throw InputError(prefix + path, Dump(*j), "must be an array of numbers");
      value.clear();
      for (std::size_t k = 0; k < j->size(); ++k) {
        value.push_back(ToNumber(prefix + path + "." + std::to_string(k), (*j)[k]));
      }
    }
    for (std::size_t k = 0; k < value.size(); ++k)
      check(prefix + path + "." + std::to_string(k), value[k]);
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
  void Text(const engine::CaseField& field, std::string& value) { At(field.path) = value; }
  void Scalar(const engine::CaseField& field, EngineCase& c) {
    if (field.kind == engine::FieldKind::kInteger) {
      At(field.path) = static_cast<long>(field.get(c));
    } else {
      At(field.path) = field.get(c);
    }
  }
  void Choice(const engine::CaseField& field, EngineCase& c) {
    At(field.path) = field.ChoiceName(c);
  }
  void Vector(const engine::CaseField& field, std::vector<double>& value) {
    At(field.path) = value;
  }
};

// Every key path in the JSON (objects only; arrays are leaves). A key holding a dot would join
// into another key's path ("skirt.cold_clearance" at the top reads as the nested field, which the
// reader never looked at): refused, naming where it is.
void LeafPaths(const json& node, const std::string& prefix, std::vector<std::string>* out) {
  for (auto it = node.begin(); it != node.end(); ++it) {
    if (it.key().find('.') != std::string::npos) {
      const std::string at = prefix.empty() ? "at the top level" : "in \"" + prefix + "\"";
      const std::string last = it.key().substr(it.key().rfind('.') + 1);
      throw InputError(prefix.empty() ? it.key() : prefix + "." + it.key(), Dump(*it).substr(0, 60),
                       "a key with a dot (\"" + it.key() + "\" " + at +
                           ") is no field: nest it as objects, e.g. {\"" +
                           it.key().substr(0, it.key().find('.')) + "\": {… \"" + last + "\": …}}");
    }
    const std::string path = prefix.empty() ? it.key() : prefix + "." + it.key();
    if (it->is_object() && path != "assumed") {  // "assumed" keys are dotted paths themselves
      LeafPaths(*it, path, out);
    } else {
      out->push_back(path);
    }
  }
}

engine::PressureCurveSource CurveFromJson(const json& j, const std::string& path) {
  if (!j.is_object()) throw InputError(path, Dump(j), "must be an object {rpm, file | table}");
  engine::PressureCurveSource source;
  Reader r{j, {}, {}};
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
    Reader inner{j, {}, path + "."};
    inner.Vector("crank_angle_deg", source.crank_angle_deg, [](const std::string& f, double x) {
      RequireInRange(f, x, 0.0, 720.0, false, false, "deg");
    });
    inner.Vector("pressure", source.pressure,
                 [](const std::string& f, double x) { RequireNonNegative(f, x, "Pa"); });
    if (source.crank_angle_deg.empty()) {
      throw InputError(path, Dump(j), "needs \"file\" or the arrays crank_angle_deg and pressure");
    }
  }
  return source;
}

// The piston radius was the skirt's size input before the cold skirt clearance
// (docs/case-file.md, "Older case files").
constexpr const char* kOldPistonRadius = "skirt.piston_radius";
constexpr const char* kColdClearance = "skirt.cold_clearance";

// The embedded default case's "assumed" notes, read from its text (not through CaseFromJson,
// which hands them on to the fields another case file leaves out).
const std::map<std::string, std::string>& DefaultAssumptions() {
  static const std::map<std::string, std::string> notes = [] {
    std::map<std::string, std::string> read;
    const auto text = ReadResource("cases/default.json");
    if (!text) return read;
    const json root = json::parse(*text, nullptr, /*allow_exceptions=*/false);
    if (!root.is_object() || !root.contains("assumed") || !root["assumed"].is_object()) return read;
    for (auto it = root["assumed"].begin(); it != root["assumed"].end(); ++it) {
      if (it->is_string()) read[it.key()] = it->get<std::string>();
    }
    return read;
  }();
  return notes;
}

// Whether the file gives the field `path` a value: the field, or another column of its table (a
// profile's h gives its y), or an older key that the reader turns into it (the piston radius for
// the clearance, a feed pressure for the supply it implies).
bool GivenByFile(const json& root, const std::string& path, const EngineCase& c) {
  if (const engine::CaseField* field = engine::FindCaseField(path)) {
    for (const engine::CaseField* f : engine::FieldsSetWith(*field)) {
      if (Find(root, f->path)) return true;
    }
  }
  if (path == kColdClearance) return Find(root, kOldPistonRadius) != nullptr;
  if (path == "big_end.supply")
    return Find(root, "big_end.oil_feed_pressure") && c.big_end.oil_feed_pressure > 0.0;
  return false;
}

// Reads an older file's piston radius as the cold skirt clearance it implies, R_l − R; the radius
// derived back from it (engine::PistonRadius) is the file's to the last bit. Errors name the old
// key, which is the one the user sees in the file.
void ReadOldPistonRadius(const json& root, Reader& reader, EngineCase& c,
                         std::vector<std::string>* notes) {
  const json* old = reader.Get(kOldPistonRadius);
  if (!old) return;
  if (Find(root, kColdClearance)) {
    throw InputError(kOldPistonRadius, Dump(*old),
                     "replaced by skirt.cold_clearance; give only skirt.cold_clearance (the cold "
                     "radial skirt clearance; docs/case-file.md)");
  }
  const double radius = reader.ToNumber(kOldPistonRadius, *old);
  RequirePositive(kOldPistonRadius, radius, "m");
  const double liner = c.geometry.liner_radius;
  const double clearance = liner - radius;
  const engine::CaseField& field = *engine::FindCaseField(kColdClearance);
  try {
    field.Check(clearance);
  } catch (const InputError& error) {
    throw InputError(kOldPistonRadius, FormatValue(radius),
                     "gives the cold skirt clearance geometry.liner_radius − piston_radius = " +
                         FormatValue(clearance) + " [m], which " + error.allowed() +
                         "; the piston must be smaller than geometry.liner_radius = " +
                         FormatValue(liner) + " [m]");
  }
  field.set(c, clearance);
  if (notes) {
    notes->push_back("the case file gives skirt.piston_radius = " + FormatValue(radius) +
                     " m (an older key): read as skirt.cold_clearance = " + FormatValue(clearance) +
                     " m; saving the case writes the new key");
  }
}

}  // namespace

EngineCase CaseFromJson(const json& root, std::vector<std::string>* notes) {
  if (!root.is_object())
    throw InputError("case", Dump(root).substr(0, 40), "must be a JSON object");
  // The format's version first: a newer FilmDyn's file would otherwise be refused for a field
  // this version does not know, which says nothing of why.
  if (const auto version = root.find("filmdyn_case_version"); version != root.end()) {
    if (!version->is_number_integer() || version->get<long long>() < 1) {
      throw InputError("filmdyn_case_version", Dump(*version).substr(0, 40),
                       "must be a whole number ≥ 1 (the case format's version)");
    }
    if (version->get<long long>() > kCaseFormatVersion) {
      throw InputError("filmdyn_case_version", Dump(*version),
                       "this FilmDyn reads case files up to version " +
                           std::to_string(kCaseFormatVersion) +
                           ": the file was written by a newer FilmDyn");
    }
  }
  EngineCase c;
  Reader reader{root, {}, {}};
  VisitCase(reader, c);
  ReadOldPistonRadius(root, reader, c, notes);
  // Before the supply kinds, a feed pressure meant one hole through the shell on the rod axis.
  if (!Find(root, "big_end.supply") && c.big_end.oil_feed_pressure > 0.0) {
    c.big_end.supply = lubrication::OilFeedKind::kShellHoles;
    if (notes) {
      notes->push_back(
          "the case file gives big_end.oil_feed_pressure without big_end.supply (an older "
          "file): read as one shell hole on the rod axis (big_end.supply = \"shell_holes\"); "
          "saving the case writes the supply");
    }
  }
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
      // A section given as something else than an object ("geometry": [1, 2]).
      const std::string section = path + ".";
      const auto& schema = engine::CaseSchema();
      if (std::any_of(schema.begin(), schema.end(), [&section](const engine::CaseField& f) {
            return f.path.rfind(section, 0) == 0;
          })) {
        throw InputError(path, node ? Dump(*node).substr(0, 60) : "?",
                         "must be an object of the section's fields (see docs/case-file.md)");
      }
      throw InputError(path, node ? Dump(*node).substr(0, 60) : "?",
                       "unknown field (see docs/case-file.md)" + engine::SimilarFieldsText(path));
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
      // An older file's note on the piston radius belongs to the clearance that replaces it.
      c.assumed[it.key() == kOldPistonRadius ? kColdClearance : it.key()] = it->get<std::string>();
    }
  }
  // A field the file leaves out takes the default case's value, and with it the default case's
  // assumption: the run's warnings and the editor's notes say so as they do for the default case.
  for (const auto& [path, reason] : DefaultAssumptions()) {
    if (c.assumed.count(path) || GivenByFile(root, path, c)) continue;
    c.assumed[path] = "not given: the default case's value (" + reason + ")";
  }
  engine::CheckCaseConsistency(c);
  return c;
}

json CaseToJson(const EngineCase& engine_case) {
  EngineCase c = engine_case;
  Writer writer;
  writer.root["filmdyn_case_version"] = kCaseFormatVersion;
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

namespace {

// A number as --set takes it: parsed strictly; "nan", "inf" and "-inf" are kept as the file's
// text for them, so that the field's range check refuses them naming the field.
json OverrideNumber(const std::string& path, std::string_view text) {
  double value = 0.0;
  if (!ParseNumber(text, value)) {
    if (text == "nan" || text == "inf" || text == "-inf") return std::string(text);
    // A number with a unit ("130mm") is the usual slip: say the unit the field takes (SI).
    const engine::CaseField* field = engine::FindCaseField(path);
    throw InputError("--set " + path, std::string(text),
                     field != nullptr && (field->kind == engine::FieldKind::kNumber ||
                                          field->kind == engine::FieldKind::kInteger)
                         ? "must be a number without a unit (SI): " + field->AllowedText()
                         : "must be a number");
  }
  return value;
}

// A list of numbers as --set takes it: comma-separated, optionally in brackets ("[0,0.5]",
// "0,0.5"); "[]" or nothing is the empty list. Blanks around the numbers are ignored.
json OverrideList(const std::string& path, std::string_view text) {
  auto trim = [](std::string_view t) {
    while (!t.empty() && (t.front() == ' ' || t.front() == '\t')) t.remove_prefix(1);
    while (!t.empty() && (t.back() == ' ' || t.back() == '\t')) t.remove_suffix(1);
    return t;
  };
  std::string_view body = trim(text);
  if (!body.empty() && body.front() == '[') {
    if (body.back() != ']') {
      throw InputError("--set " + path, std::string(text),
                       "a list of numbers: comma-separated, in brackets or not (e.g. [0,0.5])");
    }
    body = trim(body.substr(1, body.size() - 2));
  }
  json list = json::array();
  if (body.empty()) return list;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = body.find(',', start);
    const std::string_view item = trim(body.substr(start, comma - start));
    if (item.empty()) {
      throw InputError("--set " + path, std::string(text),
                       "a list of numbers: comma-separated, in brackets or not (e.g. [0,0.5]); "
                       "item " +
                           std::to_string(list.size()) + " is empty");
    }
    list.push_back(OverrideNumber(path + "." + std::to_string(list.size()), item));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return list;
}

}  // namespace

void ApplyOverride(json* root, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw InputError("--set", assignment, "must be key=value with a dotted JSON path as key");
  }
  const std::string path = assignment.substr(0, eq), text = assignment.substr(eq + 1);
  const engine::CaseField* field = engine::FindCaseField(path);
  json* node = root;
  std::size_t start = 0;
  while (true) {
    const auto dot = path.find('.', start);
    const std::string key = path.substr(start, dot - start);
    if (node->is_array()) {
      std::size_t index = 0;
      const auto [end, error] = std::from_chars(key.data(), key.data() + key.size(), index);
      if (error != std::errc() || end != key.data() + key.size() || index >= node->size()) {
        const std::string list = path.substr(0, start - 1);  // the root is an object
        throw InputError(
            "--set " + path, text,
            fmt::format("\"{}\" is not an element of {}: {}; a list's length changes only by "
                        "setting it whole, {}=[a,b,…]",
                        key, list,
                        node->empty()
                            ? std::string("it is empty")
                            : fmt::format("its elements are {} … {}", 0, node->size() - 1),
                        list));
      }
      node = &(*node)[index];
    } else if (node->is_object() && node->contains(key)) {
      node = &(*node)[key];
    } else if (node->is_object() && field != nullptr) {
      // A field the file leaves at its default (e.g. a file older than the field): added.
      node = &(*node)[key];
      if (dot != std::string::npos) *node = json::object();
    } else if (path == kOldPistonRadius) {
      throw InputError("--set " + path, text,
                       "replaced by skirt.cold_clearance, the cold radial skirt clearance "
                       "(piston radius = geometry.liner_radius − skirt.cold_clearance)");
    } else if (path == "model") {
      throw InputError("--set " + path, text,
                       "is not a case field: the run model is chosen with --model (or the joints' "
                       "models with skirt.model and big_end.model)");
    } else {
      throw InputError(
          "--set " + path, text,
          "no such field in the case (see docs/case-file.md)" + engine::SimilarFieldsText(path));
    }
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  if (node->is_null() && field != nullptr) {  // added above: the field's kind says the type
    const bool number =
        field->kind == engine::FieldKind::kNumber || field->kind == engine::FieldKind::kInteger;
    *node = field->kind == engine::FieldKind::kNumberList ? json::array()
            : number                                      ? json(0.0)
                                                          : json(std::string());
  }
  if (node->is_number()) {
    *node = OverrideNumber(path, text);
  } else if (node->is_array() && field != nullptr &&
             field->kind == engine::FieldKind::kNumberList) {
    *node = OverrideList(path, text);  // the whole list; one element is set by its index
  } else if (node->is_string()) {
    RequireUtf8("--set " + path, text);
    *node = text;
  } else if (node->is_boolean()) {
    if (text != "true" && text != "false")
      throw InputError("--set " + path, text, "must be true or false");
    *node = text == "true";
  } else {
    throw InputError("--set " + path, text, "names an object or array, not a scalar field");
  }
  // The value is the user's now: the "assumed" notes of the field (and of its table's other
  // columns) no longer hold.
  const engine::CaseField* set = engine::FieldOfPath(path);
  json* notes = root->contains("assumed") ? &(*root)["assumed"] : nullptr;
  if (set && notes && notes->is_object()) {
    for (const engine::CaseField* f : engine::FieldsSetWith(*set)) notes->erase(f->path);
  }
}

std::string OverridesText(const std::vector<std::string>& overrides) {
  std::string text;
  for (const std::string& o : overrides) {
    const std::size_t eq = o.find('=');
    text += (text.empty() ? "`" : ", `") + o.substr(0, eq) + " = " +
            (eq == std::string::npos ? std::string() : o.substr(eq + 1)) + "`";
  }
  return text;
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
    text = ReadInputFile(path, "case", kMaxCaseFileBytes);
    // Absolute: a file named without a folder ("case.json") has its files beside it too (an
    // empty directory means the embedded case, whose files are the built-in resources).
    std::error_code ignored;
    loaded.directory = std::filesystem::absolute(path, ignored).lexically_normal().parent_path();
    loaded.source = path.string();
  }
  loaded.value = LoadCaseText(text, loaded.source, overrides, &loaded.notes);
  // Every curve read and checked now, also those of speeds this run does not use: a broken curve
  // (a missing file, a table of unequal lengths) is the case's error wherever it is.
  for (const engine::PressureCurveSource& source : loaded.value.pressure_curves)
    PressureCurveForSpeed(loaded, source.rpm);
  return loaded;
}

engine::EngineCase LoadCaseText(const std::string& text, const std::string& source,
                                const std::vector<std::string>& overrides,
                                std::vector<std::string>* notes) {
  json root = ParseInputJson(text, source, kMaxCaseDepth, "a case file");
  for (const std::string& assignment : overrides) ApplyOverride(&root, assignment);
  return CaseFromJson(root, notes);
}

std::vector<std::string*> CaseFileNames(engine::EngineCase* c) {
  std::vector<std::string*> names = {&c->skirt.compliance_file, &c->big_end.compliance_file};
  for (engine::PressureCurveSource& curve : c->pressure_curves) names.push_back(&curve.file);
  return names;
}

int RebaseCaseFiles(engine::EngineCase* c, const std::filesystem::path& from,
                    const std::filesystem::path& to) {
  namespace fs = std::filesystem;
  std::error_code ignored;
  const fs::path source = fs::absolute(from, ignored).lexically_normal();
  const fs::path target = fs::absolute(to, ignored).lexically_normal();
  if (source == target) return 0;
  int changed = 0;
  for (std::string* name : CaseFileNames(c)) {
    if (name->empty() || fs::path(*name).is_absolute()) continue;
    const fs::path file = (source / *name).lexically_normal();
    if (!fs::is_regular_file(file, ignored)) continue;
    const fs::path relative = file.lexically_relative(target);
    *name = relative.empty() ? file.string() : relative.string();
    ++changed;
  }
  return changed;
}

void AbsoluteCaseFileNames(engine::EngineCase* c, const std::filesystem::path& directory) {
  namespace fs = std::filesystem;
  for (std::string* name : CaseFileNames(c)) {
    if (name->empty() || fs::path(*name).is_absolute()) continue;
    std::error_code ignored;
    const fs::path full = fs::absolute(directory / *name, ignored).lexically_normal();
    if (!full.empty() && fs::exists(full, ignored)) *name = full.string();
  }
}

engine::EngineCase CaseWithInlineCurves(const LoadedCase& loaded) {
  engine::EngineCase c = loaded.value;
  for (engine::PressureCurveSource& source : c.pressure_curves) {
    if (!source.file.empty())
      source = InlinePressureCurve(PressureCurveForSpeed(loaded, source.rpm), source.rpm);
  }
  return c;
}

engine::EngineCase CaseFileKeepingValid(const std::filesystem::path& path,
                                        const engine::EngineCase& base,
                                        std::vector<std::string>* dropped) {
  json current = ParseInputJson(ReadInputFile(path, "case", kMaxCaseFileBytes), path.string(),
                                kMaxCaseDepth, "a case file");
  const json fallback = CaseToJson(base);
  // Each refusal restores one field, list or section from `base`, one that differed: at most as
  // many rounds as the file has leaves; a file left equal to `base` that is refused throws.
  std::vector<std::string> leaves;
  if (current.is_object()) LeafPaths(current, "", &leaves);
  for (std::size_t round = 0; round <= leaves.size() + 1; ++round) {
    try {
      return CaseFromJson(current);
    } catch (const InputError& e) {
      if (!current.is_object()) throw;
      // The object members on the refused field's path, outermost first ("skirt",
      // "skirt.profile_y" for "skirt.profile_y.3"; "pressure_curves" for "pressure_curves.0.rpm").
      struct Level {
        json* parent;
        const json* base_parent;  // nullptr where `base` has no such object
        std::string key;
      };
      std::vector<Level> levels;
      json* parent = &current;
      const json* base_parent = &fallback;
      for (std::size_t start = 0;;) {
        const auto dot = e.field().find('.', start);
        const std::string key = e.field().substr(start, dot - start);
        if (!parent->is_object() || !parent->contains(key)) break;
        levels.push_back({parent, base_parent, key});
        json& child = (*parent)[key];
        base_parent = base_parent != nullptr && base_parent->is_object() &&
                              base_parent->contains(key) && (*base_parent)[key].is_object()
                          ? &(*base_parent)[key]
                          : nullptr;
        if (dot == std::string::npos || !child.is_object()) break;
        parent = &child;
        start = dot + 1;
      }
      // The innermost of them that differs from `base` takes base's value: the field itself, or
      // (a rule across fields naming one left as saved: profile_h for a shorter profile_y) the
      // section holding it.
      bool restored = false;
      for (auto level = levels.rbegin(); level != levels.rend() && !restored; ++level) {
        const json* from = level->base_parent != nullptr && level->base_parent->contains(level->key)
                               ? &(*level->base_parent)[level->key]
                               : nullptr;
        json& node = (*level->parent)[level->key];
        if (from != nullptr && node == *from) continue;
        if (from != nullptr) {
          node = *from;
        } else {
          level->parent->erase(level->key);
        }
        restored = true;
      }
      std::string what = e.what();
      if (!restored) {
        // A rule across sections naming a field left as saved (the clearance against an edited
        // liner radius): the first section that differs goes back to `base` instead, so that
        // each round still restores something.
        for (auto it = current.begin(); it != current.end(); ++it) {
          if (fallback.contains(it.key()) && *it == fallback[it.key()]) continue;
          what += " (\"" + it.key() + "\" as saved)";
          if (fallback.contains(it.key())) {
            *it = fallback[it.key()];
          } else {
            current.erase(it);
          }
          restored = true;
          break;
        }
      }
      if (!restored) throw;  // the file is `base`: base itself is refused
      if (dropped) dropped->push_back(what);
    }
  }
  return CaseFromJson(current);
}

namespace {

// An inline curve's angle [°CA] in radians: the one conversion of the case reader.
double InlineAngle(double deg) { return deg * kRadiansPerDegree; }

engine::PressureCurve CurveFromSource(const LoadedCase& loaded,
                                      const engine::PressureCurveSource& source,
                                      const std::string& field) {
  if (source.file.empty()) {
    std::vector<double> angles;
    for (double deg : source.crank_angle_deg) angles.push_back(InlineAngle(deg));
    return engine::PressureCurve(angles, source.pressure, field);
  }
  const std::filesystem::path relative(source.file);
  if (!loaded.directory.empty() || relative.is_absolute()) {
    const std::filesystem::path full =
        relative.is_absolute() ? relative : loaded.directory / relative;
    if (std::filesystem::exists(full)) return ReadPressureCsvFile(full, field + ".file");
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

engine::PressureCurveSource InlinePressureCurve(const engine::PressureCurve& curve, double rpm) {
  engine::PressureCurveSource source;
  source.rpm = rpm;
  for (double angle : curve.Angles()) {
    double deg = angle * kDegreesPerRadian;
    // A few ulps either way find the degrees that convert back to exactly this angle.
    for (int k = 0; k < 8 && InlineAngle(deg) != angle; ++k)
      deg = std::nextafter(deg, InlineAngle(deg) < angle ? HUGE_VAL : -HUGE_VAL);
    source.crank_angle_deg.push_back(deg);
  }
  source.pressure = curve.Pressures();
  return source;
}

engine::PressureCurve PressureCurveForSpeed(const LoadedCase& loaded, double rpm) {
  const auto& curves = loaded.value.pressure_curves;
  if (curves.empty()) {
    throw InputError("pressure_curves", "[]",
                     "the case has no cylinder-pressure curve; add one to the case's "
                     "pressure_curves (for one run: filmdyn run --pressure-curve FILE.csv)");
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
          "] rpm; add a curve for this speed to the case's pressure_curves (for one run: "
          "filmdyn run --pressure-curve FILE.csv)");
}

}  // namespace filmdyn::io
