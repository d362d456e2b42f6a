#pragma once
/// @file What differs between the inputs of two runs — a case, a model and a speed — over every
/// field of the case schema (core/engine/case_schema.hpp), the pressure curves and the model,
/// with compact text in display units for labels ("μ 10 mPa·s · 4000 rpm"). The GUI labels its
/// runs with it; a design study can label its variants the same way.
#include <string>
#include <string_view>
#include <vector>

#include "core/engine/engine_case.hpp"

namespace filmdyn::engine {

/// The inputs of one run: the case, the model key ("ideal", "only-skirt", "only-lbrbe",
/// "skirt-lbrbe"; empty = the joint models of the case) and the crank speed [rpm] (≤ 0 = the
/// case's operating.rpm).
struct RunInputs {
  EngineCase engine_case;
  std::string model;
  double rpm = 0.0;
};

/// One input that differs.
struct CaseDifference {
  std::string path;     ///< case-file path ("lubricant.viscosity"), "model", or a table's group
                        ///< ("skirt.profile", "skirt.ovality", "pressure_curves")
  std::string label;    ///< short label ("μ", "model", "skirt profile"); empty for the speed
  std::string value_a;  ///< value of the first inputs in display units ("20 mPa·s", "Ideal"),
                        ///< or a summary of a table ("5 points")
  std::string value_b;  ///< the same for the second inputs
  /// Compact text naming the second inputs' value: "μ 10 mPa·s", "4000 rpm", "model Only-Skirt",
  /// "skirt profile changed".
  std::string text;
};

/// Every difference from `a` to `b`: the model first, then the fields in case-file order (the
/// pressure curves last). A joint's model field is compared only when neither inputs names a
/// model (the model decides it otherwise); operating.rpm is the run's speed when one is given.
/// Identical inputs give none.
std::vector<CaseDifference> DiffRunInputs(const RunInputs& a, const RunInputs& b);

/// The differences' texts joined by `separator` ("μ 10 mPa·s · 4000 rpm"); empty for none.
std::string FormatDifferences(const std::vector<CaseDifference>& differences,
                              std::string_view separator = " · ");

/// "Ideal", "Only-Skirt", "Only-LBRBE", "Skirt-LBRBE" for a model key (the key itself when
/// unknown).
std::string ModelTitle(const std::string& model_key);

/// `value` rounded to `digits` significant digits without trailing zeros: "10", "0.615",
/// "1.2e-10" (an exponent below 1e-4 and from 1e9 on).
std::string FormatSignificant(double value, int digits);

}  // namespace filmdyn::engine
