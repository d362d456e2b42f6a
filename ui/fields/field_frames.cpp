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
  };
  return arrays;
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
