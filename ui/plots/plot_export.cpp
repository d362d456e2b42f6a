#include "ui/plots/plot_export.hpp"

#include <QChart>
#include <QDir>

#include "ui/charts/chart_export.hpp"
#include "ui/plots/plot_panel.hpp"

namespace filmdyn::ui {

RunHandle FinishedRun(int id, RunRequest request, std::vector<RunSample> samples) {
  auto run = std::make_shared<RunRecord>(id, std::move(request));
  run->Report(std::move(samples));
  run->finish(RunStatus::kFinished, QString());
  return run;
}

QStringList ExportStandardPlots(const std::vector<RunHandle>& runs, const QString& directory,
                                QString* error) {
  QStringList written;
  if (!QDir().mkpath(directory)) {
    if (error) *error = "cannot create " + directory;
    return written;
  }
  PlotPanel panel;  // never shown: the same charts as on screen, laid out at export size
  for (const auto& run : runs) panel.updateRun(run);
  for (int i = 0; i < panel.chartCount(); ++i) {
    for (const auto& [suffix, format] : {std::pair{QString("png"), ImageFormat::kPng},
                                         std::pair{QString("svg"), ImageFormat::kSvg}}) {
      const QString path = QDir(directory).filePath(panel.chartId(i) + "." + suffix);
      if (!ExportChart(panel.chart(i), path, format, QSize(960, 600), error)) return written;
      written << path;
    }
  }
  return written;
}

}  // namespace filmdyn::ui
