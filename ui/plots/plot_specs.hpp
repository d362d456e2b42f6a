#pragma once
/// @file The standard result plots (docs/gui.md): what each shows, in display units. Shared by the
/// live plot panel and anything that draws the same plots from a finished run.
#include <QList>
#include <QPointF>
#include <QString>
#include <functional>
#include <vector>

#include "ui/run/result_columns.hpp"

namespace filmdyn::ui {

struct PlotCurve {
  QString name;
  /// The curve's points from a run's samples (NaN values are skipped).
  std::function<QList<QPointF>(const std::vector<RunSample>&)> points;
};

struct PlotSpec {
  QString id;  ///< file-name friendly, e.g. "journal_orbit"
  QString title;
  QString x_title;
  QString y_title;
  bool crank_angle_axis = true;  ///< x is 0–720 °CA (shows the field-view cursor)
  bool equal_axes = false;       ///< orbit: same scale on x and y
  std::vector<PlotCurve> curves;
};

/// The plots in display order.
const std::vector<PlotSpec>& StandardPlots();

}  // namespace filmdyn::ui
