#pragma once
/// @file Headless export of the standard plots (`filmdyn run`, `filmdyn sweep`): the very charts
/// the GUI's PlotPanel draws, rendered offscreen through ui::ExportChart. Needs a QApplication
/// (the `offscreen` platform is enough; no X server).
#include <QString>
#include <QStringList>
#include <vector>

#include "ui/run/run_record.hpp"

namespace filmdyn::ui {

/// A finished run as the plots need it.
RunHandle FinishedRun(int id, RunRequest request, std::vector<RunSample> samples);

/// Writes `<directory>/<plot id>.png` and `.svg` for every standard plot, with all `runs`
/// overlaid (one run: a run's own plots; several: a sweep comparison). Creates the directory.
/// Returns the files written; on failure returns what was written and sets *error (naming the
/// file).
QStringList ExportStandardPlots(const std::vector<RunHandle>& runs, const QString& directory,
                                QString* error = nullptr);

}  // namespace filmdyn::ui
