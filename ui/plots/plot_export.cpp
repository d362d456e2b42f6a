#include "ui/plots/plot_export.hpp"

#include <QChart>
#include <QDir>

#include "ui/charts/chart_export.hpp"
#include "ui/plots/plot_panel.hpp"
#include "ui/plots/plot_specs.hpp"
#include "ui/run/sample_conversion.hpp"

namespace filmdyn::ui {

PlotRun PlotRunFromRows(int id, const engine::EngineCase& engine_case, const std::string& model,
                        double rpm, const std::vector<io::OutputRow>& rows,
                        const std::vector<io::OutputRow>& motion_rows) {
  const engine::Model parsed = engine::ParseModel(model);
  return {id,
          RunLabel(QString::fromStdString(model), rpm),
          engine::BigEndFit(engine_case).hot_clearance,
          engine::SkirtLubricated(parsed),
          engine::BigEndLubricated(parsed),
          RunSamplesFromRows(rows),
          RunSamplesFromRows(motion_rows)};
}

QStringList ExportStandardPlots(const std::vector<PlotRun>& runs, const QString& directory,
                                QString* error) {
  QStringList written;
  if (!QDir().mkpath(directory)) {
    if (error) *error = "cannot create " + directory;
    return written;
  }
  PlotPanel panel;  // never shown: the same charts as on screen, laid out at export size
  panel.setRunsInChartLegends(true);  // each file stands alone: its legend names the runs
  for (const auto& run : runs) panel.updateRun(run);
  for (int i = 0; i < panel.chartCount(); ++i) {
    // Equal-scale plots (the journal orbit in its clearance circle) are exported square.
    QSize size(960, 600);
    for (const PlotSpec& spec : StandardPlots()) {
      if (spec.id == panel.chartId(i) && spec.equal_axes) size = QSize(820, 640);
    }
    for (const auto& [suffix, format] : {std::pair{QString("png"), ImageFormat::kPng},
                                         std::pair{QString("svg"), ImageFormat::kSvg}}) {
      const QString path = QDir(directory).filePath(panel.chartId(i) + "." + suffix);
      if (!panel.exportChart(i, path, format, size, error)) return written;
      written << path;
    }
  }
  return written;
}

}  // namespace filmdyn::ui
