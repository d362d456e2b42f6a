#pragma once
/// @file Rows of `filmdyn validate` for the multibody engine: the ideal crank train against the
/// exact slider-crank kinematics and an independent Newton–Euler solution, and a free compound
/// pendulum against its elliptic-integral period. For cycle-long comparisons `ours` is
/// reference + (largest deviation over the cycle), `reference` the peak magnitude, so the relative
/// error is the deviation relative to the peak.
#include <vector>

#include "core/verification/validation_row.hpp"

namespace filmdyn::multibody {

std::vector<verification::ValidationRow> MultibodyValidationRows();

}  // namespace filmdyn::multibody
