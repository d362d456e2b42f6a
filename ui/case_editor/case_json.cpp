#include "ui/case_editor/case_json.hpp"

#include <QFile>
#include <QSaveFile>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "core/input_error.hpp"
#include "ui/case_editor/case_parameters.hpp"

namespace filmdyn::ui {

namespace {

using nlohmann::json;

json::json_pointer Pointer(const std::string& dotted) {
  std::string p = "/" + dotted;
  for (char& ch : p) {
    if (ch == '.') ch = '/';
  }
  return json::json_pointer(p);
}

// NaN (a cell the user left invalid) is stored as null so nothing typed is lost.
json Number(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

double ReadNumber(const json& j, const std::string& field) {
  if (j.is_null()) return std::numeric_limits<double>::quiet_NaN();
  if (!j.is_number()) throw InputError(field, j.dump(), "must be a number");
  return j.get<double>();
}

std::vector<double> ReadArray(const json& j, const std::string& field) {
  if (!j.is_array()) throw InputError(field, j.dump(), "must be an array of numbers");
  std::vector<double> out;
  for (size_t i = 0; i < j.size(); ++i) {
    out.push_back(ReadNumber(j[i], field + "[" + std::to_string(i) + "]"));
  }
  return out;
}

json Array(const std::vector<double>& v) {
  json a = json::array();
  for (double x : v) a.push_back(Number(x));
  return a;
}

const char* JointName(engine::JointModel m) {
  return m == engine::JointModel::kLubricated ? "lubricated" : "ideal";
}

engine::JointModel ReadJoint(const json& j, const std::string& field) {
  const std::string s = j.is_string() ? j.get<std::string>() : j.dump();
  if (s == "ideal") return engine::JointModel::kIdeal;
  if (s == "lubricated") return engine::JointModel::kLubricated;
  throw InputError(field, s, "must be \"ideal\" or \"lubricated\"");
}

// Removes a consumed key and prunes objects left empty, so leftovers are unknown keys.
void Erase(json& root, const std::string& dotted) {
  const auto ptr = Pointer(dotted);
  if (!root.contains(ptr)) return;
  root[ptr.parent_pointer()].erase(ptr.back());
  if (root[ptr.parent_pointer()].empty() && !ptr.parent_pointer().empty()) {
    Erase(root, dotted.substr(0, dotted.rfind('.')));
  }
}

}  // namespace

std::string CaseToJsonText(const engine::EngineCase& c) {
  json root;
  root["name"] = c.name;
  root["description"] = c.description;
  for (const CaseParameter& p : CaseParameters()) {
    const double v = p.get(c);
    root[Pointer(p.path)] = p.integer && std::isfinite(v) ? json(std::lround(v)) : Number(v);
  }
  root["skirt"]["model"] = JointName(c.skirt.model);
  root["big_end"]["model"] = JointName(c.big_end.model);
  root["skirt"]["profile_y"] = Array(c.skirt.profile_y);
  root["skirt"]["profile_h"] = Array(c.skirt.profile_h);
  json curves = json::array();
  for (const auto& curve : c.pressure_curves) {
    json jc;
    jc["rpm"] = Number(curve.rpm);
    if (!curve.file.empty()) jc["file"] = curve.file;
    jc["crank_angle_deg"] = Array(curve.crank_angle_deg);
    jc["pressure"] = Array(curve.pressure);
    curves.push_back(jc);
  }
  root["pressure_curves"] = curves;
  root["assumed"] = c.assumed;
  return root.dump(2) + "\n";
}

engine::EngineCase CaseFromJsonText(const std::string& text) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    throw InputError("case file", "JSON", std::string("not valid JSON: ") + e.what());
  }
  if (!root.is_object()) throw InputError("case file", root.type_name(), "must be a JSON object");
  engine::EngineCase c;
  if (root.contains("name")) c.name = root["name"].get<std::string>();
  if (root.contains("description")) c.description = root["description"].get<std::string>();
  root.erase("name");
  root.erase("description");
  for (const CaseParameter& p : CaseParameters()) {
    const auto ptr = Pointer(p.path);
    if (root.contains(ptr)) {
      p.set(c, ReadNumber(root[ptr], p.path));
      Erase(root, p.path);
    }
  }
  if (root.contains(Pointer("skirt.model"))) {
    c.skirt.model = ReadJoint(root[Pointer("skirt.model")], "skirt.model");
    Erase(root, "skirt.model");
  }
  if (root.contains(Pointer("big_end.model"))) {
    c.big_end.model = ReadJoint(root[Pointer("big_end.model")], "big_end.model");
    Erase(root, "big_end.model");
  }
  for (const char* key : {"skirt.profile_y", "skirt.profile_h"}) {
    if (!root.contains(Pointer(key))) continue;
    auto values = ReadArray(root[Pointer(key)], key);
    (std::string(key) == "skirt.profile_y" ? c.skirt.profile_y : c.skirt.profile_h) = values;
    Erase(root, key);
  }
  if (root.contains("pressure_curves")) {
    const json& curves = root["pressure_curves"];
    if (!curves.is_array()) throw InputError("pressure_curves", curves.dump(), "must be an array");
    for (size_t i = 0; i < curves.size(); ++i) {
      const std::string f = "pressure_curves[" + std::to_string(i) + "]";
      const json& jc = curves[i];
      engine::PressureCurveSource s;
      s.rpm = ReadNumber(jc.value("rpm", json(nullptr)), f + ".rpm");
      s.file = jc.value("file", std::string());
      if (jc.contains("crank_angle_deg")) {
        s.crank_angle_deg = ReadArray(jc["crank_angle_deg"], f + ".crank_angle_deg");
      }
      if (jc.contains("pressure")) s.pressure = ReadArray(jc["pressure"], f + ".pressure");
      if (s.crank_angle_deg.size() != s.pressure.size()) {
        throw InputError(f + ".pressure", std::to_string(s.pressure.size()) + " values",
                         "must have as many values as crank_angle_deg (" +
                             std::to_string(s.crank_angle_deg.size()) + ")");
      }
      c.pressure_curves.push_back(std::move(s));
    }
    root.erase("pressure_curves");
  }
  if (root.contains("assumed")) {
    c.assumed = root["assumed"].get<std::map<std::string, std::string>>();
    root.erase("assumed");
  }
  if (!root.empty()) {
    const json flat = root.flatten();
    throw InputError(flat.begin().key().substr(1), flat.begin().value().dump(),
                     "unknown key in the case file");
  }
  return c;
}

bool SaveCaseFile(const engine::EngineCase& c, const QString& path, QString* error) {
  QSaveFile file(path);
  const std::string text = CaseToJsonText(c);
  if (!file.open(QIODevice::WriteOnly) ||
      file.write(text.data(), qint64(text.size())) != qint64(text.size()) || !file.commit()) {
    if (error) *error = QObject::tr("Cannot write %1: %2").arg(path, file.errorString());
    return false;
  }
  return true;
}

bool LoadCaseFile(const QString& path, engine::EngineCase* c, QString* error) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) {
    if (error) *error = QObject::tr("Cannot read %1: %2").arg(path, file.errorString());
    return false;
  }
  const QByteArray bytes = file.readAll();
  try {
    *c = CaseFromJsonText(bytes.toStdString());
  } catch (const std::exception& e) {
    if (error) *error = QObject::tr("%1: %2").arg(path, QString::fromStdString(e.what()));
    return false;
  }
  return true;
}

}  // namespace filmdyn::ui
