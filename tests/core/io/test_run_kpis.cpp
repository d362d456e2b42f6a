// The engine KPIs of summary.json ("kpis"):
// - from a hand-built cycle whose answers are known in closed form: the skirt's side force changes
//   sign at known crank angles (one of them across the wrap from 719 to 0 °CA), the piston's
//   velocities are known functions of time, so every slap event's crank angle, direction and
//   energy ½mv² + ½Iω² are known, and so are their maximum and sum; the film extremes with
//   their crank angles and positions, and the mean friction power (a cosine over the cycle around
//   a known mean); without motion samples the output samples' own velocities are used; a stopped
//   run's partial cycle has no wrap event; the ideal model has no KPIs; the KPIs round-trip
//   through summary.json and an older summary without them still reads;
// - from a real short run (Skirt-LBRBE at 6000 rpm on coarse meshes): the KPIs are the extremes
//   of its own results.csv rows, the slap events are where the rows' side force changes sign,
//   alternate in direction and add up to the reported sum, the piston's centre-of-mass velocity
//   is the one of its state, and summary.json round-trips.
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "core/io/case_file.hpp"
#include "core/io/results_writer.hpp"
#include "core/io/run_kpis.hpp"
#include "core/io/run_summary.hpp"

using namespace filmdyn;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = 180.0 / kPi;

bool Near(double a, double b, double relative, double absolute = 0.0) {
  return std::abs(a - b) <= relative * std::max(std::abs(a), std::abs(b)) + absolute;
}

// A hand-built cycle of 720 output steps (1 °CA) at 600 rad/s, starting in the third cycle of
// the run (unwrapped crank angle 8π), with 8 motion samples per step.
struct Synthetic {
  static constexpr int kSteps = 720;
  static constexpr int kParts = 8;
  static constexpr double kOmega = 600.0;                     // [rad/s]
  static constexpr double kStep = kPi / 180.0;                // [rad]
  static constexpr double kDt = kStep / kOmega;               // [s]
  static constexpr double kPeriod = kSteps * kDt;             // [s]
  static constexpr double kT0 = 0.125, kPhi0 = 8.0 * kPi;     // start of the cycle
  static constexpr double kMass = 0.264, kInertia = 1.29e-4;  // piston [kg], [kg·m²]

  // The piston's velocities: periodic over the cycle, far from linear over an output step (a
  // 60th harmonic: 12 steps per wave), so that interpolating between output steps and between
  // motion samples give clearly different numbers.
  static double Wave(double t, double harmonic) { return 2 * kPi * harmonic * (t - kT0) / kPeriod; }
  static double Lateral(double t) {
    return 0.02 + 0.015 * std::sin(Wave(t, 1)) + 0.004 * std::sin(Wave(t, 60));
  }
  static double Angular(double t) {
    return 3.0 * std::cos(Wave(t, 1)) - 0.5 + 0.8 * std::cos(Wave(t, 60));
  }
  static double Energy(double v, double w) { return 0.5 * kMass * v * v + 0.5 * kInertia * w * w; }
  static double Time(int k) { return kT0 + k * kDt; }

  std::vector<engine::CrankTrainSample> samples;
  std::vector<engine::MotionSample> motion;

