#include "core/io/run_warnings.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <tuple>
#include <utility>

#include "core/base/angles.hpp"
#include "core/base/input_error.hpp"
#include "core/engine/case_schema.hpp"
#include "core/engine/error_estimate.hpp"
#include "core/engine/film_joints.hpp"
#include "core/io/case_file.hpp"
#include "core/io/results_writer.hpp"
#include "core/io/run_kpis.hpp"
#include "core/lubrication/bearing_solver.hpp"
#include "core/lubrication/oil_catalogue.hpp"

namespace filmdyn::io {

namespace {

// The crank angle of a sample within the reported cycle [°CA] (results.csv's first column).
double CrankAngleDeg(const engine::CrankTrainSample& s) {
  return CycleCrankAngleDeg(s.crank_angle);
}

// "355–390 °CA" pieces of the intervals where `crossed` holds, one per run of consecutive
// samples; the first and last merge into one interval wrapping past 720 °CA when the samples
// are a whole cycle.
std::vector<std::pair<double, double>> Ranges(const std::vector<double>& angles,
                                              const std::vector<bool>& crossed, bool whole_cycle) {
  std::vector<std::pair<double, double>> ranges;
  for (std::size_t i = 0; i < crossed.size(); ++i) {
    if (!crossed[i]) continue;
    if (i > 0 && crossed[i - 1] && !ranges.empty()) {
      ranges.back().second = angles[i];
    } else {
      ranges.push_back({angles[i], angles[i]});
    }
  }
  if (whole_cycle && ranges.size() > 1 && crossed.front() && crossed.back()) {
    ranges.front().first = ranges.back().first;  // from > to: wraps
    ranges.pop_back();
  }
  return ranges;
}

std::string RangesText(const std::vector<std::pair<double, double>>& ranges) {
  std::string text;
  for (std::size_t k = 0; k < ranges.size(); ++k) {
    if (k) text += ", ";
    text += ranges[k].first == ranges[k].second
                ? fmt::format("{:.0f}", ranges[k].first)
                : fmt::format("{:.0f}–{:.0f}", ranges[k].first, ranges[k].second);
  }
  return text + " °CA";
}

// The film-ratio warning of one joint (the worse of the two limits), if any.
void FilmRatioWarning(const std::vector<engine::CrankTrainSample>& samples, bool skirt,
                      double sigma, bool whole_cycle, std::vector<RunWarning>* out) {
  if (samples.empty() || !(sigma > 0.0)) return;
  std::vector<double> angles, ratios;
  for (const engine::CrankTrainSample& s : samples) {
    const bool present = skirt ? s.skirt.present : s.bearing.present;
    const double moft = skirt ? s.skirt.moft : s.bearing.moft;
    angles.push_back(CrankAngleDeg(s));
    ratios.push_back(present && std::isfinite(moft) ? moft / sigma : INFINITY);
  }
  const auto worst = std::min_element(ratios.begin(), ratios.end()) - ratios.begin();
  const double lambda = ratios[std::size_t(worst)];
  if (!(lambda < kMixedLubricationRatio)) return;
  const bool contact = lambda < kAsperityContactRatio;
  RunWarning w;
  w.code = contact ? "asperity_contact" : "mixed_lubrication";
  w.joint = skirt ? "skirt" : "big_end";
  w.value = lambda;
  w.limit = contact ? kAsperityContactRatio : kMixedLubricationRatio;
  w.crank_angle_deg = angles[std::size_t(worst)];
  std::vector<bool> crossed;
  for (double r : ratios) crossed.push_back(r < w.limit);
  w.crank_angle_ranges_deg = Ranges(angles, crossed, whole_cycle);
  const FilmPosition position = MinFilmPosition(samples[std::size_t(worst)], skirt);
  w.position_angle_deg = position.angle_deg;
  w.position_axial_m = position.axial_m;
  const std::string where =
      skirt ? fmt::format("{:.0f}° from the thrust axis, {:.1f} mm below the skirt top",
                          position.angle_deg, position.axial_m.value_or(0.0) * 1e3)
            : fmt::format("{:.0f}° around the big-end eye in the rod frame", position.angle_deg);
  const double moft = lambda * sigma;
  w.message = fmt::format(
      "{} film thickness ratio h/σ = {:.2f} (minimum film {:.3g} µm, composite roughness σ = "
      "{:.3g} µm) at {:.0f} °CA, at {}; below {:g} over {}: {}",
      skirt ? "skirt" : "big-end", lambda, moft * 1e6, sigma * 1e6, *w.crank_angle_deg, where,
      w.limit, RangesText(w.crank_angle_ranges_deg),
      !(moft > 0.0)  // a failed run's last row: the surfaces met (no film there)
          ? fmt::format("the surfaces overlap by {:.3g} µm there, where the run ended",
                        std::max(0.0, -moft) * 1e6)
          : contact ? "the surface asperities carry part of the load (asperity contact, boundary "
                      "friction and wear)"
                    : "mixed lubrication, the film is only a few roughness heights thick");
  out->push_back(std::move(w));
}

// Peak film pressures the output samples do not resolve in time (engine::SampledPeak), one
// warning per joint.
void UnresolvedPeakWarnings(const std::vector<engine::CrankTrainSample>& samples,
                            double output_interval, bool whole_cycle,
                            std::vector<RunWarning>* out) {
  for (const engine::SampledPeak& peak : engine::SampledPeaks(samples, whole_cycle)) {
    if (!peak.Unresolved()) continue;
    RunWarning w;
    w.code = "unresolved_peak";
    w.joint = peak.figure.big_end ? "big_end" : "skirt";
    w.value =
        std::min(std::max(peak.Ratio(), peak.StepRatio()), std::numeric_limits<double>::max());
    w.limit = engine::kUnresolvedPeakRatio;
    const bool caught = peak.Ratio() > engine::kUnresolvedPeakRatio;
    const bool missed = peak.StepRatio() > engine::kUnresolvedPeakRatio;
    const double step_at = CrankAngleDeg(samples[peak.step_index]);
    const double sample_at = CrankAngleDeg(samples[peak.index]);
    // Whether the steps' peak lies in an output interval next to the largest sample (ending or
    // starting at it): the same event, else two (a starved skirt's slap at both reversals).
    const bool beside_sample =
        peak.step_index == peak.index || peak.step_index == peak.index + 1 ||
        (whole_cycle && peak.index + 1 == samples.size() && peak.step_index == 0);
    const std::string steps = fmt::format(
        "the integrator's steps between the samples reached {:.4g} MPa in the output "
        "interval before {:.4g} °CA",
        peak.step_peak * 1e-6, step_at);
    std::string neighbours;  // of the largest sample
    for (double v : {peak.before, peak.after}) {
      if (!std::isfinite(v)) continue;
      neighbours += fmt::format("{}{:.3g}", neighbours.empty() ? "" : " and ", v * 1e-6);
    }
    const std::string why = fmt::format(
        "it lasts less than about three output intervals ({:.3g} °CA), so the peak figure is "
        "whatever the samples caught (an impact: a big-end journal or a skirt crossing a "
        "cavitated or starved film onto the full film beyond it); a smaller "
        "solver.output_interval resolves it",
        output_interval * kDegreesPerRadian);
    if (missed) {
      // The steps saw more than the samples did: the cycle's highest pressure is there.
      w.crank_angle_deg = step_at;
      std::string sample =
          fmt::format("{:.4g} MPa at {:.4g} °CA", peak.figure.value * 1e-6, sample_at);
      if (caught) {
        sample += fmt::format(", {}: the samples beside it show {} MPa",
                              beside_sample ? "the same spike's edge" : "itself another spike",
                              neighbours);
      }
      w.message = fmt::format(
          "the output samples miss a spike of the {} film pressure: {}, {:.2g} times the largest "
          "sample ({}); {}",
          peak.figure.big_end ? "big-end" : "skirt", steps, peak.StepRatio(), sample, why);
    } else {
      // The samples caught the spike in part: it stands out of the samples beside it.
      w.crank_angle_deg = sample_at;
      std::string seen;
      if (peak.StepRatio() > 1.0)
        seen = "; " + std::string(beside_sample ? "" : "elsewhere, ") + steps;
      w.message = fmt::format(
          "{} {:.4g} MPa at {:.4g} °CA is a spike the output samples do not resolve (the samples "
          "beside it show {} MPa{}): {}",
          peak.figure.label, peak.figure.value * 1e-6, sample_at, neighbours, seen, why);
    }
    out->push_back(std::move(w));
  }
}

// The embedded default case, read once.
const LoadedCase* DefaultCase() {
  static const std::optional<LoadedCase> loaded = []() -> std::optional<LoadedCase> {
    try {
      return LoadCase("");
    } catch (const std::exception&) {
      return std::nullopt;
    }
  }();
  return loaded ? &*loaded : nullptr;
}

// A value counts as the default case's within this share of it: a case saved by the editor,
// whose values were typed in display units (µm, mm), can differ from it in the last bits. A
// choice the default case marks assumed (its big end's oil supply: none given) counts like a
// number; the others (the joints' models) are not in its assumed list.
constexpr double kSameAsDefault = 1e-12;

// Whether `path` is a field of a joint that is ideal in this case (a case keeps its films' data
// when a model switches them off: not the run's inputs).
bool OfAnIdealJoint(const std::string& path, const engine::EngineCase& c) {
  return (c.skirt.model != engine::JointModel::kLubricated && path.rfind("skirt.", 0) == 0) ||
         (c.big_end.model != engine::JointModel::kLubricated && path.rfind("big_end.", 0) == 0);
}

// The physical inputs this run's case notes as assumed — its own notes, or the default case's
// for a field its file leaves out (io::CaseFromJson) — that it still uses at the default case's
// value. A value the user gave (a file that states it, `--set`, an edit in the editor) carries
// no note. Numerical settings (solver group: meshes, tolerances) are left out: the
// discretisation-error estimate judges those. Fields of a joint that is ideal in this run do not
// count.
void AssumedInputsWarning(const engine::EngineCase& c, std::vector<RunWarning>* out) {
  const LoadedCase* reference = DefaultCase();
  if (!reference) return;
  const engine::EngineCase& assumed_case = reference->value;
  RunWarning w;
  for (const auto& [path, reason] : c.assumed) {
    const engine::CaseField* f = engine::FindCaseField(path);
    if (!f || f->group == engine::FieldGroup::kSolver || OfAnIdealJoint(path, c)) continue;
    if (!engine::UnusedReason(c, path).empty()) continue;  // the run does not read it
    if (f->SameValue(c, assumed_case, kSameAsDefault)) w.fields.push_back(path);
  }
  if (w.fields.empty()) return;
  w.code = "assumed_inputs";
  w.value = static_cast<double>(w.fields.size());
  std::string names;
  for (std::size_t k = 0; k < w.fields.size(); ++k) names += (k ? ", " : "") + w.fields[k];
  w.message = fmt::format(
      "{} input{} at the default case's assumed value, not a known one (the case's \"assumed\" "
      "notes: a field the case file leaves out takes the default case's; the editor's notes and "
      "docs/case-file.md give each reason): {}",
      w.fields.size(), w.fields.size() == 1 ? " is" : "s are", names);
  out->push_back(std::move(w));
}

// Inputs given a value other than the default case's that this run does not read, because the
// case's choices leave them unused (a constant supply pressure beside a supply-pressure curve,
// Vogel constants of a constant-viscosity oil, a compliance file of rigid surfaces): a value set
// on purpose and silently ignored. Fields of a joint that is ideal in this run do not count (a
// case keeps its films' data when a model switches them off).
void UnusedInputsWarning(const engine::EngineCase& c, std::vector<RunWarning>* out) {
  const LoadedCase* reference = DefaultCase();
  if (!reference) return;
  RunWarning w;
  std::string list;
  for (const engine::CaseField& f : engine::CaseSchema()) {
    if (OfAnIdealJoint(f.path, c)) continue;
    const std::string why = engine::UnusedReason(c, f.path);
    if (why.empty() || f.SameValue(c, reference->value, kSameAsDefault)) continue;
    w.fields.push_back(f.path);
    list += (list.empty() ? "" : "; ") + f.path + " (" + why + ")";
  }
  if (w.fields.empty()) return;
  w.code = "unused_inputs";
  w.value = static_cast<double>(w.fields.size());
  w.message = fmt::format("{} input{} set but not read by this run: {}", w.fields.size(),
                          w.fields.size() == 1 ? " is" : "s are", list);
  out->push_back(std::move(w));
}

// The run's cylinder pressure is the default case's synthetic curve at this speed.
void SyntheticPressureWarning(const engine::RunConfig& config, std::vector<RunWarning>* out) {
  const LoadedCase* reference = DefaultCase();
  if (!reference || config.pressure.Empty()) return;
  engine::PressureCurve synthetic;
  try {
    synthetic = PressureCurveForSpeed(*reference, config.rpm);
  } catch (const std::exception&) {
    return;  // a speed the synthetic curves do not cover: the run's curve is another one
  }
  const double peak = synthetic.PeakPressure();
  for (int k = 0; k < 720; ++k) {
    const double phi = k * kRadiansPerDegree;
    if (std::abs(config.pressure.Pressure(phi) - synthetic.Pressure(phi)) > 1e-9 * peak) return;
  }
  // Between the speeds of the synthetic curves the run's curve is blended from the two beside
  // it (PressureCurveForSpeed): said so, not "the curve at 1500 rpm".
  double below = -1.0, above = -1.0;
  bool at_a_curve = false;
  for (const engine::PressureCurveSource& source : reference->value.pressure_curves) {
    if (std::abs(source.rpm - config.rpm) <= 1e-9 * config.rpm) at_a_curve = true;
    if (source.rpm < config.rpm && source.rpm > below) below = source.rpm;
    if (source.rpm > config.rpm && (above < 0.0 || source.rpm < above)) above = source.rpm;
  }
  const std::string which =
      at_a_curve || below < 0.0 || above < 0.0
          ? fmt::format("the synthetic single-zone curve at {:g} rpm", config.rpm)
          : fmt::format(
                "blended linearly for {:g} rpm from the synthetic single-zone curves at {:g} and "
                "{:g} rpm",
                config.rpm, below, above);
  RunWarning w;
  w.code = "synthetic_pressure";
  w.value = config.pressure.PeakPressure();
  w.crank_angle_deg = config.pressure.PeakAngle() * kDegreesPerRadian;
  w.message = fmt::format(
      "the cylinder pressure is {} (peak {:.2f} MPa, {:.1f} bar, at {:.0f} °CA), not a measured "
      "one (docs/pressure-model.md); give a measured curve with --pressure-curve or the case's "
      "pressure_curves",
      which, w.value * 1e-6, w.value * 1e-5, *w.crank_angle_deg);
  out->push_back(std::move(w));
}

// A cylinder pressure whose peak is below what any running engine compresses to: most likely a
// curve in bar or MPa read as Pa, or a gauge pressure (the curve is absolute, in Pa).
void LowCylinderPressureWarning(const engine::RunConfig& config, std::vector<RunWarning>* out) {
  if (config.pressure.Empty()) return;
  const double peak = config.pressure.PeakPressure();
  if (peak >= kLowestPeakCylinderPressure) return;
  RunWarning w;
  w.code = "low_cylinder_pressure";
  w.value = peak;
  w.limit = kLowestPeakCylinderPressure;
  w.crank_angle_deg = config.pressure.PeakAngle() * kDegreesPerRadian;
  w.message = fmt::format(
      "the cylinder pressure peaks at {:.4g} Pa ({:.3g} bar) at {:.0f} °CA, below the {:g} bar "
      "any running engine compresses to (the crankcase is at {:.3g} bar): is the curve in bar or "
      "MPa, or a gauge pressure? It is read as an absolute pressure in Pa",
      peak, peak * 1e-5, *w.crank_angle_deg, kLowestPeakCylinderPressure * 1e-5,
      config.engine_case.operating.crankcase_pressure * 1e-5);
  out->push_back(std::move(w));
}

// A cylinder pressure peaking far from firing TDC (360 °CA): most likely a curve whose firing
// TDC is at 0 °CA, which the run reads a whole revolution late.
void FiringAngleWarning(const engine::RunConfig& config, std::vector<RunWarning>* out) {
  if (config.pressure.Empty()) return;
  const double peak = config.pressure.PeakPressure();
  if (peak < kLowestPeakCylinderPressure) return;  // that warning says what is wrong
  const double at = engine::CycleCrankAngleDeg(config.pressure.PeakAngle());
  const double from_firing = at - 360.0;
  if (std::abs(from_firing) <= kPeakFromFiringTdc) return;
  RunWarning w;
  w.code = "pressure_peak_off_firing";
  w.value = from_firing;
  w.limit = kPeakFromFiringTdc;
  w.crank_angle_deg = at;
  w.message = fmt::format(
      "the cylinder pressure peaks ({:.3g} bar) at {:.0f} °CA, {:.0f} °CA {} firing TDC, which "
      "FilmDyn's cycle puts at 360 °CA (0 °CA is the TDC of intake); a fired engine peaks "
      "within some 40 °CA after it: is the curve's firing TDC at 0 °CA? Then add 360 °CA to its "
      "angles",
      peak * 1e-5, at, std::abs(from_firing), from_firing > 0.0 ? "after" : "before");
  out->push_back(std::move(w));
}

// Adds a warning on one joint that the case alone raises (no value, no crank angle).
void AddJointWarning(std::vector<RunWarning>* out, const char* code, const char* joint,
                     std::string message) {
  RunWarning w;
  w.code = code;
  w.joint = joint;
  w.message = std::move(message);
  out->push_back(std::move(w));
}

// A mass-conserving big end fed only by its film-start line at ambient pressure (the published
// tables' idealisation, no supply hardware): at low speed its film starves, and its figures then
// depend on the mesh beyond the error estimate (docs/validation/errors.md, section 6).
void FilmStartSupplyWarning(const engine::EngineCase& c, std::vector<RunWarning>* out) {
  if (c.big_end.model != engine::JointModel::kLubricated ||
      c.big_end.cavitation != lubrication::CavitationModel::kJfo ||
      c.big_end.supply != lubrication::OilFeedKind::kLineOfCentres) {
    return;
  }
  AddJointWarning(
      out, "film_start_supply", "big_end",
      "the mass-conserving big end is fed only by its film-start line at ambient pressure "
      "(big_end.supply = line_of_centres), an idealisation without the engine's supply: where "
      "that line cannot replace the oil the film loses at its sides, the film starves, its "
      "figures depend on the mesh beyond the error estimate and its oil content settles "
      "slowly (the default case below 6000 rpm: its minimum film fell by a quarter from 100 to "
      "200 elements around at 2000 rpm, and 7 cycles to the periodic state; "
      "docs/validation/errors.md, section 6); give the engine's oil supply (big_end.supply, "
      "big_end.oil_feed_pressure)");
}

// Proportions no engine joint has, most likely a length typed in the wrong unit
// (engine::JointProportions).
void ProportionsWarning(const engine::EngineCase& c, std::vector<RunWarning>* out) {
  RunWarning w;
  std::string list;
  for (const engine::JointProportion& q : engine::JointProportions(c)) {
    if (q.Plausible()) continue;
    w.fields.push_back(q.field);
    list += fmt::format("{}{} = {:.3g} (engines: {:g}–{:g}; {})", list.empty() ? "" : "; ", q.what,
                        q.value, q.lo, q.hi, q.field);
  }
  if (w.fields.empty()) return;
  w.code = "implausible_proportions";
  w.value = static_cast<double>(w.fields.size());
  w.message = fmt::format(
      "{}: no engine joint is so proportioned — is a length in the wrong unit? The case is in "
      "SI units (m)",
      list);
  out->push_back(std::move(w));
}

// A big end on elastic half-spaces in an engine run: Boussinesq's half-space assumes a loaded
// zone small against the surface's radius, which a journal bearing's film is not; wrapped round
// the whole bearing it gives way far more than a shell does, and the default case's runs end in
// their run-in (docs/validation/ehd.md, "Known limit (half-space big end in engine runs)").
void HalfSpaceBigEndWarning(const engine::EngineCase& c, std::vector<RunWarning>* out) {
  if (c.big_end.model != engine::JointModel::kLubricated ||
      c.big_end.compliance != lubrication::ComplianceModel::kHalfSpace) {
    return;
  }
  AddJointWarning(
      out, "half_space_big_end", "big_end",
      "the big end's journal and bearing deform as elastic half-spaces (big_end.compliance = "
      "half_space), a model for a loaded zone small against the radius, which a journal "
      "bearing's film is not: wrapped round the whole bearing it gives way far more than a "
      "shell does (9.9 µm under the default case's loads, against its 50 µm clearance), and "
      "the default case's runs at 1000, 3000 and 6000 rpm end in their run-in with the "
      "journal past the rigid wall (docs/validation/ehd.md); for the big end in an engine run "
      "use the "
      "elastic layer (big_end.compliance = elastic_layer) or a finite-element compliance "
      "(imported)");
}

// A joint whose film temperature comes from its heat balance while its oil's viscosity does not
// depend on temperature: the balance reports a temperature and changes nothing in the film.
void ConstantViscosityHeatBalanceWarning(const engine::EngineCase& c,
                                         std::vector<RunWarning>* out) {
  for (const bool skirt : {true, false}) {
    const engine::JointOil& oil = skirt ? c.skirt.oil : c.big_end.oil;
    const engine::JointModel model = skirt ? c.skirt.model : c.big_end.model;
    if (model != engine::JointModel::kLubricated ||
        oil.temperature_mode != engine::FilmTemperature::kHeatBalance ||
        !engine::TemperatureFreeOil(c, oil)) {
      continue;
    }
    const char* joint = skirt ? "skirt" : "big_end";
    AddJointWarning(out, "heat_balance_constant_viscosity", joint,
                    fmt::format("the {}'s film temperature comes from its heat balance ({}.oil."
                                "temperature_mode = heat_balance), but its oil's viscosity does "
                                "not depend on temperature ({} = constant): the balance reports "
                                "the film's temperature and changes nothing in the film; give the "
                                "oil a temperature law (vogel or grade) for the balance to act",
                                skirt ? "skirt" : "big end", joint,
                                engine::JointOilPrefix(oil, joint) + "viscosity_model"));
  }
}

// A mass-conserving big end fed through holes on a mesh too coarse for them: the hole's edge is
// placed where it cuts the mesh lines, which converges at second order, but with one node row
// inside it across the width its oil per cycle was still 7 % below the finest meshes'
// (docs/validation/errors.md, section 6). The thresholds: kHoleRowsAcross, kHoleElementsAround.
void SupplyHoleMeshWarning(const engine::EngineCase& c, std::vector<RunWarning>* out) {
  const engine::BigEndCase& be = c.big_end;
  if (be.model != engine::JointModel::kLubricated ||
      be.cavitation != lubrication::CavitationModel::kJfo || !lubrication::HasHoles(be.supply)) {
    return;
  }
  // Rows within 0.9 of the hole's radius: one at its rim is held only while a node passes
  // within the rim's short chord.
  const double r = 0.9 * 0.5 * be.supply_hole_diameter, mid = 0.5 * be.width;
  // The rows across as the solver lays them (the symmetric half mirrors the same lines).
  auto rows_inside = [&](int n_z) {
    const std::vector<double> z = lubrication::WidthLines(n_z, be.width, be.mesh_z_grading, false);
    return static_cast<int>(
        std::count_if(z.begin(), z.end(), [&](double zk) { return std::abs(zk - mid) <= r; }));
  };
  const double circumference = 2.0 * std::numbers::pi * engine::BigEndFit(c).inner_radius;
  auto around = [&](int n_theta) { return be.supply_hole_diameter * n_theta / circumference; };
  const int rows = rows_inside(be.mesh_z);
  const double spans = around(be.mesh_theta);
  if (rows >= kHoleRowsAcross && spans >= kHoleElementsAround) return;
  // The smallest meshes that hold it: an even count across (the symmetric half), around a
  // multiple of 50; none beyond the case's largest meshes.
  auto most = [](std::string_view path) {
    return static_cast<int>(engine::FindCaseField(path)->range.hi);
  };
  const int most_z = most("big_end.mesh_z"), most_theta = most("big_end.mesh_theta");
  int n_z = be.mesh_z;
  if (rows < kHoleRowsAcross)
    while (n_z < most_z && (n_z % 2 != 0 || rows_inside(n_z) < kHoleRowsAcross)) ++n_z;
  int n_theta = be.mesh_theta;
  if (spans < kHoleElementsAround) {
    n_theta = std::min(most_theta, static_cast<int>(std::ceil(kHoleElementsAround * circumference /
                                                              be.supply_hole_diameter / 50.0)) *
                                       50);
  }
  const bool held = rows_inside(n_z) >= kHoleRowsAcross && around(n_theta) >= kHoleElementsAround;
  RunWarning w;
  w.code = "supply_hole_mesh";
  w.joint = "big_end";
  w.value = rows;
  w.limit = kHoleRowsAcross;
  w.message = fmt::format(
      "the big end's {:g} mm supply hole holds {} row{} of film nodes across the width (within "
      "0.9 of its radius) and "
      "spans {:.1f} elements around (big_end.mesh_z = {}, big_end.mesh_theta = {}); with fewer "
      "than {} rows or {:g} elements the film around the hole is resolved too coarsely: the oil "
      "a mass-conserving film took through a crank-pin hole at 2000 rpm was 7 % below the "
      "finest meshes' with one row across, with 2 elements around the hole (50 around the "
      "bearing) 3.6 % below 100 around (the estimate "
      "sees the former: docs/validation/errors.md, section 6); {}",
      be.supply_hole_diameter * 1e3, rows, rows == 1 ? "" : "s", spans, be.mesh_z, be.mesh_theta,
      kHoleRowsAcross, kHoleElementsAround,
      held ? fmt::format("big_end.mesh_z = {} and big_end.mesh_theta = {} hold this hole", n_z,
                         n_theta)
           : std::string("no mesh the case allows holds a hole this small"));
  out->push_back(std::move(w));
}

// The largest value of a big-end quantity over the samples that have the film, and the sample
// it is at; (-1, 0) when none has it.
template <typename Value>
std::pair<double, std::size_t> BigEndLargest(const std::vector<engine::CrankTrainSample>& samples,
                                             Value value) {
  double largest = -1.0;
  std::size_t at = 0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    if (samples[k].bearing.present && value(samples[k]) > largest) {
      largest = value(samples[k]);
      at = k;
    }
  }
  return {largest, at};
}

// A rigid big end whose film pressure peaks above kRigidBigEndPeakPressure: a thin film between
// rigid surfaces carries its load on a narrow zone; the elastic shell's spreading of it, which
// lowers the peak (EHD analyses of con-rod bearings since Fantino et al. 1979), is what the rigid
// model leaves out (at low speed and thin oil the default case reached 350–700 MPa without a
// word).
void RigidBigEndPressureWarning(const std::vector<engine::CrankTrainSample>& samples,
                                std::vector<RunWarning>* out) {
  const auto [peak, at] = BigEndLargest(
      samples, [](const engine::CrankTrainSample& s) { return s.bearing.max_pressure; });
  if (!(peak > kRigidBigEndPeakPressure)) return;
  RunWarning w;
  w.code = "rigid_big_end_pressure";
  w.joint = "big_end";
  w.value = peak;
  w.limit = kRigidBigEndPeakPressure;
  w.crank_angle_deg = CrankAngleDeg(samples[at]);
  w.message = fmt::format(
      "the big-end film pressure peaks at {:.0f} MPa at {:.0f} °CA on rigid surfaces "
      "(big_end.compliance = rigid), above {:.0f} MPa: at such pressures the shell's elastic "
      "deformation spreads the film's load and lowers its peak (the default case at 1000 rpm: "
      "352 MPa rigid, 238 MPa on the elastic layer), so the rigid model's peak pressure and "
      "minimum film are not the engine's; give the shell's elasticity (big_end.compliance = "
      "elastic_layer, docs/validation/ehd.md)",
      peak * 1e-6, *w.crank_angle_deg, kRigidBigEndPeakPressure * 1e-6);
  out->push_back(std::move(w));
}

// A compressible oil on the linear density law whose film pressure passed
// kLinearDensityPressureRatio of its bulk modulus: the law compresses the oil far more there than
// an oil is compressed, and the compressed oil's cushion of the film's peaks is the law's (the
// default case's JFO big end at 6000 rpm: the steps' peak 810 MPa on the linear law, 1558 MPa on
// Dowson and Higginson's, as on an incompressible film). engine::SampledPeaks gives each film's
// peak, in the samples or at the steps between them.
void LinearDensityLawWarning(const engine::EngineCase& c,
                             const std::vector<engine::CrankTrainSample>& samples, bool whole_cycle,
                             std::vector<RunWarning>* out) {
  for (const engine::SampledPeak& sampled : engine::SampledPeaks(samples, whole_cycle)) {
    const bool skirt = !sampled.figure.big_end;
    const char* joint = skirt ? "skirt" : "big_end";
    const engine::JointOil& oil = skirt ? c.skirt.oil : c.big_end.oil;
    double beta = 0.0;
    try {
      beta = engine::JointBulkModulus(c, oil, joint,
                                      skirt ? c.skirt.cavitation : c.big_end.cavitation);
    } catch (const std::exception&) {
      continue;  // an input error the run has reported already
    }
    const lubrication::OilSpec& spec = engine::JointOilSpec(c, oil);
    if (!(beta > 0.0) || spec.density_law != lubrication::DensityLaw::kLinear) continue;
    // The higher of the samples' peak and the steps' between them.
    const bool at_steps = sampled.step_peak > sampled.figure.value;
    const double peak = at_steps ? sampled.step_peak : sampled.figure.value;
    const std::size_t at = at_steps ? sampled.step_index : sampled.index;
    if (!(peak > kLinearDensityPressureRatio * beta)) continue;
    const lubrication::Compression linear =
        lubrication::Compression::Of(beta, lubrication::DensityLaw::kLinear);
    const lubrication::Compression dh =
        lubrication::Compression::Of(beta, lubrication::DensityLaw::kDowsonHigginson);
    const std::string prefix = engine::JointOilPrefix(oil, joint);
    RunWarning w;
    w.code = "linear_density_law";
    w.joint = joint;
    w.value = peak;
    w.limit = kLinearDensityPressureRatio * beta;
    w.crank_angle_deg = CrankAngleDeg(samples[at]);
    w.message = fmt::format(
        "the {} film pressure reached {:.0f} MPa at {:.0f} °CA, {:.0f} % of its oil's bulk "
        "modulus ({}bulk_modulus = {:.3g} GPa): there the linear density law compresses the oil "
        "by {:.0f} %, an oil by Dowson and Higginson's law {:.0f} %, so the cushion the "
        "compressed oil gives the film's peaks is the linear law's (the default case's JFO big "
        "end at 6000 rpm: steps' peak 810 MPa linear, 1558 MPa by Dowson–Higginson, as "
        "incompressible); give {}density_law = \"{}\" (docs/validation/cavitation.md, section "
        "1c)",
        skirt ? "skirt" : "big-end", peak * 1e-6, *w.crank_angle_deg, 100.0 * peak / beta, prefix,
        beta * 1e-9, 100.0 * linear.At(peak), 100.0 * dh.At(peak), prefix,
        lubrication::ToString(lubrication::DensityLaw::kDowsonHigginson));
    out->push_back(std::move(w));
  }
}

// A big-end supply pressure no engine's oil system delivers (kHighestSupplyPressure): a value in
// the wrong unit runs and "completes" (a 1 GPa feed pushed 11 L/s through a 4 mm hole and gave a
// 5.7 GPa film peak without a word). Only the pressure the run reads: the curve when one is
// given, else the constant.
void HighSupplyPressureWarning(const engine::EngineCase& c, std::vector<RunWarning>* out) {
  const engine::BigEndCase& be = c.big_end;
  if (be.model != engine::JointModel::kLubricated) return;
  const bool curve = !be.supply_pressure_values.empty();
  const char* path = curve ? "big_end.supply_pressure_values" : "big_end.oil_feed_pressure";
  if (!engine::UnusedReason(c, path).empty()) return;
  RunWarning w;
  w.value = be.oil_feed_pressure;
  if (curve) {
    const auto peak =
        std::max_element(be.supply_pressure_values.begin(), be.supply_pressure_values.end());
    w.value = *peak;
    const auto k = static_cast<std::size_t>(peak - be.supply_pressure_values.begin());
    if (k < be.supply_pressure_angles.size())
      w.crank_angle_deg = be.supply_pressure_angles[k] * kDegreesPerRadian;
  }
  if (!(w.value > kHighestSupplyPressure)) return;
  w.code = "high_supply_pressure";
  w.joint = "big_end";
  w.limit = kHighestSupplyPressure;
  w.message = fmt::format(
      "the big end's oil-supply pressure ({}{}) is {:.4g} MPa, above the {:g} MPa no engine's "
      "oil system delivers (galleries run at 0.2–0.7 MPa): is it in the unit the case expects "
      "(Pa; MPa in the case editor)? At such a pressure the supply carries load as a hydrostatic "
      "bearing would",
      path,
      w.crank_angle_deg ? fmt::format(", its peak at {:.4g} °CA", *w.crank_angle_deg)
                        : std::string(),
      w.value * 1e-6, kHighestSupplyPressure * 1e-6);
  out->push_back(std::move(w));
}

}  // namespace

