#pragma once
/// @file Verification of the oil's pressure-viscosity laws in the film (suite "lubricant" of
/// `filmdyn validate`, docs/validation/lubricant.md): the plane inclined slider with Barus
/// viscosity against its semi-analytic solution, and Roelands' reduced pressure against an
/// independent adaptive quadrature.
#include <memory>
#include <vector>

#include "core/base/validation_row.hpp"
#include "core/lubrication/oil.hpp"
#include "core/lubrication/reynolds_fem.hpp"

namespace filmdyn::lubrication {

/// A plane inclined slider of length L, one surface sliding at U, the film thinning linearly
/// from h_inlet (x = 0) to h_outlet (x = L), p = 0 at both ends, no side leakage.
struct InclinedSlider {
  double length = 0.01, speed = 10.0, viscosity = 0.01;
  double h_inlet = 10e-6, h_outlet = 5e-6;
  /// The isoviscous pressure, closed form: with h(x) linear of slope m and the flow per width
  /// Q = U h_i h_o / (h_i + h_o),  q(x) = (6 mu / m) [U (1/h_i - 1/h) - Q (1/h_i^2 - 1/h^2)].
  /// With a pressure-dependent viscosity it is the reduced pressure (oil.hpp).
  double IsoviscousPressure(double x) const;
  /// Load per unit width int_0^L p dx for the law (p = law.Pressure(q(x))), by 64-point
  /// Gauss-Legendre quadrature on 16 equal panels [N/m].
  double Load(const PressureViscosity& law) const;
  /// The largest pressure, at h = 2 Q / U (where dq/dx = 0) [Pa].
  double PeakPressure(const PressureViscosity& law) const;
  /// Load per unit width with a shear-thinning oil, mu(x) = mu0 law.InFilm(U, h(x)) (known
  /// before the pressure): dp/dx = 12 mu (U h / 2 - Q) / h^3 with Q = (U/2) int mu/h^2 /
  /// int mu/h^3 (p = 0 at both ends), and the load int_0^L (L - x) dp/dx dx, by the same
  /// quadrature [N/m].
  double ShearThinningLoad(const CrossLaw& law) const;
};

/// The slider on a strip of n elements along x (width kStripWidth, no flow across it): the
/// solver with the rigid film, zero squeeze and p = 0 at both ends set, and its parameters
/// (isoviscous, no pressure or shear law).
struct SliderStrip {
  static constexpr double kStripWidth = 1e-4;  ///< [m]
  std::unique_ptr<ReynoldsFem> fem;
  ReynoldsParams params;
};
SliderStrip MakeSliderStrip(const InclinedSlider& slider, int n);

/// Load per unit width and peak pressure of the slider solved by ReynoldsFem on a strip of n
/// elements along x.
struct SliderFem {
  double load = 0.0, peak_pressure = 0.0;
};
SliderFem SolveSliderFem(const InclinedSlider& slider, const PressureViscosity& law, int n,
                         const CrossLaw* shear = nullptr);

/// The rows of `filmdyn validate --suite lubricant` (~0.05 s).
std::vector<verification::ValidationRow> LubricantValidationRows();

}  // namespace filmdyn::lubrication
