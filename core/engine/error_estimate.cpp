#include "core/engine/error_estimate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/engine/case_schema.hpp"
#include "core/engine/piston_slap.hpp"

namespace filmdyn::engine {

namespace {

// Half the elements of a mesh count, never below the field's own minimum (the schema's).
int Halved(const char* path, int count) {
  const CaseField* field = FindCaseField(path);
  const int lowest = field ? static_cast<int>(std::ceil(field->range.lo)) : 1;
  return std::max(std::min(lowest, count), static_cast<int>(std::lround(count / 2.0)));
}

// h_coarse / h of a 2-D mesh from its element counts (√ of the element ratio).
double SpacingRatio(double elements, double coarse_elements) {
  return std::sqrt(elements / coarse_elements);
}

// A joint's oil per cycle: present for a mass-conserving film only.
constexpr const char* kSkirtOilKey = "skirt_oil_per_cycle[m^3]";
constexpr const char* kBearingOilKey = "bearing_oil_per_cycle[m^3]";
// The largest piston-slap energy: present where the piston changes side (and SlapInputs given).
constexpr const char* kSlapKey = "slap_energy_max[J]";

// kMaxAbs: the largest magnitude of a signed curve. kAccount: the oil into the film over the
// cycle (AccountedOil), kSlap: the largest piston-slap energy (SlapOf) — neither a reduction of
// `value`.
enum class Reduction { kMin, kMax, kMaxAbs, kMean, kAccount, kSlap };

struct HeadlineDefinition {
  const char* key;
  const char* label;
  bool big_end;
  double (*value)(const CrankTrainSample&);
  Reduction reduction;
  /// A peak that can spike between output samples: the film's peak at the integrator's steps
  /// since the sample before (NaN when the film books none); nullptr for the other figures.
  double (*between_samples)(const CrankTrainSample&);
  /// Order of convergence in the element size. Observed in the coupled run over three meshes
  /// (big end 50 x 5 ... 200 x 20 graded, skirt 12 + 2 + 12 x 16 ... 48 + 8 + 48 x 64) at 2000
  /// and 6000 rpm: 1.82-2.22 for every figure (docs/validation/errors.md), so 2 for all; kept per
  /// figure so that a model with another order says so here.
  double order;
  /// A largest magnitude that can be a spike the output samples do not resolve (a force at an
  /// impact of a mass-conserving film): judged by the samples beside its largest one
  /// (NeighbourRatio), as a peak pressure is.
  bool can_spike = false;
};

// The one table of the headline figures.
const std::vector<HeadlineDefinition>& Definitions() {
  using S = CrankTrainSample;
  static const std::vector<HeadlineDefinition> table = {
      {"skirt_moft_min[m]", "min skirt MOFT", false, [](const S& s) { return s.skirt.moft; },
       Reduction::kMin, nullptr, 2.0},
      {"skirt_peak_pressure[Pa]", "peak skirt film pressure", false,
       [](const S& s) { return s.skirt.max_pressure; }, Reduction::kMax,
       [](const S& s) { return s.skirt.step_peak_pressure; }, 2.0},
      {"skirt_fpl_mean[W]", "mean skirt FPL", false, [](const S& s) { return s.skirt.fpl; },
       Reduction::kMean, nullptr, 2.0},
      // The piston's secondary motion and the skirt's side force: observed orders 1.97-2.30 (e0,
      // tilt) over the three nested meshes at 2000 and 6000 rpm; the side force is set by the gas
      // and inertia forces and moves by < 0.1 % with the mesh (docs/validation/errors.md,
      // section 3).
      {"piston_lateral_max_abs[m]", "max piston lateral |e0|", false,
       [](const S& s) { return s.piston_lateral; }, Reduction::kMaxAbs, nullptr, 2.0},
      {"piston_tilt_max_abs[rad]", "max piston tilt |γ|", false,
       [](const S& s) { return s.piston_tilt; }, Reduction::kMaxAbs, nullptr, 2.0},
      {"skirt_normal_force_max_abs[N]", "max skirt side force |F_n|", false,
       [](const S& s) { return s.skirt.normal_force; }, Reduction::kMaxAbs, nullptr, 2.0, true},
      // The piston's largest kinetic energy at a change of thrust side: observed orders 1.93
      // (6000 rpm) and 2.14 (2000 rpm) over the three nested meshes (docs/validation/errors.md,
      // section 3).
      {kSlapKey, "max piston-slap energy", false, nullptr, Reduction::kSlap, nullptr, 2.0},
      // The void's transport is first order: 1, conservatively. Observed (JFO skirt, 8 + 1 + 8 x
      // 10 ... 30 + 4 + 30 x 40): 597.11, 596.86, 596.98 mm³ at 2000 rpm, within 0.05 % on every
      // mesh (docs/validation/errors.md, section 6).
      {kSkirtOilKey, "skirt oil per cycle", false, nullptr, Reduction::kAccount, nullptr, 1.0},
      {"bearing_moft_min[m]", "min big-end MOFT", true, [](const S& s) { return s.bearing.moft; },
       Reduction::kMin, nullptr, 2.0},
      {"bearing_eps_max[-]", "max big-end eccentricity ratio", true,
       [](const S& s) { return s.bearing.eps; }, Reduction::kMax, nullptr, 2.0},
      {"bearing_peak_pressure[Pa]", "peak big-end film pressure", true,
       [](const S& s) { return s.bearing.max_pressure; }, Reduction::kMax,
       [](const S& s) { return s.bearing.step_peak_pressure; }, 2.0},
      {"bearing_fpl_mean[W]", "mean big-end FPL", true, [](const S& s) { return s.bearing.fpl; },
       Reduction::kMean, nullptr, 2.0},
      // The film's force on the rod (global frame): set by the gas and inertia forces, it moves
      // by < 0.1 % with the mesh (docs/validation/errors.md, section 3).
      {"bearing_force_x_max_abs[N]", "max big-end force |F_x|", true,
       [](const S& s) { return s.bearing.force_on_rod.x(); }, Reduction::kMaxAbs, nullptr, 2.0,
       true},
      {"bearing_force_y_max_abs[N]", "max big-end force |F_y|", true,
       [](const S& s) { return s.bearing.force_on_rod.y(); }, Reduction::kMaxAbs, nullptr, 2.0,
       true},
      // Observed 1.77 (JFO big end, 6000 rpm, 50 x 5 ... 200 x 20: 121.9, 128.3, 130.2 mm³;
      // docs/validation/errors.md); 1.6 kept (a lower order, a larger estimate).
      {kBearingOilKey, "big-end oil per cycle", true, nullptr, Reduction::kAccount, nullptr, 1.6},
  };
  return table;
}

// Whether the samples have the figure's joint (a lubricated skirt / big end).
bool HasJoint(const std::vector<CrankTrainSample>& samples, bool big_end) {
  return std::any_of(samples.begin(), samples.end(), [big_end](const CrankTrainSample& s) {
    return big_end ? s.bearing.present : s.skirt.present;
  });
}

// The definition of a headline key; nullptr for a key of no definition.
const HeadlineDefinition* DefinitionOf(const std::string& key) {
  for (const HeadlineDefinition& d : Definitions())
    if (key == d.key) return &d;
  return nullptr;
}

// A film's minimum or the eccentricity's maximum: the extreme of a curve sampled at every output
// step (not a peak between the samples, a mean or an account).
bool IsCurveExtreme(const HeadlineDefinition& d) {
  return d.value && !d.between_samples &&
         (d.reduction == Reduction::kMin || d.reduction == Reduction::kMax ||
          d.reduction == Reduction::kMaxAbs);
}

struct CurveExtreme {
  double value = 0.0;     ///< the extrapolated curve's extreme
  double at_own = 0.0;    ///< the extrapolated curve at this run's own extreme
  std::size_t index = 0;  ///< the sample of the extrapolated extreme
  std::size_t own = 0;    ///< the sample of this run's own extreme
};

// Richardson's extrapolation sample by sample, f + (f - f_coarse) * factor, and its extreme over
// the cycle. Comparing the two runs' extremes alone assumes both lie at the same place in the
// cycle; where the meshes disagree on that (a crank-pin-fed mass-conserving big end at 2000 rpm:
// the default mesh's minimum film after firing, a finer mesh's after the gas-exchange TDC,
// docs/validation/errors.md) the extrapolated curve still finds the thinner one. None when the
// runs' samples are not at the same crank angles or the joint has no sample in both.
std::optional<CurveExtreme> ExtrapolatedExtreme(const HeadlineDefinition& d,
                                                const std::vector<CrankTrainSample>& samples,
                                                const std::vector<CrankTrainSample>& coarse,
                                                double factor) {
  if (samples.size() != coarse.size()) return std::nullopt;
  constexpr double kEngineCycle = 4.0 * std::numbers::pi;
  constexpr double kSameAngle = 1e-6;  // [rad]; runs of more cycles differ by whole cycles
  const bool max = d.reduction != Reduction::kMin;
  const bool magnitude = d.reduction == Reduction::kMaxAbs;  // of the signed curve extrapolated
  const auto beyond = [max](double a, double b) { return max ? a > b : a < b; };
  const auto present = [&d](const CrankTrainSample& s) {
    return d.big_end ? s.bearing.present : s.skirt.present;
  };
  std::optional<CurveExtreme> best;
  double own_value = 0.0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    if (std::abs(std::remainder(samples[k].crank_angle - coarse[k].crank_angle, kEngineCycle)) >
        kSameAngle)
      return std::nullopt;
    if (!present(samples[k]) || !present(coarse[k])) continue;
    const double signed_f = d.value(samples[k]), c = d.value(coarse[k]);
    if (!std::isfinite(signed_f) || !std::isfinite(c)) continue;
    const double signed_x = signed_f + (signed_f - c) * factor;
    const double f = magnitude ? std::abs(signed_f) : signed_f;
    const double x = magnitude ? std::abs(signed_x) : signed_x;
    if (!best) {
      best = CurveExtreme{x, x, k, k};
      own_value = f;
      continue;
    }
    if (beyond(x, best->value)) {
      best->value = x;
      best->index = k;
    }
    if (beyond(f, own_value)) {
      own_value = f;
      best->own = k;
      best->at_own = x;
    }
  }
  return best;
}

// The keys of the figures whose value in these samples is a spike the output samples do not
// resolve: the peak pressures (SampledPeak::Unresolved) and the largest magnitudes that can spike
// (a force at an impact), judged by the samples beside their largest one.
std::vector<std::string> UnresolvedKeys(const std::vector<CrankTrainSample>& samples,
                                        bool whole_cycle) {
  std::vector<std::string> keys;
  for (const SampledPeak& p : SampledPeaks(samples, whole_cycle))
    if (p.Unresolved()) keys.push_back(p.figure.key);
  const std::size_t n = samples.size();
  if (n < 2) return keys;
  for (const HeadlineDefinition& d : Definitions()) {
    if (!d.can_spike || !HasJoint(samples, d.big_end)) continue;
    const auto magnitude = [&](std::size_t k) { return std::abs(d.value(samples[k])); };
    std::size_t at = 0;
    for (std::size_t k = 1; k < n; ++k)
      if (magnitude(k) > magnitude(at)) at = k;
    const SamplesBeside beside = SamplesBesideOf(n, at, whole_cycle);
    const double before = beside.before ? magnitude(*beside.before) : NAN;
    const double after = beside.after ? magnitude(*beside.after) : NAN;
    if (NeighbourRatio(magnitude(at), before, after) > kUnresolvedPeakRatio) keys.push_back(d.key);
  }
  return keys;
}

}  // namespace