  Synthetic() {
    for (int k = 0; k < kSteps; ++k) {
      engine::CrankTrainSample s;
      s.time = Time(k);
      s.crank_angle = kPhi0 + k * kStep;
      s.piston_com_lateral_velocity = Lateral(s.time);
      s.piston_tilt_rate = Angular(s.time);
      s.skirt.present = true;
      s.bearing.present = true;
      // Side force: + (anti-thrust wall) but -20 N at step 0 and -10/-20 N over steps 101-400.
      // Changes: 719→0 (+20 → −20: s = 1/2, to thrust), 0→1 (−20 → +60: s = 1/4, to
      // anti-thrust), 100→101 (+30 → −10: s = 3/4, to thrust), 400→401 (−20 → +60: s = 1/4, to
      // anti-thrust). Step 500 is exactly 0 between positive forces: no change of side.
      double f = 60.0;
      if (k == 0) f = -20.0;
      if (k == 100) f = 30.0;
      if (k > 100 && k < 400) f = -10.0;
      if (k == 400) f = -20.0;
      if (k == 500) f = 0.0;
      if (k == 719) f = 20.0;
      s.skirt.normal_force = f;
      // Films: a smooth MOFT with its minimum planted at step 372, the peak film pressure at
      // 365, no asperity contact on the skirt; FPL a cosine around 100 W.
      s.skirt.moft = 8e-6 + 1e-6 * std::cos(k * kStep);
      s.skirt.moft_alpha = 0.1;
      s.skirt.moft_y = 0.02;
      if (k == 372) {
        s.skirt.moft = 1.5e-6;
        s.skirt.moft_alpha = 0.3;
        s.skirt.moft_y = 0.012;
      }
      s.skirt.max_pressure = k == 365 ? 5e7 : 1e6;
      s.skirt.max_contact_pressure = 0.0;
      s.skirt.fpl = 100.0 + 50.0 * std::cos(2 * kPi * k / kSteps);
      s.skirt.inflow = 0.5e-6;  // [m³/s]; oil flows around a mean, as a run's
      s.skirt.outflow = 2e-6 + 0.5e-6 * std::sin(2 * kPi * k / kSteps);
      s.bearing.supply_flow = 1e-6 + 0.3e-6 * std::cos(2 * kPi * k / kSteps);
      s.bearing.side_flow = 0.8e-6;
      s.bearing.moft = k == 380 ? 0.9e-6 : 3e-6;
      s.bearing.journal_ecc_rod =
          k == 380 ? Eigen::Vector2d(-3e-5, -3e-5) : Eigen::Vector2d(0, 1e-5);
      s.bearing.eps = k == 381 ? 0.93 : 0.5;
      s.bearing.max_pressure = k == 370 ? 8e7 : 2e6;
      s.bearing.max_contact_pressure = k == 371 ? 2e6 : 0.0;
      s.bearing.fpl = 40.0 - 10.0 * std::sin(2 * kPi * k / kSteps);
      samples.push_back(s);
    }
    // The motion: every output step and kParts − 1 instants between consecutive ones (none after
    // the last step, as in a run).
    for (int k = 0; k < kSteps; ++k) {
      for (int j = k == 0 ? 0 : 1 - kParts; j <= 0; ++j) {
        engine::MotionSample m;
        m.time = Time(k) + j * kDt / kParts;
        m.crank_angle = kPhi0 + (k + double(j) / kParts) * kStep;
        m.piston_present = true;
        m.piston_com_lateral_velocity = Lateral(m.time);
        m.piston_tilt_rate = Angular(m.time);
        motion.push_back(m);
      }
    }
  }
};

// The expected events (time order) with motion samples: crossings at s = k/8 of a step fall on a
// motion sample, where the velocities are exact; the wrap's (after the last step, no motion
// samples there) is the linear interpolation between the last step and the first one cycle on.
struct Expected {
  double angle;
  bool to_thrust;
  double energy;
};

std::vector<Expected> ExpectedWithMotion() {
  using S = Synthetic;
  auto at = [](int k, double s) {
    const double t = S::Time(k) + s * S::kDt;
    return S::Energy(S::Lateral(t), S::Angular(t));
  };
  const double v_wrap = 0.5 * (S::Lateral(S::Time(719)) + S::Lateral(S::kT0 + S::kPeriod));
  const double w_wrap = 0.5 * (S::Angular(S::Time(719)) + S::Angular(S::kT0 + S::kPeriod));
  return {{0.25, false, at(0, 0.25)},
          {100.75, true, at(100, 0.75)},
          {400.25, false, at(400, 0.25)},
          {719.5, true, S::Energy(v_wrap, w_wrap)}};
}

void CheckEvents(const io::PistonSlap& slap, const std::vector<Expected>& expected) {
  QCOMPARE(slap.events.size(), expected.size());
  double sum = 0.0, max = -1.0, max_angle = -1.0;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const io::SlapEvent& e = slap.events[i];
    QVERIFY2(Near(e.crank_angle_deg, expected[i].angle, 0.0, 1e-9),
             qPrintable(QString("event %1 at %2 °CA").arg(i).arg(e.crank_angle_deg)));
    QCOMPARE(e.to_thrust, expected[i].to_thrust);
    QVERIFY2(Near(e.energy, expected[i].energy, 1e-12),
             qPrintable(QString("event %1: %2 J, expected %3 J")
                            .arg(i)
                            .arg(e.energy, 0, 'g', 17)
                            .arg(expected[i].energy, 0, 'g', 17)));
    sum += expected[i].energy;
    if (expected[i].energy > max) {
      max = expected[i].energy;
      max_angle = expected[i].angle;
    }
  }
  if (slap.energy_sum) QVERIFY(Near(*slap.energy_sum, sum, 1e-12));  // a whole cycle's only
  QVERIFY(slap.energy_max.has_value());
  QVERIFY(Near(*slap.energy_max, max, 1e-12));
  QVERIFY(Near(*slap.energy_max_crank_angle_deg, max_angle, 0.0, 1e-9));
}

