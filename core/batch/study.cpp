#include "core/batch/study.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "core/base/input_error.hpp"
#include "core/base/input_file.hpp"
#include "core/engine/case_diff.hpp"
#include "core/engine/case_schema.hpp"
#include "core/io/case_file.hpp"
#include "core/io/json_input.hpp"
#include "core/io/output_files.hpp"
#include "core/io/run_comparison.hpp"
#include "core/io/run_summary.hpp"

namespace filmdyn::batch {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The largest number of points a study may have: beyond it the study file is almost surely
// wrong (a factorial of many fine factors), and design.csv alone would be unwieldy.
constexpr std::size_t kMaxPoints = 100000;
// A study file is small; anything larger is not one.
constexpr std::uintmax_t kMaxStudyFileBytes = 1 << 20;

std::string Number(double v) { return fmt::format("{}", v); }

// InputError naming "<file>: <key>".
[[noreturn]] void Bad(const Study& s, const std::string& key, const std::string& value,
                      const std::string& allowed) {
  throw InputError(s.study_file.filename().string() + ": " + key, value, allowed);
}

std::string JsonText(const json& j) {
  std::string text = j.dump();
  if (text.size() > 80) text = text.substr(0, 77) + "...";
  return text;
}

double NumberAt(const Study& s, const json& j, const std::string& key) {
  if (!j.is_number()) Bad(s, key, JsonText(j), "must be a number");
  const double v = j.get<double>();
  if (!std::isfinite(v)) Bad(s, key, JsonText(j), "must be a finite number");
  return v;
}

long IntegerAt(const Study& s, const json& j, const std::string& key, long lo, long hi) {
  if (!j.is_number_integer() || j.get<long>() < lo || j.get<long>() > hi) {
    Bad(s, key, JsonText(j), fmt::format("must be an integer in [{}, {}]", lo, hi));
  }
  return j.get<long>();
}

// The overrides ("path=value") that give both joints the models of the run model `name`.
std::vector<std::string> ModelOverrides(const std::string& name) {
  engine::EngineCase probe;
  engine::ApplyModel(engine::ParseModel(name), &probe);
  return {std::string("skirt.model=") + engine::JointModelName(probe.skirt.model),
          std::string("big_end.model=") + engine::JointModelName(probe.big_end.model)};
}

StudyDesign ParseDesign(const Study& s, const json& j) {
  const std::string allowed =
      "must be \"full-factorial\", \"latin-hypercube\" or \"one-at-a-time\"";
  if (!j.is_string()) Bad(s, "design", JsonText(j), allowed);
  const std::string name = j.get<std::string>();
  for (StudyDesign d :
       {StudyDesign::kFullFactorial, StudyDesign::kLatinHypercube, StudyDesign::kOneAtATime}) {
    if (StudyDesignName(d) == name) return d;
  }
  Bad(s, "design", JsonText(j), allowed);
}

// A number level of `field` at `key`: finite, whole for integers, within the field's range.
double CheckedLevel(const Study& s, const engine::CaseField& field, const json& j,
                    const std::string& key) {
  if (!j.is_number() || !std::isfinite(j.get<double>())) {
    Bad(s, key + " (" + field.path + ")", JsonText(j), field.AllowedText());
  }
  const double v = j.get<double>();
  if (field.kind == engine::FieldKind::kInteger && v != std::floor(v)) {
    Bad(s, key, JsonText(j), "must be a whole number (" + field.path + " is an integer)");
  }
  field.Check(v, s.study_file.filename().string() + ": " + key + " (" + field.path + ")");
  return v;
}

StudyFactor ParseFactor(const Study& s, const json& j, const std::string& key) {
  if (!j.is_object())
    Bad(s, key, JsonText(j), "must be an object with \"path\" and \"levels\" or \"range\"");
  for (const auto& [name, value] : j.items()) {
    if (name != "path" && name != "levels" && name != "range" && name != "count") {
      Bad(s, key + "." + name, JsonText(value),
          "is not a key of a factor (allowed: path, levels, range, count)");
    }
  }
  if (!j.contains("path") || !j["path"].is_string()) {
    Bad(s, key + ".path", j.contains("path") ? JsonText(j["path"]) : "(missing)",
        "must be a case field's dotted path (`filmdyn case-fields` lists them) or \"model\"");
  }
  StudyFactor f;
  f.path = j["path"].get<std::string>();
  const bool has_levels = j.contains("levels"), has_range = j.contains("range");
  if (has_levels == has_range) {
    Bad(s, key, JsonText(j), "must have either \"levels\" (a list) or \"range\" ([low, high])");
  }
  if (j.contains("count") && !has_range) {
    Bad(s, key + ".count", JsonText(j["count"]), "goes with \"range\" only");
  }
  if (has_levels && (!j["levels"].is_array() || j["levels"].empty())) {
    Bad(s, key + ".levels", JsonText(j["levels"]), "must be a non-empty list");
  }
  const engine::CaseField* field = f.path == kModelFactor ? nullptr : engine::FindCaseField(f.path);
  if (f.path != kModelFactor && field == nullptr) {
    Bad(s, key + ".path", "\"" + f.path + "\"",
        "is not a case field (`filmdyn case-fields` lists every path) nor \"model\"" +
            engine::SimilarFieldsText(f.path));
  }
  const bool text = f.path == kModelFactor || field->kind == engine::FieldKind::kChoice;
  if (!text && field->kind != engine::FieldKind::kNumber &&
      field->kind != engine::FieldKind::kInteger) {
    Bad(s, key + ".path", "\"" + f.path + "\"",
        "cannot be a factor: only numbers, integers, choices (joint and cavitation models) and "
        "\"model\" can");
  }
  if (text) {
    if (has_range)
      Bad(s, key + ".range", JsonText(j["range"]), "needs a numeric field; give \"levels\"");
    for (std::size_t k = 0; k < j["levels"].size(); ++k) {
      const json& level = j["levels"][k];
      const std::string level_key = key + ".levels[" + std::to_string(k) + "]";
      if (!level.is_string()) Bad(s, level_key, JsonText(level), "must be a text");
      const std::string value = level.get<std::string>();
      try {
        if (field == nullptr) {
          engine::ParseModel(value);
        } else {
          engine::EngineCase probe;
          field->SetChoice(probe, value);
        }
      } catch (const InputError& e) {
        Bad(s, level_key, "\"" + value + "\"", e.allowed());
      }
      f.text_levels.push_back(value);
    }
  } else {
    f.integer = field->kind == engine::FieldKind::kInteger;
    f.unit = field->unit;
    if (has_levels) {
      for (std::size_t k = 0; k < j["levels"].size(); ++k) {
        f.levels.push_back(
            CheckedLevel(s, *field, j["levels"][k], key + ".levels[" + std::to_string(k) + "]"));
      }
    } else {
      const json& r = j["range"];
      if (!r.is_array() || r.size() != 2) {
        Bad(s, key + ".range", JsonText(r), "must be [low, high]");
      }
      const double lo = CheckedLevel(s, *field, r[0], key + ".range[0]");
      const double hi = CheckedLevel(s, *field, r[1], key + ".range[1]");
      if (!(lo < hi)) Bad(s, key + ".range", JsonText(r), "must have low < high");
      if (s.design == StudyDesign::kLatinHypercube) {
        if (j.contains("count")) {
          Bad(s, key + ".count", JsonText(j["count"]),
              "is not used by a Latin hypercube (it samples the range continuously); remove it");
        }
        f.range = std::pair{lo, hi};
      } else {
        if (!j.contains("count")) {
          Bad(s, key, JsonText(j),
              "a range needs \"count\" (the number of equally spaced levels) in this design");
        }
        const long count = IntegerAt(s, j["count"], key + ".count", 2, 1000);
        for (long k = 0; k < count; ++k) {
          double v = lo + (hi - lo) * double(k) / double(count - 1);
          if (f.integer) v = std::round(v);
          f.levels.push_back(v);
        }
        if (f.integer) {
          f.levels.erase(std::unique(f.levels.begin(), f.levels.end()), f.levels.end());
        }
      }
    }
  }
  // The same level twice would run the same point twice.
  for (std::size_t a = 0; a < f.level_count(); ++a) {
    for (std::size_t b = 0; b < a; ++b) {
      const bool same =
          f.is_text() ? f.text_levels[a] == f.text_levels[b] : f.levels[a] == f.levels[b];
      if (same) {
        Bad(s, key + ".levels[" + std::to_string(a) + "]",
            f.is_text() ? f.text_levels[a] : Number(f.levels[a]), "is given twice");
      }
    }
  }
  return f;
}

// The overrides ("path=value") that set a point's values: the model factor becomes the two
// joints' models.
// With `base` the study's own "set" entries first (the base case read from its case file).
std::vector<std::string> PointOverrides(const Study& study, const StudyPoint& point, bool base) {
  std::vector<std::string> sets = base ? study.base_overrides : std::vector<std::string>{};
  for (std::size_t f = 0; f < study.factors.size(); ++f) {
    const std::string& path = study.factors[f].path;
    if (path == kModelFactor) {
      for (const std::string& o : ModelOverrides(point.values[f])) sets.push_back(o);
    } else {
      sets.push_back(path + "=" + point.values[f]);
    }
  }
  return sets;
}

// The generator's raw output is specified by the standard (std::mt19937_64), the library's
// distributions and std::shuffle are not: both are done here, so a seed gives the same design
// with any standard library.
double Uniform01(std::mt19937_64& engine) { return double(engine() >> 11) * 0x1.0p-53; }

std::vector<StudyPoint> LatinHypercube(const Study& study) {
  const std::size_t n = std::size_t(study.points);
  std::mt19937_64 engine(study.seed);
  std::vector<StudyPoint> points(n);
  for (const StudyFactor& f : study.factors) {
    std::vector<std::size_t> strata(n);
    for (std::size_t k = 0; k < n; ++k) strata[k] = k;
    for (std::size_t k = n - 1; k > 0; --k) std::swap(strata[k], strata[engine() % (k + 1)]);
    for (std::size_t k = 0; k < n; ++k) {
      const double u = (double(strata[k]) + Uniform01(engine)) / double(n);  // in stratum k
      if (f.range) {
        double v = f.range->first + u * (f.range->second - f.range->first);
        if (f.integer) v = std::round(v);
        points[k].values.push_back(Number(v));
        points[k].numbers.push_back(v);
      } else {  // discrete levels: the stratum's share of the list
        const std::size_t level =
            std::min(f.level_count() - 1, std::size_t(u * double(f.level_count())));
        if (f.is_text()) {
          points[k].values.push_back(f.text_levels[level]);
          points[k].numbers.push_back(std::nullopt);
        } else {
          points[k].values.push_back(Number(f.levels[level]));
          points[k].numbers.push_back(f.levels[level]);
        }
      }
    }
  }
  return points;
}

// The value of factor `f` in the base case (one-at-a-time designs start there).
std::pair<std::string, std::optional<double>> BaseValue(const StudyFactor& f,
                                                        const engine::EngineCase& base) {
  if (f.path == kModelFactor) return {engine::ModelName(engine::ModelOfCase(base)), std::nullopt};
  const engine::CaseField* field = engine::FindCaseField(f.path);
  engine::EngineCase copy = base;
  if (field->kind == engine::FieldKind::kChoice) return {field->ChoiceName(copy), std::nullopt};
  const double v = field->get(copy);
  return {Number(v), v};
}

std::string ReadText(const fs::path& path, const std::string& what) {
  return ReadInputFile(path, what, kMaxStudyFileBytes);
}

std::string FactorHeader(const StudyFactor& f) {
  return f.path + (f.is_text() || f.unit.empty() ? "" : "[" + f.unit + "]");
}

}  // namespace