HeadlineFigure HeadlineFigureFor(const std::string& key, double value) {
  for (const HeadlineDefinition& d : Definitions()) {
    if (key == d.key) return {d.key, d.label, value, d.big_end, d.order};
  }
  return {key, key, value, key.rfind("bearing_", 0) == 0};
}

std::vector<HeadlineFigure> HeadlineFigures(const std::vector<CrankTrainSample>& samples,
                                            const SlapInputs& slap) {
  std::vector<HeadlineFigure> figures;
  if (samples.empty()) return figures;
  const bool skirt = HasJoint(samples, false), big_end = HasJoint(samples, true);
  const bool whole_cycle = SamplesSpanACycle(samples);
  for (const HeadlineDefinition& d : Definitions()) {
    if (d.big_end ? !big_end : !skirt) continue;
    // A mean over part of a cycle is not the cycle's mean (a run stopped in its run-in: the
    // part computed, at the run-in's looser tolerances).
    if (d.reduction == Reduction::kMean && !whole_cycle) continue;
    if (d.reduction == Reduction::kSlap) {
      if (slap.motion == nullptr || !(slap.mass > 0.0)) continue;
      const PistonSlap p = SlapOf(samples, *slap.motion, slap.mass, slap.inertia, whole_cycle);
      if (p.energy_max) figures.push_back({d.key, d.label, *p.energy_max, d.big_end, d.order});
      continue;
    }
    if (d.reduction == Reduction::kAccount) {
      if (const std::optional<OilPerCycle> oil = AccountedOil(samples, d.big_end))
        figures.push_back({d.key, d.label, oil->in, d.big_end, d.order});
      continue;
    }
    double best = d.reduction == Reduction::kMin ? HUGE_VAL : -HUGE_VAL, sum = 0.0;
    for (const CrankTrainSample& s : samples) {
      const double v = d.reduction == Reduction::kMaxAbs ? std::abs(d.value(s)) : d.value(s);
      best = d.reduction == Reduction::kMin ? std::min(best, v) : std::max(best, v);
      sum += v;
    }
    const double value =
        d.reduction == Reduction::kMean ? sum / static_cast<double>(samples.size()) : best;
    figures.push_back({d.key, d.label, value, d.big_end, d.order});
  }
  return figures;
}

