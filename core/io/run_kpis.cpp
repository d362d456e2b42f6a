#include "core/io/run_kpis.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "core/base/angles.hpp"
#include "core/engine/error_estimate.hpp"
#include "core/engine/slider_crank_reference.hpp"
#include "core/io/results_writer.hpp"

namespace filmdyn::io {

namespace {

// Index of the output step where `value` is smallest (largest when `largest`) among the samples
// where `present` holds and the value is finite; the first on a tie. samples.size() when none.
template <typename Present, typename Value>
std::size_t Extreme(const std::vector<engine::CrankTrainSample>& samples, Present present,
                    Value value, bool largest) {
  std::size_t at = samples.size();
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const double v = value(samples[k]);
    if (!present(samples[k]) || !std::isfinite(v)) continue;
    if (at == samples.size() || (largest ? v > value(samples[at]) : v < value(samples[at]))) {
      at = k;
    }
  }
  return at;
}

// The headline figure `key` of the samples, if present and finite.
std::optional<double> Headline(const std::vector<engine::HeadlineFigure>& figures,
                               const std::string& key) {
  for (const engine::HeadlineFigure& f : figures) {
    if (f.key == key && std::isfinite(f.value)) return f.value;
  }
  return std::nullopt;
}

// The film KPIs of one joint, if it has samples.
std::optional<JointKpis> FilmKpisOf(const std::vector<engine::CrankTrainSample>& samples,
                                    bool skirt) {
  using S = engine::CrankTrainSample;
  const auto present = [skirt](const S& s) { return skirt ? s.skirt.present : s.bearing.present; };
  const std::size_t none = samples.size();
  const std::size_t min_moft = Extreme(
      samples, present, [skirt](const S& s) { return skirt ? s.skirt.moft : s.bearing.moft; },
      false);
  if (min_moft == none) return std::nullopt;
  auto angle = [&samples](std::size_t k) { return CycleCrankAngleDeg(samples[k].crank_angle); };
  JointKpis j;
  const S& at = samples[min_moft];
  j.min_moft = skirt ? at.skirt.moft : at.bearing.moft;
  j.min_moft_crank_angle_deg = angle(min_moft);
  j.min_moft_position = MinFilmPosition(at, skirt);
  // A peak and its crank angle; no angle when the peak is 0 (nowhere in the cycle).
  auto peak = [&](double (*value)(const S&), double* peak_value, std::optional<double>* where) {
    const std::size_t k = Extreme(samples, present, value, true);
    if (k == none) return;
    *peak_value = value(samples[k]);
    if (*peak_value > 0.0) *where = angle(k);
  };
  if (skirt) {
    peak([](const S& s) { return s.skirt.max_pressure; }, &j.peak_pressure,
         &j.peak_pressure_crank_angle_deg);
    peak([](const S& s) { return s.skirt.max_contact_pressure; }, &j.peak_contact_pressure,
         &j.peak_contact_pressure_crank_angle_deg);
    peak([](const S& s) { return s.skirt.max_deformation; }, &j.max_deformation,
         &j.max_deformation_crank_angle_deg);
  } else {
    peak([](const S& s) { return s.bearing.max_pressure; }, &j.peak_pressure,
         &j.peak_pressure_crank_angle_deg);
    peak([](const S& s) { return s.bearing.max_contact_pressure; }, &j.peak_contact_pressure,
         &j.peak_contact_pressure_crank_angle_deg);
    peak([](const S& s) { return s.bearing.max_deformation; }, &j.max_deformation,
         &j.max_deformation_crank_angle_deg);
    const std::size_t k = Extreme(
        samples, present, [](const S& s) { return s.bearing.eps; }, true);
    if (k != none) {
      j.max_eps = samples[k].bearing.eps;
      j.max_eps_crank_angle_deg = angle(k);
    }
  }
  j.mean_fpl = Headline(engine::HeadlineFigures(samples),
                        skirt ? "skirt_fpl_mean[W]" : "bearing_fpl_mean[W]");
  // Oil: the mean flows of the cycle's samples times its duration (equally spaced samples).
  std::vector<const S*> with;
  for (const S& s : samples)
    if (present(s)) with.push_back(&s);
  if (with.size() >= 2) {
    const double span = (with[1]->time - with[0]->time) * static_cast<double>(with.size());
    double in = 0.0, out = 0.0, wetted = 0.0;
    for (const S* s : with) {
      in += skirt ? s->skirt.inflow : s->bearing.supply_flow;
      out += skirt ? s->skirt.outflow : s->bearing.side_flow;
      wetted += s->skirt.wetted_fraction;
    }
    const double n = static_cast<double>(with.size());
    // Per cycle only over a whole cycle: a run stopped before its first cycle ended reports the
    // part it computed (its balance over that part is still given).
    if (engine::SamplesSpanACycle(samples)) {
      j.oil_in_per_cycle = in / n * span;
      j.oil_out_per_cycle = out / n * span;
    }
    if (skirt) j.mean_wetted_fraction = wetted / n;
    const auto account = [skirt](const S* s) -> const coupling::OilAccount& {
      return skirt ? s->skirt.oil : s->bearing.oil;
    };
    // A film that keeps its account (a mass-conserving one) booked the oil at every integrator
    // step: its balance over the samples and, over a whole cycle, its oil instead of the sampled
    // flows (which miss the spikes between the samples).
    const bool kept = account(with.front()).kept && account(with.back()).kept;
    if (kept) j.oil_balance = account(with.back()).BalanceSince(account(with.front()));
    if (const auto oil = engine::AccountedOil(samples, !skirt)) {
      j.oil_in_per_cycle = oil->in;
      j.oil_out_per_cycle = oil->out;
    } else if (skirt && !kept) {
      // A Reynolds skirt creates the oil it lacks where its film reforms: its inflow is only the
      // edge cells' share beside a cavitated zone, which falls with the cell (it halves with
      // each refinement of the default case's mesh). No figure rather than a mesh quantity.
      j.oil_in_per_cycle.reset();
    }
  }
  return j;
}

}  // namespace

