#pragma once
/// @file Cylinder pressure vs crank angle over one four-stroke cycle (0–720 °CA, 360 = firing
/// TDC), interpolated periodically with a shape-preserving cubic (Fritsch & Carlson 1980
/// monotone PCHIP), so the gas force is C¹ in time and never overshoots the data.
#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace filmdyn::engine {

/// How a curve's input errors name what the user gave.
struct CurveFields {
  std::string curve;  ///< the whole curve: its number of points, its gaps, its periodic end
  /// The field of point k's crank angle (`angle`) or pressure.
  std::function<std::string(std::size_t k, bool angle)> point;
  bool angles_in_radians = false;  ///< the user gives the angles in rad (else in °CA)
  /// Points named `field[k].crank_angle` and `field[k].pressure`, angles in °CA (a case file's
  /// inline curve; a CSV file names its lines instead).
  static CurveFields Points(const std::string& field);
};

class PressureCurve {
 public:
  PressureCurve() = default;
  /// angles [rad] strictly increasing within [0, 4π], pressures absolute [Pa], finite, ≥ 0;
  /// at least 8 points. The largest gap, including the wrap-around from the last angle to the
  /// first + 4π, must be ≤ 10 °CA (up to a rounding of 1e-6 rad); a point at 4π must repeat the
  /// one at 0 (within 1 % of the peak). Throws InputError naming the field of `fields` otherwise.
  PressureCurve(std::vector<double> angles, std::vector<double> pressures,
                const CurveFields& fields);
  PressureCurve(std::vector<double> angles, std::vector<double> pressures, const std::string& field)
      : PressureCurve(std::move(angles), std::move(pressures), CurveFields::Points(field)) {}

  /// Pressure [Pa] at any crank angle [rad] (taken modulo 4π).
  double Pressure(double crank_angle) const;
  /// dp/dφ [Pa/rad].
  double Slope(double crank_angle) const;
  double PeakPressure() const;
  /// Crank angle of the largest tabulated pressure [rad], in [0, 4π).
  double PeakAngle() const;
  const std::vector<double>& Angles() const { return angles_; }
  const std::vector<double>& Pressures() const { return pressures_; }
  bool Empty() const { return angles_.empty(); }

  /// Linear blend (1 − w)·a + w·b on a's angles (for speeds between two tabulated curves).
  static PressureCurve Blend(const PressureCurve& a, const PressureCurve& b, double w);

 private:
  void Locate(double crank_angle, int* k, double* s, double* h) const;
  std::vector<double> angles_;  // periodic knots in [0, 4π), wrap point appended internally
  std::vector<double> pressures_;
  std::vector<double> slopes_;
};

}  // namespace filmdyn::engine
