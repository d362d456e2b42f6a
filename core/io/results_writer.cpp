#include "core/io/results_writer.hpp"

#include "core/io/output_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "core/base/input_error.hpp"
#include "core/io/case_file.hpp"
#include "core/io/run_summary.hpp"

namespace filmdyn::io {

// The one list of columns: the documented core columns first, then the crank-train extras.
const std::vector<ResultColumn>& ResultColumns() {
  static const std::vector<ResultColumn> columns = {
      {"crank_angle[deg]", &OutputRow::crank_angle_deg, "deg", 1.0},
      {"time[s]", &OutputRow::time, "ms", 1e3},
      {"piston_lateral[m]", &OutputRow::piston_lateral, "um", 1e6},
      {"piston_tilt[rad]", &OutputRow::piston_tilt, "mrad", 1e3},
      {"piston_lateral_velocity[m/s]", &OutputRow::piston_lateral_velocity, "mm/s", 1e3},
      {"piston_tilt_rate[rad/s]", &OutputRow::piston_tilt_rate, "rad/s", 1.0},
      {"skirt_normal_force[N]", &OutputRow::skirt_normal_force, "N", 1.0},
      {"skirt_friction_force[N]", &OutputRow::skirt_friction_force, "N", 1.0},
      {"skirt_moment[N*m]", &OutputRow::skirt_moment, "N*m", 1.0},
      {"skirt_moft[m]", &OutputRow::skirt_moft, "um", 1e6},
      {"skirt_fpl[W]", &OutputRow::skirt_fpl, "W", 1.0},
      {"journal_ecc_x[m]", &OutputRow::journal_ecc_x, "um", 1e6},
      {"journal_ecc_y[m]", &OutputRow::journal_ecc_y, "um", 1e6},
      {"bearing_eps[-]", &OutputRow::bearing_eps, "-", 1.0},
      {"bearing_moft[m]", &OutputRow::bearing_moft, "um", 1e6},
      {"bearing_fpl[W]", &OutputRow::bearing_fpl, "W", 1.0},
      {"bigend_force_x[N]", &OutputRow::bigend_force_x, "kN", 1e-3},
      {"bigend_force_y[N]", &OutputRow::bigend_force_y, "kN", 1e-3},
      {"gas_force[N]", &OutputRow::gas_force, "kN", 1e-3},
      {"skirt_peak_pressure[Pa]", &OutputRow::skirt_peak_pressure, "MPa", 1e-6},
      {"skirt_peak_contact_pressure[Pa]", &OutputRow::skirt_peak_contact_pressure, "MPa", 1e-6},
      {"skirt_contact_friction_force[N]", &OutputRow::skirt_contact_friction_force, "N", 1.0},
      {"skirt_contact_fpl[W]", &OutputRow::skirt_contact_fpl, "W", 1.0},
      {"bearing_peak_pressure[Pa]", &OutputRow::bearing_peak_pressure, "MPa", 1e-6},
      {"bearing_peak_contact_pressure[Pa]", &OutputRow::bearing_peak_contact_pressure, "MPa", 1e-6},
      {"bearing_friction_force[N]", &OutputRow::bearing_friction_force, "N", 1.0},
      {"bearing_contact_friction_force[N]", &OutputRow::bearing_contact_friction_force, "N", 1.0},
      {"bearing_contact_fpl[W]", &OutputRow::bearing_contact_fpl, "W", 1.0},
      {"bigend_force_rod_x[N]", &OutputRow::bigend_force_rod_x, "kN", 1e-3},
      {"bigend_force_rod_y[N]", &OutputRow::bigend_force_rod_y, "kN", 1e-3},
      {"bearing_eps_rate[1/s]", &OutputRow::bearing_eps_rate, "1/s", 1.0},
      {"skirt_inflow[m^3/s]", &OutputRow::skirt_inflow, "cm^3/s", 1e6},
      {"skirt_outflow[m^3/s]", &OutputRow::skirt_outflow, "cm^3/s", 1e6},
      {"skirt_wetted_fraction[-]", &OutputRow::skirt_wetted_fraction, "-", 1.0},
      {"bearing_supply_flow[m^3/s]", &OutputRow::bearing_supply_flow, "cm^3/s", 1e6},
      {"bearing_side_flow[m^3/s]", &OutputRow::bearing_side_flow, "cm^3/s", 1e6},
      {"skirt_step_peak_pressure[Pa]", &OutputRow::skirt_step_peak_pressure, "MPa", 1e-6},
      {"bearing_step_peak_pressure[Pa]", &OutputRow::bearing_step_peak_pressure, "MPa", 1e-6},
      {"skirt_max_deformation[m]", &OutputRow::skirt_max_deformation, "um", 1e6},
      {"bearing_max_deformation[m]", &OutputRow::bearing_max_deformation, "um", 1e6},
      {"piston_position[m]", &OutputRow::piston_position, "mm", 1e3},
      {"piston_velocity[m/s]", &OutputRow::piston_velocity, "m/s", 1.0},
      {"piston_acceleration[m/s^2]", &OutputRow::piston_acceleration, "m/s^2", 1.0},
      {"rod_angle[rad]", &OutputRow::rod_angle, "deg", 180 / std::numbers::pi},
      {"rod_angular_velocity[rad/s]", &OutputRow::rod_angular_velocity, "rad/s", 1.0},
      {"rod_angular_acceleration[rad/s^2]", &OutputRow::rod_angular_acceleration, "rad/s^2", 1.0},
      {"pin_force_x[N]", &OutputRow::pin_force_x, "kN", 1e-3},
      {"pin_force_y[N]", &OutputRow::pin_force_y, "kN", 1e-3},
      {"main_bearing_force_x[N]", &OutputRow::main_bearing_force_x, "kN", 1e-3},
      {"main_bearing_force_y[N]", &OutputRow::main_bearing_force_y, "kN", 1e-3},
      {"crank_torque[N*m]", &OutputRow::crank_torque, "N*m", 1.0},
      {"cylinder_pressure[Pa]", &OutputRow::cylinder_pressure, "bar", 1e-5},
      {"constraint_violation[-]", &OutputRow::constraint_violation, "-", 1.0},
  };
  return columns;
}

std::string ResultsCsvInDisplayUnits(const std::string& si_csv) {
  std::istringstream in(si_csv);
  std::string line;
  if (!std::getline(in, line))
    throw InputError("results.csv header", "(empty)", "a header line of results.csv columns");
  // The header's columns, each with its display scale.
  std::vector<double> scales;
  std::string header;
  std::istringstream names(line);
  for (std::string name; std::getline(names, name, ',');) {
    const auto& columns = ResultColumns();
    const auto it = std::find_if(columns.begin(), columns.end(),
                                 [&name](const ResultColumn& c) { return name == c.header; });
    if (it == columns.end()) {
      throw InputError("results.csv header", "'" + name + "'",
                       "a results.csv column (docs/outputs.md)");
    }
    const std::string base = name.substr(0, name.find('['));
    header += (header.empty() ? "" : ",") + base + "[" + it->display_unit + "]";
    scales.push_back(it->display_scale);
  }
  std::string out = header + "\n";
  for (int row = 2; std::getline(in, line); ++row) {
    if (line.empty()) continue;
    std::istringstream cells(line);
    std::size_t c = 0;
    std::string converted;
    for (std::string cell; std::getline(cells, cell, ','); ++c) {
      if (c >= scales.size()) {
        throw InputError("results.csv row " + std::to_string(row), line,
                         "at most one cell per header column");
      }
      if (c > 0) converted += ",";
      if (cell.empty()) continue;  // the model lacks the quantity: stays empty
      double value = 0.0;
      if (!ParseNumber(cell, value)) {
        throw InputError(
            "results.csv row " + std::to_string(row) + ", column " + std::to_string(c + 1),
            "'" + cell + "'", "a number or an empty cell");
      }
      converted += fmt::format("{:.10g}", value * scales[c]);
    }
    for (; c < scales.size(); ++c) converted += ",";  // trailing empty cells
    out += converted + "\n";
  }
  return out;
}

std::vector<std::string> ResultsHeader() {
  std::vector<std::string> header;
  for (const ResultColumn& c : ResultColumns()) header.push_back(c.header);
  return header;
}

namespace {

using engine::BigEndLubricated;
using engine::SkirtLubricated;

void WriteCsv(std::ostream& out, const std::vector<OutputRow>& rows,
              const std::vector<ResultColumn>& columns) {
  for (std::size_t c = 0; c < columns.size(); ++c) out << (c ? "," : "") << columns[c].header;
  out << "\n";
  for (const OutputRow& row : rows) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (c) out << ",";
      if (const auto& value = row.*(columns[c].member)) {
        out << fmt::format("{:.10g}", *value + 0.0);  // + 0.0: a signed zero reads "0", not "-0"
      }
    }
    out << "\n";
  }
}

}  // namespace

