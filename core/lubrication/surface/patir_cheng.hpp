#pragma once
/// @file Patir & Cheng curve fits of the average-flow model and the Wu & Zheng contact factor,
/// all as functions of H = h / sigma (h: nominal film thickness, sigma: composite rms roughness).
///
/// Sources (coefficients are cited again next to each table in patir_cheng.cpp):
///  - [PC78] Patir N, Cheng HS. An average flow model for determining effects of
///    three-dimensional roughness on partial hydrodynamic lubrication. J Lubr Technol (ASME)
///    1978;100:12-17. Table 1: pressure flow factor phi_x(H, gamma).
///  - [PC79] Patir N, Cheng HS. Application of average flow model to lubrication between rough
///    sliding surfaces. J Lubr Technol (ASME) 1979;101:220-229. Shear flow factor Phi_s and the
///    shear-stress factors Phi_f (closed form), Phi_fs and Phi_fp (tables).
///  - [WZ89] Wu C, Zheng L. An average Reynolds equation for partial film lubrication with a
///    contact factor. J Tribol 1989;111:188-191. Contact factor phi_c(H).
///
/// Every function is continuous in H on the whole real line (see docs/surface-models.md for the
/// treatment at each branch point and below each fit's range). None allocates.
#include <array>

namespace filmdyn::lubrication::patir_cheng {

/// Peklenik numbers gamma tabulated by Patir & Cheng: 1/9, 1/6, 1/3, 1, 3, 6, 9.
inline constexpr int kNumGammas = 7;
inline constexpr std::array<double, kNumGammas> kGammas = {1.0 / 9.0, 1.0 / 6.0, 1.0 / 3.0, 1.0,
                                                           3.0,       6.0,       9.0};

/// Two neighbouring tabulated curves and the weight of the upper one, for interpolation that is
/// linear in ln(gamma): f(gamma) = (1 - weight) f_lo + weight f_hi.
struct GammaBracket {
  int lo = 3;
  int hi = 3;
  double weight = 0.0;
};

/// Bracket for gamma in [1/9, 9] (values outside are clamped to the table ends; input
/// validation is SurfacePair::Validate's job). Evaluates two logarithms: call once, reuse.
GammaBracket BracketPeklenik(double gamma);

// --- Single tabulated curves (index into kGammas) ------------------------------------------

/// [PC78] Table 1 pressure flow factor phi_x of curve `index`, held constant below the fit's
/// lower limit PressureFlowLowerLimit(index).
double PressureFlowTabulated(int index, double H);
/// Lower end of the H range over which [PC78] Table 1 states the fit of curve `index` is valid.
double PressureFlowLowerLimit(int index);

/// [PC79] shear flow factor Phi_s of ONE rough surface against a smooth one (>= 0), curve
/// `index`, H >= 0.5; held constant below H = 0.5. The large-H branch amplitude is the one
/// that makes the curve continuous at H = 5 (see ShearFlowTailAmplitude).
double ShearFlowTabulated(int index, double H);
/// A2 in Phi_s = A2 exp(-0.25 H), H > 5, chosen so that Phi_s is continuous at H = 5. It
/// differs from the rounded published A2 (ShearFlowPublishedTailAmplitude) by < 0.1 %.
double ShearFlowTailAmplitude(int index);
/// A2 as printed in [PC79].
double ShearFlowPublishedTailAmplitude(int index);

/// [PC79] shear-stress factor Phi_fs of one rough surface against a smooth one, curve `index`:
/// the fit on 0.5 <= H <= 6, blended smoothly to 0 over 6 < H < 7 (C1 cubic taper), 0 for
/// H >= 7; held constant below H = 0.5.
double ShearStressFsTabulated(int index, double H);
/// The raw [PC79] fit A3 H^a4 exp(-a5 H + a6 H^2), without taper or clamp (for tests/docs).
double ShearStressFsRawFit(int index, double H);

/// [PC79] shear-stress factor Phi_fp = 1 - D exp(-s H) of curve `index`, held constant below
/// H = 0.5.
double ShearStressFpTabulated(int index, double H);

// --- Interpolated in ln(gamma) ---------------------------------------------------------------

double PressureFlow(const GammaBracket& bracket, double H);
double ShearFlow(const GammaBracket& bracket, double H);
double ShearStressFs(const GammaBracket& bracket, double H);
double ShearStressFp(const GammaBracket& bracket, double H);

// --- Independent of gamma ----------------------------------------------------------------------

/// [PC79] closed form of Phi_f for a Gaussian-like polynomial height density truncated at
/// +-3 sigma, with the cut-off eps* = 1/300 of the H <= 3 branch. Phi_f(H <= 0) = 0; -> 1 as
/// H -> infinity.
double ShearStressF(double H);

/// [WZ89] contact factor phi_c: exp(-0.6912 + 0.782 H - 0.304 H^2 + 0.0401 H^3) for 0 <= H < 3,
/// 1 for H >= 3. The published cubic reaches exp(0.0015) = 1.0015 at H = 3, so the exponent is
/// corrected by a linear term -c H / 3 with c = exponent(3) = 0.0015; this keeps phi_c(0) and
/// monotonicity and makes phi_c exactly 1 at H = 3. H < 0 is treated as H = 0.
double WuZhengContactFactor(double H);
/// The uncorrected [WZ89] cubic fit (for tests/docs).
double WuZhengContactFactorRawFit(double H);
/// The mean gap's excess over the nominal gap, (h_T - h) / sigma, that the contact factor
/// implies: phi_c = dh_T/dh and h_T = h from H = 3 on (phi_c = 1 there), so
/// (h_T - h) / sigma = integral from H to 3 of (1 - phi_c(H')) dH' — 0 for H >= 3, 0.085 at H = 1,
/// 0.40 at H = 0 (a Gaussian height density gives 0.083 and 1/sqrt(2 pi) = 0.399); below H = 0,
/// where phi_c is held at phi_c(0), it grows with slope 1 - phi_c(0).
/// (Gauss–Legendre quadrature of the smooth fit, exact to round-off.)
double WuZhengMeanGapExcess(double H);

}  // namespace filmdyn::lubrication::patir_cheng
