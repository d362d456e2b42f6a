// Engineering warnings, the per-step film peaks and friction split, and the run's progress, on
// real runs of the default case (coarse skirt mesh, 2 °CA outputs, no error estimate):
// - Skirt-LBRBE at 6000 rpm with a rough big end: its film falls below the composite roughness;
//   the warning names the big end, a crank angle where results.csv's MOFT / σ is indeed below 1 and
//   the minimum ratio; the peak film and contact pressures of each row equal the largest nodal
//   values of the field frame of that step; the asperity friction equals μ_f ∫p_c dA of the field;
//   the asperity and hydrodynamic parts of each joint's friction power add up to its FPL; progress
//   never decreases from the run-in through cycles 1 and 2, ends at 1, and the time left never
//   moves by more than the stated bound between updates; summary.json lists the warnings; the
//   Reynolds films' peaks are resolved by the samples and have no steps' peaks between them.
// - Four times the viscosity (films far thicker than the roughness) and the Ideal model: none of
//   the film or eccentricity warnings.
// - A run stopped at max_cycles before it is periodic: the not-periodic warning with the last
//   cycle-to-cycle change; progress still ends at 1.
#include <fmt/format.h>
#include <QRegularExpression>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>

#include "core/coupling/film_report.hpp"
#include "core/engine/case_schema.hpp"
#include "core/engine/run_job.hpp"
#include "core/io/case_file.hpp"
#include "core/io/results_writer.hpp"
#include "core/io/run_summary.hpp"
#include "core/io/run_warnings.hpp"
#include "core/lubrication/bearing_solver.hpp"
#include "core/lubrication/skirt_solver.hpp"

using namespace filmdyn;

namespace {

const io::LoadedCase& Loaded() {
  static const io::LoadedCase loaded = io::LoadCase({});
  return loaded;
}

engine::EngineCase CoarseCase() {
  engine::EngineCase c = Loaded().value;
  c.skirt.mesh_thrust = c.skirt.mesh_anti = 10;
  c.skirt.mesh_axial = 12;
  c.solver.output_interval = 2.0 * M_PI / 180.0;  // 2 °CA
  c.solver.error_estimate = 0;
  return c;
}

engine::RunConfig Config(const engine::EngineCase& c, engine::Model model, double rpm) {
  return engine::MakeRunConfig(c, model, rpm, io::PressureCurveForSpeed(Loaded(), rpm));
}

// What the monitor saw.
struct ProgressTrace {
  std::vector<double> fraction, remaining, elapsed, cycle_change;
  std::vector<int> cycle;
  engine::RunMonitor Monitor() {
    return [this](const engine::RunProgress& p) {
      fraction.push_back(p.fraction);
      remaining.push_back(p.remaining);
      elapsed.push_back(p.elapsed);
      cycle.push_back(p.cycle);
      cycle_change.push_back(p.cycle_change);
      return true;
    };
  }
};

// Progress never decreases and ends at 1 with nothing left; after the first 10 % the time left
// differs from the previous estimate counted down by the wall time in between by at most
// kRemainingMaxStep of the estimated whole run time.
void CheckProgress(const ProgressTrace& t, const engine::RunResult& result) {
  QVERIFY(t.fraction.size() > 10);
  // The last compared cycle's change: none in the run-in and cycles 1–2, from cycle 3 on the
  // change cycle c − 1 ended with.
  for (std::size_t k = 0; k < t.cycle.size(); ++k) {
    const int c = t.cycle[k];
    if (c < 3)
      QCOMPARE(t.cycle_change[k], -1.0);
    else
      QCOMPARE(t.cycle_change[k], result.cycle_changes.at(std::size_t(c - 3)));
  }
  for (std::size_t k = 1; k < t.fraction.size(); ++k) {
    QVERIFY2(t.fraction[k] >= t.fraction[k - 1],
             qPrintable(QString("fraction fell from %1 to %2 at update %3 (cycle %4)")
                            .arg(t.fraction[k - 1])
                            .arg(t.fraction[k])
                            .arg(k)
                            .arg(t.cycle[k])));
    QVERIFY(t.fraction[k] >= 0.0 && t.fraction[k] <= 1.0);
  }
  QCOMPARE(t.fraction.back(), 1.0);
  QCOMPARE(t.remaining.back(), 0.0);
  int checked = 0;
  for (std::size_t k = 1; k + 1 < t.remaining.size(); ++k) {  // the last update is "done"
    if (t.fraction[k - 1] < engine::kRemainingSmoothedFrom) continue;
    const double dt = t.elapsed[k] - t.elapsed[k - 1];
    const double countdown = std::max(0.0, t.remaining[k - 1] - dt);
    const double bound = engine::kRemainingMaxStep * (t.elapsed[k] + countdown) + 1e-12;
    QVERIFY2(t.remaining[k] - countdown >= -bound && t.remaining[k] - countdown <= bound + dt,
             qPrintable(QString("time left jumped from %1 s to %2 s at update %3 (bound %4 s)")
                            .arg(t.remaining[k - 1])
                            .arg(t.remaining[k])
                            .arg(k)
                            .arg(bound)));
    QVERIFY(t.remaining[k] >= 0.0);
    ++checked;
  }
  QVERIFY(checked > 100);
}

// Largest nodal values of one step's field frame.
struct FramePeaks {
  double skirt_p = 0, skirt_pc = 0, bearing_p = 0, bearing_pc = 0;
  double bearing_contact_integral = 0;  ///< ∫ p_c dA over the whole bearing film [N]
};

double MaxOf(const Eigen::VectorXd& v) { return std::max(0.0, v.maxCoeff()); }

bool Near(double a, double b, double relative, double absolute) {
  return std::abs(a - b) <= relative * std::max(std::abs(a), std::abs(b)) + absolute;
}

}  // namespace

