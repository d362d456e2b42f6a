#pragma once
/// @file The data a plot needs of a run, with no run record behind it.
#include <QString>
#include <vector>

#include "ui/run/result_columns.hpp"

namespace filmdyn::ui {

class RunRecord;

/// What the plots need of one run: its identity, label, bearing clearance, samples and motion. The
/// GUI makes one from a run record; headless commands from core's rows (no run record).
struct PlotRun {
  int id = 0;
  QString label;                   ///< e.g. "Skirt-LBRBE 6000 rpm"
  double bearing_clearance = 0.0;  ///< radial [m] (the journal-orbit plot's circle)
  /// Whether the run's skirt and big end are lubricated: the curves of a film it has not
  /// (PlotCurve::film) are not drawn — "no data", not the ideal joint's zero line.
  bool skirt_film = true;
  bool big_end_film = true;
  std::vector<RunSample> samples;
  /// The clearance joints' motion between the output steps too (only the motion columns set;
  /// empty when the run has none): curves marked PlotCurve::from_motion draw these.
  std::vector<RunSample> motion;
};
/// The current samples of a run record as plot data.
PlotRun PlotRunOf(const RunRecord& run);

}  // namespace filmdyn::ui
