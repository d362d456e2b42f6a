#include "ui/about_info.hpp"

#include <vtkVersion.h>
#include <Eigen/Core>
#include <QtGlobal>
#include <nlohmann/json.hpp>

#include <SuiteSparse_config.h>

#include "core/base/version.hpp"

namespace filmdyn::ui {

std::vector<std::pair<std::string, std::string>> LibraryVersions() {
  auto dotted = [](int a, int b, int c) {
    return std::to_string(a) + "." + std::to_string(b) + "." + std::to_string(c);
  };
  return {
      {"FilmDyn", std::string(Version())},
      {"Qt", std::string(qVersion()) + " (built with " QT_VERSION_STR ")"},
      {"VTK", vtkVersion::GetVTKVersion()},
      {"Eigen", dotted(EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION)},
      {"SuiteSparse",
       dotted(SUITESPARSE_MAIN_VERSION, SUITESPARSE_SUB_VERSION, SUITESPARSE_SUBSUB_VERSION)},
      {"nlohmann-json", dotted(NLOHMANN_JSON_VERSION_MAJOR, NLOHMANN_JSON_VERSION_MINOR,
                               NLOHMANN_JSON_VERSION_PATCH)},
  };
}

}  // namespace filmdyn::ui
