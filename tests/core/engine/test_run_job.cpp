// A whole ideal run as the CLI and the GUI worker make it: steady state, the reported cycle, the
// output folder (every fixed column of docs/outputs.md in order, empty where the model has none),
// monitor stop, cancel flag, the film models' run-in (progress, cancel, where the first cycle
// starts), and a lubricated model without film factories rejected naming the field.
#include <QtTest>
#include <numbers>

#include <QTemporaryDir>
#include <atomic>
#include <fstream>
#include <functional>
#include <limits>
#include <optional>
#include <sstream>

#include "core/base/input_error.hpp"
#include "core/engine/error_estimate.hpp"
#include "core/engine/film_joints.hpp"
#include "core/engine/run_job.hpp"
#include "core/engine/run_memory.hpp"
#include "core/io/case_fields_doc.hpp"
#include "core/io/case_file.hpp"
#include "core/io/field_output.hpp"
#include "core/io/field_series.hpp"
#include "core/io/results_writer.hpp"
#include "core/io/run_kpis.hpp"
#include "core/io/run_summary.hpp"
#include "core/io/run_warnings.hpp"
#include "core/lubrication/film_compliance.hpp"

using namespace filmdyn;

namespace {
engine::RunConfig DefaultConfig(double rpm, engine::Model model = engine::Model::kIdeal) {
  const io::LoadedCase loaded = io::LoadCase({});
  return engine::MakeRunConfig(loaded.value, model, rpm, io::PressureCurveForSpeed(loaded, rpm));
}
// Only-LBRBE at 3000 rpm on a coarse big-end mesh without the error estimate, with a Vogel oil
// (a 6.9e-5 Pa s, b 1050 K, c 165 K: 10.7 mPa s at 100 °C).
engine::RunConfig CoarseBigEndWithVogelOil() {
  engine::RunConfig config = DefaultConfig(3000, engine::Model::kOnlyLbrbe);
  engine::EngineCase& c = config.engine_case;
  c.big_end.mesh_theta = 48;
  c.big_end.mesh_z = 6;
  c.solver.error_estimate = 0;
  c.lubricant.model = lubrication::ViscosityModel::kVogel;
  c.lubricant.vogel_a = 6.9e-5;
  c.lubricant.vogel_b = 1050.0;
  c.lubricant.vogel_c = 165.0;
  return config;
}
// Only-LBRBE with a mass-conserving big end on the coarse test mesh (48 x 6), no error estimate.
engine::RunConfig CoarseJfoBigEnd(double rpm) {
  engine::RunConfig config = DefaultConfig(rpm, engine::Model::kOnlyLbrbe);
  engine::EngineCase& c = config.engine_case;
  c.big_end.cavitation = lubrication::CavitationModel::kJfo;
  c.big_end.mesh_theta = 48;
  c.big_end.mesh_z = 6;
  c.solver.error_estimate = 0;
  return config;
}
// The reported cycle's mean big-end friction power [W] and mean sampled side leakage [m³/s].
std::pair<double, double> MeanBigEndPowerAndLeakage(const engine::RunResult& result) {
  double power = 0.0, leakage = 0.0;
  for (const auto& s : result.samples) {
    power += s.bearing.fpl;
    leakage += s.bearing.side_flow;
  }
  const double n = double(result.samples.size());
  return {power / n, leakage / n};
}

// The coarse big end with the Vogel oil, its film temperature from its heat balance started at
// 100 °C, `change` applied; run, and checked to complete with a converged balance.
engine::RunResult HeatBalancedBigEnd(const std::function<void(engine::EngineCase&)>& change) {
  engine::RunConfig config = CoarseBigEndWithVogelOil();
  engine::EngineCase& c = config.engine_case;
  c.big_end.oil.temperature_mode = engine::FilmTemperature::kHeatBalance;
  c.big_end.oil.temperature = 373.15;  // the first guess
  change(c);
  engine::RunResult result = engine::RunJob(config);
  if (result.status != engine::RunStatus::kCompleted) qWarning("%s", result.message.c_str());
  return result;
}
}  // namespace

