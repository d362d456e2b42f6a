#pragma once
/// @file Rough-surface model shared by both lubricated joints: Patir–Cheng flow and shear-stress
/// factors, the Wu–Zheng contact factor and Greenwood–Tripp asperity contact, evaluated per FEM
/// node without allocation. Formulas, sources, continuity treatment and sample values:
/// docs/surface-models.md.
///
/// Average Reynolds equation these factors belong to (Patir & Cheng 1978, their eq. (12), with the
/// Wu & Zheng 1989 contact factor; x = sliding direction, y = across it; U1, U2 = velocities of
/// surface 1 and surface 2 along x; h = nominal film thickness; sigma = composite roughness):
///
///   d/dx(phi_x h^3/(12 mu) dp/dx) + d/dy(phi_y h^3/(12 mu) dp/dy)
///       = (U1 + U2)/2 * phi_c dh/dx  +  (U1 - U2)/2 * sigma * d(phi_s)/dx  +  phi_c dh/dt
///
/// with phi_x = FlowFactors::pressure_along, phi_y = pressure_across, phi_s = shear,
/// phi_c = contact. eq. 1 is this equation with the liner (surface 2) at
/// rest and u_p = -U1 along its axial coordinate y, i.e. its right side
/// -u_p/2 [phi_c dh/dy + sigma dphi_s/dy] is the same term.
///
/// Sign convention of phi_s: FlowFactors::shear = (Vr1 - Vr2) * Phi_s(H, gamma), Vr_i =
/// sigma_i^2 / sigma^2, Phi_s >= 0 the Patir–Cheng 1979 factor of one rough surface. It is
/// multiplied by (U1 - U2)/2 * sigma, the velocity of surface 1 relative to surface 2: swapping
/// the names of the two surfaces flips the sign of both factors and leaves the term unchanged.
/// It is 0 for equally rough surfaces, > 0 when surface 1 is the rougher one.
///
/// Mean viscous shear stress on surface 1 (Patir & Cheng 1979; eq. 31 with u = U1 - U2):
///   tau_1 = -mu (U1 - U2) / h * (Phi_f + Phi_fs) - Phi_fp * h/2 * dp/dx,
/// with Phi_f = ShearStressFactors::f, Phi_fs = fs (already multiplied by Vr1 - Vr2, like
/// phi_s), Phi_fp = fp. Asperity friction adds boundary_friction * ContactPressure(h).
#include <string>

#include "core/lubrication/surface/patir_cheng.hpp"

namespace filmdyn::lubrication {

enum class AsperityModel { kGreenwoodTrippFit, kGreenwoodTrippExact };

/// Two mating rough surfaces. Surface 1 and 2 are named by the caller (e.g. skirt/liner).
struct SurfacePair {
  double sigma1 = 0.0, sigma2 = 0.0;  ///< rms roughness of each surface [m] (>= 0, not both 0)
  double peklenik = 1.0;              ///< Peklenik number gamma of the composite surface, 1/9..9
  double E1 = 0.0, nu1 = 0.3, E2 = 0.0, nu2 = 0.3;  ///< [Pa], [-]
  double gt_k = 1.198e-4;  ///< Greenwood–Tripp K (paper), pairs with E' below
  AsperityModel asperity_model = AsperityModel::kGreenwoodTrippFit;
  double boundary_friction = 0.13;  ///< mu_f

  /// sqrt(sigma1^2 + sigma2^2) [m].
  double CompositeSigma() const;
  /// E' = 2 / [(1-nu1^2)/E1 + (1-nu2^2)/E2] (Hu et al. 1994) [Pa]. Twice the Hertz
  /// E*; the default gt_k = 1.198e-4 belongs to this E'.
  double CompositeModulus() const;
  /// Throws filmdyn::InputError naming "<field_prefix>.<member>" (e.g. "skirt.surface.sigma1")
  /// for: a sigma < 0, both sigmas 0, peklenik outside [1/9, 9], E <= 0, nu outside (-1, 0.5),
  /// gt_k <= 0, boundary_friction < 0, an unknown asperity_model, or any non-finite number.
  /// peklenik within 1e-4 (absolute) below 1/9 or 1e-3 above 9 is accepted (typed-in 0.1111).
  void Validate(const std::string& field_prefix) const;
};

/// Flow factors of the average Reynolds equation at one H (see the file comment for the
/// equation and the sign of `shear`).
struct FlowFactors {
  double pressure_along;   ///< Patir–Cheng pressure flow factor in the sliding direction
  double pressure_across;  ///< ... across the sliding direction (= along-factor at 1/gamma)
  double shear;            ///< shear flow factor phi_s = (Vr1 - Vr2) Phi_s
  double contact;          ///< Wu–Zheng contact factor phi_c
  double mean_gap_excess;  ///< (h_T - h) / sigma: the mean gap the contact factor implies
};

/// Patir–Cheng 1979 shear-stress factors Phi_f, Phi_fs (times Vr1 - Vr2), Phi_fp.
struct ShearStressFactors {
  double f, fs, fp;
};

class SurfaceModel {
 public:
  /// Validates (field prefix "surface"; call pair.Validate with your own prefix first for
  /// better messages) and precomputes the gamma interpolation brackets; the first model with
  /// the exact Greenwood–Tripp integral builds the process-wide tables (~2.6e6 exp, tens of ms,
  /// once).
  explicit SurfaceModel(const SurfacePair& pair);

  /// Flow factors at H = h / sigma (composite). Continuous in H for all real H.
  FlowFactors Flow(double H) const;
  /// Shear-stress factors at H = h / sigma. Continuous in H for all real H.
  ShearStressFactors Shear(double H) const;
  /// Asperity contact pressure p_c = K E' F_5/2(h / sigma) [Pa] for film thickness h [m].
  double ContactPressure(double h) const;
  /// d p_c / d h [Pa/m] (<= 0), consistent with ContactPressure: exact model
  /// -K E' (5/2) F_3/2(H) / sigma; fit -K E' 6.804 F_fit(H) / ((4 - H) sigma).
  double ContactPressureDerivative(double h) const;

  /// Composite rms roughness sigma [m].
  double sigma() const;
  const SurfacePair& pair() const;

 private:
  SurfacePair pair_;
  double sigma_ = 0.0;
  double shear_sign_weight_ = 0.0;  // Vr1 - Vr2
  double contact_scale_ = 0.0;      // K E'
  patir_cheng::GammaBracket along_;
  patir_cheng::GammaBracket across_;
};

/// Greenwood–Tripp F_5/2(H): the common fit 4.4086e-5 (4-H)^6.804 for H<4 (eq. 30
/// misprints 4.486e-5) and the exact integral (1/sqrt(2pi)) ∫_H^∞ (s-H)^{5/2}
/// e^{-s^2/2} ds (tabulated; see greenwood_tripp.hpp for the tolerance).
double GreenwoodTrippF52Fit(double H);
double GreenwoodTrippF52Exact(double H);

}  // namespace filmdyn::lubrication
