#include "core/engine/pressure_curve.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/base/angles.hpp"
#include "core/base/input_error.hpp"

namespace filmdyn::engine {

namespace {
constexpr double kCycle = 4.0 * std::numbers::pi;
// An angle in crank degrees for a message, to 1e-4 °CA: angles typed in rad to a few decimals
// convert to degrees with float noise ("50.00000023 °CA") the user never wrote.
std::string Degrees(double rad) {
  return FormatValue(std::round(rad * kDegreesPerRadian * 1e4) / 1e4);
}
}  // namespace

CurveFields CurveFields::Points(const std::string& field) {
  CurveFields f;
  f.curve = field;
  f.point = [field](std::size_t k, bool angle) {
    return field + "[" + std::to_string(k) + "]" + (angle ? ".crank_angle" : ".pressure");
  };
  return f;
}

PressureCurve::PressureCurve(std::vector<double> angles, std::vector<double> pressures,
                             const CurveFields& fields) {
  const std::string& field = fields.curve;
  // An angle as the user gave it.
  const auto angle_text = [&fields](double a) {
    return fields.angles_in_radians ? FormatValue(a) + " rad (" + Degrees(a) + " °CA)"
                                    : Degrees(a) + " °CA";
  };
  if (angles.size() != pressures.size()) {
    throw InputError(field,
                     std::to_string(angles.size()) + " angles, " +
                         std::to_string(pressures.size()) + " pressures",
                     "needs as many pressures as crank angles");
  }
  if (angles.size() < 8) {
    throw InputError(field,
                     std::to_string(angles.size()) + (angles.size() == 1 ? " point" : " points"),
                     "needs at least 8 points covering 0–720 °CA, at most 10 °CA apart");
  }
  for (std::size_t k = 0; k < angles.size(); ++k) {
    RequireInRange(fields.point(k, true), angles[k], 0.0, kCycle + 1e-9, false, false, "rad");
    // Up to 1 GPa (10 kbar): ~40x the peak of a highly loaded diesel, and far from the
    // double range the gas force is computed in.
    RequireInRange(fields.point(k, false), pressures[k], 0.0, 1e9, false, false, "Pa");
    if (k > 0 && angles[k] <= angles[k - 1]) {
      throw InputError(fields.point(k, true), angle_text(angles[k]),
                       "crank angles must increase strictly (the one before: " +
                           angle_text(angles[k - 1]) + ")");
    }
  }
  const double peak = *std::max_element(pressures.begin(), pressures.end());
  if (angles.back() >= kCycle - 1e-9) {
    if (angles.front() > 1e-9 ||
        std::abs(pressures.back() - pressures.front()) > 0.01 * std::max(peak, 1.0)) {
      throw InputError(field,
                       "p(720) = " + FormatValue(pressures.back()) +
                           " Pa, p(0) = " + FormatValue(pressures.front()) + " Pa",
                       "a point at 720 °CA must repeat the point at 0 °CA (periodic cycle)");
    }
    angles.pop_back();
    pressures.pop_back();
  }
  // The largest gap. Angles typed in rad to four decimals (a 10 °CA grid as 0.1745, 0.3491, …)
  // are each off by up to 5e-5 rad, so their gaps by up to 1e-4 rad (0.006 °CA): such a grid is
  // accepted as the 10 °CA grid it stands for.
  constexpr double kLargestGap = 10.0 * kRadiansPerDegree + 1.01e-4;
  for (std::size_t k = 1; k < angles.size(); ++k) {
    if (angles[k] - angles[k - 1] > kLargestGap) {
      throw InputError(fields.point(k, true), angle_text(angles[k]),
                       Degrees(angles[k] - angles[k - 1]) +
                           " °CA after the point before it: the curve must cover 0–720 °CA "
                           "with gaps of at most 10 °CA");
    }
  }
  if (const double wrap = angles.front() + kCycle - angles.back(); wrap > kLargestGap) {
    throw InputError(field,
                     "from " + angle_text(angles.back()) + " round to " +
                         angle_text(angles.front()) + ": a gap of " + Degrees(wrap) + " °CA",
                     "the curve must cover 0–720 °CA with gaps of at most 10 °CA");
  }
  angles_ = std::move(angles);
  pressures_ = std::move(pressures);
  // Periodic Fritsch–Carlson slopes.
  const int n = static_cast<int>(angles_.size());
  auto h_at = [&](int k) {  // width of interval k → k+1 (periodic)
    return k + 1 < n ? angles_[k + 1] - angles_[k] : angles_[0] + kCycle - angles_[n - 1];
  };
  auto delta_at = [&](int k) { return (pressures_[(k + 1) % n] - pressures_[k]) / h_at(k); };
  slopes_.assign(n, 0.0);
  for (int k = 0; k < n; ++k) {
    const int km = (k + n - 1) % n;
    const double d0 = delta_at(km), d1 = delta_at(k);
    if (d0 * d1 <= 0.0) continue;
    const double h0 = h_at(km), h1 = h_at(k);
    const double w1 = 2.0 * h1 + h0, w2 = h1 + 2.0 * h0;
    slopes_[k] = (w1 + w2) / (w1 / d0 + w2 / d1);
  }
}

void PressureCurve::Locate(double crank_angle, int* k, double* s, double* h) const {
  double a = std::fmod(crank_angle, kCycle);
  if (a < 0) a += kCycle;
  const int n = static_cast<int>(angles_.size());
  auto it = std::upper_bound(angles_.begin(), angles_.end(), a);
  int i = static_cast<int>(it - angles_.begin()) - 1;
  if (i < 0) {  // before the first knot: in the wrap interval
    i = n - 1;
    a += kCycle;
  }
  const double right = i + 1 < n ? angles_[i + 1] : angles_[0] + kCycle;
  *k = i;
  *h = right - angles_[i];
  *s = (a - angles_[i]) / *h;
}

double PressureCurve::Pressure(double crank_angle) const {
  int k;
  double s, h;
  Locate(crank_angle, &k, &s, &h);
  const int k1 = (k + 1) % static_cast<int>(angles_.size());
  const double s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * pressures_[k] + (s3 - 2 * s2 + s) * h * slopes_[k] +
         (-2 * s3 + 3 * s2) * pressures_[k1] + (s3 - s2) * h * slopes_[k1];
}

double PressureCurve::Slope(double crank_angle) const {
  int k;
  double s, h;
  Locate(crank_angle, &k, &s, &h);
  const int k1 = (k + 1) % static_cast<int>(angles_.size());
  const double s2 = s * s;
  return ((6 * s2 - 6 * s) * pressures_[k] + (-6 * s2 + 6 * s) * pressures_[k1]) / h +
         (3 * s2 - 4 * s + 1) * slopes_[k] + (3 * s2 - 2 * s) * slopes_[k1];
}

double PressureCurve::PeakPressure() const {
  return *std::max_element(pressures_.begin(), pressures_.end());
}

double PressureCurve::PeakAngle() const {
  return angles_[std::max_element(pressures_.begin(), pressures_.end()) - pressures_.begin()];
}

PressureCurve PressureCurve::Blend(const PressureCurve& a, const PressureCurve& b, double w) {
  std::vector<double> p(a.angles_.size());
  for (std::size_t k = 0; k < p.size(); ++k) {
    p[k] = (1.0 - w) * a.pressures_[k] + w * b.Pressure(a.angles_[k]);
  }
  return PressureCurve(a.angles_, p, "pressure curve blend");
}

}  // namespace filmdyn::engine