class TestRunJob : public QObject {
  Q_OBJECT
 private slots:
  // The check that ends a run at an output sample: a mass-conserving film fraction outside
  // [0, 1] by more than the tolerance names the joint and the excess; within it, nothing. Each
  // failure says which joint it is in (the cause hints are chosen by it), a non-finite state none.
  void filmFractionOutsideItsRangeIsTrouble() {
    engine::CrankTrainSample s;
    s.piston_lateral = s.crank_torque = 0.0;
    s.bearing.present = true;
    s.bearing.eps = 0.5;
    QVERIFY(!engine::FilmTrouble(s).failed());
    s.bearing.fraction_excess = 0.9 * coupling::kFractionTolerance;
    QVERIFY(!engine::FilmTrouble(s).failed());
    s.bearing.fraction_excess = 2e-3;
    engine::FilmFailure f = engine::FilmTrouble(s);
    QVERIFY2(
        QString::fromStdString(f.message).contains("big-end film fraction left [0, 1] by 0.002"),
        f.message.c_str());
    QCOMPARE(f.joint, std::string("big_end"));
    s.bearing.fraction_excess = 0.0;
    s.skirt.present = true;
    s.skirt.min_gap = 5e-6;
    s.skirt.fraction_excess = 0.5;
    f = engine::FilmTrouble(s);
    const QString skirt = QString::fromStdString(f.message);
    QVERIFY2(skirt.contains("skirt film fraction left [0, 1] by 0.5"), qPrintable(skirt));
    QVERIFY2(skirt.contains("refine the film mesh"), qPrintable(skirt));
    QCOMPARE(f.joint, std::string("skirt"));
    s.skirt.fraction_excess = 0.0;
    s.skirt.capped_nodes = 3;
    QCOMPARE(engine::FilmTrouble(s).joint, std::string("skirt"));
    s.skirt.capped_nodes = 0;
    s.skirt.min_gap = -0.649e-6;  // on the liner: at the anti-thrust side's bottom edge, tilted
    s.skirt.moft_alpha = std::numbers::pi;
    s.skirt.moft_y = 0.09;
    s.piston_tilt = -2.66e-3;
    f = engine::FilmTrouble(s);
    QVERIFY2(f.message.starts_with("piston skirt touches the liner (smallest gap -0.649 µm) at "
                                   "180° from the thrust axis, 90.0 mm below the skirt top"),
             f.message.c_str());
    QVERIFY2(f.message.find("tilted -2.66 mrad") != std::string::npos, f.message.c_str());
    QVERIFY2(f.message.find("geometry.skirt_top_to_pin") != std::string::npos, f.message.c_str());
    QCOMPARE(f.joint, std::string("skirt"));
    s.skirt.min_gap = 5e-6;
    s.bearing.eps = std::numeric_limits<double>::quiet_NaN();
    QCOMPARE(engine::FilmTrouble(s).joint, std::string("big_end"));
    s.bearing.eps = 0.5;
    s.bearing.capped_nodes = 1;
    QCOMPARE(engine::FilmTrouble(s).joint, std::string("big_end"));
    s.bearing.capped_nodes = 0;
    s.crank_torque = std::numeric_limits<double>::infinity();
    f = engine::FilmTrouble(s);
    QVERIFY(f.failed());
    QCOMPARE(f.joint, std::string());
  }
  void idealRunReachesSteadyStateAndWritesFolder() {
    const engine::RunConfig config = DefaultConfig(6000);
    int calls = 0;
    const engine::RunResult result =
        engine::RunJob(config, [&](const engine::RunProgress&) { return ++calls > 0; });
    QCOMPARE(engine::StatusName(result.status), std::string("completed"));
    QCOMPARE(result.cycles_to_steady_state, 2);
    QCOMPARE(result.samples.size(), std::size_t(720));
    QCOMPARE(calls, 1440);
    qInfo("6000 rpm ideal: %.3f s wall, %ld steps, %ld rejected, %ld Newton, %ld f evals",
          result.wall_time, result.stats.steps, result.stats.rejected_steps,
          result.stats.newton_iterations, result.stats.rhs_evaluations);

    QTemporaryDir dir;
    const auto rows = io::WriteRunFolder(dir.path().toStdString(), "default", config, result);
    std::ifstream csv(dir.path().toStdString() + "/results.csv");
    std::string header, first;
    std::getline(csv, header);
    std::getline(csv, first);
    const std::string spec =
        "crank_angle[deg],time[s],piston_lateral[m],piston_tilt[rad],"
        "piston_lateral_velocity[m/s],piston_tilt_rate[rad/s],skirt_normal_force[N],"
        "skirt_friction_force[N],skirt_moment[N*m],skirt_moft[m],skirt_fpl[W],"
        "journal_ecc_x[m],journal_ecc_y[m],bearing_eps[-],bearing_moft[m],bearing_fpl[W],"
        "bigend_force_x[N],bigend_force_y[N],gas_force[N]";
    QVERIFY(header.rfind(spec, 0) == 0);  // the 19 fixed columns first, in their order
    // MOFT columns present and empty: fields 10 and 15 (1-based).
    std::vector<std::string> cells;
    std::stringstream line(first);
    for (std::string cell; std::getline(line, cell, ',');) cells.push_back(cell);
    QVERIFY(cells.at(9).empty());
    QVERIFY(cells.at(14).empty());
    QVERIFY(!cells.at(6).empty());
    QCOMPARE(cells.at(0), std::string("0"));
    QCOMPARE(rows.back().crank_angle_deg.value(), 719.0);
    std::ifstream summary_file(dir.path().toStdString() + "/summary.json");
    const auto summary = nlohmann::json::parse(summary_file);
    QCOMPARE(summary["cycles_to_steady_state"].get<int>(), 2);
    QVERIFY(summary["solver"]["steps"].get<long>() > 0);
    QVERIFY(summary["extremes"].contains("bigend_force_y[N]"));
    // The quantity the cycle-to-cycle change is of names a results.csv column.
    const std::string worst = summary["cycle_to_cycle_worst_quantity"].get<std::string>();
    QVERIFY2(header.find(worst) != std::string::npos, worst.c_str());
  }
  // A starved skirt on a liner film far too thin to carry it (0.1 µm) fails; the message says
  // it runs starved and names the liner's film, not only the clearance or the mesh.
  void aStarvedSkirtsFailureNamesTheLinersOilFilm() {
    engine::RunConfig config = DefaultConfig(6000, engine::Model::kOnlySkirt);
    engine::EngineCase& c = config.engine_case;
    c.skirt.cavitation = lubrication::CavitationModel::kJfo;
    c.skirt.supply = lubrication::SkirtSupply::kStarved;
    c.skirt.oil_film = 1e-7;
    c.skirt.mesh_thrust = c.skirt.mesh_anti = 6;
    c.skirt.mesh_relief = 1;
    c.skirt.mesh_axial = 8;
    const engine::RunResult result = engine::RunJob(config);
    QCOMPARE(engine::StatusName(result.status), std::string("failed"));
    QVERIFY2(result.message.find("skirt.oil_film = 0.1 um") != std::string::npos &&
                 result.message.find("starved") != std::string::npos,
             result.message.c_str());
  }
  void monitorCanStop() {
    const engine::RunConfig config = DefaultConfig(2000);
    int calls = 0;
    const auto result = engine::RunJob(
        config, [&](const engine::RunProgress& p) { return ++calls < 100 && p.cycle == 1; });
    QCOMPARE(engine::StatusName(result.status), std::string("cancelled"));
    QCOMPARE(calls, 100);
    QVERIFY(!result.samples.empty());
    // Stopped in its first cycle: no cycle compared, no change to report (null, not a 0 that
    // would read as perfectly periodic).
    QTemporaryDir dir;
    io::WriteRunFolder(dir.path().toStdString(), "default", config, result);
    std::ifstream summary_file(dir.path().toStdString() + "/summary.json");
    const auto summary = nlohmann::json::parse(summary_file);
    QVERIFY(summary["cycle_to_cycle_change"].is_null());
    QVERIFY(summary["cycle_to_cycle_worst_quantity"].is_null());
    QVERIFY(summary["cycle_to_cycle_changes"].empty());
  }
  void cancelFlagStops() {
    const engine::RunConfig config = DefaultConfig(4000);
    std::atomic<bool> cancel{false};
    int calls = 0;
    const auto result = engine::RunJob(
        config,
        [&](const engine::RunProgress&) {
          if (++calls == 10) cancel = true;
          return true;
        },
        &cancel);
    QCOMPARE(engine::StatusName(result.status), std::string("cancelled"));
    QCOMPARE(calls, 10);
  }
  void filmJointsSideBySideMatchOneThread() {
    // Skirt-LBRBE on coarse meshes: the two film joints (and the skirt's two panels) on two
    // threads, beside the error estimate's companion thread, give the samples of one thread bit
    // for bit (the ThreadSanitizer build runs this on plain threads and reports any race).
    engine::RunConfig config = DefaultConfig(6000, engine::Model::kSkirtLbrbe);
    config.engine_case.skirt.mesh_thrust = config.engine_case.skirt.mesh_anti = 6;
    config.engine_case.skirt.mesh_relief = 1;
    config.engine_case.skirt.mesh_axial = 6;
    config.engine_case.big_end.mesh_theta = 24;
    config.engine_case.big_end.mesh_z = 6;
    QCOMPARE(config.engine_case.solver.error_estimate, 1);
    auto run = [&config](int threads) {
      config.threads = threads;
      int steps = 0;
      return engine::RunJob(config, [&steps](const engine::RunProgress&) { return ++steps < 30; });
    };
    const engine::RunResult one = run(1), two = run(2);
    QCOMPARE(engine::StatusName(two.status), std::string("cancelled"));
    QCOMPARE(two.samples.size(), std::size_t(30));
    QCOMPARE(one.samples.size(), two.samples.size());
    for (std::size_t k = 0; k < one.samples.size(); ++k) {
      const engine::CrankTrainSample &a = one.samples[k], &b = two.samples[k];
      QCOMPARE(a.time, b.time);
      QCOMPARE(a.piston_lateral, b.piston_lateral);
      QCOMPARE(a.piston_tilt, b.piston_tilt);
      QCOMPARE(a.bearing.eps, b.bearing.eps);
      QCOMPARE(a.skirt.min_gap, b.skirt.min_gap);
    }
  }

