#include "core/lubrication/surface/surface_model.hpp"

#include <cmath>

#include "core/base/input_error.hpp"
#include "core/lubrication/surface/greenwood_tripp.hpp"

namespace filmdyn::lubrication {
namespace {

constexpr double kPeklenikMin = 1.0 / 9.0;
constexpr double kPeklenikMax = 9.0;
// Tolerance for typed-in bounds such as 0.1111 or 9.0001.
constexpr double kPeklenikSlackLow = 1e-4;
constexpr double kPeklenikSlackHigh = 1e-3;

double ClampPeklenik(double gamma) {
  return std::fmin(std::fmax(gamma, kPeklenikMin), kPeklenikMax);
}

}  // namespace

double SurfacePair::CompositeSigma() const { return std::hypot(sigma1, sigma2); }

double SurfacePair::CompositeModulus() const {
  return 2.0 / ((1.0 - nu1 * nu1) / E1 + (1.0 - nu2 * nu2) / E2);
}

void SurfacePair::Validate(const std::string& field_prefix) const {
  const std::string p = field_prefix.empty() ? std::string() : field_prefix + ".";
  RequireNonNegative(p + "sigma1", sigma1, "m");
  RequireNonNegative(p + "sigma2", sigma2, "m");
  if (!(CompositeSigma() > 0.0)) {
    throw InputError(p + "sigma1", FormatValue(sigma1),
                     "sigma1 and sigma2 must not both be 0 (composite roughness must be > 0) [m]");
  }
  if (!std::isfinite(peklenik) || peklenik < kPeklenikMin - kPeklenikSlackLow ||
      peklenik > kPeklenikMax + kPeklenikSlackHigh) {
    throw InputError(p + "peklenik", FormatValue(peklenik),
                     "must be a finite number in [1/9, 9] (range of the Patir–Cheng tables)");
  }
  RequirePositive(p + "E1", E1, "Pa");
  RequireInRange(p + "nu1", nu1, -1.0, 0.5, true, true);
  RequirePositive(p + "E2", E2, "Pa");
  RequireInRange(p + "nu2", nu2, -1.0, 0.5, true, true);
  RequirePositive(p + "gt_k", gt_k);
  RequireNonNegative(p + "boundary_friction", boundary_friction);
  if (asperity_model != AsperityModel::kGreenwoodTrippFit &&
      asperity_model != AsperityModel::kGreenwoodTrippExact) {
    throw InputError(p + "asperity_model", std::to_string(static_cast<int>(asperity_model)),
                     "must be greenwood-tripp-fit or greenwood-tripp-exact");
  }
}

SurfaceModel::SurfaceModel(const SurfacePair& pair) : pair_(pair) {
  pair_.Validate("surface");
  sigma_ = pair_.CompositeSigma();
  const double sigma_sq = sigma_ * sigma_;
  shear_sign_weight_ = (pair_.sigma1 * pair_.sigma1 - pair_.sigma2 * pair_.sigma2) / sigma_sq;
  contact_scale_ = pair_.gt_k * pair_.CompositeModulus();
  const double gamma = ClampPeklenik(pair_.peklenik);
  along_ = patir_cheng::BracketPeklenik(gamma);
  across_ = patir_cheng::BracketPeklenik(1.0 / gamma);
  if (pair_.asperity_model == AsperityModel::kGreenwoodTrippExact) {
    (void)GreenwoodTrippF52Exact(1.0);  // build the shared tables now, not inside a solve
    (void)GreenwoodTrippF32Exact(1.0);
  }
}

FlowFactors SurfaceModel::Flow(double H) const {
  FlowFactors factors;
  factors.pressure_along = patir_cheng::PressureFlow(along_, H);
  factors.pressure_across = patir_cheng::PressureFlow(across_, H);
  factors.shear = shear_sign_weight_ * patir_cheng::ShearFlow(along_, H);
  factors.contact = patir_cheng::WuZhengContactFactor(H);
  factors.mean_gap_excess = patir_cheng::WuZhengMeanGapExcess(H);
  return factors;
}

ShearStressFactors SurfaceModel::Shear(double H) const {
  ShearStressFactors factors;
  factors.f = patir_cheng::ShearStressF(H);
  factors.fs = shear_sign_weight_ * patir_cheng::ShearStressFs(along_, H);
  factors.fp = patir_cheng::ShearStressFp(along_, H);
  return factors;
}

double SurfaceModel::ContactPressure(double h) const {
  const double H = h / sigma_;
  if (pair_.asperity_model == AsperityModel::kGreenwoodTrippExact) {
    return contact_scale_ * GreenwoodTrippF52Exact(H);
  }
  return contact_scale_ * GreenwoodTrippF52Fit(H);
}

double SurfaceModel::ContactPressureDerivative(double h) const {
  const double H = h / sigma_;
  if (pair_.asperity_model == AsperityModel::kGreenwoodTrippExact) {
    return -contact_scale_ * 2.5 * GreenwoodTrippF32Exact(H) / sigma_;
  }
  if (H >= 4.0) return 0.0;
  return -contact_scale_ * 6.804 * GreenwoodTrippF52Fit(H) / ((4.0 - H) * sigma_);
}

double SurfaceModel::sigma() const { return sigma_; }

const SurfacePair& SurfaceModel::pair() const { return pair_; }

}  // namespace filmdyn::lubrication
