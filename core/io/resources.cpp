#include "core/io/resources.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace filmdyn::io {

std::optional<std::string> ReadResource(const std::string& name) {
  if (const char* dir = std::getenv("FILMDYN_RESOURCE_DIR"); dir != nullptr && *dir != '\0') {
    std::ifstream file(std::filesystem::path(dir) / name, std::ios::binary);
    if (file) {
      std::ostringstream text;
      text << file.rdbuf();
      return text.str();
    }
  }
  for (const EmbeddedResource& resource : EmbeddedResources()) {
    if (resource.name == name) return std::string(resource.content);
  }
  return std::nullopt;
}

}  // namespace filmdyn::io
