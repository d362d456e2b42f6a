// The discretisation-error estimate of a run against the true error of the whole coupled cycle:
// the default case, Skirt-LBRBE, at 6000 and 2000 rpm on 1x, 2x and 4x meshes (1x = skirt
// 12 + 2 + 12 x 16, big end 50 x 5 graded 8:1 / 4:1). The "true" error of each run is its
// distance to the Richardson extrapolation of the 2x and 4x runs at the order observed over the
// three meshes — data the estimate never sees for the 1x and 2x runs (it uses only the run and
// its own coarse companion). Each headline estimate must be within a factor of 2 of the true
// error, unless both are below 0.25 % of the figure (the integrator's tolerance noise;
// docs/validation/errors.md). Exception, measured and documented there: the peak pressures on
// the 1x meshes (coarser than the default case's), whose companion (big end 25 x 3) is not in
// the asymptotic range — the nodal peak of a spike a few elements wide jumps with the node
// positions; there the estimate overstates the error (up to 2.5x on the big end). Also: the
// companion's meshes and tolerances, the figures' definitions against the samples, a minimum film
// taken from the extrapolated curve, and the estimate off / unavailable.
#include <QtTest>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>

#include "core/engine/error_estimate.hpp"
#include "core/engine/piston_slap.hpp"
#include "core/engine/run_job.hpp"
#include "core/io/case_file.hpp"

using namespace filmdyn;

namespace {

engine::RunConfig Config(double rpm, int multiple) {
  io::LoadedCase loaded = io::LoadCase({});
  engine::EngineCase& c = loaded.value;
  c.skirt.mesh_thrust = c.skirt.mesh_anti = 12 * multiple;
  c.skirt.mesh_relief = 2 * multiple;
  c.skirt.mesh_axial = 16 * multiple;
  c.big_end.mesh_theta = 50 * multiple;
  c.big_end.mesh_z = 5 * multiple;
  c.big_end.mesh_theta_grading = 8.0;
  c.big_end.mesh_z_grading = 4.0;
  return engine::MakeRunConfig(c, engine::Model::kSkirtLbrbe, rpm,
                               io::PressureCurveForSpeed(loaded, rpm));
}

std::map<std::string, double> Values(const std::vector<engine::HeadlineFigure>& figures) {
  std::map<std::string, double> v;
  for (const auto& f : figures) v[f.key] = f.value;
  return v;
}

// The estimate's figure with this key (a test failure if there is none).
const engine::FigureError& FigureOf(const engine::ErrorEstimate& e, const std::string& key) {
  for (const auto& f : e.figures)
    if (f.figure.key == key) return f;
  throw std::runtime_error("no figure " + key);
}

}  // namespace

class TestErrorEstimate : public QObject {
  Q_OBJECT
 private slots:
  void companionHalvesTheMeshesAndKeepsTheTolerances() {
    engine::EngineCase c = io::LoadCase({}).value;
    c.skirt.mesh_thrust = 15;
    c.skirt.mesh_relief = 2;
    c.skirt.mesh_anti = 15;
    c.skirt.mesh_axial = 20;
    c.big_end.mesh_theta = 100;
    c.big_end.mesh_z = 10;
    c.skirt.model = c.big_end.model = engine::JointModel::kLubricated;
    const engine::CoarseCompanion k = engine::MakeCoarseCompanion(c);
    QCOMPARE(k.engine_case.skirt.mesh_thrust, 8);  // round(7.5)
    QCOMPARE(k.engine_case.skirt.mesh_relief, 1);
    QCOMPARE(k.engine_case.skirt.mesh_axial, 10);
    QCOMPARE(k.engine_case.big_end.mesh_theta, 50);
    QCOMPARE(k.engine_case.big_end.mesh_z, 5);
    QCOMPARE(k.engine_case.big_end.mesh_theta_grading, c.big_end.mesh_theta_grading);
    QCOMPARE(k.big_end_ratio, 2.0);
    QCOMPARE(k.skirt_ratio, std::sqrt(32.0 * 20.0 / (17.0 * 10.0)));
    QCOMPARE(k.tolerance_factor, 1.0);  // the run's own tolerances
    QCOMPARE(k.engine_case.solver.relative_tolerance, c.solver.relative_tolerance);
    QCOMPARE(k.engine_case.solver.position_tolerance, c.solver.position_tolerance);
    QCOMPARE(k.engine_case.solver.error_estimate, 0);
    // Counts at their minimum stay there.
    c.big_end.mesh_theta = 8;
    c.skirt.mesh_relief = 1;
    const engine::CoarseCompanion m = engine::MakeCoarseCompanion(c);
    QCOMPARE(m.engine_case.big_end.mesh_theta, 8);
    QCOMPARE(m.engine_case.skirt.mesh_relief, 1);
  }

  // A starved skirt's inlet takes the liner's film half a cell late (first order): its figures
  // are estimated at order 1, not 2, so that the estimate covers what the meshes show (friction
  // and oil at order 1.1, the film at 1.6-2, docs/validation/errors.md, section 6). The big
  // end's figures keep their own order.
  void starvedSkirtFiguresAreEstimatedAtFirstOrder() {
    engine::EngineCase c = io::LoadCase({}).value;
    c.skirt.model = c.big_end.model = engine::JointModel::kLubricated;
    QCOMPARE(engine::MakeCoarseCompanion(c).skirt_max_order, 2.0);
    c.skirt.cavitation = lubrication::CavitationModel::kJfo;
    c.skirt.supply = lubrication::SkirtSupply::kStarved;
    const engine::CoarseCompanion companion = engine::MakeCoarseCompanion(c);
    QCOMPARE(companion.skirt_max_order, 1.0);
    std::vector<engine::CrankTrainSample> samples(4);
    for (int k = 0; k < 4; ++k) {
      samples[k].crank_angle = k * M_PI;  // a whole cycle: 4 samples 180 °CA apart
      samples[k].skirt.present = samples[k].bearing.present = true;
      samples[k].skirt.moft = 3e-6 + 1e-7 * k;
      samples[k].skirt.fpl = 16.0;
      samples[k].bearing.moft = 1e-6;
      samples[k].bearing.eps = 0.9;
      samples[k].bearing.fpl = 100.0;
    }
    auto coarse = samples;
    for (auto& s : coarse) {
      s.skirt.moft -= 0.8e-6;
      s.skirt.fpl = 17.0;
      s.bearing.moft = 0.7e-6;
    }
    const engine::ErrorEstimate e = engine::EstimateErrors(samples, coarse, companion);
    QCOMPARE(e.status, std::string("estimated"));
    const double r = companion.skirt_ratio;
    const engine::FigureError& film = FigureOf(e, "skirt_moft_min[m]");
    QCOMPARE(film.figure.order, 1.0);  // what summary.json reports
    QVERIFY(std::abs(film.error - 0.8e-6 / (r - 1.0)) < 1e-15);
    const engine::FigureError& friction = FigureOf(e, "skirt_fpl_mean[W]");
    QCOMPARE(friction.figure.order, 1.0);
    QVERIFY(std::abs(friction.error - (-1.0 / (r - 1.0))) < 1e-12);
    const engine::FigureError& bearing = FigureOf(e, "bearing_moft_min[m]");
    QCOMPARE(bearing.figure.order, 2.0);
    QVERIFY(std::abs(bearing.error - 0.3e-6 / (std::pow(companion.big_end_ratio, 2.0) - 1.0)) <
            1e-15);
  }

