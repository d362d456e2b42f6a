#include "core/engine/run_job.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>
#include <thread>
#include <tuple>

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

#include "core/base/angles.hpp"
#include "core/base/input_error.hpp"
#include "core/base/vector_unit.hpp"
#include "core/coupling/lubricated_big_end_element.hpp"
#include "core/coupling/lubricated_skirt_element.hpp"
#include "core/coupling/steady_state.hpp"
#include "core/engine/film_joints.hpp"
#include "core/engine/run_memory.hpp"

namespace filmdyn::engine {

Model ParseModel(const std::string& text) {
  if (text == "ideal") return Model::kIdeal;
  if (text == "only-skirt") return Model::kOnlySkirt;
  if (text == "only-lbrbe") return Model::kOnlyLbrbe;
  if (text == "skirt-lbrbe") return Model::kSkirtLbrbe;
  throw InputError("--model", text, "must be one of skirt-lbrbe, only-skirt, only-lbrbe, ideal");
}

std::string ModelName(Model model) {
  switch (model) {
    case Model::kIdeal:
      return "ideal";
    case Model::kOnlySkirt:
      return "only-skirt";
    case Model::kOnlyLbrbe:
      return "only-lbrbe";
    case Model::kSkirtLbrbe:
      return "skirt-lbrbe";
  }
  return "?";
}

bool SkirtLubricated(Model model) {
  return model == Model::kOnlySkirt || model == Model::kSkirtLbrbe;
}
bool BigEndLubricated(Model model) {
  return model == Model::kOnlyLbrbe || model == Model::kSkirtLbrbe;
}

void ApplyModel(Model model, EngineCase* c) {
  c->skirt.model = SkirtLubricated(model) ? JointModel::kLubricated : JointModel::kIdeal;
  c->big_end.model = BigEndLubricated(model) ? JointModel::kLubricated : JointModel::kIdeal;
}

Model ModelOfCase(const EngineCase& c) {
  const bool skirt = c.skirt.model == JointModel::kLubricated;
  const bool big_end = c.big_end.model == JointModel::kLubricated;
  return skirt && big_end ? Model::kSkirtLbrbe
         : skirt          ? Model::kOnlySkirt
         : big_end        ? Model::kOnlyLbrbe
                          : Model::kIdeal;
}

std::string StatusName(RunStatus status) {
  switch (status) {
    case RunStatus::kCompleted:
      return "completed";
    case RunStatus::kNotConverged:
      return "not-converged";
    case RunStatus::kCancelled:
      return "cancelled";
    case RunStatus::kTimeLimit:
      return "time-limit";
    case RunStatus::kFailed:
      return "failed";
  }
  return "?";
}

RunConfig MakeRunConfig(const EngineCase& engine_case, Model model, double rpm,
                        PressureCurve pressure, const std::filesystem::path& case_directory) {
  RunConfig config;
  config.engine_case = engine_case;
  ApplyModel(model, &config.engine_case);
  config.model = model;
  config.rpm = rpm;
  config.pressure = std::move(pressure);
  config.factories = FilmJointFactories(case_directory);
  config.case_directory = case_directory;
  const SolverCase& s = engine_case.solver;
  config.integrator.relative_tolerance = s.relative_tolerance;
  config.integrator.position_tolerance = s.position_tolerance;
  // Angles: the position tolerance over a 0.1 m lever. Velocities: the secondary motions of a
  // film-supported body are slaved to its film (squeeze-film damping relaxes a velocity error
  // within a fraction of a degree, it does not accumulate), so their local error is controlled
  // in absolute terms: 3e-7 m/s and 1e-3 rad/s at the default 1e-10 m (before: 1e-7 m/s and
  // 1e-6 rad/s; the piston tilt rate then limited ~70 % of all steps). 1e-6 m/s was 10 % faster
  // but left the minimum big-end MOFT up to 0.9 % (1.6 % at 0.25 °CA outputs) from a 100 x
  // tighter run; 3e-7 m/s keeps it within 0.5 % (docs/validation/coupling.md (b)).
  config.integrator.angle_tolerance = s.position_tolerance * 10.0;
  config.integrator.velocity_tolerance = s.position_tolerance * 3e3;
  config.integrator.angular_velocity_tolerance = s.position_tolerance * 1e7;
  // Bounded work per output step (never a hang): a stalled step size ends the run with a status.
  // A cancel or the time limit is honoured within the interval (the films' solves check them).
  // 20 000 was too few for the flooded start of a compressible mass-conserving film at 10×
  // tighter tolerances than the case's (more than 20 000 steps in its first 1 °CA output
  // interval, a run that then completes).
  config.integrator.max_steps_per_output = 200000;
  return config;
}

namespace {

// The skirt on the liner: where (the sample's thinnest film), the piston's attitude there, and
// what moves it. A contact at a skirt end with the piston tilted is the tilting moment's doing
// (pin height, centre of mass, the profile's end relief), one along the skirt the side force's
// (clearance, profile, viscosity). `at` says which sample it is when not the contact's own.
std::string SkirtContactText(const CrankTrainSample& s, const std::string& how,
                             const std::string& at) {
  return fmt::format(
      "piston skirt touches the liner ({}) at {:.0f}° from the thrust axis, {:.1f} mm below the "
      "skirt top{}, the piston {:.3g} µm off the bore axis and tilted {:.3g} mrad: the skirt "
      "film cannot carry the side force or hold the tilt there. What moves it: the clearance and "
      "the profile (skirt.cold_clearance, skirt.profile_h: more relief at the end that touches), "
      "the oil's viscosity, and the tilting moment (geometry.skirt_top_to_pin, "
      "geometry.skirt_top_to_com, geometry.piston_inertia)",
      how, s.skirt.moft_alpha * kDegreesPerRadian, s.skirt.moft_y * 1e3, at, s.piston_lateral * 1e6,
      s.piston_tilt * 1e3);
}

// A film failure's message with what in the case may have caused it: a starved skirt's liner
// film; a compressible oil whose bulk modulus the film's pressures passed, far beyond the small
// density changes the mass-conserving film's linearised density rho0 (1 + p / beta) stands for
// (the default case's big end at 6000 rpm fails in the first degrees of its run-in at beta =
// 0.1 GPa, its pressures reaching 23 GPa; at a mineral oil's 1.7 GPa it runs, its steps' peaks
// about 0.8 GPa).
std::string WithCauseHint(const FilmFailure& failure, const EngineCase& c,
                          const CrankTrainSample& sample) {
  std::string trouble = failure.message;
  const bool skirt_trouble = failure.joint == "skirt";
  const bool big_end_trouble = failure.joint == "big_end";
  if (skirt_trouble && c.skirt.supply == lubrication::SkirtSupply::kStarved) {
    const std::string film = c.skirt.oil_film_values.empty()
                                 ? fmt::format("skirt.oil_film = {:.3g} um", c.skirt.oil_film * 1e6)
                                 : "the table skirt.oil_film_values";
    trouble += "; the skirt runs starved on the liner's oil film (" + film +
               "): a thicker film may carry it";
  }
  if (!skirt_trouble && !big_end_trouble) return trouble;
  const JointOil& oil = skirt_trouble ? c.skirt.oil : c.big_end.oil;
  const std::string joint = skirt_trouble ? "skirt" : "big_end";
  double beta = 0.0;
  try {
    beta =
        JointBulkModulus(c, oil, joint, skirt_trouble ? c.skirt.cavitation : c.big_end.cavitation);
  } catch (const InputError&) {
    return trouble;  // the failure's own message stands
  }
  double peak = skirt_trouble ? sample.skirt.max_pressure : sample.bearing.max_pressure;
  const double step_peak =
      skirt_trouble ? sample.skirt.step_peak_pressure : sample.bearing.step_peak_pressure;
  if (std::isfinite(step_peak)) peak = std::max(peak, step_peak);
  const std::string prefix = JointOilPrefix(oil, joint);
  if (beta > 0.0 && peak > beta &&
      JointOilSpec(c, oil).density_law == lubrication::DensityLaw::kLinear) {
    trouble += fmt::format(
        "; the film's pressures (up to {:.3g} Pa) passed its oil's bulk modulus ({}bulk_modulus "
        "= {:.3g} Pa), far beyond the small density changes the linear density law stands for "
        "({}density_law = \"{}\" stiffens with pressure as oils do",
        peak, prefix, beta, prefix,
        lubrication::ToString(lubrication::DensityLaw::kDowsonHigginson));
    if (beta < lubrication::OilSpec::kMineralOilBulkModulus)
      trouble += fmt::format("; mineral oils: about {:.2g} Pa",
                             lubrication::OilSpec::kMineralOilBulkModulus);
    trouble += ")";
  }
  return trouble;
}

// The periodic-steady-state quantities of a model: e0, γ and the skirt MOFT for
// a lubricated skirt, ε and the bearing MOFT for a lubricated big end; the ideal model tracks
// the forces it has. Floors: 1 % of the clearance scales, so a flat trace cannot block.
struct Tracked {
  std::vector<coupling::TrackedQuantity> quantities;
  std::function<std::vector<double>(const CrankTrainSample&)> values;
};

Tracked TrackedFor(const EngineCase& c) {
  const bool skirt = c.skirt.model == JointModel::kLubricated;
  const bool big_end = c.big_end.model == JointModel::kLubricated;
  Tracked t;
  if (!skirt && !big_end) {
    t.quantities = {{"skirt_normal_force[N]", 1.0, "the liner's lateral force"},
                    {"bigend_force_x[N]", 1.0, "the big-end force x"},
                    {"bigend_force_y[N]", 1.0, "the big-end force y"},
                    {"crank_torque[N*m]", 0.1, "the crank torque"}};
    t.values = [](const CrankTrainSample& s) {
      return std::vector<double>{s.liner_force_on_piston.x(), s.big_end_force_on_rod.x(),
                                 s.big_end_force_on_rod.y(), s.crank_torque};
    };
    return t;
  }
  const double c_p = SkirtFit(c).hot_clearance;
  const double c_b = BigEndFit(c).hot_clearance;
  if (skirt) {
    t.quantities.push_back({"piston_lateral[m]", 0.01 * c_p, "the piston's lateral displacement"});
    t.quantities.push_back({"piston_tilt[rad]", 0.01 * c_p / c.skirt.length, "the piston's tilt"});
    t.quantities.push_back({"skirt_moft[m]", 0.01 * c_p, "the skirt's minimum film"});
  }
  if (big_end) {
    t.quantities.push_back({"bearing_eps[-]", 0.01, "the big-end eccentricity ratio"});
    t.quantities.push_back({"bearing_moft[m]", 0.01 * c_b, "the big end's minimum film"});
  }
  t.values = [skirt, big_end](const CrankTrainSample& s) {
    std::vector<double> v;
    v.reserve(5);
    if (skirt) {
      v.push_back(s.piston_lateral);
      v.push_back(s.piston_tilt);
      v.push_back(s.skirt.moft);
    }
    if (big_end) {
      v.push_back(s.bearing.eps);
      v.push_back(s.bearing.moft);
    }
    return v;
  };
  return t;
}

// Where the run stands, for messages: " (cycle 2, 123.0 °CA)"; cycle 0 is the run-in, whose
// angles count (negative) towards the first cycle. `crank_deg`: from the first cycle's start
// (cycle_start, the case's start crank angle [rad]); the message names the crank angle as the
// results label it (CycleCrankAngleDeg).
std::string AtAngle(int cycle, double crank_deg, double cycle_start) {
  const double label = CycleCrankAngleDeg(cycle_start + crank_deg * kRadiansPerDegree);
  if (cycle < 1) {
    return fmt::format(" (run-in, at {:.1f} °CA, {:.1f} °CA before the first cycle)", label,
                       -crank_deg);
  }
  return fmt::format(" (cycle {}, {:.1f} °CA)", cycle, label);
}

// Overall progress and time left for the monitor. Work is counted in cycles (the run-in as its
// share of a cycle). The expected total is the typical cycle count until the run gets there,
// then one cycle more than the current one (at most max_cycles). When the expected total grows,
// the fraction is not recomputed from scratch (that made it fall back, e.g. from 60 % to 44 %
// when cycle 2 started): the share still missing, 1 − f, is spread over the new remaining work,
// so the fraction is continuous and never decreases. The time left is extrapolated from the
// wall time per cycle of work so far (the film joints' set-up excluded); from
// kRemainingSmoothedFrom of the work on it is smoothed: it counts down with the wall clock and
// moves toward the extrapolation with a time constant of max(1 s, 20 % of the elapsed time), by
// at most kRemainingMaxStep of the estimated whole run time per update (up: plus the wall time
// since the last update).
class ProgressClock {
 public:
  ProgressClock(int typical, int max_cycles, double run_in_cycles, double setup_time)
      : typical_(typical),
        max_cycles_(max_cycles),
        run_in_cycles_(run_in_cycles),
        setup_time_(setup_time) {}

