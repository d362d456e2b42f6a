// summary.json has one struct and one mapping: every field survives a round trip through the
// file, required keys and wrong types are named in the error, and a summary written by a real
// (ideal, short) run carries the run's figures.
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "core/io/case_file.hpp"
#include "core/io/results_writer.hpp"
#include "core/io/run_summary.hpp"

using namespace filmdyn;

namespace {

io::RunSummary Full() {
  io::RunSummary s{
      .filmdyn_version = "9.9.9",
      .case_name = "c",
      .model = "skirt-lbrbe",
      .rpm = 4500.5,
      .status = "not converged",
      .complete = false,
      .message = "cycle-to-cycle change 0.02 above 0.01",
      .cycles = 7,
      .reported_cycle = 6,
      .cycles_to_steady_state = 0,
      .cycle_to_cycle_change = 0.02,
      .cycle_to_cycle_worst_quantity = "bearing_moft",
      .cycle_to_cycle_changes = {0.22, 0.043, 0.02},
      .wall_time_s = 12.25,
      .max_constraint_violation = 3e-12,
      .extremes = {{"bearing_moft[m]", {1.1e-6, 2.5e-5}},
                   {"gas_force[N]", {-300.0, 41000.0}},
                   {"bigend_force_y[N]", {-1.1e4, 8.2e4, false, true}},
                   {"bigend_force_x[N]", {-8.5e4, 5.7e3, true, false}}},
      .mean_fpl_skirt_w = 659.75,
      .mean_fpl_bearing_w = std::nullopt,
      .solver = {"integrator", 5276, 12, 9000, 220, 12000, 300, 60000, 20.0, 30.0, 1e-4},
      .pressure_peak_pa = 6.1e6,
      .pressure_peak_crank_angle_deg = 372.0,
      .headline = {{"skirt_fpl_mean[W]", "mean skirt FPL", 659.75, false},
                   {"bearing_moft_min[m]", "min big-end MOFT", 1.1e-6, true}},
      .error_estimate = {},
      .cycle_scatter =
          engine::CycleScatter{
              3, 7, {{{"bearing_moft_min[m]", "min big-end MOFT", 1.1e-6, true}, 1.05e-6, 1.2e-6}}},
      .warnings = {},
      .kpis = {},
      .oil_skirt = {},
      .oil_big_end = {},
      .clearance_skirt = {},
      .clearance_big_end = {},
      .heat_balance = {}};
  engine::ErrorEstimate& e = s.error_estimate;
  e.status = "estimated";
  e.figures = {{{"bearing_moft_min[m]", "min big-end MOFT", 1.1e-6, true},
                1.0e-6,
                3.3e-8,
                0.03,
                true,
                (4 * 720.0 + 48.0) * std::numbers::pi / 180.0,
                (4 * 720.0 + 392.0) * std::numbers::pi / 180.0,
                true},
               {{"bearing_peak_pressure[Pa]", "peak big-end film pressure", 1.8e9, true},
                1.4e8,
                5.5e8,
                0.31,
                false,
                std::nullopt,
                std::nullopt,
                false}};
  e.worst_relative = 0.03;
  e.worst_label = "min big-end MOFT";
  e.skirt_ratio = 2.0;
  e.big_end_ratio = 2.0;
  e.tolerance_factor = 4.0;
  e.coarse_wall_time = 3.5;
  e.coarse_steps = 4000;
  io::RunWarning contact;
  contact.code = "asperity_contact";
  contact.joint = "big_end";
  contact.message = "big-end film thickness ratio h/σ = 0.72";
  contact.value = 0.72;
  contact.limit = 1.0;
  contact.crank_angle_deg = 372.0;
  contact.crank_angle_ranges_deg = {{355.0, 390.0}, {716.0, 4.0}};
  contact.position_angle_deg = 181.5;
  io::RunWarning assumed;
  assumed.code = "assumed_inputs";
  assumed.message = "2 inputs are still at the value the default case assumes";
  assumed.value = 2.0;
  assumed.fields = {"skirt.peklenik", "big_end.peklenik"};
  s.warnings = {contact, assumed};
  io::JointKpis skirt;
  skirt.min_moft = 1.9e-6;
  skirt.min_moft_crank_angle_deg = 381.0;
  skirt.min_moft_position = {12.5, 0.0215};
  skirt.peak_pressure = 3.1e7;
  skirt.peak_pressure_crank_angle_deg = 376.0;
  skirt.peak_contact_pressure = 0.0;  // no contact: no crank angle
  skirt.mean_fpl = 659.75;
  skirt.slap = io::PistonSlap{{{12.25, 0.004, true}, {371.5, 0.031, false}}, 0.031, 371.5, 0.035};
  io::JointKpis big_end;
  big_end.min_moft = 1.1e-6;
  big_end.min_moft_crank_angle_deg = 372.0;
  big_end.min_moft_position = {181.5, std::nullopt};
  big_end.peak_pressure = 9.5e7;
  big_end.peak_pressure_crank_angle_deg = 371.0;
  big_end.peak_contact_pressure = 2.5e6;
  big_end.peak_contact_pressure_crank_angle_deg = 372.0;
  big_end.mean_fpl = 120.5;
  big_end.max_eps = 0.97;
  big_end.max_eps_crank_angle_deg = 373.0;
  s.kpis = {skirt, big_end};
  s.oil_skirt = io::JointOilUsed{393.15, 0.0061, "own", "grade", "barus", 2e-8, "5w-30",
                                 "hths", 0.7,    1.0,   2.5e5,   0.0,     ""};
  s.clearance_skirt = io::RunSummary::Clearance{25e-6, 18.5e-6};
  s.oil_big_end = io::JointOilUsed{373.15, 0.02, "lubricant", "constant", "none", 0.0, "",
                                   "none", 1.0,  1.0,         0.0,        0.0,    ""};
  return s;
}

void CompareSummaries(const io::RunSummary& a, const io::RunSummary& b) {
  QCOMPARE(io::SummaryToJson(a).dump(), io::SummaryToJson(b).dump());
  QCOMPARE(a.case_name, b.case_name);
  QCOMPARE(a.rpm, b.rpm);
  QCOMPARE(a.extremes.at("gas_force[N]").max, b.extremes.at("gas_force[N]").max);
  QCOMPARE(a.mean_fpl_skirt_w, b.mean_fpl_skirt_w);
  QCOMPARE(a.mean_fpl_bearing_w.has_value(), b.mean_fpl_bearing_w.has_value());
  QCOMPARE(a.solver.newton_failures, b.solver.newton_failures);
  QCOMPARE(a.solver.relative_tolerance, b.solver.relative_tolerance);
  QCOMPARE(a.pressure_peak_crank_angle_deg, b.pressure_peak_crank_angle_deg);
  QCOMPARE(a.error_estimate.Summary(), b.error_estimate.Summary());
  for (const auto& [x, y] :
       {std::pair{&a.oil_skirt, &b.oil_skirt}, {&a.oil_big_end, &b.oil_big_end}}) {
    QCOMPARE(x->has_value(), y->has_value());
    if (!*x) continue;
    QCOMPARE((*x)->temperature_k, (*y)->temperature_k);
    QCOMPARE((*x)->viscosity_pa_s, (*y)->viscosity_pa_s);
    QCOMPARE((*x)->source, (*y)->source);
    QCOMPARE((*x)->viscosity_model, (*y)->viscosity_model);
    QCOMPARE((*x)->pressure_viscosity, (*y)->pressure_viscosity);
    QCOMPARE((*x)->pressure_viscosity_coefficient, (*y)->pressure_viscosity_coefficient);
    QCOMPARE((*x)->grade, (*y)->grade);
    QCOMPARE((*x)->shear_thinning, (*y)->shear_thinning);
    QCOMPARE((*x)->cross_ratio, (*y)->cross_ratio);
    QCOMPARE((*x)->cross_exponent, (*y)->cross_exponent);
    QCOMPARE((*x)->cross_critical_rate, (*y)->cross_critical_rate);
    QCOMPARE((*x)->bulk_modulus, (*y)->bulk_modulus);
  }
  QCOMPARE(a.clearance_skirt.has_value(), b.clearance_skirt.has_value());
  if (a.clearance_skirt && b.clearance_skirt) {
    QCOMPARE(a.clearance_skirt->cold, b.clearance_skirt->cold);
    QCOMPARE(a.clearance_skirt->hot, b.clearance_skirt->hot);
  }
  QCOMPARE(a.clearance_big_end.has_value(), b.clearance_big_end.has_value());
  QCOMPARE(a.kpis.skirt.has_value(), b.kpis.skirt.has_value());
  QCOMPARE(a.kpis.big_end.has_value(), b.kpis.big_end.has_value());
  if (a.kpis.skirt && b.kpis.skirt) {
    QCOMPARE(a.kpis.skirt->slap->events.size(), b.kpis.skirt->slap->events.size());
    QCOMPARE(a.kpis.skirt->slap->energy_sum, b.kpis.skirt->slap->energy_sum);
    QCOMPARE(a.kpis.skirt->min_moft_position.axial_m, b.kpis.skirt->min_moft_position.axial_m);
  }
}

}  // namespace

