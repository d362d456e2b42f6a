#include "core/lubrication/oil.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>

#include <cstdio>
#include <limits>

#include "core/base/input_error.hpp"
#include "core/lubrication/oil_catalogue.hpp"

namespace filmdyn::lubrication {

namespace {
std::string Kelvin(double t) { return fmt::format("{:.6g} K ({:.4g} °C)", t, t - kZeroCelsius); }

// Cubic Hermite on [x0, x1] with values y0, y1 and slopes d0, d1.
double Hermite(double x, double x0, double x1, double y0, double y1, double d0, double d1) {
  const double h = x1 - x0, s = (x - x0) / h, s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * y0 + (s3 - 2 * s2 + s) * h * d0 + (-2 * s3 + 3 * s2) * y1 +
         (s3 - s2) * h * d1;
}
}  // namespace

double VogelLaw::At(double temperature, const std::string& field) const {
  if (!std::isfinite(temperature) || !(temperature > c)) {
    throw InputError(field, Kelvin(temperature), "above the Vogel law's pole c = " + Kelvin(c));
  }
  return a * std::exp(b / (temperature - c));
}

void VogelLaw::Validate(const std::string& prefix) const {
  RequirePositive(prefix + "a", a, "Pa*s");
  RequirePositive(prefix + "b", b, "K");
  RequireFinite(prefix + "c", c, "K");
}

VogelLaw VogelLaw::Through(double t1, double mu1, double t2, double mu2, double t3, double mu3) {
  if (!(t1 < t2 && t2 < t3) || !(mu1 > mu2 && mu2 > mu3 && mu3 > 0.0)) {
    throw InputError("vogel points", "(" + Kelvin(t1) + ", " + Kelvin(t2) + ", " + Kelvin(t3) + ")",
                     "rising temperatures with falling positive viscosities");
  }
  // ln mu = ln a + b / (T - c): the ratio of the two log-differences fixes c in closed form.
  const double r = (std::log(mu1) - std::log(mu2)) / (std::log(mu2) - std::log(mu3));
  const double den = (t2 - t1) - r * (t3 - t2);
  const double c = ((t2 - t1) * t3 - r * (t3 - t2) * t1) / den;
  const double b = (std::log(mu1) - std::log(mu2)) * (t1 - c) * (t2 - c) / (t2 - t1);
  if (!std::isfinite(c) || !(c < t1) || !(b > 0.0)) {
    throw InputError("vogel points", "c = " + FormatValue(c) + " K, b = " + FormatValue(b),
                     "a Vogel law with b > 0 and its pole below the lowest temperature");
  }
  return {mu1 * std::exp(-b / (t1 - c)), b, c};
}

const char* ToString(PressureLaw law) {
  switch (law) {
    case PressureLaw::kNone:
      return "none";
    case PressureLaw::kBarus:
      return "barus";
    case PressureLaw::kRoelands:
      return "roelands";
  }
  return "?";
}

PressureViscosity PressureViscosity::Barus(double alpha, const std::string& prefix) {
  RequirePositive(prefix + "barus_alpha", alpha, "1/Pa");
  PressureViscosity v;
  v.law_ = PressureLaw::kBarus;
  v.alpha_ = alpha;
  v.q_max_ = 1.0 / alpha;
  return v;
}

PressureViscosity PressureViscosity::Roelands(double z, double mu0, const std::string& prefix) {
  RequirePositive(prefix + "roelands_z", z);
  if (!std::isfinite(mu0) || !(mu0 > kRoelandsViscosity)) {
    throw InputError(prefix + "viscosity", FormatValue(mu0) + " Pa*s",
                     "above Roelands' reference viscosity 6.31e-5 Pa*s (with the Roelands law)");
  }
  PressureViscosity v;
  v.law_ = PressureLaw::kRoelands;
  v.z_ = z;
  v.log_ratio_ = std::log(mu0 / kRoelandsViscosity);
  v.TabulateRoelands(4096);
  return v;
}

void PressureViscosity::TabulateRoelands(int intervals) {
  // Tabulate q(p) up to where mu0/mu < 1e-17 (the rest of the integral is below rounding):
  // s L [(1 + p/p_r)^z - 1] = 39. The grid is uniform in ln(1 + p / 1 MPa): fine where the
  // integrand is ~1, 0.25 % steps at GPa with 4 096 intervals.
  const double p_end =
      kRoelandsPressure * (std::pow(1.0 + 39.0 / (scale_ * log_ratio_), 1.0 / z_) - 1.0);
  constexpr double kScale = 1e6;
  const double step = std::log1p(p_end / kScale) / intervals;
  p_grid_.resize(intervals + 1);
  q_grid_.resize(intervals + 1);
  dqdp_.resize(intervals + 1);
  auto integrand = [this](double p) { return RoelandsIntegrand(p); };
  for (int i = 0; i <= intervals; ++i) {
    p_grid_[i] = kScale * std::expm1(i * step);
    dqdp_[i] = RoelandsIntegrand(p_grid_[i]);
    q_grid_[i] = i == 0 ? 0.0
                        : q_grid_[i - 1] + boost::math::quadrature::gauss<double, 10>::integrate(
                                               integrand, p_grid_[i - 1], p_grid_[i]);
  }
  q_max_ = q_grid_.back();
}

PressureViscosity PressureViscosity::Weakened(double s) const {
  // Below s = 1e-6 the law changes mu by less than a millionth of its own change (and Roelands'
  // table would reach past any double): no law.
  if (!(s >= 1e-6) || law_ == PressureLaw::kNone) return {};
  if (s >= 1.0) return *this;
  PressureViscosity v = *this;
  if (law_ == PressureLaw::kBarus) {
    v.alpha_ = alpha_ * s;
    v.q_max_ = 1.0 / v.alpha_;
  } else {
    // A weakened law serves only the start of an engine run (PressureLawRamp), retabulated at
    // every new time there: 512 intervals (q to ~1e-7) cost an eighth of the full table's.
    v.scale_ = scale_ * s;
    v.TabulateRoelands(512);
  }
  return v;
}

double PressureViscosity::RoelandsIntegrand(double p) const {
  return std::exp(-scale_ * log_ratio_ * (std::pow(1.0 + p / kRoelandsPressure, z_) - 1.0));
}

double PressureViscosity::InitialCoefficient() const {
  switch (law_) {
    case PressureLaw::kNone:
      return 0.0;
    case PressureLaw::kBarus:
      return alpha_;
    case PressureLaw::kRoelands:
      return scale_ * z_ * log_ratio_ / kRoelandsPressure;
  }
  return 0.0;
}

double PressureViscosity::Ratio(double p) const {
  if (!(p > 0.0)) return 1.0;
  switch (law_) {
    case PressureLaw::kNone:
      return 1.0;
    case PressureLaw::kBarus:
      return std::exp(alpha_ * p);
    case PressureLaw::kRoelands:
      return 1.0 / RoelandsIntegrand(p);
  }
  return 1.0;
}

double PressureViscosity::Reduced(double p) const {
  if (!(p > 0.0) || law_ == PressureLaw::kNone) return p;
  if (law_ == PressureLaw::kBarus) return -std::expm1(-alpha_ * p) / alpha_;
  if (p >= p_grid_.back()) return q_max_;
  const auto it = std::upper_bound(p_grid_.begin(), p_grid_.end(), p);
  const size_t i = static_cast<size_t>(it - p_grid_.begin()) - 1;
  return Hermite(p, p_grid_[i], p_grid_[i + 1], q_grid_[i], q_grid_[i + 1], dqdp_[i], dqdp_[i + 1]);
}

double PressureViscosity::Pressure(double q) const {
  if (!(q > 0.0) || law_ == PressureLaw::kNone) return q;
  if (q >= q_max_) return std::numeric_limits<double>::infinity();
  if (law_ == PressureLaw::kBarus) return -std::log1p(-alpha_ * q) / alpha_;
  const auto it = std::upper_bound(q_grid_.begin(), q_grid_.end(), q);
  const size_t i = static_cast<size_t>(it - q_grid_.begin()) - 1;
  return Hermite(q, q_grid_[i], q_grid_[i + 1], p_grid_[i], p_grid_[i + 1], 1.0 / dqdp_[i],
                 1.0 / dqdp_[i + 1]);
}

double CrossLaw::Factor(double shear_rate) const {
  if (!active() || !(shear_rate > 0.0)) return 1.0;
  return ratio + (1.0 - ratio) / (1.0 + std::pow(shear_rate / critical_rate, exponent));
}

double CrossLaw::CriticalRateForHths(double mu1_hths, double hths, double ratio, double exponent,
                                     const std::string& hths_field) {
  if (!std::isfinite(hths) || !(hths > ratio * mu1_hths) || !(hths < mu1_hths)) {
    throw InputError(
        hths_field, FormatValue(hths) + " Pa*s",
        "between the second Newtonian viscosity r mu1 = " + FormatValue(ratio * mu1_hths) +
            " Pa*s and the low-shear viscosity mu1 = " + FormatValue(mu1_hths) + " Pa*s at 150 °C");
  }
  // hths = mu1 [r + (1 - r) / (1 + x^m)], x = gamma_HTHS / gamma_c.
  const double x_m = (mu1_hths - hths) / (hths - ratio * mu1_hths);
  return kHthsShearRate / std::pow(x_m, 1.0 / exponent);
}

const char* ToString(DensityLaw law) {
  switch (law) {
    case DensityLaw::kLinear:
      return "linear";
    case DensityLaw::kDowsonHigginson:
      return "dowson_higginson";
  }
  return "?";
}

Compression Compression::Of(double bulk_modulus, DensityLaw law) {
  Compression g;
  if (bulk_modulus > 0.0) {
    g.compressibility = 1.0 / bulk_modulus;
    g.limit = law == DensityLaw::kDowsonHigginson ? kDowsonHigginsonLimit : 0.0;
  }
  return g;
}

const char* ToString(ShearThinning model) {
  switch (model) {
    case ShearThinning::kNone:
      return "none";
    case ShearThinning::kCross:
      return "cross";
    case ShearThinning::kHths:
      return "hths";
  }
  return "?";
}

const char* ToString(ViscosityModel model) {
  switch (model) {
    case ViscosityModel::kConstant:
      return "constant";
    case ViscosityModel::kVogel:
      return "vogel";
    case ViscosityModel::kGrade:
      return "grade";
  }
  return "?";
}

void OilSpec::CheckBulkModulus(const std::string& prefix) const {
  if (!(bulk_modulus == 0.0 ||
        (bulk_modulus >= kMinBulkModulus && bulk_modulus <= kMaxBulkModulus))) {
    throw InputError(prefix + "bulk_modulus", FormatValue(bulk_modulus) + " Pa",
                     "0 (incompressible) or 1e7–1e11 Pa (mineral oils: about " +
                         FormatValue(kMineralOilBulkModulus / 1e9) + " GPa)");
  }
}

OilSpec::AtTemperature OilSpec::At(double temperature, const std::string& prefix,
                                   const std::string& temperature_field) const {
  AtTemperature out;
  double mu1_hths = 0.0;  // the low-shear viscosity at the HTHS temperature
  double hths_used = hths;
  if (model == ViscosityModel::kConstant) {
    RequirePositive(prefix + "viscosity", viscosity, "Pa*s");
    out.viscosity = mu1_hths = viscosity;
  } else {
    VogelLaw law{vogel_a, vogel_b, vogel_c};
    if (model == ViscosityModel::kVogel) {
      law.Validate(prefix + "vogel_");
    } else {
      const std::span<const OilGrade> catalogue = OilCatalogue();
      if (grade < 0 || grade >= static_cast<int>(catalogue.size())) {
        throw InputError(prefix + "grade", std::to_string(grade),
                         "an entry of the oil catalogue (docs/validation/lubricant.md)");
      }
      const OilGrade& g = catalogue[grade];
      law = GradeVogel(g);
      if (hths == 0.0) hths_used = g.hths;  // the grade's own
      if (!(temperature >= kGradeMinTemperature && temperature <= kGradeMaxTemperature)) {
        throw InputError(temperature_field, Kelvin(temperature),
                         "within 0–200 °C for a catalogue oil (" + std::string(g.product) +
                             "; its fit is made over 40–150 °C)");
      }
      out.extrapolated =
          !(temperature >= kGradeFitMinTemperature && temperature <= kGradeFitMaxTemperature);
    }
    out.viscosity = law.At(temperature, temperature_field);
    if (!std::isfinite(out.viscosity)) {
      throw InputError(temperature_field, Kelvin(temperature),
                       "a temperature where the oil's Vogel law (" + prefix + "vogel_a, " + prefix +
                           "vogel_b, " + prefix + "vogel_c) gives a finite viscosity: " +
                           "exp(b/(T − c)) overflows at b/(T − c) = " +
                           FormatValue(law.b / (temperature - law.c)));
    }
    if (shear_thinning != ShearThinning::kNone)
      mu1_hths = law.At(CrossLaw::kHthsTemperature, prefix + "vogel_c");
  }
  if (shear_thinning != ShearThinning::kNone) {
    if (!std::isfinite(cross_ratio) || !(cross_ratio > 0.0) || !(cross_ratio < 1.0)) {
      throw InputError(prefix + "cross_ratio", FormatValue(cross_ratio), "between 0 and 1");
    }
    RequirePositive(prefix + "cross_exponent", cross_exponent);
    double rate_hths = cross_rate;
    if (shear_thinning == ShearThinning::kCross) {
      RequirePositive(prefix + "cross_rate", cross_rate, "1/s");
    } else {
      rate_hths = CrossLaw::CriticalRateForHths(mu1_hths, hths_used, cross_ratio, cross_exponent,
                                                prefix + "hths");
    }
    out.shear.ratio = cross_ratio;
    out.shear.exponent = cross_exponent;
    out.shear.critical_rate = rate_hths * mu1_hths / out.viscosity;
  }
  switch (pressure_law) {
    case PressureLaw::kNone:
      break;
    case PressureLaw::kBarus:
      out.pressure = PressureViscosity::Barus(barus_alpha, prefix);
      break;
    case PressureLaw::kRoelands:
      out.pressure = PressureViscosity::Roelands(roelands_z, out.viscosity, prefix);
      break;
  }
  return out;
}

}  // namespace filmdyn::lubrication