engine::RunConfig CoarseSkirtLbrbe() {
  const io::LoadedCase loaded = io::LoadCase({});
  engine::RunConfig config = engine::MakeRunConfig(loaded.value, engine::Model::kSkirtLbrbe, 6000.0,
                                                   io::PressureCurveForSpeed(loaded, 6000.0));
  auto& c = config.engine_case;
  c.skirt.mesh_thrust = c.skirt.mesh_anti = 6;
  c.skirt.mesh_relief = 1;
  c.skirt.mesh_axial = 6;
  c.big_end.mesh_theta = 24;
  c.big_end.mesh_z = 6;
  c.solver.error_estimate = 0;
  c.solver.max_cycles = 1;
  c.solver.run_in_angle = kPi / 2;
  return config;
}

}  // namespace

class TestRunKpis : public QObject {
  Q_OBJECT
 private slots:
  void slapFromMotionSamples() {
    const Synthetic cycle;
    const io::RunKpis kpis = io::ComputeRunKpis(cycle.samples, cycle.motion, Synthetic::kMass,
                                                Synthetic::kInertia, true);
    QVERIFY(kpis.skirt && kpis.skirt->slap);
    CheckEvents(*kpis.skirt->slap, ExpectedWithMotion());
    QVERIFY(!kpis.big_end->slap);  // the big end has no slap
  }

  void slapWithoutMotionSamplesUsesTheOutputSamples() {
    // Linear interpolation of the velocities between the two output steps: a different number
    // than the motion samples give (the velocities are not linear in time).
    using S = Synthetic;
    const Synthetic cycle;
    const io::RunKpis kpis = io::ComputeRunKpis(cycle.samples, {}, S::kMass, S::kInertia, true);
    auto between = [](int k, int next, double s) {
      const double t_next = next == 0 ? S::kT0 + S::kPeriod : S::Time(next);
      const double v = S::Lateral(S::Time(k)) + s * (S::Lateral(t_next) - S::Lateral(S::Time(k)));
      const double w = S::Angular(S::Time(k)) + s * (S::Angular(t_next) - S::Angular(S::Time(k)));
      return S::Energy(v, w);
    };
    const std::vector<Expected> expected = {{0.25, false, between(0, 1, 0.25)},
                                            {100.75, true, between(100, 101, 0.75)},
                                            {400.25, false, between(400, 401, 0.25)},
                                            {719.5, true, between(719, 0, 0.5)}};
    CheckEvents(*kpis.skirt->slap, expected);
    // Not the motion samples' numbers (they differ by the curvature of the velocities).
    for (int i = 0; i < 3; ++i) {
      QVERIFY(!Near(expected[i].energy, ExpectedWithMotion()[i].energy, 1e-3));
    }
  }

  // A side force of exactly 0 (a starved skirt off its oil) is no side: the piston changes side
  // only where the force reappears on the other side, at the last step without one; a return to
  // the same side is no slap. A whole cycle whose first steps have no side force still sees the
  // change across them once, after its last step.
  void stepsWithoutSideForceAreNoSide() {
    const auto events = [](const std::vector<double>& forces, bool whole) {
      std::vector<engine::CrankTrainSample> samples(forces.size());
      for (std::size_t k = 0; k < forces.size(); ++k) {
        engine::CrankTrainSample& s = samples[k];
        s.time = 1e-3 * double(k);
        s.crank_angle = 4.0 * kPi * double(k) / double(forces.size());  // 90 °CA apart for 8
        s.skirt.present = true;
        s.skirt.normal_force = forces[k];
        s.piston_com_lateral_velocity = 0.1;  // [m/s]
      }
      return io::ComputeRunKpis(samples, {}, 1.0, 0.0, whole).skirt->slap->events;
    };
    // −4 N, then no force, then −97 N: the same side, no slap (it counted two before).
    QCOMPARE(events({-4, 0, -97, -50, -20, -10, -5, -4}, true).size(), std::size_t(0));
    // Off its oil from 90 to 180 °CA, then onto the anti-thrust wall at 270 °CA: one change, at
    // 180 °CA (the last step without a force); back onto the thrust wall between 450 and 540.
    std::vector<io::SlapEvent> e = events({-4, 0, 0, 50, 40, 30, -30, -4}, true);
    QCOMPARE(e.size(), std::size_t(2));
    QVERIFY(Near(e[0].crank_angle_deg, 180.0, 0.0, 1e-9) && !e[0].to_thrust);
    QVERIFY(Near(e[1].crank_angle_deg, 495.0, 0.0, 1e-9) && e[1].to_thrust);
    QVERIFY(Near(e[0].energy, 0.5 * 0.1 * 0.1, 1e-12));
    // The same cycle started at the steps without a force: the change across them is seen once,
    // after the cycle's last step (crank angle past 720, read within the cycle).
    e = events({0, 0, 50, 40, 30, -30, -4, -4}, true);
    QCOMPARE(e.size(), std::size_t(2));
    QVERIFY(Near(e[0].crank_angle_deg, 405.0, 0.0, 1e-9) && e[0].to_thrust);
    QVERIFY(Near(e[1].crank_angle_deg, 90.0, 0.0, 1e-9) && !e[1].to_thrust);
    // Not a whole cycle: no look round it.
    QCOMPARE(events({0, 0, 50, 40, 30, -30, -4, -4}, false).size(), std::size_t(1));
  }

