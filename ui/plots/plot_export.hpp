#pragma once
/// @file Headless export of the standard plots (`filmdyn run`, `filmdyn sweep`): the very charts
/// the GUI's PlotPanel draws, rendered offscreen through ui::ExportChart. Needs a QApplication
/// (the `offscreen` platform is enough; no X server).
#include <QString>
#include <QStringList>
#include <string>
#include <vector>

#include "core/io/results_writer.hpp"

#include "ui/plots/plot_run.hpp"

namespace filmdyn::ui {

/// The plot data of a run from core's rows (as written to results.csv) and its motion rows (as
/// written to motion.csv; io::MotionRows).
PlotRun PlotRunFromRows(int id, const engine::EngineCase& engine_case, const std::string& model,
                        double rpm, const std::vector<io::OutputRow>& rows,
                        const std::vector<io::OutputRow>& motion_rows);

/// Writes `<directory>/<plot id>.png` and `.svg` for every standard plot, with all `runs`
/// overlaid (one run: a run's own plots; several: a sweep comparison). Creates the directory.
/// Returns the files written; on failure returns what was written and sets *error (naming the
/// file).
QStringList ExportStandardPlots(const std::vector<PlotRun>& runs, const QString& directory,
                                QString* error = nullptr);

}  // namespace filmdyn::ui