class TestRunWarnings : public QObject {
  Q_OBJECT
 private slots:
  void coupledRunWithRoughBigEnd() {
    // The default big end at 6000 rpm runs at h/σ ≥ 2.6 (mixed lubrication); with surfaces
    // three to five times rougher (σ = 2.1 µm) its film of ~1.7 µm falls below σ.
    engine::EngineCase rough = CoarseCase();
    rough.big_end.roughness_journal = rough.big_end.roughness_bearing = 1.5e-6;
    engine::RunConfig config = Config(rough, engine::Model::kSkirtLbrbe, 6000.0);
    std::map<int, FramePeaks> peaks;  // by output step, newest cycle
    int frame_cycle = 0;
    config.field_callback = [&](const engine::FieldFrame& f) {
      if (f.cycle != frame_cycle) peaks.clear(), frame_cycle = f.cycle;
      FramePeaks p;
      QVERIFY(f.skirt && f.bearing);
      p.skirt_p = MaxOf(f.skirt->fields().pressure);
      p.skirt_pc = MaxOf(f.skirt->fields().contact_pressure);
      p.bearing_p = MaxOf(f.bearing->fields().pressure);
      p.bearing_pc = MaxOf(f.bearing->fields().contact_pressure);
      // A P1 field integrates exactly with the lumped (row-sum) areas.
      const auto& area = f.bearing->fem().lumped_area();
      const Eigen::VectorXd& pc = f.bearing->fields().contact_pressure;
      for (std::size_t k = 0; k < area.size(); ++k) p.bearing_contact_integral += area[k] * pc[k];
      if (f.bearing->config().mesh.symmetric_half) p.bearing_contact_integral *= 2.0;
      peaks[f.step] = p;
    };
    ProgressTrace trace;
    const engine::RunResult result = engine::RunJob(config, trace.Monitor());
    QCOMPARE(engine::StatusName(result.status), std::string("completed"));
    QVERIFY(result.cycles >= 2);  // run-in → cycle 1 → cycle 2: where the fraction used to fall
    CheckProgress(trace, result);

    const engine::EngineCase& c = config.engine_case;
    const double omega = 6000.0 * 2.0 * M_PI / 60.0;
    QCOMPARE(peaks.size(), result.samples.size());
    double largest_contact_friction = 0.0;
    for (std::size_t k = 0; k < result.samples.size(); ++k) {
      const engine::CrankTrainSample& s = result.samples[k];
      const io::OutputRow r = io::RowFromSample(s, config.model, 0.0);
      const FramePeaks& p = peaks.at(int(k));
      // Reynolds films have no step-by-step history: no peaks between the samples.
      QVERIFY(std::isnan(s.skirt.step_peak_pressure) && std::isnan(s.bearing.step_peak_pressure));
      QVERIFY(!r.skirt_step_peak_pressure && !r.bearing_step_peak_pressure);  // empty cells
      // Peaks: at least every nodal value of the step's frame, and attained.
      for (const auto& [peak, nodal] : {std::pair{*r.skirt_peak_pressure, p.skirt_p},
                                        {*r.skirt_peak_contact_pressure, p.skirt_pc},
                                        {*r.bearing_peak_pressure, p.bearing_p},
                                        {*r.bearing_peak_contact_pressure, p.bearing_pc}}) {
        QVERIFY2(peak >= nodal * (1.0 - 1e-9),
                 qPrintable(QString("step %1: %2 < %3").arg(k).arg(peak).arg(nodal)));
        QVERIFY(Near(peak, nodal, 1e-6, 1e-3));
      }
      // Skirt: friction power split at the sliding speed the film was solved at.
      const double u = s.skirt.speed;
      const double F = *r.skirt_friction_force, Fc = *r.skirt_contact_friction_force;
      QVERIFY(Fc * u <= 0.0);  // the asperities' friction opposes the sliding
      QVERIFY(Near(*r.skirt_fpl, std::abs(F * u), 1e-9, 1e-12));
      QVERIFY(Near(*r.skirt_contact_fpl, -Fc * u, 1e-9, 1e-12));  // what they dissipate
      // Big end: the asperity friction is μ_f ∫ p_c dA of the field, against the sliding.
      const double Fb = *r.bearing_friction_force, Fbc = *r.bearing_contact_friction_force;
      QVERIFY2(
          Near(std::abs(Fbc), c.big_end.boundary_friction * p.bearing_contact_integral, 1e-6, 1e-9),
          qPrintable(QString("step %1: %2 vs %3")
                         .arg(k)
                         .arg(Fbc)
                         .arg(c.big_end.boundary_friction * p.bearing_contact_integral)));
      const double ub = c.big_end.journal_radius * (omega - s.rod_angular_velocity);
      QVERIFY(Fbc * ub <= 0.0);
      QVERIFY(Near(*r.bearing_fpl, std::abs(Fb * ub), 1e-6, 1e-9));
      QVERIFY(Near(*r.bearing_contact_fpl, -Fbc * ub, 1e-6, 1e-9));
      largest_contact_friction = std::max(largest_contact_friction, std::abs(Fbc));
    }
    QVERIFY(largest_contact_friction > 0.0);  // the split is exercised: the asperities touch

    // The big end's film falls below its composite roughness: asperity contact, where and when.
    const double sigma = std::hypot(c.big_end.roughness_journal, c.big_end.roughness_bearing);
    const std::vector<io::RunWarning> warnings = io::RunWarnings(config, result);
    auto find = [&](const std::string& code, const std::string& joint) {
      return std::find_if(warnings.begin(), warnings.end(), [&](const io::RunWarning& w) {
        return w.code == code && w.joint == joint;
      });
    };
    for (const io::RunWarning& w : warnings) qInfo("%s: %s", w.code.c_str(), w.message.c_str());
    const auto contact = find("asperity_contact", "big_end");
    QVERIFY(contact != warnings.end());
    QVERIFY(find("mixed_lubrication", "big_end") == warnings.end());  // the worse one only
    QVERIFY(contact->value < 1.0);
    QVERIFY(contact->crank_angle_deg.has_value());
    QVERIFY(contact->position_angle_deg.has_value());
    double min_ratio = INFINITY;
    bool found = false;
    for (const engine::CrankTrainSample& s : result.samples) {
      const io::OutputRow r = io::RowFromSample(s, config.model, 0.0);
      const double ratio = *r.bearing_moft / sigma;
      min_ratio = std::min(min_ratio, ratio);
      if (std::abs(*r.crank_angle_deg - *contact->crank_angle_deg) < 1e-9) {
        QVERIFY2(ratio < 1.0,
                 qPrintable(QString("MOFT/σ = %1 at %2 °CA").arg(ratio).arg(*r.crank_angle_deg)));
        QCOMPARE(ratio, contact->value);
        found = true;
      }
      // Every step below 1 lies in one of the warning's intervals.
      if (ratio < 1.0) {
        const double a = *r.crank_angle_deg;
        const bool inside = std::any_of(
            contact->crank_angle_ranges_deg.begin(), contact->crank_angle_ranges_deg.end(),
            [a](const auto& range) {
              return range.first <= range.second ? a >= range.first && a <= range.second
                                                 : a >= range.first || a <= range.second;
            });
        QVERIFY2(inside, qPrintable(QString("%1 °CA is below 1 but in no interval").arg(a)));
      }
    }
    QVERIFY(found);
    QCOMPARE(contact->value, min_ratio);
    QVERIFY(!contact->crank_angle_ranges_deg.empty());
    QVERIFY(QString::fromStdString(contact->message).contains("big-end"));
    // Inputs: the synthetic pressure curve, the assumed elastic constants.
    QVERIFY(find("synthetic_pressure", "") != warnings.end());
    const auto assumed = find("assumed_inputs", "");
    QVERIFY(assumed != warnings.end());
    QVERIFY(std::count(assumed->fields.begin(), assumed->fields.end(), "big_end.modulus_bearing"));
    QVERIFY(!std::count(assumed->fields.begin(), assumed->fields.end(), "solver.max_cycles"));
    // A choice the default case assumes (no oil supply given) counts like a number.
    QVERIFY(std::count(assumed->fields.begin(), assumed->fields.end(), "big_end.supply"));
    QVERIFY(find("not_periodic", "") == warnings.end());
    // The Reynolds films' peaks are broad: resolved by the 2 °CA samples.
    QVERIFY(find("unresolved_peak", "skirt") == warnings.end());
    QVERIFY(find("unresolved_peak", "big_end") == warnings.end());

    // summary.json lists the same warnings and reads them back.
    const io::RunSummary summary = io::SummarizeRun("default", config, result, {});
    const nlohmann::json j = io::SummaryToJson(summary);
    QCOMPARE(j["warnings"].size(), warnings.size());
    const io::RunSummary back = io::SummaryFromJson(j);
    QCOMPARE(back.warnings.size(), warnings.size());
    for (std::size_t k = 0; k < warnings.size(); ++k) {
      QCOMPARE(back.warnings[k].code, warnings[k].code);
      QCOMPARE(back.warnings[k].joint, warnings[k].joint);
      QCOMPARE(back.warnings[k].value, warnings[k].value);
      QCOMPARE(back.warnings[k].crank_angle_deg, warnings[k].crank_angle_deg);
      QCOMPARE(back.warnings[k].crank_angle_ranges_deg, warnings[k].crank_angle_ranges_deg);
      QCOMPARE(back.warnings[k].fields, warnings[k].fields);
    }
  }

