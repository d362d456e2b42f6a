#include "core/lubrication/surface_film.hpp"

#include <algorithm>
#include <cmath>

namespace filmdyn::lubrication {

NodalFilmFactors SurfaceFilm::At(double h) const {
  const double H = h / model_.sigma();
  const FlowFactors fl = model_.Flow(H);
  const ShearStressFactors sh = model_.Shear(H);
  NodalFilmFactors f;
  f.phi_along = fl.pressure_along;
  f.phi_across = fl.pressure_across;
  f.phi_shear = fl.shear;
  f.phi_contact = fl.contact;
  f.mean_gap_excess = fl.mean_gap_excess * model_.sigma();
  f.contact_pressure = model_.ContactPressure(h);
  f.shear_f = sh.f;
  f.shear_fs = sh.fs;
  f.shear_fp = sh.fp;
  return f;
}

TabulatedSurfaceFilm::TabulatedSurfaceFilm(const SurfacePair& pair)
    : direct_(pair), inv_sigma_(1.0 / direct_.sigma()) {
  const double sigma = direct_.sigma();
  for (int z = 0; z < 3; ++z) {
    const Zone& zone = kZones[z];
    const int n = static_cast<int>(std::lround((zone.end - zone.begin) * zone.per_unit));
    table_[z].resize(static_cast<std::size_t>(n) + 1);
    for (int i = 0; i <= n; ++i) {
      const double H = zone.begin + i / zone.per_unit;  // exact: per_unit is a power of 2
      table_[z][static_cast<std::size_t>(i)] = direct_.At(H * sigma);
    }
  }
}

NodalFilmFactors TabulatedSurfaceFilm::At(double h) const {
  const double H = h * inv_sigma_;
  int z = 0;
  while (z < 3 && !(H <= kZones[z].end)) ++z;  // NaN falls through to the formulas
  if (z == 3 || !(H >= 0.0)) return direct_.At(h);
  const Zone& zone = kZones[z];
  const std::vector<NodalFilmFactors>& t = table_[z];
  const double u = (H - zone.begin) * zone.per_unit;
  const std::size_t i = std::min(static_cast<std::size_t>(u), t.size() - 2);
  const double w = u - static_cast<double>(i);
  const NodalFilmFactors& a = t[i];
  const NodalFilmFactors& b = t[i + 1];
  auto mix = [w](double x, double y) { return x + w * (y - x); };
  NodalFilmFactors f;
  f.phi_along = mix(a.phi_along, b.phi_along);
  f.phi_across = mix(a.phi_across, b.phi_across);
  f.phi_shear = mix(a.phi_shear, b.phi_shear);
  f.phi_contact = mix(a.phi_contact, b.phi_contact);
  f.mean_gap_excess = mix(a.mean_gap_excess, b.mean_gap_excess);
  f.contact_pressure = mix(a.contact_pressure, b.contact_pressure);
  f.shear_f = mix(a.shear_f, b.shear_f);
  f.shear_fs = mix(a.shear_fs, b.shear_fs);
  f.shear_fp = mix(a.shear_fp, b.shear_fp);
  return f;
}

}  // namespace filmdyn::lubrication
