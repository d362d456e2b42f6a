#pragma once
/// @file Film fields of a run for the 3D views: per joint and per output step one triangulated
/// surface (node coordinates [m]) with nodal arrays in SI named "pressure" [Pa],
/// "contact_pressure" [Pa] and "film_thickness" [m]. The coupled lubricated run fills
/// this; the ideal model has no fields. The GUI's exports are core's files
/// (the run's writers), not these frames.
#include <QString>
#include <string>
#include <vector>

#include "core/io/surface_field.hpp"

namespace filmdyn::ui {

/// One joint: the surface (points [m], triangles; fixed over the run) and per frame the nodal
/// arrays (name, values) in SI.
struct JointFieldFrames {
  std::string name;       ///< "skirt", "big_end"
  io::SurfaceField mesh;  ///< point_data unused
  std::vector<std::vector<std::pair<std::string, std::vector<double>>>> frames;
  /// Frame k as a complete surface with its arrays.
  io::SurfaceField Frame(size_t k) const;
};

struct FieldFrames {
  std::vector<double> crank_angle_deg;  ///< one per frame [°CA]
  std::vector<double> time;             ///< [s], same length
  std::vector<JointFieldFrames> joints;
  bool empty() const { return crank_angle_deg.empty() || joints.empty(); }
};

/// The arrays the views offer: (array name, title with display unit, display scale).
struct FieldArrayInfo {
  const char* name;
  const char* title;
  double scale;
};
const std::vector<FieldArrayInfo>& FieldArrays();


}  // namespace filmdyn::ui
