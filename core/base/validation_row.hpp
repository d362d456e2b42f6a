#pragma once
/// @file One row of `filmdyn validate`: a built-in verification case against a published
/// number or a closed form. Each domain provides a function returning its rows; the CLI
/// prints them as a table (case, ours, reference, error, tolerance, pass).
#include <string>
#include <vector>

namespace filmdyn::verification {

struct ValidationRow {
  std::string suite;  ///< e.g. "surface", "bearing", "multibody"
  std::string name;   ///< what is compared, e.g. "Raimondi-Boyd L/D=1 eps=0.6 Sommerfeld"
  std::string reference_source;  ///< citation of the reference value, e.g. "Raimondi & Boyd 1958"
  double ours = 0.0;
  double reference = 0.0;
  double tolerance = 0.0;  ///< allowed error, in the unit of `error`
  bool relative = true;    ///< true: error = |ours-ref|/|ref|; false: error = |ours-ref|
  double Error() const;
  bool Pass() const { return Error() <= tolerance; }
};

}  // namespace filmdyn::verification