std::optional<OilPerCycle> AccountedOil(const std::vector<CrankTrainSample>& samples,
                                        bool big_end) {
  if (!SamplesSpanACycle(samples)) return std::nullopt;
  auto account = [big_end](const CrankTrainSample& s) -> const coupling::OilAccount& {
    return big_end ? s.bearing.oil : s.skirt.oil;
  };
  const coupling::OilAccount& first = account(samples.front());
  const coupling::OilAccount& last = account(samples.back());
  if (!first.kept || !last.kept || !(last.time > first.time)) return std::nullopt;
  const double span = (samples[1].time - samples[0].time) * static_cast<double>(samples.size());
  const double scale = span / (last.time - first.time);
  return OilPerCycle{(last.supplied - first.supplied) * scale, (last.lost - first.lost) * scale};
}

bool SamplesSpanACycle(const std::vector<CrankTrainSample>& samples) {
  if (samples.size() < 2) return false;
  return SpanIsACycle(samples.size(), samples[1].crank_angle - samples[0].crank_angle);
}

bool SpanIsACycle(std::size_t count, double interval) {
  if (count < 2) return false;
  const double span = interval * static_cast<double>(count);
  // One cycle, neither less (a run stopped before its first cycle ended) nor more (a run stopped
  // late in a run-in longer than a cycle, whose samples are the run-in's).
  return interval > 0.0 && std::abs(span - 4.0 * std::numbers::pi) < 0.5 * interval;
}

