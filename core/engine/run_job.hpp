#pragma once
/// @file One headless run of the crank train: config in, result out, a per-output-step monitor that
/// may stop the run, an atomic cancel flag. The CLI (`filmdyn run`) and the GUI worker make the
/// same call; only the monitor differs.
#include <atomic>
#include <filesystem>
#include <functional>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "core/base/angles.hpp"
#include "core/engine/crank_train.hpp"
#include "core/engine/engine_case.hpp"
#include "core/engine/error_estimate.hpp"
#include "core/engine/pressure_curve.hpp"
#include "core/multibody/integrator.hpp"

namespace filmdyn::lubrication {
class SkirtSolver;
class BearingSolver;
}  // namespace filmdyn::lubrication

namespace filmdyn::engine {

/// The joint models: both ideal, one lubricated joint, or both (the paper's three plus Ideal).
enum class Model { kIdeal, kOnlySkirt, kOnlyLbrbe, kSkirtLbrbe };
/// "ideal", "only-skirt", "only-lbrbe", "skirt-lbrbe"; throws InputError("--model", ...).
Model ParseModel(const std::string& text);
/// Whether the model's skirt / big end is a lubricated film (the others are ideal joints).
bool SkirtLubricated(Model model);
bool BigEndLubricated(Model model);
std::string ModelName(Model model);
/// Sets skirt.model / big_end.model of a case for a model.
void ApplyModel(Model model, EngineCase* engine_case);
/// The model of a case, from its joints' models (the inverse of ApplyModel).
Model ModelOfCase(const EngineCase& engine_case);

/// The nodal fields of both lubricated joints at one output step (for the field files and the field
/// view). The solvers' fields() (pressure, contact_pressure, fluid_fraction), film_thickness() and
/// mesh() (node coordinates: skirt x = R α, y from the skirt top; bearing x = R θ from the maximum
/// film, y = z across the width) belong to the sampled state. nullptr = joint not lubricated.
/// Valid only during the callback.
struct FieldFrame {
  /// 1-based cycle the step belongs to; 0: the run-in, whose only frame is a failure's (below).
  int cycle = 0;
  /// Output step within the cycle, 0 … steps_per_cycle − 1 (in the run-in: of the run-in's).
  int step = 0;
  /// The output step at which the run failed, its film in trouble (the sample that ends
  /// results.csv): in a cycle the frame its step would have had anyway; in the run-in, whose
  /// film fields are not recorded, the one frame a failure there leaves, to see where it
  /// happened.
  bool failure = false;
  /// The step's crank angle in [0, 720) as results.csv labels it (CycleCrankAngleDeg): a cycle
  /// that starts elsewhere than 0 °CA (operating.start_crank_angle) passes 720 → 0 within it.
  double crank_angle_deg = 0.0;
  double time = 0.0;             ///< [s] since the start of the run
  /// The whole run's pass, from 1: a film temperature found by heat balance runs the whole run
  /// again at each new temperature, its cycles counted from 1 again; frames of an earlier pass
  /// belong to no reported cycle.
  int pass = 1;
  const CrankTrainSample* sample = nullptr;
  const lubrication::SkirtSolver* skirt = nullptr;
  const lubrication::BearingSolver* bearing = nullptr;
};
/// Called at every output step of every cycle, and at the output step where a run in its run-in
/// fails (FieldFrame::failure). The run reports the last cycle it computed (RunResult::cycles):
/// keep the frames of the newest cycle only (e.g. write them into a fresh folder per cycle, or
/// buffer one cycle). Costs nothing when empty.
using FieldCallback = std::function<void(const FieldFrame&)>;

/// Default RunConfig::motion_interval: 1/8 °CA (a journal crossing its clearance in ~20 °CA
/// near firing is drawn through ~160 points).
inline constexpr double kMotionInterval = kRadiansPerDegree / 8.0;

/// The progress displays' heartbeat (RunConfig::heartbeat_interval) [s].
inline constexpr double kHeartbeatInterval = 1.0;

struct RunConfig {
  EngineCase engine_case;  ///< joint models already set (ApplyModel)
  Model model = Model::kIdeal;
  double rpm = 6000.0;
  PressureCurve pressure;                  ///< cylinder pressure at rpm (io::PressureCurveForSpeed)
  LubricatedJointFactories factories;      ///< the film elements (MakeRunConfig sets them)
  multibody::IntegratorConfig integrator;  ///< tolerances (set from the case by MakeRunConfig)
  double wall_time_limit = 0.0;  ///< [s]; 0 = none. Reached: result incomplete, partial rows kept
  /// Threads for the two film joints of each evaluation (side by side; results identical bit
  /// for bit): 1 or 2; 0 = automatic (2 on a machine with at least 2 cores).
  int threads = 0;
  FieldCallback field_callback;  ///< optional per-output-step fields of the film joints
  /// Spacing of the motion samples (RunResult::motion) [rad of crank angle]: the output interval
  /// is divided into the fewest equal parts no longer than this. 0 = none (the error estimate's
  /// companion run). The samples are interpolated by the integrator between the steps it takes
  /// anyway: they cost no film solve and change no result.
  double motion_interval = kMotionInterval;
  /// Copies of one cycle's film fields the field callback's consumers hold in memory, for the
  /// memory check (the run folder's recorder: 1, or 2 where io::FieldRecorder::Attach keeps the
  /// previous cycle too; the GUI keeps its own view besides).
  double field_copies = 1.0;
  /// Where the case's relative file names (an imported compliance, a pressure-curve file)
  /// resolve: the case file's folder; empty = the working directory.
  std::filesystem::path case_directory;
  /// Wall time [s] without a progress report after which the monitor hears where the
  /// integration stands inside an output step (RunProgress::heartbeat), at the next evaluation
  /// of the forces; 0: no heartbeats (the monitor sees output steps only). The CLI and the GUI
  /// ask for kHeartbeatInterval.
  double heartbeat_interval = 0.0;
};

/// Refuses (InputError naming the largest film mesh) a run whose estimated memory exceeds what
/// this machine has available (core/engine/run_memory.hpp). RunJob calls it first; callers that
/// prepare outputs call it before they do.
void CheckRunMemory(const RunConfig& config);

/// Fills the integrator tolerances from the case's solver section.
/// `case_directory`: where the case's relative file names (an imported compliance) resolve.
RunConfig MakeRunConfig(const EngineCase& engine_case, Model model, double rpm,
                        PressureCurve pressure, const std::filesystem::path& case_directory = {});

/// What the monitor sees after each output step.
struct RunProgress {
  int cycle = 0;  ///< 1-based cycle being computed; 0 during the run-in
  int max_cycles = 0;
  bool run_in = false;            ///< the run-in before the first cycle (SolverCase::run_in_angle)
  /// From the cycle's start, [0, 720); run-in: to the first cycle, < 0 (the progress, not the
  /// crank angle's label)
  double crank_angle_deg = 0.0;
  double cycle_start_time = 0.0;  ///< time of the cycle's first sample [s] (run time, not crank)
  /// Overall progress [0, 1]: never decreases during a run (also from the run-in into cycle 1
  /// and from cycle to cycle when more cycles turn out to be needed), 1 at the last output step
  /// of a run that reached the steady state or max_cycles.
  double fraction = 0.0;
  double elapsed = 0.0;  ///< wall time so far [s]
  /// Estimated wall time left [s]. From a fraction of kRemainingSmoothedFrom on it is smoothed:
  /// between two updates it differs from the previous estimate minus the wall time in between by
  /// at most kRemainingMaxStep × (elapsed + that count-down) down, and that plus the wall time in
  /// between up, so it counts down steadily instead of jumping when a cycle starts, and holds
  /// (not counting down to nothing) through a stretch that is slow to integrate.
  double remaining = 0.0;
  /// The change of the last compared cycle (RunResult::cycle_changes' last); < 0 until the
  /// second cycle has ended.
  double cycle_change = -1.0;
  long steps = 0;                 ///< integrator steps so far
  long reynolds_solves = 0;       ///< film solves so far (both joints)
  /// The crank's angle at the time reached [rad], as CrankTrainSample::crank_angle (its label
  /// in results.csv: CycleCrankAngleDeg).
  double crank_angle = 0.0;
  /// A report from inside an output step (RunConfig::heartbeat_interval): the time the
  /// integration has reached (never going back), no sample; the fields above are then that
  /// time's.
  bool heartbeat = false;
  const CrankTrainSample* sample = nullptr;  ///< the step just computed (none in a heartbeat)
};

/// Largest change of RunProgress::remaining between two updates beyond the count-down of the
/// wall time in between, as a share of the estimated whole run time (elapsed + remaining).
inline constexpr double kRemainingMaxStep = 0.01;
/// Fraction of the run from which RunProgress::remaining is smoothed (before it, it follows the
/// extrapolation from the first steps).
inline constexpr double kRemainingSmoothedFrom = 0.1;

/// Return false to stop the run (it then ends as kCancelled with the rows so far).
using RunMonitor = std::function<bool(const RunProgress&)>;

enum class RunStatus { kCompleted, kNotConverged, kCancelled, kTimeLimit, kFailed };
std::string StatusName(RunStatus status);

struct RunResult {
  RunStatus status = RunStatus::kFailed;
  std::string message;                    ///< the reason, with the crank angle, when not completed
  std::vector<CrankTrainSample> samples;  ///< the reported (last) cycle, one per output step
  /// The clearance joints' motion over the same span as `samples`, in time order: at every
  /// output step (MotionOf the sample) and, inside the cycles of a model with a film joint, at
  /// RunConfig::motion_interval between them (the integrator's interpolation; none before the
  /// integrator's first step).
  std::vector<MotionSample> motion;
  int cycles = 0;                         ///< cycles computed
  /// The cycle `samples` belong to: the last (completed, not converged), the last whole one (a
  /// run stopped in its second or later cycle), the one it stopped in (its first, or a failure),
  /// 0 for the part of the run-in computed.
  int reported_cycle = 0;
  int cycles_to_steady_state = 0;         ///< 0 when not reached
  double cycle_change = 0.0;              ///< last cycle-to-cycle change / range (largest quantity)
  /// cycle_change after every compared cycle, in cycle order (cycles 2, 3, …): how the run
  /// approaches its periodic state.
  std::vector<double> cycle_changes;
  std::string worst_quantity;             ///< the quantity furthest from periodicity (last cycle)
  std::string worst_quantity_label;       ///< what messages call it ("the big end's minimum film")
  /// The headline figures of every completed cycle, in cycle order (HeadlineFigures; the last is
  /// the reported cycle's): with no periodic steady state, ScatterOverCycles says how far they
  /// move from cycle to cycle.
  std::vector<std::vector<HeadlineFigure>> cycle_headlines;
  long reynolds_solves = 0;               ///< Reynolds (FEM + cavitation) solves, both joints
  long reynolds_factorizations = 0;       ///< their numeric LDLᵀ factorisations
  multibody::SolverStats stats;
  double wall_time = 0.0;  ///< [s], start to end (with the error estimate's companion run)
  double max_constraint_violation = 0.0;
  /// The discretisation error of the headline figures (solver.error_estimate): a coarse
  /// companion run of the same case beside this one.
  ErrorEstimate error_estimate;
  /// Joints whose film temperature comes from their heat balance: the temperature the reported
  /// run used [K] (none: given), and how the iteration ended.
  std::optional<double> skirt_film_temperature, big_end_film_temperature;
  struct HeatBalance {
    int runs = 0;           ///< whole runs computed (each at the temperatures of the last)
    double residual = 0.0;  ///< largest |T_balance − T_used| of the reported run [K]
    bool converged = false;
  };
  std::optional<HeatBalance> heat_balance;  ///< none: no joint in heat-balance mode
};

/// A joint's heat balance at one run: the film temperature that carries `share` of its mean
/// friction power away with the oil leaving it, T_supply + share · P / (ρ c_p Q) [K];
/// T_supply when nothing leaves or nothing is lost. P [W] and Q [m³/s] over the reported cycle.
double HeatBalanceTemperature(double supply_temperature, double share, double friction_power,
                              double density, double heat_capacity, double outflow);

/// The physical failure of a film joint at an output sample: the joint it is in ("skirt",
/// "big_end", or empty: the whole run's state) and what happened; no message, no failure.
struct FilmFailure {
  std::string joint;
  std::string message;
  bool failed() const { return !message.empty(); }
};

/// The physical failure at an output sample, if any: the journal on the bearing, the skirt on
/// the liner, a mass-conserving film fraction outside [0, 1] by more than
/// coupling::kFractionTolerance, a film beyond its pressure-viscosity limit, a non-finite state.
/// RunJob ends a run with it (status failed, the message followed by what in the case may have
/// caused it and where).
FilmFailure FilmTrouble(const CrankTrainSample& sample);

/// The origin of results.csv's and motion.csv's time[s] for the reported samples: the start of
/// the reported cycle (its first output step, at 0 °CA), or for the part of the run-in a run
/// stopped in (reported_cycle 0) the run's start, t = 0, the start state before its first output
/// step — so that time[s] and crank_angle[deg] tell the same interval in every row.
double ReportedTimeOrigin(const RunResult& result);

/// Runs cycles from the assembled start until the periodic steady state (cycle-to-cycle change of
/// the monitored outputs below solver.steady_state_tolerance of their range) or max_cycles, and
/// keeps the last cycle. With solver.error_estimate = 1 and a film joint, a coarse companion
/// run (MakeCoarseCompanion) computes beside it and RunResult::error_estimate compares the two;
/// wall_time includes waiting for it. Never throws for numerical trouble (status + message
/// instead); bad input still throws InputError before anything runs.
RunResult RunJob(const RunConfig& config, const RunMonitor& monitor = {},
                 const std::atomic<bool>* cancel = nullptr);

}  // namespace filmdyn::engine
