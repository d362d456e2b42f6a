#include "core/engine/piston_slap.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace filmdyn::engine {

namespace {

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

}  // namespace

PistonSlap SlapOf(const std::vector<CrankTrainSample>& samples,
                  const std::vector<MotionSample>& motion, double mass, double inertia,
                  bool whole_cycle) {
  PistonSlap slap;
  const std::size_t n = samples.size();
  if (whole_cycle) slap.energy_sum = 0.0;
  if (n < 2) return slap;
  // The velocities from the motion samples (every output step and the integrator's own
  // interpolation between them); a run without motion samples (data from before they existed)
  // falls back to the output samples' own values, which are the motion at the output steps.
  std::vector<PistonVelocity> track;
  auto add = [&track](const MotionSample& m) {
    if (m.piston_present && (track.empty() || m.time > track.back().time)) {
      track.push_back({m.time, m.piston_com_lateral_velocity, m.piston_tilt_rate});
    }
  };
  if (!motion.empty()) {
    for (const MotionSample& m : motion) add(m);
  } else {
    for (const CrankTrainSample& s : samples) add(MotionOf(s));
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
    const CrankTrainSample& s = samples[k];
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

}  // namespace filmdyn::engine
