#pragma once
/// @file Rows of `filmdyn validate` for the general multibody engine: a free compound pendulum
/// against its elliptic-integral period. (The crank train's rows live with the engine, which
/// builds it: core/engine/validation_cases.hpp.)
#include <vector>

#include "core/base/validation_row.hpp"

namespace filmdyn::multibody {

std::vector<verification::ValidationRow> MultibodyValidationRows();

}  // namespace filmdyn::multibody
