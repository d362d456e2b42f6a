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

io::SurfaceField JointFieldFrames::Frame(size_t k) const {
  io::SurfaceField f = mesh;
  f.point_data = frames[k];
  return f;
}

}  // namespace filmdyn::ui