  void filmModelsRunInBeforeTheFirstCycle() {
    // Only-LBRBE on a coarse bearing mesh: the run-in (default 360 °CA) reports progress with
    // negative crank angles rising towards the first cycle, and a cancel inside it ends the run
    // with the run-in named and its samples kept.
    engine::RunConfig config = DefaultConfig(6000, engine::Model::kOnlyLbrbe);
    config.engine_case.big_end.mesh_theta = 24;
    config.engine_case.big_end.mesh_z = 6;
    QCOMPARE(config.engine_case.solver.run_in_angle, 2.0 * M_PI);
    std::vector<double> angles;
    bool all_run_in = true;
    const auto result = engine::RunJob(config, [&](const engine::RunProgress& p) {
      all_run_in = all_run_in && p.run_in && p.cycle == 0 && p.sample;
      angles.push_back(p.crank_angle_deg);
      return angles.size() < 90;  // 90 of the 359 run-in samples at 1 °CA
    });
    QVERIFY(all_run_in);
    QCOMPARE(engine::StatusName(result.status), std::string("cancelled"));
    QCOMPARE(angles.size(), std::size_t(90));
    QVERIFY(std::abs(angles.front() + 359.0) < 1e-9);
    QVERIFY(std::abs(angles.back() + 270.0) < 1e-9);
    QVERIFY2(result.message.find("run-in, at 450.0 °CA, 270.0 °CA before the first cycle") !=
                 std::string::npos,
             result.message.c_str());
    QCOMPARE(result.samples.size(), std::size_t(90));
    QVERIFY(result.samples.back().bearing.present && result.samples.back().bearing.eps > 0.0);

    // The first cycle starts where the run-in ends: its first sample is the case's start angle.
    config.engine_case.solver.run_in_angle = M_PI / 18.0;  // 10 °CA: the cycle comes quickly
    std::optional<engine::RunProgress> first;
    engine::CrankTrainSample first_sample;
    engine::RunJob(config, [&](const engine::RunProgress& p) {
      if (p.run_in) return true;
      first = p;
      first_sample = *p.sample;
      return false;
    });
    QVERIFY(first.has_value());
    QCOMPARE(first->cycle, 1);
    QCOMPARE(first->crank_angle_deg, 0.0);
    const double t_start = (M_PI / 18.0) / (6000.0 * M_PI / 30.0);
    QVERIFY(std::abs(first->cycle_start_time - t_start) < 1e-15);
    QVERIFY(std::abs(first_sample.time - t_start) < 1e-15);
    QVERIFY(std::abs(first_sample.crank_angle - config.engine_case.operating.start_crank_angle) <
            1e-9);
  }
  // A run stopped before its first cycle ended reports the part it computed: no oil "per cycle"
  // (nor mean friction power, FMEP) over that part, only the account's balance — whether the part
  // is shorter than a cycle or longer (a run-in of more than 720 °CA). A run stopped in its second
  // cycle reports its first, a whole cycle, with both, and its film fields.
  void stoppedRunInReportsNoOilPerCycle() {
    engine::RunConfig config = DefaultConfig(6000, engine::Model::kOnlyLbrbe);
    config.engine_case.big_end.mesh_theta = 24;
    config.engine_case.big_end.mesh_z = 6;
    config.engine_case.big_end.cavitation = lubrication::CavitationModel::kJfo;
    config.engine_case.solver.jfo_run_in_angle = 5 * M_PI;  // 900 °CA, sampled every 1 °CA
    const auto stopped_after = [&config](int count) {
      int samples = 0;
      return engine::RunJob(
          config, [&](const engine::RunProgress& p) { return !p.sample || ++samples < count; });
    };
    for (const int count : {90, 800}) {  // 90 and 800 °CA into the run-in
      const engine::RunResult stopped = stopped_after(count);
      QCOMPARE(engine::StatusName(stopped.status), std::string("cancelled"));
      QCOMPARE(stopped.samples.size(), std::size_t(count));
      QCOMPARE(stopped.reported_cycle, 0);  // the run-in's part
      QVERIFY(!engine::SamplesSpanACycle(stopped.samples));
      // Its rows' time[s] counts from the run's start (the start state, at 720 - 900 = -180 °CA,
      // has no row), so that each row's time and crank angle tell the same interval: the first
      // row at 541 °CA is one output interval in (it was at time 0 before).
      QCOMPARE(engine::ReportedTimeOrigin(stopped), 0.0);
      const double omega = 6000.0 * M_PI / 30.0, degree = (M_PI / 180.0) / omega;
      for (std::size_t k = 0; k < stopped.samples.size(); ++k) {
        const io::OutputRow row = io::RowFromSample(stopped.samples[k], config.model,
                                                    engine::ReportedTimeOrigin(stopped));
        QVERIFY2(std::abs(*row.time - (k + 1.0) * degree) < 1e-12 * degree * (k + 1.0),
                 std::to_string(k).c_str());
        const double angle = std::fmod(540.0 + (k + 1.0), 720.0);
        QVERIFY2(std::abs(*row.crank_angle_deg - angle) < 1e-9, std::to_string(k).c_str());
      }
      const io::RunKpis part = io::RunKpisOf(config, stopped);
      QVERIFY(part.big_end.has_value());
      QVERIFY2(!part.big_end->oil_in_per_cycle && !part.big_end->oil_out_per_cycle,
               std::to_string(count).c_str());
      QVERIFY(part.big_end->oil_balance && std::abs(*part.big_end->oil_balance) < 1e-9);
      for (const engine::HeadlineFigure& f : engine::HeadlineFigures(stopped.samples)) {
        QVERIFY2(f.key != "bearing_oil_per_cycle[m^3]", "a headline oil per cycle of a run-in");
        // Nor a cycle's mean (friction power) over the part, nor its FMEP.
        QVERIFY2(f.key != "bearing_fpl_mean[W]", "a headline mean FPL of a run-in");
      }
      QVERIFY(!part.big_end->mean_fpl && !part.big_end->fmep);
    }

    // Two recorders of the same run: one as runs attach it (keeping the previous cycle, which
    // this small mesh's memory allows), one keeping the newest cycle only.
    io::FieldRecorder recorder, newest_only;
    // Where two cycles of fields do not fit but one does, the newest only.
    const double one = engine::EstimateRunMemory(config.engine_case, 1.0).total(),
                 two = engine::EstimateRunMemory(config.engine_case, 2.0).total();
    QVERIFY(two > one);
    QVERIFY(!recorder.Attach(&config, 0.5 * (one + two)));
    QCOMPARE(config.field_copies, 1.0);
    QVERIFY(recorder.Attach(&config, two));
    QCOMPARE(config.field_copies, 2.0);
    QVERIFY(recorder.Attach(&config));  // this machine holds two cycles of this small mesh
    config.field_callback = [both = config.field_callback,
                             newest = newest_only.Callback()](const engine::FieldFrame& f) {
      both(f);
      newest(f);
    };
    const engine::RunResult second = stopped_after(900 + 720 + 10);  // 10 °CA into cycle 2
    // The newest frames are those of cycle 2, the one it stopped in: not the reported cycle's.
    QCOMPARE(newest_only.bearing_frames(), std::size_t(11));
    QCOMPARE(recorder.bearing_frames(), std::size_t(11));
    QVERIFY(!newest_only.Holds(second.samples));
    // The attached recorder also kept cycle 1's, the reported cycle: its fields/ are written,
    // one frame per reported output step at the crank angle results.csv gives it.
    QVERIFY(recorder.Holds(second.samples));
    QTemporaryDir dir;
    QVERIFY(!newest_only.WriteReported(dir.path().toStdString(), second.samples));
    QVERIFY(recorder.WriteReported(dir.path().toStdString(), second.samples));
    const io::FieldSeries series =
        io::ReadFieldSeries(std::filesystem::path(dir.path().toStdString()) / "bearing.xdmf");
    QCOMPARE(series.frames.size(), second.samples.size());
    for (std::size_t k = 0; k < series.frames.size(); ++k) {
      QVERIFY(std::abs(series.frames[k].crank_angle_deg -
                       engine::CycleCrankAngleDeg(second.samples[k].crank_angle)) < 1e-6);
    }
    QCOMPARE(engine::StatusName(second.status), std::string("cancelled"));
    QCOMPARE(second.samples.size(), std::size_t(720));  // cycle 1, whole
    QCOMPARE(second.cycles, 2);
    QCOMPARE(second.reported_cycle, 1);
    QVERIFY(engine::SamplesSpanACycle(second.samples));
    // A reported cycle's time[s] counts from its own start, its first row at 0 °CA.
    QCOMPARE(engine::ReportedTimeOrigin(second), second.samples.front().time);
    QCOMPARE(
        io::RowFromSample(second.samples.front(), config.model, engine::ReportedTimeOrigin(second))
            .time.value(),
        0.0);
    const io::RunKpis cycle = io::RunKpisOf(config, second);
    QVERIFY(cycle.big_end && cycle.big_end->oil_in_per_cycle &&
            *cycle.big_end->oil_in_per_cycle > 0.0);
    QVERIFY(cycle.big_end->oil_balance && std::abs(*cycle.big_end->oil_balance) < 1e-9);
    QVERIFY(cycle.big_end->mean_fpl && *cycle.big_end->mean_fpl > 0.0 && cycle.big_end->fmep);
  }

  // A run whose film fails keeps the film where it failed: in a cycle the failing step's frame
  // ends the cycle's fields (it had none: the fields ended a step before results.csv); in the
  // run-in, whose fields are not recorded, that one frame is the fields/ the run writes.
  void aFailedRunKeepsTheFilmWhereItFailed() {
    struct Seen {
      int cycle, step;
      double time;
      bool failure;
    };
    const auto run = [](double viscosity, double run_in, std::vector<Seen>* seen,
                        io::FieldRecorder* recorder) {
      engine::RunConfig config = DefaultConfig(6000, engine::Model::kOnlyLbrbe);
      config.engine_case.big_end.mesh_theta = 24;
      config.engine_case.big_end.mesh_z = 4;
      config.engine_case.big_end.cavitation = lubrication::CavitationModel::kJfo;
      config.engine_case.lubricant.viscosity = viscosity;  // too thin: the journal touches
      config.engine_case.solver.jfo_run_in_angle = run_in;
      recorder->Attach(&config);
      config.field_callback = [seen, record = config.field_callback](const engine::FieldFrame& f) {
        seen->push_back({f.cycle, f.step, f.time, f.failure});
        record(f);
      };
      return engine::RunJob(config);
    };
    for (const double run_in : {4 * M_PI, 0.0}) {  // 720 °CA run-in, none
      std::vector<Seen> seen;
      io::FieldRecorder recorder;
      const engine::RunResult r = run(0.6e-3, run_in, &seen, &recorder);
      QCOMPARE(engine::StatusName(r.status), std::string("failed"));
      QVERIFY2(r.message.find("journal touches the bearing") != std::string::npos,
               r.message.c_str());
      QVERIFY(!r.samples.empty() && !seen.empty());
      {  // the row where it failed
        const coupling::BearingFilmSample& last = r.samples.back().bearing;
        const double c = engine::BigEndFit(DefaultConfig(6000).engine_case).hot_clearance;
        qInfo("failed at eps %.6f (eps_max %.6f): moft %.4g um, c (1 - eps) %.4g um", last.eps,
              last.eps_max, last.moft * 1e6, c * (1.0 - last.eps) * 1e6);
        // Its film is the journal's own, not the one solved at eps_max (1 % thicker here).
        QVERIFY(last.eps >= last.eps_max);
        QVERIFY(std::abs(last.moft - c * (1.0 - last.eps)) < 1e-3 * c * (1.0 - last.eps_max));
      }
      // The last frame is the failure's, at the last sample's time; the only one flagged.
      QVERIFY(seen.back().failure);
      QCOMPARE(seen.back().time, r.samples.back().time);
      QCOMPARE(std::count_if(seen.begin(), seen.end(), [](const Seen& s) { return s.failure; }),
               std::ptrdiff_t(1));
      if (run_in > 0.0) {
        QVERIFY2(r.message.find("run-in") != std::string::npos, r.message.c_str());
        QCOMPARE(r.reported_cycle, 0);
        QCOMPARE(seen.size(), std::size_t(1));
        QCOMPARE(seen.back().cycle, 0);
      } else {
        QCOMPARE(r.reported_cycle, 1);
        // One frame per reported output step, the failing one included.
        QCOMPARE(seen.size(), r.samples.size());
      }
      // fields/ as results.csv: the same steps at the same crank angles.
      QVERIFY(recorder.Holds(r.samples));
      QTemporaryDir dir;
      QVERIFY(recorder.WriteReported(dir.path().toStdString(), r.samples));
      const io::FieldSeries series =
          io::ReadFieldSeries(std::filesystem::path(dir.path().toStdString()) / "bearing.xdmf");
      QCOMPARE(series.frames.size(), run_in > 0.0 ? std::size_t(1) : r.samples.size());
      QVERIFY(std::abs(series.frames.back().crank_angle_deg -
                       engine::CycleCrankAngleDeg(r.samples.back().crank_angle)) < 1e-6);
    }
  }