  // A mass-conserving big end fed through holes converged below second order from the default
  // mesh (2000 rpm, crank-pin hole: minimum film and friction at observed orders 0.7-1.7, an
  // order-2 estimate gave half the film's true error): its figures are estimated at order 1. A
  // Reynolds big end with the same holes, and a JFO big end fed only at its film-start line
  // (order 2.2 at 6000 rpm), keep order 2; the skirt's figures are not affected.
  void holeFedMassConservingBigEndIsEstimatedAtFirstOrder() {
    engine::EngineCase c = io::LoadCase({}).value;
    c.skirt.model = c.big_end.model = engine::JointModel::kLubricated;
    c.big_end.supply = lubrication::OilFeedKind::kPinHoles;
    QCOMPARE(engine::MakeCoarseCompanion(c).big_end_max_order, 2.0);  // Reynolds
    c.big_end.cavitation = lubrication::CavitationModel::kJfo;
    c.big_end.supply = lubrication::OilFeedKind::kLineOfCentres;
    QCOMPARE(engine::MakeCoarseCompanion(c).big_end_max_order, 2.0);
    c.big_end.supply = lubrication::OilFeedKind::kGroove;
    QCOMPARE(engine::MakeCoarseCompanion(c).big_end_max_order, 2.0);
    for (auto kind : {lubrication::OilFeedKind::kShellHoles, lubrication::OilFeedKind::kPinHoles,
                      lubrication::OilFeedKind::kPinHolesAndGroove}) {
      c.big_end.supply = kind;
      QCOMPARE(engine::MakeCoarseCompanion(c).big_end_max_order, 1.0);
    }
    const engine::CoarseCompanion companion = engine::MakeCoarseCompanion(c);
    QCOMPARE(companion.skirt_max_order, 2.0);
    std::vector<engine::CrankTrainSample> samples(4);
    for (int k = 0; k < 4; ++k) {
      samples[k].crank_angle = k * M_PI;  // a whole cycle: 4 samples 180 °CA apart
      samples[k].skirt.present = samples[k].bearing.present = true;
      samples[k].skirt.moft = 3e-6;
      samples[k].skirt.fpl = 16.0;
      samples[k].bearing.moft = 1e-6 + 1e-7 * k;
      samples[k].bearing.eps = 0.9;
      samples[k].bearing.fpl = 28.0;
    }
    auto coarse = samples;
    for (auto& s : coarse) {
      s.skirt.moft = 2.9e-6;
      s.bearing.moft -= 0.1e-6;
      s.bearing.fpl = 26.0;
    }
    const engine::ErrorEstimate e = engine::EstimateErrors(samples, coarse, companion);
    QCOMPARE(e.status, std::string("estimated"));
    const double r = companion.big_end_ratio;
    const engine::FigureError& film = FigureOf(e, "bearing_moft_min[m]");
    QCOMPARE(film.figure.order, 1.0);  // what summary.json reports
    QVERIFY(std::abs(film.error - 0.1e-6 / (r - 1.0)) < 1e-15);
    const engine::FigureError& friction = FigureOf(e, "bearing_fpl_mean[W]");
    QCOMPARE(friction.figure.order, 1.0);
    QVERIFY(std::abs(friction.error - 2.0 / (r - 1.0)) < 1e-12);
    const engine::FigureError& skirt = FigureOf(e, "skirt_moft_min[m]");
    QCOMPARE(skirt.figure.order, 2.0);
    QVERIFY(std::abs(skirt.error - 0.1e-6 / (std::pow(companion.skirt_ratio, 2.0) - 1.0)) < 1e-15);
  }

