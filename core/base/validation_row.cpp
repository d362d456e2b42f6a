#include "core/base/validation_row.hpp"

#include <cmath>

namespace filmdyn::verification {

double ValidationRow::Error() const {
  const double diff = std::abs(ours - reference);
  if (!relative) return diff;
  return reference != 0.0 ? diff / std::abs(reference) : diff;
}

}  // namespace filmdyn::verification
