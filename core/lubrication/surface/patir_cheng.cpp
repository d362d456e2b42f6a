#include "core/lubrication/surface/patir_cheng.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

#include <boost/math/quadrature/gauss.hpp>

namespace filmdyn::lubrication::patir_cheng {
namespace {

// [PC78] Patir & Cheng 1978, Table 1 ("Coefficients of equation (22)"):
//   phi_x = 1 - C exp(-r H)  for gamma <= 1,   phi_x = 1 + C H^(-r)  for gamma > 1,
// with the H range over which each fit is stated to hold (H > 1 for gamma = 1/9 and 1/6,
// H > 0.75 for gamma = 1/3, H > 0.5 otherwise). Below the range 1/9 would go negative
// (1 - 1.48 e^-0.21 = -0.20 at H = 0.5), hence the per-curve lower limits.
struct PressureFlowFit {
  double c;
  double r;
  double h_min;
};
constexpr std::array<PressureFlowFit, kNumGammas> kPressureFlow = {{
    {1.48, 0.42, 1.0},   // gamma = 1/9
    {1.38, 0.42, 1.0},   // gamma = 1/6
    {1.18, 0.42, 0.75},  // gamma = 1/3
    {0.90, 0.56, 0.5},   // gamma = 1
    {0.225, 1.5, 0.5},   // gamma = 3
    {0.520, 1.5, 0.5},   // gamma = 6
    {0.870, 1.5, 0.5},   // gamma = 9
}};

// [PC79] Patir & Cheng 1979, Table 1 (shear flow factor, their eq. (12)):
//   Phi_s = A1 H^a1 exp(-a2 H + a3 H^2)  for H <= 5,   Phi_s = A2 exp(-0.25 H)  for H > 5.
struct ShearFlowFit {
  double a1_amp;
  double alpha1;
  double alpha2;
  double alpha3;
  double a2_amp_published;
};
constexpr std::array<ShearFlowFit, kNumGammas> kShearFlow = {{
    {2.046, 1.12, 0.78, 0.03, 1.856},  // gamma = 1/9
    {1.962, 1.08, 0.77, 0.03, 1.754},  // gamma = 1/6
    {1.858, 1.01, 0.76, 0.03, 1.561},  // gamma = 1/3
    {1.899, 0.98, 0.92, 0.05, 1.126},  // gamma = 1
    {1.560, 0.85, 1.13, 0.08, 0.556},  // gamma = 3
    {1.290, 0.62, 1.09, 0.08, 0.388},  // gamma = 6
    {1.011, 0.54, 1.07, 0.08, 0.295},  // gamma = 9
}};
constexpr double kShearFlowBranch = 5.0;      // [PC79]: H <= 5 / H > 5
constexpr double kShearFlowTailDecay = 0.25;  // [PC79]: exp(-0.25 H)

// [PC79] Patir & Cheng 1979, Table 4 (shear-stress factor Phi_fs, their eq. (28)):
//   Phi_fs = A3 H^a4 exp(-a5 H + a6 H^2)  for 0.5 < H < 7,  0 for H > 7.
struct ShearStressFsFit {
  double a3_amp;
  double alpha4;
  double alpha5;
  double alpha6;
};
constexpr std::array<ShearStressFsFit, kNumGammas> kShearStressFs = {{
    {14.1, 2.45, 2.30, 0.10},  // gamma = 1/9
    {13.4, 2.42, 2.30, 0.10},  // gamma = 1/6
    {12.3, 2.32, 2.30, 0.10},  // gamma = 1/3
    {11.1, 2.31, 2.38, 0.11},  // gamma = 1
    {9.8, 2.25, 2.80, 0.18},   // gamma = 3
    {10.1, 2.25, 2.90, 0.18},  // gamma = 6
    {8.7, 2.15, 2.97, 0.18},   // gamma = 9
}};
// Phi_fs(7) is 0.004-0.023 by the fit, not 0: taper to 0 over [6, 7] (C1 cubic smoothstep).
constexpr double kFsTaperStart = 6.0;
constexpr double kFsTaperEnd = 7.0;

// [PC79] Patir & Cheng 1979, Table 3 (shear-stress factor Phi_fp, their eq. (27)):
//   Phi_fp = 1 - D exp(-s H),  H > 0.5.
struct ShearStressFpFit {
  double d;
  double s;
};
constexpr std::array<ShearStressFpFit, kNumGammas> kShearStressFp = {{
    {1.51, 0.52},  // gamma = 1/9
    {1.51, 0.54},  // gamma = 1/6
    {1.47, 0.58},  // gamma = 1/3
    {1.40, 0.66},  // gamma = 1
    {0.98, 0.79},  // gamma = 3
    {0.97, 0.91},  // gamma = 6
    {0.73, 0.91},  // gamma = 9
}};

// Lower end of the [PC79] fits' range; the factors are held constant below it.
constexpr double kPc79LowerLimit = 0.5;

// [PC79] closed form of Phi_f (their eq. (24)): z = H/3, truncation eps* = 1/300.
constexpr double kPhiFCutoff = 1.0 / 300.0;
// Beyond z = H/3 = 5 the H > 3 closed form loses digits to cancellation; a series is used.
constexpr double kPhiFSeriesStart = 5.0;

// [WZ89] Wu & Zheng 1989 contact factor fit (their eq. (13)), 0 <= H < 3.
constexpr double kWz0 = -0.6912;
constexpr double kWz1 = 0.782;
constexpr double kWz2 = -0.304;
constexpr double kWz3 = 0.0401;
constexpr double kWzUpper = 3.0;

double WuZhengExponent(double H) { return kWz0 + H * (kWz1 + H * (kWz2 + H * kWz3)); }

template <typename Curve>
double Interpolate(const GammaBracket& bracket, double H, Curve curve) {
  const double lo = curve(bracket.lo, H);
  if (bracket.weight == 0.0) return lo;
  return lo + bracket.weight * (curve(bracket.hi, H) - lo);
}

}  // namespace

GammaBracket BracketPeklenik(double gamma) {
  GammaBracket bracket;
  if (!(gamma > kGammas.front())) {  // also NaN: the caller validated, this only guards
    bracket.lo = bracket.hi = 0;
    return bracket;
  }
  if (gamma >= kGammas.back()) {
    bracket.lo = bracket.hi = kNumGammas - 1;
    return bracket;
  }
  int hi = 1;
  while (kGammas[hi] < gamma) ++hi;
  const int lo = hi - 1;
  bracket.lo = lo;
  bracket.hi = hi;
  bracket.weight =
      (std::log(gamma) - std::log(kGammas[lo])) / (std::log(kGammas[hi]) - std::log(kGammas[lo]));
  if (bracket.weight >= 1.0) {  // gamma on a tabulated value: one curve suffices
    bracket.lo = hi;
    bracket.weight = 0.0;
  }
  return bracket;
}

double PressureFlowLowerLimit(int index) {
  assert(index >= 0 && index < kNumGammas);
  return kPressureFlow[index].h_min;
}

double PressureFlowTabulated(int index, double H) {
  assert(index >= 0 && index < kNumGammas);
  const PressureFlowFit& fit = kPressureFlow[index];
  const double h_eval = std::max(H, fit.h_min);
  if (kGammas[index] <= 1.0) return 1.0 - fit.c * std::exp(-fit.r * h_eval);
  return 1.0 + fit.c * std::pow(h_eval, -fit.r);
}

double ShearFlowTailAmplitude(int index) {
  assert(index >= 0 && index < kNumGammas);
  const ShearFlowFit& fit = kShearFlow[index];
  const double h = kShearFlowBranch;
  const double low_branch_at_5 =
      fit.a1_amp * std::pow(h, fit.alpha1) * std::exp(-fit.alpha2 * h + fit.alpha3 * h * h);
  return low_branch_at_5 * std::exp(kShearFlowTailDecay * h);
}

double ShearFlowPublishedTailAmplitude(int index) {
  assert(index >= 0 && index < kNumGammas);
  return kShearFlow[index].a2_amp_published;
}

double ShearFlowTabulated(int index, double H) {
  assert(index >= 0 && index < kNumGammas);
  const ShearFlowFit& fit = kShearFlow[index];
  const double h = std::max(H, kPc79LowerLimit);
  if (h <= kShearFlowBranch) {
    return fit.a1_amp * std::pow(h, fit.alpha1) * std::exp(-fit.alpha2 * h + fit.alpha3 * h * h);
  }
  // Same expression as ShearFlowTailAmplitude, folded so that the two branches agree at H = 5
  // to rounding: A2 exp(-0.25 H) = Phi_s,low(5) exp(-0.25 (H - 5)). Phi_s,low(5) is a constant
  // of the fit, evaluated once (this branch runs at every node of a thick film).
  static const std::array<double, kNumGammas> low_branch_at_5 = [] {
    std::array<double, kNumGammas> values{};
    const double h5 = kShearFlowBranch;
    for (int i = 0; i < kNumGammas; ++i) {
      const ShearFlowFit& f = kShearFlow[i];
      values[i] = f.a1_amp * std::pow(h5, f.alpha1) * std::exp(-f.alpha2 * h5 + f.alpha3 * h5 * h5);
    }
    return values;
  }();
  return low_branch_at_5[index] * std::exp(-kShearFlowTailDecay * (h - kShearFlowBranch));
}

double ShearStressFsRawFit(int index, double H) {
  assert(index >= 0 && index < kNumGammas);
  const ShearStressFsFit& fit = kShearStressFs[index];
  return fit.a3_amp * std::pow(H, fit.alpha4) * std::exp(-fit.alpha5 * H + fit.alpha6 * H * H);
}

double ShearStressFsTabulated(int index, double H) {
  assert(index >= 0 && index < kNumGammas);
  if (H >= kFsTaperEnd) return 0.0;
  const double h = std::max(H, kPc79LowerLimit);
  const double raw = ShearStressFsRawFit(index, h);
  if (h <= kFsTaperStart) return raw;
  const double t = (h - kFsTaperStart) / (kFsTaperEnd - kFsTaperStart);
  return raw * (1.0 - t * t * (3.0 - 2.0 * t));
}

double ShearStressFpTabulated(int index, double H) {
  assert(index >= 0 && index < kNumGammas);
  const ShearStressFpFit& fit = kShearStressFp[index];
  return 1.0 - fit.d * std::exp(-fit.s * std::max(H, kPc79LowerLimit));
}

double PressureFlow(const GammaBracket& bracket, double H) {
  return Interpolate(bracket, H, PressureFlowTabulated);
}

double ShearFlow(const GammaBracket& bracket, double H) {
  return Interpolate(bracket, H, ShearFlowTabulated);
}

double ShearStressFs(const GammaBracket& bracket, double H) {
  return Interpolate(bracket, H, ShearStressFsTabulated);
}

double ShearStressFp(const GammaBracket& bracket, double H) {
  return Interpolate(bracket, H, ShearStressFpTabulated);
}

double ShearStressF(double H) {
  if (!(H > 0.0)) return 0.0;  // z * (...) -> 0 as H -> 0+
  const double z = H / 3.0;
  const double one_minus_z2 = 1.0 - z * z;
  const double cube = one_minus_z2 * one_minus_z2 * one_minus_z2;
  if (z <= 1.0) {
    // Horner form of -55 + 132 z + 345 z^2 - 160 z^3 - 405 z^4 + 60 z^5 + 147 z^6.
    const double poly =
        -55.0 + z * (132.0 + z * (345.0 + z * (-160.0 + z * (-405.0 + z * (60.0 + z * 147.0)))));
    return 35.0 / 32.0 * z * (cube * std::log((z + 1.0) / kPhiFCutoff) + poly / 60.0);
  }
  if (z > kPhiFSeriesStart) {
    // For large z the two terms below are each ~2 z^5 and cancel to O(1): expand in w = 1/z
    // instead. With s_k = 1/(2k+1) (series of ln((z+1)/(z-1)) / 2) and c_k the third difference
    // s_k - 3 s_{k-1} + 3 s_{k-2} - s_{k-3}, Phi_f = 1 - 35/16 sum_{k>=4} c_k w^(2(k-3))
    // = 1 + 1/(9 z^2) + ... ; 14 terms leave < 1e-19 for z > 5.
    // The c_k are constants: computed once (the same arithmetic, so the same values).
    static const std::array<double, 14> coefficients = [] {
      std::array<double, 14> c{};
      const auto s = [](int j) { return 1.0 / (2.0 * j + 1.0); };
      for (int k = 4; k < 18; ++k) c[k - 4] = s(k) - 3.0 * s(k - 1) + 3.0 * s(k - 2) - s(k - 3);
      return c;
    }();
    const double w2 = 1.0 / (z * z);
    double sum = 0.0;
    double w_power = w2;
    for (double c : coefficients) {
      sum += c * w_power;
      w_power *= w2;
    }
    return 1.0 - 35.0 / 16.0 * sum;
  }
  const double poly = z / 15.0 * (66.0 + z * z * (30.0 * z * z - 80.0));
  return 35.0 / 32.0 * z * (cube * std::log((z + 1.0) / (z - 1.0)) + poly);
}

double WuZhengContactFactorRawFit(double H) { return std::exp(WuZhengExponent(H)); }

double WuZhengContactFactor(double H) {
  if (H >= kWzUpper) return 1.0;
  const double h = std::max(H, 0.0);
  const double correction = WuZhengExponent(kWzUpper) * h / kWzUpper;  // 0.0015 H / 3
  return std::exp(WuZhengExponent(h) - correction);
}

double WuZhengMeanGapExcess(double H) {
  if (H >= kWzUpper) return 0.0;
  const double from = std::max(H, 0.0);
  const double above = boost::math::quadrature::gauss<double, 20>::integrate(
      [](double x) { return 1.0 - WuZhengContactFactor(x); }, from, kWzUpper);
  return H < 0.0 ? above - H * (1.0 - WuZhengContactFactor(0.0)) : above;
}

}  // namespace filmdyn::lubrication::patir_cheng
