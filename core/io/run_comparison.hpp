#pragma once
/// @file The comparison of several runs (`filmdyn sweep`): one row per run with its main figures,
/// read from each run folder's summary.json — the files are the interface, so a comparison can
/// also be rebuilt later from folders on disk.
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace filmdyn::io {

/// One figure of the comparison: how it is derived from summary.json and how it is shown.
struct ComparisonFigure {
  std::string key;           ///< CSV column, SI, e.g. "max_abs_piston_lateral[m]"
  std::string display_name;  ///< e.g. "max |e0| [µm]"
  double display_scale;      ///< SI → display unit
};

/// The figures, in column order.
const std::vector<ComparisonFigure>& ComparisonFigures();

struct ComparisonRow {
  std::string folder;  ///< the run folder's name
  std::string model;
  double rpm = 0.0;
  std::string status;
  int cycles = 0;
  double wall_time_s = 0.0;
  std::vector<std::optional<double>> figures;  ///< per ComparisonFigures(), SI; empty = n/a
  /// Figures the run has but the comparison leaves out, one sentence each: a spike between the
  /// output samples (an extreme summary.json marks min_spike / max_spike, or a peak film
  /// pressure with the run's unresolved_peak warning).
  std::vector<std::string> notes;
};

/// The notes as one text ("; " between them), for a table cell.
std::string NotesText(const std::vector<std::string>& notes);

/// Reads `<folder>/summary.json`. Throws std::runtime_error naming the file when it is missing
/// or malformed.
ComparisonRow ReadComparisonRow(const std::filesystem::path& folder);

/// comparison.csv: header with units, one row per run, empty cells for missing figures, the
/// notes last.
void WriteComparisonCsv(std::ostream& out, const std::vector<ComparisonRow>& rows);
/// A Markdown table in display units (also printed by `filmdyn sweep`), the notes below it.
std::string ComparisonMarkdown(const std::vector<ComparisonRow>& rows);

}  // namespace filmdyn::io