  // A value given to an input the run does not read (a constant supply pressure beside a
  // supply-pressure curve, which sets the pressure) is named, with why; the default case and a
  // case that reads what it sets have no such warning; an ideal joint's data do not count.
  // The asperities' friction power is what they dissipate, |F_c u|, also where the film's
  // pressure-driven shear pushes the surface along so that the total friction force does not
  // oppose the sliding (the share fpl · F_c / F read negative there: −15 W below).
  void theAsperityFrictionPowerIsNeverNegative() {
    const double u = 3.0, F = 2.0, Fc = -5.0;  // total along u, the asperities' part against
    const double fpl = std::abs(F * u);
    QCOMPARE(filmdyn::coupling::AsperityFrictionPower(fpl, F, Fc), 15.0);
    QCOMPARE(filmdyn::coupling::AsperityFrictionPower(fpl, -1.0, -4.0), 4.0 * fpl);  // > fpl
    QCOMPARE(filmdyn::coupling::AsperityFrictionPower(0.0, 0.0, 0.0), 0.0);
  }

  void inputsSetButNotReadAreNamed() {
    const engine::RunResult none;
    auto unused = [&](const engine::EngineCase& c, engine::Model model) {
      const auto w = io::RunWarnings(Config(c, model, 2000.0), none);
      const auto it = std::find_if(
          w.begin(), w.end(), [](const io::RunWarning& x) { return x.code == "unused_inputs"; });
      return it == w.end() ? io::RunWarning{} : *it;
    };
    engine::EngineCase c = CoarseCase();
    QVERIFY(unused(c, engine::Model::kOnlyLbrbe).code.empty());
    c.big_end.supply = lubrication::OilFeedKind::kPinHoles;
    c.big_end.oil_feed_pressure = 5e5;
    QVERIFY(unused(c, engine::Model::kOnlyLbrbe).code.empty());  // read: a constant pressure
    c.big_end.supply_pressure_angles.clear();
    c.big_end.supply_pressure_values.clear();
    for (int k = 0; k < 72; ++k) {
      c.big_end.supply_pressure_angles.push_back(k * 4.0 * std::numbers::pi / 72.0);
      c.big_end.supply_pressure_values.push_back(3e5);
    }
    const io::RunWarning w = unused(c, engine::Model::kOnlyLbrbe);
    QCOMPARE(w.code, std::string("unused_inputs"));
    QCOMPARE(w.fields, std::vector<std::string>{"big_end.oil_feed_pressure"});
    QVERIFY2(QString::fromStdString(w.message).contains("curve"), w.message.c_str());
    QCOMPARE(io::WarningShortText(w), std::string("1 unused inputs"));
    // The same big end switched off (an ideal pin joint): its data are not the run's concern.
    QVERIFY(unused(c, engine::Model::kIdeal).code.empty());
  }

  // The assumed inputs are those the case notes as assumed: a value the user states is theirs,
  // even when it equals the default case's; a field the file leaves out takes the default case's
  // value and its note.
  void assumedInputsAreThoseTheCaseDoesNotState() {
    const engine::RunResult none;
    auto assumed = [&](const engine::EngineCase& c) {
      const auto w = io::RunWarnings(Config(c, engine::Model::kSkirtLbrbe, 2000.0), none);
      const auto it = std::find_if(
          w.begin(), w.end(), [](const io::RunWarning& x) { return x.code == "assumed_inputs"; });
      return it == w.end() ? std::vector<std::string>{} : it->fields;
    };
    auto has = [](const std::vector<std::string>& fields, const char* path) {
      return std::count(fields.begin(), fields.end(), path) == 1;
    };
    // The default case: its own notes.
    const std::vector<std::string> all = assumed(Loaded().value);
    QVERIFY(has(all, "geometry.gravity") && has(all, "skirt.profile_h") &&
            has(all, "skirt.modulus_skirt") && has(all, "operating.crankcase_pressure"));
    // A user's file that states the gravity and the crankcase pressure at the default case's
    // values, and its own skirt profile; everything else left out.
    nlohmann::json file = {
        {"filmdyn_case_version", 1},
        {"geometry", {{"gravity", 9.81}}},
        {"operating", {{"crankcase_pressure", 1.0e5}}},
        {"skirt", {{"profile_y", {0.0, 0.0095, 0.019}}, {"profile_h", {2.0e-5, 0.0, 2.0e-5}}}}};
    const engine::EngineCase own = io::LoadCaseText(file.dump(), "own.json");
    QCOMPARE(own.geometry.gravity, Loaded().value.geometry.gravity);
    const std::vector<std::string> mine = assumed(own);
    QVERIFY(!has(mine, "geometry.gravity") && !has(mine, "operating.crankcase_pressure"));
    QVERIFY(!has(mine, "skirt.profile_h") && !has(mine, "skirt.profile_y"));
    // What it leaves out is the default case's assumption, and says so.
    QVERIFY(has(mine, "skirt.modulus_skirt") && has(mine, "big_end.peklenik"));
    QVERIFY(QString::fromStdString(own.assumed.at("skirt.modulus_skirt")).startsWith("not given"));
    // --set makes a value the user's, at the default case's value too; an element of a list
    // makes its whole table the user's (the profile's y with its h).
    const engine::EngineCase set =
        io::LoadCaseText(file.dump(), "own.json",
                         {"skirt.modulus_skirt=75e9", "big_end.peklenik=1", "skirt.ovality_h=[]"});
    const std::vector<std::string> after = assumed(set);
    QVERIFY(!has(after, "skirt.modulus_skirt") && !has(after, "big_end.peklenik"));
    QVERIFY(!has(after, "skirt.ovality_h") && !has(after, "skirt.ovality_alpha"));
    QVERIFY(has(after, "skirt.poisson_skirt"));
    const auto default_text = filmdyn::io::CaseToJson(Loaded().value).dump();
    const engine::EngineCase element =
        io::LoadCaseText(default_text, "default", {"skirt.profile_h.2=0"});
    QVERIFY(!element.assumed.count("skirt.profile_h") && !element.assumed.count("skirt.profile_y"));
    QVERIFY(element.assumed.count("skirt.ovality_h"));
  }

  void massConservingBigEndOnTheFilmStartLineWarns() {
    // The supply warning is the configuration's: judged without a run.
    const engine::RunResult none;
    auto has = [&](const engine::EngineCase& c) {
      const auto w = io::RunWarnings(Config(c, engine::Model::kOnlyLbrbe, 2000.0), none);
      return std::any_of(w.begin(), w.end(), [](const io::RunWarning& x) {
        return x.code == "film_start_supply" && x.joint == "big_end";
      });
    };
    engine::EngineCase c = CoarseCase();
    QVERIFY(!has(c));  // Reynolds: the film start is the published tables' boundary
    c.big_end.cavitation = lubrication::CavitationModel::kJfo;
    QVERIFY(has(c));
    engine::EngineCase fed = c;
    fed.big_end.supply = lubrication::OilFeedKind::kPinHoles;
    fed.big_end.oil_feed_pressure = 3e5;
    QVERIFY(!has(fed));
    const auto w = io::RunWarnings(Config(c, engine::Model::kOnlyLbrbe, 2000.0), none);
    for (const io::RunWarning& x : w)
      if (x.code == "film_start_supply") {
        QVERIFY(QString::fromStdString(x.message).contains("big_end.supply"));
        QCOMPARE(QString::fromStdString(io::WarningShortText(x)), QString("film-start supply"));
      }
  }

