#include "ui/fields/field_frames.hpp"

#include <QDir>
#include <QObject>
#include <cstdio>

namespace filmdyn::ui {

const std::vector<FieldArrayInfo>& FieldArrays() {
  static const std::vector<FieldArrayInfo> arrays = {
      {"pressure", "Film pressure [MPa]", 1e-6, "film pressure", "MPa", false},
      {"contact_pressure", "Asperity contact pressure [MPa]", 1e-6, "asperity contact pressure",
       "MPa", false},
      {"film_thickness", "Film thickness [µm]", 1e6, "film thickness", "µm", true},
      {"fluid_fraction", "Fluid fraction θ [-]", 1.0, "fluid fraction θ", "-", true, 0.0, 1.0,
       "fraction",
       "The share of the gap filled with oil: 1 = full film, below 1 = cavitated (oil and gas). "
       "Computed for a joint solved with mass-conserving (JFO) cavitation."},
      {"deformation", "Surface deformation [µm]", 1e6, "surface deformation", "µm", false,
       std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN(), nullptr,
       "How far the surfaces' elastic deformation under the film and asperity pressure opens the "
       "film (the film thickness shown is the deformed one). Computed for a joint with elastic "
       "surfaces."},
  };
  return arrays;
}

bool JointFieldFrames::HasArray(const std::string& name) const {
  return !frames.empty() && FindFieldArray(frames.front(), name) != nullptr;
}

bool JointFieldFrames::InNoFilm(double angle) const {
  for (const auto& [a, b] : no_film) {
    const double tol = 1e-9 * (b - a);
    if (angle > a + tol && angle < b - tol) return true;
  }
  return false;
}

const std::vector<double>* FindFieldArray(
    const std::vector<std::pair<std::string, std::vector<double>>>& frame, const std::string& name) {
  for (const auto& [array_name, values] : frame) {
    if (array_name == name) return &values;
  }
  return nullptr;
}

io::SurfaceField JointFieldFrames::Frame(size_t k) const {
  io::SurfaceField f = mesh;
  f.point_data = frames[k];
  return f;
}

}  // namespace filmdyn::ui