SamplesBeside SamplesBesideOf(std::size_t count, std::size_t at, bool whole_cycle) {
  SamplesBeside beside;
  if (count < 2 || at >= count) return beside;
  if (at > 0 || whole_cycle) beside.before = (at + count - 1) % count;
  if (at + 1 < count || whole_cycle) beside.after = (at + 1) % count;
  return beside;
}

double NeighbourRatio(double value, double before, double after) {
  double beside = -HUGE_VAL;
  for (double v : {before, after})
    if (std::isfinite(v)) beside = std::max(beside, v);
  if (beside == -HUGE_VAL) return 1.0;  // no neighbour to judge by
  if (beside > 0.0) return value / beside;
  return value > 0.0 ? HUGE_VAL : 1.0;
}

double SampledPeak::StepRatio() const {
  if (!std::isfinite(step_peak)) return 1.0;
  if (figure.value > 0.0) return step_peak / figure.value;
  return step_peak > 0.0 ? HUGE_VAL : 1.0;
}

std::vector<SampledPeak> SampledPeaks(const std::vector<CrankTrainSample>& samples,
                                      bool whole_cycle) {
  std::vector<SampledPeak> peaks;
  const std::size_t n = samples.size();
  if (n == 0) return peaks;
  const bool skirt = HasJoint(samples, false), big_end = HasJoint(samples, true);
  for (const HeadlineDefinition& d : Definitions()) {
    if (!d.between_samples || (d.big_end ? !big_end : !skirt)) continue;
    std::size_t at = 0;
    for (std::size_t k = 1; k < n; ++k)
      if (d.value(samples[k]) > d.value(samples[at])) at = k;
    SampledPeak peak;
    peak.figure = {d.key, d.label, d.value(samples[at]), d.big_end, d.order};
    peak.index = at;
    const SamplesBeside beside = SamplesBesideOf(n, at, whole_cycle);
    if (beside.before) peak.before = d.value(samples[*beside.before]);
    if (beside.after) peak.after = d.value(samples[*beside.after]);
    for (std::size_t k = 0; k < n; ++k) {
      const double step = d.between_samples(samples[k]);
      if (std::isfinite(step) && !(step <= peak.step_peak)) {
        peak.step_peak = step;
        peak.step_index = k;
      }
    }
    peaks.push_back(peak);
  }
  return peaks;
}

