#pragma once
/// @file How the oil's viscosity follows temperature and pressure (docs/equations.md, "Oil").
///
/// Temperature: Vogel's law  mu(T) = a exp(b / (T - c)), T in kelvin, a in Pa s, b and c in K.
/// Pressure (the film's gauge pressure p >= 0):
///   Barus     mu(p) = mu0 exp(alpha p);
///   Roelands  mu(p) = mu0 exp( ln(mu0 / mu_r) [ (1 + p / p_r)^z - 1 ] ),
///             mu_r = 6.31e-5 Pa s, p_r = 1.96e8 Pa (Roelands 1966, in the SI form of Hamrock,
///             Schmid & Jacobson, Fundamentals of Machine Elements / Fluid Film Lubrication).
/// A viscosity that depends on pressure only (uniform temperature over the film) leaves the
/// Reynolds equation linear in the reduced pressure  q(p) = int_0^p mu0 / mu(s) ds :
///   div( h^3 / (12 mu(p)) grad p ) = div( h^3 / (12 mu0) grad q ),
/// and q >= 0 exactly where p >= 0, so the cavitation conditions carry over unchanged. The film
/// is solved for q and p = q^-1(q) recovered node by node: an exact treatment of the nonlinear
/// equation, with no iteration. q is bounded: q < q_max = int_0^inf mu0 / mu (1 / alpha for
/// Barus); nodes that need more are beyond the pressure-viscosity limit (the pressure would be
/// infinite): the solve caps them and counts them (ReynoldsStats::capped_nodes).
#include <cmath>
#include <string>
#include <vector>

namespace filmdyn::lubrication {

/// 0 °C in kelvin: temperatures are kelvin inside core/, °C where people type them.
inline constexpr double kZeroCelsius = 273.15;

/// mu(T) = a exp(b / (T - c)).
struct VogelLaw {
  double a = 0.0;  ///< [Pa s]
  double b = 0.0;  ///< [K]
  double c = 0.0;  ///< [K], the pole: the law holds for T > c
  /// Viscosity at T [K]. Throws filmdyn::InputError (field `field`) for T <= c.
  double At(double temperature, const std::string& field = "temperature") const;
  /// Throws filmdyn::InputError naming `prefix`a, `prefix`b or `prefix`c for a <= 0, b <= 0 or
  /// non-finite values (prefix e.g. "lubricant.vogel_" or "--vogel.").
  void Validate(const std::string& prefix) const;
  /// The law through three (T [K], mu [Pa s]) points with T1 < T2 < T3 and mu1 > mu2 > mu3
  /// (exact, c in closed form from the ratio of the log-differences). Throws
  /// filmdyn::InputError when no Vogel law with b > 0 passes through them.
  static VogelLaw Through(double t1, double mu1, double t2, double mu2, double t3, double mu3);
};

enum class PressureLaw { kNone, kBarus, kRoelands };
const char* ToString(PressureLaw law);

/// mu(p) / mu0 and the reduced pressure of one oil at one temperature.
class PressureViscosity {
 public:
  static constexpr double kRoelandsViscosity = 6.31e-5;  ///< mu_r [Pa s]
  static constexpr double kRoelandsPressure = 1.96e8;    ///< p_r [Pa]

  PressureViscosity() = default;  ///< kNone: mu independent of p
  /// alpha [1/Pa] > 0. Throws filmdyn::InputError naming `prefix`barus_alpha.
  static PressureViscosity Barus(double alpha, const std::string& prefix = "");
  /// z [-] > 0; mu0 [Pa s] > mu_r (the law's own reference viscosity). Throws
  /// filmdyn::InputError naming `prefix`roelands_z or `prefix`viscosity.
  static PressureViscosity Roelands(double z, double mu0, const std::string& prefix = "");

  PressureLaw law() const { return law_; }
  bool active() const { return law_ != PressureLaw::kNone; }
  /// Pressure-viscosity coefficient at p = 0: dln(mu)/dp [1/Pa] (alpha; for Roelands
  /// z ln(mu0/mu_r) / p_r).
  double InitialCoefficient() const;
  /// mu(p) / mu0 (p < 0 is taken as 0: a cavitated film).
  double Ratio(double p) const;
  /// q(p) [Pa]; q(p) = p for kNone. Negative p (none in a solved film) map to themselves.
  double Reduced(double p) const;
  /// p(q), the inverse; +infinity for q >= ReducedLimit().
  double Pressure(double q) const;
  /// q_max = lim q(p) as p -> infinity [Pa] (+infinity for kNone).
  double ReducedLimit() const { return q_max_; }
  /// The law with ln(mu / mu0) scaled by s: none for s < 1e-6, this law for s >= 1 (Barus with
  /// alpha s; Roelands with its exponent times s, tabulated to ~1e-7). Phases a law in over an
  /// engine run's start.
  PressureViscosity Weakened(double s) const;

