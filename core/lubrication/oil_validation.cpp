#include "core/lubrication/oil_validation.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>

#include "core/lubrication/reynolds_fem.hpp"
#include "core/lubrication/tri_mesh.hpp"

namespace filmdyn::lubrication {

double InclinedSlider::IsoviscousPressure(double x) const {
  const double m = (h_outlet - h_inlet) / length;
  const double h = h_inlet + m * x;
  const double q = speed * h_inlet * h_outlet / (h_inlet + h_outlet);
  return 6.0 * viscosity / m *
         (speed * (1.0 / h_inlet - 1.0 / h) - q * (1.0 / (h_inlet * h_inlet) - 1.0 / (h * h)));
}

double InclinedSlider::Load(const PressureViscosity& law) const {
  constexpr int kPanels = 16;
  double sum = 0.0;
  for (int i = 0; i < kPanels; ++i) {
    sum += boost::math::quadrature::gauss<double, 64>::integrate(
        [&](double x) { return law.Pressure(IsoviscousPressure(x)); }, length * i / kPanels,
        length * (i + 1) / kPanels);
  }
  return sum;
}

double InclinedSlider::PeakPressure(const PressureViscosity& law) const {
  const double q = speed * h_inlet * h_outlet / (h_inlet + h_outlet);
  const double h_peak = 2.0 * q / speed;
  const double x = (h_peak - h_inlet) / (h_outlet - h_inlet) * length;
  return law.Pressure(IsoviscousPressure(x));
}

double InclinedSlider::ShearThinningLoad(const CrossLaw& law) const {
  auto h = [this](double x) { return h_inlet + (h_outlet - h_inlet) * x / length; };
  auto mu = [&](double x) { return viscosity * law.InFilm(speed, h(x)); };
  auto integrate = [this](auto&& f) {
    constexpr int kPanels = 16;
    double sum = 0.0;
    for (int i = 0; i < kPanels; ++i) {
      sum += boost::math::quadrature::gauss<double, 64>::integrate(f, length * i / kPanels,
                                                                   length * (i + 1) / kPanels);
    }
    return sum;
  };
  const double flow = 0.5 * speed * integrate([&](double x) { return mu(x) / (h(x) * h(x)); }) /
                      integrate([&](double x) { return mu(x) / std::pow(h(x), 3); });
  return integrate([&](double x) {
    return (length - x) * 12.0 * mu(x) * (0.5 * speed * h(x) - flow) / std::pow(h(x), 3);
  });
}

SliderStrip MakeSliderStrip(const InclinedSlider& s, int n) {
  SliderStrip strip;
  strip.fem = std::make_unique<ReynoldsFem>(MakeStripMesh(s.length, n, SliderStrip::kStripWidth), 0,
                                            ReynoldsOptions{});
  ReynoldsFem& fem = *strip.fem;
  const TriMesh& m = fem.mesh();
  for (int k = 0; k < m.NodeCount(); ++k) {
    fem.film_thickness()[k] = s.h_inlet + (s.h_outlet - s.h_inlet) * m.x[k] / s.length;
    fem.film_rate()[k] = 0.0;
    fem.boundary_pressure()[k] = 0.0;
  }
  strip.params.viscosity = s.viscosity;
  strip.params.u_sum = s.speed;
  strip.params.u_diff = s.speed;
  return strip;
}

SliderFem SolveSliderFem(const InclinedSlider& s, const PressureViscosity& law, int n,
                         const CrossLaw* shear) {
  SliderStrip strip = MakeSliderStrip(s, n);
  strip.params.pressure_viscosity = &law;
  strip.params.shear_thinning = shear;
  const ReynoldsSolution& sol = strip.fem->Solve(strip.params);
  SliderFem out;
  out.load = strip.fem->Integrate(sol.pressure) / SliderStrip::kStripWidth;
  out.peak_pressure = sol.pressure.maxCoeff();
  return out;
}

std::vector<verification::ValidationRow> LubricantValidationRows() {
  std::vector<verification::ValidationRow> rows;
  const InclinedSlider slider;
  constexpr int kCells = 400;
  // Barus with alpha q_max ~ 0.4: the load is 1.21 times the isoviscous slider's.
  const double alpha = 4e-8;
  const PressureViscosity barus = PressureViscosity::Barus(alpha);
  const SliderFem fem = SolveSliderFem(slider, barus, kCells);
  const std::string src = "inclined slider, isoviscous closed form through Barus' law";
  const std::string what = fmt::format("Barus slider (alpha {:g} 1/Pa, {} cells): ", alpha, kCells);
  rows.push_back({"lubricant", what + "load per width", src, fem.load, slider.Load(barus), 1e-4});
  rows.push_back({"lubricant", what + "peak pressure", src, fem.peak_pressure,
                  slider.PeakPressure(barus), 1e-3});
  const PressureViscosity none;
  const SliderFem iso = SolveSliderFem(slider, none, kCells);
  rows.push_back({"lubricant",
                  fmt::format("Barus slider: load / isoviscous load ({} cells)", kCells), src,
                  fem.load / iso.load, slider.Load(barus) / slider.Load(none), 1e-4});
  // Cross: the viscosity varies along the film with the Couette rate U/h (1e6 to 2e6 1/s here,
  // across the critical rate), halving at most: the load falls to ~0.64 of the isoviscous one.
  const CrossLaw cross{0.5, 1.5e6, 1.0};
  const SliderFem thin = SolveSliderFem(slider, none, kCells, &cross);
  rows.push_back({"lubricant",
                  fmt::format("Cross slider (r 0.5, m 1, critical rate 1.5e6 1/s, {} cells): "
                              "load per width",
                              kCells),
                  "1-D Reynolds with mu(h(x)) by Gauss-Legendre quadrature", thin.load,
                  slider.ShearThinningLoad(cross), 1e-4});
  // Roelands: our tabulated reduced pressure against adaptive Gauss-Kronrod quadrature of mu0/mu.
  const double mu0 = 0.01, z = 0.6, p = 5e8;
  const PressureViscosity roelands = PressureViscosity::Roelands(z, mu0);
  const double log_ratio = std::log(mu0 / PressureViscosity::kRoelandsViscosity);
  const double q_ref = boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
      [&](double s) {
        return std::exp(-log_ratio *
                        (std::pow(1.0 + s / PressureViscosity::kRoelandsPressure, z) - 1.0));
      },
      0.0, p, 15, 1e-13);
  rows.push_back({"lubricant", "Roelands (z 0.6, mu0 0.01 Pa s): reduced pressure at 0.5 GPa",
                  "adaptive Gauss-Kronrod quadrature of mu0/mu(p)", roelands.Reduced(p), q_ref,
                  1e-10});
  rows.push_back({"lubricant", "Roelands: pressure of that reduced pressure (round trip)",
                  "the pressure itself", roelands.Pressure(q_ref), p, 1e-10});
  // HTHS: a Vogel oil (a 6.9e-5 Pa s, b 1050 K, c 165 K) calibrated to 3.2 mPa s, evaluated
  // through Cross' law at 150 °C and 1e6 1/s.
  OilSpec oil;
  oil.model = ViscosityModel::kVogel;
  oil.vogel_a = 6.9e-5;
  oil.vogel_b = 1050.0;
  oil.vogel_c = 165.0;
  oil.shear_thinning = ShearThinning::kHths;
  oil.hths = 3.2e-3;
  const OilSpec::AtTemperature hot = oil.At(CrossLaw::kHthsTemperature, "", "temperature");
  rows.push_back({"lubricant", "HTHS through Cross' law (r 0.7, m 1) at 150 °C, 1e6 1/s [Pa s]",
                  "the HTHS viscosity it was calibrated to",
                  hot.viscosity * hot.shear.Factor(CrossLaw::kHthsShearRate), oil.hths, 1e-12});
  return rows;
}

}  // namespace filmdyn::lubrication
