#include "core/io/run_summary.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "core/base/angles.hpp"
#include "core/base/version.hpp"
#include "core/engine/error_estimate.hpp"
#include "core/engine/film_joints.hpp"
#include "core/io/output_files.hpp"
#include "core/io/run_kpis.hpp"
#include "core/lubrication/oil_catalogue.hpp"

namespace filmdyn::io {

using nlohmann::json;

std::optional<engine::CycleScatter> ReportedCycleScatter(const engine::RunResult& result) {
  if (result.status != engine::RunStatus::kNotConverged &&
      result.status != engine::RunStatus::kCompleted)
    return std::nullopt;
  return engine::ScatterOverCycles(result.cycle_headlines, result.samples,
                                   engine::SamplesSpanACycle(result.samples));
}

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
  s.reported_cycle = result.reported_cycle;
  s.cycles_to_steady_state = result.cycles_to_steady_state;
  s.cycle_to_cycle_change = result.cycle_change;
  s.cycle_to_cycle_worst_quantity = result.worst_quantity;
  s.cycle_to_cycle_changes = result.cycle_changes;
  s.wall_time_s = result.wall_time;
  s.max_constraint_violation = result.max_constraint_violation;
  const auto& columns = ResultColumns();
  const bool whole_cycle = engine::SamplesSpanACycle(result.samples);
  const std::size_t n = rows.size();
  for (std::size_t c = 2; c < columns.size(); ++c) {  // crank angle and time have no extremes
    const auto value = [&](std::size_t k) { return rows[k].*(columns[c].member); };
    std::optional<std::size_t> lo, hi;
    for (std::size_t k = 0; k < n; ++k) {
      if (const auto& v = value(k); v && std::isfinite(*v)) {  // a failed step's NaN: no extreme
        if (!lo || *v < *value(*lo)) lo = k;
        if (!hi || *v > *value(*hi)) hi = k;
      }
    }
    if (!lo) continue;
    // The extreme's magnitude against the samples beside it (none past an end of samples that
    // are not a whole cycle, nor where the column is empty).
    const auto spike = [&](std::size_t at) {
      const auto magnitude = [&](std::optional<std::size_t> k) {
        const auto& v = k ? value(*k) : std::optional<double>();
        return v ? std::abs(*v) : std::numeric_limits<double>::quiet_NaN();
      };
      const engine::SamplesBeside beside = engine::SamplesBesideOf(n, at, whole_cycle);
      return engine::NeighbourRatio(std::abs(*value(at)), magnitude(beside.before),
                                    magnitude(beside.after)) > engine::kUnresolvedPeakRatio;
    };
    // + 0.0: a signed zero (e.g. a friction power of -0) reads 0.
    s.extremes[columns[c].header] = {*value(*lo) + 0.0, *value(*hi) + 0.0, spike(*lo), spike(*hi)};
  }
  s.headline = engine::HeadlineFigures(result.samples,
                                       {&result.motion, config.engine_case.geometry.piston_mass,
                                        config.engine_case.geometry.piston_inertia});
  for (const engine::HeadlineFigure& f : s.headline) {
    if (f.key == "skirt_fpl_mean[W]") s.mean_fpl_skirt_w = f.value;
    if (f.key == "bearing_fpl_mean[W]") s.mean_fpl_bearing_w = f.value;
  }
  s.error_estimate = result.error_estimate;
  s.cycle_scatter = ReportedCycleScatter(result);
  s.warnings = RunWarnings(config, result);
  s.kpis = RunKpisOf(config, result);
  auto oil_used = [&](engine::JointOil oil, const std::string& joint,
                      const std::optional<double>& balanced) {
    if (balanced) oil.temperature = *balanced;  // from the joint's heat balance
    const auto at = engine::JointOilAt(config.engine_case, oil, joint);
    const lubrication::OilSpec& spec = engine::JointOilSpec(config.engine_case, oil);
    JointOilUsed used{
        oil.temperature,
        at.viscosity,
        oil.source == engine::OilSource::kOwn ? "own" : "lubricant",
        lubrication::ToString(spec.model),
        lubrication::ToString(spec.pressure_law),
        at.pressure.InitialCoefficient(),
        spec.model == lubrication::ViscosityModel::kGrade
            ? std::string(lubrication::OilCatalogue()[spec.grade].key)
            : std::string(),
        lubrication::ToString(spec.shear_thinning),
        at.shear.ratio,
        at.shear.exponent,
        at.shear.critical_rate,
        engine::JointBulkModulus(config.engine_case, oil, joint,
                                 joint == "skirt" ? config.engine_case.skirt.cavitation
                                                  : config.engine_case.big_end.cavitation),
        std::string()};
    if (used.bulk_modulus > 0.0) used.density_law = lubrication::ToString(spec.density_law);
    return used;
  };
  if (s.kpis.skirt) {
    const engine::JointFit fit = engine::SkirtFit(config.engine_case);
    s.clearance_skirt = RunSummary::Clearance{fit.cold_clearance, fit.hot_clearance};
  }
  if (s.kpis.big_end) {
    const engine::JointFit fit = engine::BigEndFit(config.engine_case);
    s.clearance_big_end = RunSummary::Clearance{fit.cold_clearance, fit.hot_clearance};
  }
  if (s.kpis.skirt)
    s.oil_skirt = oil_used(config.engine_case.skirt.oil, "skirt", result.skirt_film_temperature);
  if (s.kpis.big_end) {
    s.oil_big_end =
        oil_used(config.engine_case.big_end.oil, "big_end", result.big_end_film_temperature);
  }
  if (result.heat_balance) {
    s.heat_balance = HeatBalanceUsed{result.heat_balance->runs, result.heat_balance->residual,
                                     result.heat_balance->converged};
  }
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
  s.pressure_peak_crank_angle_deg = config.pressure.PeakAngle() * kDegreesPerRadian;
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

// "kpis": one object per lubricated joint, keys with their units in brackets.
json JointKpisToJson(const JointKpis& k) {
  json o;
  o["min_moft[m]"] = k.min_moft;
  o["min_moft_crank_angle[deg]"] = k.min_moft_crank_angle_deg;
  o["min_moft_position_angle[deg]"] = k.min_moft_position.angle_deg;
  if (k.min_moft_position.axial_m) o["min_moft_position_axial[m]"] = *k.min_moft_position.axial_m;
  o["peak_pressure[Pa]"] = k.peak_pressure;
  o["peak_pressure_crank_angle[deg]"] = Optional(k.peak_pressure_crank_angle_deg);
  o["peak_contact_pressure[Pa]"] = k.peak_contact_pressure;
  o["peak_contact_pressure_crank_angle[deg]"] = Optional(k.peak_contact_pressure_crank_angle_deg);
  o["max_deformation[m]"] = k.max_deformation;
  o["max_deformation_crank_angle[deg]"] = Optional(k.max_deformation_crank_angle_deg);
  o["mean_fpl[W]"] = Optional(k.mean_fpl);
  o["fmep[Pa]"] = Optional(k.fmep);
  o["fmep_share[-]"] = Optional(k.fmep_share);
  o["oil_in_per_cycle[m^3]"] = Optional(k.oil_in_per_cycle);
  o["oil_out_per_cycle[m^3]"] = Optional(k.oil_out_per_cycle);
  o["oil_balance[-]"] = Optional(k.oil_balance);
  if (k.mean_wetted_fraction) o["mean_wetted_fraction[-]"] = *k.mean_wetted_fraction;
  if (k.max_eps) {
    o["max_eps[-]"] = *k.max_eps;
    o["max_eps_crank_angle[deg]"] = Optional(k.max_eps_crank_angle_deg);
  }
  if (k.slap) {
    json events = json::array();
    for (const SlapEvent& e : k.slap->events) {
      events.push_back({{"crank_angle[deg]", e.crank_angle_deg},
                        {"energy[J]", e.energy},
                        {"direction", e.to_thrust ? "to_thrust" : "to_anti_thrust"}});
    }
    o["slap_events"] = events;
    o["slap_energy_max[J]"] = Optional(k.slap->energy_max);
    o["slap_energy_max_crank_angle[deg]"] = Optional(k.slap->energy_max_crank_angle_deg);
    o["slap_energy_sum[J]"] = Optional(k.slap->energy_sum);
  }
  return o;
}

JointKpis JointKpisFromJson(const json& o, const std::string& at) {
  if (!o.is_object()) throw std::runtime_error("\"" + at + "\" is not an object");
  JointKpis k;
  k.min_moft = Get<double>(o, "min_moft[m]", at);
  Read(o, "min_moft_crank_angle[deg]", at, &k.min_moft_crank_angle_deg);
  Read(o, "min_moft_position_angle[deg]", at, &k.min_moft_position.angle_deg);
  k.min_moft_position.axial_m = GetOptional(o, "min_moft_position_axial[m]", at);
  Read(o, "peak_pressure[Pa]", at, &k.peak_pressure);
  k.peak_pressure_crank_angle_deg = GetOptional(o, "peak_pressure_crank_angle[deg]", at);
  Read(o, "peak_contact_pressure[Pa]", at, &k.peak_contact_pressure);
  k.peak_contact_pressure_crank_angle_deg =
      GetOptional(o, "peak_contact_pressure_crank_angle[deg]", at);
  // Summaries written before elastic surfaces existed have none: rigid.
  k.max_deformation = GetOptional(o, "max_deformation[m]", at).value_or(0.0);
  k.max_deformation_crank_angle_deg = GetOptional(o, "max_deformation_crank_angle[deg]", at);
  k.mean_fpl = GetOptional(o, "mean_fpl[W]", at);
  k.fmep = GetOptional(o, "fmep[Pa]", at);
  k.fmep_share = GetOptional(o, "fmep_share[-]", at);
  k.max_eps = GetOptional(o, "max_eps[-]", at);
  k.oil_in_per_cycle = GetOptional(o, "oil_in_per_cycle[m^3]", at);
  k.oil_out_per_cycle = GetOptional(o, "oil_out_per_cycle[m^3]", at);
  k.oil_balance = GetOptional(o, "oil_balance[-]", at);
  k.mean_wetted_fraction = GetOptional(o, "mean_wetted_fraction[-]", at);
  k.max_eps_crank_angle_deg = GetOptional(o, "max_eps_crank_angle[deg]", at);
  if (o.contains("slap_events") || o.contains("slap_energy_sum[J]")) {
    PistonSlap slap;
    json events = json::array();
    Read(o, "slap_events", at, &events);
    if (!events.is_array()) throw std::runtime_error("\"" + at + ".slap_events\" is not an array");
    for (std::size_t i = 0; i < events.size(); ++i) {
      const std::string where = at + ".slap_events." + std::to_string(i);
      SlapEvent e;
      e.crank_angle_deg = Get<double>(events[i], "crank_angle[deg]", where);
      e.energy = Get<double>(events[i], "energy[J]", where);
      const std::string direction = Get<std::string>(events[i], "direction", where);
      if (direction != "to_thrust" && direction != "to_anti_thrust") {
        throw std::runtime_error("\"" + where + ".direction\" is \"" + direction +
                                 "\" (allowed: to_thrust, to_anti_thrust)");
      }
      e.to_thrust = direction == "to_thrust";
      slap.events.push_back(e);
    }
    slap.energy_max = GetOptional(o, "slap_energy_max[J]", at);
    slap.energy_max_crank_angle_deg = GetOptional(o, "slap_energy_max_crank_angle[deg]", at);
    slap.energy_sum = GetOptional(o, "slap_energy_sum[J]", at);
    k.slap = std::move(slap);
  }
  return k;
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
  j["reported_cycle"] = s.reported_cycle;
  j["cycles_to_steady_state"] = s.cycles_to_steady_state;
  // No cycle compared yet (a run stopped in its first cycle or its run-in): no change, null —
  // a 0 would read as perfectly periodic.
  const bool compared = !s.cycle_to_cycle_changes.empty();
  j["cycle_to_cycle_change"] = compared ? json(s.cycle_to_cycle_change) : json(nullptr);
  j["cycle_to_cycle_worst_quantity"] =
      compared ? json(s.cycle_to_cycle_worst_quantity) : json(nullptr);
  json changes = json::array();  // a diverging (non-finite) change as the largest double
  for (double c : s.cycle_to_cycle_changes)
    changes.push_back(std::isfinite(c) ? c : std::numeric_limits<double>::max());
  j["cycle_to_cycle_changes"] = changes;
  j["wall_time_s"] = s.wall_time_s;
  j["max_constraint_violation"] = s.max_constraint_violation;
  json extremes = json::object();
  for (const auto& [column, e] : s.extremes) {
    json o = {{"min", e.min}, {"max", e.max}};
    if (e.min_spike) o["min_spike"] = true;
    if (e.max_spike) o["max_spike"] = true;
    extremes[column] = o;
  }
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
  json headline = json::object();
  for (const engine::HeadlineFigure& f : s.headline) headline[f.key] = f.value;
  j["headline"] = headline;
  if (s.cycle_scatter) {
    json figures = json::object();
    for (const engine::FigureScatter& f : s.cycle_scatter->figures)
      figures[f.figure.key] = {
          {"min", f.min}, {"max", f.max}, {"resolved_in_time", f.resolved_in_time}};
    j["cycle_scatter"] = {{"first_cycle", s.cycle_scatter->first_cycle},
                          {"last_cycle", s.cycle_scatter->last_cycle},
                          {"figures", figures}};
  } else {
    j["cycle_scatter"] = nullptr;
  }
  const engine::ErrorEstimate& e = s.error_estimate;
  json figures = json::object();
  for (const engine::FigureError& f : e.figures) {
    figures[f.figure.key] = {
        {"value", f.figure.value},
        {"coarse_value", f.coarse_value},
        {"error", f.error},
        {"relative", f.relative},
        {"order", f.figure.order},
        // No best estimate from two samples of a spike that neither
        // resolves (it gave a negative pressure): null.
        {"extrapolated", f.resolved_in_time ? json(f.figure.value + f.error) : json(nullptr)},
        {"resolved_in_time", f.resolved_in_time},
        {"far_companion", f.far_companion}};
    if (f.crank_angle && f.extrapolated_crank_angle) {
      json& o = figures[f.figure.key];
      o["crank_angle[deg]"] = engine::CycleCrankAngleDeg(*f.crank_angle);
      o["extrapolated_crank_angle[deg]"] = engine::CycleCrankAngleDeg(*f.extrapolated_crank_angle);
      o["extreme_elsewhere"] = f.extreme_elsewhere;
    }
  }
  j["discretisation_error"] = {
      {"status", e.status},
      {"message", e.message},
      {"summary", e.Summary()},
      {"warning", e.Warn()},
      {"threshold", e.threshold},
      {"worst_relative", e.worst_relative},
      {"worst_figure", e.worst_label},
      {"coarse_run",
       {{"skirt_spacing_ratio", e.skirt_ratio},
        {"big_end_spacing_ratio", e.big_end_ratio},
        {"tolerance_factor", e.tolerance_factor},
        {"wall_time_s", e.coarse_wall_time},
        {"steps", e.coarse_steps}}},
      {"figures", figures}};
  json warnings = json::array();
  for (const RunWarning& w : s.warnings) {
    json o = {{"code", w.code},       {"joint", w.joint},
              {"message", w.message}, {"value", w.value},
              {"limit", w.limit},     {"crank_angle_deg", Optional(w.crank_angle_deg)}};
    json ranges = json::array();
    for (const auto& [from, to] : w.crank_angle_ranges_deg) ranges.push_back({from, to});
    o["crank_angle_ranges_deg"] = ranges;
    o["position_angle_deg"] = Optional(w.position_angle_deg);
    o["position_axial_m"] = Optional(w.position_axial_m);
    o["fields"] = w.fields;
    warnings.push_back(o);
  }
  j["warnings"] = warnings;
  json kpis = json::object();
  if (s.kpis.skirt) kpis["skirt"] = JointKpisToJson(*s.kpis.skirt);
  if (s.kpis.big_end) kpis["big_end"] = JointKpisToJson(*s.kpis.big_end);
  j["kpis"] = kpis;
  json oil = json::object();
  for (const auto& [name, used] : {std::pair{"skirt", &s.oil_skirt}, {"big_end", &s.oil_big_end}}) {
    if (!*used) continue;
    const JointOilUsed& u = **used;
    oil[name] = {{"temperature[K]", u.temperature_k},
                 {"viscosity[Pa*s]", u.viscosity_pa_s},
                 {"source", u.source},
                 {"viscosity_model", u.viscosity_model},
                 {"pressure_viscosity", u.pressure_viscosity},
                 {"pressure_viscosity_coefficient[1/Pa]", u.pressure_viscosity_coefficient},
                 {"shear_thinning", u.shear_thinning},
                 {"bulk_modulus[Pa]", u.bulk_modulus}};
    if (!u.grade.empty()) oil[name]["grade"] = u.grade;
    if (!u.density_law.empty()) oil[name]["density_law"] = u.density_law;
    if (u.shear_thinning != "none") {
      oil[name]["cross_ratio[-]"] = u.cross_ratio;
      oil[name]["cross_exponent[-]"] = u.cross_exponent;
      oil[name]["cross_critical_rate[1/s]"] = u.cross_critical_rate;
    }
  }
  j["oil"] = oil;
  if (s.heat_balance) {
    j["heat_balance"] = {{"runs", s.heat_balance->runs},
                         {"residual[K]", s.heat_balance->residual},
                         {"converged", s.heat_balance->converged}};
  }
  json clearance = json::object();
  for (const auto& [name, c] :
       {std::pair{"skirt", &s.clearance_skirt}, std::pair{"big_end", &s.clearance_big_end}}) {
    if (*c) clearance[name] = {{"cold[m]", (*c)->cold}, {"hot[m]", (*c)->hot}};
  }
  j["clearance"] = clearance;
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
  s.reported_cycle = s.cycles;  // a summary written before it existed: the last cycle
  Read(j, "reported_cycle", "", &s.reported_cycle);
  Read(j, "cycles_to_steady_state", "", &s.cycles_to_steady_state);
  s.cycle_to_cycle_change = GetOptional(j, "cycle_to_cycle_change", "").value_or(0.0);
  if (j.contains("cycle_to_cycle_worst_quantity") &&
      !j.at("cycle_to_cycle_worst_quantity").is_null())
    Read(j, "cycle_to_cycle_worst_quantity", "", &s.cycle_to_cycle_worst_quantity);
  Read(j, "cycle_to_cycle_changes", "", &s.cycle_to_cycle_changes);  // absent before: empty
  Read(j, "wall_time_s", "", &s.wall_time_s);
  Read(j, "max_constraint_violation", "", &s.max_constraint_violation);
  json extremes = json::object();
  Read(j, "extremes", "", &extremes);
  if (!extremes.is_object()) throw std::runtime_error("\"extremes\" is not an object");
  for (const auto& [column, e] : extremes.items()) {
    ColumnExtremes& x = s.extremes[column];
    x.min = Get<double>(e, "min", "extremes." + column);
    x.max = Get<double>(e, "max", "extremes." + column);
    Read(e, "min_spike", "extremes." + column, &x.min_spike);  // absent: resolved (and before)
    Read(e, "max_spike", "extremes." + column, &x.max_spike);
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
  json headline = json::object();
  Read(j, "headline", "", &headline);
  if (!headline.is_object()) throw std::runtime_error("\"headline\" is not an object");
  for (const auto& [key, value] : headline.items()) {
    s.headline.push_back(engine::HeadlineFigureFor(key, Get<double>(headline, key, "headline")));
  }
  if (j.contains("cycle_scatter") && !j.at("cycle_scatter").is_null()) {
    const json& o = j.at("cycle_scatter");
    engine::CycleScatter scatter;
    scatter.first_cycle = Get<int>(o, "first_cycle", "cycle_scatter");
    scatter.last_cycle = Get<int>(o, "last_cycle", "cycle_scatter");
    json figures = json::object();
    Read(o, "figures", "cycle_scatter", &figures);
    if (!figures.is_object())
      throw std::runtime_error("\"cycle_scatter.figures\" is not an object");
    for (const engine::HeadlineFigure& f : s.headline) {  // the reported values, in their order
      if (!figures.contains(f.key)) continue;
      const std::string where = "cycle_scatter.figures." + f.key;
      engine::FigureScatter& fs = scatter.figures.emplace_back(
          engine::FigureScatter{.figure = f,
                                .min = Get<double>(figures.at(f.key), "min", where),
                                .max = Get<double>(figures.at(f.key), "max", where)});
      Read(figures.at(f.key), "resolved_in_time", where, &fs.resolved_in_time);  // absent: true
    }
    s.cycle_scatter = scatter;
  }
  json error = json::object();
  Read(j, "discretisation_error", "", &error);
  engine::ErrorEstimate& e = s.error_estimate;
  Read(error, "status", "discretisation_error", &e.status);
  Read(error, "message", "discretisation_error", &e.message);
  Read(error, "threshold", "discretisation_error", &e.threshold);
  Read(error, "worst_relative", "discretisation_error", &e.worst_relative);
  Read(error, "worst_figure", "discretisation_error", &e.worst_label);
  json coarse = json::object();
  Read(error, "coarse_run", "discretisation_error", &coarse);
  const std::string where = "discretisation_error.coarse_run";
  Read(coarse, "skirt_spacing_ratio", where, &e.skirt_ratio);
  Read(coarse, "big_end_spacing_ratio", where, &e.big_end_ratio);
  Read(coarse, "tolerance_factor", where, &e.tolerance_factor);
  Read(coarse, "wall_time_s", where, &e.coarse_wall_time);
  Read(coarse, "steps", where, &e.coarse_steps);
  json figures = json::object();
  Read(error, "figures", "discretisation_error", &figures);
  if (!figures.is_object()) {
    throw std::runtime_error("\"discretisation_error.figures\" is not an object");
  }
  for (const auto& [key, f] : figures.items()) {
    const std::string at = "discretisation_error.figures." + key;
    engine::FigureError fe;
    fe.figure = engine::HeadlineFigureFor(key, Get<double>(f, "value", at));
    fe.coarse_value = Get<double>(f, "coarse_value", at);
    fe.error = Get<double>(f, "error", at);
    fe.relative = Get<double>(f, "relative", at);
    Read(f, "order", at, &fe.figure.order);
    Read(f, "resolved_in_time", at, &fe.resolved_in_time);  // absent before: resolved
    Read(f, "far_companion", at, &fe.far_companion);        // absent before: not far
    // A curve's extreme (absent for the other figures and in older summaries).
    const std::optional<double> own = GetOptional(f, "crank_angle[deg]", at);
    const std::optional<double> extrapolated = GetOptional(f, "extrapolated_crank_angle[deg]", at);
    if (own && extrapolated) {
      fe.crank_angle = *own * kRadiansPerDegree;
      fe.extrapolated_crank_angle = *extrapolated * kRadiansPerDegree;
      Read(f, "extreme_elsewhere", at, &fe.extreme_elsewhere);
    }
    e.figures.push_back(fe);
  }
  json warnings = json::array();
  Read(j, "warnings", "", &warnings);
  if (!warnings.is_array()) throw std::runtime_error("\"warnings\" is not an array");
  for (std::size_t k = 0; k < warnings.size(); ++k) {
    const json& o = warnings[k];
    const std::string at = "warnings." + std::to_string(k);
    RunWarning w;
    w.code = Get<std::string>(o, "code", at);
    Read(o, "joint", at, &w.joint);
    Read(o, "message", at, &w.message);
    Read(o, "value", at, &w.value);
    Read(o, "limit", at, &w.limit);
    w.crank_angle_deg = GetOptional(o, "crank_angle_deg", at);
    json ranges = json::array();
    Read(o, "crank_angle_ranges_deg", at, &ranges);
    if (!ranges.is_array())
      throw std::runtime_error("\"" + at + ".crank_angle_ranges_deg\" is not an array");
    for (const json& r : ranges) {
      if (!r.is_array() || r.size() != 2 || !r[0].is_number() || !r[1].is_number()) {
        throw std::runtime_error("\"" + at + ".crank_angle_ranges_deg\" holds no [from, to] pair");
      }
      w.crank_angle_ranges_deg.push_back({r[0].get<double>(), r[1].get<double>()});
    }
    w.position_angle_deg = GetOptional(o, "position_angle_deg", at);
    w.position_axial_m = GetOptional(o, "position_axial_m", at);
    Read(o, "fields", at, &w.fields);
    s.warnings.push_back(std::move(w));
  }
  json kpis = json::object();  // absent in a summary written before the KPIs existed
  Read(j, "kpis", "", &kpis);
  if (!kpis.is_object()) throw std::runtime_error("\"kpis\" is not an object");
  if (kpis.contains("skirt")) s.kpis.skirt = JointKpisFromJson(kpis.at("skirt"), "kpis.skirt");
  if (kpis.contains("big_end")) {
    s.kpis.big_end = JointKpisFromJson(kpis.at("big_end"), "kpis.big_end");
  }
  json oil = json::object();  // absent in a summary written before it existed
  Read(j, "oil", "", &oil);
  if (!oil.is_object()) throw std::runtime_error("\"oil\" is not an object");
  for (const auto& [name, used] :
       {std::pair{"skirt", &s.oil_skirt}, std::pair{"big_end", &s.oil_big_end}}) {
    if (!oil.contains(name)) continue;
    const json& o = oil.at(name);
    const std::string at = std::string("oil.") + name;
    JointOilUsed u;
    Read(o, "temperature[K]", at, &u.temperature_k);
    Read(o, "viscosity[Pa*s]", at, &u.viscosity_pa_s);
    Read(o, "source", at, &u.source);
    Read(o, "viscosity_model", at, &u.viscosity_model);
    Read(o, "pressure_viscosity", at, &u.pressure_viscosity);
    Read(o, "pressure_viscosity_coefficient[1/Pa]", at, &u.pressure_viscosity_coefficient);
    if (o.contains("grade")) Read(o, "grade", at, &u.grade);
    if (o.contains("shear_thinning")) Read(o, "shear_thinning", at, &u.shear_thinning);
    if (o.contains("bulk_modulus[Pa]")) Read(o, "bulk_modulus[Pa]", at, &u.bulk_modulus);
    if (o.contains("density_law")) Read(o, "density_law", at, &u.density_law);
    if (u.shear_thinning != "none") {
      Read(o, "cross_ratio[-]", at, &u.cross_ratio);
      Read(o, "cross_exponent[-]", at, &u.cross_exponent);
      Read(o, "cross_critical_rate[1/s]", at, &u.cross_critical_rate);
    }
    *used = u;
  }
  if (j.contains("heat_balance")) {
    HeatBalanceUsed h;
    Read(j.at("heat_balance"), "runs", "heat_balance", &h.runs);
    Read(j.at("heat_balance"), "residual[K]", "heat_balance", &h.residual);
    Read(j.at("heat_balance"), "converged", "heat_balance", &h.converged);
    s.heat_balance = h;
  }
  json clearance = json::object();  // absent in a summary written before it existed
  Read(j, "clearance", "", &clearance);
  if (!clearance.is_object()) throw std::runtime_error("\"clearance\" is not an object");
  for (const auto& [name, c] :
       {std::pair{"skirt", &s.clearance_skirt}, std::pair{"big_end", &s.clearance_big_end}}) {
    if (!clearance.contains(name)) continue;
    const std::string at = std::string("clearance.") + name;
    RunSummary::Clearance value;
    Read(clearance.at(name), "cold[m]", at, &value.cold);
    Read(clearance.at(name), "hot[m]", at, &value.hot);
    *c = value;
  }
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
  // Invalid UTF-8 in a text field (the readers refuse it; this is the last guard) is replaced
  // rather than losing the summary.
  WriteFileAtomically(path,
                      SummaryToJson(summary).dump(2, ' ', false, json::error_handler_t::replace) + "\n");
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