  void partialCycleHasNoWrapEvent() {
    const Synthetic cycle;
    const io::RunKpis kpis = io::ComputeRunKpis(cycle.samples, cycle.motion, Synthetic::kMass,
                                                Synthetic::kInertia, false);
    std::vector<Expected> expected = ExpectedWithMotion();
    expected.pop_back();
    CheckEvents(*kpis.skirt->slap, expected);
    // Part of a cycle has no slap energy "per cycle": the sum is a whole cycle's only.
    QVERIFY(!kpis.skirt->slap->energy_sum.has_value());
    const io::RunKpis whole = io::ComputeRunKpis(cycle.samples, cycle.motion, Synthetic::kMass,
                                                 Synthetic::kInertia, true);
    QVERIFY(whole.skirt->slap->energy_sum.has_value());
  }

  void filmExtremesPositionsAndMeans() {
    const Synthetic cycle;
    const io::RunKpis kpis = io::ComputeRunKpis(cycle.samples, cycle.motion, Synthetic::kMass,
                                                Synthetic::kInertia, true);
    QVERIFY(kpis.skirt && kpis.big_end);
    const io::JointKpis &skirt = *kpis.skirt, &big_end = *kpis.big_end;
    QCOMPARE(skirt.min_moft, 1.5e-6);
    QVERIFY(Near(skirt.min_moft_crank_angle_deg, 372.0, 0.0, 1e-9));
    QVERIFY(Near(skirt.min_moft_position.angle_deg, 0.3 * kDeg, 1e-15));
    QCOMPARE(skirt.min_moft_position.axial_m.value(), 0.012);
    QCOMPARE(skirt.peak_pressure, 5e7);
    QVERIFY(Near(skirt.peak_pressure_crank_angle_deg.value(), 365.0, 0.0, 1e-9));
    QCOMPARE(skirt.peak_contact_pressure, 0.0);
    QVERIFY(!skirt.peak_contact_pressure_crank_angle_deg);  // no contact: no crank angle
    QVERIFY(!skirt.max_eps);
    // Means: a whole period of a cosine around 100 W (and of a sine around 40 W), and exactly
    // the headline figure.
    QVERIFY(Near(skirt.mean_fpl.value(), 100.0, 1e-12));
    QVERIFY(Near(big_end.mean_fpl.value(), 40.0, 1e-12));
    for (const engine::HeadlineFigure& f : engine::HeadlineFigures(cycle.samples)) {
      if (f.key == "skirt_fpl_mean[W]") QCOMPARE(*skirt.mean_fpl, f.value);
      if (f.key == "bearing_fpl_mean[W]") QCOMPARE(*big_end.mean_fpl, f.value);
    }
    QCOMPARE(big_end.min_moft, 0.9e-6);
    QVERIFY(Near(big_end.min_moft_crank_angle_deg, 380.0, 0.0, 1e-9));
    QVERIFY(Near(big_end.min_moft_position.angle_deg, 225.0, 1e-15));  // (−1, −1) in the rod frame
    QVERIFY(!big_end.min_moft_position.axial_m);
    QCOMPARE(big_end.peak_pressure, 8e7);
    QVERIFY(Near(big_end.peak_pressure_crank_angle_deg.value(), 370.0, 0.0, 1e-9));
    QCOMPARE(big_end.peak_contact_pressure, 2e6);
    QVERIFY(Near(big_end.peak_contact_pressure_crank_angle_deg.value(), 371.0, 0.0, 1e-9));
    QCOMPARE(big_end.max_eps.value(), 0.93);
    QVERIFY(Near(big_end.max_eps_crank_angle_deg.value(), 381.0, 0.0, 1e-9));
    // Oil, films without an account (Reynolds): the big end's supply and side flow are the mean
    // of the samples times the cycle (1 and 0.8 cm³/s over its 4π / 600 rad/s); the skirt's
    // outflow too, but its inflow is no figure (a Reynolds skirt's is a mesh quantity).
    QVERIFY(Near(big_end.oil_in_per_cycle.value(), 1e-6 * Synthetic::kPeriod, 1e-12));
    QVERIFY(Near(big_end.oil_out_per_cycle.value(), 0.8e-6 * Synthetic::kPeriod, 1e-12));
    QVERIFY(Near(skirt.oil_out_per_cycle.value(), 2e-6 * Synthetic::kPeriod, 1e-12));
    QVERIFY(!skirt.oil_in_per_cycle);
    QVERIFY(!skirt.oil_balance && !big_end.oil_balance);
    // Likewise its results.csv column: the Reynolds skirt's inflow is an empty cell, its outflow
    // and the big end's flows are there; a skirt that keeps an oil account (JFO) reports it.
    {
      engine::CrankTrainSample reynolds = cycle.samples.at(10);
      const io::OutputRow row = io::RowFromSample(reynolds, engine::Model::kSkirtLbrbe, 0.0);
      QVERIFY(!row.skirt_inflow);
      QCOMPARE(row.skirt_outflow.value(), reynolds.skirt.outflow);
      QCOMPARE(row.bearing_supply_flow.value(), reynolds.bearing.supply_flow);
      engine::CrankTrainSample jfo = reynolds;
      jfo.skirt.oil.Book(jfo.time, 1e-6, 0.5e-6, 0.4e-6, 0.0, 0.0, 0.0);
      QCOMPARE(io::RowFromSample(jfo, engine::Model::kSkirtLbrbe, 0.0).skirt_inflow.value(),
               0.5e-6);
    }
    // The position rule's other quadrants: 90° = toward the small end, 0 = rod-frame x.
    engine::CrankTrainSample s;
    s.bearing.journal_ecc_rod = {0.0, 2e-5};
    QVERIFY(Near(io::MinFilmPosition(s, false).angle_deg, 90.0, 1e-15));
    s.bearing.journal_ecc_rod = {2e-5, -1e-20};
    QVERIFY(io::MinFilmPosition(s, false).angle_deg < 360.0);
  }

