#pragma once
/// @file A design study (`filmdyn study`): a study file names factors — any case field by its
/// dotted path, the crank speed (operating.rpm) and the model among them — with levels or a
/// range, and a design (full factorial, Latin hypercube, one factor at a time); each design
/// point is one run of the base case with the factors' values set, in its own folder of the
/// study folder. The study folder and its files are the interface: a study is run, resumed and
/// collected from what is on disk (docs/study.md).
///
///     DIR/study.json     the study as read (every path resolved, ranges expanded), written
///                        before any run: a second run into DIR must be the same study
///     DIR/base-case.json the base case as the study's first run read it (its "set" entries
///                        applied, pressure curves inline, file names absolute): every point of
///                        DIR is made from it, so a later edit of the case file changes no point
///     DIR/design.csv     one row per point: point number, folder, each factor's value (SI)
///     DIR/point-NNNN/    the point's run folder, exactly what `filmdyn run` writes
///     DIR/study.csv      one row per point: the design, the status and the figures of each
///                        run (written by collecting the folders; empty cells where none yet)
///     DIR/study.md       the same for people, the status counts, the main effects and the best
///                        points
///     DIR/plots/         the same as pictures: main effects, scatter matrix, best points
///                        (drawn by the command line with ui/plots/study_charts.hpp)
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "core/engine/run_job.hpp"
#include "core/io/case_file.hpp"

namespace filmdyn::batch {

enum class StudyDesign { kFullFactorial, kLatinHypercube, kOneAtATime };
/// "full-factorial", "latin-hypercube", "one-at-a-time".
std::string StudyDesignName(StudyDesign design);

/// The factor path that sets the model of a point (levels: skirt-lbrbe, only-skirt, ...).
inline constexpr char kModelFactor[] = "model";

/// One factor: a case field (or kModelFactor) and its values. Numbers are SI, as in a case file.
struct StudyFactor {
  std::string path;
  /// Discrete levels (numbers), in the order given or expanded from a range with `count`.
  std::vector<double> levels;
  /// Discrete levels of a text-valued factor (the model; a joint model "ideal"/"lubricated").
  std::vector<std::string> text_levels;
  /// A range [lo, hi] for the Latin hypercube (sampled continuously; integers rounded).
  std::optional<std::pair<double, double>> range;
  bool integer = false;  ///< an integer case field (mesh counts, cycles)
  std::string unit;      ///< the field's SI unit ("" for the model)

