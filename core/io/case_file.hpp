#pragma once
/// @file The case file (JSON; every field in docs/case-file.md). One visitor,
/// VisitCase, lists every field once with its unit and allowed range; reading, writing and
/// checking are visitors over it (Drake's Serialize(Archive*) pattern).
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/engine/engine_case.hpp"
#include "core/engine/pressure_curve.hpp"

namespace filmdyn::io {

/// The largest case file read (docs/case-file.md): a case is a few kB, 16 MB leaves room for long
/// inline pressure curves.
inline constexpr std::uintmax_t kMaxCaseFileBytes = 16u << 20;

/// Reads and checks a case from JSON. Missing fields keep their defaults; unknown fields, wrong
/// types, values out of range, NaN and inconsistent geometry throw InputError naming the dotted
/// path (e.g. "geometry.rod_length"). A file written before the cold skirt clearance became the
/// input gives `skirt.piston_radius` instead: it is read as skirt.cold_clearance =
/// geometry.liner_radius − piston_radius (the same radius to the last bit), and a one-line note
/// saying so is appended to *notes when given.
engine::EngineCase CaseFromJson(const nlohmann::json& json,
                                std::vector<std::string>* notes = nullptr);
/// Writes every field (and the "assumed" notes).
nlohmann::json CaseToJson(const engine::EngineCase& engine_case);

/// `--set key=value`: replaces the scalar at a dotted JSON path ("geometry.rod_length=0.13",
/// "skirt.model=lubricated", "pressure_curves.0.rpm=1000"). The path must name an existing
/// scalar; numbers are parsed strictly. Throws InputError naming the path.
void ApplyOverride(nlohmann::json* json, const std::string& assignment);
/// A curve as a case file's inline pressure curve at `rpm` that the case reader turns back into
/// exactly `curve` (its angles in degrees chosen so that they convert back to the same radians).
engine::PressureCurveSource InlinePressureCurve(const engine::PressureCurve& curve, double rpm);
/// Overrides ("key=value") as a report lists them: "`key = value`, `key = value`".
std::string OverridesText(const std::vector<std::string>& overrides);

/// A case and the directory its relative file names resolve against.
struct LoadedCase {
  engine::EngineCase value;
  std::filesystem::path directory;  ///< empty for the embedded default case
  std::string source;               ///< file path or "embedded:cases/default.json"
  /// One line each: what the reader did beyond reading (an older key read as its replacement);
  /// the CLI prints them, the GUI shows them in the status bar.
  std::vector<std::string> notes;
};

/// Loads a case file (or the embedded default when path is empty), applies the overrides, and
/// reads and checks every pressure curve (PressureCurveForSpeed at each curve's speed).
LoadedCase LoadCase(const std::filesystem::path& path,
                    const std::vector<std::string>& overrides = {});
/// The same from the file's text (`source` names it in messages). Bad input of any kind throws
/// InputError and nothing else (the fuzz harness tests/fuzz/fuzz_case_reader.cpp holds it to
/// that).
engine::EngineCase LoadCaseText(const std::string& text, const std::string& source,
                                const std::vector<std::string>& overrides = {},
                                std::vector<std::string>* notes = nullptr);

/// The case's file names relative to the case file's folder may be: the compliance files and the
/// pressure curves' CSV files (one list for the places that resolve or move them).
std::vector<std::string*> CaseFileNames(engine::EngineCase* engine_case);
/// For a case moving from the folder `from` to the folder `to` (a Save As elsewhere): each
/// relative file name that names an existing file from `from` is rewritten to name the same file
/// from `to` (relative, or absolute where no relative path leads there). Names of no file there
/// (a built-in resource's, a missing file) stay as written. Returns how many changed.
int RebaseCaseFiles(engine::EngineCase* engine_case, const std::filesystem::path& from,
                    const std::filesystem::path& to);

/// The case with every pressure curve given by a CSV file turned into its inline table: the
/// curve the reader reads from the file, exactly (InlinePressureCurve).
engine::EngineCase CaseWithInlineCurves(const LoadedCase& loaded);
/// Makes each relative file name of the case (CaseFileNames) that names an existing file from
/// `directory` absolute; names of no file there (a built-in resource's) stay as written.
void AbsoluteCaseFileNames(engine::EngineCase* engine_case, const std::filesystem::path& directory);

/// Reads a case an editor saved with values the reader refuses (the GUI's autosave of a case
/// with a marked cell: a NaN, a value out of range, an inconsistent pair), keeping every other
/// value: each refused field (the object field the reader names, or the list or section holding
/// it) takes its value from `base` — a case that reads — and the rest is read again. One line
/// per field taken from `base` ("geometry.rod_length = -1: must be > 0 [m]") goes to *dropped.
/// Throws InputError when the file cannot be read, is not JSON or `base` itself is refused.
engine::EngineCase CaseFileKeepingValid(const std::filesystem::path& path,
                                        const engine::EngineCase& base,
                                        std::vector<std::string>* dropped);

/// The cylinder-pressure curve for `rpm`: the case curve at that speed, or linear interpolation
/// between the two neighbouring speeds; InputError outside the tabulated speeds. CSV files are
/// resolved against the case directory, then against resources/ (embedded copies).
engine::PressureCurve PressureCurveForSpeed(const LoadedCase& loaded, double rpm);

}  // namespace filmdyn::io