  // A cylinder pressure that never rises above a few bar is a curve in the wrong unit (bar read
  // as Pa: a 51 bar peak became 51 Pa and ran without a word), or a gauge pressure.
  void aCylinderPressureInTheWrongUnitWarns() {
    const engine::RunResult none;
    const engine::EngineCase c = CoarseCase();
    engine::RunConfig config = Config(c, engine::Model::kOnlyLbrbe, 6000.0);
    auto low = [&]() -> std::optional<io::RunWarning> {
      for (const io::RunWarning& w : io::RunWarnings(config, none))
        if (w.code == "low_cylinder_pressure") return w;
      return std::nullopt;
    };
    QVERIFY(!low());  // the synthetic curve, 6 MPa
    std::vector<double> angles, in_bar;
    for (int k = 0; k < 720; k += 5) {
      angles.push_back(k * std::numbers::pi / 180.0);
      in_bar.push_back(config.pressure.Pressure(angles.back()) * 1e-5);
    }
    config.pressure = engine::PressureCurve(angles, in_bar, "bar.csv");
    const std::optional<io::RunWarning> w = low();
    QVERIFY(w.has_value());
    QVERIFY(w->value < 100.0 && w->limit == io::kLowestPeakCylinderPressure);
    QVERIFY2(QString::fromStdString(w->message).contains("is the curve in bar or MPa"),
             w->message.c_str());
    QVERIFY2(io::WarningShortText(*w).starts_with("cylinder peak 0."),
             io::WarningShortText(*w).c_str());
  }

  // A completed run whose headline figures still moved over its last cycles by more than the
  // steady-state tolerance says so (the periodic test judges a quantity against its range, which
  // let a minimum film move by ±1.6 % at a change of 0.63 %); within the tolerance, nothing.
  void aPeriodicRunWhoseFiguresStillMoveWarns() {
    const engine::EngineCase c = CoarseCase();
    const engine::RunConfig config = Config(c, engine::Model::kOnlyLbrbe, 2000.0);
    engine::RunResult r;
    r.status = engine::RunStatus::kCompleted;
    r.cycles = 2;
    r.cycle_change = 0.0063;
    auto cycle = [](double moft) {
      return std::vector<engine::HeadlineFigure>{
          engine::HeadlineFigureFor("bearing_moft_min[m]", moft),
          engine::HeadlineFigureFor("bearing_fpl_mean[W]", 595.0)};
    };
    auto scatter = [&]() -> std::optional<io::RunWarning> {
      for (const io::RunWarning& w : io::RunWarnings(config, r))
        if (w.code == "cycle_scatter") return w;
      return std::nullopt;
    };
    r.cycle_headlines = {cycle(1.634e-6), cycle(1.582e-6)};
    const std::optional<io::RunWarning> w = scatter();
    QVERIFY(w.has_value());
    QVERIFY(std::abs(w->value - 0.026 / 1.582) < 1e-9);
    QVERIFY2(QString::fromStdString(w->message)
                 .contains("periodic by the cycle-to-cycle test (the change 0.63 % of each "
                           "quantity's range over the cycle, below 1 %), yet over cycles 1–2 the "
                           "headline figures moved by up to ±1.6 %"),
             w->message.c_str());
    QCOMPARE(io::WarningShortText(*w), std::string("cycles scatter ±1.6 %"));
    r.cycle_headlines = {cycle(1.590e-6), cycle(1.582e-6)};  // ±0.25 %
    QVERIFY(!scatter());
  }

  // A length in the wrong unit that the field's wide range lets through (a big-end width of
  // 40 m for 40 mm) gives proportions no engine has: it warns, naming the field; the default
  // case's proportions do not, and an ideal joint's data are not the run's.
  void implausibleProportionsWarn() {
    const engine::RunResult none;
    auto proportions = [&](const engine::EngineCase& c, engine::Model model) {
      for (const io::RunWarning& w : io::RunWarnings(Config(c, model, 2000.0), none))
        if (w.code == "implausible_proportions") return w;
      return io::RunWarning{};
    };
    engine::EngineCase c = CoarseCase();
    QVERIFY(proportions(c, engine::Model::kSkirtLbrbe).code.empty());
    c.big_end.width = 0.040 * 1000.0 * c.big_end.bearing_radius / 0.0475;  // "40" for 40 mm
    c.skirt.cold_clearance = 1e-3 * c.geometry.liner_radius * 0.9;         // 0.9e-3 R: fine
    io::RunWarning w = proportions(c, engine::Model::kSkirtLbrbe);
    QCOMPARE(w.code, std::string("implausible_proportions"));
    QCOMPARE(w.fields, std::vector<std::string>{"big_end.width"});
    QVERIFY2(QString::fromStdString(w.message).contains("L/D = 421"), w.message.c_str());
    QVERIFY2(QString::fromStdString(w.message).contains("wrong unit"), w.message.c_str());
    QCOMPARE(io::WarningShortText(w), std::string("1 implausible proportions"));
    // The editor's note beside the field says the same while it is typed; a plausible width
    // shows its L/D.
    QCOMPARE(engine::DerivedNote(c, "big_end.width"),
             std::string("L/D = 421: engines lie within 0.1–2; a length in the wrong unit?"));
    QCOMPARE(engine::DerivedNote(CoarseCase(), "big_end.width"), std::string("L/D = 0.733"));
    QCOMPARE(engine::DerivedNote(CoarseCase(), "skirt.length"), std::string("length/bore = 0.384"));
    QVERIFY(proportions(c, engine::Model::kOnlySkirt).code.empty());  // an ideal big end
    c.skirt.length = 90.0;                                            // m
    QCOMPARE(proportions(c, engine::Model::kSkirtLbrbe).fields,
             (std::vector<std::string>{"big_end.width", "skirt.length"}));
  }

  // A curve whose firing TDC is at 0 °CA (a cycle counted from firing) peaks a revolution away
  // from this program's firing TDC at 360 °CA: it runs without complaint, so it warns.
  void aCurveFiringAtZeroWarns() {
    const engine::RunResult none;
    const engine::EngineCase c = CoarseCase();
    engine::RunConfig config = Config(c, engine::Model::kOnlyLbrbe, 6000.0);
    auto off = [&]() -> std::optional<io::RunWarning> {
      for (const io::RunWarning& w : io::RunWarnings(config, none))
        if (w.code == "pressure_peak_off_firing") return w;
      return std::nullopt;
    };
    QVERIFY(!off());  // the synthetic curve peaks after 360 °CA
    const double peak_at = config.pressure.PeakAngle() * 180.0 / std::numbers::pi;
    std::vector<double> angles, shifted;
    for (int k = 0; k < 720; ++k) {
      angles.push_back(k * std::numbers::pi / 180.0);
      shifted.push_back(config.pressure.Pressure((k + 360) * std::numbers::pi / 180.0));
    }
    config.pressure = engine::PressureCurve(angles, shifted, "firing-at-zero.csv");
    const std::optional<io::RunWarning> w = off();
    QVERIFY(w.has_value());
    QVERIFY2(std::abs(*w->crank_angle_deg - (peak_at - 360.0)) <= 1.0,
             qPrintable(QString::number(*w->crank_angle_deg)));
    QVERIFY2(QString::fromStdString(w->message).contains("add 360 °CA to its angles"),
             w->message.c_str());
    QVERIFY2(io::WarningShortText(*w).starts_with("cylinder peak at "),
             io::WarningShortText(*w).c_str());
  }

