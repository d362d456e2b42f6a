#pragma once
/// @file The integrals over a solved film that both lubricated joints report: load components
/// (normal pressure and asperity pressure along given directions), the friction of eq. 31 on
/// both surfaces and its moments, the minimum film thickness (MOFT) and where it is, the peak
/// film and contact pressures, and the cavitated share of the film area. One routine serves the
/// skirt (SkirtSolver, per panel) and the big end (BearingSolver): a joint supplies only what
/// differs, its load directions and friction moment arms as nodal fields, its sliding velocity
/// (ReynoldsParams::u_diff) and its symmetry factor, and maps the plain FilmIntegrals into its own
/// result, naming the coordinates of the node indices.
#include <Eigen/Core>
#include <array>
#include <span>

#include "core/lubrication/reynolds_fem.hpp"

namespace filmdyn::lubrication {

/// A P1 field on the film's mesh times a constant: w = scale * field.
struct ScaledField {
  const Eigen::VectorXd* field = nullptr;  ///< one value per mesh node
  double scale = 1.0;
};

/// What a joint supplies beyond the solved film. The fields are P1 nodal fields on the film's
/// mesh (one value per node); the caller keeps them alive during the call.
struct FilmIntegralSpec {
  /// Directions d of the load components, at most FilmIntegrals::kMaxLoads: e.g. cos(theta),
  /// sin(theta) for the bearing; cos(alpha) and the moment arm cos(alpha) (y - a_p) for the skirt.
  std::span<const Eigen::VectorXd* const> load_directions = {};
  /// Weights w of the friction moments, at most ElementFriction::kMaxMoments: the
  /// displacement of surface 1 along the sliding axis per unit of a generalised coordinate,
  /// e.g. -R cos(alpha) for the skirt's tilt.
  std::span<const ScaledField> friction_arms = {};
  /// Factor from the solved mesh to the whole film, applied to every integral (loads, friction,
  /// areas): 2 for a half film mirrored about a plane of symmetry, else 1.
  double symmetry = 1.0;
};

/// eq. 31 plus boundary friction integrated part by part over the whole film. u = U1 - U2
/// (ReynoldsParams::u_diff), s the sliding axis of the mesh (ReynoldsFem::sliding_axis), surface 1
/// the one moving at U1 (journal, skirt), surface 2 the other (bearing, liner). The shear
/// stresses along +s are
///   tau_1 = -mu u/h (Phi_f + Phi_fs) - Phi_fp (h/2) dp/ds - sgn(u) mu_f p_c,
///   tau_2 = +mu u/h (Phi_f - Phi_fs) - Phi_fp (h/2) dp/ds + sgn(u) mu_f p_c.
/// With a pressure-dependent viscosity mu in tau is mu(p): the Couette integrals below then carry
/// the factor mu(p)/mu0 and mu is mu0.
struct FilmFriction {
  double couette_surface1 = 0.0;  ///< int theta (Phi_f + Phi_fs)/h dA [m]
  double couette_surface2 = 0.0;  ///< int theta (Phi_f - Phi_fs)/h dA [m]
  double poiseuille = 0.0;        ///< int Phi_fp (h/2) dp/ds dA [N]
  double contact = 0.0;           ///< int p_c dA [N]
  /// int tau_1 dA = -mu u couette_surface1 - poiseuille - sgn(u) mu_f contact [N].
  double surface1 = 0.0;
  /// int tau_2 dA = +mu u couette_surface2 - poiseuille + sgn(u) mu_f contact [N].
  double surface2 = 0.0;
};

/// The friction on surface 1 summed element by element (each element's tau_1 times its area),
/// the form that carries moment arms. force is FilmFriction::surface1 summed in another order:
/// the two agree to rounding.
struct ElementFriction {
  static constexpr int kMaxMoments = 2;
  double force = 0.0;          ///< int tau_1 dA [N]
  double contact_force = 0.0;  ///< its asperity part, -sgn(u) mu_f int p_c dA [N]
  /// int tau_1 w_i dA per friction arm w_i [N times the unit of w_i].
  std::array<double, kMaxMoments> moment{};
};

/// Integrals of one film (whole film: times FilmIntegralSpec::symmetry).
struct FilmIntegrals {
  static constexpr int kMaxLoads = 4;
  /// int (p + p_c) d_i dA per load direction d_i [N times the unit of d_i].
  std::array<double, kMaxLoads> load{};
  /// int p_c d_i dA: the asperity part of load [N times the unit of d_i].
  std::array<double, kMaxLoads> contact_load{};
  FilmFriction friction;              ///< eq. 31, part by part
  ElementFriction element_friction;   ///< eq. 31 on surface 1, element by element
  double moft = 0.0;                  ///< minimum nodal film thickness [m]
  int moft_node = -1;                 ///< its node (the first one in node order)
  double max_pressure = 0.0;          ///< max(0, max p) [Pa]
  int max_pressure_node = -1;         ///< its node; -1 when p <= 0 everywhere
  double max_contact_pressure = 0.0;  ///< max(0, max p_c) [Pa]
  /// Lumped area of the cavitated nodes, each weighted by 1 - theta with JFO cavitation (theta
  /// = fluid fraction), by 1 with Reynolds cavitation [m^2].
  double cavitated_area = 0.0;
  double film_area = 0.0;  ///< area of the film [m^2]

  /// cavitated_area / film_area (0 for an empty film) [-].
  double CavitatedFraction() const { return film_area > 0 ? cavitated_area / film_area : 0.0; }
};

/// Integrates `fields` (normally fem.solution()) over the mesh of `fem`, with the film thickness
/// and roughness factors of fem's last solve, the cavitation model of fem's options, and the
/// viscosity, U1 - U2 and film model (boundary friction mu_f) of `params`. Products of P1 fields
/// (the loads) are integrated exactly; the friction from the element means of the nodal Couette
/// terms, of Phi_fp h and of p_c, and each element's pressure gradient. Throws std::logic_error
/// on more directions or arms than the capacity, or fields of the wrong size (a bug in the
/// caller).
FilmIntegrals IntegrateFilm(const ReynoldsFem& fem, const ReynoldsSolution& fields,
                            const ReynoldsParams& params, const FilmIntegralSpec& spec);

}  // namespace filmdyn::lubrication