std::string StudyDesignName(StudyDesign design) {
  switch (design) {
    case StudyDesign::kFullFactorial:
      return "full-factorial";
    case StudyDesign::kLatinHypercube:
      return "latin-hypercube";
    case StudyDesign::kOneAtATime:
      return "one-at-a-time";
  }
  return "?";
}

Study ParseStudy(const std::string& text, const fs::path& path) {
  Study s;
  s.study_file = path;
  // A study file is a few levels deep (a factor's levels, a `set` list).
  const json j = io::ParseInputJson(text, path.filename().string(), 16, "a study file",
                                    /*bracketed=*/true);
  if (!j.is_object()) Bad(s, "(top level)", JsonText(j), "must be a JSON object");
  static const char* const kKeys[] = {"name", "case",    "set",    "design",      "points",
                                      "seed", "factors", "fields", "time_limit_s"};
  for (const auto& item : j.items()) {
    const std::string& key = item.key();
    const json& value = item.value();
    if (std::find_if(std::begin(kKeys), std::end(kKeys),
                     [&key](const char* k) { return key == k; }) == std::end(kKeys)) {
      Bad(s, key, JsonText(value),
          "is not a key of a study file (allowed: name, case, set, design, points, seed, "
          "factors, fields, time_limit_s)");
    }
  }
  s.name = j.value("name", path.stem().string());
  if (j.contains("name") && !j["name"].is_string())
    Bad(s, "name", JsonText(j["name"]), "must be a text");
  if (j.contains("case")) {
    if (!j["case"].is_string() || j["case"].get<std::string>().empty()) {
      Bad(s, "case", JsonText(j["case"]), "must be the path of a case file");
    }
    fs::path case_path = j["case"].get<std::string>();
    if (case_path.is_relative()) case_path = path.parent_path() / case_path;
    s.case_file = fs::absolute(case_path).lexically_normal();
  }
  if (j.contains("set")) {
    if (!j["set"].is_object())
      Bad(s, "set", JsonText(j["set"]), "must be an object of path: value");
    for (const auto& [key, value] : j["set"].items()) {
      const std::string set_key = "set." + key;
      if (key == kModelFactor) {  // the run model, as for a factor: both joints' models
        if (!value.is_string()) Bad(s, set_key, JsonText(value), "must be a run model's name");
        const std::string name = value.get<std::string>();
        try {
          for (const std::string& o : ModelOverrides(name)) s.base_overrides.push_back(o);
        } catch (const InputError& e) {
          Bad(s, set_key, "\"" + name + "\"", e.allowed());
        }
        continue;
      }
      const engine::CaseField* field = engine::FindCaseField(key);
      if (value.is_number()) {
        const double v = NumberAt(s, value, set_key);
        if (field != nullptr && (field->kind == engine::FieldKind::kNumber ||
                                 field->kind == engine::FieldKind::kInteger)) {
          if (field->kind == engine::FieldKind::kInteger && v != std::floor(v))
            Bad(s, set_key, JsonText(value), "must be a whole number");
          field->Check(v, s.study_file.filename().string() + ": " + set_key);
        }
        s.base_overrides.push_back(key + "=" + Number(v));
      } else if (value.is_string()) {
        s.base_overrides.push_back(key + "=" + value.get<std::string>());
      } else if (value.is_array() && field != nullptr &&
                 field->kind == engine::FieldKind::kNumberList) {
        std::string list;
        for (std::size_t k = 0; k < value.size(); ++k) {
          const std::string element = set_key + "[" + std::to_string(k) + "]";
          const double v = NumberAt(s, value[k], element);
          field->Check(v, s.study_file.filename().string() + ": " + element);
          list += (k ? "," : "") + Number(v);
        }
        s.base_overrides.push_back(key + "=[" + list + "]");
      } else {
        Bad(s, set_key, JsonText(value),
            field != nullptr && field->kind == engine::FieldKind::kNumberList
                ? "must be a list of numbers"
                : "must be a number or a text");
      }
    }
  }
  if (!j.contains("design")) Bad(s, "design", "(missing)", "must be given");
  s.design = ParseDesign(s, j["design"]);
  if (s.design == StudyDesign::kLatinHypercube) {
    if (!j.contains("points"))
      Bad(s, "points", "(missing)", "a Latin hypercube needs its number of points");
    s.points = int(IntegerAt(s, j["points"], "points", 2, long(kMaxPoints)));
    if (j.contains("seed")) {
      s.seed = std::uint64_t(IntegerAt(s, j["seed"], "seed", 0, 9007199254740991L));
    }
  } else {
    for (const char* key : {"points", "seed"}) {
      if (j.contains(key)) {
        Bad(s, key, JsonText(j[key]),
            "belongs to a Latin hypercube; the " + StudyDesignName(s.design) + " design has no " +
                key);
      }
    }
  }
  if (!j.contains("factors") || !j["factors"].is_array() || j["factors"].empty()) {
    Bad(s, "factors", j.contains("factors") ? JsonText(j["factors"]) : "(missing)",
        "must be a non-empty list of factors");
  }
  for (std::size_t k = 0; k < j["factors"].size(); ++k) {
    StudyFactor f = ParseFactor(s, j["factors"][k], "factors[" + std::to_string(k) + "]");
    for (const StudyFactor& other : s.factors) {
      const bool same_model =
          (f.path == kModelFactor &&
           (other.path == "skirt.model" || other.path == "big_end.model")) ||
          (other.path == kModelFactor && (f.path == "skirt.model" || f.path == "big_end.model"));
      if (other.path == f.path || same_model) {
        Bad(s, "factors[" + std::to_string(k) + "].path", "\"" + f.path + "\"",
            "is already a factor (\"model\" sets skirt.model and big_end.model)");
      }
    }
    s.factors.push_back(std::move(f));
  }
  if (s.design == StudyDesign::kFullFactorial) {
    double count = 1;
    for (const StudyFactor& f : s.factors) count *= double(f.level_count());
    if (count > double(kMaxPoints)) {
      Bad(s, "factors", fmt::format("{:g} points", count),
          fmt::format("a full factorial of these levels is too large (at most {} points); use "
                      "fewer levels or a Latin hypercube",
                      kMaxPoints));
    }
  }
  if (j.contains("fields")) {
    if (!j["fields"].is_boolean()) Bad(s, "fields", JsonText(j["fields"]), "must be true or false");
    s.write_fields = j["fields"].get<bool>();
  }
  if (j.contains("time_limit_s")) {
    s.time_limit_s = NumberAt(s, j["time_limit_s"], "time_limit_s");
    if (s.time_limit_s < 0)
      Bad(s, "time_limit_s", Number(s.time_limit_s), "must be ≥ 0 [s] (0 = none)");
  }
  return s;
}