const std::vector<ResultColumn>& MotionColumns() {
  static const std::vector<ResultColumn> columns = [] {
    const std::optional<double> OutputRow::*const members[] = {&OutputRow::crank_angle_deg,
                                                               &OutputRow::time,
                                                               &OutputRow::piston_lateral,
                                                               &OutputRow::piston_tilt,
                                                               &OutputRow::piston_lateral_velocity,
                                                               &OutputRow::piston_tilt_rate,
                                                               &OutputRow::journal_ecc_x,
                                                               &OutputRow::journal_ecc_y,
                                                               &OutputRow::bearing_eps,
                                                               &OutputRow::bearing_eps_rate};
    std::vector<ResultColumn> chosen;
    for (const ResultColumn& column : ResultColumns()) {
      if (std::find(std::begin(members), std::end(members), column.member) != std::end(members))
        chosen.push_back(column);
    }
    return chosen;
  }();
  return columns;
}

OutputRow RowFromMotion(const engine::MotionSample& s, engine::Model model,
                        double cycle_start_time) {
  OutputRow r;
  r.time = s.time - cycle_start_time;
  r.crank_angle_deg = CycleCrankAngleDeg(s.crank_angle);
  // Ideal liner: no secondary motion (exactly zero, not round-off).
  const bool skirt = SkirtLubricated(model);
  r.piston_lateral = skirt ? s.piston_lateral : 0.0;
  r.piston_tilt = skirt ? s.piston_tilt : 0.0;
  r.piston_lateral_velocity = skirt ? s.piston_lateral_velocity : 0.0;
  r.piston_tilt_rate = skirt ? s.piston_tilt_rate : 0.0;
  if (BigEndLubricated(model) && s.journal_present) {  // journal orbit in the rod-fixed frame
    r.journal_ecc_x = s.journal_ecc_rod.x();
    r.journal_ecc_y = s.journal_ecc_rod.y();
    r.bearing_eps = s.eps;
    r.bearing_eps_rate = s.eps_dot;
  }
  if (!BigEndLubricated(model)) {  // ideal pin joint: centred journal
    r.journal_ecc_x = 0.0;
    r.journal_ecc_y = 0.0;
    r.bearing_eps = 0.0;
    r.bearing_eps_rate = 0.0;
  }
  return r;
}