CoarseCompanion MakeCoarseCompanion(const EngineCase& engine_case) {
  CoarseCompanion companion;
  EngineCase& c = companion.engine_case;
  c = engine_case;
  SkirtCase& s = c.skirt;
  s.mesh_thrust = Halved("skirt.mesh_thrust", s.mesh_thrust);
  s.mesh_relief = Halved("skirt.mesh_relief", s.mesh_relief);
  s.mesh_anti = Halved("skirt.mesh_anti", s.mesh_anti);
  s.mesh_axial = Halved("skirt.mesh_axial", s.mesh_axial);
  const SkirtCase& s0 = engine_case.skirt;
  companion.skirt_ratio =
      SpacingRatio(double(s0.mesh_thrust + s0.mesh_relief + s0.mesh_anti) * s0.mesh_axial,
                   double(s.mesh_thrust + s.mesh_relief + s.mesh_anti) * s.mesh_axial);
  BigEndCase& b = c.big_end;
  b.mesh_theta = Halved("big_end.mesh_theta", b.mesh_theta);
  b.mesh_z = Halved("big_end.mesh_z", b.mesh_z);
  const BigEndCase& b0 = engine_case.big_end;
  companion.big_end_ratio = SpacingRatio(double(b0.mesh_theta) * b0.mesh_z,
                                         double(b.mesh_theta) * b.mesh_z);
  // The companion integrates with the run's own tolerances, so that the time-integration error
  // is alike in both and the difference is the mesh's. Loosening them by r^2 (so that the time
  // error would grow as the mesh error does) was the first design and was dropped: near
  // eps = 0.97 the integrator's error is not proportional to its tolerance (2x mesh, 6000 rpm,
  // min big-end MOFT against 10x tighter tolerances: -0.15 % at 1x, -1.0 % at 2x, -2.4 % at
  // 4x the tolerances), and the looser companion's own time error then dominated the estimate
  // on fine meshes (4x meshes: estimate 1.3 % for a true 0.46 %); it was not even cheaper
  // there (more cycles to steady state).
  companion.tolerance_factor = 1.0;
  if (engine_case.skirt.model == JointModel::kLubricated &&
      engine_case.skirt.supply == lubrication::SkirtSupply::kStarved)
    companion.skirt_max_order = 1.0;
  if (engine_case.big_end.model == JointModel::kLubricated &&
      engine_case.big_end.cavitation == lubrication::CavitationModel::kJfo &&
      lubrication::HasHoles(engine_case.big_end.supply))
    companion.big_end_max_order = 1.0;
  c.solver.error_estimate = 0;
  return companion;
}

double FigureScatter::RelativeHalfSpread() const {
  const double half = 0.5 * (max - min);
  if (half == 0.0) return 0.0;
  return figure.value != 0.0 ? half / std::abs(figure.value)
                             : std::numeric_limits<double>::infinity();
}

DisplayUnit HeadlineDisplayUnit(const std::string& key) {
  const std::size_t open = key.rfind('[');
  const std::size_t close = key.rfind(']');
  const std::string si = open == std::string::npos || close == std::string::npos || close < open
                             ? std::string()
                             : key.substr(open + 1, close - open - 1);
  if (si == "m") return {"µm", 1e6};
  if (si == "rad") return {"mrad", 1e3};
  if (si == "N") return {"kN", 1e-3};
  if (si == "J") return {"mJ", 1e3};
  if (si == "Pa") return {"MPa", 1e-6};
  if (si == "m^3") return {"mm³", 1e9};
  if (si == "-") return {"", 1.0};
  return {si, 1.0};
}

std::string PercentText(double fraction) {
  const double percent = 100.0 * fraction;
  return percent < 10.0 ? fmt::format("{:.2g}", percent) : fmt::format("{:.0f}", percent);
}