Study ReadStudyFile(const fs::path& path) {
  return ParseStudy(ReadText(path, path.filename().string()), path);
}

Study ReadStudyFolder(const fs::path& dir) {
  const fs::path file = dir / "study.json";
  if (!fs::exists(file)) {
    throw InputError(dir.string(), "(folder)",
                     "is not a study folder: it has no study.json (`filmdyn study STUDY.json "
                     "--out DIR` makes one)");
  }
  Study study = ReadStudyFile(file);
  if (fs::exists(dir / kBaseCaseFile)) study.base_snapshot = dir / kBaseCaseFile;
  return study;
}

std::vector<StudyPoint> DesignPoints(const Study& study, const engine::EngineCase& base) {
  std::vector<StudyPoint> points;
  switch (study.design) {
    case StudyDesign::kFullFactorial: {
      std::size_t total = 1;
      for (const StudyFactor& f : study.factors) total *= f.level_count();
      for (std::size_t k = 0; k < total; ++k) {
        StudyPoint p;
        p.values.resize(study.factors.size());
        p.numbers.resize(study.factors.size());
        // k in mixed radix, the last factor's digit varying fastest.
        std::size_t rest = k;
        for (std::size_t f = study.factors.size(); f-- > 0;) {
          const StudyFactor& factor = study.factors[f];
          const std::size_t level = rest % factor.level_count();
          rest /= factor.level_count();
          if (factor.is_text()) {
            p.values[f] = factor.text_levels[level];
          } else {
            p.values[f] = Number(factor.levels[level]);
            p.numbers[f] = factor.levels[level];
          }
        }
        points.push_back(std::move(p));
      }
      break;
    }
    case StudyDesign::kLatinHypercube:
      points = LatinHypercube(study);
      break;
    case StudyDesign::kOneAtATime: {
      StudyPoint centre;
      for (const StudyFactor& f : study.factors) {
        const auto [text, number] = BaseValue(f, base);
        centre.values.push_back(text);
        centre.numbers.push_back(number);
      }
      points.push_back(centre);
      for (std::size_t f = 0; f < study.factors.size(); ++f) {
        const StudyFactor& factor = study.factors[f];
        for (std::size_t l = 0; l < factor.level_count(); ++l) {
          StudyPoint p = centre;
          if (factor.is_text()) {
            if (factor.text_levels[l] == centre.values[f]) continue;
            p.values[f] = factor.text_levels[l];
          } else {
            const double v = factor.levels[l];
            const double b = *centre.numbers[f];
            if (std::abs(v - b) <= 1e-12 * std::max(std::abs(v), std::abs(b))) continue;
            p.values[f] = Number(v);
            p.numbers[f] = v;
          }
          points.push_back(std::move(p));
        }
      }
      break;
    }
  }
  for (std::size_t k = 0; k < points.size(); ++k) {
    points[k].number = int(k + 1);
    points[k].folder = fmt::format("point-{:04d}", k + 1);
  }
  return points;
}

