#include "ui/plots/skirt_map_chart.hpp"

#include <QChart>
#include <QDir>
#include <QLineSeries>
#include <QValueAxis>
#include <algorithm>

#include "core/io/skirt_report.hpp"
#include "ui/charts/chart_export.hpp"

namespace filmdyn::ui {

namespace {

const io::SkirtQuantity& Quantity(const std::string& key) {
  for (const io::SkirtQuantity& q : io::SkirtQuantities()) {
    if (q.key == key) return q;
  }
  return io::SkirtQuantities().front();
}

QString AxisTitle(const io::SkirtQuantity& q) {
  return QString::fromStdString(q.label + " [" + q.display_unit + "]");
}

}  // namespace

const std::vector<std::string>& SkirtMapQuantities() {
  static const std::vector<std::string> keys = {"normal_force", "moment_about_pin", "moft"};
  return keys;
}

std::unique_ptr<QChart> MakeSkirtMapChart(const std::vector<lubrication::SkirtPoint>& points,
                                          const std::string& key) {
  const io::SkirtQuantity& e0 = Quantity("e0");
  const io::SkirtQuantity& tilt = Quantity("tilt");
  const io::SkirtQuantity& q = Quantity(key);
  auto chart = std::make_unique<QChart>();
  const double speed = points.empty() ? 0.0 : points.front().state.piston_velocity;
  chart->setTitle(QString("Skirt at %1 m/s in steady sliding: %2 against e0 (e0 > 0 toward thrust)")
                      .arg(speed, 0, 'g', 4)
                      .arg(QString::fromStdString(q.label)));
  auto* x_axis = new QValueAxis;
  auto* y_axis = new QValueAxis;
  x_axis->setTitleText(AxisTitle(e0));
  y_axis->setTitleText(AxisTitle(q));
  x_axis->setLabelFormat("%g");
  y_axis->setLabelFormat("%g");
  chart->addAxis(x_axis, Qt::AlignBottom);
  chart->addAxis(y_axis, Qt::AlignLeft);
  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  QLineSeries* series = nullptr;
  double series_tilt = 0.0;
  for (const lubrication::SkirtPoint& p : points) {
    if (series == nullptr || p.state.gamma != series_tilt) {
      series = new QLineSeries;
      series_tilt = p.state.gamma;
      series->setName(QString("tilt %1 %2")
                          .arg(series_tilt * tilt.display_scale, 0, 'g', 4)
                          .arg(QString::fromStdString(tilt.display_unit)));
      chart->addSeries(series);
      series->attachAxis(x_axis);
      series->attachAxis(y_axis);
    }
    const double x = e0.value(p) * e0.display_scale, y = q.value(p) * q.display_scale;
    series->append(x, y);
    xmin = std::min(xmin, x), xmax = std::max(xmax, x);
    ymin = std::min(ymin, y), ymax = std::max(ymax, y);
  }
  if (key == "moft") ymin = 0.0;  // a thickness: from zero
  if (!points.empty()) {
    x_axis->setRange(xmin, xmax);
    y_axis->setRange(ymin, ymax > ymin ? ymax : ymin + 1.0);
    x_axis->applyNiceNumbers();
    y_axis->applyNiceNumbers();
  }
  chart->legend()->setAlignment(Qt::AlignRight);
  chart->legend()->setVisible(chart->series().size() > 1);
  return chart;
}

QStringList ExportSkirtMapPlots(const std::vector<lubrication::SkirtPoint>& points,
                                const QString& directory, QString* error) {
  QStringList written;
  if (!QDir().mkpath(directory)) {
    if (error) *error = "cannot create " + directory;
    return written;
  }
  for (const std::string& key : SkirtMapQuantities()) {
    const std::unique_ptr<QChart> chart = MakeSkirtMapChart(points, key);
    for (const auto& [suffix, format] : {std::pair{QString("png"), ImageFormat::kPng},
                                         std::pair{QString("svg"), ImageFormat::kSvg}}) {
      const QString path =
          QDir(directory).filePath("skirt_map_" + QString::fromStdString(key) + "." + suffix);
      if (!ExportChart(chart.get(), path, format, QSize(960, 600), error)) return written;
      written << path;
    }
  }
  return written;
}

}  // namespace filmdyn::ui
