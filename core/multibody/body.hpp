#pragma once
/// @file A rigid body of the planar multibody system: constant inertial data only (the state
/// lives in SystemState), after MuJoCo's model/data split.
#include <string>

namespace filmdyn::multibody {

struct Body {
  std::string name;
  double mass = 0.0;     ///< [kg], > 0
  double inertia = 0.0;  ///< moment of inertia about the centre of mass, axis Z [kg·m²], > 0
};

}  // namespace filmdyn::multibody
