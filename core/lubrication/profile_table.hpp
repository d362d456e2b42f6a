#pragma once
/// @file Piecewise-linear tables (skirt axial profile, ovality) with validation.
#include <string>
#include <vector>

namespace filmdyn::lubrication {

/// y(x) by linear interpolation; constant extrapolation beyond the ends (documented behaviour:
/// the last profile value holds past the table). Abscissae strictly increasing, all finite.
struct Table1D {
  std::vector<double> x, y;
  bool empty() const { return x.empty(); }
  double operator()(double at) const;
  /// Throws filmdyn::InputError naming `field` for: mismatched sizes, empty table (unless
  /// allow_empty), non-finite entries, abscissae not strictly increasing.
  void Validate(const std::string& field, bool allow_empty) const;
};

}  // namespace filmdyn::lubrication
