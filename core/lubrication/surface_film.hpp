#pragma once
/// @file Adapter from the rough-surface model (core/lubrication/surface/surface_model.hpp) to the
/// per-node factors of the Reynolds FEM. Sign conventions are those documented there: surface 1
/// is the journal (bearing joint) or the skirt (skirt joint).
#include <memory>

#include "core/lubrication/film_factors.hpp"
#include "core/lubrication/surface/surface_model.hpp"

namespace filmdyn::lubrication {

class SurfaceFilm final : public FilmFactorModel {
 public:
  explicit SurfaceFilm(const SurfacePair& pair) : model_(pair) {}
  NodalFilmFactors At(double h) const override {
    const double H = h / model_.sigma();
    const FlowFactors fl = model_.Flow(H);
    const ShearStressFactors sh = model_.Shear(H);
    NodalFilmFactors f;
    f.phi_along = fl.pressure_along;
    f.phi_across = fl.pressure_across;
    f.phi_shear = fl.shear;
    f.phi_contact = fl.contact;
    f.contact_pressure = model_.ContactPressure(h);
    f.shear_f = sh.f;
    f.shear_fs = sh.fs;
    f.shear_fp = sh.fp;
    return f;
  }
  double sigma() const override { return model_.sigma(); }
  double boundary_friction() const override { return model_.pair().boundary_friction; }
  const SurfaceModel& model() const { return model_; }

 private:
  SurfaceModel model_;
};

/// Convenience: a shared film model for the joint configs.
inline std::shared_ptr<const FilmFactorModel> MakeSurfaceFilm(const SurfacePair& pair) {
  return std::make_shared<SurfaceFilm>(pair);
}

}  // namespace filmdyn::lubrication