std::vector<OutputRow> ResultRows(const engine::RunResult& result, engine::Model model) {
  std::vector<OutputRow> rows;
  const double start = engine::ReportedTimeOrigin(result);
  rows.reserve(result.samples.size());
  for (const auto& s : result.samples) rows.push_back(RowFromSample(s, model, start));
  return rows;
}

std::vector<OutputRow> MotionRows(const engine::RunResult& result, engine::Model model) {
  std::vector<OutputRow> rows;
  const double start = engine::ReportedTimeOrigin(result);
  rows.reserve(result.motion.size());
  for (const auto& m : result.motion) rows.push_back(RowFromMotion(m, model, start));
  return rows;
}

void WriteMotionCsv(std::ostream& out, const std::vector<OutputRow>& rows) {
  WriteCsv(out, rows, MotionColumns());
}

OutputRow RowFromSample(const engine::CrankTrainSample& s, engine::Model model,
                        double cycle_start_time) {
  // Crank angle, time, secondary motion, journal position: one rule for both kinds of row.
  OutputRow r = RowFromMotion(engine::MotionOf(s), model, cycle_start_time);
  const bool skirt_lubricated = SkirtLubricated(model);
  const bool big_end_lubricated = BigEndLubricated(model);
  // Ideal liner: the prismatic joint's reaction as side force and moment, frictionless.
  if (!skirt_lubricated) {
    r.skirt_normal_force = s.liner_force_on_piston.x();
    r.skirt_friction_force = 0.0;
    r.skirt_moment = s.liner_moment_about_pin;
    r.skirt_fpl = 0.0;
    r.skirt_contact_friction_force = 0.0;
    r.skirt_contact_fpl = 0.0;
  }
  if (skirt_lubricated && s.skirt.present) {  // film of the lubricated skirt (on the piston)
    r.skirt_normal_force = s.skirt.normal_force;
    r.skirt_friction_force = s.skirt.friction_force;
    r.skirt_moment = s.skirt.moment_about_pin;
    r.skirt_moft = s.skirt.moft;
    r.skirt_fpl = s.skirt.fpl;
    r.skirt_peak_pressure = s.skirt.max_pressure;
    r.skirt_peak_contact_pressure = s.skirt.max_contact_pressure;
    r.skirt_contact_friction_force = s.skirt.contact_friction_force;
    r.skirt_contact_fpl = s.skirt.contact_fpl;
    // A Reynolds skirt creates the oil it lacks where its film reforms: its boundary inflow is
    // only the edge cells' share beside a cavitated zone, which falls with the cell. Only a
    // mass-conserving skirt (one that keeps an oil account) has an inflow to report.
    if (s.skirt.oil.kept) r.skirt_inflow = s.skirt.inflow;
    r.skirt_outflow = s.skirt.outflow;
    r.skirt_wetted_fraction = s.skirt.wetted_fraction;
    r.skirt_max_deformation = s.skirt.max_deformation;
    if (std::isfinite(s.skirt.step_peak_pressure))
      r.skirt_step_peak_pressure = s.skirt.step_peak_pressure;
  }
  if (big_end_lubricated && s.bearing.present) {
    r.bearing_moft = s.bearing.moft;
    r.bearing_fpl = s.bearing.fpl;
    r.bigend_force_x = s.bearing.force_on_rod.x();
    r.bigend_force_y = s.bearing.force_on_rod.y();
    r.bearing_peak_pressure = s.bearing.max_pressure;
    r.bearing_peak_contact_pressure = s.bearing.max_contact_pressure;
    r.bearing_friction_force = s.bearing.friction_force;
    r.bearing_contact_friction_force = s.bearing.contact_friction_force;
    r.bearing_contact_fpl = s.bearing.contact_fpl;
    r.bearing_supply_flow = s.bearing.supply_flow;
    r.bearing_side_flow = s.bearing.side_flow;
    r.bearing_max_deformation = s.bearing.max_deformation;
    if (std::isfinite(s.bearing.step_peak_pressure))
      r.bearing_step_peak_pressure = s.bearing.step_peak_pressure;
  }
  if (!big_end_lubricated) {  // ideal pin joint: frictionless
    r.bearing_fpl = 0.0;
    r.bearing_friction_force = 0.0;
    r.bearing_contact_friction_force = 0.0;
    r.bearing_contact_fpl = 0.0;
    r.bigend_force_x = s.big_end_force_on_rod.x();
    r.bigend_force_y = s.big_end_force_on_rod.y();
  }
  if (r.bigend_force_x && r.bigend_force_y) {
    // The same force in the rod frame (x ⟂ rod, y along the rod toward the small end): the
    // global axes turned by the rod angle, as the journal orbit is given.
    const double c = std::cos(s.rod_angle), sn = std::sin(s.rod_angle);
    r.bigend_force_rod_x = c * *r.bigend_force_x + sn * *r.bigend_force_y;
    r.bigend_force_rod_y = -sn * *r.bigend_force_x + c * *r.bigend_force_y;
  }
  r.gas_force = s.gas_force;
  r.piston_position = s.piston_position;
  r.piston_velocity = s.piston_velocity;
  r.piston_acceleration = s.piston_acceleration;
  r.rod_angle = s.rod_angle;
  r.rod_angular_velocity = s.rod_angular_velocity;
  r.rod_angular_acceleration = s.rod_angular_acceleration;
  r.pin_force_x = s.pin_force_on_piston.x();
  r.pin_force_y = s.pin_force_on_piston.y();
  r.main_bearing_force_x = s.main_bearing_force_on_crank.x();
  r.main_bearing_force_y = s.main_bearing_force_on_crank.y();
  r.crank_torque = s.crank_torque;
  r.cylinder_pressure = s.cylinder_pressure;
  r.constraint_violation = s.constraint_violation;
  return r;
}