  /// `cycle`: 1-based cycle being computed (0 in the run-in); `work`: cycles done (with the
  /// run-in's share); `elapsed`: wall time since the run started [s].
  void Update(int cycle, double work, double elapsed, RunProgress* progress) {
    const double total = run_in_cycles_ + std::min(max_cycles_, std::max(typical_, cycle + 1.0));
    if (total > total_) {  // more work than expected: keep the fraction reached
      anchor_fraction_ = total_ > 0.0 ? std::clamp(FractionAt(work), fraction_, 1.0) : 0.0;
      anchor_work_ = total_ > 0.0 ? work : 0.0;
      total_ = total;
    }
    fraction_ = std::clamp(FractionAt(work), fraction_, 1.0);
    const double busy = std::max(0.0, elapsed - setup_time_);
    // The first steps (the stiff start from rest) are slow: a rate from under 2 % of the
    // expected work would overestimate the rest many times over.
    const double raw = busy / std::max(work, 0.02 * total_) * std::max(0.0, total_ - work);
    if (fraction_ < kRemainingSmoothedFrom) {
      remaining_ = raw;  // too little done to smooth from: follow the extrapolation
    } else {
      const double dt = std::max(0.0, elapsed - last_elapsed_);
      const double countdown = std::max(0.0, remaining_ - dt);
      const double weight = 1.0 - std::exp(-dt / std::max(1.0, 0.2 * elapsed));
      const double limit = kRemainingMaxStep * (elapsed + countdown);
      // Up by the wall time in between as well: while the extrapolation wants more (a stretch
      // of the cycle that is slow to integrate), the estimate holds instead of counting down to
      // a few seconds and staying there.
      remaining_ = countdown + std::clamp(weight * (raw - countdown), -limit, limit + dt);
    }
    last_elapsed_ = elapsed;
    progress->fraction = fraction_;
    progress->remaining = remaining_;
  }
  /// The run's last output step: all done.
  void Finish(RunProgress* progress) {
    fraction_ = 1.0;
    remaining_ = 0.0;
    progress->fraction = 1.0;
    progress->remaining = 0.0;
  }

