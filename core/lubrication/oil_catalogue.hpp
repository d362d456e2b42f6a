#pragma once
/// @file A catalogue of representative engine oils of common SAE grades, each a named product with
/// its published typical properties (docs/validation/lubricant.md, "Catalogue"), and the fit that
/// turns them into Vogel's law.
///
/// An SAE grade is a range of viscosities, so each entry is one named oil that represents it. The
/// product data give the kinematic viscosity at 40 and 100 °C (ASTM D445), the density near 15 °C
/// (ASTM D4052) and the high-temperature high-shear viscosity at 150 °C (HTHS, ASTM D4683). The
/// fit: the kinematic viscosity follows Walther's equation through the two points (ASTM D341,
/// log10 log10(nu + 0.7) = A - B log10 T, nu in mm²/s, T in K), the density the thermal expansion
/// of lubricating oils of API MPMS 11.1 / ASTM D1250 (Table 54D: alpha60 = 0.34878 / rho60 per °F),
/// and Vogel's law passes through the dynamic viscosities at 40, 100 and 150 °C (the last by
/// Walther's extrapolation). The fit is meant for 40–150 °C; outside it is an extrapolation,
/// which a run reports as a warning, and outside 0–200 °C an input error.
#include <span>
#include <string>
#include <string_view>

#include "core/lubrication/oil.hpp"

namespace filmdyn::lubrication {

struct OilGrade {
  std::string_view key;              ///< the name a case or `--grade` uses, e.g. "0w-20"
  std::string_view product;          ///< the oil it is, e.g. "Mobil 1 0W-20"
  std::string_view source;           ///< where its numbers come from
  double kv40 = 0.0;                 ///< kinematic viscosity at 40 °C [mm²/s]
  double kv100 = 0.0;                ///< at 100 °C [mm²/s]
  double density = 0.0;              ///< [kg/m³] at density_temperature
  double density_temperature = 0.0;  ///< [K]
  double hths = 0.0;                 ///< HTHS viscosity at 150 °C, 1e6 1/s [Pa s]
};

/// The fit's range [K]: 40 °C and 150 °C; outside it a run warns (an extrapolation).
inline constexpr double kGradeFitMinTemperature = 313.15;
inline constexpr double kGradeFitMaxTemperature = 423.15;
/// The range a catalogue oil accepts at all [K]: 0 °C and 200 °C. Below, a multigrade's cold
/// viscosity is set by its winter (W) behaviour, which two warm viscosities do not describe;
/// above, the oil is far past its flash-point region and the fit's extrapolation meaningless.
inline constexpr double kGradeMinTemperature = 273.15;
inline constexpr double kGradeMaxTemperature = 473.15;

std::span<const OilGrade> OilCatalogue();
/// The entry named `key`. Throws filmdyn::InputError naming `field` and listing the names.
const OilGrade& FindOilGrade(std::string_view key, const std::string& field);
/// Walther's equation through the entry's two viscosities: nu(T) [mm²/s], T [K].
double WaltherViscosity(const OilGrade& grade, double temperature);
/// Density of a lubricating oil at T [K] from its density rho_ref at T_ref (API MPMS 11.1,
/// lubricating-oil group) [kg/m³].
double LubricatingOilDensity(double rho_ref, double t_ref, double temperature);
/// Vogel's law through the entry's dynamic viscosity at 40, 100 and 150 °C.
VogelLaw GradeVogel(const OilGrade& grade);

}  // namespace filmdyn::lubrication