std::string CycleScatter::Summary() const {
  constexpr double kNoted = 1e-3;  // figures that moved less are not listed
  std::vector<const FigureScatter*> moved;
  for (const FigureScatter& f : figures)
    if (f.resolved_in_time && f.RelativeHalfSpread() > kNoted) moved.push_back(&f);
  std::sort(moved.begin(), moved.end(), [](const FigureScatter* a, const FigureScatter* b) {
    return a->RelativeHalfSpread() > b->RelativeHalfSpread();
  });
  const auto range = [](const FigureScatter& f) {
    const DisplayUnit u = HeadlineDisplayUnit(f.figure.key);
    return fmt::format("{} {:.4g}–{:.4g}{}{}", f.figure.label, f.min * u.scale, f.max * u.scale,
                       u.unit.empty() ? "" : " ", u.unit);
  };
  const std::string span = fmt::format("over cycles {}–{}", first_cycle, last_cycle);
  std::string text;
  if (moved.empty()) {
    text = span + " the headline figures moved by less than ±0.1 % of the reported values";
  } else {
    text = fmt::format("{} the headline figures moved by up to ±{} % of the reported values:", span,
                       PercentText(moved.front()->RelativeHalfSpread()));
    for (std::size_t i = 0; i < moved.size(); ++i) {
      text += fmt::format("{} {} (±{} %)", i == 0 ? "" : ",", range(*moved[i]),
                          PercentText(moved[i]->RelativeHalfSpread()));
    }
  }
  std::string spikes;
  for (const FigureScatter& f : figures)
    if (!f.resolved_in_time) spikes += (spikes.empty() ? "" : ", ") + range(f);
  if (!spikes.empty()) text += "; not counted: " + spikes + " (a spike between output samples)";
  return text;
}

std::string CycleChangeTrend(const std::vector<double>& changes, double tolerance) {
  if (changes.size() < 2) return {};
  std::string list;
  for (double c : changes) list += (list.empty() ? "" : ", ") + PercentText(c);
  std::string text = "the change after each cycle from cycle 2 on: " + list + " %";
  const double last = changes.back(), before = changes[changes.size() - 2];
  if (!(std::isfinite(last) && std::isfinite(before) && last > 0.0 && before > 0.0 &&
        tolerance > 0.0))
    return text;
  const double ratio = last / before;
  if (ratio < kFallingRatio) {
    const int more =
        std::max(1, static_cast<int>(std::ceil(std::log(tolerance / last) / std::log(ratio))));
    return text + fmt::format(
                      ", falling by about ×{:.2g} per cycle: about {} more cycle{} would reach "
                      "the tolerance if it keeps falling so (solver.max_cycles)",
                      1.0 / ratio, more, more == 1 ? "" : "s");
  }
  return text + fmt::format(
                    ", not falling (×{:.2g} of the cycle before): more cycles may not reach the "
                    "tolerance — the change may be a floor of the time integration's error "
                    "(tighter solver.relative_tolerance and solver.position_tolerance lower it) "
                    "or a motion that does not repeat",
                    ratio);
}

std::optional<CycleScatter> ScatterOverCycles(
    const std::vector<std::vector<HeadlineFigure>>& per_cycle,
    const std::vector<CrankTrainSample>& reported_samples, bool whole_cycle) {
  const int cycles = static_cast<int>(per_cycle.size());
  if (cycles < 2 || per_cycle.back().empty()) return std::nullopt;
  CycleScatter scatter;
  scatter.last_cycle = cycles;
  // The first cycle holds the start-up transient: left out when two others remain.
  scatter.first_cycle = std::max(cycles >= 3 ? 2 : 1, cycles - kScatterCycles + 1);
  const std::vector<std::string> unresolved = UnresolvedKeys(reported_samples, whole_cycle);
  for (const HeadlineFigure& reported : per_cycle.back()) {
    FigureScatter f{.figure = reported, .min = reported.value, .max = reported.value};
    for (int c = scatter.first_cycle; c <= cycles; ++c) {
      for (const HeadlineFigure& other : per_cycle[c - 1]) {
        if (other.key != reported.key) continue;
        f.min = std::min(f.min, other.value);
        f.max = std::max(f.max, other.value);
      }
    }
    if (std::find(unresolved.begin(), unresolved.end(), reported.key) != unresolved.end())
      f.resolved_in_time = false;
    scatter.figures.push_back(f);
  }
  return scatter;
}

