#pragma once
/// @file The case schema: the one table of every field of an EngineCase (everything but the
/// pressure curves and the notes): dotted path, kind, SI unit, display unit and scale, allowed
/// range, label, one-line help, and accessors. The case file reader and writer, `--set`, the GUI's
/// editors and their checks, and the field table of docs/case-file.md all come from it; the rules
/// that tie several fields together live in CheckCaseConsistency, used by all of them.
#include <functional>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "core/engine/engine_case.hpp"

namespace filmdyn::engine {

enum class FieldKind {
  kText,        ///< a string
  kChoice,      ///< one of a few names (CaseField::choices): joint and cavitation models
  kNumber,      ///< a finite real in SI
  kInteger,     ///< a whole number (mesh counts, cycle counts)
  kNumberList,  ///< an array of finite reals in SI, each within the range
};

/// The editor tab a field belongs to.
enum class FieldGroup { kCase, kGeometry, kMasses, kSkirt, kBigEnd, kLubricant, kOperating, kSolver };
/// "Geometry", "Masses and inertias", ... (the GUI's tab titles).
std::string FieldGroupTitle(FieldGroup group);

/// Allowed values of a number (SI): lo < x or lo ≤ x, x < hi or x ≤ hi. Unbounded ends are ±inf.
struct FieldRange {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;
};

struct CaseField {
  std::string path;  ///< dotted case-file key, e.g. "big_end.journal_radius"
  FieldKind kind = FieldKind::kNumber;
  FieldGroup group = FieldGroup::kCase;
  std::string label;             ///< with the paper's symbol, e.g. "Journal radius R_j"
  /// Short label for compact text such as a run's differences ("μ", "R_j", "skirt profile");
  /// empty for the crank speed, whose unit ("rpm") names it.
  std::string symbol;
  std::string help;              ///< one line: what it is, where the default comes from
  /// What the input is and what it changes, in plain words for someone who knows engines but
  /// not this program (the case editor's tooltips).
  std::string description;
  std::string unit;              ///< SI unit as the file uses it: "m", "Pa*s", "-", "rpm", ...
  std::string display_unit;      ///< unit the GUI shows: "mm", "µm", "°", "MPa", ...
  double display_scale = 1.0;    ///< SI value = display value × display_scale + display_offset
  /// Shift of the display unit's zero: −273.15 for temperatures in K shown in °C (SI =
  /// display + 273.15). Scalars only; lists keep 0.
  double display_offset = 0.0;
  /// The value as the GUI shows it, and back (ScaleToDisplay, ScaleFromDisplay).
  double ToDisplay(double si) const;
  double FromDisplay(double display) const;
  FieldRange range;              ///< numbers, integers and list elements (SI)

  /// Numbers and integers: the value in SI, and setting it (integers are rounded; a non-finite
  /// value becomes −1, which every integer range rejects).
  std::function<double(const EngineCase&)> get;
  std::function<void(EngineCase&, double)> set;
  /// Number lists, text: the member itself.
  std::function<std::vector<double>&(EngineCase&)> list;
  std::function<std::string&(EngineCase&)> text;
  /// Choices: the allowed names, in the order of the member's enumerators, and the index of the
  /// chosen one.
  std::vector<std::string> choices;
  std::function<int(const EngineCase&)> choice;
  std::function<void(EngineCase&, int)> set_choice;

  /// The chosen name of a choice field.
  const std::string& ChoiceName(const EngineCase& c) const;
  /// What the GUI shows for the k-th choice ("JFO (mass-conserving)" for "jfo", "0W-20" for
  /// "0w-20", "heat balance" for "heat_balance"); the file, `--set` and messages keep the names.
  std::string ChoiceTitle(std::size_t k) const;
  /// The choice whose name or title is `text`; −1 when none is.
  int ChoiceIndex(std::string_view text) const;
  /// Sets a choice field by name; any other name throws InputError(path, name, the choices).
  void SetChoice(EngineCase& c, const std::string& name) const;
  /// The choices quoted: "a" | "b" | "c", or in prose "a", "b" or "c".
  std::string ChoicesText(bool prose = false) const;

