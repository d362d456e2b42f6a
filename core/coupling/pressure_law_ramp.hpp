#pragma once
/// @file Phasing a pressure-viscosity law in over the start of an engine run.
///
/// An engine run starts from rest: in its first steps the journal and the piston meet their films
/// at metres per second, and the isoviscous film pressure passes any pressure law's limit (1/alpha
/// for Barus: the pressure the film would need is infinite). The run therefore starts without the
/// law and phases it in: ln(mu / mu0) is scaled by s(t) = x^2 (3 - 2x), x = t / t_end, smooth and
/// monotone from 0 at t = 0 to 1 at t_end, which the engine run puts halfway through its run-in
/// (before the first reported cycle). From t_end on the law is the oil's own.
#include "core/lubrication/oil.hpp"

namespace filmdyn::coupling {

/// The run-in's phase-in factor s(t) = x^2 (3 - 2x), x = t / end_time: 0 at t <= 0, 1 from
/// end_time on (and always 1 when end_time <= 0). Pressure laws and surface compliances use it.
double RunInScale(double t, double end_time);

class PressureLawRamp {
 public:
  PressureLawRamp() = default;  ///< no law
  /// `end_time` [s] <= 0: the full law from the start.
  PressureLawRamp(lubrication::PressureViscosity full, double end_time);

  /// Moves to time t [s]; true when the law changed (law() is then the new one).
  bool Update(double t);
  const lubrication::PressureViscosity& law() const { return current_; }
  /// Whether the law still changes after t (results then depend on the time as well).
  bool VariesAfter(double t) const { return full_.active() && t < end_time_; }
  /// The factor on ln(mu / mu0) at t: 0 at t <= 0, 1 from end_time on.
  double Scale(double t) const;

 private:
  lubrication::PressureViscosity full_, current_;
  double end_time_ = 0.0;
  double scale_ = 1.0;  // the current law's
};

}  // namespace filmdyn::coupling