std::vector<RunWarning> RunWarnings(const engine::RunConfig& config,
                                    const engine::RunResult& result) {
  std::vector<RunWarning> out;
  const engine::EngineCase& c = config.engine_case;
  const auto& samples = result.samples;
  const bool whole_cycle = engine::SamplesSpanACycle(result.samples);
  const bool skirt = c.skirt.model == engine::JointModel::kLubricated;
  const bool big_end = c.big_end.model == engine::JointModel::kLubricated;
  if (skirt) {
    FilmRatioWarning(samples, true, std::hypot(c.skirt.roughness_skirt, c.skirt.roughness_liner),
                     whole_cycle, &out);
  }
  if (big_end) {
    FilmRatioWarning(samples, false,
                     std::hypot(c.big_end.roughness_journal, c.big_end.roughness_bearing),
                     whole_cycle, &out);
    const auto [eps, at] =
        BigEndLargest(samples, [](const engine::CrankTrainSample& s) { return s.bearing.eps; });
    if (eps > kHighEccentricity) {
      RunWarning w;
      w.code = "high_eccentricity";
      w.joint = "big_end";
      w.value = eps;
      w.limit = kHighEccentricity;
      w.crank_angle_deg = CrankAngleDeg(samples[at]);
      std::vector<double> angles;
      std::vector<bool> crossed;
      for (const engine::CrankTrainSample& s : samples) {
        angles.push_back(CrankAngleDeg(s));
        crossed.push_back(s.bearing.present && s.bearing.eps > kHighEccentricity);
      }
      w.crank_angle_ranges_deg = Ranges(angles, crossed, whole_cycle);
      // Past ε = 1 (elastic surfaces only) the rigid position is inside the wall, which the
      // surfaces' deformation opens.
      const double gap_um = (1.0 - eps) * engine::BigEndFit(c).hot_clearance * 1e6;
      w.message = fmt::format(
          "big-end eccentricity ratio ε = {:.3f} at {:.0f} °CA, above {:g} over {}: {}", eps,
          *w.crank_angle_deg, kHighEccentricity, RangesText(w.crank_angle_ranges_deg),
          gap_um >= 0.0
              ? fmt::format("the journal runs within {:.1f} µm of the bearing wall", gap_um)
              : fmt::format("the journal's rigid position is {:.1f} µm past the bearing wall, "
                            "which only the surfaces' elastic deformation opens",
                            -gap_um));
      out.push_back(std::move(w));
    }
  }
  if (big_end && c.big_end.compliance == lubrication::ComplianceModel::kRigid)
    RigidBigEndPressureWarning(samples, &out);
  UnresolvedPeakWarnings(samples, c.solver.output_interval, whole_cycle, &out);
  LinearDensityLawWarning(c, samples, whole_cycle, &out);
  // How far the headline figures moved over the last cycles: said by both warnings below.
  const auto scatter =
      engine::ScatterOverCycles(result.cycle_headlines, result.samples, whole_cycle);
  if (result.status == engine::RunStatus::kNotConverged) {
    RunWarning w;
    w.code = "not_periodic";
    // A non-finite change (a diverging quantity) as the largest double: summary.json keeps it.
    w.value = std::isfinite(result.cycle_change) ? result.cycle_change
                                                 : std::numeric_limits<double>::max();
    w.limit = c.solver.steady_state_tolerance;
    w.message =
        result.cycles < 2
            ? fmt::format(
                  "no periodic steady state: solver.max_cycles = {} allows no second cycle to "
                  "compare the first with, so the start-up transient may still be in the results",
                  result.cycles)
            : fmt::format(
                  "no periodic steady state after {} cycles (solver.max_cycles): the last "
                  "cycle-to-cycle change is {:.3g} % of the range of {}, above the tolerance of "
                  "{:g} %; the reported cycle is the last one computed",
                  result.cycles, 100.0 * result.cycle_change, result.worst_quantity_label,
                  100.0 * w.limit);
    if (const std::string trend =
            engine::CycleChangeTrend(result.cycle_changes, c.solver.steady_state_tolerance);
        !trend.empty())
      w.message += "; " + trend;
    if (scatter) w.message += "; " + scatter->Summary();
    out.push_back(std::move(w));
  }
  // A periodic run whose headline figures still moved over its last cycles by more than the
  // steady-state tolerance: the test judges each quantity's change against its range over the
  // cycle, which can hide a minimum film's scatter (a mass-conserving big end's 1.6 % between
  // two cycles passed at 0.63 % of the range).
  if (result.status == engine::RunStatus::kCompleted && scatter) {
    double largest = 0.0;
    for (const engine::FigureScatter& f : scatter->figures)
      if (f.resolved_in_time) largest = std::max(largest, f.RelativeHalfSpread());
    if (largest > c.solver.steady_state_tolerance) {
      RunWarning w;
      w.code = "cycle_scatter";
      w.value = largest;
      w.limit = c.solver.steady_state_tolerance;
      w.message = fmt::format(
          "periodic by the cycle-to-cycle test (the change {} % of each quantity's range over "
          "the cycle, below {:g} %), yet {}: read the figures to that scatter, or tighten "
          "solver.steady_state_tolerance for more cycles",
          engine::PercentText(result.cycle_change), 100.0 * c.solver.steady_state_tolerance,
          scatter->Summary());
      out.push_back(std::move(w));
    }
  }
  // A catalogue oil at a film temperature outside its fit's range.
  for (const auto& [lubricated, oil, joint, balanced] :
       {std::tuple{skirt, c.skirt.oil, "skirt", result.skirt_film_temperature},
        std::tuple{big_end, c.big_end.oil, "big_end", result.big_end_film_temperature}}) {
    if (!lubricated) continue;
    engine::JointOil used = oil;
    if (balanced) used.temperature = *balanced;
    const lubrication::OilSpec& spec = engine::JointOilSpec(c, used);
    if (spec.model != lubrication::ViscosityModel::kGrade) continue;
    lubrication::OilSpec::AtTemperature at;
    try {
      at = engine::JointOilAt(c, used, joint);
    } catch (const std::exception&) {
      continue;  // an input error the run has reported already
    }
    if (!at.extrapolated) continue;
    const lubrication::OilGrade& grade = lubrication::OilCatalogue()[spec.grade];
    RunWarning w;
    w.code = "oil_extrapolated";
    w.joint = joint;
    w.value = used.temperature;
    w.limit = used.temperature < lubrication::kGradeFitMinTemperature
                  ? lubrication::kGradeFitMinTemperature
                  : lubrication::kGradeFitMaxTemperature;
    w.message = fmt::format(
        "{} film temperature {:.1f} °C is outside the {:.0f}–{:.0f} °C the catalogue oil {} ({}) "
        "was fitted over: its viscosity {:.3g} mPa·s is extrapolated",
        joint == std::string("skirt") ? "skirt" : "big-end",
        used.temperature - lubrication::kZeroCelsius,
        lubrication::kGradeFitMinTemperature - lubrication::kZeroCelsius,
        lubrication::kGradeFitMaxTemperature - lubrication::kZeroCelsius, grade.key, grade.product,
        at.viscosity * 1e3);
    out.push_back(std::move(w));
  }
  AssumedInputsWarning(c, &out);
  UnusedInputsWarning(c, &out);
  SyntheticPressureWarning(config, &out);
  LowCylinderPressureWarning(config, &out);
  FiringAngleWarning(config, &out);
  FilmStartSupplyWarning(c, &out);
  SupplyHoleMeshWarning(c, &out);
  HighSupplyPressureWarning(c, &out);
  HalfSpaceBigEndWarning(c, &out);
  ConstantViscosityHeatBalanceWarning(c, &out);
  ProportionsWarning(c, &out);
  return out;
}