  // A cycle that starts elsewhere than 0 °CA (operating.start_crank_angle = 90 °CA): its film
  // fields and its messages name each output step's crank angle as results.csv labels it, and
  // the fields are written in crank-angle order from 0 °CA (the time a reader keys them by).
  void aCycleStartingAt90DegreesIsLabelledAsItsResults() {
    engine::RunConfig config = DefaultConfig(3000, engine::Model::kOnlyLbrbe);
    config.engine_case.big_end.mesh_theta = 24;
    config.engine_case.big_end.mesh_z = 4;
    config.engine_case.solver.max_cycles = 1;
    config.engine_case.operating.start_crank_angle = M_PI / 2;
    io::FieldRecorder recorder;
    std::vector<double> frame_angles, sample_angles;
    config.field_callback = [&, record = recorder.Callback()](const engine::FieldFrame& f) {
      frame_angles.push_back(f.crank_angle_deg);
      sample_angles.push_back(engine::CycleCrankAngleDeg(f.sample->crank_angle));
      record(f);
    };
    const engine::RunResult run = engine::RunJob(config);
    QCOMPARE(run.samples.size(), std::size_t(720));
    QCOMPARE(run.reported_cycle, 1);
    QCOMPARE(frame_angles, sample_angles);
    QCOMPARE(frame_angles.front(), 90.0);
    QCOMPARE(frame_angles.back(), 89.0);
    QVERIFY(recorder.Holds(run.samples));
    QTemporaryDir dir;
    recorder.Write(dir.path().toStdString());
    const io::FieldSeries series =
        io::ReadFieldSeries(std::filesystem::path(dir.path().toStdString()) / "bearing.xdmf");
    QCOMPARE(series.frames.size(), std::size_t(720));
    for (std::size_t k = 0; k < series.frames.size(); ++k)
      QCOMPARE(series.frames[k].crank_angle_deg, double(k));

    // A stop names where it stopped as results.csv labels it: 100 output steps into the cycle.
    config.field_callback = nullptr;
    int samples = 0;
    const engine::RunResult stopped = engine::RunJob(config, [&](const engine::RunProgress& p) {
      return p.run_in || !p.sample || ++samples < 101;
    });
    QCOMPARE(engine::CycleCrankAngleDeg(stopped.samples.back().crank_angle), 190.0);
    QVERIFY2(stopped.message == "cancelled (cycle 1, 190.0 °CA)", stopped.message.c_str());
    // In the run-in, the crank angle and how far the first cycle still is.
    samples = 0;
    const engine::RunResult run_in = engine::RunJob(
        config, [&](const engine::RunProgress& p) { return !p.sample || ++samples < 101; });
    QCOMPARE(engine::CycleCrankAngleDeg(run_in.samples.back().crank_angle),
             90.0 - 360.0 + 101.0 + 720.0);
    QVERIFY2(run_in.message == "cancelled (run-in, at 551.0 °CA, 259.0 °CA before the first cycle)",
             run_in.message.c_str());
  }

  void motionBetweenOutputStepsIsTheIntegratorsOwnSolution() {
    // Skirt-LBRBE at 6000 rpm on coarse meshes, one cycle after a 90 °CA run-in. The motion
    // samples between the output steps (1/8 °CA) come from CVODE's interpolation inside the
    // steps it takes anyway: (a) they change no sample, no step and no film solve of the run;
    // (b) they are the solution a run with 1/8 °CA output steps computes at the same instants;
    // (c) the exact ε̇ and γ̇ they carry agree with the slopes of ε and γ along them.
    engine::RunConfig config = DefaultConfig(6000, engine::Model::kSkirtLbrbe);
    auto& c = config.engine_case;
    c.skirt.mesh_thrust = c.skirt.mesh_anti = 6;
    c.skirt.mesh_relief = 1;
    c.skirt.mesh_axial = 6;
    c.big_end.mesh_theta = 24;
    c.big_end.mesh_z = 6;
    c.solver.error_estimate = 0;
    c.solver.max_cycles = 1;
    c.solver.run_in_angle = M_PI / 2;
    const engine::RunResult with = engine::RunJob(config);
    config.motion_interval = 0.0;
    const engine::RunResult without = engine::RunJob(config);
    QCOMPARE(engine::StatusName(with.status), engine::StatusName(without.status));
    QCOMPARE(with.samples.size(), std::size_t(720));
    QCOMPARE(without.samples.size(), with.samples.size());
    for (std::size_t k = 0; k < with.samples.size(); ++k) {  // (a) bit for bit
      const engine::CrankTrainSample &a = with.samples[k], &b = without.samples[k];
      QCOMPARE(a.time, b.time);
      QCOMPARE(a.piston_lateral, b.piston_lateral);
      QCOMPARE(a.piston_tilt_rate, b.piston_tilt_rate);
      QCOMPARE(a.bearing.eps, b.bearing.eps);
      QCOMPARE(a.bearing.moft, b.bearing.moft);
      QCOMPARE(a.skirt.moft, b.skirt.moft);
    }
    QCOMPARE(with.stats.steps, without.stats.steps);
    QCOMPARE(with.stats.rhs_evaluations, without.stats.rhs_evaluations);
    QCOMPARE(with.reynolds_solves, without.reynolds_solves);
    // 8 parts per 1 °CA output step; each output step's motion is its sample's.
    QCOMPARE(without.motion.size(), with.samples.size());
    QCOMPARE(with.motion.size(), 8 * (with.samples.size() - 1) + 1);
    for (std::size_t k = 0; k < with.samples.size(); ++k) {
      const engine::MotionSample& m = with.motion[8 * k];
      QCOMPARE(m.time, with.samples[k].time);
      QCOMPARE(m.eps, with.samples[k].bearing.eps);
      QCOMPARE(m.piston_tilt, with.samples[k].piston_tilt);
      QVERIFY(m.piston_present && m.journal_present);
    }

    // (b) The same run with output steps of 1/8 °CA: its samples at the motion's instants.
    config.engine_case.solver.output_interval = M_PI / 180.0 / 8.0;
    const engine::RunResult fine = engine::RunJob(config);
    QCOMPARE(fine.samples.size(), std::size_t(8 * 720));
    // The two runs are not the same computation bit for bit (each output step's film solve warm-
    // starts the next one, so the steps differ within the error control): the motion must differ
    // from the fine run between the output steps no more than the output samples themselves do
    // at them — the interpolation adds nothing to the integration error.
    double eps_at = 0.0, eps_between = 0.0, tilt_at = 0.0, tilt_between = 0.0;
    for (std::size_t k = 0; k < with.motion.size(); ++k) {
      const engine::MotionSample& m = with.motion[k];
      const engine::MotionSample f = engine::MotionOf(fine.samples[k]);
      QVERIFY(std::abs(m.time - f.time) < 1e-12);
      const bool at_output = k % 8 == 0;
      double& eps = at_output ? eps_at : eps_between;
      double& tilt = at_output ? tilt_at : tilt_between;
      eps = std::max(eps, std::abs(m.eps - f.eps));
      tilt = std::max(tilt, std::abs(m.piston_tilt - f.piston_tilt));
    }
    qInfo(
        "against 1/8 °CA output steps: |Δε| %.2e at the output steps, %.2e between them; |Δγ| "
        "%.2e / %.2e rad; %ld vs %ld integrator steps",
        eps_at, eps_between, tilt_at, tilt_between, with.stats.steps, fine.stats.steps);
    QVERIFY2(eps_between <= 1.5 * eps_at, qPrintable(QString::number(eps_between)));
    QVERIFY2(tilt_between <= 1.5 * tilt_at, qPrintable(QString::number(tilt_between)));

    // (c) Exact rates against central differences of the positions along the motion (second
    // order: measured 0.09 % of the largest dε/dt here, 4x that at twice the spacing). Not where
    // the journal passes near the bearing centre: ε = |e| has a kink there, which the exact
    // rate follows and a difference quotient cannot (it is off by ~2 % of the largest rate at
    // ε ≈ 0.1 near firing).
    double eps_rate_error = 0.0, eps_rate_max = 0.0, tilt_rate_error = 0.0, tilt_rate_max = 0.0;
    for (std::size_t k = 1; k + 1 < with.motion.size(); ++k) {
      const engine::MotionSample &p = with.motion[k - 1], &m = with.motion[k],
                                 &n = with.motion[k + 1];
      const double dt = n.time - p.time;
      if (m.eps > 0.3)
        eps_rate_error = std::max(eps_rate_error, std::abs((n.eps - p.eps) / dt - m.eps_dot));
      tilt_rate_error = std::max(
          tilt_rate_error, std::abs((n.piston_tilt - p.piston_tilt) / dt - m.piston_tilt_rate));
      eps_rate_max = std::max(eps_rate_max, std::abs(m.eps_dot));
      tilt_rate_max = std::max(tilt_rate_max, std::abs(m.piston_tilt_rate));
    }
    qInfo("exact vs central-difference rates: dε/dt %.2e of %.3e 1/s, dγ/dt %.2e of %.3e rad/s",
          eps_rate_error, eps_rate_max, tilt_rate_error, tilt_rate_max);
    QVERIFY2(eps_rate_error < 0.005 * eps_rate_max, qPrintable(QString::number(eps_rate_error)));
    QVERIFY2(tilt_rate_error < 0.005 * tilt_rate_max, qPrintable(QString::number(tilt_rate_error)));
  }
  void lubricatedWithoutFilmModelIsAnInputError() {
    engine::RunConfig config = DefaultConfig(6000, engine::Model::kOnlySkirt);
    QVERIFY(config.factories.skirt && config.factories.big_end);  // MakeRunConfig provides them
    config.factories = {};                                        // a build without film models
    try {
      engine::RunJob(config);
      QFAIL("no error");
    } catch (const InputError& e) {
      QCOMPARE(e.field(), std::string("skirt.model"));
    }
    QVERIFY_THROWS_EXCEPTION(InputError, engine::ParseModel("wet"));
  }