void WriteResultsCsv(std::ostream& out, const std::vector<OutputRow>& rows) {
  WriteCsv(out, rows, ResultColumns());
}

std::filesystem::path DefaultOutputFolder(const std::string& case_name, engine::Model model,
                                          double rpm) {
  return std::filesystem::path("results") /
         fmt::format("{}-{}-{:g}", SafeFolderName(case_name), engine::ModelName(model), rpm);
}

nlohmann::json RunCaseJson(const engine::RunConfig& config) {
  engine::EngineCase c = config.engine_case;
  c.operating.rpm = config.rpm;
  // The curve the run used (a --pressure-curve, a blend, ...): inline, no file.
  if (!config.pressure.Empty())
    c.pressure_curves = {InlinePressureCurve(config.pressure, config.rpm)};
  // Relative names of files found from the case's folder, as the run found them, made absolute
  // so that the file runs from anywhere (a name of the built-in resources stays as it is).
  AbsoluteCaseFileNames(&c, config.case_directory);
  return CaseToJson(c);
}

namespace {
std::vector<OutputRow> WriteRunFiles(const std::filesystem::path& directory,
                                     const std::string& case_name, const engine::RunConfig& config,
                                     const engine::RunResult& result,
                                     const BeforeSummary& before_summary);

void WriteRunCase(const std::filesystem::path& directory, const engine::RunConfig& config) {
  WriteFileAtomically(directory / "case-as-run.json", RunCaseJson(config).dump(2) + "\n");
}
}  // namespace