std::string WarningShortText(const RunWarning& w) {
  if (w.code == "asperity_contact" || w.code == "mixed_lubrication") {
    return fmt::format("h/σ {:.2f} < {:g} {}", w.value, w.limit,
                       w.joint == "skirt" ? "skirt" : "big end");
  }
  if (w.code == "high_eccentricity") return fmt::format("ε {:.3f} > {:g}", w.value, w.limit);
  if (w.code == "not_periodic") return fmt::format("not periodic ({:.2g} %)", 100.0 * w.value);
  if (w.code == "cycle_scatter") return fmt::format("cycles scatter ±{:.2g} %", 100.0 * w.value);
  if (w.code == "assumed_inputs") return fmt::format("{:.0f} assumed inputs", w.value);
  if (w.code == "unused_inputs") return fmt::format("{:.0f} unused inputs", w.value);
  if (w.code == "synthetic_pressure") return "synthetic pressure";
  if (w.code == "film_start_supply") return "film-start supply";
  if (w.code == "supply_hole_mesh") return "supply hole on a coarse mesh";
  if (w.code == "high_supply_pressure") return fmt::format("supply {:.3g} MPa", w.value * 1e-6);
  if (w.code == "rigid_big_end_pressure") {
    return fmt::format("rigid big end {:.0f} MPa", w.value * 1e-6);
  }
  if (w.code == "low_cylinder_pressure") {
    return fmt::format("cylinder peak {:.3g} bar", w.value * 1e-5);
  }
  if (w.code == "pressure_peak_off_firing") {
    return fmt::format("cylinder peak at {:.0f} °CA", w.crank_angle_deg.value_or(0.0));
  }
  if (w.code == "half_space_big_end") return "half-space big end";
  if (w.code == "implausible_proportions")
    return fmt::format("{:.0f} implausible proportions", w.value);
  if (w.code == "heat_balance_constant_viscosity") return "heat balance, constant viscosity";
  if (w.code == "unresolved_peak") {
    return fmt::format("peak spike ×{:.2g} {}", w.value, w.joint == "skirt" ? "skirt" : "big end");
  }
  if (w.code == "linear_density_law") {
    return fmt::format("linear density law {}", w.joint == "skirt" ? "skirt" : "big end");
  }
  if (w.code == "oil_extrapolated") {
    return fmt::format("oil extrapolated {}", w.joint == "skirt" ? "skirt" : "big end");
  }
  return w.code;
}

}  // namespace filmdyn::io