  // A film's minimum is the minimum of the curve the two runs extrapolate to, sample by sample,
  // not the extrapolation of the two runs' own minima: where the meshes put the minimum at
  // different places in the cycle, the finer one's trend is what counts. Two dips: at A the fine
  // film 1.00 µm, the coarse 0.96 µm (the runs' own minima); at B 1.05 µm, the coarse 1.35 µm —
  // thinning fast with the mesh. At order 2 and r = 2, A extrapolates to 1.00 + 0.04/3 µm, B to
  // 1.05 − 0.30/3 = 0.95 µm: the converged minimum is B's, 5 % below the run's.
  void extremesAreThoseOfTheExtrapolatedCurve() {
    constexpr int n = 72, a = 20, b = 50;
    constexpr double cycle = 4.0 * std::numbers::pi;
    std::vector<engine::CrankTrainSample> fine(n), coarse(n);
    for (int k = 0; k < n; ++k) {
      for (auto* s : {&fine[k], &coarse[k]}) {
        s->bearing.present = true;
        s->bearing.moft = 2e-6;
        s->bearing.eps = 0.9;
        s->bearing.fpl = 50.0;
      }
      fine[k].crank_angle = 3 * cycle + k * cycle / n;    // the runs reach their periodic
      coarse[k].crank_angle = 2 * cycle + k * cycle / n;  // states after different cycles
    }
    fine[a].bearing.moft = 1.00e-6;
    coarse[a].bearing.moft = 0.96e-6;
    fine[b].bearing.moft = 1.05e-6;
    coarse[b].bearing.moft = 1.35e-6;
    fine[b].bearing.eps = 0.95;  // the eccentricity's maximum where both have it: as before
    coarse[b].bearing.eps = 0.93;
    engine::CoarseCompanion companion;
    companion.big_end_ratio = 2.0;
    auto find = [](const engine::ErrorEstimate& e,
                   const std::string& key) -> const engine::FigureError& {
      for (const auto& f : e.figures)
        if (f.figure.key == key) return f;
      throw std::runtime_error("no figure " + key);
    };
    const engine::ErrorEstimate e = engine::EstimateErrors(fine, coarse, companion);
    const engine::FigureError& moft = find(e, "bearing_moft_min[m]");
    QCOMPARE(moft.figure.value, 1.00e-6);
    QCOMPARE(moft.coarse_value, 0.96e-6);
    QVERIFY(std::abs(moft.error - (0.95e-6 - 1.00e-6)) < 1e-15);
    QVERIFY(std::abs(moft.relative - 0.05) < 1e-9);
    QVERIFY(moft.crank_angle && moft.extrapolated_crank_angle);
    QCOMPARE(engine::CycleCrankAngleDeg(*moft.crank_angle), 200.0);  // sample 20 of 72
    QCOMPARE(engine::CycleCrankAngleDeg(*moft.extrapolated_crank_angle), 500.0);
    QVERIFY(moft.extreme_elsewhere);
    QVERIFY2(
        e.Summary().find("the meshes disagree on where the min big-end MOFT lies: this run "
                         "has it at 200 °CA, the extrapolation at 500 °CA") != std::string::npos,
        e.Summary().c_str());
    const engine::FigureError& eps = find(e, "bearing_eps_max[-]");
    QVERIFY(std::abs(eps.error - 0.02 / 3.0) < 1e-12);
    QVERIFY(eps.crank_angle && *eps.crank_angle == fine[b].crank_angle);
    QVERIFY(!eps.extreme_elsewhere);
    QVERIFY(!find(e, "bearing_fpl_mean[W]").crank_angle);  // a mean: no curve's extreme
    // A largest magnitude: that of the signed curve extrapolated (here F_x = −5000 N against
    // −4900 N on the coarse mesh at sample a: −5033.3 N, so |F_x| 5000 → 5033.3 N; a larger
    // coarse value elsewhere that the fine mesh lowers does not count).
    auto fine_f = fine, coarse_f = coarse;
    fine_f[a].bearing.force_on_rod = {-5000.0, 0.0};
    coarse_f[a].bearing.force_on_rod = {-4900.0, 0.0};
    fine_f[b].bearing.force_on_rod = {4950.0, 0.0};
    coarse_f[b].bearing.force_on_rod = {5100.0, 0.0};
    const engine::FigureError& fx =
        find(engine::EstimateErrors(fine_f, coarse_f, companion), "bearing_force_x_max_abs[N]");
    QCOMPARE(fx.figure.value, 5000.0);
    QVERIFY(std::abs(fx.error - 100.0 / 3.0) < 1e-9);
    QVERIFY(fx.crank_angle && *fx.crank_angle == fine[a].crank_angle);
    QVERIFY(!fx.extreme_elsewhere);
    // B thinning less with the mesh (to 1.02 µm extrapolated): A's 1.0133 µm stays the minimum.
    auto milder = coarse;
    milder[b].bearing.moft = 1.14e-6;
    const engine::FigureError& a_again =
        find(engine::EstimateErrors(fine, milder, companion), "bearing_moft_min[m]");
    QVERIFY(std::abs(a_again.error - 0.04e-6 / 3.0) < 1e-15);
    QVERIFY(!a_again.extreme_elsewhere);
    // Samples at other crank angles (another output step): the runs' own minima, as before.
    auto shifted = coarse;
    for (auto& s : shifted) s.crank_angle += 0.5 * cycle / n;
    const engine::FigureError& own =
        find(engine::EstimateErrors(fine, shifted, companion), "bearing_moft_min[m]");
    QVERIFY(std::abs(own.error - 0.04e-6 / 3.0) < 1e-15);
    QVERIFY(!own.crank_angle && !own.extrapolated_crank_angle && !own.extreme_elsewhere);
    // None of these companions lies far from the run (4 % at most): no "rough" note.
    for (const auto& f : e.figures) QVERIFY2(!f.far_companion, f.figure.key.c_str());
    QVERIFY2(e.Summary().find("rough") == std::string::npos, e.Summary().c_str());
    // A companion whose friction power lies 40 % from the run's (70 against 50 W): its
    // estimate is rough, and the summary says so, naming the figure and the distance; the
    // film's companion, 4 % away, is not.
    auto far = coarse;
    for (auto& s : far) s.bearing.fpl = 70.0;
    const engine::ErrorEstimate rough = engine::EstimateErrors(fine, far, companion);
    QVERIFY(find(rough, "bearing_fpl_mean[W]").far_companion);
    QVERIFY(!find(rough, "bearing_moft_min[m]").far_companion);
    QVERIFY2(rough.Summary().find("the companion run on the coarser mesh lies far from this run "
                                  "in the mean big-end FPL (40 %): outside the range") !=
                 std::string::npos,
             rough.Summary().c_str());
    // Just inside the bound (24 %: 62 W against 50 W): not far.
    for (auto& s : far) s.bearing.fpl = 62.0;
    QVERIFY(
        !find(engine::EstimateErrors(fine, far, companion), "bearing_fpl_mean[W]").far_companion);
  }

  // Every figure above the threshold is named, largest first, with the meshes of their joints
  // to refine in all directions together (it named only the largest, and its mesh's fields as
  // if either one would do).
  void everyFigureAboveTheThresholdIsNamed() {
    constexpr int n = 72;
    constexpr double cycle = 4.0 * std::numbers::pi;
    std::vector<engine::CrankTrainSample> fine(n), coarse(n);
    for (int k = 0; k < n; ++k) {
      for (auto* s : {&fine[k], &coarse[k]}) {
        s->bearing.present = s->skirt.present = true;
        s->bearing.moft = 2e-6;
        s->bearing.eps = 0.9;
        s->skirt.moft = 10e-6;
        s->bearing.fpl = s->skirt.fpl = 50.0;
        s->crank_angle = 2 * cycle + k * cycle / n;
      }
    }
    fine[20].bearing.moft = 1.00e-6;  // 4 % → 1.3 % estimated (order 2, ratio 2)
    coarse[20].bearing.moft = 1.04e-6;
    fine[30].skirt.moft = 5.0e-6;  // 30 % → 10 % estimated
    coarse[30].skirt.moft = 6.5e-6;
    engine::CoarseCompanion companion;
    companion.big_end_ratio = companion.skirt_ratio = 2.0;
    const std::string text = engine::EstimateErrors(fine, coarse, companion).Summary();
    const auto skirt = text.find("10 % in the min skirt MOFT");
    const auto big_end = text.find("1.3 % in the min big-end MOFT");
    QVERIFY2(skirt != std::string::npos && big_end != std::string::npos && skirt < big_end,
             text.c_str());
    QVERIFY2(text.find("refine the skirt's mesh (skirt.mesh_thrust, mesh_anti and mesh_axial) "
                       "and the big end's mesh (big_end.mesh_theta and mesh_z) in all "
                       "directions together") != std::string::npos,
             text.c_str());
    // The big end's figure alone above: its mesh alone.
    coarse[30].skirt.moft = 5.0e-6;
    const std::string one = engine::EstimateErrors(fine, coarse, companion).Summary();
    QVERIFY2(one.find("skirt") == std::string::npos &&
                 one.find("big_end.mesh_theta") != std::string::npos,
             one.c_str());
  }

