#pragma once
/// @file For the suites that check what the plots call a run: on screen the runs are listed once
/// above the plots, and each exported plot names them in its own legend.
#include <QString>

#include "ui/plots/plot_panel.hpp"

namespace filmdyn::test {

/// Whether the legend above the plots and some exported plot's own legend name `label`.
inline bool LegendsName(ui::PlotPanel& panel, const QString& label) {
  if (!panel.runLegendText().contains(label.toHtmlEscaped())) return false;
  panel.setRunsInChartLegends(true);
  bool found = false;
  for (int i = 0; i < panel.chartCount(); ++i) {
    for (const auto& [text, pen] : panel.legendEntries(i)) found = found || text == label;
  }
  panel.setRunsInChartLegends(false);
  return found;
}

}  // namespace filmdyn::test
