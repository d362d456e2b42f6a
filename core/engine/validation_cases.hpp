#pragma once
/// @file Rows of `filmdyn validate` for the ideal crank train (suite "multibody"): integrated
/// against the exact offset slider crank and an independent Newton–Euler solution. For
/// cycle-long comparisons `ours` is reference + (largest deviation over the cycle), `reference`
/// the peak magnitude, so the relative error is the deviation relative to the peak.
#include <vector>

#include "core/base/validation_row.hpp"

namespace filmdyn::engine {

std::vector<verification::ValidationRow> CrankTrainValidationRows();

}  // namespace filmdyn::engine