  // The heat balance by hand, then a big end whose film temperature comes from it: the run is
  // repeated until T = T_supply + share · P / (ρ c_p Q) holds for the reported cycle's own mean
  // friction power P and side leakage Q (checked here from the samples), within 0.25 K.
  void heatBalanceReachesItsFixedPoint() {
    QCOMPARE(
        engine::HeatBalanceTemperature(363.15, 0.5, 860.0 * 2000.0 * 1e-6, 860.0, 2000.0, 1e-6),
        363.65);
    QCOMPARE(engine::HeatBalanceTemperature(363.15, 1.0, 100.0, 860.0, 2000.0, 0.0), 363.15);
    const engine::RunResult result = HeatBalancedBigEnd([](engine::EngineCase&) {});
    QVERIFY2(result.status == engine::RunStatus::kCompleted, result.message.c_str());
    QVERIFY(result.heat_balance && result.heat_balance->converged);
    QVERIFY(result.big_end_film_temperature && !result.skirt_film_temperature);
    const double t = *result.big_end_film_temperature;
    const auto [power, leakage] = MeanBigEndPowerAndLeakage(result);
    const double balance = 363.15 + power / (860.0 * 2000.0 * leakage);
    qInfo("heat balance: %d runs, T %.3f K, balance %.3f K, P %.1f W, Q %.3g m3/s",
          result.heat_balance->runs, t, balance, power, leakage);
    QVERIFY(std::abs(balance - t) <= 0.25);
    QVERIFY(t > 363.15 + 1.0);
    QVERIFY(result.heat_balance->runs >= 2 && result.heat_balance->runs <= 10);
  }

  // A balance that asks for a temperature the oil has no viscosity at (here a catalogue oil,
  // 0–200 °C, and an oil that carries almost no heat: c_p = 1 J/(kg·K)) ends the iteration with
  // the run it has, not computed: not converged, its results kept and its film temperature the
  // one it ran at, the message naming the joint and the temperature asked for. (It used to throw
  // an input error naming a temperature nobody gave, the computed run dropped.) A time limit
  // holds for all the runs of a balance together (it held for each).
  void aHeatBalanceOutsideTheOilsRangeEndsWithItsLastRun() {
    const engine::RunResult result = HeatBalancedBigEnd([](engine::EngineCase& c) {
      c.lubricant.model = lubrication::ViscosityModel::kGrade;
      c.lubricant.heat_capacity = 1.0;
    });
    QCOMPARE(int(result.status), int(engine::RunStatus::kNotConverged));
    qInfo("%s", result.message.c_str());
    QVERIFY(result.message.find("heat balance stopped: the big-end film") != std::string::npos);
    QVERIFY(result.message.find("big_end.oil.heat_share") != std::string::npos);
    QVERIFY(!result.samples.empty() && result.cycles >= 1);
    QVERIFY(result.heat_balance && !result.heat_balance->converged);
    QCOMPARE(result.heat_balance->runs, 1);
    QCOMPARE(*result.big_end_film_temperature, 373.15);

    // The time limit of all the runs together: the first run takes longer than this limit
    // allows the whole, so no second run starts (each run used to have the limit to itself).
    engine::RunConfig config = CoarseBigEndWithVogelOil();
    engine::EngineCase& c = config.engine_case;
    c.big_end.oil.temperature_mode = engine::FilmTemperature::kHeatBalance;
    c.big_end.oil.temperature = 373.15;
    const engine::RunResult untimed = engine::RunJob(config);
    QVERIFY(untimed.heat_balance && untimed.heat_balance->runs >= 2);
    config.wall_time_limit = 0.6 * untimed.wall_time;  // under the runs' time together
    const engine::RunResult timed = engine::RunJob(config);
    qInfo("untimed: %d runs in %.2f s; limit %.2f s: %d runs in %.2f s, %s",
          untimed.heat_balance->runs, untimed.wall_time, config.wall_time_limit,
          timed.heat_balance->runs, timed.wall_time, timed.message.c_str());
    QCOMPARE(int(timed.status), int(engine::RunStatus::kTimeLimit));
    QVERIFY(timed.message.find("heat-balance run") != std::string::npos);
  }

  // The film fields of a heat-balanced run are the reported pass's only: each pass runs the
  // whole run again, its cycles counted from 1 again (FieldFrame::pass), and with one cycle per
  // pass the frames of every pass used to be appended into one series, whose crank angles then
  // went back (the fields' writer refused it: the run ended "failed").
  void heatBalancedFieldsAreTheReportedPassOnly() {
    engine::RunConfig config = CoarseBigEndWithVogelOil();
    engine::EngineCase& c = config.engine_case;
    c.big_end.oil.temperature_mode = engine::FilmTemperature::kHeatBalance;
    c.big_end.oil.temperature = 373.15;
    c.solver.max_cycles = 1;
    io::FieldRecorder recorder;
    recorder.Attach(&config);
    const engine::RunResult result = engine::RunJob(config);
    QVERIFY2(result.heat_balance && result.heat_balance->runs >= 2, result.message.c_str());
    QVERIFY(!result.samples.empty());
    QTemporaryDir dir;
    QVERIFY(recorder.WriteReported(dir.path().toStdString(), result.samples));
    // One frame per output sample of the reported cycle.
    QCOMPARE(recorder.bearing_frames(), result.samples.size());
  }

  // Every run that reports a cycle after another says how far its last cycles' headline figures
  // disagree (summary.json cycle_scatter), not only one that finds no periodic state: the
  // periodic-state test judges each quantity against its range over the cycle, which hides a
  // minimum film's scatter. The coarse big end, periodic after its cycles: each figure's range
  // over them holds the reported value.
  void periodicRunReportsItsCycleScatter() {
    engine::RunConfig config = CoarseBigEndWithVogelOil();
    config.engine_case.lubricant.model = lubrication::ViscosityModel::kConstant;
    const engine::RunResult result = engine::RunJob(config);
    QVERIFY2(result.status == engine::RunStatus::kCompleted, result.message.c_str());
    QVERIFY(result.cycles >= 2);
    QTemporaryDir dir;
    io::WriteRunFolder(dir.path().toStdString(), "coarse", config, result);
    const io::RunSummary s = io::ReadSummaryJson(dir.filePath("summary.json").toStdString());
    QVERIFY(s.cycle_scatter.has_value());
    QCOMPARE(s.cycle_scatter->last_cycle, result.cycles);
    QCOMPARE(s.cycle_scatter->first_cycle, result.cycles >= 3 ? 2 : 1);
    QCOMPARE(s.cycle_scatter->figures.size(), s.headline.size());
    for (std::size_t k = 0; k < s.headline.size(); ++k) {
      const auto& f = s.cycle_scatter->figures[k];
      QCOMPARE(f.figure.key, s.headline[k].key);
      QVERIFY(f.min <= s.headline[k].value && s.headline[k].value <= f.max);
    }
    qInfo("%s", s.cycle_scatter->Summary().c_str());
    // The run warns of nothing about it: it is periodic.
    for (const io::RunWarning& w : io::RunWarnings(config, result))
      QVERIFY(w.code != "not_periodic");
  }

