#include "core/base/input_error.hpp"

#include <cmath>
#include <sstream>

namespace filmdyn {

InputError::InputError(std::string field, std::string value, std::string allowed)
    : std::runtime_error(field + " = " + value + ": " + allowed),
      field_(std::move(field)),
      value_(std::move(value)),
      allowed_(std::move(allowed)) {}

std::string FormatValue(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  std::ostringstream out;
  out.precision(10);
  out << value;
  return out.str();
}

namespace {
std::string WithUnit(const std::string& text, const std::string& unit) {
  return unit.empty() ? text : text + " [" + unit + "]";
}
}  // namespace

void RequireFinite(const std::string& field, double value, const std::string& unit) {
  if (!std::isfinite(value)) {
    throw InputError(field, FormatValue(value), WithUnit("must be a finite number", unit));
  }
}

void RequirePositive(const std::string& field, double value, const std::string& unit) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw InputError(field, FormatValue(value), WithUnit("must be a finite number > 0", unit));
  }
}

void RequireNonNegative(const std::string& field, double value, const std::string& unit) {
  if (!std::isfinite(value) || value < 0.0) {
    throw InputError(field, FormatValue(value), WithUnit("must be a finite number >= 0", unit));
  }
}

void RequireInRange(const std::string& field, double value, double lo, double hi, bool lo_open,
                    bool hi_open, const std::string& unit) {
  const bool above = lo_open ? value > lo : value >= lo;
  const bool below = hi_open ? value < hi : value <= hi;
  if (!std::isfinite(value) || !above || !below) {
    const std::string range = std::string(lo_open ? "(" : "[") + FormatValue(lo) + ", " +
                              FormatValue(hi) + (hi_open ? ")" : "]");
    throw InputError(field, FormatValue(value),
                     WithUnit("must be a finite number in " + range, unit));
  }
}

}  // namespace filmdyn