  // The synthetic curve's warning says which curve the run has: at a curve's speed that curve,
  // between two speeds the blend of the two (it said "the curve at 1500 rpm", which is none).
  void theSyntheticCurveIsNamedAsUsed() {
    const engine::RunResult none;
    auto message = [&](double rpm) -> QString {
      for (const io::RunWarning& w :
           io::RunWarnings(Config(CoarseCase(), engine::Model::kOnlyLbrbe, rpm), none))
        if (w.code == "synthetic_pressure") return QString::fromStdString(w.message);
      return {};
    };
    QVERIFY2(message(6000).startsWith("the cylinder pressure is the synthetic single-zone curve at "
                                      "6000 rpm (peak "),
             qPrintable(message(6000)));
    QVERIFY2(message(1500).startsWith("the cylinder pressure is blended linearly for 1500 rpm "
                                      "from the synthetic single-zone curves at 1000 and 2000 "
                                      "rpm (peak "),
             qPrintable(message(1500)));
  }

  // A rigid big end whose film pressure peaks above what engine bearings see (the default case
  // at 1000 rpm in thin oil reached 350-700 MPa without a word): warned, naming the elastic
  // shell; not on an elastic shell, not below the limit.
  void aRigidBigEndsHighPressureWarns() {
    engine::RunResult result;
    for (double p : {100e6, 300e6, 50e6}) {
      engine::CrankTrainSample s;
      s.crank_angle = (360.0 + 10.0 * double(result.samples.size())) * M_PI / 180.0;
      s.bearing.present = true;
      s.bearing.max_pressure = p;
      result.samples.push_back(s);
    }
    engine::EngineCase c = CoarseCase();
    auto found = [&]() -> std::optional<io::RunWarning> {
      for (const io::RunWarning& w :
           io::RunWarnings(Config(c, engine::Model::kOnlyLbrbe, 6000.0), result))
        if (w.code == "rigid_big_end_pressure") return w;
      return std::nullopt;
    };
    std::optional<io::RunWarning> w = found();
    QVERIFY(w.has_value());
    QCOMPARE(w->joint, std::string("big_end"));
    QCOMPARE(w->value, 300e6);
    QCOMPARE(w->limit, io::kRigidBigEndPeakPressure);
    QVERIFY(w->crank_angle_deg && std::abs(*w->crank_angle_deg - 370.0) < 1e-9);
    QVERIFY2(QString::fromStdString(w->message)
                 .startsWith("the big-end film pressure peaks at 300 MPa at 370 °CA on rigid "
                             "surfaces (big_end.compliance = rigid), above 250 MPa: "),
             w->message.c_str());
    QVERIFY(QString::fromStdString(w->message).contains("big_end.compliance = elastic_layer"));
    QCOMPARE(io::WarningShortText(*w), std::string("rigid big end 300 MPa"));
    c.big_end.compliance = lubrication::ComplianceModel::kElasticLayer;
    QVERIFY(!found());
    c.big_end.compliance = lubrication::ComplianceModel::kRigid;
    result.samples[1].bearing.max_pressure = 200e6;
    QVERIFY(!found());
  }

  // A compressible oil on the linear density law whose film pressure (sampled or at the steps)
  // passed a tenth of its bulk modulus: the warning names the joint, the peak and where, both
  // laws' compression there and the field to change; none on Dowson and Higginson's law, below
  // the ratio, with an incompressible oil or on a Reynolds film.
  void aLinearDensityLawBeyondItsRangeWarns() {
    engine::RunResult result;
    for (double p : {100e6, 150e6, 50e6}) {
      engine::CrankTrainSample s;
      s.crank_angle = (360.0 + 10.0 * double(result.samples.size())) * M_PI / 180.0;
      s.bearing.present = true;
      s.bearing.max_pressure = p;
      result.samples.push_back(s);
    }
    result.samples[2].bearing.step_peak_pressure = 850e6;  // between the samples, before 380 °CA
    engine::EngineCase c = CoarseCase();
    c.big_end.compliance = lubrication::ComplianceModel::kElasticLayer;  // no rigid-peak warning
    c.big_end.cavitation = lubrication::CavitationModel::kJfo;
    c.lubricant.bulk_modulus = 1.7e9;
    auto found = [&]() -> std::optional<io::RunWarning> {
      for (const io::RunWarning& w :
           io::RunWarnings(Config(c, engine::Model::kOnlyLbrbe, 6000.0), result))
        if (w.code == "linear_density_law") return w;
      return std::nullopt;
    };
    std::optional<io::RunWarning> w = found();
    QVERIFY(w.has_value());
    QCOMPARE(w->joint, std::string("big_end"));
    QCOMPARE(w->value, 850e6);
    QCOMPARE(w->limit, io::kLinearDensityPressureRatio * 1.7e9);
    QVERIFY(w->crank_angle_deg && std::abs(*w->crank_angle_deg - 380.0) < 1e-9);
    // 850 MPa is half of 1.7 GPa: the linear law 50 %, Dowson–Higginson's 0.5/(1 + 0.5/0.353)
    // = 21 %.
    QVERIFY2(QString::fromStdString(w->message)
                 .startsWith("the big-end film pressure reached 850 MPa at 380 °CA, 50 % of its "
                             "oil's bulk modulus (lubricant.bulk_modulus = 1.7 GPa): there the "
                             "linear density law compresses the oil by 50 %, an oil by Dowson and "
                             "Higginson's law 21 %"),
             w->message.c_str());
    QVERIFY(QString::fromStdString(w->message)
                .contains("lubricant.density_law = \"dowson_higginson\""));
    QCOMPARE(io::WarningShortText(*w), std::string("linear density law big end"));
    // The joint's own oil is named by its own field.
    c.big_end.oil.source = engine::OilSource::kOwn;
    c.big_end.oil.own = c.lubricant;
    w = found();
    QVERIFY(w.has_value());
    QVERIFY2(QString::fromStdString(w->message).contains("(big_end.oil.bulk_modulus = 1.7 GPa)"),
             w->message.c_str());
    c.big_end.oil.own.density_law = lubrication::DensityLaw::kDowsonHigginson;
    QVERIFY(!found());
    c.big_end.oil.source = engine::OilSource::kLubricant;
    QVERIFY(found());
    result.samples[2].bearing.step_peak_pressure = 160e6;  // below 170 MPa
    QVERIFY(!found());
    result.samples[2].bearing.step_peak_pressure = 850e6;
    c.lubricant.bulk_modulus = 0.0;
    QVERIFY(!found());
    c.lubricant.bulk_modulus = 1.7e9;
    c.big_end.cavitation = lubrication::CavitationModel::kReynolds;
    QVERIFY(!found());
  }