  void headlineFiguresAreTheirDefinitions() {
    std::vector<engine::CrankTrainSample> samples(4);
    const double moft[] = {3e-6, 1e-6, 2e-6, 4e-6}, fpl[] = {10, 20, 30, 60};
    const double fx[] = {-3000, 1000, 2000, -500}, fy[] = {2e4, -2.5e4, 1e3, 0};
    for (int k = 0; k < 4; ++k) {
      samples[k].crank_angle = k * M_PI;  // a whole cycle: 4 samples 180 °CA apart
      samples[k].bearing.present = true;
      samples[k].bearing.moft = moft[k];
      samples[k].bearing.eps = 0.5 + 0.1 * k;
      samples[k].bearing.max_pressure = 1e6 * (k == 2 ? 9 : 1);
      samples[k].bearing.fpl = fpl[k];
      samples[k].bearing.force_on_rod = {fx[k], fy[k]};
    }
    const auto v = Values(engine::HeadlineFigures(samples));
    QCOMPARE(v.size(), std::size_t(6));  // no skirt figures without a skirt
    QCOMPARE(v.at("bearing_moft_min[m]"), 1e-6);
    QCOMPARE(v.at("bearing_eps_max[-]"), 0.8);
    QCOMPARE(v.at("bearing_peak_pressure[Pa]"), 9e6);
    QCOMPARE(v.at("bearing_fpl_mean[W]"), 30.0);
    // The force components' largest magnitudes, whichever their sign.
    QCOMPARE(v.at("bearing_force_x_max_abs[N]"), 3000.0);
    QCOMPARE(v.at("bearing_force_y_max_abs[N]"), 2.5e4);
    // Part of a cycle (a run stopped in its run-in): its extremes, but no cycle mean.
    auto part = samples;
    for (int k = 0; k < 4; ++k) part[k].crank_angle = k * 0.25 * M_PI;
    const auto in_part = Values(engine::HeadlineFigures(part));
    QCOMPARE(in_part.size(), std::size_t(5));
    QVERIFY(!in_part.count("bearing_fpl_mean[W]"));
    QCOMPARE(in_part.at("bearing_moft_min[m]"), 1e-6);
    // Richardson: converged ≈ f + (f − f_coarse) / (r² − 1).
    auto coarse = samples;
    for (auto& s : coarse) s.bearing.moft *= 0.7;
    engine::CoarseCompanion companion;
    companion.big_end_ratio = 2.0;
    const engine::ErrorEstimate e = engine::EstimateErrors(samples, coarse, companion);
    QCOMPARE(e.status, std::string("estimated"));
    const auto& moft_error = e.figures.at(0);
    QCOMPARE(moft_error.figure.key, std::string("bearing_moft_min[m]"));
    const double p = moft_error.figure.order;
    QVERIFY(p >= 1.0 && p <= 2.0);
    QVERIFY(std::abs(moft_error.error - 0.3e-6 / (std::pow(2.0, p) - 1.0)) < 1e-15);
    QVERIFY(std::abs(moft_error.relative - 0.3 / (std::pow(2.0, p) - 1.0)) < 1e-12);
    QCOMPARE(e.worst_label, std::string("min big-end MOFT"));
    QVERIFY(e.Warn());
    QVERIFY2(QString::fromStdString(e.Summary())
                 .contains(QString("%1 % in the min big-end MOFT")
                               .arg(100 * moft_error.relative, 0, 'g', 2)),
             e.Summary().c_str());
  }

  // The largest piston-slap energy is a skirt headline figure when its inputs are given: the
  // KPIs' value (SlapOf), none without them; a run whose companion has no change of side keeps
  // it out of the estimate instead of making the estimate unavailable.
  void slapEnergyIsAHeadlineFigureWithItsInputs() {
    constexpr int n = 8;
    const double force[n] = {50, 40, -30, -60, 20, 70, -10, -40};
    std::vector<engine::CrankTrainSample> samples(n);
    for (int k = 0; k < n; ++k) {
      samples[k].crank_angle = k * 0.5 * M_PI;  // a whole cycle: 8 samples 90 °CA apart
      samples[k].time = k * 1e-3;
      samples[k].skirt.present = true;
      samples[k].skirt.moft = 5e-6;
      samples[k].skirt.normal_force = force[k];
      samples[k].piston_com_lateral_velocity = 0.01 * (k + 1);
      samples[k].piston_tilt_rate = 0.5;
    }
    const std::vector<engine::MotionSample> motion;  // the output samples' own motion
    const engine::SlapInputs inputs{&motion, 0.4, 2e-4};
    const engine::PistonSlap slap = engine::SlapOf(samples, motion, 0.4, 2e-4, true);
    QVERIFY(slap.energy_max && slap.events.size() == 4);
    const auto with = Values(engine::HeadlineFigures(samples, inputs));
    QCOMPARE(with.at("slap_energy_max[J]"), *slap.energy_max);
    QVERIFY(!Values(engine::HeadlineFigures(samples)).count("slap_energy_max[J]"));
    // The companion's piston never changes side: no slap figure to compare, the rest estimated.
    auto one_side = samples;
    for (auto& s : one_side) s.skirt.normal_force = std::abs(s.skirt.normal_force);
    engine::CoarseCompanion companion;
    const engine::ErrorEstimate e =
        engine::EstimateErrors(samples, one_side, companion, inputs, inputs);
    QCOMPARE(e.status, std::string("estimated"));
    QVERIFY(std::none_of(e.figures.begin(), e.figures.end(), [](const engine::FigureError& f) {
      return f.figure.key == "slap_energy_max[J]";
    }));
    QCOMPARE(engine::HeadlineDisplayUnit("slap_energy_max[J]").unit, std::string("mJ"));
  }