std::vector<OutputRow> WriteRunFolder(const std::filesystem::path& directory,
                                      const std::string& case_name, const engine::RunConfig& config,
                                      const engine::RunResult& result,
                                      const BeforeSummary& before_summary) {
  try {
    return WriteRunFiles(directory, case_name, config, result, before_summary);
  } catch (const std::exception& e) {
    // The summary says why the folder is incomplete (it said "running", which reads as a run
    // killed); when even it cannot be written (a full disk) the caller has the message.
    try {
      RunSummary summary = SummarizeRun(case_name, config, result, {});
      summary.status = engine::StatusName(engine::RunStatus::kFailed);
      summary.complete = false;
      summary.message = std::string("its results could not be written: ") + e.what();
      WriteSummaryJson(directory / "summary.json", summary);
    } catch (const std::exception&) {
    }
    throw;
  }
}

namespace {
std::vector<OutputRow> WriteRunFiles(const std::filesystem::path& directory,
                                     const std::string& case_name, const engine::RunConfig& config,
                                     const engine::RunResult& result,
                                     const BeforeSummary& before_summary) {
  CreateFolder(directory, "--out");
  WriteRunCase(directory, config);
  std::vector<OutputRow> rows = ResultRows(result, config.model);
  std::ostringstream csv;
  WriteResultsCsv(csv, rows);
  WriteFileAtomically(directory / "results.csv", csv.str());
  if (config.model != engine::Model::kIdeal && !result.motion.empty()) {
    std::ostringstream motion;
    WriteMotionCsv(motion, MotionRows(result, config.model));
    WriteFileAtomically(directory / "motion.csv", motion.str());
  }
  if (before_summary) before_summary(rows);
  // Last: a summary that says "completed" is only ever beside complete files.
  WriteSummaryJson(directory / "summary.json", SummarizeRun(case_name, config, result, rows));
  return rows;
}
}  // namespace

namespace {
// The summary of a run with no result yet: `status`, not complete, `message`.
void WriteResultlessSummary(const std::filesystem::path& directory, const std::string& case_name,
                            const engine::RunConfig& config, const std::string& status,
                            const std::string& message) {
  engine::RunResult none;
  RunSummary summary = SummarizeRun(case_name, config, none, {});
  summary.status = status;
  summary.complete = false;
  summary.message = message;
  WriteSummaryJson(directory / "summary.json", summary);
}
}  // namespace

void MarkRunStarted(const std::filesystem::path& directory, const std::string& case_name,
                    const engine::RunConfig& config) {
  WriteRunCase(directory, config);
  WriteResultlessSummary(directory, case_name, config, kRunningStatus,
                         "the run is in progress, or was killed before it could write its results");
}

void MarkRunFailed(const std::filesystem::path& directory, const std::string& case_name,
                   const engine::RunConfig& config, const std::string& message) {
  try {
    WriteResultlessSummary(directory, case_name, config,
                           engine::StatusName(engine::RunStatus::kFailed), message);
  } catch (const std::exception&) {  // the caller's error is the one to report
  }
}

}  // namespace filmdyn::io