  // A big end in heat-balance mode whose oil's viscosity does not follow temperature: a second
  // run at the balance's temperature would be the first again, so one run gives the balance's
  // fixed point (residual 0) and the film temperature is the balance of that run's P and Q.
  void heatBalanceOfAConstantViscosityTakesOneRun() {
    const engine::RunResult result = HeatBalancedBigEnd(
        [](engine::EngineCase& c) { c.lubricant.model = lubrication::ViscosityModel::kConstant; });
    QVERIFY2(result.status == engine::RunStatus::kCompleted, result.message.c_str());
    QVERIFY(result.heat_balance && result.heat_balance->converged);
    QCOMPARE(result.heat_balance->runs, 1);
    QCOMPARE(result.heat_balance->residual, 0.0);
    const auto [power, leakage] = MeanBigEndPowerAndLeakage(result);
    const double balance = 363.15 + power / (860.0 * 2000.0 * leakage);
    QVERIFY2(std::abs(*result.big_end_film_temperature - balance) < 1e-9,
             qPrintable(QString::number(*result.big_end_film_temperature - balance)));
  }

  // A mass-conserving big end's heat balance takes the oil leaving the film from its oil account
  // (the oil per cycle it reports, booked at every integrator step), not the sampled leakage: the
  // balance computed here from the account misses the film temperature by exactly the residual
  // the run reports (to round-off); the samples' mean leakage differs from the account's.
  void massConservingHeatBalanceUsesTheOilAccount() {
    const engine::RunResult result = HeatBalancedBigEnd(
        [](engine::EngineCase& c) { c.big_end.cavitation = lubrication::CavitationModel::kJfo; });
    QVERIFY2(result.status == engine::RunStatus::kCompleted, result.message.c_str());
    QVERIFY(result.heat_balance && result.heat_balance->converged);
    const double t = *result.big_end_film_temperature;
    const auto oil = engine::AccountedOil(result.samples, true);
    QVERIFY(oil.has_value());
    const double span =
        (result.samples[1].time - result.samples[0].time) * double(result.samples.size());
    const auto [power, sampled] = MeanBigEndPowerAndLeakage(result);
    const double leakage = oil->out / span;
    const double balance = 363.15 + power / (860.0 * 2000.0 * leakage);
    const double residual = result.heat_balance->residual;
    qInfo(
        "JFO heat balance: %d runs, T %.4f K, balance %.4f K, residual %.2e K; leakage %.5g "
        "m3/s (account), %.5g (samples)",
        result.heat_balance->runs, t, balance, residual, leakage, sampled);
    QVERIFY(std::abs(balance - t) <= 0.25);
    QVERIFY2(std::abs(std::abs(balance - t) - residual) < 1e-9,
             qPrintable(QString::number(std::abs(balance - t) - residual)));
    // What the samples would have given differs by more than that round-off.
    const double from_samples = 363.15 + power / (860.0 * 2000.0 * sampled);
    QVERIFY(std::abs(std::abs(from_samples - t) - residual) > 1e-6);
  }

  // A pressure law in an engine run, phased in over the first half of the run-in: a vanishing
  // coefficient reproduces the isoviscous run; Barus' law at 2e-8 1/Pa (and Roelands' at z 0.6,
  // weaker at these pressures) raises the peak film pressure and thickens the thinnest film.
  void pressureLawInAnEngineRun() {
    struct Figures {
      double moft = 1e9, peak = 0.0, fpl = 0.0;
    };
    auto run = [](lubrication::PressureLaw law, double alpha) {
      // Only-LBRBE at 6000 rpm on a coarse big-end mesh, the case's oil (20 mPa s).
      engine::RunConfig config = DefaultConfig(6000, engine::Model::kOnlyLbrbe);
      config.engine_case.big_end.mesh_theta = 48;
      config.engine_case.big_end.mesh_z = 6;
      config.engine_case.solver.error_estimate = 0;
      config.engine_case.solver.steady_state_tolerance = 1e-3;
      config.engine_case.lubricant.pressure_law = law;
      config.engine_case.lubricant.barus_alpha = alpha;
      const engine::RunResult r = engine::RunJob(config);
      if (r.status != engine::RunStatus::kCompleted) qFatal("%s", r.message.c_str());
      Figures f;
      for (const auto& s : r.samples) {
        f.moft = std::min(f.moft, s.bearing.moft);
        f.peak = std::max(f.peak, s.bearing.max_pressure);
        f.fpl += s.bearing.fpl / static_cast<double>(r.samples.size());
      }
      qInfo("%s alpha %g: min MOFT %.4f um, peak %.4g MPa, mean FPL %.4g W",
            lubrication::ToString(law), alpha, f.moft * 1e6, f.peak * 1e-6, f.fpl);
      return f;
    };
    const Figures iso = run(lubrication::PressureLaw::kNone, 0.0);
    const Figures tiny = run(lubrication::PressureLaw::kBarus, 1e-15);
    const Figures barus = run(lubrication::PressureLaw::kBarus, 2e-8);
    const Figures roelands = run(lubrication::PressureLaw::kRoelands, 0.0);
    // The vanishing law changes the films by ~1e-7; the runs differ by their periodic-state
    // tolerance (1e-3 of each tracked quantity's range over the cycle) through the adaptive
    // steps: 0.5 %, against the 20–50 % a real law makes.
    const double d_moft = tiny.moft / iso.moft - 1.0, d_peak = tiny.peak / iso.peak - 1.0,
                 d_fpl = tiny.fpl / iso.fpl - 1.0;
    qInfo("vanishing law vs none: MOFT %.2e, peak %.2e, FPL %.2e", d_moft, d_peak, d_fpl);
    QVERIFY(std::abs(d_moft) < 5e-3 && std::abs(d_peak) < 5e-3 && std::abs(d_fpl) < 5e-3);
    QVERIFY(barus.peak > 1.2 * iso.peak);
    QVERIFY(barus.moft > 1.2 * iso.moft);
    QVERIFY(barus.fpl > 1.1 * iso.fpl);
    QVERIFY(roelands.peak > iso.peak && roelands.peak < barus.peak);
    QVERIFY(roelands.moft > iso.moft && roelands.moft < barus.moft);
  }

  // Where even the phased-in law cannot keep the rigid film's reduced pressure below its limit
  // (the big end at 3000 rpm with the thin Vogel oil reaches 270 MPa isoviscous), the run ends
  // failed, naming the joint, the limit and the crank angle, with what was computed kept.
  void filmBeyondThePressureLawLimitEndsTheRunNamingIt() {
    engine::RunConfig config = CoarseBigEndWithVogelOil();
    config.engine_case.lubricant.pressure_law = lubrication::PressureLaw::kBarus;
    const engine::RunResult r = engine::RunJob(config);
    QCOMPARE(r.status, engine::RunStatus::kFailed);
    QVERIFY2(
        r.message.find("big-end film beyond the pressure-viscosity limit") != std::string::npos &&
            r.message.find("°CA") != std::string::npos,
        r.message.c_str());
    QVERIFY(!r.samples.empty());
  }

  // A run that fails inside a cycle (here an error thrown at 100 °CA of cycle 2, as the
  // integrator's own failures are) counts that cycle: its results are that cycle up to the
  // failure, and cycles = reported_cycle says so (cycles stayed at the last whole cycle, so the
  // command called the part "the last whole one").
  void aRunFailingInsideACycleCountsThatCycle() {
    const engine::RunConfig config = CoarseBigEndWithVogelOil();
    const engine::RunMonitor monitor = [](const engine::RunProgress& p) {
      if (!p.run_in && p.cycle == 2 && p.crank_angle_deg >= 100.0)
        throw std::runtime_error("a test's failure");
      return true;
    };
    const engine::RunResult r = engine::RunJob(config, monitor);
    QCOMPARE(r.status, engine::RunStatus::kFailed);
    QVERIFY2(r.message.find("a test's failure") != std::string::npos, r.message.c_str());
    QCOMPARE(r.cycles, 2);
    QCOMPARE(r.reported_cycle, 2);
    QVERIFY(!r.samples.empty());
    QVERIFY(engine::CycleCrankAngleDeg(r.samples.back().crank_angle) < 101.0);
  }

