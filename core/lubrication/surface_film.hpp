#pragma once
/// @file Adapter from the rough-surface model (core/lubrication/surface/surface_model.hpp) to the
/// per-node factors of the Reynolds FEM. Sign conventions are those documented there: surface 1
/// is the journal (bearing joint) or the skirt (skirt joint).
#include <memory>
#include <vector>

#include "core/lubrication/film_factors.hpp"
#include "core/lubrication/surface/surface_model.hpp"

namespace filmdyn::lubrication {

/// The factors evaluated from their formulas at every call (exp, log and powers per node).
class SurfaceFilm final : public FilmFactorModel {
 public:
  explicit SurfaceFilm(const SurfacePair& pair) : model_(pair) {}
  NodalFilmFactors At(double h) const override;
  double sigma() const override { return model_.sigma(); }
  double boundary_friction() const override { return model_.pair().boundary_friction; }
  const SurfaceModel& model() const { return model_; }

 private:
  SurfaceModel model_;
};

/// The same factors read from a table in H = h / sigma, built once per surface pair from
/// SurfaceFilm and interpolated linearly: the formulas cost ~10 % of a coupled run (one
/// evaluation per node per film solve), a table read a fraction of that.
///
/// Table spacing ΔH: 1/1024 on [0, 8], 1/64 on [8, 64], 1/8 on [64, 512]; every point where a
/// published fit changes branch or is clamped (H = 0.5, 0.75, 1, 3, 4, 5, 6, 7, 15) is a table
/// point, so each interval interpolates a smooth piece. Outside [0, 512] the formulas are used.
/// Interpolation error (measured against SurfaceFilm, test_surface_model): below 1e-5 of each
/// factor's scale (1 for the dimensionless factors, the asperity pressure at H = 0 for the
/// asperity pressure); 3e-7 at Peklenik number 1, 4.4e-6 at 1/9 (the across-factor H^-1.5
/// near H = 0.5). The fits themselves represent Patir and Cheng's simulations to a few percent.
/// Memory: ~1 MB per surface pair, built in a few ms.
class TabulatedSurfaceFilm final : public FilmFactorModel {
 public:
  explicit TabulatedSurfaceFilm(const SurfacePair& pair);
  NodalFilmFactors At(double h) const override;
  double sigma() const override { return direct_.sigma(); }
  double boundary_friction() const override { return direct_.boundary_friction(); }
  /// The formulas the table was built from.
  const SurfaceFilm& direct() const { return direct_; }

  /// Table zones: [H_begin, H_end] with spacing 1 / per_unit (public for the tests).
  struct Zone {
    double begin, end, per_unit;
  };
  static constexpr Zone kZones[3] = {{0.0, 8.0, 1024.0}, {8.0, 64.0, 64.0}, {64.0, 512.0, 8.0}};

 private:
  SurfaceFilm direct_;
  double inv_sigma_ = 0.0;
  std::vector<NodalFilmFactors> table_[3];
};

/// The film model of a joint's surface pair (the tabulated one).
inline std::shared_ptr<const FilmFactorModel> MakeSurfaceFilm(const SurfacePair& pair) {
  return std::make_shared<TabulatedSurfaceFilm>(pair);
}

}  // namespace filmdyn::lubrication