  // A high eccentricity says how close the journal runs to the wall; past ε = 1 (elastic
  // surfaces) its rigid position is past the wall, not "within −5.6 µm" of it.
  void aHighEccentricitySaysWhereTheJournalRuns() {
    for (const double eps : {0.97, 1.113}) {
      engine::RunResult result;
      for (double e : {0.5, eps, 0.6}) {
        engine::CrankTrainSample s;
        s.crank_angle = (360.0 + 10.0 * double(result.samples.size())) * M_PI / 180.0;
        s.bearing.present = true;
        s.bearing.eps = e;
        result.samples.push_back(s);
      }
      const engine::EngineCase c = CoarseCase();
      std::string message;
      for (const io::RunWarning& w :
           io::RunWarnings(Config(c, engine::Model::kOnlyLbrbe, 6000.0), result))
        if (w.code == "high_eccentricity") message = w.message;
      const double gap_um = (1.0 - eps) * engine::BigEndFit(c).hot_clearance * 1e6;
      qInfo("%s", message.c_str());
      QVERIFY2(message.find(eps < 1.0 ? fmt::format("within {:.1f} µm of the bearing wall", gap_um)
                                      : fmt::format("{:.1f} µm past the bearing wall", -gap_um)) !=
                   std::string::npos,
               message.c_str());
      QVERIFY(message.find("within -") == std::string::npos);
    }
  }

  // A failed run's last row, where the skirt had passed the liner's wall: the film-ratio warning
  // says the surfaces overlap there, not that asperities carry part of the load.
  void aFilmRatioBelowZeroSaysTheSurfacesOverlap() {
    engine::RunResult result;
    for (double moft : {5e-6, 2e-7, -3.1e-7}) {
      engine::CrankTrainSample s;
      s.crank_angle = (360.0 + double(result.samples.size())) * M_PI / 180.0;
      s.skirt.present = true;
      s.skirt.moft = moft;
      result.samples.push_back(s);
    }
    result.status = engine::RunStatus::kFailed;
    const engine::EngineCase c = CoarseCase();
    std::string message;
    for (const io::RunWarning& w :
         io::RunWarnings(Config(c, engine::Model::kOnlySkirt, 6000.0), result))
      if (w.code == "asperity_contact" && w.joint == "skirt") message = w.message;
    qInfo("%s", message.c_str());
    QVERIFY2(message.find("the surfaces overlap by 0.31 µm there, where the run ended") !=
                 std::string::npos,
             message.c_str());
    QVERIFY(message.find("asperities carry") == std::string::npos);
  }

  void halfSpaceBigEndWarns() {
    // Judged from the case: a big end on elastic half-spaces, which engine runs outgrow; not the
    // skirt's half-spaces, nor the big end's elastic layer.
    const engine::RunResult none;
    auto warnings = [&](const engine::EngineCase& c) {
      return io::RunWarnings(Config(c, engine::Model::kSkirtLbrbe, 6000.0), none);
    };
    auto has = [&](const engine::EngineCase& c) {
      const auto w = warnings(c);
      return std::any_of(w.begin(), w.end(), [](const io::RunWarning& x) {
        return x.code == "half_space_big_end" && x.joint == "big_end";
      });
    };
    engine::EngineCase c = CoarseCase();
    QVERIFY(!has(c));
    c.skirt.compliance = lubrication::ComplianceModel::kHalfSpace;
    QVERIFY(!has(c));
    c.big_end.compliance = lubrication::ComplianceModel::kElasticLayer;
    QVERIFY(!has(c));
    c.big_end.compliance = lubrication::ComplianceModel::kHalfSpace;
    QVERIFY(has(c));
    for (const io::RunWarning& x : warnings(c))
      if (x.code == "half_space_big_end") {
        QVERIFY(QString::fromStdString(x.message).contains("big_end.compliance = elastic_layer"));
        QCOMPARE(QString::fromStdString(io::WarningShortText(x)), QString("half-space big end"));
      }
  }

  void anImplausibleSupplyPressureWarns() {
    // Judged from the case: the supply pressure the run reads, the constant or a curve's peak,
    // above what engine oil systems deliver (a value in the wrong unit otherwise "completes");
    // not a real gallery pressure, not a constant the curve leaves unused, not an ideal big end.
    const engine::RunResult none;
    auto found = [&](const engine::EngineCase& c,
                     engine::Model model =
                         engine::Model::kSkirtLbrbe) -> std::optional<io::RunWarning> {
      for (const io::RunWarning& x : io::RunWarnings(Config(c, model, 6000.0), none)) {
        if (x.code == "high_supply_pressure") return x;
      }
      return std::nullopt;
    };
    engine::EngineCase c = CoarseCase();
    c.big_end.supply = lubrication::OilFeedKind::kPinHoles;
    c.big_end.oil_feed_pressure = 0.5e6;
    QVERIFY(!found(c));
    c.big_end.oil_feed_pressure = 1e9;
    std::optional<io::RunWarning> w = found(c);
    QVERIFY(w.has_value());
    QCOMPARE(w->joint, std::string("big_end"));
    QCOMPARE(w->value, 1e9);
    QCOMPARE(w->limit, io::kHighestSupplyPressure);
    QVERIFY(!w->crank_angle_deg);
    QVERIFY2(QString::fromStdString(w->message)
                 .startsWith("the big end's oil-supply pressure (big_end.oil_feed_pressure) is "
                             "1000 MPa, above the 2 MPa"),
             w->message.c_str());
    QCOMPARE(io::WarningShortText(*w), std::string("supply 1e+03 MPa"));
    // A curve: its peak and where; the constant beside it is unused and not judged.
    for (int k = 0; k < 72; ++k) {
      c.big_end.supply_pressure_angles.push_back(k * 10.0 * std::numbers::pi / 180.0);
      c.big_end.supply_pressure_values.push_back(k == 36 ? 3e6 : 0.4e6);
    }
    w = found(c);
    QVERIFY(w.has_value());
    QCOMPARE(w->value, 3e6);
    QVERIFY(w->crank_angle_deg && std::abs(*w->crank_angle_deg - 360.0) < 1e-9);
    QVERIFY2(QString::fromStdString(w->message)
                 .contains("(big_end.supply_pressure_values, its "
                           "peak at 360 °CA) is 3 MPa"),
             w->message.c_str());
    c.big_end.supply_pressure_values[36] = 0.4e6;
    QVERIFY(!found(c));  // 1 GPa constant, unused beside the curve
    c.big_end.supply_pressure_values[36] = 3e6;
    QVERIFY(!found(c, engine::Model::kOnlySkirt));
  }

  void heatBalanceOfAConstantViscosityWarns() {
    // Judged from the case: a joint in heat-balance mode whose oil's viscosity does not follow
    // temperature (the default lubricant is a constant 20 mPa s) — per joint, naming the field
    // that gives the oil its law; not with a Vogel oil, nor with a given film temperature.
    const engine::RunResult none;
    auto found = [&](const engine::EngineCase& c,
                     const char* joint) -> std::optional<io::RunWarning> {
      for (const io::RunWarning& x :
           io::RunWarnings(Config(c, engine::Model::kSkirtLbrbe, 6000.0), none)) {
        if (x.code == "heat_balance_constant_viscosity" && x.joint == joint) return x;
      }
      return std::nullopt;
    };
    engine::EngineCase c = CoarseCase();
    QVERIFY(!found(c, "skirt") && !found(c, "big_end"));
    c.big_end.oil.temperature_mode = engine::FilmTemperature::kHeatBalance;
    const auto w = found(c, "big_end");
    QVERIFY(w && !found(c, "skirt"));
    QVERIFY2(QString::fromStdString(w->message).contains("lubricant.viscosity_model = constant"),
             w->message.c_str());
    QCOMPARE(QString::fromStdString(io::WarningShortText(*w)),
             QString("heat balance, constant viscosity"));
    c.skirt.oil.temperature_mode = engine::FilmTemperature::kHeatBalance;
    c.skirt.oil.source = engine::OilSource::kOwn;  // its own oil, constant too
    const auto s = found(c, "skirt");
    QVERIFY(s);
    QVERIFY2(QString::fromStdString(s->message).contains("skirt.oil.viscosity_model = constant"),
             s->message.c_str());
    c.lubricant.model = lubrication::ViscosityModel::kVogel;  // the big end's oil follows T now
    QVERIFY(!found(c, "big_end") && found(c, "skirt"));
  }