  void idealModelHasNoKpis() {
    Synthetic cycle;
    for (auto& s : cycle.samples) s.skirt.present = s.bearing.present = false;
    for (auto& m : cycle.motion) m.piston_present = false;
    const io::RunKpis kpis = io::ComputeRunKpis(cycle.samples, cycle.motion, Synthetic::kMass,
                                                Synthetic::kInertia, true);
    QVERIFY(!kpis.skirt && !kpis.big_end);
    io::RunSummary summary;
    summary.model = "ideal";
    summary.status = "completed";
    summary.kpis = kpis;
    const nlohmann::json j = io::SummaryToJson(summary);
    QVERIFY(j.at("kpis").is_object() && j.at("kpis").empty());
  }

  void roundTripAndOlderSummaries() {
    const Synthetic cycle;
    io::RunSummary summary;
    summary.model = "skirt-lbrbe";
    summary.status = "completed";
    summary.kpis = io::ComputeRunKpis(cycle.samples, cycle.motion, Synthetic::kMass,
                                      Synthetic::kInertia, true);
    const nlohmann::json j = io::SummaryToJson(summary);
    const io::RunSummary back = io::SummaryFromJson(j);
    QCOMPARE(io::SummaryToJson(back).dump(), j.dump());
    QCOMPARE(back.kpis.skirt->slap->events.size(), std::size_t(4));
    QCOMPARE(back.kpis.skirt->slap->events[1].to_thrust, true);
    QVERIFY(back.kpis.skirt->min_moft_position.axial_m.has_value());
    QVERIFY(!back.kpis.big_end->min_moft_position.axial_m.has_value());
    const nlohmann::json& k = j.at("kpis");
    QCOMPARE(k.at("skirt").at("slap_events").at(0).at("direction").get<std::string>(),
             std::string("to_anti_thrust"));
    QVERIFY(k.at("skirt").at("peak_contact_pressure_crank_angle[deg]").is_null());
    QVERIFY(!k.at("skirt").contains("max_eps[-]"));
    QVERIFY(!k.at("big_end").contains("slap_events"));
    // A summary written before the KPIs existed reads, without them.
    nlohmann::json old = j;
    old.erase("kpis");
    const io::RunSummary read_old = io::SummaryFromJson(old);
    QVERIFY(!read_old.kpis.skirt && !read_old.kpis.big_end);
    // A wrong direction is named.
    nlohmann::json bad = j;
    bad["kpis"]["skirt"]["slap_events"][2]["direction"] = "sideways";
    try {
      io::SummaryFromJson(bad);
      QFAIL("no error");
    } catch (const std::runtime_error& e) {
      QVERIFY2(QString(e.what()).contains("kpis.skirt.slap_events.2.direction"), e.what());
    }
  }