ErrorEstimate EstimateErrors(const std::vector<CrankTrainSample>& samples,
                             const std::vector<CrankTrainSample>& coarse_samples,
                             const CoarseCompanion& companion, const SlapInputs& slap,
                             const SlapInputs& coarse_slap) {
  ErrorEstimate estimate;
  estimate.skirt_ratio = companion.skirt_ratio;
  estimate.big_end_ratio = companion.big_end_ratio;
  estimate.tolerance_factor = companion.tolerance_factor;
  std::vector<HeadlineFigure> figures = HeadlineFigures(samples, slap);
  std::vector<HeadlineFigure> coarse = HeadlineFigures(coarse_samples, coarse_slap);
  if (figures.empty()) {
    estimate.status = "not-applicable";
    estimate.message = "no lubricated joint";
    return estimate;
  }
  // The slap figure exists where the piston changes side: one run may have it and the other not
  // (a light side force near zero); it is then not estimated (nothing to compare it with).
  const auto has = [](const std::vector<HeadlineFigure>& list, const std::string& key) {
    return std::any_of(list.begin(), list.end(),
                       [&key](const HeadlineFigure& f) { return f.key == key; });
  };
  if (has(figures, kSlapKey) != has(coarse, kSlapKey)) {
    for (auto* list : {&figures, &coarse})
      std::erase_if(*list, [](const HeadlineFigure& f) { return f.key == kSlapKey; });
  }
  if (coarse.size() != figures.size()) {
    estimate.status = "unavailable";
    estimate.message = "the coarse run reported no cycle";
    return estimate;
  }
  // Peaks that either run's samples do not resolve in time.
  std::vector<std::string> unresolved;
  for (const auto* run : {&samples, &coarse_samples}) {
    for (const std::string& key : UnresolvedKeys(*run, true)) unresolved.push_back(key);
  }
  for (std::size_t k = 0; k < figures.size(); ++k) {
    const double r = figures[k].big_end ? companion.big_end_ratio : companion.skirt_ratio;
    if (r < 1.05) {
      estimate.status = "unavailable";
      estimate.message = fmt::format(
          "the {} mesh is at its smallest element counts and cannot be coarsened",
          figures[k].big_end ? "big-end" : "skirt");
      estimate.figures.clear();
      return estimate;
    }
    FigureError e;
    e.figure = figures[k];
    // (A hole-fed mass-conserving big end's oil keeps its own order: observed 1.7-2.4 there.)
    if (!e.figure.big_end)
      e.figure.order = std::min(e.figure.order, companion.skirt_max_order);
    else if (e.figure.key != kBearingOilKey)
      e.figure.order = std::min(e.figure.order, companion.big_end_max_order);
    e.coarse_value = coarse[k].value;
    const double factor = 1.0 / (std::pow(r, e.figure.order) - 1.0);
    e.error = (figures[k].value - coarse[k].value) * factor;
    const HeadlineDefinition* definition = DefinitionOf(e.figure.key);
    if (definition && IsCurveExtreme(*definition)) {
      if (const std::optional<CurveExtreme> x =
              ExtrapolatedExtreme(*definition, samples, coarse_samples, factor)) {
        e.error = x->value - figures[k].value;
        e.extrapolated_crank_angle = samples[x->index].crank_angle;
        e.crank_angle = samples[x->own].crank_angle;
        const double apart = std::abs(CycleCrankAngleDeg(*e.extrapolated_crank_angle) -
                                      CycleCrankAngleDeg(*e.crank_angle));
        e.extreme_elsewhere =
            std::min(apart, 720.0 - apart) > kElsewhereAngle &&
            std::abs(x->value - x->at_own) > kElsewhereShare * std::abs(figures[k].value);
      }
    }
    e.relative = figures[k].value != 0.0 ? std::abs(e.error / figures[k].value) : 0.0;
    e.resolved_in_time =
        std::find(unresolved.begin(), unresolved.end(), e.figure.key) == unresolved.end();
    e.far_companion = e.CompanionDistance() > kFarCompanion;
    if (e.resolved_in_time && e.relative >= estimate.worst_relative) {
      estimate.worst_relative = e.relative;
      estimate.worst_label = e.figure.label;
    }
    estimate.figures.push_back(e);
  }
  estimate.status = "estimated";
  return estimate;
}

