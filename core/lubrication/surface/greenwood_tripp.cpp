#include "core/lubrication/surface/greenwood_tripp.hpp"

#include <boost/math/quadrature/gauss.hpp>

#include <array>
#include <cassert>
#include <cmath>
#include <numbers>

namespace filmdyn::lubrication {
namespace {

// Fit constants: Hu, Cheng, Arai, Kobayashi, Aoyama 1994 (Numerical simulation of piston ring in
// mixed lubrication), also Arcoumanis et al. 1997; eq. 30 prints 4.486e-5 (a misprint).
constexpr double kFitAmplitude = 4.4086e-5;
constexpr double kFitExponent = 6.804;
constexpr double kFitCutoff = 4.0;

// Composite 10-point Gauss–Legendre (Boost.Math's rule) over panels of the smooth integrand.
constexpr int kQuadraturePanels = 64;

// Lookup table of ln F_n on a uniform grid with exact slopes for cubic Hermite interpolation.
constexpr double kTableStart = -4.0;
constexpr double kTableEnd = 12.0;
constexpr int kStepsPerUnit = 64;
constexpr int kTableNodes = static_cast<int>((kTableEnd - kTableStart) * kStepsPerUnit) + 1;
constexpr double kTableStep = 1.0 / kStepsPerUnit;

class LogTable {
 public:
  explicit LogTable(double order) : order_(order) {
    for (int i = 0; i < kTableNodes; ++i) {
      const double h = kTableStart + i * kTableStep;
      const double f = GreenwoodTrippQuadrature(order, h);
      const double f_lower = GreenwoodTrippQuadrature(order - 1.0, h);
      log_f_[i] = std::log(f);
      slope_[i] = -order * f_lower / f;  // dF_n/dH = -n F_(n-1)
    }
    tail_series_at_end_ = AsymptoticSeries(kTableEnd);
  }

  double operator()(double H) const {
    if (H < kTableStart) {
      // Continue with the exact slope at the table start: positive and growing as H decreases.
      const double f0 = std::exp(log_f_[0]);
      return f0 * (1.0 + slope_[0] * (H - kTableStart));
    }
    if (H >= kTableEnd) {
      // F_n ~ Gamma(n+1)/sqrt(2 pi) H^-(n+1) e^(-H^2/2) * series, scaled to the table's last
      // node so that F is continuous at the table end.
      const double ratio = kTableEnd / H;
      return std::exp(log_f_[kTableNodes - 1]) * std::pow(ratio, order_ + 1.0) *
             std::exp(-0.5 * (H - kTableEnd) * (H + kTableEnd)) * AsymptoticSeries(H) /
             tail_series_at_end_;
    }
    const double position = (H - kTableStart) * kStepsPerUnit;
    int i = static_cast<int>(position);
    if (i > kTableNodes - 2) i = kTableNodes - 2;
    const double t = position - i;
    const double t2 = t * t;
    const double t3 = t2 * t;
    const double h00 = 2.0 * t3 - 3.0 * t2 + 1.0;
    const double h10 = t3 - 2.0 * t2 + t;
    const double h01 = -2.0 * t3 + 3.0 * t2;
    const double h11 = t3 - t2;
    const double log_f = h00 * log_f_[i] + h10 * kTableStep * slope_[i] + h01 * log_f_[i + 1] +
                         h11 * kTableStep * slope_[i + 1];
    return std::exp(log_f);
  }

 private:
  // sum_k (-1)^k Gamma(n+2k+1) / (Gamma(n+1) 2^k k!) H^(-2k), from expanding
  // integral_0^inf t^n exp(-H t - t^2/2) dt; six terms leave < 1e-6 relative at H >= 12.
  double AsymptoticSeries(double H) const {
    const double inv_h2 = 1.0 / (H * H);
    double term = 1.0;
    double sum = 1.0;
    for (int k = 1; k < 6; ++k) {
      term *= -(order_ + 2.0 * k - 1.0) * (order_ + 2.0 * k) / (2.0 * k) * inv_h2;
      sum += term;
    }
    return sum;
  }

  double order_;
  double tail_series_at_end_ = 1.0;
  std::array<double, kTableNodes> log_f_{};
  std::array<double, kTableNodes> slope_{};
};

const LogTable& TableF52() {
  static const LogTable table(2.5);
  return table;
}

const LogTable& TableF32() {
  static const LogTable table(1.5);
  return table;
}

}  // namespace

double GreenwoodTrippF52Fit(double H) {
  if (H >= kFitCutoff) return 0.0;
  return kFitAmplitude * std::pow(kFitCutoff - H, kFitExponent);
}

double GreenwoodTrippF52Exact(double H) { return TableF52()(H); }

double GreenwoodTrippF32Exact(double H) { return TableF32()(H); }

double GreenwoodTrippQuadrature(double n, double H) {
  assert(n >= 0.0);
  const double u_end = std::sqrt(std::abs(H) + 10.0);
  const double panel = u_end / kQuadraturePanels;
  const double power = 2.0 * n + 1.0;
  auto integrand = [H, power](double u) {
    const double s = H + u * u;
    return 2.0 * std::pow(u, power) * std::exp(-0.5 * s * s);
  };
  double sum = 0.0;
  for (int p = 0; p < kQuadraturePanels; ++p) {
    sum += boost::math::quadrature::gauss<double, 10>::integrate(integrand, p * panel,
                                                                 (p + 1) * panel);
  }
  return sum / std::sqrt(2.0 * std::numbers::pi);
}

}  // namespace filmdyn::lubrication
