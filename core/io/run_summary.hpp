#pragma once
/// @file summary.json of a run as one struct with one JSON mapping: what `filmdyn run`, a sweep
/// and the GUI write, and what the run comparison reads back. Keys and units in docs/outputs.md.
#include <filesystem>
#include <map>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/engine/run_job.hpp"
#include "core/io/results_writer.hpp"
#include "core/io/run_kpis.hpp"
#include "core/io/run_warnings.hpp"

namespace filmdyn::io {

/// Smallest and largest value of one results.csv column over the reported cycle.
struct ColumnExtremes {
  double min = 0.0;
  double max = 0.0;
  /// The extreme is a spike the output samples do not resolve: its magnitude is more than
  /// engine::kUnresolvedPeakRatio times the larger magnitude of the samples beside it
  /// (engine::NeighbourRatio; an impact lasting a fraction of the output interval), so its value
  /// is whatever the samples caught. summary.json: "min_spike" / "max_spike", written when true.
  bool min_spike = false;
  bool max_spike = false;
};

/// Solver statistics of a run.
struct SolverSummary {
  std::string integrator;
  long steps = 0;
  long rejected_steps = 0;
  long newton_iterations = 0;
  long newton_failures = 0;
  long rhs_evaluations = 0;
  long jacobian_evaluations = 0;
  long reynolds_solves = 0;
  double baumgarte_alpha = 0.0;
  double baumgarte_beta = 0.0;
  double relative_tolerance = 0.0;
};

/// The status of a run folder whose run has started and not yet written its results (or was
/// killed before it could): io::MarkRunStarted.
inline constexpr char kRunningStatus[] = "running";

/// The oil a lubricated joint's film ran with ("oil" in the file): its film temperature and the
/// viscosity that follows from it, and the pressure law.
struct JointOilUsed {
  double temperature_k = 0.0;
  double viscosity_pa_s = 0.0;                  ///< at zero gauge pressure, at that temperature
  std::string source;                           ///< "lubricant" (the case's) or "own"
  std::string viscosity_model;                  ///< "constant" or "vogel"
  std::string pressure_viscosity;               ///< "none", "barus" or "roelands"
  double pressure_viscosity_coefficient = 0.0;  ///< dln(mu)/dp at p = 0 [1/Pa]
  std::string grade;                            ///< the catalogue oil's name (model "grade")
  std::string shear_thinning = "none";          ///< "none", "cross" or "hths"
  /// Cross' law at the film temperature (with shear thinning): r, m, critical rate [1/s].
  double cross_ratio = 1.0, cross_exponent = 1.0, cross_critical_rate = 0.0;
  /// The bulk modulus the film ran with [Pa]: 0 = incompressible (every Reynolds film; a
  /// mass-conserving film with an incompressible oil).
  double bulk_modulus = 0.0;
  /// With a bulk modulus: "linear" or "dowson_higginson" (lubrication::DensityLaw).
  std::string density_law;
};

/// The film-temperature iteration of joints in heat-balance mode ("heat_balance" in the file,
/// absent without such a joint): whole runs computed, the largest |T_balance − T| of the
/// reported run [K], and whether it met the tolerance.
struct HeatBalanceUsed {
  int runs = 0;
  double residual = 0.0;
  bool converged = false;
};

struct RunSummary {
  std::string filmdyn_version;
  std::string case_name;  ///< "case" in the file
  std::string model;      ///< e.g. "skirt-lbrbe"
  double rpm = 0.0;
  std::string status;     ///< engine::StatusName, or kRunningStatus
  bool complete = false;  ///< status is "completed"
  std::string message;
  int cycles = 0;
  int reported_cycle = 0;  ///< engine::RunResult::reported_cycle
  int cycles_to_steady_state = 0;
  double cycle_to_cycle_change = 0.0;
  std::string cycle_to_cycle_worst_quantity;
  std::vector<double> cycle_to_cycle_changes;  ///< engine::RunResult::cycle_changes
  double wall_time_s = 0.0;
  double max_constraint_violation = 0.0;
  /// Per results.csv column header (all but crank angle and time) that has any value.
  std::map<std::string, ColumnExtremes> extremes;
  std::optional<double> mean_fpl_skirt_w;    ///< empty: the model has no skirt FPL
  std::optional<double> mean_fpl_bearing_w;  ///< empty: the model has no bearing FPL
  SolverSummary solver;
  double pressure_peak_pa = 0.0;
  double pressure_peak_crank_angle_deg = 0.0;
  /// engine::HeadlineFigures of the reported cycle ("headline" in the file).
  std::vector<engine::HeadlineFigure> headline;
  /// Their estimated discretisation error ("discretisation_error").
  engine::ErrorEstimate error_estimate;
  /// A run that found no periodic steady state: how far the headline figures moved over its last
  /// cycles ("cycle_scatter"; null otherwise; engine::ScatterOverCycles).
  std::optional<engine::CycleScatter> cycle_scatter;
  /// The engineering warnings of the run (io::RunWarnings; "warnings").
  std::vector<RunWarning> warnings;
  /// The engine KPIs of the reported cycle per lubricated joint (io::RunKpisOf; "kpis"; empty
  /// for the ideal model and in a summary written before they existed).
  RunKpis kpis;
  /// Per lubricated joint (empty for an ideal joint and in a summary written before it existed).
  std::optional<JointOilUsed> oil_skirt, oil_big_end;
  /// Per lubricated joint: the radial clearance cold and at the running temperatures [m]
  /// ("clearance" in the file; engine::SkirtFit, engine::BigEndFit).
  struct Clearance {
    double cold = 0.0, hot = 0.0;
  };
  std::optional<Clearance> clearance_skirt, clearance_big_end;
  std::optional<HeatBalanceUsed> heat_balance;
};

/// How far the headline figures moved over the last cycles of a run that completed or stopped
/// at its cycle limit (summary.json's cycle_scatter): none for other runs, or with fewer than two
/// cycles or no headline figures. The periodic-state test judges each quantity against its range
/// over the cycle, which hides a minimum film's scatter (docs/validation/errors.md).
std::optional<engine::CycleScatter> ReportedCycleScatter(const engine::RunResult& result);

/// The summary of a finished (or stopped) run from its configuration, result and the rows
/// written to results.csv.
RunSummary SummarizeRun(const std::string& case_name, const engine::RunConfig& config,
                        const engine::RunResult& result, const std::vector<OutputRow>& rows);

/// The one mapping between the struct and summary.json.
nlohmann::json SummaryToJson(const RunSummary& summary);
/// model, rpm and status are required; other keys may be absent (an earlier version's summary)
/// and keep their defaults. Throws std::runtime_error naming the key when a required key is
/// missing or any key has the wrong type.
RunSummary SummaryFromJson(const nlohmann::json& json);

/// Writes `path` (2-space indented JSON and a newline) atomically. Throws OutputError naming the
/// file.
void WriteSummaryJson(const std::filesystem::path& path, const RunSummary& summary);
/// Reads `path`. Throws std::runtime_error naming the file when it is missing or malformed.
RunSummary ReadSummaryJson(const std::filesystem::path& path);

}  // namespace filmdyn::io
