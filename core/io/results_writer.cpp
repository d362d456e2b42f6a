#include "core/io/results_writer.hpp"

#include "core/io/output_files.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <stdexcept>

#include "core/base/input_error.hpp"
#include "core/io/run_summary.hpp"

namespace filmdyn::io {

// The one list of columns: the documented core columns first, then the crank-train extras.
const std::vector<ResultColumn>& ResultColumns() {
  static const std::vector<ResultColumn> columns = {
      {"crank_angle[deg]", &OutputRow::crank_angle_deg},
      {"time[s]", &OutputRow::time},
      {"piston_lateral[m]", &OutputRow::piston_lateral},
      {"piston_tilt[rad]", &OutputRow::piston_tilt},
      {"piston_lateral_velocity[m/s]", &OutputRow::piston_lateral_velocity},
      {"piston_tilt_rate[rad/s]", &OutputRow::piston_tilt_rate},
      {"skirt_normal_force[N]", &OutputRow::skirt_normal_force},
      {"skirt_friction_force[N]", &OutputRow::skirt_friction_force},
      {"skirt_moment[N*m]", &OutputRow::skirt_moment},
      {"skirt_moft[m]", &OutputRow::skirt_moft},
      {"skirt_fpl[W]", &OutputRow::skirt_fpl},
      {"journal_ecc_x[m]", &OutputRow::journal_ecc_x},
      {"journal_ecc_y[m]", &OutputRow::journal_ecc_y},
      {"bearing_eps[-]", &OutputRow::bearing_eps},
      {"bearing_moft[m]", &OutputRow::bearing_moft},
      {"bearing_fpl[W]", &OutputRow::bearing_fpl},
      {"bigend_force_x[N]", &OutputRow::bigend_force_x},
      {"bigend_force_y[N]", &OutputRow::bigend_force_y},
      {"gas_force[N]", &OutputRow::gas_force},
      {"piston_position[m]", &OutputRow::piston_position},
      {"piston_velocity[m/s]", &OutputRow::piston_velocity},
      {"piston_acceleration[m/s^2]", &OutputRow::piston_acceleration},
      {"rod_angle[rad]", &OutputRow::rod_angle},
      {"rod_angular_velocity[rad/s]", &OutputRow::rod_angular_velocity},
      {"rod_angular_acceleration[rad/s^2]", &OutputRow::rod_angular_acceleration},
      {"pin_force_x[N]", &OutputRow::pin_force_x},
      {"pin_force_y[N]", &OutputRow::pin_force_y},
      {"main_bearing_force_x[N]", &OutputRow::main_bearing_force_x},
      {"main_bearing_force_y[N]", &OutputRow::main_bearing_force_y},
      {"crank_torque[N*m]", &OutputRow::crank_torque},
      {"cylinder_pressure[Pa]", &OutputRow::cylinder_pressure},
      {"constraint_violation[-]", &OutputRow::constraint_violation},
  };
  return columns;
}

std::vector<std::string> ResultsHeader() {
  std::vector<std::string> header;
  for (const ResultColumn& c : ResultColumns()) header.push_back(c.header);
  return header;
}

OutputRow RowFromSample(const engine::CrankTrainSample& s, engine::Model model,
                        double cycle_start_time) {
  OutputRow r;
  const double deg = 180.0 / std::numbers::pi;
  r.time = s.time - cycle_start_time;
  r.crank_angle_deg = std::fmod(s.crank_angle * deg, 720.0);
  if (*r.crank_angle_deg < 0) *r.crank_angle_deg += 720.0;
  if (*r.crank_angle_deg > 720.0 - 1e-9) *r.crank_angle_deg = 0.0;
  const bool skirt_lubricated =
      model == engine::Model::kOnlySkirt || model == engine::Model::kSkirtLbrbe;
  const bool big_end_lubricated =
      model == engine::Model::kOnlyLbrbe || model == engine::Model::kSkirtLbrbe;
  // Ideal liner: no secondary motion (exactly zero, not round-off), the prismatic joint's
  // reaction as side force and moment, frictionless.
  r.piston_lateral = skirt_lubricated ? s.piston_lateral : 0.0;
  r.piston_tilt = skirt_lubricated ? s.piston_tilt : 0.0;
  r.piston_lateral_velocity = skirt_lubricated ? s.piston_lateral_velocity : 0.0;
  r.piston_tilt_rate = skirt_lubricated ? s.piston_tilt_rate : 0.0;
  if (!skirt_lubricated) {
    r.skirt_normal_force = s.liner_force_on_piston.x();
    r.skirt_friction_force = 0.0;
    r.skirt_moment = s.liner_moment_about_pin;
    r.skirt_fpl = 0.0;
  }
  if (skirt_lubricated && s.skirt.present) {  // film of the lubricated skirt (on the piston)
    r.skirt_normal_force = s.skirt.normal_force;
    r.skirt_friction_force = s.skirt.friction_force;
    r.skirt_moment = s.skirt.moment_about_pin;
    r.skirt_moft = s.skirt.moft;
    r.skirt_fpl = s.skirt.fpl;
  }
  if (big_end_lubricated && s.bearing.present) {  // journal orbit in the rod-fixed frame
    r.journal_ecc_x = s.bearing.journal_ecc_rod.x();
    r.journal_ecc_y = s.bearing.journal_ecc_rod.y();
    r.bearing_eps = s.bearing.eps;
    r.bearing_moft = s.bearing.moft;
    r.bearing_fpl = s.bearing.fpl;
    r.bigend_force_x = s.bearing.force_on_rod.x();
    r.bigend_force_y = s.bearing.force_on_rod.y();
  }
  if (!big_end_lubricated) {  // ideal pin joint: centred journal, frictionless
    r.journal_ecc_x = 0.0;
    r.journal_ecc_y = 0.0;
    r.bearing_eps = 0.0;
    r.bearing_fpl = 0.0;
    r.bigend_force_x = s.big_end_force_on_rod.x();
    r.bigend_force_y = s.big_end_force_on_rod.y();
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
  const auto& columns = ResultColumns();
  for (std::size_t c = 0; c < columns.size(); ++c) out << (c ? "," : "") << columns[c].header;
  out << "\n";
  for (const OutputRow& row : rows) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (c) out << ",";
      if (const auto& value = row.*(columns[c].member)) {
        out << fmt::format("{:.10g}", *value);
      }
    }
    out << "\n";
  }
}

