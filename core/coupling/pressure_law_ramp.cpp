#include "core/coupling/pressure_law_ramp.hpp"

#include <utility>

namespace filmdyn::coupling {

PressureLawRamp::PressureLawRamp(lubrication::PressureViscosity full, double end_time)
    : full_(std::move(full)), current_(full_), end_time_(end_time) {}

double RunInScale(double t, double end_time) {
  if (!(end_time > 0.0) || t >= end_time) return 1.0;
  if (!(t > 0.0)) return 0.0;
  const double x = t / end_time;
  return x * x * (3.0 - 2.0 * x);
}

double PressureLawRamp::Scale(double t) const { return RunInScale(t, end_time_); }

bool PressureLawRamp::Update(double t) {
  if (!full_.active()) return false;
  const double s = Scale(t);
  if (s == scale_) return false;
  scale_ = s;
  current_ = full_.Weakened(s);
  return true;
}

}  // namespace filmdyn::coupling
