#pragma once
/// @file Every built-in verification suite, as run by `filmdyn validate`: each domain contributes
/// its rows (lubrication: finite-bearing tables, Ocvirk, squeeze, pocketed slider; multibody:
/// exact slider-crank kinematics and Newton–Euler reactions; skirt: the skirt film's closed-form
/// limits and symmetries).
#include <string>
#include <vector>

#include "core/base/validation_row.hpp"

namespace filmdyn::verification {

/// Names of the suites, in the order they run.
std::vector<std::string> SuiteNames();

/// Names of the groups of rows inside a suite that --suite also takes: each is the suite column
/// of its rows (e.g. "bearing", "jfo" of the lubrication suite).
std::vector<std::string> GroupNames();

/// Runs the named suites or groups (all when `suites` is empty). Throws InputError naming an
/// unknown name.
std::vector<ValidationRow> RunSuites(const std::vector<std::string>& suites);

}  // namespace filmdyn::verification