  // A mass-conserving film's oil per cycle is its account's: a film booking 2e-6 m³/s in and
  // 1.5e-6 m³/s out at steps that end after each output sample takes in 2e-6 × 8 × 1e-4 m³ over
  // the 8 samples' span (a cycle, 90 °CA apart), whatever its sampled flows say; a film without
  // an account has none, and samples short of a cycle give no oil "per cycle".
  void oilPerCycleIsTheAccounts() {
    std::vector<engine::CrankTrainSample> samples(8);
    for (int k = 0; k < 8; ++k) {
      engine::CrankTrainSample& s = samples[k];
      s.time = 0.05 + 1e-4 * k;
      s.crank_angle = 0.5 * std::numbers::pi * k;
      s.bearing.present = true;
      s.bearing.supply_flow = k == 3 ? 1.0 : 0.0;       // a sampled spike the account does not see
      const double step_end = s.time + 3e-6 * (k % 3);  // the accepted step past the sample
      s.bearing.oil.Book(step_end, step_end - 0.04, 2e-6, 1.5e-6, 0.0, 0.0, 0.0);
    }
    const std::optional<engine::OilPerCycle> oil = engine::AccountedOil(samples, true);
    QVERIFY(oil);
    QVERIFY(std::abs(oil->in / (2e-6 * 8e-4) - 1.0) < 1e-12);
    QVERIFY(std::abs(oil->out / (1.5e-6 * 8e-4) - 1.0) < 1e-12);
    QVERIFY(!engine::AccountedOil(samples, false));  // no skirt account
    auto half = samples;                             // the same samples 45 °CA apart: half a cycle
    for (int k = 0; k < 8; ++k) half[k].crank_angle = 0.25 * std::numbers::pi * k;
    QVERIFY(!engine::SamplesSpanACycle(half) && !engine::AccountedOil(half, true));
    QVERIFY(!Values(engine::HeadlineFigures(half)).count("bearing_oil_per_cycle[m^3]"));
    const auto v = Values(engine::HeadlineFigures(samples));
    QCOMPARE(v.at("bearing_oil_per_cycle[m^3]"), oil->in);
    QCOMPARE(engine::HeadlineFigureFor("bearing_oil_per_cycle[m^3]", 1.0).label,
             std::string("big-end oil per cycle"));
    QCOMPARE(engine::HeadlineDisplayUnit("bearing_oil_per_cycle[m^3]").unit, std::string("mm³"));
    // Its estimate says that mass-conserving films converge slowly at low speed.
    engine::CoarseCompanion companion;
    companion.big_end_ratio = 2.0;
    const engine::ErrorEstimate e = engine::EstimateErrors(samples, samples, companion);
    QVERIFY2(e.Summary().find(engine::kMassConservingNote) != std::string::npos,
             e.Summary().c_str());
    for (auto& s : samples) s.bearing.oil = {};  // a Reynolds film keeps no account
    QVERIFY(engine::EstimateErrors(samples, samples, companion)
                .Summary()
                .find(engine::kMassConservingNote) == std::string::npos);
    QVERIFY(!engine::AccountedOil(samples, true));
    QVERIFY(!Values(engine::HeadlineFigures(samples)).count("bearing_oil_per_cycle[m^3]"));
  }

