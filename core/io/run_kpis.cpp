#include "core/io/run_kpis.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "core/engine/error_estimate.hpp"
#include "core/engine/slider_crank_reference.hpp"
#include "core/io/results_writer.hpp"

namespace filmdyn::io {

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

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

// The piston's lateral and angular velocity at one instant.
struct PistonVelocity {
  double time = 0.0;
  double lateral = 0.0;  // X velocity of the centre of mass [m/s]
  double angular = 0.0;  // [rad/s]
};

// The velocities at time t, linear between the neighbouring entries of `track` (time order);
// the end values outside it.
PistonVelocity At(const std::vector<PistonVelocity>& track, double t) {
  const auto after = std::upper_bound(track.begin(), track.end(), t,
                                      [](double x, const PistonVelocity& p) { return x < p.time; });
  if (after == track.begin()) return track.front();
  if (after == track.end()) return track.back();
  const PistonVelocity &a = *(after - 1), &b = *after;
  const double s = (t - a.time) / (b.time - a.time);
  return {t, a.lateral + s * (b.lateral - a.lateral), a.angular + s * (b.angular - a.angular)};
}

PistonSlap SlapOf(const std::vector<engine::CrankTrainSample>& samples,
                  const std::vector<engine::MotionSample>& motion, double mass, double inertia,
                  bool whole_cycle) {
  PistonSlap slap;
  const std::size_t n = samples.size();
  if (whole_cycle) slap.energy_sum = 0.0;
  if (n < 2) return slap;
  // The velocities from the motion samples (every output step and the integrator's own
  // interpolation between them); a run without motion samples (data from before they existed)
  // falls back to the output samples' own values, which are the motion at the output steps.
  std::vector<PistonVelocity> track;
  auto add = [&track](const engine::MotionSample& m) {
    if (m.piston_present && (track.empty() || m.time > track.back().time)) {
      track.push_back({m.time, m.piston_com_lateral_velocity, m.piston_tilt_rate});
    }
  };
  if (!motion.empty()) {
    for (const engine::MotionSample& m : motion) add(m);
  } else {
    for (const engine::CrankTrainSample& s : samples) add(engine::MotionOf(s));
  }
  if (track.empty()) return slap;
  // One cycle later the motion repeats: the first step's velocities close the wrap interval.
  const double period = (samples.back().time - samples.front().time) * static_cast<double>(n) /
                        static_cast<double>(n - 1);
  if (whole_cycle && track.front().time == samples.front().time) {
    PistonVelocity image = track.front();
    image.time += period;
    track.push_back(image);
  }
  // The side of each output step: -1 pressed onto the major-thrust wall (results.csv's
  // skirt_normal_force < 0), +1 onto the other, 0 with no side force at all (a starved skirt
  // off its oil), kUnknown without a finite film force. The piston changes side between two
  // steps with a side, the later one on the other; the last step and the first one cycle later
  // are neighbours when the samples are a whole cycle (that event comes last in time, and its
  // crank angle, within the cycle, reads small when it falls past the cycle's end). The instant
  // is where the straight line between the two forces crosses zero — between the last step
  // without a side force and the first on the new side where such steps lie between them (the
  // force of the new side begins there).
  constexpr int kUnknown = 2;
  const auto side = [&samples](std::size_t k) {
    const engine::CrankTrainSample& s = samples[k];
    if (!s.skirt.present || !std::isfinite(s.skirt.normal_force)) return kUnknown;
    return (s.skirt.normal_force > 0.0) - (s.skirt.normal_force < 0.0);
  };
  // Positions p run over the steps, and on into the next cycle for a whole one.
  const auto time_at = [&](std::size_t p) { return samples[p % n].time + (p >= n ? period : 0.0); };
  const auto angle_at = [&](std::size_t p) {
    return samples[p % n].crank_angle + (p >= n ? 4.0 * std::numbers::pi : 0.0);
  };
  const auto force_at = [&](std::size_t p) { return samples[p % n].skirt.normal_force; };
  // A whole cycle is scanned from its first step with a side round to that step one cycle on
  // (a change of side across steps without one at the cycle's start is then seen once).
  std::size_t first = 0;
  if (whole_cycle) {
    while (first + 1 < n && (side(first) == 0 || side(first) == kUnknown)) ++first;
  }
  const std::size_t last_end = whole_cycle ? first + n : n - 1;
  std::optional<std::size_t> sided;  // the last step with a side before p
  for (std::size_t p = first; p <= last_end; ++p) {
    const int now = side(p % n);
    if (now == kUnknown) {
      sided.reset();  // no change of side is judged across a step without a film force
      continue;
    }
    if (now == 0) continue;
    if (sided && side(*sided % n) != now) {
      const std::size_t a = p - 1;  // the step before: the last with a side, or one without
      const double fa = a == *sided ? force_at(a) : 0.0, fb = force_at(p);
      const double s = fa / (fa - fb);
      const double t = time_at(a) + s * (time_at(p) - time_at(a));
      const PistonVelocity v = At(track, t);
      SlapEvent e;
      e.crank_angle_deg = CycleCrankAngleDeg(angle_at(a) + s * (angle_at(p) - angle_at(a)));
      e.energy = 0.5 * mass * v.lateral * v.lateral + 0.5 * inertia * v.angular * v.angular;
      e.to_thrust = fb < 0.0;
      if (slap.energy_sum) *slap.energy_sum += e.energy;
      if (!slap.energy_max || e.energy > *slap.energy_max) {
        slap.energy_max = e.energy;
        slap.energy_max_crank_angle_deg = e.crank_angle_deg;
      }
      slap.events.push_back(e);
    }
    sided = p;
  }
  return slap;
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
    p.angle_deg = s.skirt.moft_alpha * kDeg;
    p.axial_m = s.skirt.moft_y;
  } else {
    const Eigen::Vector2d& e = s.bearing.journal_ecc_rod;
    p.angle_deg = std::atan2(e.y(), e.x()) * kDeg;
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
    kpis.skirt->slap = SlapOf(samples, motion, piston_mass, piston_inertia, whole_cycle);
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