  // Inside an output step the monitor hears where the integration stands (heartbeats, here at
  // every force evaluation): between the output steps' crank angles, no sample, the progress
  // never running backwards across heartbeats and output steps, in the run-in and in the
  // cycles; a monitor that answers "stop" to a heartbeat ends the run there, cancelled.
  void heartbeatsReportInsideOutputSteps() {
    engine::RunConfig config = CoarseBigEndWithVogelOil();
    config.engine_case.solver.max_cycles = 1;
    config.engine_case.solver.output_interval = 30.0 * M_PI / 180.0;
    config.heartbeat_interval = 1e-12;  // at every evaluation of the forces
    struct Seen {
      bool heartbeat, has_sample, run_in;
      int cycle;
      double position, fraction, label;
    };
    std::vector<Seen> seen;
    bool angles_are_the_samples = true;  // an output step's crank angle is its sample's
    const engine::RunMonitor monitor = [&](const engine::RunProgress& p) {
      seen.push_back({p.heartbeat, p.sample != nullptr, p.run_in, p.cycle, p.crank_angle_deg,
                      p.fraction, engine::CycleCrankAngleDeg(p.crank_angle)});
      if (p.sample != nullptr) angles_are_the_samples &= p.crank_angle == p.sample->crank_angle;
      return true;
    };
    const engine::RunResult r = engine::RunJob(config, monitor);
    QVERIFY2(r.status != engine::RunStatus::kFailed, r.message.c_str());
    QVERIFY(angles_are_the_samples);
    int heartbeats[2] = {0, 0};  // run-in, cycle 1
    // The start of the run-in: where the integration is before the first output step.
    double last_output = -engine::RunInAngle(config.engine_case) * 180.0 / M_PI;
    for (std::size_t k = 0; k < seen.size(); ++k) {
      const Seen& s = seen[k];
      if (k > 0) QVERIFY(s.fraction >= seen[k - 1].fraction);
      if (!s.heartbeat) {
        QVERIFY(s.has_sample);
        last_output = s.run_in ? s.position : s.position + 720.0 * (s.cycle - 1);
        continue;
      }
      QVERIFY(!s.has_sample);
      ++heartbeats[s.run_in ? 0 : 1];
      // Past the last output step, not past the next (30 °CA on).
      const double at = s.run_in ? s.position : s.position + 720.0 * (s.cycle - 1);
      QVERIFY2(
          at > last_output - 1e-9 && at <= last_output + 30.0 + 1e-9,
          qPrintable(
              QString("heartbeat at %1 after the output step at %2").arg(at).arg(last_output)));
      // Its label is the crank angle of that position (the cycle starts at 0 °CA).
      if (!s.run_in && s.position >= 0.0) QVERIFY(std::abs(s.label - s.position) < 1e-6);
    }
    qInfo("%d heartbeats in the run-in, %d in cycle 1, %zu reports", heartbeats[0], heartbeats[1],
          seen.size());
    QVERIFY(heartbeats[0] > 0 && heartbeats[1] > 0);

    // Stopped by the monitor at a heartbeat of cycle 1: cancelled there, with its rows so far.
    const engine::RunMonitor stop = [](const engine::RunProgress& p) {
      return !(p.heartbeat && p.cycle == 1 && p.crank_angle_deg > 100.0);
    };
    const engine::RunResult stopped = engine::RunJob(config, stop);
    QCOMPARE(stopped.status, engine::RunStatus::kCancelled);
    QVERIFY2(stopped.message.find("cancelled (cycle 1") != std::string::npos,
             stopped.message.c_str());
    QVERIFY(!stopped.samples.empty());
    QVERIFY(engine::CycleCrankAngleDeg(stopped.samples.back().crank_angle) < 130.0 + 1e-6);
  }

  // A skirt that passes the liner's wall (100 rpm with the default oil: the rigid skirt cannot
  // carry the side force) ends the run, and its last row gives the gap it reached, negative, as
  // the message does: the film the solver held at its floor (1 nm) read as a film.
  void aSkirtPastTheLinersWallReportsItsGap() {
    const io::LoadedCase loaded = io::LoadCase({});
    engine::EngineCase c = loaded.value;
    c.solver.error_estimate = 0;
    const engine::RunConfig config = engine::MakeRunConfig(c, engine::Model::kOnlySkirt, 100,
                                                           io::PressureCurveForSpeed(loaded, 1000));
    const engine::RunResult r = engine::RunJob(config);
    QCOMPARE(engine::StatusName(r.status), std::string("failed"));
    QVERIFY2(r.message.find("skirt touches the liner") != std::string::npos, r.message.c_str());
    QVERIFY(!r.samples.empty());
    const coupling::SkirtFilmSample& last = r.samples.back().skirt;
    qInfo("smallest gap %.4g um, moft %.4g um", last.min_gap * 1e6, last.moft * 1e6);
    QVERIFY(last.min_gap < 0.0);
    QCOMPARE(last.moft, last.min_gap);
    // Where: on the thrust or anti-thrust centre line (a round skirt), within the skirt's length.
    QVERIFY(std::abs(last.moft_alpha) < 1e-12 || std::abs(last.moft_alpha - M_PI) < 1e-12);
    QVERIFY(last.moft_y >= 0.0 && last.moft_y <= c.skirt.length + 1e-12);
    for (std::size_t k = 0; k + 1 < r.samples.size(); ++k)  // the rows before: films
      QVERIFY(r.samples[k].skirt.moft > 0.0);
  }

  // The same with an elastic skirt: its surfaces meet past their rigid position and no
  // deformation opens the film. The run says the skirt touches the liner, where, and what moves
  // it (it used to end as "integration failed: CVODE step failed (-10)").
  void anElasticSkirtOnTheLinerSaysSo() {
    const io::LoadedCase loaded = io::LoadCase({});
    engine::EngineCase c = loaded.value;
    c.solver.error_estimate = 0;
    c.skirt.compliance = lubrication::ComplianceModel::kElasticLayer;
    const engine::RunConfig config = engine::MakeRunConfig(c, engine::Model::kOnlySkirt, 100,
                                                           io::PressureCurveForSpeed(loaded, 1000));
    const engine::RunResult r = engine::RunJob(config);
    QCOMPARE(engine::StatusName(r.status), std::string("failed"));
    QVERIFY2(r.message.starts_with("piston skirt touches the liner (the elastic surfaces meet"),
             r.message.c_str());
    QVERIFY2(r.message.find("below the skirt top at the last output") != std::string::npos,
             r.message.c_str());
    QVERIFY2(r.message.find("geometry.skirt_top_to_pin") != std::string::npos, r.message.c_str());
    QVERIFY(!r.samples.empty());
  }

  // A cranking speed with a cold, thick oil (100 rpm, 0.2 Pa·s; both joints lubricated, the
  // 1000 rpm firing curve): the films' squeeze damping makes the implicit steps span ~100 of the
  // journal's and the skirt's relaxation times, which Newton's iteration survives only with
  // accurate velocity columns in the films' Jacobians. Its first cycle takes ~11 000 steps; with
  // difference increments fixed in m/s it took ~0.4 million steps for 520–590 °CA alone (the
  // budget below stops such a run at once).
  void aCrankingSpeedRunWithAColdOilKeepsItsSteps() {
    const io::LoadedCase loaded = io::LoadCase({});
    engine::EngineCase c = loaded.value;
    c.lubricant.viscosity = 0.2;
    c.solver.error_estimate = 0;
    c.solver.max_cycles = 1;
    const engine::RunConfig config = engine::MakeRunConfig(c, engine::Model::kSkirtLbrbe, 100,
                                                           io::PressureCurveForSpeed(loaded, 1000));
    const long budget = 40000;
    const engine::RunMonitor monitor = [&](const engine::RunProgress& p) {
      return p.steps < budget;
    };
    const engine::RunResult r = engine::RunJob(config, monitor);
    qInfo("100 rpm, 0.2 Pa s: %s after %ld steps (%s)", engine::StatusName(r.status).c_str(),
          r.stats.steps, r.message.c_str());
    QVERIFY2(r.status != engine::RunStatus::kCancelled, "stopped at the step budget");
    QVERIFY2(r.status != engine::RunStatus::kFailed, r.message.c_str());
    QCOMPARE(r.cycles, 1);
    QVERIFY(r.stats.steps < budget);
  }