  // A peak film pressure the output samples do not resolve in time: a Gaussian peak whose width
  // at half height spans w output intervals is down to 2^(-4/w²) one interval away, so its ratio
  // to the larger neighbour is 2^(4/w²): resolved at w = 4 (1.19), not at w = 2 (2). Neighbours
  // wrap round a whole cycle; the steps' peaks between samples flag a spike the samples miss;
  // the estimate leaves an unresolved peak out of its worst figure and says so.
  void peaksBetweenOutputSamplesAreFlagged() {
    const int n = 40;
    auto cycle = [&](double width, int centre) {
      std::vector<engine::CrankTrainSample> samples(n);
      for (int k = 0; k < n; ++k) {
        const int d = std::min(std::abs(k - centre), n - std::abs(k - centre));  // periodic
        samples[k].bearing.present = true;
        samples[k].bearing.moft = 1e-6;
        samples[k].bearing.max_pressure = 1e8 * std::pow(2.0, -4.0 * d * d / (width * width));
      }
      return samples;
    };
    for (const double width : {4.0, 2.0}) {
      const auto peaks = engine::SampledPeaks(cycle(width, 10), true);
      QCOMPARE(peaks.size(), std::size_t(1));  // the big end's; no skirt
      const engine::SampledPeak& p = peaks[0];
      QCOMPARE(p.figure.key, std::string("bearing_peak_pressure[Pa]"));
      QCOMPARE(p.index, std::size_t(10));
      QCOMPARE(p.figure.value, 1e8);
      QVERIFY(std::abs(p.Ratio() - std::pow(2.0, 4.0 / (width * width))) < 1e-12);
      QVERIFY(std::isnan(p.step_peak));
      QCOMPARE(p.StepRatio(), 1.0);
      QCOMPARE(p.Unresolved(), width < 2.6);
    }
    // At the first sample: the last one is beside it only in a whole cycle.
    const auto at_start = cycle(2.0, 0);
    const engine::SampledPeak whole = engine::SampledPeaks(at_start, true).at(0);
    QCOMPARE(whole.before, at_start.back().bearing.max_pressure);
    QCOMPARE(whole.after, at_start[1].bearing.max_pressure);
    const engine::SampledPeak part = engine::SampledPeaks(at_start, false).at(0);
    QVERIFY(std::isnan(part.before));
    QCOMPARE(part.Ratio(), 2.0);
    // A spike the samples miss: a smooth sampled peak, the steps between samples 24 and 25 at
    // three times its height.
    auto missed = cycle(6.0, 10);
    for (auto& s : missed) s.bearing.step_peak_pressure = 0.9 * s.bearing.max_pressure;
    missed[25].bearing.step_peak_pressure = 3e8;
    const engine::SampledPeak m = engine::SampledPeaks(missed, true).at(0);
    QVERIFY(m.Ratio() < engine::kUnresolvedPeakRatio);
    QCOMPARE(m.step_peak, 3e8);
    QCOMPARE(m.step_index, std::size_t(25));
    QCOMPARE(m.StepRatio(), 3.0);
    QVERIFY(m.Unresolved());
    // The estimate: MOFT off by 1 %, the unresolved peak by 50 % — the worst is the MOFT.
    const auto fine = cycle(2.0, 10);
    auto coarse = fine;
    for (auto& s : coarse) {
      s.bearing.moft *= 0.97;
      s.bearing.max_pressure *= 0.5;
    }
    engine::CoarseCompanion companion;
    companion.big_end_ratio = 2.0;
    const engine::ErrorEstimate e = engine::EstimateErrors(fine, coarse, companion);
    QCOMPARE(e.status, std::string("estimated"));
    for (const engine::FigureError& f : e.figures) {
      QCOMPARE(f.resolved_in_time, f.figure.key != "bearing_peak_pressure[Pa]");
    }
    QCOMPARE(e.worst_label, std::string("min big-end MOFT"));
    QVERIFY(std::abs(e.worst_relative - 0.01) < 1e-9);  // 0.03 / 3 of a MOFT of 1
    QVERIFY2(QString::fromStdString(e.Summary())
                 .contains("peak big-end film pressure not estimated (a spike between output "
                           "samples)"),
             e.Summary().c_str());
    // Resolved in both runs: estimated like any other figure.
    auto smooth = cycle(6.0, 10), smooth_coarse = smooth;
    for (auto& s : smooth_coarse) s.bearing.max_pressure *= 0.5;
    const engine::ErrorEstimate r = engine::EstimateErrors(smooth, smooth_coarse, companion);
    QCOMPARE(r.worst_label, std::string("peak big-end film pressure"));
    QVERIFY(std::all_of(r.figures.begin(), r.figures.end(),
                        [](const engine::FigureError& f) { return f.resolved_in_time; }));
    // A force at an impact (a mass-conserving big end's): its largest magnitude, −60 kN at one
    // sample beside 1 and 14 kN, is a spike — not estimated, not the worst, not in the note on
    // where the meshes put extremes; a force that rises over several samples is estimated.
    auto impact = smooth, impact_coarse = smooth;
    for (int k = 0; k < n; ++k) {
      const double load = 1e4 * std::cos(2.0 * M_PI * k / n);
      impact[k].bearing.force_on_rod = {load, 2e4};
      impact_coarse[k].bearing.force_on_rod = {load, 2e4 * 1.001};
    }
    impact[25].bearing.force_on_rod.x() = -6e4;
    impact[24].bearing.force_on_rod.x() = -1.4e4;
    impact_coarse[5].bearing.force_on_rod.x() = 1.5e5;  // the coarse run's impact elsewhere
    const engine::ErrorEstimate f = engine::EstimateErrors(impact, impact_coarse, companion);
    for (const engine::FigureError& x : f.figures) {
      QCOMPARE(x.resolved_in_time, x.figure.key != "bearing_force_x_max_abs[N]");
    }
    // The worst is F_y's 0.1 % / 3 (the film pressure and MOFT alike in both runs).
    QCOMPARE(f.worst_label, std::string("max big-end force |F_y|"));
    QVERIFY(std::abs(f.worst_relative - 0.001 / 3.0) < 1e-9);
    const std::string text = f.Summary();
    QVERIFY2(text.find("max big-end force |F_x| not estimated (a spike between output samples)") !=
                     std::string::npos &&
                 text.find("disagree") == std::string::npos,
             text.c_str());
  }

