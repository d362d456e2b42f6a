#pragma once
/// @file Versions of FilmDyn and the libraries it was built with (About box, `filmdyn versions`).
#include <string>
#include <utility>
#include <vector>

namespace filmdyn::ui {

/// (name, version) pairs: FilmDyn, Qt (compile and run time), VTK, Eigen, SuiteSparse, JSON.
std::vector<std::pair<std::string, std::string>> LibraryVersions();

}  // namespace filmdyn::ui