class TestRunSummary : public QObject {
  Q_OBJECT
 private slots:
  void everyFieldRoundTrips() {
    const io::RunSummary s = Full();
    CompareSummaries(s, io::SummaryFromJson(io::SummaryToJson(s)));
    QTemporaryDir dir;
    const std::filesystem::path path = dir.filePath("summary.json").toStdString();
    io::WriteSummaryJson(path, s);
    CompareSummaries(s, io::ReadSummaryJson(path));
    // The file's keys are the documented ones (docs/outputs.md).
    const nlohmann::json j = io::SummaryToJson(s);
    for (const char* key : {"filmdyn_version",
                            "case",
                            "model",
                            "rpm",
                            "status",
                            "complete",
                            "message",
                            "cycles",
                            "reported_cycle",
                            "cycles_to_steady_state",
                            "cycle_to_cycle_change",
                            "cycle_to_cycle_worst_quantity",
                            "cycle_to_cycle_changes",
                            "wall_time_s",
                            "max_constraint_violation",
                            "extremes",
                            "mean_fpl_w",
                            "solver",
                            "pressure_curve",
                            "headline",
                            "cycle_scatter",
                            "discretisation_error",
                            "warnings",
                            "kpis",
                            "oil",
                            "clearance"}) {
      QVERIFY2(j.contains(key), key);
    }
    QCOMPARE(j.size(), std::size_t(26));
    QCOMPARE(io::SummaryFromJson(j).cycle_to_cycle_changes, s.cycle_to_cycle_changes);
    QCOMPARE(io::SummaryFromJson(j).reported_cycle, 6);
    nlohmann::json before_reported = j;  // written before the reported cycle was: the last one
    before_reported.erase("reported_cycle");
    QCOMPARE(io::SummaryFromJson(before_reported).reported_cycle, 7);
    nlohmann::json old = j;  // written before the changes per cycle were: none
    old.erase("cycle_to_cycle_changes");
    QVERIFY(io::SummaryFromJson(old).cycle_to_cycle_changes.empty());
    QCOMPARE(j["clearance"]["skirt"]["hot[m]"].get<double>(), 18.5e-6);
    QCOMPARE(j["oil"]["skirt"]["viscosity[Pa*s]"].get<double>(), 0.0061);
    QCOMPARE(j["discretisation_error"]["figures"]["bearing_moft_min[m]"]["relative"].get<double>(),
             0.03);
    QVERIFY(j["discretisation_error"]["warning"].get<bool>());  // 3 % > 1 %
    // The labels come back from the one table of headline figures.
    const io::RunSummary back = io::SummaryFromJson(j);
    QCOMPARE(back.error_estimate.figures.at(0).figure.label, std::string("min big-end MOFT"));
    QCOMPARE(back.error_estimate.worst_relative, 0.03);
    // A peak the samples do not resolve in time stays marked; older summaries read it resolved.
    QVERIFY(back.error_estimate.figures.at(0).resolved_in_time);
    QVERIFY(!back.error_estimate.figures.at(1).resolved_in_time);
    // No best estimate from a spike neither run resolves; the resolved figure has one.
    QVERIFY(j["discretisation_error"]["figures"]["bearing_peak_pressure[Pa]"]["extrapolated"]
                .is_null());
    QVERIFY(
        j["discretisation_error"]["figures"]["bearing_moft_min[m]"]["extrapolated"].is_number());
    nlohmann::json before_marks = j;
    before_marks["discretisation_error"]["figures"]["bearing_peak_pressure[Pa]"].erase(
        "resolved_in_time");
    QVERIFY(io::SummaryFromJson(before_marks).error_estimate.figures.at(1).resolved_in_time);
    // A curve's extreme: where the run has it and where the extrapolation does, in the cycle.
    const nlohmann::json& moft = j["discretisation_error"]["figures"]["bearing_moft_min[m]"];
    QCOMPARE(moft["crank_angle[deg]"].get<double>(), 392.0);
    QCOMPARE(moft["extrapolated_crank_angle[deg]"].get<double>(), 48.0);
    QVERIFY(moft["extreme_elsewhere"].get<bool>());
    QVERIFY(!j["discretisation_error"]["figures"]["bearing_peak_pressure[Pa]"].contains(
        "extrapolated_crank_angle[deg]"));
    const engine::FigureError& moft_back = back.error_estimate.figures.at(0);
    QVERIFY(moft_back.extreme_elsewhere && moft_back.crank_angle &&
            moft_back.extrapolated_crank_angle);
    QCOMPARE(engine::CycleCrankAngleDeg(*moft_back.extrapolated_crank_angle), 48.0);
    QCOMPARE(back.error_estimate.Summary(), s.error_estimate.Summary());
    QVERIFY2(back.error_estimate.Summary().find("this run has it at 392 °CA, the extrapolation "
                                                "at 48 °CA") != std::string::npos,
             back.error_estimate.Summary().c_str());
    QVERIFY(!back.error_estimate.figures.at(1).extrapolated_crank_angle);
    QVERIFY(j["mean_fpl_w"]["bearing"].is_null());
    // The scatter over the last cycles of a run without a periodic state: null otherwise, and a
    // summary written before it existed reads without it.
    QCOMPARE(j["cycle_scatter"]["first_cycle"].get<int>(), 3);
    QCOMPARE(j["cycle_scatter"]["figures"]["bearing_moft_min[m]"]["max"].get<double>(), 1.2e-6);
    QCOMPARE(back.cycle_scatter->figures.at(0).min, 1.05e-6);
    QCOMPARE(back.cycle_scatter->figures.at(0).figure.label, std::string("min big-end MOFT"));
    nlohmann::json older = j;
    older.erase("cycle_scatter");
    QVERIFY(!io::SummaryFromJson(older).cycle_scatter);
    io::RunSummary periodic = Full();
    periodic.cycle_scatter.reset();
    QVERIFY(io::SummaryToJson(periodic)["cycle_scatter"].is_null());
    // KPIs: one object per lubricated joint; no crank angle for a peak of 0; the slap's events.
    QCOMPARE(j["kpis"]["skirt"]["slap_events"].size(), std::size_t(2));
    QCOMPARE(j["kpis"]["skirt"]["slap_events"][1]["direction"].get<std::string>(),
             std::string("to_anti_thrust"));
    QVERIFY(j["kpis"]["skirt"]["peak_contact_pressure_crank_angle[deg]"].is_null());
    QCOMPARE(j["kpis"]["big_end"]["max_eps[-]"].get<double>(), 0.97);
    QVERIFY(!j["kpis"]["big_end"].contains("min_moft_position_axial[m]"));
  }