  // The scatter of the headline figures over a run's last cycles: which cycles, the extremes,
  // the sentence a warning carries.
  void scatterOverCyclesSpansTheLastCycles() {
    auto cycle = [](double moft, double fpl, double eps) {
      return std::vector<engine::HeadlineFigure>{
          engine::HeadlineFigureFor("bearing_moft_min[m]", moft),
          engine::HeadlineFigureFor("bearing_eps_max[-]", eps),
          engine::HeadlineFigureFor("bearing_fpl_mean[W]", fpl)};
    };
    std::vector<std::vector<engine::HeadlineFigure>> per_cycle = {cycle(9e-6, 300.0, 0.5)};
    QVERIFY(!engine::ScatterOverCycles(per_cycle, {}, true));  // nothing to compare with
    per_cycle.push_back(cycle(2.0e-6, 200.0, 0.9));
    auto s = engine::ScatterOverCycles(per_cycle, {}, true);
    QVERIFY(s);  // two cycles: both, the first included
    QCOMPARE(s->first_cycle, 1);
    QCOMPARE(s->last_cycle, 2);
    QCOMPARE(s->figures[0].min, 2.0e-6);
    QCOMPARE(s->figures[0].max, 9e-6);
    per_cycle.push_back(cycle(2.2e-6, 200.1, 0.9));
    s = engine::ScatterOverCycles(per_cycle, {}, true);
    QCOMPARE(s->first_cycle, 2);  // the start-up cycle left out once two others remain
    QCOMPARE(s->figures[0].min, 2.0e-6);
    QCOMPARE(s->figures[0].max, 2.2e-6);
    QCOMPARE(s->figures[0].figure.value, 2.2e-6);  // the reported (last) cycle's
    for (int c = 0; c < 5; ++c) per_cycle.push_back(cycle(2.1e-6 + 1e-8 * c, 200.0, 0.9));
    s = engine::ScatterOverCycles(per_cycle, {}, true);  // 8 cycles: the last 5
    QCOMPARE(s->first_cycle, 4);
    QCOMPARE(s->last_cycle, 8);
    QCOMPARE(s->figures[0].min, 2.1e-6);
    QCOMPARE(s->figures[0].max, 2.14e-6);
    QCOMPARE(s->figures[2].min, 200.0);  // cycle 3's 200.1 is outside the span
    QCOMPARE(s->figures[2].max, 200.0);
    QCOMPARE(s->figures[0].RelativeHalfSpread(), 0.02e-6 / 2.14e-6);
    // The sentence: figures that moved by more than ±0.1 %, largest first, in display units.
    QCOMPARE(s->Summary(),
             std::string("over cycles 4–8 the headline figures moved by up to ±0.93 % of the "
                         "reported values: min big-end MOFT 2.1–2.14 µm (±0.93 %)"));
    // Large spreads in whole percent, not with an exponent.
    std::vector<std::vector<engine::HeadlineFigure>> start = {cycle(9e-6, 300.0, 0.5),
                                                              cycle(1e-6, 200.0, 0.9)};
    QCOMPARE(engine::ScatterOverCycles(start, {}, true)->Summary(),
             std::string("over cycles 1–2 the headline figures moved by up to ±400 % of the "
                         "reported values: min big-end MOFT 1–9 µm (±400 %), mean big-end FPL "
                         "200–300 W (±25 %), max big-end eccentricity ratio 0.5–0.9 (±22 %)"));
    per_cycle.push_back(cycle(2.14e-6, 200.0, 0.9));
    per_cycle.push_back(cycle(2.14e-6, 200.0, 0.9));
    per_cycle.push_back(cycle(2.14e-6, 200.0, 0.9));
    per_cycle.push_back(cycle(2.14e-6, 200.0, 0.9));
    per_cycle.push_back(cycle(2.1405e-6, 200.0, 0.9));
    QCOMPARE(engine::ScatterOverCycles(per_cycle, {}, true)->Summary(),
             std::string("over cycles 9–13 the headline figures moved by less than ±0.1 % of "
                         "the reported values"));
    // A peak that is a spike between the reported cycle's output samples is not counted: its
    // sampled heights scatter by whatever the samples caught (here ±11 %).
    auto with_peak = [](double moft, double peak) {
      return std::vector<engine::HeadlineFigure>{
          engine::HeadlineFigureFor("bearing_moft_min[m]", moft),
          engine::HeadlineFigureFor("bearing_peak_pressure[Pa]", peak)};
    };
    std::vector<engine::CrankTrainSample> reported(40);
    for (int k = 0; k < 40; ++k) {
      reported[size_t(k)].bearing.present = true;
      reported[size_t(k)].bearing.moft = 1.4e-6;
      reported[size_t(k)].bearing.max_pressure = k == 20 ? 1.835e9 : 4e7;  // one sample of it
    }
    const std::vector<std::vector<engine::HeadlineFigure>> spiky = {with_peak(1.40e-6, 1.422e9),
                                                                    with_peak(1.42e-6, 1.835e9)};
    const auto spread = engine::ScatterOverCycles(spiky, reported, true);
    QVERIFY(spread->figures[0].resolved_in_time);
    QVERIFY(!spread->figures[1].resolved_in_time);
    QCOMPARE(spread->Summary(),
             std::string("over cycles 1–2 the headline figures moved by up to ±0.7 % of the "
                         "reported values: min big-end MOFT 1.4–1.42 µm (±0.7 %); not counted: "
                         "peak big-end film pressure 1422–1835 MPa (a spike between output "
                         "samples)"));
    // Resolved by its samples (a broad peak): counted like any other.
    for (int k = 17; k <= 23; ++k) reported[size_t(k)].bearing.max_pressure = 1.835e9 * 0.9;
    reported[20].bearing.max_pressure = 1.835e9;
    QVERIFY(engine::ScatterOverCycles(spiky, reported, true)->figures[1].resolved_in_time);
    // How the change per cycle fell: geometrically (×3.6 per cycle, 1.2 % → under 1 % in one
    // more cycle: 1.2 × 0.28 = 0.33), or not.
    QCOMPARE(engine::CycleChangeTrend({0.22}, 0.01), std::string());
    QCOMPARE(engine::CycleChangeTrend({0.22, 0.043, 0.012}, 0.01),
             std::string("the change after each cycle from cycle 2 on: 22, 4.3, 1.2 %, falling by "
                         "about ×3.6 per cycle: about 1 more cycle would reach the tolerance if "
                         "it keeps falling so (solver.max_cycles)"));
    // 5 % falling by ×2 per cycle: 2.5, 1.25, 0.625 — three more.
    QVERIFY(engine::CycleChangeTrend({0.1, 0.05}, 0.01).find("about 3 more cycles") !=
            std::string::npos);
    const std::string floor = engine::CycleChangeTrend({0.05, 0.03, 0.028}, 0.01);
    QVERIFY2(floor.find(", not falling (×0.93 of the cycle before)") != std::string::npos,
             floor.c_str());
    QVERIFY(floor.find("solver.relative_tolerance") != std::string::npos);
    // A diverging change: the list, no trend.
    QCOMPARE(engine::CycleChangeTrend({0.05, HUGE_VAL}, 0.01),
             std::string("the change after each cycle from cycle 2 on: 5, inf %"));
    const engine::DisplayUnit pa = engine::HeadlineDisplayUnit("skirt_peak_pressure[Pa]");
    QCOMPARE(pa.unit, std::string("MPa"));
    QCOMPARE(pa.scale, 1e-6);
    QCOMPARE(engine::HeadlineDisplayUnit("bearing_eps_max[-]").unit, std::string());
    QCOMPARE(engine::HeadlineDisplayUnit("skirt_fpl_mean[W]").unit, std::string("W"));
  }

  void offAndUnavailableSayWhy() {
    engine::RunConfig config = Config(6000, 1);
    config.engine_case.solver.error_estimate = 0;
    config.engine_case.solver.max_cycles = 1;
    config.engine_case.solver.run_in_angle = 0.0;
    const engine::RunResult off = engine::RunJob(config);
    QCOMPARE(off.error_estimate.status, std::string("off"));
    QVERIFY(!off.error_estimate.Warn());
    // The paper's 50 x 10 uniform big-end mesh: at half of it the journal touches the bearing
    // near firing, so the estimate is unavailable, which is a warning.
    config = Config(6000, 1);
    config.engine_case.big_end.mesh_theta = 24;
    config.engine_case.big_end.mesh_z = 4;
    config.engine_case.big_end.mesh_theta_grading = config.engine_case.big_end.mesh_z_grading = 1;
    const engine::RunResult r = engine::RunJob(config);
    QCOMPARE(r.error_estimate.status, std::string("unavailable"));
    QVERIFY(r.error_estimate.Warn());
    QVERIFY2(QString::fromStdString(r.error_estimate.message).contains("half the elements"),
             r.error_estimate.message.c_str());
  }

