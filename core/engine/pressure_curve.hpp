#pragma once
/// @file Cylinder pressure vs crank angle over one four-stroke cycle (0–720 °CA, 360 = firing
/// TDC), interpolated periodically with a shape-preserving cubic (Fritsch & Carlson 1980
/// monotone PCHIP), so the gas force is C¹ in time and never overshoots the data.
#include <string>
#include <vector>

namespace filmdyn::engine {

class PressureCurve {
 public:
  PressureCurve() = default;
  /// angles [rad] strictly increasing within [0, 4π], pressures absolute [Pa], finite, ≥ 0.
  /// The largest gap, including the wrap-around from the last angle to the first + 4π, must be
  /// ≤ 10 °CA; a point at 4π must repeat the one at 0 (within 1 % of the peak). Throws
  /// InputError naming `field` otherwise.
  PressureCurve(std::vector<double> angles, std::vector<double> pressures,
                const std::string& field);

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