std::optional<double> ReportedOilPerCycle(const std::optional<JointKpis>& joint) {
  if (!joint || !joint->oil_balance) return std::nullopt;
  return joint->oil_in_per_cycle;
}

FilmPosition MinFilmPosition(const engine::CrankTrainSample& s, bool skirt) {
  FilmPosition p;
  if (skirt) {
    p.angle_deg = s.skirt.moft_alpha * kDegreesPerRadian;
    p.axial_m = s.skirt.moft_y;
  } else {
    const Eigen::Vector2d& e = s.bearing.journal_ecc_rod;
    p.angle_deg = std::atan2(e.y(), e.x()) * kDegreesPerRadian;
    if (p.angle_deg < 0.0) p.angle_deg += 360.0;
  }
  return p;
}

RunKpis ComputeRunKpis(const std::vector<engine::CrankTrainSample>& samples,
                       const std::vector<engine::MotionSample>& motion, double piston_mass,
                       double piston_inertia, bool whole_cycle) {
  RunKpis kpis;
  kpis.skirt = FilmKpisOf(samples, true);
  kpis.big_end = FilmKpisOf(samples, false);
  if (kpis.skirt)
    kpis.skirt->slap = engine::SlapOf(samples, motion, piston_mass, piston_inertia, whole_cycle);
  return kpis;
}

double FrictionMep(double mean_fpl_w, const engine::CrankTrainGeometry& geometry, double rpm) {
  const double cycle_s = 2.0 * 60.0 / rpm;  // 720 °CA
  return mean_fpl_w * cycle_s / engine::SweptVolume(geometry);
}

void AddFrictionMep(RunKpis* kpis, const engine::CrankTrainGeometry& geometry, double rpm) {
  double sum = 0.0;
  for (std::optional<JointKpis>* j : {&kpis->skirt, &kpis->big_end}) {
    if (!*j || !(*j)->mean_fpl) continue;
    (*j)->fmep = FrictionMep(*(*j)->mean_fpl, geometry, rpm);
    sum += *(*j)->fmep;
  }
  for (std::optional<JointKpis>* j : {&kpis->skirt, &kpis->big_end}) {
    if (*j && (*j)->fmep && sum > 0.0) (*j)->fmep_share = *(*j)->fmep / sum;
  }
}

RunKpis RunKpisOf(const engine::RunConfig& config, const engine::RunResult& result) {
  const engine::CrankTrainGeometry& g = config.engine_case.geometry;
  RunKpis kpis = ComputeRunKpis(result.samples, result.motion, g.piston_mass, g.piston_inertia,
                                engine::SamplesSpanACycle(result.samples));
  AddFrictionMep(&kpis, g, config.rpm);
  return kpis;
}

}  // namespace filmdyn::io