namespace {

// LoadCase names an override's error "--set <path>", as the command line writes it; a study's
// overrides are its file's "set" entries (a factor's own values are checked when parsed).
io::LoadedCase LoadWithOverrides(const Study& study, const std::vector<std::string>& overrides) {
  try {
    return io::LoadCase(study.case_file, overrides);
  } catch (const InputError& e) {
    // A rule between fields names one of them: when the study file's "set" gives that field (or
    // the list that element belongs to), the error is the set entry's.
    std::string named = e.field();
    if (const auto dot = named.rfind('.');
        dot != std::string::npos && dot + 1 < named.size() &&
        named.find_first_not_of("0123456789", dot + 1) == std::string::npos) {
      named.erase(dot);
    }
    if (std::any_of(study.base_overrides.begin(), study.base_overrides.end(),
                    [&named](const std::string& o) { return o.rfind(named + "=", 0) == 0; })) {
      throw InputError(study.study_file.filename().string() + ": set." + e.field(), e.value(),
                       e.allowed());
    }
    const std::string prefix = "--set";
    if (e.field().rfind(prefix, 0) != 0) throw;
    std::string path = e.field().substr(prefix.size());
    if (!path.empty() && path[0] == ' ') path.erase(0, 1);
    const bool from_set = std::any_of(
        study.base_overrides.begin(), study.base_overrides.end(),
        [&path](const std::string& o) { return path.empty() || o.rfind(path + "=", 0) == 0; });
    if (!from_set) throw;
    throw InputError(
        study.study_file.filename().string() + ": set" + (path.empty() ? "" : ".") + path,
        e.value(), e.allowed());
  }
}

}  // namespace

