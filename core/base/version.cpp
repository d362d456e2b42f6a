#include "core/base/version.hpp"

namespace filmdyn {

std::string_view Version() { return FILMDYN_VERSION; }

}  // namespace filmdyn
