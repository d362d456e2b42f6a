#pragma once
/// @file Built-in verification cases of the Reynolds solvers: the rows of `filmdyn validate`
/// (suite "bearing" / "jfo") and the reference data the tests use.
#include <vector>

#include "core/lubrication/bearing_solver.hpp"
#include "core/base/validation_row.hpp"

namespace filmdyn::lubrication {

/// One row of the Raimondi & Boyd (1958) full (360 deg) journal bearing table, Swift-Stieber
/// (Reynolds) film rupture, film starting at the maximum film thickness.
struct RaimondiBoydPoint {
  double l_over_d, eps;
  double sommerfeld;    ///< S = (mu N / P)(R/c)^2
  double attitude_deg;  ///< phi
  double friction_var;  ///< (R/c) f
  double flow_var;      ///< Q / (R c N L)
  double side_ratio;    ///< Q_s / Q
};
/// L/D = 1/4, 1/2, 1 at eps = 0.1, 0.2, 0.4, 0.6, 0.8, 0.9.
const std::vector<RaimondiBoydPoint>& RaimondiBoydTable();

/// Steady journal bearing at (L/D, eps), journal rotating, bearing at rest; returns the solver
/// result and S, attitude etc. through `BearingCalcResult`-like fields.
struct SteadyBearingPoint {
  double sommerfeld, attitude_deg, friction_var, side_flow_var, inlet_flow_var;
  ReynoldsStats stats;
};
SteadyBearingPoint SolveSteadyBearing(double l_over_d, double eps, const BearingMeshSpec& mesh,
                                      CavitationModel cavitation = CavitationModel::kReynolds);

/// Ocvirk & DuBois (1953) short bearing, half-Sommerfeld film: S and attitude [deg].
double OcvirkSommerfeld(double l_over_d, double eps);
double OcvirkAttitudeDeg(double eps);

/// Pure squeeze of a short bearing (no rotation), load per mu eps_dot L^3 R / c^2:
/// full film:      I_full(eps) = int_0^2pi cos^2/(1+eps cos)^3 = pi (1 + 2 eps^2)/(1-eps^2)^(5/2)
/// Reynolds (p>=0): I_half(eps) = int_{pi/2}^{3pi/2} cos^2/(1+eps cos)^3 (Gauss-Legendre, 1e-12)
double SqueezeIntegralFull(double eps);
double SqueezeIntegralHalf(double eps);

/// Pressure flow from a round hole (radius a, gauge pressure p_s) at the middle of a film of
/// uniform gap c and width L whose two edges are at ambient pressure, on a circumference far
/// longer than L (no motion): the strip |z| < L/2 maps onto the unit disc by w = tanh(pi z / 2L),
/// the hole's circle onto a circle of radius pi a / 2L to fourth order in a / L, so
/// Q = 2 pi (c^3 / 12 mu) p_s / ln(2 L / (pi a)) [m^3/s].
double HoleInStripFlow(double gap, double viscosity, double width, double hole_radius,
                       double pressure);
/// The same film fed by a whole-circle groove of width w round a circumference P:
/// Q = 2 P (c^3 / 12 mu) p_s / ((L - w) / 2) (exact) [m^3/s].
double GrooveInStripFlow(double gap, double viscosity, double width, double groove_width,
                         double circumference, double pressure);

/// Pocketed parallel slider (Fowell et al. 2007; configuration used by Giacopini et al. 2010 and
/// Almqvist et al. 2014): L = 20 mm, pocket [2, 5] mm of depth 9 um over h0 = 1 um, U = 1 m/s,
/// mu = 0.01 Pa s, both ends at 50 kPa above the cavitation pressure.
struct PocketSliderCase {
  double length = 20e-3, pocket_start = 2e-3, pocket_end = 5e-3;
  double h0 = 1e-6, h1 = 10e-6, speed = 1.0, viscosity = 0.01, p_ends = 50e3;
};
/// Closed-form JFO solution (derivation in validation_cases.cpp): flow per unit width q [m^2/s],
/// pressure at the pocket exit p_b [Pa], start of the reformed full film x_c [m].
struct PocketSliderSolution {
  double q, p_exit, x_reform, fluid_fraction;
};
PocketSliderSolution PocketSliderAnalytic(const PocketSliderCase& c);
/// FEM solution on a 1-element-wide strip of n elements (JFO or Reynolds), same outputs; q is
/// the inflow at x = 0 and `fluid_fraction` the minimum theta. outflow_q is the outflow at x = L.
struct PocketSliderFem {
  PocketSliderSolution sol;
  double outflow_q;
  ReynoldsStats stats;
};
PocketSliderFem PocketSliderNumeric(const PocketSliderCase& c, int n, CavitationModel model);

/// The lubrication rows of `filmdyn validate` (about 1 s in Release on 2 cores).
std::vector<verification::ValidationRow> LubricationValidationRows();

}  // namespace filmdyn::lubrication