  void realRunAgreesWithItsResults() {
    const engine::RunConfig config = CoarseSkirtLbrbe();
    const engine::RunResult result = engine::RunJob(config);
    QCOMPARE(engine::StatusName(result.status), std::string("not-converged"));  // 1 cycle
    QCOMPARE(result.samples.size(), std::size_t(720));
    QTemporaryDir dir;
    const auto rows = io::WriteRunFolder(dir.path().toStdString(), "default", config, result);
    const std::filesystem::path file = dir.filePath("summary.json").toStdString();
    const io::RunSummary summary = io::ReadSummaryJson(file);
    // summary.json round-trips, and it is what SummarizeRun makes.
    QCOMPARE(io::SummaryToJson(io::SummaryFromJson(io::SummaryToJson(summary))).dump(),
             io::SummaryToJson(summary).dump());
    QCOMPARE(
        io::SummaryToJson(summary).at("kpis").dump(),
        io::SummaryToJson(io::SummarizeRun("default", config, result, rows)).at("kpis").dump());
    QVERIFY(summary.kpis.skirt && summary.kpis.big_end);
    const io::JointKpis &skirt = *summary.kpis.skirt, &big_end = *summary.kpis.big_end;
    QCOMPARE(*skirt.fmep,
             io::FrictionMep(*skirt.mean_fpl, config.engine_case.geometry, config.rpm));
    QVERIFY(std::abs(*skirt.fmep_share + *big_end.fmep_share - 1.0) < 1e-14);

    // The extremes of the rows, at the crank angle of the (first) row holding them.
    // (A lambda returning void: the test macros return from it.)
    std::size_t skirt_min = 0, bearing_min = 0, unused = 0;
    auto check_extreme = [&rows, &summary](std::optional<double> io::OutputRow::*column,
                                           const char* header, bool largest, double value,
                                           std::optional<double> angle, std::size_t* where) {
      std::size_t at = rows.size();
      for (std::size_t k = 0; k < rows.size(); ++k) {
        const double v = *(rows[k].*column);
        if (at == rows.size() || (largest ? v > *(rows[at].*column) : v < *(rows[at].*column)))
          at = k;
      }
      *where = at;
      QCOMPARE(value, *(rows[at].*column));
      const io::ColumnExtremes& e = summary.extremes.at(header);
      QCOMPARE(value, largest ? e.max : e.min);
      QCOMPARE(angle.has_value(), value != 0.0);  // no "where" for a peak of 0
      if (angle) QCOMPARE(*angle, *rows[at].crank_angle_deg);
    };
    check_extreme(&io::OutputRow::skirt_moft, "skirt_moft[m]", false, skirt.min_moft,
                  skirt.min_moft_crank_angle_deg, &skirt_min);
    check_extreme(&io::OutputRow::skirt_peak_pressure, "skirt_peak_pressure[Pa]", true,
                  skirt.peak_pressure, skirt.peak_pressure_crank_angle_deg, &unused);
    check_extreme(&io::OutputRow::skirt_peak_contact_pressure, "skirt_peak_contact_pressure[Pa]",
                  true, skirt.peak_contact_pressure, skirt.peak_contact_pressure_crank_angle_deg,
                  &unused);
    check_extreme(&io::OutputRow::bearing_moft, "bearing_moft[m]", false, big_end.min_moft,
                  big_end.min_moft_crank_angle_deg, &bearing_min);
    check_extreme(&io::OutputRow::bearing_peak_pressure, "bearing_peak_pressure[Pa]", true,
                  big_end.peak_pressure, big_end.peak_pressure_crank_angle_deg, &unused);
    check_extreme(&io::OutputRow::bearing_peak_contact_pressure,
                  "bearing_peak_contact_pressure[Pa]", true, big_end.peak_contact_pressure,
                  big_end.peak_contact_pressure_crank_angle_deg, &unused);
    check_extreme(&io::OutputRow::bearing_eps, "bearing_eps[-]", true, big_end.max_eps.value(),
                  big_end.max_eps_crank_angle_deg, &unused);
    if (QTest::currentTestFailed()) return;
    QVERIFY(!skirt.max_eps);
    // Where the minimum films are: the skirt's within the skirt, the big end's the direction of
    // the row's journal position in the rod frame.
    QCOMPARE(skirt.min_moft_position.angle_deg, result.samples[skirt_min].skirt.moft_alpha * kDeg);
    QVERIFY(skirt.min_moft_position.angle_deg >= 0.0 && skirt.min_moft_position.angle_deg <= 180.0);
    QVERIFY(*skirt.min_moft_position.axial_m >= 0.0 &&
            *skirt.min_moft_position.axial_m <= config.engine_case.skirt.length + 1e-12);
    double direction =
        std::atan2(*rows[bearing_min].journal_ecc_y, *rows[bearing_min].journal_ecc_x) * kDeg;
    if (direction < 0.0) direction += 360.0;
    QVERIFY(Near(big_end.min_moft_position.angle_deg, direction, 1e-12));
    // Mean friction power: the plain mean of the rows (the headline figure's).
    double skirt_sum = 0.0, bearing_sum = 0.0;
    for (const auto& row : rows) {
      skirt_sum += *row.skirt_fpl;
      bearing_sum += *row.bearing_fpl;
    }
    QVERIFY(Near(skirt.mean_fpl.value(), skirt_sum / rows.size(), 1e-12));
    QVERIFY(Near(big_end.mean_fpl.value(), bearing_sum / rows.size(), 1e-12));
    QCOMPARE(*skirt.mean_fpl, *summary.mean_fpl_skirt_w);
    QCOMPARE(*big_end.mean_fpl, *summary.mean_fpl_bearing_w);

    // Piston slap: one event per change of sign of the rows' side force (the wrap included: the
    // reported cycle is whole), each between those two rows, alternating in direction.
    const io::PistonSlap& slap = skirt.slap.value();
    const std::size_t n = rows.size();
    std::vector<std::size_t> changes;
    for (std::size_t k = 0; k < n; ++k) {
      if ((*rows[k].skirt_normal_force < 0.0) != (*rows[(k + 1) % n].skirt_normal_force < 0.0))
        changes.push_back(k);
    }
    qInfo("%zu changes of thrust side; slap energy max %.4g J at %.2f °CA, sum %.4g J",
          changes.size(), slap.energy_max.value_or(0.0),
          slap.energy_max_crank_angle_deg.value_or(-1.0), slap.energy_sum.value_or(-1.0));
    QVERIFY(changes.size() >= 2);  // the piston crosses the clearance at least twice a cycle
    QCOMPARE(slap.events.size(), changes.size());
    double sum = 0.0, max = 0.0;
    for (std::size_t i = 0; i < changes.size(); ++i) {
      const io::SlapEvent& e = slap.events[i];
      const std::size_t k = changes[i];
      const double from = *rows[k].crank_angle_deg;
      const double to = from + (*rows[1].crank_angle_deg - *rows[0].crank_angle_deg);
      const double angle = e.crank_angle_deg < from ? e.crank_angle_deg + 720.0 : e.crank_angle_deg;
      QVERIFY2(angle >= from && angle <= to,
               qPrintable(QString("event at %1 °CA, change between %2 and %3 °CA")
                              .arg(e.crank_angle_deg)
                              .arg(from)
                              .arg(to)));
      QCOMPARE(e.to_thrust, *rows[(k + 1) % n].skirt_normal_force < 0.0);
      QCOMPARE(e.to_thrust, !slap.events[(i + 1) % changes.size()].to_thrust);
      QVERIFY(e.energy > 0.0);
      // Linear velocities between two motion samples: the energy is at most the larger of the
      // energies of the motion samples over the output step around it.
      double bound = 0.0;
      const double t_from = result.samples[k].time;
      const double t_to = k + 1 == n ? result.samples[k].time + 1e-12 : result.samples[k + 1].time;
      const double m = config.engine_case.geometry.piston_mass;
      const double inertia = config.engine_case.geometry.piston_inertia;
      for (const engine::MotionSample& s : result.motion) {
        if (s.time >= t_from && s.time <= t_to) {
          bound = std::max(bound,
                           0.5 * m * s.piston_com_lateral_velocity * s.piston_com_lateral_velocity +
                               0.5 * inertia * s.piston_tilt_rate * s.piston_tilt_rate);
        }
      }
      if (k + 1 == n) {  // the wrap: up to the first step's motion one cycle on
        const engine::MotionSample& s = result.motion.front();
        bound = std::max(bound,
                         0.5 * m * s.piston_com_lateral_velocity * s.piston_com_lateral_velocity +
                             0.5 * inertia * s.piston_tilt_rate * s.piston_tilt_rate);
      }
      QVERIFY2(e.energy <= bound * (1.0 + 1e-12),
               qPrintable(QString("event %1: %2 J above %3 J").arg(i).arg(e.energy).arg(bound)));
      sum += e.energy;
      max = std::max(max, e.energy);
    }
    QVERIFY(slap.energy_sum && Near(*slap.energy_sum, sum, 1e-12));
    QCOMPARE(slap.energy_max.value(), max);
    for (const io::SlapEvent& e : slap.events) {
      if (e.energy == max) QCOMPARE(slap.energy_max_crank_angle_deg.value(), e.crank_angle_deg);
    }

    // The centre of mass's lateral velocity is that of the piston's state: the pin axis's ė0
    // plus the rotation about it, ẋ_CoM = ė0 + γ̇ [(A(θ) s_pin)_y − C_p sin θ] (exact).
    const auto& g = config.engine_case.geometry;
    const double s_x = g.pin_offset - g.piston_com_lateral_offset;
    const double s_y = -(g.skirt_top_to_pin - g.skirt_top_to_com);
    double worst = 0.0, largest = 0.0;
    for (const engine::MotionSample& s : result.motion) {
      QVERIFY(s.piston_present);
      const double th = s.piston_tilt;
      const double expected = s.piston_lateral_velocity +
                              s.piston_tilt_rate * (std::sin(th) * s_x + std::cos(th) * s_y -
                                                    g.pin_offset * std::sin(th));
      worst = std::max(worst, std::abs(s.piston_com_lateral_velocity - expected));
      largest = std::max(largest, std::abs(s.piston_com_lateral_velocity));
    }
    QVERIFY(largest > 0.0);
    QVERIFY2(worst <= 1e-9 * largest, qPrintable(QString::number(worst / largest)));
    for (std::size_t k = 0; k < result.samples.size(); ++k) {  // the output steps' are theirs
      QCOMPARE(result.motion[8 * k].piston_com_lateral_velocity,
               result.samples[k].piston_com_lateral_velocity);
    }
  }

