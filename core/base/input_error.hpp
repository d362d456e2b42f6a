#pragma once
/// @file Bad user input (docs/conventions.md, "Error handling"): an exception whose message
/// names the field, the value and what is allowed. Bugs in our own code are assertions instead,
/// never this.
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace filmdyn {

/// Thrown for any invalid input from a case file, a CLI option, a CSV table or a GUI cell.
/// what() reads: "<field> = <value>: <allowed>", e.g.
/// "bearing.radial_clearance = -1e-05: must be a finite number > 0 [m]".
class InputError : public std::runtime_error {
 public:
  InputError(std::string field, std::string value, std::string allowed);

  const std::string& field() const { return field_; }
  const std::string& value() const { return value_; }
  const std::string& allowed() const { return allowed_; }

 private:
  std::string field_;
  std::string value_;
  std::string allowed_;
};

/// Whether `text` is well-formed UTF-8 (no overlong forms, no surrogates, at most U+10FFFF).
bool IsUtf8(std::string_view text);
/// Throws InputError naming `field` unless `text` is well-formed UTF-8.
void RequireUtf8(const std::string& field, std::string_view text);

/// Formats a double for error messages with enough digits to be recognised ("nan", "inf" too).
std::string FormatValue(double value);
/// Every digit a double needs to be read back exactly (the shortest such form).
std::string FormatValueExact(double value);
/// Reads a whole string as a number in the C locale's form (the forms FormatValue writes, with
/// an optional leading '+'), whatever the process's locale — the GUI runs under the user's, where
/// the C library's strtod reads "1.5" as 1 in a German one; false (value untouched) when it is
/// not one or out of range. The one reader of numbers in text: files, options, table cells.
bool ParseNumber(std::string_view text, double& value);
/// `shown`, a short form of `value`, or every digit `value` needs (FormatValueExact) where
/// `shown`, read back, would land on the other side of `inside` than `value` itself: a number
/// shown as allowed is allowed when typed back, one shown as refused is refused.
std::string FormatOnItsSide(double value, const std::string& shown,
                            const std::function<bool(double)>& inside);
/// A value refused for lying outside [lo, hi] (or an open end): FormatValue's, or every digit it
/// needs where that would read as inside ("720.0000000000001", not "720", against [0, 720]).
std::string FormatValueOutside(double value, double lo, double hi, bool lo_open = false,
                               bool hi_open = false);
/// A range's bound as messages and documents show it: FormatValue's, or every digit it needs
/// where a closed bound's FormatValue would read outside the range ("25.132741228718345", not
/// "25.13274123", for an upper bound of 8 pi): the bound shown, typed back, is allowed.
std::string FormatBound(double bound, bool upper, bool open = false);

/// Throws InputError unless value is finite and > 0. unit is appended to the message, e.g. "m".
void RequirePositive(const std::string& field, double value, const std::string& unit = "");
/// Throws InputError unless value is finite and >= 0.
void RequireNonNegative(const std::string& field, double value, const std::string& unit = "");
/// Throws InputError unless value is finite.
void RequireFinite(const std::string& field, double value, const std::string& unit = "");
/// Throws InputError unless lo <= value <= hi (or lo < value < hi when the bounds are open).
void RequireInRange(const std::string& field, double value, double lo, double hi,
                    bool lo_open = false, bool hi_open = false, const std::string& unit = "");

}  // namespace filmdyn
