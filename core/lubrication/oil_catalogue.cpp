#include "core/lubrication/oil_catalogue.hpp"

#include <array>
#include <cmath>

#include "core/base/input_error.hpp"

namespace filmdyn::lubrication {

namespace {

// Typical properties published by ExxonMobil on its product pages (the pages' HTML, archived in
// github.com/khwsab/Documentum at commit 4b8395a844251f1a436e1e0f64c2955f8d4dc674, folder
// AP-English-LCW). Typical values, not specifications; formulations change and one product name
// carries different numbers in different markets, hence the country page and its date.
constexpr std::array<OilGrade, 4> kCatalogue{{
    {"0w-20", "Mobil 1 0W-20",
     "ExxonMobil typical properties, Australia product page dated 2015-07-01 "
     "(carengineoils_au_products_mobil-1-0W-20.aspx)",
     44.8, 8.7, 841.0, 288.75, 2.7e-3},
    {"5w-30", "Mobil 1 ESP Formula 5W-30",
     "ExxonMobil typical properties, Singapore product page dated 2011-10-01 "
     "(carengineoils_sg_mobil-1-esp-formula-5w30.aspx)",
     72.8, 12.1, 850.0, 288.75, 3.58e-3},
    {"10w-40", "Mobil Super 2000 X2 10W-40",
     "ExxonMobil typical properties, Australia product page dated 2012-08-01 "
     "(carengineoils_au_products_mobil-super-2000-x2-10w40.aspx)",
     96.0, 14.4, 877.0, 288.15, 3.8e-3},
    {"15w-40", "Mobil Delvac MX ESP 15W-40",
     "ExxonMobil typical properties, Singapore product page dated 2011-10-01 "
     "(heavydutyoils_sg_engine-oil-products_mobil-delvac-mx-esp-15w40.aspx)",
     114.0, 15.0, 876.0, 288.15, 4.3e-3},
}};

constexpr double kCelsius40 = 313.15, kCelsius100 = 373.15, kCelsius150 = 423.15;

double Fahrenheit(double kelvin) { return (kelvin - kZeroCelsius) * 1.8 + 32.0; }

// API MPMS 11.1 correction of a lubricating oil's volume from 60 °F to T: CTL = exp(-a dT (1 +
// 0.8 a dT)), a = K1 / rho60 with K1 = 0.34878 (kg/m³)/°F, dT in °F.
double VolumeCorrection(double rho60, double temperature) {
  const double a = 0.34878 / rho60, dt = Fahrenheit(temperature) - 60.0;
  return std::exp(-a * dt * (1.0 + 0.8 * a * dt));
}

}  // namespace

std::span<const OilGrade> OilCatalogue() { return kCatalogue; }

const OilGrade& FindOilGrade(std::string_view key, const std::string& field) {
  std::string names;
  for (const OilGrade& g : kCatalogue) {
    if (g.key == key) return g;
    names += (names.empty() ? "" : ", ") + std::string(g.key);
  }
  throw InputError(field, std::string(key), "one of the catalogue's grades: " + names);
}

double WaltherViscosity(const OilGrade& grade, double temperature) {
  auto y = [](double nu) { return std::log10(std::log10(nu + 0.7)); };
  const double x40 = std::log10(kCelsius40), x100 = std::log10(kCelsius100);
  const double b = (y(grade.kv40) - y(grade.kv100)) / (x100 - x40);
  const double a = y(grade.kv40) + b * x40;
  return std::pow(10.0, std::pow(10.0, a - b * std::log10(temperature))) - 0.7;
}

double LubricatingOilDensity(double rho_ref, double t_ref, double temperature) {
  // rho60 from rho_ref at t_ref (fixed point: a depends weakly on rho60), then to T.
  double rho60 = rho_ref;
  for (int i = 0; i < 20; ++i) rho60 = rho_ref / VolumeCorrection(rho60, t_ref);
  return rho60 * VolumeCorrection(rho60, temperature);
}

VogelLaw GradeVogel(const OilGrade& grade) {
  auto mu = [&grade](double t) {
    return WaltherViscosity(grade, t) * 1e-6 *
           LubricatingOilDensity(grade.density, grade.density_temperature, t);
  };
  return VogelLaw::Through(kCelsius40, mu(kCelsius40), kCelsius100, mu(kCelsius100), kCelsius150,
                           mu(kCelsius150));
}

}  // namespace filmdyn::lubrication