  void errorsNameTheKey() {
    nlohmann::json j = io::SummaryToJson(Full());
    j.erase("model");
    try {
      io::SummaryFromJson(j);
      QFAIL("no error");
    } catch (const std::runtime_error& e) {
      QVERIFY2(QString(e.what()).contains("\"model\""), e.what());
    }
    j = io::SummaryToJson(Full());
    j["solver"]["steps"] = "many";
    try {
      io::SummaryFromJson(j);
      QFAIL("no error");
    } catch (const std::runtime_error& e) {
      QVERIFY2(QString(e.what()).contains("solver.steps"), e.what());
    }
  }

  // An extreme more than 1.5 times the larger magnitude of the samples beside it is a spike the
  // output samples do not resolve (engine::NeighbourRatio): summary.json marks it, and only it.
  // The samples of a whole cycle wrap around; those of a run that stopped early do not.
  void extremesBetweenSamplesAreMarked() {
    auto loaded = io::LoadCase({});
    const engine::RunConfig config = engine::MakeRunConfig(
        loaded.value, engine::Model::kIdeal, 3000.0, io::PressureCurveForSpeed(loaded, 3000.0));
    engine::RunResult result;
    result.status = engine::RunStatus::kCompleted;
    const int n = 40;
    // The run's samples are one whole cycle (engine::SamplesSpanACycle): 40 of 18 °CA.
    result.samples.resize(n);
    for (int k = 0; k < n; ++k)
      result.samples[size_t(k)].crank_angle = 4 * std::numbers::pi * k / n;
    std::vector<io::OutputRow> rows(n);
    for (int k = 0; k < n; ++k) {
      const double x = k - 20.0;
      io::OutputRow& r = rows[size_t(k)];
      // A Gaussian 4 samples wide at half height: 2^(-4/16) = 0.84 of its peak beside it.
      r.gas_force = 4e4 * std::exp2(-4.0 * x * x / 16.0) - 300.0;
      // One sample of an impact, 8.2 times the samples beside it; 0 elsewhere.
      r.bigend_force_y = k == 20 ? 8.2e4 : (k == 19 || k == 21 ? 1e4 : 0.0);
      // A negative spike, at the first sample: beside it the last one (a whole cycle).
      r.bigend_force_x = k == 0 ? -8.5e4 : (k == n - 1 ? 2e4 : 5.7e3);
      // A value that is not a number (a failed step) is no extreme, and no neighbour.
      r.piston_lateral = k == 0 ? NAN : 1e-6 * k;
    }
    io::RunSummary s = io::SummarizeRun("default", config, result, rows);
    const io::ColumnExtremes &gas = s.extremes.at("gas_force[N]"),
                             &fy = s.extremes.at("bigend_force_y[N]"),
                             &fx = s.extremes.at("bigend_force_x[N]");
    QVERIFY(!gas.min_spike && !gas.max_spike);
    QCOMPARE(fy.max, 8.2e4);
    QVERIFY(fy.max_spike && !fy.min_spike);
    QCOMPARE(fx.min, -8.5e4);
    QVERIFY(fx.min_spike && !fx.max_spike);  // 8.5e4 against 2e4 and 5.7e3
    QCOMPARE(s.extremes.at("piston_lateral[m]").min, 1e-6);
    QCOMPARE(s.extremes.at("piston_lateral[m]").max, 39e-6);
    QVERIFY(!s.extremes.at("piston_lateral[m]").min_spike);  // beside it: only 2e-6
    // In the file only where true; read back.
    const nlohmann::json j = io::SummaryToJson(s);
    QVERIFY(j.at("extremes").at("bigend_force_y[N]").at("max_spike").get<bool>());
    QVERIFY(!j.at("extremes").at("bigend_force_y[N]").contains("min_spike"));
    QVERIFY(!j.at("extremes").at("gas_force[N]").contains("max_spike"));
    QVERIFY(io::SummaryFromJson(j).extremes.at("bigend_force_x[N]").min_spike);
    // A wider impact (the samples beside it at 2/3 of it and more) is resolved.
    rows[19].bigend_force_y = rows[21].bigend_force_y = 8.2e4 / 1.5;
    QVERIFY(!io::SummarizeRun("default", config, result, rows)
                 .extremes.at("bigend_force_y[N]")
                 .max_spike);
    // A run that stopped before its first cycle ended (samples short of a cycle): the first
    // sample has only the one after it (5.7e3): still a spike; the last sample's extreme has only
    // the one before it.
    result.status = engine::RunStatus::kFailed;
    for (int k = 0; k < n; ++k)
      result.samples[size_t(k)].crank_angle = 2 * std::numbers::pi * k / n;
    rows[size_t(n - 1)].bigend_force_x = -9e4;  // beside it 5.7e3 before, nothing after
    s = io::SummarizeRun("default", config, result, rows);
    QCOMPARE(s.extremes.at("bigend_force_x[N]").min, -9e4);
    QVERIFY(s.extremes.at("bigend_force_x[N]").min_spike);
    rows[size_t(n - 2)].bigend_force_x = -8e4;  // now a neighbour of similar size
    QVERIFY(!io::SummarizeRun("default", config, result, rows)
                 .extremes.at("bigend_force_x[N]")
                 .min_spike);
  }