io::LoadedCase LoadStudyBase(const Study& study) {
  if (!study.base_snapshot.empty()) return io::LoadCase(study.base_snapshot);
  return LoadWithOverrides(study, study.base_overrides);
}

std::string BaseCaseText(const io::LoadedCase& base) {
  engine::EngineCase c = io::CaseWithInlineCurves(base);
  io::AbsoluteCaseFileNames(&c, base.directory);
  return io::CaseToJson(c).dump(2) + "\n";
}

Study PinStudyBase(const fs::path& dir, Study study, const io::LoadedCase& base) {
  const fs::path file = dir / kBaseCaseFile;
  const std::string text = BaseCaseText(base);
  if (fs::exists(file)) {
    const std::string pinned = ReadInputFile(file, "base case", io::kMaxCaseFileBytes);
    if (pinned != text) {
      // Both as base-case.json holds them (curves inline), so that only real changes show.
      const engine::EngineCase before = io::LoadCaseText(pinned, file.string());
      const engine::EngineCase now = io::LoadCaseText(text, "the case");
      std::string differences;
      for (const engine::CaseDifference& d :
           engine::DiffRunInputs({before, "", 0.0}, {now, "", 0.0})) {
        differences +=
            (differences.empty() ? "" : "; ") + d.path + " " + d.value_a + " → now " + d.value_b;
      }
      throw InputError(
          study.case_file.empty() ? std::string("case (the embedded default case)")
                                  : "case " + study.case_file.string(),
          differences.empty() ? std::string("(its files)") : differences,
          "differs from the base case the study in " + dir.string() + " began with (" +
              file.string() +
              "), so its points would mix two cases; restore the case, or run the study into "
              "a new folder");
    }
  } else {
    io::WriteFileAtomically(file, text);
  }
  study.base_snapshot = file;
  return study;
}