  bool is_text() const { return !text_levels.empty(); }
  /// Number of discrete levels (0 for a continuous range in a Latin hypercube).
  std::size_t level_count() const { return is_text() ? text_levels.size() : levels.size(); }
};

/// A study file as read and checked (ReadStudyFile).
struct Study {
  std::string name;
  std::filesystem::path study_file;         ///< where it was read from (messages)
  std::filesystem::path case_file;          ///< the base case; empty = the embedded default case
  std::vector<std::string> base_overrides;  ///< "path=value", applied to the base case first
  StudyDesign design = StudyDesign::kFullFactorial;
  int points = 0;          ///< Latin hypercube: the number of points
  std::uint64_t seed = 1;  ///< Latin hypercube: the random generator's seed
  std::vector<StudyFactor> factors;
  bool write_fields = false;  ///< fields/ in every point's folder (off by default: volume)
  double time_limit_s = 0.0;  ///< per run; 0 = none
  /// The study folder's base-case.json once a run has started there (PinStudyBase,
  /// ReadStudyFolder): the base case and the points are read from it instead of case_file and
  /// base_overrides. Not part of the study's definition (StudyJson).
  std::filesystem::path base_snapshot;
};

/// The study folder's copy of the base case.
inline constexpr char kBaseCaseFile[] = "base-case.json";

/// One design point: the value of each factor (as the case-file text it sets).
struct StudyPoint {
  int number = 0;                              ///< 1-based
  std::string folder;                          ///< "point-0001"
  std::vector<std::string> values;             ///< one per factor: "3e-05", "skirt-lbrbe"
  std::vector<std::optional<double>> numbers;  ///< the numeric values (empty for text)
};

/// Reads and checks a study file: every factor path is a case field the schema knows (or
/// "model"), every level within the field's range, a range only where the design samples
/// ranges. Throws InputError naming the file and the key (e.g. "study.json: factors[2].levels[1]")
/// with the value and what is allowed.
Study ReadStudyFile(const std::filesystem::path& path);
/// The same from the file's text; `path` names it in messages and resolves the case file.
Study ParseStudy(const std::string& text, const std::filesystem::path& path);

/// The design's points, in a fixed order (factorial: the last factor varies fastest; Latin
/// hypercube: reproducible from the seed; one at a time: the base point first, then each factor
/// through its levels with the others at the base case's values).
std::vector<StudyPoint> DesignPoints(const Study& study, const engine::EngineCase& base);

/// The base case of the study (its case file or the embedded default, with its overrides; or
/// the study folder's copy, Study::base_snapshot).
io::LoadedCase LoadStudyBase(const Study& study);
/// base-case.json's text for `base` (LoadStudyBase's): the case with its pressure curves inline
/// and its relative file names absolute, so that it reads the same from the study folder.
std::string BaseCaseText(const io::LoadedCase& base);
/// Pins the base case of the study run into `dir`: writes DIR/base-case.json from `base` when
/// the folder has none (a new study, or one begun by a version without it) and returns `study`
/// reading its cases from it. When DIR's copy differs — the case file (or the version's
/// embedded default case) changed since the study began — throws InputError naming the case and
/// every field that differs: its points would mix two base cases.
Study PinStudyBase(const std::filesystem::path& dir, Study study, const io::LoadedCase& base);
/// The case of a point: the base case with the point's values set (through the case reader, so
/// every field's range and the rules between fields are checked). Throws InputError naming the
/// point and the field.
io::LoadedCase LoadPointCase(const Study& study, const StudyPoint& point);

/// The study as study.json holds it (a canonical form: a re-run compares it byte for byte).
std::string StudyJson(const Study& study);
/// design.csv.
void WriteDesignCsv(std::ostream& out, const Study& study, const std::vector<StudyPoint>& points);

/// What a point's folder says of it.
enum class PointState { kPending, kRunning, kDone, kIncomplete, kFailed };
std::string PointStateName(PointState state);
/// Done: summary.json says the run reached its end ("completed" or "not-converged"). Running:
/// it says "running" and another process holds the folder's lock. Incomplete: started but
/// stopped (cancelled, time limit, or killed: "running" with no lock held). Failed: the run
/// failed, or the folder cannot be read (`reason` says why). Pending: no summary.json.
PointState ReadPointState(const std::filesystem::path& folder, std::string* reason = nullptr);

/// One row of study.csv.
struct StudyRow {
  StudyPoint point;
  PointState state = PointState::kPending;
  std::string status;  ///< the run's status from summary.json, or the state's name
  std::string reason;  ///< why a point failed or is incomplete
  std::optional<double> wall_time_s;
  std::vector<std::optional<double>> figures;  ///< io::ComparisonFigures(), SI
  std::vector<std::string> notes;              ///< figures left out (io::ComparisonRow::notes)
};

/// Reads every point's folder under `dir` (design.csv gives the points).
std::vector<StudyRow> CollectStudy(const std::filesystem::path& dir, const Study& study);
/// study.csv (SI): point, folder, the factors, state, status, wall time, the figures, the reason
/// of a point that is not done, the notes (figures left out).
void WriteStudyCsv(std::ostream& out, const Study& study, const std::vector<StudyRow>& rows);
/// The index in io::ComparisonFigures() of the figure whose key (a study.csv column, e.g.
/// "mean_bearing_fpl[W]") is `key`. Throws InputError("--rank-by", key, "must be one of: …"),
/// listing every key, when there is none.
std::size_t StudyFigureIndex(const std::string& key);
/// The figure the best points are ranked by when none is asked for: the mean big-end friction
/// power (mean_bearing_fpl[W]), or the skirt's (mean_skirt_fpl[W]) when no done point has a
/// big-end film (every point's big end ideal). An index in io::ComparisonFigures().
std::size_t DefaultRankFigure(const std::vector<StudyRow>& rows);

/// One level of a factor in the main effects.
struct MainEffectLevel {
  std::string label;            ///< the level as study.csv writes it ("3e-05", "ideal")
  std::optional<double> value;  ///< the level's number (empty for a text factor)
  int points = 0;               ///< done points at this level
  /// Per io::ComparisonFigures() (SI): the mean over the done points at this level that have the
  /// figure; empty when none has it.
  std::vector<std::optional<double>> means;
};
/// The main effects of one factor with discrete levels.
struct MainEffect {
  std::size_t factor = 0;               ///< index in Study::factors
  std::vector<MainEffectLevel> levels;  ///< in the factor's order of levels
};
/// The main effects of every factor with discrete levels (a factor sampled continuously over a
/// range, in a Latin hypercube, has none): for each level, the done points whose value of the
/// factor is that level and the mean of each figure over them. The other factors are as the
/// design combines them, so in a full factorial each level's mean averages over the same
/// combinations of the others. In a one-at-a-time design a factor's levels take only its own
/// points: those that vary it, and the base point at the level equal to its base value (if one
/// is); the points that vary another factor, which hold this one at its base value, do not count.
std::vector<MainEffect> MainEffects(const Study& study, const std::vector<StudyRow>& rows);
/// The done points that have figure `figure` (an index in io::ComparisonFigures()), best first:
/// smallest first, or largest when `largest_first`; equal values keep the order of `rows`.
/// Indices in `rows`.
std::vector<std::size_t> RankedPoints(const std::vector<StudyRow>& rows, std::size_t figure,
                                      bool largest_first);

/// study.md: the design, counts per state, the table (display units), the main effects of each
/// factor on each figure (MainEffects) and, when `rank_by` names a figure key, the ten best
/// points by it (RankedPoints: smallest first, or largest when `largest_first`). A `rank_by`
/// that is no figure's key throws InputError (StudyFigureIndex).
std::string StudyMarkdown(const Study& study, const std::vector<StudyRow>& rows,
                          const std::string& rank_by = {}, bool largest_first = false);

/// Reads DIR/study.json back (a study folder's own copy), reading its cases from
/// DIR/base-case.json when there is one (Study::base_snapshot). Throws InputError naming the
/// file.
Study ReadStudyFolder(const std::filesystem::path& dir);

}  // namespace filmdyn::batch