 private:
  PressureLaw law_ = PressureLaw::kNone;
  double alpha_ = 0.0, z_ = 0.0, log_ratio_ = 0.0;
  double scale_ = 1.0;  // Roelands: the factor on ln(mu / mu0) (Weakened)
  double q_max_ = 1e300;
  // Roelands: q(p) tabulated on a graded grid with dq/dp = mu0/mu (cubic Hermite both ways).
  std::vector<double> p_grid_, q_grid_, dqdp_;
  double RoelandsIntegrand(double p) const;
  void TabulateRoelands(int intervals);
};

/// Shear thinning (temporary viscosity loss of polymer-thickened oils) by Cross' law
///   mu(gamma) = mu1 [ r + (1 - r) / (1 + (gamma / gamma_c)^m) ],
/// mu1 the low-shear (first Newtonian) viscosity, r mu1 the second Newtonian plateau, gamma_c the
/// critical shear rate, m the exponent (Cross 1965). In a film the shear rate of a node is taken
/// as its Couette rate |U1 - U2| / h: the viscosity is then known before the pressure and the
/// Reynolds equation stays linear in p (docs/equations.md, "Oil").
struct CrossLaw {
  /// The HTHS test's shear rate [1/s] and temperature [K] (ASTM D4683: 10^6 1/s, 150 °C).
  static constexpr double kHthsShearRate = 1.0e6;
  static constexpr double kHthsTemperature = 423.15;

