#pragma once
/// @file One triangulated surface with nodal fields: the film of one joint at one output step, as
/// the field recorder collects it and the GUI's field view draws it.
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace filmdyn::io {

struct SurfaceField {
  std::vector<std::array<double, 3>> points;  ///< node coordinates [m]
  std::vector<std::array<int, 3>> triangles;  ///< node indices, counter-clockwise
  /// (name, values) with one value per point, e.g. ("pressure[Pa]", p).
  std::vector<std::pair<std::string, std::vector<double>>> point_data;
};

}  // namespace filmdyn::io