  // The real model where the meshes put the minimum film at different places: a mass-conserving
  // big end fed by a 4 mm crank-pin hole at 0.3 MPa, 2000 rpm, default meshes (Only-LBRBE). The
  // run has its minimum after firing (0.9285 µm at 392 °CA, the companion 0.8913 µm at 393 °CA);
  // finer meshes have it after the gas-exchange TDC, 0.830 and 0.775 µm on 200 x 20 and 400 x 20,
  // not yet converged — the default mesh 17 % above 400 x 20's film and some 20-25 % above the
  // limit (docs/validation/errors.md, section 6). Comparing the two runs' minima estimated +1.3 %,
  // the wrong sign; the extrapolated curve at order 2 found the thinner film near 50 °CA but only
  // half the error (about 11 %). At order 1 (a hole-fed mass-conserving big end) the estimate
  // must cover the 17 % without overstating the 20-25 % by more than about two, and put the
  // minimum around the gas-exchange TDC, not after firing.
  void crankPinFedMinimumFilmIsEstimatedWhereTheFinerMeshesHaveIt() {
    io::LoadedCase loaded = io::LoadCase({}, {"big_end.cavitation=jfo", "big_end.supply=pin_holes",
                                              "big_end.oil_feed_pressure=3e5"});
    const engine::RunResult r =
        engine::RunJob(engine::MakeRunConfig(loaded.value, engine::Model::kOnlyLbrbe, 2000.0,
                                             io::PressureCurveForSpeed(loaded, 2000.0)));
    QCOMPARE(engine::StatusName(r.status), std::string("completed"));
    QCOMPARE(r.error_estimate.status, std::string("estimated"));
    const engine::FigureError* moft = nullptr;
    for (const auto& f : r.error_estimate.figures)
      if (f.figure.key == "bearing_moft_min[m]") moft = &f;
    QVERIFY(moft && moft->crank_angle && moft->extrapolated_crank_angle);
    const double own = engine::CycleCrankAngleDeg(*moft->crank_angle);
    const double extrapolated = engine::CycleCrankAngleDeg(*moft->extrapolated_crank_angle);
    qInfo("min big-end MOFT %.4f µm at %.0f °CA (companion %.4f µm), estimate %+.2f %% at %.0f °CA",
          moft->figure.value * 1e6, own, moft->coarse_value * 1e6,
          100.0 * moft->error / moft->figure.value, extrapolated);
    QVERIFY2(own > 360.0 && own < 420.0, "the run's minimum after firing");
    QCOMPARE(moft->figure.order, 1.0);
    for (const auto& f : r.error_estimate.figures)  // its oil converged at 1.7-2.4: its own order
      if (f.figure.key == "bearing_oil_per_cycle[m^3]") QCOMPARE(f.figure.order, 1.6);
    QVERIFY2(extrapolated > 650.0 || extrapolated < 70.0,
             "the extrapolated minimum around the gas-exchange TDC");
    QVERIFY(moft->extreme_elsewhere);
    QVERIFY(moft->error < 0.0);
    QVERIFY2(moft->relative >= 0.17, "at least the default mesh's 17 % against 400 x 20");
    QVERIFY2(moft->relative <= 0.5, "not more than about twice the true 20-25 %");
    QVERIFY(r.error_estimate.Summary().find("the meshes disagree on where the min big-end MOFT "
                                            "lies") != std::string::npos);
  }

  void estimateIsWithinAFactorOfTwoOfTheTrueError() {
    QStringList failures;  // all of them, after the whole table is printed
    for (const double rpm : {6000.0, 2000.0}) {
      std::array<engine::RunResult, 3> runs;
      for (int level = 0; level < 3; ++level) {
        runs[level] = engine::RunJob(Config(rpm, 1 << level));
        QCOMPARE(engine::StatusName(runs[level].status), std::string("completed"));
        QCOMPARE(runs[level].error_estimate.status, std::string("estimated"));
        qInfo("%.0f rpm, %dx meshes: %.1f s (companion %.1f s), %s", rpm, 1 << level,
              runs[level].wall_time, runs[level].error_estimate.coarse_wall_time,
              runs[level].error_estimate.Summary().c_str());
      }
      // The run's own headline figures, the slap energy's included (summary.json's).
      const engine::CrankTrainGeometry& g = Config(rpm, 1).engine_case.geometry;
      const auto figures = [&](const engine::RunResult& r) {
        return Values(
            engine::HeadlineFigures(r.samples, {&r.motion, g.piston_mass, g.piston_inertia}));
      };
      const auto f1 = figures(runs[0]), f2 = figures(runs[1]), f4 = figures(runs[2]);
      QVERIFY(f4.count("slap_energy_max[J]") == 1);
      for (const auto& [key, v4] : f4) {
        const double d12 = f2.at(key) - f1.at(key), d24 = v4 - f2.at(key);
        // Observed order over the three meshes, kept to [1, 3] (2 when the differences do not
        // shrink monotonically).
        double p = 2.0;
        if (d12 * d24 > 0 && std::abs(d24) < std::abs(d12)) {
          p = std::clamp(std::log2(d12 / d24), 1.0, 3.0);
        }
        const double reference = v4 + d24 / (std::pow(2.0, p) - 1.0);
        for (int level = 0; level < 3; ++level) {
          const engine::FigureError* e = nullptr;
          for (const auto& fe : runs[level].error_estimate.figures) {
            if (fe.figure.key == key) e = &fe;
          }
          QVERIFY(e != nullptr);
          const double value = e->figure.value;
          const double truth = std::abs(reference - value), estimate = std::abs(e->error);
          const double floor = 2.5e-3 * std::abs(value);
          qInfo("  %-26s %dx: value %.6g, true error %+.3f %%, estimate %+.3f %% (order %.2f)",
                key.c_str(), 1 << level, value, 100 * (reference - value) / std::abs(value),
                100 * e->error / std::abs(value), p);
          const bool both_small = truth < floor && estimate < floor;
          const bool pre_asymptotic = level == 0 && key.find("peak_pressure") != std::string::npos;
          if (pre_asymptotic) continue;
          const bool within = estimate <= 2.0 * truth && estimate >= 0.5 * truth;
          if (!both_small && !within) {
            failures << QString("%1 rpm %2x %3: estimate %4, true %5")
                            .arg(rpm)
                            .arg(1 << level)
                            .arg(QString::fromStdString(key))
                            .arg(e->error)
                            .arg(reference - value);
          }
        }
      }
    }
    QVERIFY2(failures.isEmpty(), qPrintable(failures.join("; ")));
  }
};

QTEST_GUILESS_MAIN(TestErrorEstimate)
#include "test_error_estimate.moc"