  void supplyHoleOnACoarseMeshWarns() {
    // Judged from the case: a JFO big end fed through a 4 mm crank-pin hole on the default mesh
    // (100 around, 10 graded 4:1 across: only the mid-width row inside the hole) warns and names
    // a mesh that holds it; on that mesh, a Reynolds film or no holes, it does not.
    const engine::RunResult none;
    auto find = [&](const engine::EngineCase& c) -> std::optional<io::RunWarning> {
      for (const io::RunWarning& x :
           io::RunWarnings(Config(c, engine::Model::kOnlyLbrbe, 2000.0), none))
        if (x.code == "supply_hole_mesh") return x;
      return std::nullopt;
    };
    engine::EngineCase c = engine::EngineCase{};
    c.big_end.cavitation = lubrication::CavitationModel::kJfo;
    c.big_end.supply = lubrication::OilFeedKind::kPinHoles;
    c.big_end.oil_feed_pressure = 3e5;
    QCOMPARE(c.big_end.mesh_theta, 100);
    QCOMPARE(c.big_end.mesh_z, 10);
    const auto w = find(c);
    QVERIFY(w.has_value());
    QCOMPARE(w->joint, std::string("big_end"));
    QCOMPARE(w->value, 1.0);  // the mid-width row alone
    QCOMPARE(w->limit, double(io::kHoleRowsAcross));
    const QString text = QString::fromStdString(w->message);
    qInfo("%s", qPrintable(text));
    QVERIFY(text.contains("big_end.mesh_z = 10") && text.contains("1 row of"));
    QCOMPARE(QString::fromStdString(io::WarningShortText(*w)),
             QString("supply hole on a coarse mesh"));
    // The mesh it names holds the hole: no warning there.
    const QRegularExpression named("big_end.mesh_z = (\\d+) and big_end.mesh_theta = (\\d+)");
    const QRegularExpressionMatch m = named.match(text);
    QVERIFY(m.hasMatch());
    engine::EngineCase fine = c;
    fine.big_end.mesh_z = m.captured(1).toInt();
    fine.big_end.mesh_theta = m.captured(2).toInt();
    QCOMPARE(fine.big_end.mesh_z, 20);       // rows at 0 and ±1.7 mm, within 0.9 × 2 mm
    QCOMPARE(fine.big_end.mesh_theta, 100);  // 4.3 mean elements across the hole
    QVERIFY(!find(fine).has_value());
    // 20 across but 50 around (the hole spans 2.1 mean elements; at 10 across the oil on 50
    // around was 3.6 % below 100 around): coarse.
    engine::EngineCase across_only = fine;
    across_only.big_end.mesh_theta = 50;
    QVERIFY(find(across_only).has_value());
    // A hole too small for any mesh the case allows (a 10 µm hole needs 38 000 elements around).
    engine::EngineCase pinhole = c;
    pinhole.big_end.supply_hole_diameter = 1e-5;
    const auto tiny = find(pinhole);
    QVERIFY(tiny.has_value());
    QVERIFY(QString::fromStdString(tiny->message).contains("no mesh the case allows"));
    engine::EngineCase reynolds = c;
    reynolds.big_end.cavitation = lubrication::CavitationModel::kReynolds;
    QVERIFY(!find(reynolds).has_value());
    engine::EngineCase groove = c;
    groove.big_end.supply = lubrication::OilFeedKind::kGroove;
    QVERIFY(!find(groove).has_value());
  }

  // Two impacts of a starved skirt in one cycle (at both reversals), one caught in part by a
  // sample, one seen only by the integrator's steps between two samples: the warning leads with
  // the larger (the steps'), at its crank angle, and says the largest sample is another spike;
  // the steps' peak beside that sample is the same spike's; steps' peaks within 1.5 times the
  // largest sample leave the caught spike the warning's subject.
  void unresolvedPeaksAtTwoPlacesAreToldApart() {
    const engine::RunConfig config = Config(CoarseCase(), engine::Model::kSkirtLbrbe, 6000.0);
    engine::RunResult result;
    result.status = engine::RunStatus::kCompleted;
    const int n = 720;  // a whole cycle, 1 °CA apart
    result.samples.resize(n);
    for (int k = 0; k < n; ++k) {
      engine::CrankTrainSample& s = result.samples[std::size_t(k)];
      s.crank_angle = 4.0 * M_PI * k / n;
      s.time = 1e-5 * k;
      s.skirt.present = true;
      s.skirt.max_pressure = s.skirt.step_peak_pressure = 7e6;
    }
    auto& at = result.samples;
    at[554].skirt.max_pressure = at[554].skirt.step_peak_pressure = 0.0;
    at[555].skirt.max_pressure = 147.2e6;  // caught: 13 times the samples beside it
    at[555].skirt.step_peak_pressure = 180e6;
    at[556].skirt.max_pressure = 11.2e6;
    at[556].skirt.step_peak_pressure = 151e6;
    at[88].skirt.step_peak_pressure = 368e6;  // the steps in (87, 88] °CA: 2.5 times
    // The skirt's warning: at `angle`, its message holding `text`; returns its value.
    const auto expect = [&](double angle, const char* text) {
      for (const io::RunWarning& w : io::RunWarnings(config, result)) {
        if (w.code != "unresolved_peak" || w.joint != "skirt") continue;
        if (*w.crank_angle_deg != angle || !QString::fromStdString(w.message).contains(text))
          qWarning("at %g °CA: %s", *w.crank_angle_deg, w.message.c_str());
        return *w.crank_angle_deg == angle && QString::fromStdString(w.message).contains(text)
                   ? w.value
                   : -1.0;
      }
      return -1.0;
    };
    QCOMPARE(expect(88.0,
                    "miss a spike of the skirt film pressure: the integrator's steps between the "
                    "samples reached 368 MPa in the output interval before 88 °CA, 2.5 times the "
                    "largest sample (147.2 MPa at 555 °CA, itself another spike: the samples "
                    "beside it show 0 and 11.2 MPa)"),
             147.2 / 11.2);  // the larger ratio
    // The steps' larger peak right after the caught sample: one spike.
    at[88].skirt.step_peak_pressure = 7e6;
    at[556].skirt.step_peak_pressure = 368e6;
    QVERIFY(expect(556.0,
                   "(147.2 MPa at 555 °CA, the same spike's edge: the samples beside it "
                   "show 0 and 11.2 MPa)") > 0.0);
    // Steps' peaks within 1.5 times the largest sample: the caught spike, the steps' elsewhere.
    at[556].skirt.step_peak_pressure = 151e6;
    at[88].skirt.step_peak_pressure = 200e6;
    QVERIFY(expect(555.0,
                   "147.2 MPa at 555 °CA is a spike the output samples do not resolve "
                   "(the samples beside it show 0 and 11.2 MPa; elsewhere, the "
                   "integrator's steps between the samples reached 200 MPa in the output "
                   "interval before 88 °CA)") > 0.0);
  }