  void writtenByARun() {
    auto loaded = io::LoadCase({});
    loaded.value.solver.max_cycles = 2;
    engine::RunConfig config = engine::MakeRunConfig(
        loaded.value, engine::Model::kIdeal, 3000.0, io::PressureCurveForSpeed(loaded, 3000.0));
    const engine::RunResult result = engine::RunJob(config);
    QTemporaryDir dir;
    const auto rows = io::WriteRunFolder(dir.path().toStdString(), "default", config, result);
    const io::RunSummary s = io::ReadSummaryJson(dir.filePath("summary.json").toStdString());
    QCOMPARE(s.model, std::string("ideal"));
    QCOMPARE(s.rpm, 3000.0);
    QCOMPARE(s.cycles, result.cycles);
    QCOMPARE(s.solver.steps, result.stats.steps);
    double lo = 1e300, hi = -1e300;
    for (const auto& row : rows) {
      lo = std::min(lo, *row.gas_force);
      hi = std::max(hi, *row.gas_force);
    }
    QCOMPARE(s.extremes.at("gas_force[N]").min, lo);
    QCOMPARE(s.extremes.at("gas_force[N]").max, hi);
    QVERIFY(!s.mean_fpl_skirt_w);                    // ideal joints: no film, no FPL figure
    QVERIFY(!s.cycle_scatter);                       // no headline figures (ideal joints)
    QVERIFY(!s.extremes.contains("skirt_moft[m]"));  // no film: no values, no extremes
    QVERIFY(!s.kpis.skirt && !s.kpis.big_end);       // nor KPIs
  }

