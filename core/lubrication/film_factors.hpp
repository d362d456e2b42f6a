#pragma once
/// @file The per-node roughness factors the Reynolds assembly needs, behind one small interface
/// so the FEM code does not depend on how they are computed. SmoothFilm gives the classical
/// Reynolds equation exactly; SurfaceFilm (surface_film.hpp) wraps the Patir-Cheng / Wu-Zheng /
/// Greenwood-Tripp SurfaceModel of core/lubrication/surface/.
namespace filmdyn::lubrication {

/// Factors of the average Reynolds equation (Patir & Cheng 1978, 1979; Wu & Zheng 1989) at one
/// film thickness h. "along" is the sliding direction, "across" the other surface direction.
struct NodalFilmFactors {
  double phi_along = 1.0;         ///< pressure flow factor along the sliding direction
  double phi_across = 1.0;        ///< pressure flow factor across it
  double phi_shear = 0.0;         ///< shear flow factor phi_s (multiplies sigma, Patir-Cheng 1979)
  double phi_contact = 1.0;       ///< Wu-Zheng contact factor phi_c = d(h_T)/dh
  /// h_T - h [m]: the mean gap h_T (the oil a full film holds per unit area) less the nominal
  /// gap h; 0 for smooth surfaces and from H = 3 on
  double mean_gap_excess = 0.0;
  double contact_pressure = 0.0;  ///< Greenwood-Tripp asperity pressure [Pa]
  double shear_f = 1.0;           ///< Patir-Cheng shear-stress factor Phi_f
  double shear_fs = 0.0;          ///< Phi_fs
  double shear_fp = 1.0;          ///< Phi_fp
};

/// Evaluates the factors at a film thickness. Implementations are immutable and thread-safe.
class FilmFactorModel {
 public:
  virtual ~FilmFactorModel() = default;
  virtual NodalFilmFactors At(double h) const = 0;
  /// Composite rms roughness sigma [m] (0 for smooth surfaces).
  virtual double sigma() const = 0;
  /// Boundary friction coefficient mu_f applied to the asperity pressure.
  virtual double boundary_friction() const = 0;
};

/// Smooth surfaces: every factor takes its classical value, no asperity contact.
class SmoothFilm final : public FilmFactorModel {
 public:
  NodalFilmFactors At(double) const override { return {}; }
  double sigma() const override { return 0.0; }
  double boundary_friction() const override { return 0.0; }
};

}  // namespace filmdyn::lubrication
