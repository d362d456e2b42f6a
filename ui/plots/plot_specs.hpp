#pragma once
/// @file The standard result plots (docs/gui.md): what each shows, in display units. Shared by the
/// live plot panel and the headless plots of `filmdyn run` / `sweep` (one code path).
#include <QList>
#include <QPointF>
#include <QString>
#include <functional>
#include <vector>

#include "ui/run/result_columns.hpp"

namespace filmdyn::ui {

/// A curve's points (display units) and the crank angle [°CA] of each point.
struct CurvePoints {
  QList<QPointF> xy;
  std::vector<double> crank_angle;
  /// The index of the first point not joined to the one before it (a run that has not yet
  /// computed the crank angles between them); -1 when the curve is one line.
  qsizetype after_gap = -1;
};

/// The film a quantity belongs to: a run whose joint there is ideal has no such quantity (the
/// piston's secondary motion and the skirt's friction without a skirt film, the journal's orbit
/// without a big-end film: their columns hold the ideal joint's zeros).
enum class FilmOf { kNone, kSkirt, kBigEnd };

/// One kind of series of a plot (e.g. "skirt" or "big end" in the MOFT plot). Every run draws
/// each kind with the kind's line style; colours tell runs apart.
struct PlotCurve {
  QString name;
  /// The curve's points from a run's samples (NaN values are skipped).
  std::function<CurvePoints(const std::vector<RunSample>&)> points;
  /// Drawn from the run's motion samples (PlotRun::motion: the output steps and the
  /// integrator's interpolation between them) when it has them, else from its output samples.
  bool from_motion = false;
  /// Drawn only for runs with this film (PlotRun::skirt_film / big_end_film); kNone: for all.
  FilmOf film = FilmOf::kNone;
};

struct PlotSpec {
  QString id;  ///< file-name friendly, e.g. "journal_orbit"
  QString title;
  QString x_title;  ///< quantity and unit, e.g. "crank angle [°CA]"
  QString y_title;
  QString y_unit;  ///< display unit of the values (cursor readout), e.g. "µm"
  QString x_unit;
  bool crank_angle_axis = true;   ///< x is 0–720 °CA (the linked crank-angle cursor)
  bool equal_axes = false;        ///< same scale on x and y, centred on the origin
  bool clearance_circle = false;  ///< the journal orbit: the bearing clearance drawn, axes fit it
  bool non_negative = false;      ///< the quantity cannot be negative: the y axis starts at 0
  bool x_non_negative = false;    ///< same for x (phase portraits of ε)
  std::vector<PlotCurve> curves;
};

/// The plots in display order.
const std::vector<PlotSpec>& StandardPlots();

}  // namespace filmdyn::ui