io::LoadedCase LoadPointCase(const Study& study, const StudyPoint& point) {
  try {
    if (!study.base_snapshot.empty())
      return io::LoadCase(study.base_snapshot, PointOverrides(study, point, false));
    return LoadWithOverrides(study, PointOverrides(study, point, true));
  } catch (const InputError& e) {
    std::string where;
    for (std::size_t f = 0; f < study.factors.size(); ++f) {
      where += (f ? ", " : "") + study.factors[f].path + " = " + point.values[f];
    }
    throw InputError("point " + std::to_string(point.number) + " (" + where + "): " + e.field(),
                     e.value(), e.allowed());
  }
}

std::string StudyJson(const Study& s) {
  json j;
  j["name"] = s.name;
  if (!s.case_file.empty()) j["case"] = s.case_file.string();
  if (!s.base_overrides.empty()) {
    json set = json::object();
    for (const std::string& o : s.base_overrides) {
      const auto eq = o.find('=');
      const std::string value = o.substr(eq + 1);
      double number = 0.0;
      if (ParseNumber(value, number)) {
        set[o.substr(0, eq)] = number;
      } else if (json list = json::parse(value, nullptr, false); list.is_array()) {
        set[o.substr(0, eq)] = list;  // a list field, as the file gave it
      } else {
        set[o.substr(0, eq)] = value;
      }
    }
    j["set"] = set;
  }
  j["design"] = StudyDesignName(s.design);
  if (s.design == StudyDesign::kLatinHypercube) {
    j["points"] = s.points;
    j["seed"] = s.seed;
  }
  json factors = json::array();
  for (const StudyFactor& f : s.factors) {
    json factor = {{"path", f.path}};
    if (f.is_text()) {
      factor["levels"] = f.text_levels;
    } else if (f.range) {
      factor["range"] = {f.range->first, f.range->second};
    } else {
      factor["levels"] = f.levels;
    }
    factors.push_back(factor);
  }
  j["factors"] = factors;
  j["fields"] = s.write_fields;
  j["time_limit_s"] = s.time_limit_s;
  return j.dump(2) + "\n";
}

void WriteDesignCsv(std::ostream& out, const Study& study, const std::vector<StudyPoint>& points) {
  out << "point,folder";
  for (const StudyFactor& f : study.factors) out << "," << io::CsvCell(FactorHeader(f));
  out << "\n";
  for (const StudyPoint& p : points) {
    out << p.number << "," << p.folder;
    for (const std::string& v : p.values) out << "," << io::CsvCell(v);
    out << "\n";
  }
}

std::string PointStateName(PointState state) {
  switch (state) {
    case PointState::kPending:
      return "pending";
    case PointState::kRunning:
      return "running";
    case PointState::kDone:
      return "done";
    case PointState::kIncomplete:
      return "incomplete";
    case PointState::kFailed:
      return "failed";
  }
  return "?";
}

PointState ReadPointState(const fs::path& folder, std::string* reason) {
  const fs::path file = folder / "summary.json";
  if (!fs::exists(file)) return PointState::kPending;
  io::RunSummary summary;
  try {
    summary = io::ReadSummaryJson(file);
  } catch (const std::exception& e) {
    if (reason) *reason = e.what();
    return PointState::kFailed;
  }
  if (reason) *reason = summary.message;
  if (summary.status == io::kRunningStatus) {
    if (io::OutputFolder::IsLocked(folder)) return PointState::kRunning;
    if (reason) *reason = "stopped before it wrote its results (killed, or out of time)";
    return PointState::kIncomplete;
  }
  if (summary.status == "completed" || summary.status == "not-converged") return PointState::kDone;
  if (summary.status == "failed") return PointState::kFailed;
  return PointState::kIncomplete;  // cancelled, time-limit
}

