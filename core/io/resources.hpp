#pragma once
/// @file The default case and pressure curves, available without the source tree: the files of
/// resources/ are compiled in (cmake/EmbedResources.cmake). A directory named by the environment
/// variable FILMDYN_RESOURCE_DIR, when set, takes precedence (for editing resources in place).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace filmdyn::io {

struct EmbeddedResource {
  std::string_view name;  ///< path relative to resources/, e.g. "cases/default.json"
  std::string_view content;
};

/// All compiled-in resources (generated source).
const std::vector<EmbeddedResource>& EmbeddedResources();

/// Text of a resource by its name relative to resources/ ("pressure/synthetic_6000rpm.csv"):
/// from $FILMDYN_RESOURCE_DIR if set and the file exists there, else the embedded copy.
std::optional<std::string> ReadResource(const std::string& name);

}  // namespace filmdyn::io
