#include "core/base/input_error.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

namespace filmdyn {

namespace {
// A value as echoed in a message: control characters shown as '?', and cut after
// kEchoLimit bytes (at a character boundary) with its full length said — a 30 MB CSV cell
// or a binary file must not flood the terminal.
constexpr std::size_t kEchoLimit = 160;
std::string Echo(std::string value) {
  const std::size_t size = value.size();
  if (size > kEchoLimit) {
    std::size_t cut = kEchoLimit;
    while (cut > 0 && (static_cast<unsigned char>(value[cut]) & 0xC0) == 0x80) --cut;
    value.resize(cut);
    value += "… (" + std::to_string(size) + " bytes)";
  }
  for (char& c : value) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7F) c = '?';
  }
  return value;
}
}  // namespace

InputError::InputError(std::string field, std::string value, std::string allowed)
    : std::runtime_error(Echo(field) + " = " + Echo(value) + ": " + allowed),
      field_(std::move(field)),
      value_(Echo(std::move(value))),
      allowed_(std::move(allowed)) {}

bool IsUtf8(std::string_view text) {
  std::size_t i = 0;
  const std::size_t n = text.size();
  while (i < n) {
    const auto c = static_cast<unsigned char>(text[i]);
    int extra = 0;
    unsigned long code = 0;
    if (c < 0x80) {
      ++i;
      continue;
    } else if ((c & 0xE0) == 0xC0) {
      extra = 1;
      code = c & 0x1F;
    } else if ((c & 0xF0) == 0xE0) {
      extra = 2;
      code = c & 0x0F;
    } else if ((c & 0xF8) == 0xF0) {
      extra = 3;
      code = c & 0x07;
    } else {
      return false;
    }
    if (i + static_cast<std::size_t>(extra) >= n) return false;
    for (int k = 1; k <= extra; ++k) {
      const auto d = static_cast<unsigned char>(text[i + k]);
      if ((d & 0xC0) != 0x80) return false;
      code = (code << 6) | (d & 0x3F);
    }
    static constexpr unsigned long kMin[4] = {0, 0x80, 0x800, 0x10000};
    if (code < kMin[extra] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) {
      return false;
    }
    i += static_cast<std::size_t>(extra) + 1;
  }
  return true;
}

void RequireUtf8(const std::string& field, std::string_view text) {
  if (!IsUtf8(text)) {
    throw InputError(field, std::string(text), "must be text in UTF-8 (this is not)");
  }
}

std::string FormatValue(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  std::ostringstream out;
  out.precision(10);
  out << value;
  return out.str();
}

std::string FormatValueExact(double value) {
  if (!std::isfinite(value)) return FormatValue(value);
  char digits[32];
  const std::to_chars_result r = std::to_chars(digits, digits + sizeof digits, value);
  const std::ptrdiff_t length = r.ptr - digits;
  if (r.ec != std::errc() || length <= 0 || length > 31) return FormatValue(value);
  return std::string(digits, static_cast<std::size_t>(length));
}

bool ParseNumber(std::string_view text, double& value) {
  // from_chars takes no '+'; one is allowed before a digit or a point ("+-1" is no number).
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
    if (text.empty() || text.front() == '-' || text.front() == '+') return false;
  }
  double read = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), read);
  if (text.empty() || error != std::errc() || end != text.data() + text.size()) return false;
  value = read;
  return true;
}

std::string FormatOnItsSide(double value, const std::string& shown,
                            const std::function<bool(double)>& inside) {
  double read = 0.0;
  if (!std::isfinite(value) || !ParseNumber(shown, read)) return shown;
  return inside(read) != inside(value) ? FormatValueExact(value) : shown;
}

std::string FormatValueOutside(double value, double lo, double hi, bool lo_open, bool hi_open) {
  return FormatOnItsSide(value, FormatValue(value), [=](double x) {
    return (lo_open ? x > lo : x >= lo) && (hi_open ? x < hi : x <= hi);
  });
}

std::string FormatBound(double bound, bool upper, bool open) {
  if (open) return FormatValue(bound);
  return FormatOnItsSide(bound, FormatValue(bound),
                         [=](double x) { return upper ? x <= bound : x >= bound; });
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
    const std::string range = std::string(lo_open ? "(" : "[") + FormatBound(lo, false, lo_open) +
                              ", " + FormatBound(hi, true, hi_open) + (hi_open ? ")" : "]");
    throw InputError(field, FormatValueOutside(value, lo, hi, lo_open, hi_open),
                     WithUnit("must be a finite number in " + range, unit));
  }
}

}  // namespace filmdyn