  // FMEP by hand: the friction work of a 720 °CA cycle per swept volume, with the exact stroke
  // of an offset slider crank; each joint's share of the sum.
  void frictionMeanEffectivePressureByHand() {
    engine::CrankTrainGeometry g;
    g.crank_radius = 0.04;
    g.rod_length = 0.14;
    g.liner_radius = 0.04;
    g.pin_offset = 0.0;
    const double swept = std::numbers::pi * 0.04 * 0.04 * 0.08;  // stroke 2 r without offset
    QVERIFY(std::abs(io::FrictionMep(500.0, g, 3000.0) / (500.0 * 0.04 / swept) - 1.0) < 1e-14);
    g.pin_offset = 0.01;  // (L + r)^2 - e^2 = 0.0323, (L - r)^2 - e^2 = 0.0099
    const double stroke = std::sqrt(0.0323) - std::sqrt(0.0099);
    QVERIFY(std::abs(io::FrictionMep(500.0, g, 3000.0) /
                         (500.0 * 0.04 / (std::numbers::pi * 0.0016 * stroke)) -
                     1.0) < 1e-13);
    io::RunKpis kpis;
    kpis.skirt = io::JointKpis{};
    kpis.skirt->mean_fpl = 300.0;
    kpis.big_end = io::JointKpis{};
    kpis.big_end->mean_fpl = 100.0;
    io::AddFrictionMep(&kpis, g, 3000.0);
    QCOMPARE(*kpis.skirt->fmep, io::FrictionMep(300.0, g, 3000.0));
    QVERIFY(std::abs(*kpis.skirt->fmep_share - 0.75) < 1e-15);
    QVERIFY(std::abs(*kpis.big_end->fmep_share - 0.25) < 1e-15);
    kpis.big_end->mean_fpl.reset();  // a joint without friction power: no FMEP, the other 100 %
    kpis.big_end->fmep.reset();
    kpis.big_end->fmep_share.reset();
    io::AddFrictionMep(&kpis, g, 3000.0);
    QVERIFY(!kpis.big_end->fmep);
    QCOMPARE(*kpis.skirt->fmep_share, 1.0);
  }
};

QTEST_GUILESS_MAIN(TestRunKpis)
#include "test_run_kpis.moc"
