#include "core/io/run_summary.hpp"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <stdexcept>

#include "core/base/version.hpp"

namespace filmdyn::io {

using nlohmann::json;

RunSummary SummarizeRun(const std::string& case_name, const engine::RunConfig& config,
                        const engine::RunResult& result, const std::vector<OutputRow>& rows) {
  RunSummary s;
  s.filmdyn_version = std::string(Version());
  s.case_name = case_name;
  s.model = engine::ModelName(config.model);
  s.rpm = config.rpm;
  s.status = engine::StatusName(result.status);
  s.complete = result.status == engine::RunStatus::kCompleted;
  s.message = result.message;
  s.cycles = result.cycles;
  s.cycles_to_steady_state = result.cycles_to_steady_state;
  s.cycle_to_cycle_change = result.cycle_change;
  s.cycle_to_cycle_worst_quantity = result.worst_quantity;
  s.wall_time_s = result.wall_time;
  s.max_constraint_violation = result.max_constraint_violation;
  const auto& columns = ResultColumns();
  for (std::size_t c = 2; c < columns.size(); ++c) {  // crank angle and time have no extremes
    double lo = INFINITY, hi = -INFINITY;
    bool any = false;
    for (const OutputRow& row : rows) {
      if (const auto& v = row.*(columns[c].member)) {
        lo = std::min(lo, *v);
        hi = std::max(hi, *v);
        any = true;
      }
    }
    if (any) s.extremes[columns[c].header] = {lo, hi};
  }
  auto mean_of = [&rows](std::optional<double> OutputRow::*member) -> std::optional<double> {
    double sum = 0;
    int n = 0;
    for (const OutputRow& row : rows) {
      if (const auto& v = row.*member) {
        sum += *v;
        ++n;
      }
    }
    return n ? std::optional<double>(sum / n) : std::nullopt;
  };
  s.mean_fpl_skirt_w = mean_of(&OutputRow::skirt_fpl);
  s.mean_fpl_bearing_w = mean_of(&OutputRow::bearing_fpl);
  SolverSummary& v = s.solver;
  v.integrator = "CVODE BDF (SUNDIALS), dense Newton";
  v.steps = result.stats.steps;
  v.rejected_steps = result.stats.rejected_steps;
  v.newton_iterations = result.stats.newton_iterations;
  v.newton_failures = result.stats.newton_failures;
  v.rhs_evaluations = result.stats.rhs_evaluations;
  v.jacobian_evaluations = result.stats.jacobian_evaluations;
  v.reynolds_solves = result.reynolds_solves;
  v.baumgarte_alpha = config.engine_case.solver.baumgarte_alpha;
  v.baumgarte_beta = config.engine_case.solver.baumgarte_beta;
  v.relative_tolerance = config.integrator.relative_tolerance;
  s.pressure_peak_pa = config.pressure.PeakPressure();
  s.pressure_peak_crank_angle_deg = config.pressure.PeakAngle() * 180.0 / std::numbers::pi;
  return s;
}

namespace {

json Optional(const std::optional<double>& value) { return value ? json(*value) : json(nullptr); }

// The value of `key` in `object`, converted, or an error naming the key path.
template <typename T>
T Get(const json& object, const std::string& key, const std::string& where) {
  const std::string path = where.empty() ? key : where + "." + key;
  if (!object.is_object() || !object.contains(key)) {
    throw std::runtime_error("missing \"" + path + "\"");
  }
  try {
    return object.at(key).get<T>();
  } catch (const json::exception&) {
    throw std::runtime_error("\"" + path + "\" has the wrong type (" + object.at(key).type_name() +
                             ")");
  }
}

// Keys other than the run's identity may be absent (a summary of an earlier version, or of a
// run stopped before it knew them): they keep the struct's default. Present keys must have the
// right type.
template <typename T>
void Read(const json& object, const std::string& key, const std::string& where, T* value) {
  if (object.is_object() && object.contains(key)) *value = Get<T>(object, key, where);
}

std::optional<double> GetOptional(const json& object, const std::string& key,
                                  const std::string& where) {
  if (!object.is_object() || !object.contains(key) || object.at(key).is_null()) return std::nullopt;
  return Get<double>(object, key, where);
}

RunSummary FromJson(const json& j);

}  // namespace

json SummaryToJson(const RunSummary& s) {
  json j;
  j["filmdyn_version"] = s.filmdyn_version;
  j["case"] = s.case_name;
  j["model"] = s.model;
  j["rpm"] = s.rpm;
  j["status"] = s.status;
  j["complete"] = s.complete;
  j["message"] = s.message;
  j["cycles"] = s.cycles;
  j["cycles_to_steady_state"] = s.cycles_to_steady_state;
  j["cycle_to_cycle_change"] = s.cycle_to_cycle_change;
  j["cycle_to_cycle_worst_quantity"] = s.cycle_to_cycle_worst_quantity;
  j["wall_time_s"] = s.wall_time_s;
  j["max_constraint_violation"] = s.max_constraint_violation;
  json extremes = json::object();
  for (const auto& [column, e] : s.extremes) extremes[column] = {{"min", e.min}, {"max", e.max}};
  j["extremes"] = extremes;
  j["mean_fpl_w"] = {{"skirt", Optional(s.mean_fpl_skirt_w)},
                     {"bearing", Optional(s.mean_fpl_bearing_w)}};
  const SolverSummary& v = s.solver;
  j["solver"] = {{"integrator", v.integrator},
                 {"steps", v.steps},
                 {"rejected_steps", v.rejected_steps},
                 {"newton_iterations", v.newton_iterations},
                 {"newton_failures", v.newton_failures},
                 {"rhs_evaluations", v.rhs_evaluations},
                 {"jacobian_evaluations", v.jacobian_evaluations},
                 {"reynolds_solves", v.reynolds_solves},
                 {"baumgarte_alpha", v.baumgarte_alpha},
                 {"baumgarte_beta", v.baumgarte_beta},
                 {"relative_tolerance", v.relative_tolerance}};
  j["pressure_curve"] = {{"peak_pa", s.pressure_peak_pa},
                         {"peak_crank_angle_deg", s.pressure_peak_crank_angle_deg}};
  return j;
}

namespace {

RunSummary FromJson(const json& j) {
  if (!j.is_object()) throw std::runtime_error("not a JSON object");
  RunSummary s;
  s.model = Get<std::string>(j, "model", "");
  s.rpm = Get<double>(j, "rpm", "");
  s.status = Get<std::string>(j, "status", "");
  Read(j, "filmdyn_version", "", &s.filmdyn_version);
  Read(j, "case", "", &s.case_name);
  Read(j, "complete", "", &s.complete);
  Read(j, "message", "", &s.message);
  Read(j, "cycles", "", &s.cycles);
  Read(j, "cycles_to_steady_state", "", &s.cycles_to_steady_state);
  Read(j, "cycle_to_cycle_change", "", &s.cycle_to_cycle_change);
  Read(j, "cycle_to_cycle_worst_quantity", "", &s.cycle_to_cycle_worst_quantity);
  Read(j, "wall_time_s", "", &s.wall_time_s);
  Read(j, "max_constraint_violation", "", &s.max_constraint_violation);
  json extremes = json::object();
  Read(j, "extremes", "", &extremes);
  if (!extremes.is_object()) throw std::runtime_error("\"extremes\" is not an object");
  for (const auto& [column, e] : extremes.items()) {
    s.extremes[column] = {Get<double>(e, "min", "extremes." + column),
                          Get<double>(e, "max", "extremes." + column)};
  }
  json fpl = json::object();
  Read(j, "mean_fpl_w", "", &fpl);
  s.mean_fpl_skirt_w = GetOptional(fpl, "skirt", "mean_fpl_w");
  s.mean_fpl_bearing_w = GetOptional(fpl, "bearing", "mean_fpl_w");
  json solver = json::object();
  Read(j, "solver", "", &solver);
  SolverSummary& v = s.solver;
  Read(solver, "integrator", "solver", &v.integrator);
  Read(solver, "steps", "solver", &v.steps);
  Read(solver, "rejected_steps", "solver", &v.rejected_steps);
  Read(solver, "newton_iterations", "solver", &v.newton_iterations);
  Read(solver, "newton_failures", "solver", &v.newton_failures);
  Read(solver, "rhs_evaluations", "solver", &v.rhs_evaluations);
  Read(solver, "jacobian_evaluations", "solver", &v.jacobian_evaluations);
  Read(solver, "reynolds_solves", "solver", &v.reynolds_solves);
  Read(solver, "baumgarte_alpha", "solver", &v.baumgarte_alpha);
  Read(solver, "baumgarte_beta", "solver", &v.baumgarte_beta);
  Read(solver, "relative_tolerance", "solver", &v.relative_tolerance);
  json curve = json::object();
  Read(j, "pressure_curve", "", &curve);
  Read(curve, "peak_pa", "pressure_curve", &s.pressure_peak_pa);
  Read(curve, "peak_crank_angle_deg", "pressure_curve", &s.pressure_peak_crank_angle_deg);
  return s;
}

}  // namespace

RunSummary SummaryFromJson(const json& j) {
  try {
    return FromJson(j);
  } catch (const std::runtime_error& error) {
    throw std::runtime_error(std::string("summary.json: ") + error.what());
  }
}

void WriteSummaryJson(const std::filesystem::path& path, const RunSummary& summary) {
  std::ofstream out(path);
  out << SummaryToJson(summary).dump(2) << "\n";
  out.close();
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

RunSummary ReadSummaryJson(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  json j;
  try {
    in >> j;
  } catch (const json::exception& error) {
    throw std::runtime_error(path.string() + ": not valid JSON (" + error.what() + ")");
  }
  try {
    return FromJson(j);
  } catch (const std::runtime_error& error) {
    throw std::runtime_error(path.string() + ": " + error.what());
  }
}

}  // namespace filmdyn::io