  // Both films mass-conserving at an idle speed (500 rpm on the 1000 rpm curve): in the run-in
  // the journal rebounds off the bearing (eps 0.989 -> 0.972 within a 6 us step) and the
  // integrator's rate of the gap overstates the gap's own change at the thinnest film, a
  // cavity there being emptied by the squeeze term alone; the run ended failed there (the
  // big end's film fraction 1.04 at 79 degrees of the run-in). The void's capacity (the
  // mass-conserving solve: a void never outgrows its gap) keeps every accepted step's fraction
  // within [0, 1].
  void anIdleSpeedMassConservingRunKeepsItsFilmFraction() {
    const io::LoadedCase loaded = io::LoadCase({});
    engine::EngineCase c = loaded.value;
    c.skirt.cavitation = lubrication::CavitationModel::kJfo;
    c.big_end.cavitation = lubrication::CavitationModel::kJfo;
    c.solver.error_estimate = 0;
    const engine::RunConfig config = engine::MakeRunConfig(c, engine::Model::kSkirtLbrbe, 500,
                                                           io::PressureCurveForSpeed(loaded, 1000));
    double reached = -1e9;
    const engine::RunMonitor monitor = [&](const engine::RunProgress& p) {
      if (p.run_in) reached = p.crank_angle_deg;
      return !(p.run_in && p.crank_angle_deg > -450.0);  // 270 degrees into the run-in
    };
    const engine::RunResult r = engine::RunJob(config, monitor);
    qInfo("500 rpm, both JFO: %s at %.1f degrees before the first cycle, %ld steps (%s)",
          engine::StatusName(r.status).c_str(), -reached, r.stats.steps, r.message.c_str());
    QVERIFY2(r.status == engine::RunStatus::kCancelled, r.message.c_str());
    QVERIFY(!r.samples.empty());
    const engine::CrankTrainSample& last = r.samples.back();
    QVERIFY(last.bearing.oil.kept && last.skirt.oil.kept);
    qInfo("largest fraction excess at any accepted step: big end %.3g, skirt %.3g",
          last.bearing.oil.fraction_excess, last.skirt.oil.fraction_excess);
    QVERIFY(last.bearing.oil.fraction_excess < coupling::kFractionTolerance);
    QVERIFY(last.skirt.oil.fraction_excess < coupling::kFractionTolerance);
  }

  // A run-in of a vanishing angle is none: at 1e-300 rad the integrator's first steps were
  // subnormal numbers and the mass-conserving film's solve failed at 0 °CA ("factorization
  // failed"), where 0 and 1e-9 rad run.
  void aVanishingRunInIsNone() {
    engine::RunConfig config = CoarseJfoBigEnd(3000);
    engine::EngineCase& c = config.engine_case;
    c.solver.jfo_run_in_angle = 1e-300;
    QCOMPARE(engine::RunInAngle(c), 0.0);
    // The fields' documentation gives the same floor.
    for (const char* path : {"solver.run_in_angle", "solver.jfo_run_in_angle"}) {
      const std::string doc = io::CaseFieldsMarkdown();
      const std::string row =
          doc.substr(doc.find(path), doc.find('\n', doc.find(path)) - doc.find(path));
      const auto below = row.find("below "), rad = row.find(" rad, none");
      double floor = 0.0;
      QVERIFY2(below != std::string::npos && rad != std::string::npos &&
                   ParseNumber(row.substr(below + 6, rad - below - 6), floor) &&
                   floor == engine::kShortestRunIn,
               row.c_str());
    }
    c.solver.jfo_run_in_angle = engine::kShortestRunIn;
    QCOMPARE(engine::RunInAngle(c), engine::kShortestRunIn);
    c.solver.jfo_run_in_angle = 1e-300;
    const engine::RunMonitor monitor = [](const engine::RunProgress& p) {
      return p.run_in || p.crank_angle_deg < 30.0;  // stop 30 degrees into the first cycle
    };
    const engine::RunResult r = engine::RunJob(config, monitor);
    QVERIFY2(r.status == engine::RunStatus::kCancelled, r.message.c_str());
    QVERIFY(!r.samples.empty());
  }

  // A compressible oil far softer than a mineral oil (0.1 GPa against ~1.7 GPa) in a
  // mass-conserving big end: the film's pressures pass its bulk modulus in the first degrees of
  // the run-in and the journal reaches the bearing. The failure names the bulk modulus, not only
  // the clearance and viscosity.
  void aFailedSoftCompressibleFilmNamesItsBulkModulus() {
    engine::RunConfig config = CoarseJfoBigEnd(6000);
    config.engine_case.lubricant.bulk_modulus = 1e8;
    const engine::RunMonitor monitor = [](const engine::RunProgress& p) {
      return p.run_in;  // the failure comes within the run-in; stop at the first cycle if not
    };
    const engine::RunResult r = engine::RunJob(config, monitor);
    qInfo("%s", r.message.c_str());
    QCOMPARE(r.status, engine::RunStatus::kFailed);
    for (const char* part :
         {"touches the bearing", "passed its oil's bulk modulus",
          "lubricant.bulk_modulus = 1e+08 Pa", "lubricant.density_law = \"dowson_higginson\"",
          "mineral oils: about 1.7e+09 Pa"})
      QVERIFY2(r.message.find(part) != std::string::npos, part);
    // The same oil on Dowson and Higginson's law, which stiffens as oils do (at most 35 %
    // denser), carries the load: the whole run-in passes, its film pressures beyond beta.
    config.engine_case.lubricant.density_law = lubrication::DensityLaw::kDowsonHigginson;
    double peak = 0.0;
    const engine::RunMonitor to_first_cycle = [&peak](const engine::RunProgress& p) {
      if (p.sample != nullptr)
        peak =
            std::max({peak, p.sample->bearing.max_pressure, p.sample->bearing.step_peak_pressure});
      return p.run_in;
    };
    const engine::RunResult dh = engine::RunJob(config, to_first_cycle);
    qInfo("Dowson-Higginson, beta 0.1 GPa: %s; film pressure up to %.3g Pa", dh.message.c_str(),
          peak);
    QVERIFY2(dh.status == engine::RunStatus::kCancelled, dh.message.c_str());
    QVERIFY(peak > 1e8);
  }

  // Shear thinning in an engine run: the Vogel oil calibrated to an HTHS viscosity of 3.2 mPa s
  // (Cross r 0.7, m 1) thins the big-end film; the summary's oil reports the law at the film
  // temperature.
  void shearThinningThinsTheFilm() {
    double moft[2] = {};
    for (int k = 0; k < 2; ++k) {
      engine::RunConfig config = CoarseBigEndWithVogelOil();
      if (k == 1) {
        config.engine_case.lubricant.shear_thinning = lubrication::ShearThinning::kHths;
        config.engine_case.lubricant.hths = 3.2e-3;
      }
      const engine::RunResult r = engine::RunJob(config);
      QVERIFY2(r.status == engine::RunStatus::kCompleted, r.message.c_str());
      moft[k] = 1e9;
      for (const auto& s : r.samples) moft[k] = std::min(moft[k], s.bearing.moft);
    }
    qInfo("min big-end MOFT: Newtonian %.4f um, shear-thinning %.4f um", moft[0] * 1e6,
          moft[1] * 1e6);
    QVERIFY(moft[1] < 0.95 * moft[0]);
  }

  // A catalogue oil below its fit's range (30 °C) runs, and the run's warnings say the
  // viscosity was extrapolated, naming the joint and the oil.
  void catalogueOilOutsideItsRangeIsAWarning() {
    engine::RunConfig config = CoarseBigEndWithVogelOil();
    config.engine_case.lubricant.model = lubrication::ViscosityModel::kGrade;
    config.engine_case.lubricant.grade = 3;  // 15w-40
    config.engine_case.big_end.oil.temperature = 303.15;
    const engine::RunResult r = engine::RunJob(config);
    QVERIFY2(r.status == engine::RunStatus::kCompleted, r.message.c_str());
    bool found = false;
    for (const io::RunWarning& w : io::RunWarnings(config, r)) {
      if (w.code != "oil_extrapolated") continue;
      found = true;
      QCOMPARE(w.joint, std::string("big_end"));
      QVERIFY2(w.message.find("Mobil Delvac MX ESP 15W-40") != std::string::npos,
               w.message.c_str());
    }
    QVERIFY(found);
    config.engine_case.big_end.oil.temperature = 373.15;
    for (const io::RunWarning& w : io::RunWarnings(config, r))
      QVERIFY(w.code != "oil_extrapolated");
  }

  // Hotter oil, thinner film: the big end at three film temperatures (Vogel oil) — the minimum
  // film falls and the asperity contact rises as the viscosity falls.
  void hotterFilmsAreThinner() {
    double last_moft = 1e9, last_contact = -1.0;
    for (double t : {353.15, 393.15, 433.15}) {
      engine::RunConfig config = CoarseBigEndWithVogelOil();
      config.engine_case.big_end.oil.temperature = t;
      const engine::RunResult r = engine::RunJob(config);
      QVERIFY2(r.status == engine::RunStatus::kCompleted, r.message.c_str());
      double moft = 1e9, contact = 0.0;
      for (const auto& s : r.samples) {
        moft = std::min(moft, s.bearing.moft);
        contact = std::max(contact, s.bearing.max_contact_pressure);
      }
      qInfo("%.2f K: min MOFT %.3f um, peak contact %.3g Pa", t, moft * 1e6, contact);
      QVERIFY(moft < 0.9 * last_moft);
      QVERIFY(contact >= last_contact);
      last_moft = moft;
      last_contact = contact;
    }
    QVERIFY(last_contact > 0.0);
  }
};

QTEST_GUILESS_MAIN(TestRunJob)
#include "test_run_job.moc"