  void thickFilmsGiveNoFilmWarnings() {
    engine::EngineCase c = CoarseCase();
    c.lubricant.viscosity = 0.08;  // 4 x the default: films far thicker than the roughness
    const engine::RunConfig config = Config(c, engine::Model::kSkirtLbrbe, 6000.0);
    ProgressTrace trace;
    const engine::RunResult result = engine::RunJob(config, trace.Monitor());
    QCOMPARE(engine::StatusName(result.status), std::string("completed"));
    CheckProgress(trace, result);
    const double sigma = std::hypot(c.big_end.roughness_journal, c.big_end.roughness_bearing);
    double min_ratio = INFINITY;
    for (const engine::CrankTrainSample& s : result.samples) {
      min_ratio = std::min(min_ratio, s.bearing.moft / sigma);
    }
    QVERIFY2(min_ratio >= io::kMixedLubricationRatio, qPrintable(QString::number(min_ratio)));
    for (const io::RunWarning& w : io::RunWarnings(config, result)) {
      QVERIFY2(w.code != "asperity_contact" && w.code != "mixed_lubrication" &&
                   w.code != "high_eccentricity" && w.code != "not_periodic",
               w.message.c_str());
    }
  }

  // Three cycles against a tolerance no run meets: from cycle 3 on the progress carries the
  // last compared cycle's change (CheckProgress), and the warning tells how the two changes fell.
  void progressAndWarningTellHowTheChangeFell() {
    engine::EngineCase c = CoarseCase();
    c.solver.max_cycles = 3;
    c.solver.steady_state_tolerance = 1e-12;
    const engine::RunConfig config = Config(c, engine::Model::kOnlyLbrbe, 6000.0);
    ProgressTrace trace;
    const engine::RunResult result = engine::RunJob(config, trace.Monitor());
    QCOMPARE(engine::StatusName(result.status), std::string("not-converged"));
    QCOMPARE(result.cycle_changes.size(), std::size_t(2));
    QVERIFY(std::count(trace.cycle.begin(), trace.cycle.end(), 3) > 10);
    CheckProgress(trace, result);
    const std::vector<io::RunWarning> warnings = io::RunWarnings(config, result);
    const auto w = std::find_if(warnings.begin(), warnings.end(),
                                [](const io::RunWarning& x) { return x.code == "not_periodic"; });
    QVERIFY(w != warnings.end());
    QVERIFY2(QString::fromStdString(w->message)
                 .contains(QString::fromStdString(engine::CycleChangeTrend(
                     result.cycle_changes, c.solver.steady_state_tolerance))),
             w->message.c_str());
    QVERIFY2(QString::fromStdString(w->message)
                 .contains("the change after each cycle from cycle 2 on: "),
             w->message.c_str());
    // The status message and the warning name the quantity in words (they showed the results
    // column's name, "bearing_eps[-]", and the change as a fraction with six decimals).
    const QRegularExpression status(
        "^no periodic steady state after 3 cycles \\(the last change [0-9.e+-]+ % of the range "
        "of (the big end's minimum film|the big-end eccentricity ratio)\\)$");
    QVERIFY2(status.match(QString::fromStdString(result.message)).hasMatch(),
             result.message.c_str());
    QVERIFY2(QString::fromStdString(w->message).contains("of the range of the big"),
             w->message.c_str());
  }

  void idealJointsGiveNoFilmWarnings() {
    const engine::RunConfig config = Config(CoarseCase(), engine::Model::kIdeal, 6000.0);
    ProgressTrace trace;
    const engine::RunResult result = engine::RunJob(config, trace.Monitor());
    QCOMPARE(engine::StatusName(result.status), std::string("completed"));
    CheckProgress(trace, result);
    for (const io::RunWarning& w : io::RunWarnings(config, result)) {
      QVERIFY2(w.code != "asperity_contact" && w.code != "mixed_lubrication" &&
                   w.code != "high_eccentricity" && w.code != "not_periodic",
               w.message.c_str());
      QVERIFY(w.joint.empty());
    }
    // Ideal joints: empty film peaks, zero friction parts.
    const io::OutputRow r = io::RowFromSample(result.samples.at(100), config.model, 0.0);
    QVERIFY(!r.skirt_peak_pressure && !r.bearing_peak_pressure && !r.bearing_peak_contact_pressure);
    QCOMPARE(*r.skirt_contact_fpl, 0.0);
    QCOMPARE(*r.bearing_contact_friction_force, 0.0);
  }

  void stoppedBeforePeriodicWarns() {
    engine::EngineCase c = CoarseCase();
    c.solver.run_in_angle = 0.0;  // the start-up transient is still in cycle 2
    c.solver.max_cycles = 2;
    const engine::RunConfig config = Config(c, engine::Model::kOnlyLbrbe, 6000.0);
    ProgressTrace trace;
    const engine::RunResult result = engine::RunJob(config, trace.Monitor());
    QCOMPARE(engine::StatusName(result.status), std::string("not-converged"));
    CheckProgress(trace, result);
    const std::vector<io::RunWarning> warnings = io::RunWarnings(config, result);
    const auto w = std::find_if(warnings.begin(), warnings.end(),
                                [](const io::RunWarning& x) { return x.code == "not_periodic"; });
    QVERIFY(w != warnings.end());
    QCOMPARE(w->value, result.cycle_change);
    QVERIFY(w->value > c.solver.steady_state_tolerance);
    QCOMPARE(w->limit, c.solver.steady_state_tolerance);
    QVERIFY(QString::fromStdString(w->message).contains("2 cycles"));
    // One compared cycle: its change, no trend to tell (engine::CycleChangeTrend needs two).
    QCOMPARE(result.cycle_changes, std::vector<double>{result.cycle_change});
    QVERIFY(!QString::fromStdString(w->message).contains("the change after each cycle"));
    // One set of headline figures per cycle, the last the reported cycle's; the warning says how
    // far they moved (cycle 2 still holds the start-up transient: more than ±0.1 %).
    QCOMPARE(result.cycle_headlines.size(), std::size_t(2));
    const std::vector<engine::HeadlineFigure> reported = engine::HeadlineFigures(result.samples);
    QCOMPARE(result.cycle_headlines.back().size(), reported.size());
    for (std::size_t i = 0; i < reported.size(); ++i)
      QCOMPARE(result.cycle_headlines.back()[i].value, reported[i].value);
    const auto scatter = engine::ScatterOverCycles(result.cycle_headlines, result.samples, true);
    QVERIFY(scatter);
    QCOMPARE(scatter->first_cycle, 1);
    QCOMPARE(scatter->last_cycle, 2);
    for (std::size_t i = 0; i < reported.size(); ++i) {
      const double a = result.cycle_headlines[0][i].value, b = reported[i].value;
      QCOMPARE(scatter->figures[i].min, std::min(a, b));
      QCOMPARE(scatter->figures[i].max, std::max(a, b));
    }
    QVERIFY2(QString::fromStdString(w->message)
                 .contains("over cycles 1–2 the headline figures moved by up to ±"),
             w->message.c_str());
  }
};

QTEST_GUILESS_MAIN(TestRunWarnings)
#include "test_run_warnings.moc"
