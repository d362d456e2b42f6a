#pragma once
/// @file The output folder of a run: results.csv (the documented core columns first, then
/// extra crank-train columns; a column a model does not have is present and empty) and
/// summary.json. Columns, frames and signs: docs/outputs.md.
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/engine/run_job.hpp"

namespace filmdyn::io {

/// One row of results.csv; std::nullopt = empty cell.
struct OutputRow {
  std::optional<double> crank_angle_deg, time, piston_lateral, piston_tilt, piston_lateral_velocity,
      piston_tilt_rate, skirt_normal_force, skirt_friction_force, skirt_moment, skirt_moft,
      skirt_fpl, journal_ecc_x, journal_ecc_y, bearing_eps, bearing_moft, bearing_fpl,
      bigend_force_x, bigend_force_y, gas_force,
      // Film peaks and the friction split of each joint (documented block, after the 19):
      skirt_peak_pressure, skirt_peak_contact_pressure, skirt_contact_friction_force,
      skirt_contact_fpl, bearing_peak_pressure, bearing_peak_contact_pressure,
      bearing_friction_force, bearing_contact_friction_force, bearing_contact_fpl,
      bigend_force_rod_x, bigend_force_rod_y, bearing_eps_rate,
      // Oil flows of each joint and the skirt's oil-covered share:
      skirt_inflow, skirt_outflow, skirt_wetted_fraction, bearing_supply_flow, bearing_side_flow,
      // Mass-conserving films: the peak pressure of the integrator's steps since the last row:
      skirt_step_peak_pressure, bearing_step_peak_pressure,
      // Elastic surfaces: the largest film opening by deformation (0 when rigid):
      skirt_max_deformation, bearing_max_deformation,
      // Extras (after the core columns):
      piston_position, piston_velocity, piston_acceleration, rod_angle, rod_angular_velocity,
      rod_angular_acceleration, pin_force_x, pin_force_y, main_bearing_force_x,
      main_bearing_force_y, crank_torque, cylinder_pressure, constraint_violation;
};

/// One results.csv column: its header (name[unit], SI), the row member holding it, and the unit
/// a person reads it in (the GUI's display units, ASCII: "um", "kN", "MPa") with the factor from
/// SI to it.
struct ResultColumn {
  const char* header;
  std::optional<double> OutputRow::*member;
  const char* display_unit;
  double display_scale;
};
/// Every column, in file order: the one definition of results.csv's columns.
const std::vector<ResultColumn>& ResultColumns();

/// results.csv text (SI, as written by WriteResultsCsv) converted to display units: each header
/// `name[SI unit]` becomes `name[display unit]`, each value is multiplied by the column's
/// display_scale (`%.10g`), empty cells stay empty. Throws InputError naming the column or row
/// for a header it does not know or a cell that is not a number.
std::string ResultsCsvInDisplayUnits(const std::string& si_csv);

/// The crank angle within the reported cycle [°CA] (defined with the crank train's samples).
using engine::CycleCrankAngleDeg;

/// Header names with units, in column order.
std::vector<std::string> ResultsHeader();
/// The row of a crank-train sample for a model (ideal joints fill zero secondary motion, zero
/// friction and FPL; their film quantities stay empty). Lubricated joints fill every film column
/// from the sample's skirt / bearing film quantities (journal_ecc in the rod-fixed frame). crank_angle_deg within the reported cycle.
OutputRow RowFromSample(const engine::CrankTrainSample& sample, engine::Model model,
                        double cycle_start_time);

/// The results.csv rows of a run's reported samples, time[s] from engine::ReportedTimeOrigin.
std::vector<OutputRow> ResultRows(const engine::RunResult& result, engine::Model model);

void WriteResultsCsv(std::ostream& out, const std::vector<OutputRow>& rows);

/// The columns of motion.csv, in results.csv's order: crank angle, time, the piston's secondary
/// motion, the journal's position and ε, ε̇ — the quantities a run samples between its output
/// steps (engine::RunResult::motion).
const std::vector<ResultColumn>& MotionColumns();
/// The row of a motion sample: the MotionColumns() cells, by the rules of RowFromSample (ideal
/// joints: zeros), the others empty. RowFromSample fills these cells the same way.
OutputRow RowFromMotion(const engine::MotionSample& sample, engine::Model model,
                        double cycle_start_time);
/// The motion rows of a run (times and crank angles relative to its reported cycle, as
/// results.csv's rows).
std::vector<OutputRow> MotionRows(const engine::RunResult& result, engine::Model model);
/// motion.csv: MotionColumns() of each row.
void WriteMotionCsv(std::ostream& out, const std::vector<OutputRow>& rows);

/// Called by WriteRunFolder after results.csv and before summary.json, with the rows written:
/// the caller's further outputs (fields, plots) go here, so that the summary comes last.
using BeforeSummary = std::function<void(const std::vector<OutputRow>&)>;

/// The case a run ran, as a case file that runs it again (`filmdyn run DIR/case-as-run.json`): its
/// joint models, `operating.rpm` = the run's speed, the cylinder pressure it used as the one
/// inline curve at that speed, and the files it names (imported compliances) by absolute paths.
nlohmann::json RunCaseJson(const engine::RunConfig& config);

/// Writes case-as-run.json (RunCaseJson), results.csv and motion.csv (for a model with a film
/// joint), then `before_summary`'s outputs, then summary.json into `directory` (created), each file
/// atomically (core/io/output_files.hpp). Returns the rows written. Throws OutputError naming the
/// file when a write fails, after replacing the summary by one of status "failed" that says so
/// (when that can be written: MarkRunStarted's "running" would read as a run killed).
std::vector<OutputRow> WriteRunFolder(const std::filesystem::path& directory,
                                      const std::string& case_name, const engine::RunConfig& config,
                                      const engine::RunResult& result,
                                      const BeforeSummary& before_summary = {});

/// Writes the case-as-run.json and the summary.json of a run that has started: status "running",
/// not complete. A run killed before it writes its results leaves exactly this (with the inputs it
/// was given), never an earlier run's summary.
void MarkRunStarted(const std::filesystem::path& directory, const std::string& case_name,
                    const engine::RunConfig& config);

/// Replaces MarkRunStarted's summary by one of status "failed" with `message` (why the run
/// stopped before any result: an input only the run's set-up could check); the "running" left
/// would read as a run killed. Writes nothing else. Best effort, called while the caller reports
/// that error: a summary that cannot be written is left as it is, without a second error.
void MarkRunFailed(const std::filesystem::path& directory, const std::string& case_name,
                   const engine::RunConfig& config, const std::string& message);

/// The default output folder `results/<case>-<model>-<rpm>`.
std::filesystem::path DefaultOutputFolder(const std::string& case_name, engine::Model model,
                                          double rpm);

}  // namespace filmdyn::io