std::filesystem::path DefaultOutputFolder(const std::string& case_name, engine::Model model,
                                          double rpm) {
  return std::filesystem::path("results") /
         fmt::format("{}-{}-{:g}", SafeFolderName(case_name), engine::ModelName(model), rpm);
}

std::vector<OutputRow> WriteRunFolder(const std::filesystem::path& directory,
                                      const std::string& case_name, const engine::RunConfig& config,
                                      const engine::RunResult& result,
                                      const BeforeSummary& before_summary) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error)
    throw InputError("--out", directory.string(), "cannot create the folder: " + error.message());
  std::vector<OutputRow> rows;
  const double start = result.samples.empty() ? 0.0 : result.samples.front().time;
  for (const auto& s : result.samples) rows.push_back(RowFromSample(s, config.model, start));
  std::ostringstream csv;
  WriteResultsCsv(csv, rows);
  WriteFileAtomically(directory / "results.csv", csv.str());
  if (before_summary) before_summary(rows);
  // Last: a summary that says "completed" is only ever beside complete files.
  WriteSummaryJson(directory / "summary.json", SummarizeRun(case_name, config, result, rows));
  return rows;
}

void MarkRunStarted(const std::filesystem::path& directory, const std::string& case_name,
                    const engine::RunConfig& config) {
  engine::RunResult running;
  RunSummary summary = SummarizeRun(case_name, config, running, {});
  summary.status = kRunningStatus;
  summary.complete = false;
  summary.message = "the run is in progress, or was killed before it could write its results";
  WriteSummaryJson(directory / "summary.json", summary);
}

}  // namespace filmdyn::io
