#pragma once
/// @file Greenwood–Tripp asperity-contact integrals F_n(H) of a Gaussian height distribution
/// (Greenwood & Tripp 1970, Proc IMechE 185:625-633):
///   F_n(H) = (1/sqrt(2 pi)) * integral_H^inf (s - H)^n exp(-s^2 / 2) ds.
/// The asperity contact pressure is p_c = K E' F_5/2(h / sigma) (eq. 29).

namespace filmdyn::lubrication {

/// The common curve fit F_5/2(H) = 4.4086e-5 (4 - H)^6.804 for H < 4, 0 for H >= 4
/// (Hu et al. 1994; Arcoumanis et al. 1997). eq. 30 misprints the constant as 4.486e-5
/// (docs/equations.md). Continuous at H = 4; for H < 0 it keeps growing as the
/// same power law.
double GreenwoodTrippF52Fit(double H);

/// F_5/2(H) from a table built once per process (first call, thread-safe): ln F_5/2 on
/// H in [-4, 12] with step 1/64, cubic Hermite in ln F using the exact slope
/// d ln F_5/2 / dH = -(5/2) F_3/2 / F_5/2. Relative error < 1e-9 on [-4, 12] (checked against
/// direct quadrature in the tests). Beyond the table: H > 12 uses the large-H asymptotic
/// expansion (6 terms) scaled to match the table at H = 12 (continuous; F(12) ~ 1e-34);
/// H < -4 continues linearly with the exact slope at -4. No allocation, one exp per call
/// inside the table.
double GreenwoodTrippF52Exact(double H);

/// F_3/2(H) from the same table machinery (ln F_3/2 with slope -(3/2) F_1/2 / F_3/2). Used for
/// the derivative dF_5/2/dH = -(5/2) F_3/2 (e.g. a Newton Jacobian of the contact pressure).
double GreenwoodTrippF32Exact(double H);

/// Direct quadrature of F_n(H) for any n >= 0 (slow: ~700 exponentials). Substituting
/// s = H + u^2 makes the integrand 2 u^(2n+1) exp(-(H + u^2)^2 / 2) smooth; composite 10-point
/// Gauss–Legendre on 64 panels over u in [0, sqrt(|H| + 10)]. Relative accuracy ~1e-13.
/// For tests, documentation tables and building the lookup tables.
double GreenwoodTrippQuadrature(double n, double H);

}  // namespace filmdyn::lubrication