std::vector<StudyRow> CollectStudy(const fs::path& dir, const Study& study) {
  const engine::EngineCase base = LoadStudyBase(study).value;
  std::vector<StudyRow> rows;
  for (const StudyPoint& point : DesignPoints(study, base)) {
    StudyRow row;
    row.point = point;
    const fs::path folder = dir / point.folder;
    row.state = ReadPointState(folder, &row.reason);
    row.status = PointStateName(row.state);
    row.figures.assign(io::ComparisonFigures().size(), std::nullopt);
    if (row.state == PointState::kDone || row.state == PointState::kIncomplete ||
        row.state == PointState::kFailed) {
      try {
        const io::ComparisonRow figures = io::ReadComparisonRow(folder);
        row.status = figures.status;
        // A point stopped before it wrote its results (killed) left no wall time: empty, not 0.
        if (figures.status != "running") row.wall_time_s = figures.wall_time_s;
        row.figures = figures.figures;
        row.notes = figures.notes;
      } catch (const std::exception& e) {
        row.reason = e.what();
      }
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

void WriteStudyCsv(std::ostream& out, const Study& study, const std::vector<StudyRow>& rows) {
  out << "point,folder";
  for (const StudyFactor& f : study.factors) out << "," << io::CsvCell(FactorHeader(f));
  out << ",state,status,wall_time[s]";
  for (const io::ComparisonFigure& figure : io::ComparisonFigures()) out << "," << figure.key;
  out << ",reason,notes\n";
  for (const StudyRow& r : rows) {
    out << r.point.number << "," << r.point.folder;
    for (const std::string& v : r.point.values) out << "," << io::CsvCell(v);
    out << "," << PointStateName(r.state) << "," << io::CsvCell(r.status) << ",";
    if (r.wall_time_s) out << fmt::format("{:.3f}", *r.wall_time_s);
    for (const auto& value : r.figures) {
      out << ",";
      if (value) out << fmt::format("{:.10g}", *value);
    }
    out << "," << io::CsvCell(r.state == PointState::kDone ? std::string() : r.reason) << ","
        << io::CsvCell(io::NotesText(r.notes)) << "\n";
  }
}

std::size_t StudyFigureIndex(const std::string& key) {
  const auto& figures = io::ComparisonFigures();
  for (std::size_t k = 0; k < figures.size(); ++k) {
    if (figures[k].key == key) return k;
  }
  std::string keys;
  for (std::size_t k = 0; k < figures.size(); ++k) keys += (k ? ", " : "") + figures[k].key;
  throw InputError("--rank-by", key, "must be one of: " + keys);
}

std::size_t DefaultRankFigure(const std::vector<StudyRow>& rows) {
  const std::size_t bearing = StudyFigureIndex("mean_bearing_fpl[W]");
  const bool any = std::any_of(rows.begin(), rows.end(), [bearing](const StudyRow& r) {
    return r.state == PointState::kDone && r.figures[bearing];
  });
  return any ? bearing : StudyFigureIndex("mean_skirt_fpl[W]");
}

std::vector<MainEffect> MainEffects(const Study& study, const std::vector<StudyRow>& rows) {
  const std::size_t count = io::ComparisonFigures().size();
  // One at a time: the base point (the design's first) and the points that vary the factor
  // itself; a point that varies another factor has this one at its base value and would mix
  // that factor's effect into this one's base level.
  const StudyPoint* base = nullptr;
  if (study.design == StudyDesign::kOneAtATime) {
    for (const StudyRow& r : rows)
      if (r.point.number == 1) base = &r.point;
  }
  const auto on_line = [&](const StudyRow& r, std::size_t f) {
    if (base == nullptr) return true;
    for (std::size_t g = 0; g < study.factors.size(); ++g) {
      if (g != f && g < r.point.values.size() && r.point.values[g] != base->values[g]) return false;
    }
    return true;
  };
  std::vector<MainEffect> effects;
  for (std::size_t f = 0; f < study.factors.size(); ++f) {
    const StudyFactor& factor = study.factors[f];
    if (factor.range) continue;  // sampled continuously: no levels to average over
    MainEffect effect;
    effect.factor = f;
    for (std::size_t l = 0; l < factor.level_count(); ++l) {
      MainEffectLevel level;
      level.label = factor.is_text() ? factor.text_levels[l] : Number(factor.levels[l]);
      if (!factor.is_text()) level.value = factor.levels[l];
      // A point is at the level when its value, as written, is the level's (the values of a
      // point are the levels' own texts).
      std::vector<double> sum(count, 0.0);
      std::vector<int> have(count, 0);
      for (const StudyRow& r : rows) {
        if (r.state != PointState::kDone || r.point.values[f] != level.label || !on_line(r, f))
          continue;
        ++level.points;
        for (std::size_t k = 0; k < count && k < r.figures.size(); ++k) {
          if (r.figures[k]) {
            sum[k] += *r.figures[k];
            ++have[k];
          }
        }
      }
      level.means.assign(count, std::nullopt);
      for (std::size_t k = 0; k < count; ++k) {
        if (have[k]) level.means[k] = sum[k] / have[k];
      }
      effect.levels.push_back(std::move(level));
    }
    effects.push_back(std::move(effect));
  }
  return effects;
}

std::vector<std::size_t> RankedPoints(const std::vector<StudyRow>& rows, std::size_t figure,
                                      bool largest_first) {
  std::vector<std::size_t> ranked;
  for (std::size_t n = 0; n < rows.size(); ++n) {
    const StudyRow& r = rows[n];
    if (r.state == PointState::kDone && figure < r.figures.size() && r.figures[figure])
      ranked.push_back(n);
  }
  std::stable_sort(ranked.begin(), ranked.end(), [&](std::size_t a, std::size_t b) {
    const double va = *rows[a].figures[figure], vb = *rows[b].figures[figure];
    return largest_first ? va > vb : va < vb;
  });
  return ranked;
}

std::string StudyMarkdown(const Study& study, const std::vector<StudyRow>& rows,
                          const std::string& rank_by, bool largest_first) {
  const auto& figures = io::ComparisonFigures();
  std::ostringstream md;
  md << "# Study: " << study.name << "\n\n";
  md << "Design: " << StudyDesignName(study.design);
  if (study.design == StudyDesign::kLatinHypercube) {
    md << " (" << study.points << " points, seed " << study.seed << ")";
  }
  md << "; base case: "
     << (study.case_file.empty() ? std::string("the embedded default case")
                                 : study.case_file.filename().string())
     << ".\n\n";
  if (!study.base_overrides.empty()) {  // the study file's "set": every point runs with these
    // In the order of their paths: the same whether the study file or the study folder's copy of
    // it (whose "set" a JSON object keeps sorted) was read.
    std::vector<std::string> sets = study.base_overrides;
    std::sort(sets.begin(), sets.end());
    md << "Changed in the base case for every point: " << io::OverridesText(sets) << ".\n\n";
  }
  md << "| factor | levels (SI) |\n|---|---|\n";
  for (const StudyFactor& f : study.factors) {
    md << "| " << FactorHeader(f) << " | ";
    if (f.is_text()) {
      for (std::size_t k = 0; k < f.text_levels.size(); ++k)
        md << (k ? ", " : "") << f.text_levels[k];
    } else if (f.range) {
      md << Number(f.range->first) << " – " << Number(f.range->second) << " (sampled)";
    } else {
      for (std::size_t k = 0; k < f.levels.size(); ++k)
        md << (k ? ", " : "") << Number(f.levels[k]);
    }
    md << " |\n";
  }
  std::map<std::string, int> counts;
  for (const StudyRow& r : rows) ++counts[PointStateName(r.state)];
  md << "\nPoints: " << rows.size();
  for (const auto& [state, count] : counts) md << ", " << state << " " << count;
  md << ".\n\n";

  // The table: factors, status and the figures any point has.
  std::vector<std::size_t> shown;
  for (std::size_t k = 0; k < figures.size(); ++k) {
    if (std::any_of(rows.begin(), rows.end(), [k](const StudyRow& r) { return r.figures[k]; }))
      shown.push_back(k);
  }
  auto cell = [](const std::optional<double>& v, double scale) {
    return v ? fmt::format("{:.4g}", *v * scale) : std::string("–");
  };
  // A Markdown table row of cells.
  auto row = [](const std::vector<std::string>& cells) {
    std::string text = "|";
    for (const std::string& c : cells) fmt::format_to(std::back_inserter(text), " {} |", c);
    return text + "\n";
  };
  auto header = [&] {
    std::vector<std::string> names = {"point"};
    for (const StudyFactor& f : study.factors) names.push_back(FactorHeader(f));
    names.push_back("status");
    for (std::size_t k : shown) names.push_back(figures[k].display_name);
    return row(names) + row(std::vector<std::string>(names.size(), "---"));
  };
  auto line = [&](const StudyRow& r) {
    std::vector<std::string> cells = {std::to_string(r.point.number)};
    for (const std::string& v : r.point.values) cells.push_back(v);
    cells.push_back(r.status);
    for (std::size_t k : shown) cells.push_back(cell(r.figures[k], figures[k].display_scale));
    return row(cells);
  };
  md << "## Points\n\n" << header();
  for (const StudyRow& r : rows) md << line(r);
  bool noted = false;
  for (const StudyRow& r : rows) {
    for (const std::string& note : r.notes) {
      if (!noted) md << "\nNotes:\n\n";
      noted = true;
      md << "- point " << r.point.number << ": " << note << "\n";
    }
  }

  // Main effects: for each factor with discrete levels, the mean of each figure over the done
  // points at each level.
  if (!shown.empty()) {
    md << "\n## Main effects\n\nMean of each figure over the finished points at each level of a "
          "factor (all other factors as the design combines them).\n";
    for (const MainEffect& effect : MainEffects(study, rows)) {
      md << "\n### " << FactorHeader(study.factors[effect.factor]) << "\n\n| level | points |";
      std::string rule = "|---|---|";
      for (std::size_t k : shown) {
        md << " " << figures[k].display_name << " |";
        rule += "---|";
      }
      md << "\n" << rule << "\n";
      for (const MainEffectLevel& level : effect.levels) {
        md << "| " << level.label << " | " << level.points << " |";
        for (std::size_t k : shown)
          md << " " << cell(level.means[k], figures[k].display_scale) << " |";
        md << "\n";
      }
    }
  }

  if (!rank_by.empty()) {
    const std::size_t k = StudyFigureIndex(rank_by);
    const std::vector<std::size_t> ranked = RankedPoints(rows, k, largest_first);
    md << "\n## Best points by " << figures[k].display_name << " ("
       << (largest_first ? "largest" : "smallest") << " first)\n\n"
       << header();
    for (std::size_t n = 0; n < std::min<std::size_t>(10, ranked.size()); ++n)
      md << line(rows[ranked[n]]);
  }
  return md.str();
}

}  // namespace filmdyn::batch