 private:
  double FractionAt(double work) const {
    return anchor_fraction_ + (1.0 - anchor_fraction_) * (work - anchor_work_) /
                                  std::max(total_ - anchor_work_, 1e-12);
  }

  const double typical_, max_cycles_, run_in_cycles_, setup_time_;
  double total_ = 0.0, anchor_fraction_ = 0.0, anchor_work_ = 0.0;
  double fraction_ = 0.0, remaining_ = -1.0, last_elapsed_ = 0.0;
};

// One run of the model as configured (no error estimate).
RunResult RunSingle(const RunConfig& config, const RunMonitor& monitor,
                    const std::atomic<bool>* cancel) {
  ResetVectorUnitState();  // e.g. after a QApplication in this thread (core/base/vector_unit.hpp)
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  RunResult result;
  const EngineCase& c = config.engine_case;
  // Run-in: the integration starts run_in_angle before the first monitored cycle, so that the
  // start-up transient of the films (from the centred, resting journal and piston) has died
  // out by then and two cycles can already agree (docs/performance.md); jfo_run_in_angle when a
  // film conserves mass (its flooded start drains over about two cycles). Ideal joints have no
  // start-up transient (the kinematics are exact from the start): no run-in.
  const bool has_films =
      c.skirt.model == JointModel::kLubricated || c.big_end.model == JointModel::kLubricated;
  const double run_in = RunInAngle(c);
  EngineCase start_case = c;
  start_case.operating.start_crank_angle -= run_in;
  // A cancel or the time limit is honoured from the start: between the film joints' set-up
  // (mesh, matrix pattern, fill-reducing ordering: about a second each on the largest meshes
  // the case accepts), then inside every film evaluation and solve.
  auto past_time_limit = [&](double seconds) {
    return config.wall_time_limit > 0 && seconds > config.wall_time_limit;
  };
  const StopCheck stop = [&] { return (cancel && cancel->load()) || past_time_limit(elapsed()); };
  auto stop_around = [&stop](const JointForceFactory& make) -> JointForceFactory {
    if (!make) return make;
    return [&stop, make](const EngineCase& engine_case, const CrankTrainLayout& layout) {
      ThrowIfStopRequested(stop);
      auto element = make(engine_case, layout);
      ThrowIfStopRequested(stop);
      return element;
    };
  };
  const LubricatedJointFactories factories{stop_around(config.factories.skirt),
                                           stop_around(config.factories.big_end)};
  std::optional<CrankTrain> built;
  try {
    built.emplace(BuildCrankTrain(start_case, config.rpm, config.pressure, factories));
  } catch (const StopRequested&) {
    const bool cancelled = cancel && cancel->load();
    result.status = cancelled ? RunStatus::kCancelled : RunStatus::kTimeLimit;
    result.message = std::string(cancelled ? "cancelled" : "wall-time limit reached") +
                     " while setting up the film joints";
    result.wall_time = elapsed();
    return result;
  }
  CrankTrain& train = *built;
  auto* skirt = dynamic_cast<coupling::LubricatedSkirtElement*>(train.skirt_element);
  auto* big_end = dynamic_cast<coupling::LubricatedBigEndElement*>(train.big_end_element);
  // Threads: the two film joints side by side, and the skirt's two panels side by side.
  const int threads = config.threads > 0
                          ? config.threads
                          : std::min(2, static_cast<int>(std::thread::hardware_concurrency()));
  train.system->SetThreads(threads);
  if (skirt) skirt->SetPanelThreads(threads);
  // The integration stops inside an output step, at the next evaluation of the films (a step
  // on a huge mesh can take minutes).
  train.system->SetStopCheck(stop);
  if (skirt) skirt->SetStopCheck(stop);
  if (big_end) big_end->SetStopCheck(stop);
  const double omega = train.layout.omega;
  const double t_start = run_in / omega;  // time of the first monitored sample
  // A pressure-viscosity law is phased in over the first half of the run-in (the start from rest
  // drives the films past its limit; coupling/pressure_law_ramp.hpp); elastic surfaces over its
  // first quarter (they meet the start's squeeze rigid), which leaves a flexible skirt three
  // quarters of the run-in to settle (phased in over half of it, the FE skirt of the examples
  // needed a third cycle to be periodic: docs/performance.md).
  if (skirt) skirt->PhaseIn(0.5 * t_start, 0.25 * t_start);
  if (big_end) big_end->PhaseIn(0.5 * t_start, 0.25 * t_start);
  multibody::Integrator integrator(*train.system, config.integrator);
  integrator.Initialize(0.0, train.initial_state);

  const double cycle_time = 4.0 * std::numbers::pi / omega;
  const int steps_per_cycle =
      std::max(2, static_cast<int>(std::lround(4.0 * std::numbers::pi / c.solver.output_interval)));
  const int max_cycles = c.solver.max_cycles;
  const Tracked tracked = TrackedFor(c);
  coupling::PeriodicSteadyState steady(tracked.quantities, steps_per_cycle,
                                       c.solver.steady_state_tolerance);
  auto solves = [&] {
    result.reynolds_factorizations =
        (skirt ? skirt->factorizations() : 0L) + (big_end ? big_end->factorizations() : 0L);
    return (skirt ? skirt->reynolds_solves() : 0L) + (big_end ? big_end->reynolds_solves() : 0L);
  };
  // The reported span: a cycle's (or the run-in's) output samples and the motion over them.
  struct Span {
    std::vector<CrankTrainSample> samples;
    std::vector<MotionSample> motion;
    int cycle = 0;  ///< the cycle the samples belong to (0: the run-in)
    bool empty() const { return samples.empty(); }
    void clear() {
      samples.clear();
      motion.clear();
    }
    const CrankTrainSample& Add(CrankTrainSample sample) {
      motion.push_back(MotionOf(sample));
      samples.push_back(std::move(sample));
      return samples.back();
    }
  };
  Span previous, current;
  auto keep = [&result](Span span) {
    result.reported_cycle = span.cycle;
    result.samples = std::move(span.samples);
    result.motion = std::move(span.motion);
  };
  // Motion samples between output steps: the output interval in equal parts of at most
  // config.motion_interval. CVODE (CV_NORMAL) returns a time inside the steps it has taken by
  // interpolation and chooses its steps independently of the times asked for, so these cost no
  // evaluation of the films and leave every result as it is — except before its first step,
  // whose initial size it estimates from the first time asked for: none there. Ideal joints have
  // no clearance motion: none either.
  const int motion_parts =
      config.motion_interval > 0.0 && has_films
          ? std::max(1, static_cast<int>(
                            std::ceil(c.solver.output_interval / config.motion_interval - 1e-9)))
          : 1;
  auto add_motion_between = [&](double t_from, double t_to) {
    if (motion_parts < 2 || integrator.Stats().steps == 0) return;
    for (int j = 1; j < motion_parts; ++j) {
      const double t_j = t_from + (t_to - t_from) * j / motion_parts;
      current.motion.push_back(SampleMotion(train, c, t_j, integrator.AdvanceTo(t_j)));
    }
  };
  double crank_deg = 0.0;
  int cycle = 1;
  // Where the run stands now, for messages.
  auto where_now = [&] { return AtAngle(cycle, crank_deg, c.operating.start_crank_angle); };
  // Typical cycle counts (for the progress estimate): 2 for the ideal model and for film models
  // after a run-in of at least 270 °CA (measured: cycle 2 then agrees with cycle 1 to < 1 %),
  // 4 for film models without one. The run-in counts as its share of a cycle.
  const int typical = !has_films || run_in >= 1.5 * std::numbers::pi - 1e-9 ? 2 : 4;
  const double run_in_cycles = run_in / (4.0 * std::numbers::pi);
  ProgressClock clock(typical, max_cycles, run_in_cycles, elapsed());
  double last_report = elapsed();   // wall time of the monitor's last call
  bool stopped_by_monitor = false;  // its answer: stop
  double t_target = 0.0;            // the output (or motion) time being integrated to
  // Fills the common progress fields (`work`: cycles done, with the run-in's share; `last`: the
  // run's last output step), calls the monitor and sets a cancel/time-limit status.
  auto report = [&](RunProgress& progress, double work, bool last, const std::string& where) {
    progress.max_cycles = max_cycles;
    progress.elapsed = elapsed();
    if (last) {
      clock.Finish(&progress);
    } else {
      clock.Update(progress.cycle, work, progress.elapsed, &progress);
    }
    progress.steps = result.stats.steps;
    progress.reynolds_solves = result.reynolds_solves;
    if (progress.sample != nullptr) progress.crank_angle = progress.sample->crank_angle;
    last_report = progress.elapsed;
    const bool go_on = !monitor || monitor(progress);
    stopped_by_monitor = !go_on;
    const bool cancelled = cancel && cancel->load();
    if (!go_on || cancelled) {
      result.status = RunStatus::kCancelled;
      result.message = "cancelled" + where;
    } else if (past_time_limit(progress.elapsed)) {
      result.status = RunStatus::kTimeLimit;
      result.message = "wall-time limit reached" + where;
    }
    return result.status == RunStatus::kCancelled || result.status == RunStatus::kTimeLimit;
  };
  // Heartbeats: inside an output step that takes long (a large mesh, a stiff stretch), the
  // monitor hears the time the integration has reached (bounded by the output time it heads
  // for, which the integrator may overshoot and interpolate back from, and never earlier than
  // the last heartbeat's: the progress never runs backwards).
  const double crank_angle_0 = train.gas_force->CrankAngle(train.initial_state);
  double t_shown = 0.0;  // the last heartbeat's time: a retried step evaluates earlier ones
  if (monitor && config.heartbeat_interval > 0.0) {
    train.system->SetEvaluationObserver([&](double t_eval) {
      if (elapsed() - last_report < config.heartbeat_interval) return;
      const double t = t_shown = std::max(t_shown, std::min(t_eval, t_target));
      result.stats = integrator.Stats();
      result.reynolds_solves = solves();
      RunProgress progress;
      progress.heartbeat = true;
      progress.crank_angle = crank_angle_0 + omega * t;
      double work = 0.0;
      if (cycle == 0) {
        progress.run_in = true;
        progress.crank_angle_deg = -(t_start - t) * omega * kDegreesPerRadian;
        work = run_in_cycles * t / t_start;
      } else {
        const double cycle_start = t_start + (cycle - 1) * cycle_time;
        progress.cycle = cycle;
        progress.cycle_start_time = cycle_start;
        progress.crank_angle_deg = 720.0 * (t - cycle_start) / cycle_time;
        if (!result.cycle_changes.empty()) progress.cycle_change = result.cycle_changes.back();
        // As the output step it heads for counts itself done (k + 1 of the cycle's steps).
        work = run_in_cycles + (cycle - 1) + (t - cycle_start) / cycle_time + 1.0 / steps_per_cycle;
      }
      if (report(progress, work, false, where_now())) throw StopRequested();
    });
  }
  // The films at an output step, to the field callback (the solvers re-solved at the step's
  // state: the integrator's last evaluation may lie elsewhere).
  auto field_frame = [&](int in_cycle, int step, double t, const CrankTrainSample& sample,
                         bool failure) {
    if (skirt) skirt->RefreshFields();
    if (big_end) big_end->RefreshFields();
    FieldFrame frame;
    frame.cycle = in_cycle;
    frame.step = step;
    frame.failure = failure;
    frame.crank_angle_deg = CycleCrankAngleDeg(sample.crank_angle);  // as results.csv
    frame.time = t;
    frame.sample = &sample;
    frame.skirt = skirt ? &skirt->solver() : nullptr;
    frame.bearing = big_end ? &big_end->solver() : nullptr;
    config.field_callback(frame);
    result.reynolds_solves = solves();
  };
  // The films where the run failed (the step's film solved, its figures out of bounds). Only a
  // picture of the failure: should the films not solve again there, the failure stands without.
  auto failure_frame = [&](int in_cycle, int step, double t, const CrankTrainSample& sample) {
    if (!config.field_callback) return;
    try {
      field_frame(in_cycle, step, t, sample, true);
    } catch (const std::exception&) {
    }
  };
  try {
    if (t_start > 0.0) {
      // Only where the run-in ends matters, not its accuracy: 10 x looser tolerances (the
      // start-up transient from rest is the stiffest part of the run). Sampled at the output
      // interval, so a film failure or a cancel in the run-in is reported where it happened
      // and what was computed is kept.
      integrator.SetTolerances(config.integrator.ScaledTolerances(10.0));
      cycle = 0;
      const int chunks =
          std::max(1, static_cast<int>(std::ceil(run_in / c.solver.output_interval - 1e-9)));
      for (int j = 1; j < chunks; ++j) {
        const double t = t_start * j / chunks;
        crank_deg = -(run_in - run_in * j / chunks) * kDegreesPerRadian;
        t_target = t;
        current.Add(SampleCrankTrain(train, c, t, integrator.AdvanceTo(t)));
        result.stats = integrator.Stats();
        result.reynolds_solves = solves();
        const std::string where = where_now();
        if (const FilmFailure trouble = FilmTrouble(current.samples.back()); trouble.failed()) {
          result.status = RunStatus::kFailed;
          result.message = WithCauseHint(trouble, c, current.samples.back()) + where;
          failure_frame(0, j, t, current.samples.back());
          keep(std::move(current));
          result.wall_time = elapsed();
          return result;
        }
        RunProgress progress;
        progress.run_in = true;
        progress.crank_angle_deg = crank_deg;
        progress.sample = &current.samples.back();
        if (report(progress, run_in_cycles * j / chunks, false, where)) {
          keep(std::move(current));
          result.wall_time = elapsed();
          return result;
        }
      }
      t_target = t_start;
      integrator.AdvanceTo(t_start);
      integrator.SetTolerances(config.integrator);
      current.clear();
    }
    coupling::CycleVerdict verdict;
    for (cycle = 1; cycle <= max_cycles; ++cycle) {
      current.clear();
      current.cycle = cycle;
      for (int k = 0; k < steps_per_cycle; ++k) {
        const double t = t_start + (cycle - 1) * cycle_time + k * cycle_time / steps_per_cycle;
        crank_deg = 720.0 * k / steps_per_cycle;
        t_target = t;
        if (k > 0) add_motion_between(t - cycle_time / steps_per_cycle, t);
        const multibody::SystemState state =
            t > 0.0 ? integrator.AdvanceTo(t) : train.initial_state;
        const CrankTrainSample& sample = current.Add(SampleCrankTrain(train, c, t, state));
        result.max_constraint_violation =
            std::max(result.max_constraint_violation, sample.constraint_violation);
        result.stats = integrator.Stats();
        result.reynolds_solves = solves();
        if (const FilmFailure trouble = FilmTrouble(sample); trouble.failed()) {
          result.status = RunStatus::kFailed;
          result.message = WithCauseHint(trouble, c, sample) + where_now();
          result.cycles = cycle;
          failure_frame(cycle, k, t, sample);
          keep(std::move(current));
          result.wall_time = elapsed();
          return result;
        }
        steady.Record(k, tracked.values(sample));
        if (config.field_callback) field_frame(cycle, k, t, sample, false);
        // The cycle's verdict before its last step is reported, so that the monitor sees the
        // run's last step as such (fraction 1).
        const bool cycle_end = k == steps_per_cycle - 1;
        if (cycle_end) verdict = steady.EndCycle();
        RunProgress progress;
        progress.cycle = cycle;
        progress.crank_angle_deg = crank_deg;
        if (!result.cycle_changes.empty()) progress.cycle_change = result.cycle_changes.back();
        progress.cycle_start_time = t_start + (cycle - 1) * cycle_time;
        progress.sample = &current.samples.back();
        const double work = run_in_cycles + (cycle - 1) + (k + 1.0) / steps_per_cycle;
        const bool last = cycle_end && (verdict.converged || cycle == max_cycles);
        if (report(progress, work, last, where_now())) {
          result.cycles = cycle;
          keep(previous.empty() ? current : previous);
          result.wall_time = elapsed();
          return result;
        }
      }
      result.cycles = cycle;
      result.cycle_headlines.push_back(HeadlineFigures(
          current.samples, {&current.motion, c.geometry.piston_mass, c.geometry.piston_inertia}));
      if (verdict.compared) {
        result.cycle_change = verdict.worst_relative_change;
        result.cycle_changes.push_back(verdict.worst_relative_change);
        result.worst_quantity = verdict.worst_quantity;
        result.worst_quantity_label = verdict.worst_label;
      }
      if (verdict.converged) {
        result.cycles_to_steady_state = cycle;
        result.status = RunStatus::kCompleted;
        keep(std::move(current));
        result.stats = integrator.Stats();
        result.reynolds_solves = solves();
        result.wall_time = elapsed();
        return result;
      }
      previous = std::move(current);
    }
    result.status = RunStatus::kNotConverged;
    result.message =
        max_cycles < 2
            ? fmt::format(
                  "no periodic steady state: solver.max_cycles = {} allows no second "
                  "cycle to compare the first with",
                  max_cycles)
            : fmt::format(
                  "no periodic steady state after {} cycles (the last change {} % of "
                  "the range of {})",
                  max_cycles, PercentText(result.cycle_change), result.worst_quantity_label);
    keep(std::move(previous));
  } catch (const InputError&) {
    throw;
  } catch (const StopRequested&) {
    const bool cancelled = (cancel && cancel->load()) || stopped_by_monitor;
    result.status = cancelled ? RunStatus::kCancelled : RunStatus::kTimeLimit;
    result.message = (cancelled ? "cancelled" : "wall-time limit reached") + where_now();
    result.cycles = std::max(cycle, 0);
    keep(previous.empty() ? current : previous);
  } catch (const multibody::SurfacesInContact& contact) {
    // Elastic surfaces that meet past their rigid position: the contact, not the integrator.
    result.status = RunStatus::kFailed;
    const bool skirt = contact.Joint() == "skirt";
    const std::string how =
        "the elastic surfaces meet past their rigid position and their deformation does not "
        "open the film";
    FilmFailure failure{
        skirt ? "skirt" : "big_end",
        fmt::format(
            "{} ({})",
            skirt ? "piston skirt touches the liner" : "big-end journal touches the bearing", how)};
    if (!current.empty()) {
      const CrankTrainSample& last = current.samples.back();
      if (skirt) {
        failure.message = SkirtContactText(
            last, how,
            fmt::format(" at the last output ({:.1f} °CA)", CycleCrankAngleDeg(last.crank_angle)));
      }
      failure.message = WithCauseHint(failure, c, last);
    }
    result.message =
        failure.message + where_now() + "; the integrator's account: " + contact.what();
    result.cycles = std::max(cycle, 0);
    keep(current.empty() ? previous : current);
  } catch (const std::exception& error) {
    result.status = RunStatus::kFailed;
    result.message = std::string("integration failed: ") + error.what() + where_now();
    if (dynamic_cast<const multibody::TolerancesTooTight*>(&error) != nullptr)
      result.message +=
          "; the tolerances ask for more accuracy than double precision gives: loosen "
          "solver.relative_tolerance or solver.position_tolerance";
    result.cycles = std::max(cycle, 0);  // the cycle it failed in, as a film's failure
    if (!current.empty()) {  // name the film state where it stopped
      const CrankTrainSample& last = current.samples.back();
      result.message += fmt::format("; last output: eps = {:.4f}, skirt gap {:.3g} um",
                                    last.bearing.eps, last.skirt.min_gap * 1e6);
    }
    keep(current.empty() ? previous : current);
  }
  result.stats = integrator.Stats();
  result.reynolds_solves = solves();
  result.wall_time = elapsed();
  return result;
}

}  // namespace

void CheckRunMemory(const RunConfig& config) {
  const EngineCase& c = config.engine_case;
  RequireMemory(c, EstimateRunMemory(c, config.field_callback ? config.field_copies : 0.0),
                AvailableMemoryBytes());
}

FilmFailure FilmTrouble(const CrankTrainSample& s) {
  if (s.bearing.present && (!std::isfinite(s.bearing.eps) || s.bearing.eps >= s.bearing.eps_max)) {
    return {
        "big_end",
        fmt::format(
            "big-end journal touches the bearing (eps = {:.5f}): the film cannot carry the load "
            "with this clearance/viscosity",
            s.bearing.eps)};
  }
  if (s.skirt.present &&
      (!std::isfinite(s.skirt.min_gap) || s.skirt.min_gap <= s.skirt.min_gap_allowed)) {
    return {"skirt",
            SkirtContactText(s, fmt::format("smallest gap {:.3g} µm", s.skirt.min_gap * 1e6), "")};
  }
  for (const auto& [present, excess, joint, name] :
       {std::tuple{s.bearing.present, s.bearing.fraction_excess, "big_end", "big-end"},
        std::tuple{s.skirt.present, s.skirt.fraction_excess, "skirt", "skirt"}}) {
    if (present && excess > coupling::kFractionTolerance) {
      return {
          joint,
          fmt::format(
              "{} film fraction left [0, 1] by {:.3g} (more than {:g}): the mass-conserving "
              "cavitation solve failed; refine the film mesh or tighten solver.relative_tolerance",
              name, excess, coupling::kFractionTolerance)};
    }
  }
  for (const auto& [present, capped, joint, name] :
       {std::tuple{s.bearing.present, s.bearing.capped_nodes, "big_end", "big-end"},
        std::tuple{s.skirt.present, s.skirt.capped_nodes, "skirt", "skirt"}}) {
    if (present && capped > 0) {
      return {
          joint,
          fmt::format(
              "{} film beyond the pressure-viscosity limit at {} nodes: with this oil's pressure "
              "law no finite pressure carries the load (the isoviscous pressure exceeds the law's "
              "limit, 1/alpha for Barus): a smaller coefficient (lubricant.barus_alpha or "
              "lubricant.roelands_z, or the joint's own oil's) or pressure_viscosity \"none\"",
              name, capped)};
    }
  }
  if (!std::isfinite(s.piston_lateral) || !std::isfinite(s.crank_torque) ||
      !std::isfinite(s.big_end_force_on_rod.norm())) {
    return {"", "the solution diverged (non-finite state)"};
  }
  return {};
}

namespace {
RunResult RunWithEstimate(const RunConfig& config, const RunMonitor& monitor,
                          const std::atomic<bool>* cancel);

// A joint whose film temperature comes from its heat balance: the secant iteration on
// f(T) = T_balance(T) − T, safeguarded by the bracket the signs of f give (f(T_supply) >= 0;
// f falls with T: a hotter film loses less power and sheds more oil).
struct BalancedJoint {
  bool skirt = false;
  JointOil* oil = nullptr;
  double t = 0.0, f = 0.0;  // the last run's temperature and residual
  double t_prev = 0.0, f_prev = 0.0;
  bool have_prev = false;
  double lo = 0.0, hi = 1e300;  // f(lo) >= 0 > f(hi)
};

// The joint's mean friction power [W] (its headline figure) and mean outflow [m³/s] over the
// reported samples; false when they hold no film of the joint. A mass-conserving film's outflow
// is its oil account's (booked at every integrator step, the oil per cycle it reports), not the
// samples' mean, which misses or over-weights the flows' spikes between the samples.
bool PowerAndOutflow(const std::vector<CrankTrainSample>& samples, bool skirt, double* power,
                     double* outflow) {
  const char* key = skirt ? "skirt_fpl_mean[W]" : "bearing_fpl_mean[W]";
  const std::vector<HeadlineFigure> figures = HeadlineFigures(samples);
  const auto fpl = std::find_if(figures.begin(), figures.end(),
                                [key](const HeadlineFigure& f) { return f.key == key; });
  if (fpl == figures.end()) return false;
  *power = fpl->value;
  const double n = static_cast<double>(samples.size());
  if (const auto oil = AccountedOil(samples, !skirt)) {
    // The account's oil over the samples' whole span (their count times their interval).
    *outflow = oil->out / ((samples[1].time - samples[0].time) * n);
    return true;
  }
  double q = 0.0;
  for (const CrankTrainSample& s : samples) q += skirt ? s.skirt.outflow : s.bearing.side_flow;
  *outflow = q / n;
  return true;
}
}  // namespace

double HeatBalanceTemperature(double supply_temperature, double share, double friction_power,
                              double density, double heat_capacity, double outflow) {
  if (!(outflow > 0.0) || !(friction_power > 0.0)) return supply_temperature;
  return supply_temperature + share * friction_power / (density * heat_capacity * outflow);
}

double ReportedTimeOrigin(const RunResult& result) {
  if (result.samples.empty() || result.reported_cycle == 0) return 0.0;
  return result.samples.front().time;
}

RunResult RunJob(const RunConfig& config, const RunMonitor& monitor,
                 const std::atomic<bool>* cancel) {
  const EngineCase& c0 = config.engine_case;
  std::vector<BalancedJoint> joints;
  RunConfig run = config;
  EngineCase& c = run.engine_case;
  if (c.skirt.model == JointModel::kLubricated &&
      c.skirt.oil.temperature_mode == FilmTemperature::kHeatBalance)
    joints.push_back({.skirt = true, .oil = &c.skirt.oil});
  if (c.big_end.model == JointModel::kLubricated &&
      c.big_end.oil.temperature_mode == FilmTemperature::kHeatBalance)
    joints.push_back({.skirt = false, .oil = &c.big_end.oil});
  if (joints.empty()) return RunWithEstimate(config, monitor, cancel);
  RequirePositive("lubricant.density", c0.lubricant.density, "kg/m^3");
  RequirePositive("lubricant.heat_capacity", c0.lubricant.heat_capacity, "J/(kg*K)");
  const double t_supply = c0.lubricant.supply_temperature;
  constexpr double kTolerance = 0.25;  // [K]
  constexpr int kMaxRuns = 10;
  for (BalancedJoint& j : joints) {
    j.t = StartFilmTemperature(c0, *j.oil);
    j.lo = t_supply;
  }
  RunResult::HeatBalance hb;
  RunResult result;
  double wall = 0.0;
  bool reported = false;  // the last run reported a cycle (completed or not converged)
  // Why the iteration stopped before its balance (empty: converged, or out of runs).
  std::string stopped;
  // The time limit holds for the whole command, every run of the balance included.
  const auto start = std::chrono::steady_clock::now();
  const auto seconds_used = [&start] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  while (true) {
    for (BalancedJoint& j : joints) j.oil->temperature = j.t;
    if (config.wall_time_limit > 0.0)
      run.wall_time_limit = std::max(config.wall_time_limit - seconds_used(), 1e-3);
    if (config.field_callback) {  // each pass's frames marked with it (its cycles restart at 1)
      run.field_callback = [&config, pass = hb.runs + 1](const FieldFrame& frame) {
        FieldFrame marked = frame;
        marked.pass = pass;
        config.field_callback(marked);
      };
    }
    result = RunWithEstimate(run, monitor, cancel);
    wall += result.wall_time;
    ++hb.runs;
    reported = result.status == RunStatus::kCompleted || result.status == RunStatus::kNotConverged;
    if (!reported) {
      if (hb.runs > 1)  // the results are this run's part, not an earlier whole run's
        result.message = fmt::format("heat-balance run {}: {}", hb.runs, result.message);
      break;
    }
    hb.residual = 0.0;
    for (BalancedJoint& j : joints) {
      double power = 0.0, outflow = 0.0;
      if (!PowerAndOutflow(result.samples, j.skirt, &power, &outflow)) continue;
      const JointOil& oil = *j.oil;
      const double target =
          HeatBalanceTemperature(t_supply, oil.heat_share, power, c0.lubricant.density,
                                 c0.lubricant.heat_capacity, outflow);
      j.f = target - j.t;
      hb.residual = std::max(hb.residual, std::abs(j.f));
    }
    if (hb.residual <= kTolerance) {
      hb.converged = true;
      break;
    }
    // Oils whose viscosity does not follow temperature: another run at the balance's temperature
    // would be this one again, so the balance is its fixed point already.
    if (std::all_of(joints.begin(), joints.end(),
                    [&c](const BalancedJoint& j) { return TemperatureFreeOil(c, *j.oil); })) {
      for (BalancedJoint& j : joints) j.t += j.f;
      hb.residual = 0.0;
      hb.converged = true;
      break;
    }
    if (hb.runs >= kMaxRuns) break;
    if (config.wall_time_limit > 0.0 && seconds_used() >= config.wall_time_limit) {
      stopped = fmt::format("wall-time limit reached after heat-balance run {}", hb.runs);
      result.status = RunStatus::kTimeLimit;
      break;
    }
    for (BalancedJoint& j : joints) {
      if (j.f >= 0.0) j.lo = std::max(j.lo, j.t);
      if (j.f < 0.0) j.hi = std::min(j.hi, j.t);
      double next = j.t + j.f;  // the plain fixed-point step first
      if (j.have_prev && j.f != j.f_prev) next = j.t - j.f * (j.t - j.t_prev) / (j.f - j.f_prev);
      // Inside the bracket (bisection when the secant leaves it), never below the supply.
      if (j.hi < 1e300 && !(next > j.lo && next < j.hi)) next = 0.5 * (j.lo + j.hi);
      next = std::max(next, t_supply);
      j.t_prev = j.t;
      j.f_prev = j.f;
      j.have_prev = true;
      j.t = next;
    }
    // A temperature the balance asks for that the joint's oil has no viscosity at (past a
    // catalogue oil's range, or where its law has no finite value) ends the iteration here,
    // with this run's results: another run cannot start there.
    for (const BalancedJoint& j : joints) {
      JointOil next_oil = *j.oil;
      next_oil.temperature = j.t;
      try {
        JointOilAt(c, next_oil, j.skirt ? "skirt" : "big_end");
      } catch (const InputError& e) {
        stopped = fmt::format(
            "heat balance stopped: the {} film's balance asks for {:.1f} K ({:.1f} °C; this run "
            "at {:.1f} K), where its oil has no viscosity ({}): the friction power is too large "
            "for the oil flow through the film (lubricant.heat_capacity, lubricant.density, {}.oil"
            ".heat_share)",
            j.skirt ? "skirt" : "big-end", j.t, j.t - 273.15, j.oil->temperature, e.what(),
            j.skirt ? "skirt" : "big_end");
        break;
      }
    }
    if (!stopped.empty()) break;
  }
  // The temperatures the reported run used (a run stopped before its balance: not the next
  // ones the iteration would have tried).
  for (const BalancedJoint& j : joints)
    (j.skirt ? result.skirt_film_temperature : result.big_end_film_temperature) =
        hb.converged ? j.t : j.oil->temperature;
  result.heat_balance = hb;
  result.wall_time = wall;
  if (!hb.converged && reported) {
    // Its results are one run's at temperatures that are not their balance: not converged
    // (a run that found no periodic state stays so; a time limit stays a time limit).
    if (result.status == RunStatus::kCompleted) result.status = RunStatus::kNotConverged;
    result.message +=
        (result.message.empty() ? "" : "; ") + (stopped.empty() ? std::string() : stopped + "; ") +
        fmt::format(
            "heat balance not converged: film temperature {:.2f} K from its balance after {} "
            "runs (tolerance {:g} K)",
            hb.residual, hb.runs, kTolerance);
  }
  return result;
}

namespace {
RunResult RunWithEstimate(const RunConfig& config, const RunMonitor& monitor,
                          const std::atomic<bool>* cancel) {
  CheckRunMemory(config);
  const EngineCase& c = config.engine_case;
  const bool has_films =
      c.skirt.model == JointModel::kLubricated || c.big_end.model == JointModel::kLubricated;
  if (!has_films || c.solver.error_estimate == 0) {
    RunResult result = RunSingle(config, monitor, cancel);
    result.error_estimate.status = has_films ? "off" : "not-applicable";
    return result;
  }
  // The coarse companion runs beside the run on its own thread (one film thread: the run itself
  // keeps the machine's other core busy only part of the time) and is stopped when the run is
  // cancelled or ends without a reported cycle.
  const auto start = std::chrono::steady_clock::now();
  const CoarseCompanion companion = MakeCoarseCompanion(c);
  RunConfig coarse = config;
  coarse.engine_case = companion.engine_case;
  coarse.integrator = config.integrator.ScaledTolerances(companion.tolerance_factor);
  coarse.threads = 1;
  coarse.field_callback = nullptr;
  // Its motion samples as the run's: the slap energy is taken from them (SlapOf).
  std::atomic<bool> stop_coarse{false};
  RunResult coarse_result;
  std::string coarse_error;
  std::thread coarse_thread([&] {
    // Lower priority (nice +10): the companion takes the cycles the run and the GUI leave idle
    // instead of taking them from them — a desktop's event loop must stay responsive with the
    // run's two film threads and the companion busy. On Linux, setpriority with a thread id
    // affects that thread only; elsewhere the companion runs at normal priority.
#if defined(__linux__)
    setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 10);
#endif
    try {
      coarse_result = RunSingle(
          coarse,
          [&](const RunProgress&) { return !stop_coarse.load() && !(cancel && cancel->load()); },
          &stop_coarse);
    } catch (const std::exception& error) {
      coarse_error = error.what();
    }
  });
  RunResult result;
  try {
    result = RunSingle(config, monitor, cancel);
  } catch (...) {
    stop_coarse = true;
    coarse_thread.join();
    throw;
  }
  if (result.status != RunStatus::kCompleted && result.status != RunStatus::kNotConverged) {
    stop_coarse = true;
  }
  coarse_thread.join();
  ErrorEstimate& estimate = result.error_estimate;
  if (!coarse_error.empty()) {
    estimate.status = "unavailable";
    estimate.message = "the coarse companion run failed: " + coarse_error;
  } else if (stop_coarse) {
    estimate.status = "unavailable";
    estimate.message = "the run did not complete";
  } else if (coarse_result.status == RunStatus::kCancelled ||
             coarse_result.status == RunStatus::kTimeLimit) {
    // Stopped from outside (a Cancel, a stop signal, the time limit) while it ended: no
    // judgement of the meshes.
    estimate.status = "unavailable";
    estimate.message = "the companion run on meshes with half the elements was stopped (" +
                       StatusName(coarse_result.status) + ") before it ended";
  } else if (coarse_result.status != RunStatus::kCompleted &&
             coarse_result.status != RunStatus::kNotConverged) {
    estimate.status = "unavailable";
    estimate.message = fmt::format(
        "the companion run on meshes with half the elements did not complete ({}: {}); the "
        "meshes are likely too coarse for this operating point",
        StatusName(coarse_result.status), coarse_result.message);
  } else {
    const auto slap = [&c](const RunResult& r) {
      return SlapInputs{&r.motion, c.geometry.piston_mass, c.geometry.piston_inertia};
    };
    estimate = EstimateErrors(result.samples, coarse_result.samples, companion, slap(result),
                              slap(coarse_result));
  }
  estimate.skirt_ratio = companion.skirt_ratio;
  estimate.big_end_ratio = companion.big_end_ratio;
  estimate.tolerance_factor = companion.tolerance_factor;
  estimate.coarse_wall_time = coarse_result.wall_time;
  estimate.coarse_steps = coarse_result.stats.steps;
  result.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}
}  // namespace

}  // namespace filmdyn::engine
