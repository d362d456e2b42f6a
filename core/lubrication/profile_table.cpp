#include "core/lubrication/profile_table.hpp"

#include <algorithm>
#include <cmath>

#include "core/base/input_error.hpp"

namespace filmdyn::lubrication {

double Table1D::operator()(double at) const {
  if (x.empty()) return 0.0;
  if (at <= x.front()) return y.front();
  if (at >= x.back()) return y.back();
  const auto it = std::upper_bound(x.begin(), x.end(), at);
  const size_t i = static_cast<size_t>(it - x.begin());
  const double t = (at - x[i - 1]) / (x[i] - x[i - 1]);
  return y[i - 1] + t * (y[i] - y[i - 1]);
}

void Table1D::Validate(const std::string& field, bool allow_empty) const {
  if (x.size() != y.size()) {
    throw InputError(
        field, std::to_string(x.size()) + " x values, " + std::to_string(y.size()) + " y values",
        "both columns must have the same number of rows");
  }
  if (x.empty()) {
    if (allow_empty) return;
    throw InputError(field, "empty table", "must have at least one row");
  }
  for (size_t i = 0; i < x.size(); ++i) {
    RequireFinite(field + ".x[" + std::to_string(i) + "]", x[i]);
    RequireFinite(field + ".y[" + std::to_string(i) + "]", y[i]);
    if (i > 0 && !(x[i] > x[i - 1])) {
      throw InputError(
          field + ".x[" + std::to_string(i) + "]", FormatValue(x[i]),
          "abscissae must be strictly increasing (previous " + FormatValue(x[i - 1]) + ")");
    }
  }
}

}  // namespace filmdyn::lubrication