std::string ErrorEstimate::Summary() const {
  if (status == "off") return "discretisation error not estimated (solver.error_estimate = 0)";
  if (status == "not-applicable") return "no film joint: no discretisation error to estimate";
  if (status == "unavailable") {
    return "warning: discretisation error not estimated: " + message;
  }
  // What follows the figure: peaks between output samples (named, not estimated), extremes the
  // meshes place apart, a mass-conserving big end's note.
  const auto join = [](const std::vector<std::string>& items) {  // "a", "a and b", "a, b and c"
    std::string text;
    for (std::size_t k = 0; k < items.size(); ++k)
      text += (k == 0 ? "" : k + 1 == items.size() ? " and " : ", ") + items[k];
    return text;
  };
  std::vector<std::string> spiked;
  for (const FigureError& e : figures)
    if (!e.resolved_in_time) spiked.push_back(e.figure.label);
  std::string notes;
  const std::string spikes = join(spiked);
  if (!spikes.empty()) notes = fmt::format("; {} {}", spikes, kUnresolvedPeakNote);
  // Extremes whose place in the cycle the meshes disagree on.
  for (const FigureError& e : figures) {
    if (!e.resolved_in_time || !e.extreme_elsewhere || !e.crank_angle ||
        !e.extrapolated_crank_angle)
      continue;
    notes += fmt::format(
        "; the meshes disagree on where the {} lies: this run has it at {:.0f} °CA, the "
        "extrapolation at {:.0f} °CA",
        e.figure.label, CycleCrankAngleDeg(*e.crank_angle),
        CycleCrankAngleDeg(*e.extrapolated_crank_angle));
  }
  // Figures whose companion lies far from this run: a rough estimate.
  std::vector<std::string> far_figures;
  for (const FigureError& e : figures) {
    if (!e.resolved_in_time || !e.far_companion) continue;
    far_figures.push_back(
        fmt::format("{} ({:.0f} %)", e.figure.label, 100.0 * e.CompanionDistance()));
  }
  if (const std::string far = join(far_figures); !far.empty()) {
    notes += fmt::format(
        "; the companion run on the coarser mesh lies far from this run in the {}: outside the "
        "range where the two meshes' difference measures the error, so those estimates are "
        "rough (they can be several times too large, or half too small); a finer mesh settles "
        "them",
        far);
  }
  // A mass-conserving big end (its oil figure): at low speed not in the asymptotic range of the
  // meshes the estimate compares (docs/validation/errors.md, section 6). A mass-conserving
  // skirt's figures converge as its film's.
  if (std::any_of(figures.begin(), figures.end(),
                  [](const FigureError& e) { return e.figure.key == kBearingOilKey; })) {
    notes += "; ";
    notes += kMassConservingNote;
  }
  if (worst_relative <= threshold) {
    return fmt::format("estimated discretisation error <= {:.2g} % (largest: {}){}",
                       100.0 * worst_relative, worst_label, notes);
  }
  // Every figure above the threshold, largest first, and the meshes of their joints. The
  // companion coarsens all of a mesh's directions together, so the estimate cannot say which
  // direction limits: refine them together.
  std::vector<const FigureError*> above;
  for (const FigureError& e : figures)
    if (e.resolved_in_time && e.relative > threshold) above.push_back(&e);
  std::stable_sort(above.begin(), above.end(), [](const FigureError* a, const FigureError* b) {
    return a->relative > b->relative;
  });
  std::vector<std::string> listed;
  bool big_end = false, skirt = false;
  for (const FigureError* e : above) {
    listed.push_back(fmt::format("{:.2g} % in the {}", 100.0 * e->relative, e->figure.label));
    (e->figure.big_end ? big_end : skirt) = true;
  }
  std::vector<std::string> meshes;
  if (skirt) meshes.push_back("the skirt's mesh (skirt.mesh_thrust, mesh_anti and mesh_axial)");
  if (big_end) meshes.push_back("the big end's mesh (big_end.mesh_theta and mesh_z)");
  return fmt::format(
      "warning: estimated discretisation error {} (above {:.0f} %): refine {} in all directions "
      "together (the estimate coarsens them together, so it cannot say which one limits) or "
      "tighten solver.relative_tolerance{}",
      join(listed), 100.0 * threshold, join(meshes), notes);
}

}  // namespace filmdyn::engine
