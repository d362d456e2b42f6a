#include "ui/fields/field_frames.hpp"

#include <QDir>
#include <QObject>
#include <cstdio>

namespace filmdyn::ui {

const std::vector<FieldArrayInfo>& FieldArrays() {
  static const std::vector<FieldArrayInfo> arrays = {
      {"pressure", "p [MPa]", 1e-6},
      {"contact_pressure", "p_c [MPa]", 1e-6},
      {"film_thickness", "h [µm]", 1e6},
  };
  return arrays;
}

io::SurfaceField JointFieldFrames::Frame(size_t k) const {
  io::SurfaceField f = mesh;
  f.point_data = frames[k];
  return f;
}

}  // namespace filmdyn::ui
