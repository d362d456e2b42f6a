#pragma once
/// @file Degrees and radians: the one conversion between them.
///
/// Inside the code every angle is in radians (SI); the case file, the outputs, the GUI and the
/// messages give crank angles and angles around a joint in degrees. Every conversion multiplies
/// by one of these two factors, so no file carries a "kDeg" of its own whose direction a reader
/// has to look up.
#include <numbers>

namespace filmdyn {

/// Radians in one degree: an angle in degrees times this is the angle in radians.
inline constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;
/// Degrees in one radian: an angle in radians times this is the angle in degrees.
inline constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

}  // namespace filmdyn