  double ratio = 1.0;          ///< r = mu2 / mu1 in (0, 1); 1: no thinning
  double critical_rate = 0.0;  ///< gamma_c [1/s] at the film's temperature
  double exponent = 1.0;       ///< m > 0
  bool active() const { return ratio < 1.0; }
  /// mu(gamma) / mu1 (1 for an inactive law).
  double Factor(double shear_rate) const;
  /// The factor in a film of thickness h [m] whose surfaces slide at u_diff [m/s] relative to
  /// each other: the Couette shear rate |u_diff| / h.
  double InFilm(double u_diff, double h) const { return Factor(std::abs(u_diff) / h); }
  /// gamma_c for which mu(kHthsShearRate) = hths when mu1 = mu1_hths (both at the HTHS
  /// temperature). Throws filmdyn::InputError naming `hths_field` unless r mu1 < hths < mu1.
  static double CriticalRateForHths(double mu1_hths, double hths, double ratio, double exponent,
                                    const std::string& hths_field);
};

enum class ShearThinning {
  kNone,   ///< Newtonian
  kCross,  ///< Cross' law, gamma_c given at the HTHS temperature
  kHths    ///< Cross' law, gamma_c from the oil's HTHS viscosity
};
const char* ToString(ShearThinning model);

/// How a compressible oil's density follows its gauge pressure p >= 0 in a mass-conserving
/// film's full zone (OilSpec::bulk_modulus beta > 0).
enum class DensityLaw {
  /// rho / rho0 = 1 + p / beta: constant beta, good while p / beta is small (a few per cent).
  kLinear,
  /// Dowson and Higginson's rho / rho0 = 1 + 0.6 p / (1 + 1.7 p) (p in GPa), scaled to the oil's
  /// own beta at low pressure: rho / rho0 = 1 + (p / beta) / (1 + p / (kappa beta)), kappa =
  /// 0.6 / 1.7 the compression it tends to; beta = 1 / 0.6 GPa gives their law itself.
  kDowsonHigginson
};
const char* ToString(DensityLaw law);

/// The compression rho / rho0 - 1 of an oil in a full film, g(p), and its slope: what a
/// compressible mass-conserving film stores beyond its gap per unit gap (reynolds_jfo.cpp).
struct Compression {
  static constexpr double kDowsonHigginsonLimit = 0.6 / 1.7;  ///< kappa
  double compressibility = 0.0;  ///< 1 / beta [1/Pa]; 0: incompressible (g = 0)
  double limit = 0.0;            ///< kappa (kDowsonHigginson), or 0: linear
  static Compression Of(double bulk_modulus, DensityLaw law);
  /// g(p); for p < 0 (a trial pressure of the film's solve, never a result) the linear law's.
  double At(double p) const {
    if (limit == 0.0 || p <= 0.0) return compressibility * p;
    const double x = compressibility * p;
    return x / (1.0 + x / limit);
  }
  /// dg/dp [1/Pa].
  double Slope(double p) const {
    if (limit == 0.0 || p <= 0.0) return compressibility;
    const double d = 1.0 + compressibility * p / limit;
    return compressibility / (d * d);
  }
};

/// kGrade: Vogel's law fitted to a catalogue oil (oil_catalogue.hpp).
enum class ViscosityModel { kConstant, kVogel, kGrade };
const char* ToString(ViscosityModel model);

/// An oil as a case or a command line gives it: how its viscosity follows temperature
/// (constant, or Vogel's law) and pressure (none, Barus, Roelands).
struct OilSpec {
  ViscosityModel model = ViscosityModel::kConstant;
  double viscosity = 0.02;  ///< kConstant: mu [Pa s]
  double vogel_a = 0.0;     ///< kVogel: a [Pa s]
  double vogel_b = 0.0;     ///< kVogel: b [K]
  double vogel_c = 0.0;     ///< kVogel: c [K]
  int grade = 0;            ///< kGrade: the entry of OilCatalogue()
  PressureLaw pressure_law = PressureLaw::kNone;
  /// kBarus: alpha [1/Pa]; the default is within the 16–26 1/GPa of mineral oils of engine-oil
  /// viscosity at 60–100 °C (Stachowiak & Batchelor, Engineering Tribology, Table 2.3).
  double barus_alpha = 2.0e-8;
  double roelands_z = 0.6;  ///< kRoelands: z [-] (about 0.6 for mineral oils)
  ShearThinning shear_thinning = ShearThinning::kNone;
  double cross_ratio = 0.7;     ///< r = mu2 / mu1 [-]
  double cross_exponent = 1.0;  ///< m [-]
  double cross_rate = 1.0e6;    ///< kCross: gamma_c at the HTHS temperature [1/s]
  /// kHths: viscosity at 150 °C and 10^6 1/s [Pa s]; 0 with a grade: the grade's
  double hths = 0.0;
  /// Bulk modulus beta [Pa] of the oil in a mass-conserving film's full zone, at low pressure
  /// (density_law); 0 = incompressible. 0 or within [kMinBulkModulus, kMaxBulkModulus].
  double bulk_modulus = 0.0;
  /// With bulk_modulus > 0: how the density rises with the pressure.
  DensityLaw density_law = DensityLaw::kLinear;
  static constexpr double kMinBulkModulus = 1e7;
  static constexpr double kMaxBulkModulus = 1e11;
  /// A mineral oil's at low pressure (the slope of Dowson and Higginson's density law) [Pa].
  static constexpr double kMineralOilBulkModulus = 1.7e9;
  /// Throws filmdyn::InputError naming `prefix`bulk_modulus unless it is 0 or within
  /// [kMinBulkModulus, kMaxBulkModulus].
  void CheckBulkModulus(const std::string& prefix) const;

  /// The oil at one film temperature.
  struct AtTemperature {
    double viscosity = 0.0;  ///< at zero gauge pressure and low shear [Pa s]
    PressureViscosity pressure;
    /// gamma_c shifted from the HTHS temperature by the low-shear viscosity (time-temperature
    /// superposition: gamma_c(T) = gamma_c(T_HTHS) mu1(T_HTHS) / mu1(T)).
    CrossLaw shear;
    /// kGrade: the film temperature is outside the catalogue fit's 40–150 °C.
    bool extrapolated = false;
  };
  /// Resolves the oil at `temperature` [K] (ignored by a constant viscosity). Throws
  /// filmdyn::InputError naming `prefix` + the field (e.g. "lubricant.vogel_a") or
  /// `temperature_field` (a temperature at or below the Vogel pole).
  AtTemperature At(double temperature, const std::string& prefix,
                   const std::string& temperature_field) const;
};

}  // namespace filmdyn::lubrication