  /// Throws InputError naming `field` (the path, or path.k for a list element), the value and
  /// the allowed range when `si_value` is not allowed; the one check of a field's own range.
  void Check(double si_value, const std::string& field = {}) const;
  /// Whether Check lets si_value through.
  bool Allows(double si_value) const;
  /// Whether this field holds the same value in both cases: numbers equal, or within `relative`
  /// of the larger in magnitude when given (a NaN equals a NaN); lists of the same length, element
  /// by element alike; texts and choices equal. The one comparison of a field's values.
  bool SameValue(const EngineCase& a, const EngineCase& b, double relative = 0.0) const;
  /// Whether this field and `other` are columns of one table, set together (the skirt profile's
  /// y and h): number lists of the same group and symbol. A field is in its own table.
  bool SameListTable(const CaseField& other) const;
  /// "> 0 [m]", "[1e-14, 0.01] [-]", "integer in [8, 5000]", ... (docs and tooltips).
  std::string RangeText() const;
  /// What Check says a number or integer field allows ("must be a finite number in (0, 100]
  /// [m]"), for errors about a value that is no number at all.
  std::string AllowedText() const;
};

/// Every field, in case-file order.
/// A value in SI as a number of display units of `scale` SI units each, and back. Where the unit
/// is an integer fraction of SI (mm, µm: 1e-3 and 1e-6 are not exact in binary, 1000 and 1e6 are)
/// the conversion goes by that integer: a decimal typed in µm is then stored as the same decimal
/// written in m far more often (0.615 µm → 6.15e-07 m, where × 1e-6 gives 6.1500000000000004e-07;
/// of random 1–6 digit decimals 13 % still differ in the last bit, against 36 %).
double ScaleToDisplay(double si, double scale);
double ScaleFromDisplay(double display, double scale);

const std::vector<CaseField>& CaseSchema();
/// The field with this dotted path, or nullptr.
const CaseField* FindCaseField(std::string_view path);

/// For a path that names no field: "; did you mean skirt.length?" naming the fields a slip of
/// the keyboard away (at most two letters typed, left out, swapped or wrong, and at most a
/// third of the name's length), or the field of that name in another section
/// ("geometry.cold_clearance" → skirt.cold_clearance); empty when none is.
std::string SimilarFieldsText(std::string_view path);
/// The field a `--set` path sets: the field itself, or the list whose element it names
/// ("skirt.profile_h.2" → skirt.profile_h); nullptr when the path names no field.
const CaseField* FieldOfPath(std::string_view path);
/// The fields whose "assumed" note a new value of `field` makes stale: the field, and for a list
/// every column of its table (a new profile h makes its y the user's too).
std::vector<const CaseField*> FieldsSetWith(const CaseField& field);

/// "ideal" / "lubricated" (the choices of the joint-model fields).
const char* JointModelName(JointModel model);

/// The rules that tie fields together (rod longer than crank + |pin offset|, clearances > 0,
/// panel widths, profile and ovality tables). Throws InputError naming the field to fix.
void CheckCaseConsistency(const EngineCase& engine_case);
/// A proportion of a lubricated joint that its lengths give, and the band engine joints lie well
/// inside (an order of magnitude or more beyond their own): outside it a length is most likely in
/// the wrong unit (mm typed as m passes the fields' wide ranges).
struct JointProportion {
  std::string field;   ///< the field the editor and the warning name
  std::string what;    ///< e.g. "the big end's width over its diameter, L/D"
  std::string symbol;  ///< e.g. "L/D"
  double value = 0.0, lo = 0.0, hi = 0.0;
  bool Plausible() const { return value >= lo && value <= hi; }
};
/// The big end's L/D and c/R, the skirt's length over the bore and cold clearance over the bore
/// radius, for the joints that are lubricated.
std::vector<JointProportion> JointProportions(const EngineCase& engine_case);

/// What a field implies beyond its own value, for the editor's note column, e.g. the hot
/// clearance beside the cold one ("hot: 6.41 µm (cold 25.00 µm)"); empty when there is nothing
/// to add.
std::string DerivedNote(const EngineCase& engine_case, const std::string& path);
/// Why a field (a scalar, or a list by any of its columns' paths) is not used with the case's
/// choices (e.g. "the viscosity follows Vogel's law" for lubricant.viscosity), or empty when it
/// is used: the editor greys such rows and list tables. A value the choices make an error (a
/// supply pressure without holes or groove) is not "unused": it stays editable. The choices it
/// quotes are named as the case file and `--set` write them ("shell_holes"), or by their titles
/// (CaseField::ChoiceTitle: “holes in the shell”) where the reader sees titles (the editor).
enum class ChoiceWording { kNames, kTitles };
std::string UnusedReason(const EngineCase& engine_case, const std::string& path,
                         ChoiceWording wording = ChoiceWording::kNames);

}  // namespace filmdyn::engine
