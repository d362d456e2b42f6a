#include "core/engine/synthetic_pressure.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/base/angles.hpp"
#include "core/engine/slider_crank_reference.hpp"

namespace filmdyn::engine {

namespace {
constexpr double kGasConstant = 287.0;  // air [J/(kg·K)]
}  // namespace

SyntheticPressureParameters SyntheticPressureParameters::ForSpeed(double rpm) {
  // Calibration points: breathing peaks mid-range, burn angle grows with speed, spark advanced.
  struct Point {
    double rpm, intake, exhaust, start, duration;
  };
  static const Point table[] = {{1000, 0.88e5, 1.03e5, 347.0, 36.0},
                                {2000, 0.96e5, 1.05e5, 345.0, 40.0},
                                {4000, 1.01e5, 1.10e5, 342.0, 46.0},
                                {6000, 0.96e5, 1.18e5, 338.0, 52.0}};
  const double r = std::clamp(rpm, table[0].rpm, table[3].rpm);
  int k = 0;
  while (k < 2 && r > table[k + 1].rpm) ++k;
  const double w = (r - table[k].rpm) / (table[k + 1].rpm - table[k].rpm);
  auto lerp = [w](double a, double b) { return a + w * (b - a); };
  SyntheticPressureParameters p;
  p.rpm = rpm;
  p.intake_pressure = lerp(table[k].intake, table[k + 1].intake);
  p.exhaust_pressure = lerp(table[k].exhaust, table[k + 1].exhaust);
  p.combustion_start_deg = lerp(table[k].start, table[k + 1].start);
  p.combustion_duration_deg = lerp(table[k].duration, table[k + 1].duration);
  return p;
}

std::vector<double> SyntheticCylinderPressure(const CrankTrainGeometry& g,
                                              const SyntheticPressureParameters& p,
                                              const std::vector<double>& crank_angle_deg) {
  const double area = std::numbers::pi * g.liner_radius * g.liner_radius;
  auto height = [&](double deg) {
    return ExactSliderCrank(g, deg * kRadiansPerDegree, 0.0, 0.0).piston_position;
  };
  double top = 0.0, bottom = 1e9;
  for (double deg = 0; deg < 360; deg += 0.05) {
    top = std::max(top, height(deg));
    bottom = std::min(bottom, height(deg));
  }
  const double displacement = area * (top - bottom);
  const double clearance = displacement / (g.compression_ratio - 1.0);
  auto volume = [&](double deg) { return clearance + area * (top - height(deg)); };

  // Closed cycle, RK4 in 0.05° steps from IVC to EVO.
  const double step = 0.05;
  const int n = static_cast<int>(std::round((p.evo_deg - p.ivc_deg) / step));
  const double v_ivc = volume(p.ivc_deg);
  const double charge = p.intake_pressure * v_ivc / (kGasConstant * p.intake_temperature);
  const double heat =
      p.heat_release_efficiency * charge / (1.0 + p.air_fuel_ratio) * p.fuel_heating_value;
  auto burn_rate = [&](double deg) {  // dx_b/dφ per degree
    const double s = (deg - p.combustion_start_deg) / p.combustion_duration_deg;
    if (s <= 0.0 || s >= 2.5) return 0.0;
    const double m1 = p.wiebe_m + 1.0;
    return p.wiebe_a * m1 / p.combustion_duration_deg * std::pow(s, p.wiebe_m) *
           std::exp(-p.wiebe_a * std::pow(s, m1));
  };
  auto dp = [&](double deg, double pressure) {  // dp/dφ per degree, Heywood eq. 9.25
    const double v = volume(deg);
    const double dv = (volume(deg + 1e-4) - volume(deg - 1e-4)) / 2e-4;
    return -p.polytropic_exponent * pressure / v * dv +
           (p.polytropic_exponent - 1.0) / v * heat * burn_rate(deg);
  };
  std::vector<double> closed(n + 1);
  closed[0] = p.intake_pressure;
  for (int k = 0; k < n; ++k) {
    const double a = p.ivc_deg + k * step, y = closed[k];
    const double k1 = dp(a, y), k2 = dp(a + step / 2, y + step / 2 * k1),
                 k3 = dp(a + step / 2, y + step / 2 * k2), k4 = dp(a + step, y + step * k3);
    closed[k + 1] = y + step / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  const double p_evo = closed[n];
  auto closed_at = [&](double deg) {
    const double x = (deg - p.ivc_deg) / step;
    const int k = std::clamp(static_cast<int>(x), 0, n - 1);
    const double w = x - k;
    return (1 - w) * closed[k] + w * closed[k + 1];
  };
  auto smoothstep = [](double x) {
    x = std::clamp(x, 0.0, 1.0);
    return x * x * (3 - 2 * x);
  };
  std::vector<double> out;
  out.reserve(crank_angle_deg.size());
  const double half = p.overlap_blend_deg / 2;
  for (double deg : crank_angle_deg) {
    double value;
    if (deg >= p.ivc_deg && deg <= p.evo_deg) {
      value = closed_at(deg);
    } else if (deg > p.evo_deg) {
      const double exhaust = p.exhaust_pressure + (p_evo - p.exhaust_pressure) *
                                                      std::exp(-(deg - p.evo_deg) / p.blowdown_deg);
      const double w = smoothstep((deg - (720.0 - half)) / p.overlap_blend_deg);
      value = (1 - w) * exhaust + w * p.intake_pressure;
    } else {  // intake stroke, blending from exhaust pressure across 0 °CA
      const double w = smoothstep((deg + half) / p.overlap_blend_deg);
      value = (1 - w) * p.exhaust_pressure + w * p.intake_pressure;
    }
    out.push_back(value);
  }
  return out;
}

}  // namespace filmdyn::engine
