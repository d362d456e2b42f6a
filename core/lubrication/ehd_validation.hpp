#pragma once
/// @file Verification of the elastic surfaces (suite "ehd" of `filmdyn validate`,
/// docs/validation/ehd.md): Love's uniformly loaded rectangle against Johnson's published
/// deflections, and the plane inclined slider on an elastic lining against a shooting solution of
/// its one-dimensional Reynolds equation.
#include <vector>

#include "core/base/validation_row.hpp"
#include "core/lubrication/oil_validation.hpp"

namespace filmdyn::lubrication {

/// The inclined slider (oil_validation.hpp) with its film opened by an elastic layer,
/// h(x) = h_rigid(x) + layer p(x), no side leakage, p = 0 at both ends. Reference: the flow per
/// width Q of dp/dx = 6 mu (U h - 2 Q) / h^3 found by bisection so that p(L) = 0, p integrated
/// by classical Runge-Kutta on `steps` equal steps, the load by Simpson's rule on them.
struct ElasticSliderReference {
  double load = 0.0, peak_pressure = 0.0, max_deformation = 0.0;
};
ElasticSliderReference ElasticSliderByShooting(const InclinedSlider& slider, double layer,
                                               int steps);

/// The same slider solved by ReynoldsFem and the coupled elastic solve on a strip of n elements.
struct ElasticSliderFem {
  double load = 0.0, peak_pressure = 0.0, max_deformation = 0.0;
  bool converged = false;
};
ElasticSliderFem SolveElasticSliderFem(const InclinedSlider& slider, double thickness,
                                       double modulus, double poisson, int n);

/// The rows of `filmdyn validate --suite ehd`.
std::vector<verification::ValidationRow> EhdValidationRows();

}  // namespace filmdyn::lubrication
