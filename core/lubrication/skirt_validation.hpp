#pragma once
/// @file Built-in verification cases of the piston skirt solver: the rows of `filmdyn validate`
/// (suite "skirt") and the closed-form limits and cases that the tests share with them
/// (docs/validation/skirt.md).
#include <vector>

#include "core/base/validation_row.hpp"
#include "core/lubrication/skirt_solver.hpp"

namespace filmdyn::lubrication {

/// Load per unit width of the plane inclined slider (e.g. Cameron, Basic Lubrication Theory,
/// ch. 4): W' = 6 mu |U| L^2 / (h0^2 (K - 1)^2) [ln K - 2 (K - 1)/(K + 1)], K = h_inlet / h0,
/// for a film converging linearly from h_inlet to h0 = h_outlet along the sliding direction,
/// p = 0 at both ends [N/m]. Requires h_inlet > h_outlet > 0.
double InclinedSliderLoad(double viscosity, double speed, double length, double h_outlet,
                          double h_inlet);

/// Long-skirt limit of the pure squeeze of a round, unprofiled skirt (e0 = 0, e0_dot > 0 towards
/// the thrust side): away from the skirt ends p(alpha) = (12 mu R^2 e0_dot / c^3)(cos alpha -
/// cos alpha1) on the thrust panel, the anti-thrust panel separates (p = 0), and the lateral force
/// on the piston per unit skirt length, both halves, is
///   -(12 mu R^3 e0_dot / c^3)(alpha1 - sin alpha1 cos alpha1)  [N/m].
double LongSkirtSqueezeForcePerLength(double viscosity, double radius, double clearance,
                                      double alpha1, double e0_dot);

/// A skirt, a state and the closed-form value of its lateral force in the limit the case
/// approaches.
struct SkirtLimitCase {
  SkirtConfig config;
  SkirtState state;
  double reference = 0.0;  ///< lateral force of the limit [N]
};

/// Inclined-slider limit: R = 41.5 mm, alpha1 = alpha2 = 46 deg, mu = 0.008 Pa s, a linear
/// profile from 20 um (h0, skirt top) to 40 um (skirt bottom), e0 = gamma = 0, u_p = +10 m/s:
/// in the piston frame the liner drags the oil from the bottom (inlet, thickest film) to the
/// top, a converging film without cavitation. The anti-thrust panel is lifted off by a 1 mm
/// ovality, so the thrust panel carries the load. Away from the relief edges p does not depend
/// on alpha, and as the panel width R alpha1 grows relative to L the lateral force approaches
///   reference = -2 R sin(alpha1) W'(h0, h1) + 2 R sin(alpha2) W'(h0 + 1 mm, h1 + 1 mm)
/// (the second term, the lifted panel's, is 2e-5 of the first). Mesh: n_axial elements along the
/// skirt, about L/8 wide circumferentially on the thrust panel.
SkirtLimitCase SliderLimitCase(double skirt_length, int n_axial);

/// Long-skirt squeeze limit: the same radius, panels and viscosity, c = 20 um, no profile,
/// e0_dot = 5 mm/s; reference = LongSkirtSqueezeForcePerLength(...) * L, which the lateral force
/// approaches as L grows (the ends lose a fixed amount, so the relative error falls as 1/L).
/// Mesh: n_thrust elements on the thrust panel, square elements along the skirt.
SkirtLimitCase SqueezeLimitCase(double skirt_length, int n_thrust);

/// The skirt rows of `filmdyn validate` (about 0.05 s in Release).
std::vector<verification::ValidationRow> SkirtValidationRows();

}  // namespace filmdyn::lubrication
