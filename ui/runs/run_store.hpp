#pragma once
/// @file The runs of a project, saved beside its case file and read back.
///
/// Layout for the project `dir/case.json` (docs/gui.md, "Projects and runs"):
///
///     dir/case.json                 the case (CaseDocument::save)
///     dir/case.runs/runs.json       format, format_version, base (run key), runs in table order:
///                                   key, name, notes, hidden, model, rpm, status, reason,
///                                   wall_time_s, has_folder and the run's own case (case file
///                                   JSON)
///     dir/case.runs/<key>/          exactly what `filmdyn run` writes: results.csv,
///                                   summary.json, fields/*.h5 + *.xdmf
///     dir/case.runs/<key>.samples.csv  the samples the plots show, every double to the last
///                                   bit (results.csv rounds to 10 digits)
///     dir/case.runs/<key>.motion.csv   the motion samples (between the output steps too) the
///                                   orbit and phase portraits draw, as exactly; absent for a
///                                   run without them
///
/// Every file is written atomically; runs.json last, so a save that fails leaves the previous
/// runs.json (and the folders it names) intact. A run folder is written once under its key and
/// kept by later saves; folders no runs.json names any more are removed.
#include <QString>
#include <QStringList>
#include <functional>
#include <vector>

#include "ui/run/run_record.hpp"

namespace filmdyn::ui {

/// A run in the order of the run table, with what the table shows of it.
struct ProjectRun {
  RunHandle run;
  bool visible = true;
};

/// "dir/case.runs" for "dir/case.json".
QString RunsFolderFor(const QString& project_path);

/// What SaveProjectRuns did.
struct SaveRunsReport {
  int saved = 0;
  int skipped_running = 0;     ///< runs still running: not saved
  int skipped_unrestored = 0;  ///< runs that could not be read back: listed and kept as saved
};

/// Saves the finished, failed and cancelled runs of `runs` (in this order) beside the project
/// `project_path`; `base_id` is the base run. Runs that could not be read back are listed again
/// as they were saved. Removes the files of runs the folder's index listed and `runs` does not;
/// nothing else. Returns false with *error naming the file when a write fails (the previous
/// runs.json then stays) or when the folder's runs.json cannot be read (nothing is written).
bool SaveProjectRuns(const QString& project_path, const std::vector<ProjectRun>& runs, int base_id,
                     SaveRunsReport* report, QString* error);

/// The runs read back from a project, in their saved order.
struct LoadedRuns {
  std::vector<ProjectRun> runs;
  int base_id = -1;  ///< -1: none saved (the first run is the base)
  /// One line per run that could not be read back (or for an unreadable runs.json): which run
  /// and why. Such a run is still in `runs`, with its restore error set.
  QStringList problems;
};

/// Reads the runs saved beside `project_path` (none when there is no runs folder). `take_id`
/// gives each restored run its id. Never throws: what cannot be read is reported in problems.
LoadedRuns LoadProjectRuns(const QString& project_path, const std::function<int()>& take_id);

/// A run folder as `filmdyn run` and every point of `filmdyn study` write it, read as a run of
/// the session: its samples from results.csv (10 significant digits), the motion samples from
/// motion.csv, status, counters, error estimate and warnings from summary.json, the film fields
/// from fields/ when it has them. A folder holds no case: `request` gives the run's inputs.
/// Throws std::runtime_error naming the file when one cannot be read or the run has not ended.
RunHandle ReadRunFolder(const QString& folder, RunRequest request, int id);

/// The film fields of a run folder's fields/ files (core's HDF5 series) as the field view's
/// frames, keeping every stride-th frame as a live run does (at most 240 per cycle); `rpm`
/// gives each frame's time within the cycle, `engine_case` the skirt's relief and each joint's
/// cavitation model (the fluid fraction is read for a joint with JFO cavitation, when the files
/// have it). nullptr when the folder has no fields. Throws
/// std::runtime_error naming the file when one cannot be read.
std::shared_ptr<const FieldFrames> ReadFieldFrames(const QString& fields_folder,
                                                   const engine::EngineCase& engine_case,
                                                   double rpm);

}  // namespace filmdyn::ui