  // A results file that cannot be written (here its temporary name is taken by a folder; a full
  // disk alike): the folder's summary says the run failed and why, instead of "running", which
  // reads as a run killed; the error still reaches the caller.
  void aFailedWriteLeavesAFailedSummary() {
    const io::LoadedCase loaded = io::LoadCase("");
    const engine::RunConfig config = engine::MakeRunConfig(
        loaded.value, engine::Model::kIdeal, 3000.0, io::PressureCurveForSpeed(loaded, 3000.0));
    const engine::RunResult result = engine::RunJob(config);
    QTemporaryDir dir;
    const std::filesystem::path folder = dir.path().toStdString();
    io::MarkRunStarted(folder, "default", config);
    std::filesystem::create_directories(folder / "results.csv.tmp" / "x");
    bool threw = false;
    try {
      io::WriteRunFolder(folder, "default", config, result);
    } catch (const std::exception& e) {
      threw = true;
      QVERIFY2(std::string(e.what()).find("results.csv") != std::string::npos, e.what());
    }
    QVERIFY(threw);
    const io::RunSummary s = io::ReadSummaryJson(folder / "summary.json");
    QCOMPARE(s.status, std::string("failed"));
    QVERIFY(!s.complete);
    QVERIFY2(s.message.find("its results could not be written") != std::string::npos &&
                 s.message.find("results.csv") != std::string::npos,
             s.message.c_str());
  }
};

QTEST_GUILESS_MAIN(TestRunSummary)
#include "test_run_summary.moc"
