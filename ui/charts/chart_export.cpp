#include "ui/charts/chart_export.hpp"

#include <QChart>
#include <QChartView>
#include <QFileInfo>
#include <QGraphicsScene>
#include <QGraphicsSimpleTextItem>
#include <QImage>
#include <QPainter>
#include <QPdfWriter>
#include <QSaveFile>
#include <QSvgGenerator>
#include <algorithm>
#include <cmath>
#include <functional>

namespace filmdyn::ui {

bool FormatFromSuffix(const QString& path, ImageFormat* format) {
  const QString suffix = QFileInfo(path).suffix().toLower();
  if (suffix == "png")
    *format = ImageFormat::kPng;
  else if (suffix == "svg")
    *format = ImageFormat::kSvg;
  else if (suffix == "pdf")
    *format = ImageFormat::kPdf;
  else
    return false;
  return true;
}

namespace {

// Renders through a temporary QChartView so the chart lays out exactly as on screen; the chart
// is handed back to its previous owner afterwards.
class ScopedChartView {
 public:
  ScopedChartView(QChart* chart, const QSize& size) : chart_(chart) {
    view_.setRenderHint(QPainter::Antialiasing);
    view_.setChart(chart);
    view_.resize(size);
    chart->resize(size);
  }
  ~ScopedChartView() {
    // setChart() took ownership; give it back without deleting it.
    view_.scene()->removeItem(chart_);
  }
  void Render(QPainter* painter, const QRectF& target) {
    view_.scene()->render(painter, target, QRectF(QPointF(0, 0), chart_->size()));
  }

 private:
  QChart* chart_;
  QChartView view_;
};

bool Fail(QString* error, const QString& message) {
  if (error) *error = message;
  return false;
}

// Writes what `paint` draws on a canvas of `size` (logical pixels) to `path` in `format`,
// through QSaveFile: written under a temporary name, renamed into place only when complete
// (commit), so a failed or interrupted export never leaves a cut file. PNG at `png_scale`,
// without an alpha channel when `opaque` (a quarter less to compress).
bool WritePicture(const std::function<void(QPainter*)>& paint, const QString& path,
                  ImageFormat format, const QSize& size, const QString& title, qreal png_scale,
                  bool opaque = false) {
  // Paints on a vector device (SVG, PDF); false when the painter cannot start.
  auto paint_vector = [&paint](QPaintDevice* device) {
    QPainter painter;
    if (!painter.begin(device)) return false;
    paint(&painter);
    return painter.end();
  };
  QSaveFile file(path);
  bool ok = file.open(QIODevice::WriteOnly);
  switch (format) {
    case ImageFormat::kPng: {
      QImage image(size * png_scale,
                   opaque ? QImage::Format_RGB32 : QImage::Format_ARGB32_Premultiplied);
      image.setDevicePixelRatio(png_scale);
      image.fill(Qt::white);
      QPainter painter(&image);
      painter.setRenderHint(QPainter::Antialiasing);
      paint(&painter);
      painter.end();
      ok = ok && image.save(&file, "PNG");
      break;
    }
    case ImageFormat::kSvg: {
      QSvgGenerator generator;
      generator.setOutputDevice(&file);
      generator.setSize(size);
      generator.setViewBox(QRect(QPoint(0, 0), size));
      generator.setTitle(title);
      ok = ok && paint_vector(&generator);
      break;
    }
    case ImageFormat::kPdf: {
      QPdfWriter writer(&file);
      writer.setPageSize(QPageSize(QSizeF(size), QPageSize::Point));
      writer.setPageMargins(QMarginsF(0, 0, 0, 0));
      writer.setResolution(72);
      writer.setTitle(title);
      ok = ok && paint_vector(&writer);
      break;
    }
  }
  return ok && file.commit();
}

}  // namespace

bool ExportChart(QChart* chart, const QString& path, ImageFormat format, const QSize& size,
                 QString* error) {
  if (chart == nullptr) return Fail(error, "no chart to export");
  // A chart shown in a view is borrowed and put back with its on-screen geometry.
  QGraphicsScene* old_scene = chart->scene();
  const QRectF old_geometry = chart->geometry();
  if (old_scene != nullptr) old_scene->removeItem(chart);
  bool ok = true;
  {
    ScopedChartView view(chart, size);
    ok = WritePicture(
        [&view, &size](QPainter* painter) { view.Render(painter, QRectF(QPointF(0, 0), size)); },
        path, format, size, chart->title(), 2.0);
  }
  if (old_scene != nullptr) {
    old_scene->addItem(chart);
    chart->setGeometry(old_geometry);
  }
  if (!ok || !QFileInfo(path).exists() || QFileInfo(path).size() == 0) {
    return Fail(error, "cannot write " + path);
  }
  return true;
}

bool ExportChartGrid(const std::vector<QChart*>& charts, int columns, const QString& path,
                     ImageFormat format, const QSize& cell, const QString& heading,
                     QString* error) {
  if (charts.empty() || columns < 1) return Fail(error, "no chart to export");
  const int rows = int((charts.size() + std::size_t(columns) - 1) / std::size_t(columns));
  const int used_columns = std::min<int>(columns, int(charts.size()));
  QGraphicsScene scene;
  int top = 0;
  if (!heading.isEmpty()) {
    auto* text = new QGraphicsSimpleTextItem(heading);  // the scene owns it
    QFont font = charts.front() ? charts.front()->titleFont() : text->font();
    font.setBold(true);
    font.setPointSizeF(font.pointSizeF() * 1.15);
    text->setFont(font);
    text->setPos(12, 8);
    scene.addItem(text);
    top = int(std::ceil(text->boundingRect().height())) + 16;
  }
  const QSize size(used_columns * cell.width(), top + rows * cell.height());
  // Each chart is borrowed from its scene (a view's) and put back with its geometry afterwards.
  struct Borrowed {
    QChart* chart;
    QGraphicsScene* scene;
    QRectF geometry;
  };
  std::vector<Borrowed> borrowed;
  for (std::size_t k = 0; k < charts.size(); ++k) {
    QChart* chart = charts[k];
    if (chart == nullptr) continue;
    borrowed.push_back({chart, chart->scene(), chart->geometry()});
    if (chart->scene() != nullptr) chart->scene()->removeItem(chart);
    scene.addItem(chart);
    const int row = int(k) / columns, column = int(k) % columns;
    chart->setGeometry(
        QRectF(QPointF(column * cell.width(), top + row * cell.height()), QSizeF(cell)));
  }
  scene.setSceneRect(QRectF(QPointF(0, 0), QSizeF(size)));
  // A picture of more than 50 million pixels at 2x (a scatter matrix of many factors and
  // figures) is written at 1x: 200 MB of image memory is enough.
  const qreal scale = 4.0 * size.width() * size.height() > 50e6 ? 1.0 : 2.0;
  const bool ok = WritePicture(
      [&scene, &size](QPainter* painter) {
        painter->fillRect(QRectF(QPointF(0, 0), QSizeF(size)), Qt::white);
        scene.render(painter, QRectF(QPointF(0, 0), QSizeF(size)), scene.sceneRect());
      },
      path, format, size, heading, scale, /*opaque=*/true);
  for (const Borrowed& b : borrowed) {
    scene.removeItem(b.chart);
    if (b.scene != nullptr) {
      b.scene->addItem(b.chart);
      b.chart->setGeometry(b.geometry);
    }
  }
  if (!ok || !QFileInfo(path).exists() || QFileInfo(path).size() == 0) {
    return Fail(error, "cannot write " + path);
  }
  return true;
}

}  // namespace filmdyn::ui
