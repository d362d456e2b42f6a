#pragma once
/// @file What the GUI needs from a solver run, independent of which core API provides it: a
/// function called on the worker thread that streams samples and progress into a sink, polls a
/// cancel flag, and throws (InputError or std::runtime_error) with the reason when it fails.
/// core_run_backend.cpp adapts core's run-job API (core/engine/run_job) to it; tests substitute
/// their own.
#include <atomic>
#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/engine/engine_case.hpp"
#include "core/engine/error_estimate.hpp"
#include "core/io/run_kpis.hpp"
#include "core/io/run_warnings.hpp"
#include "ui/fields/field_frames.hpp"
#include "ui/run/result_columns.hpp"

namespace filmdyn::ui {

struct RunRequest {
  engine::EngineCase engine_case;  ///< a copy: the user may keep editing while it runs
  std::string model;               ///< "ideal", "only-skirt", "only-lbrbe", "skirt-lbrbe"
  double rpm = 0.0;
  /// The case file's folder: the files the case names (e.g. a compliance file) by a relative
  /// path are found from there. Empty: the working directory (an unsaved case).
  std::string case_directory;
};

struct RunProgress {
  int cycle = 0;  ///< current cycle, 1-based (0 in the run-in)
  int max_cycles = 0;
  bool run_in = false;        ///< integrating the run-in before the first cycle
  double cycle_fraction = 0;  ///< 0..1 within the current cycle (run-in: < 0, to cycle 1)
  /// The crank angle [°CA] reached (the last output step's, or inside a step the integration's)
  /// as the results label it, [0, 720)
  double crank_angle_deg = 0;
  double cycle_change = -1;   ///< last cycle-to-cycle change (relative), < 0 when unknown
  double fraction = -1;       ///< overall progress 0..1 (< 0: unknown)
  double remaining = -1;      ///< estimated wall time left [s] (< 0: unknown)
};

/// How a finished run writes its outputs: core's writers, so the GUI's exports are the files
/// `filmdyn run` writes. Each throws std::runtime_error (naming the file) when it cannot write.
struct RunWriters {
  std::function<void(const std::string& dir)> folder;  ///< results.csv, summary.json, fields/
  std::function<std::string()> csv;                    ///< results.csv's text
  std::function<void(const std::string& dir)> fields;  ///< the fields/ files into `dir`
};

/// Receives results on the worker thread. Thread-safe (RunRecord implements it).
class RunSink {
 public:
  virtual ~RunSink() = default;
  /// Starts a new cycle: the live plots show the cycle being computed; the samples of the last
  /// completed cycle are what a finished run reports.
  virtual void BeginCycle(int cycle) = 0;
  virtual void Append(const RunSample& sample) = 0;
  virtual void Progress(const RunProgress& progress) = 0;
  /// Free-form solver statistics for the run table ("steps", "rejected steps", ...).
  virtual void Statistic(const std::string& name, double value) = 0;
  /// The run's reported cycle (what results.csv holds), replacing the streamed samples.
  virtual void Report(std::vector<RunSample> reported_cycle) = 0;
  /// The clearance joints' motion over the reported cycle, sampled between the output steps too
  /// (io::MotionRows: the orbit and the phase portraits draw it). Called before Report.
  virtual void ReportMotion(std::vector<RunSample> motion) { (void)motion; }
  /// A caveat on usable results (e.g. no periodic steady state within max_cycles).
  virtual void Warn(const std::string& message) { (void)message; }
  /// Core's writers of the finished run (the files `filmdyn run` writes).
  virtual void SetWriters(RunWriters writers) { (void)writers; }
  /// The estimated discretisation error of the run's headline figures.
  virtual void ReportErrorEstimate(const engine::ErrorEstimate& estimate) { (void)estimate; }
  /// How far the headline figures moved over the run's last cycles (summary.json's
  /// cycle_scatter; none with fewer than two cycles or no headline figures).
  virtual void ReportCycleScatter(const std::optional<engine::CycleScatter>& scatter) {
    (void)scatter;
  }
  /// The film fields of the reported cycle (lubricated joints only).
  virtual void ReportFields(std::shared_ptr<const FieldFrames> fields) { (void)fields; }
  /// The engineering warnings of the finished run (io::RunWarnings: what summary.json lists).
  virtual void ReportWarnings(std::vector<io::RunWarning> warnings) { (void)warnings; }
};

/// The solver counters of a finished run, as the run table shows them (live from the run's
/// result, or from the summary.json of a run reopened with its project).
struct RunCounters {
  double cycles = 0, cycles_to_steady_state = 0, cycle_change = 0, steps = 0, rejected_steps = 0,
         max_constraint_violation = 0, reynolds_solves = 0;
  /// Oil into each mass-conserving film over the reported cycle [m^3] (io::ReportedOilPerCycle);
  /// NaN where there is none (a Reynolds film, a run stopped before a whole cycle): not reported.
  double skirt_oil_per_cycle = std::nan(""), big_end_oil_per_cycle = std::nan("");
};
/// The statistics' names of the oil per cycle (RunCounters).
inline constexpr const char* kSkirtOilStatistic = "skirt oil per cycle [m^3]";
inline constexpr const char* kBigEndOilStatistic = "big-end oil per cycle [m^3]";
/// Reports them as the sink's statistics: the one list of their names.
void ReportRunCounters(RunSink& sink, const RunCounters& counters);
/// `counters` with the oil per cycle of the run's KPIs.
RunCounters OilCounters(RunCounters counters, const io::RunKpis& kpis);

/// A backend returns when the run reached its end (completed, or not periodic with a warning)
/// and throws when it did not: RunCancelled when it was stopped by `cancel` (its partial results
/// reported), anything else when it failed. A cancel raised after the run ended changes nothing.
using RunBackend =
    std::function<void(const RunRequest& request, const std::atomic<bool>& cancel, RunSink& sink)>;

/// What a backend throws for a run stopped by its cancel flag.
struct RunCancelled : std::runtime_error {
  RunCancelled() : std::runtime_error("cancelled by the user") {}
};

/// The backend built on core's run API (see core_run_backend.cpp for what it covers).
RunBackend CoreRunBackend();

}  // namespace filmdyn::ui
