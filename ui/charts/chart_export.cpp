#include "ui/charts/chart_export.hpp"

#include <QChart>
#include <QChartView>
#include <QFileInfo>
#include <QImage>
#include <QPainter>
#include <QPdfWriter>
#include <QSaveFile>
#include <QSvgGenerator>

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
    // Paints the chart on a vector device (SVG, PDF); false when the painter cannot start.
    auto paint = [&view, &size](QPaintDevice* device) {
      QPainter painter;
      if (!painter.begin(device)) return false;
      view.Render(&painter, QRectF(QPointF(0, 0), size));
      return painter.end();
    };
    // Every format through QSaveFile: written under a temporary name, renamed into place only
    // when complete (commit), so a failed or interrupted export never leaves a cut file.
    QSaveFile file(path);
    ok = file.open(QIODevice::WriteOnly);
    switch (format) {
      case ImageFormat::kPng: {
        const qreal scale = 2.0;
        QImage image(size * scale, QImage::Format_ARGB32_Premultiplied);
        image.setDevicePixelRatio(scale);
        image.fill(Qt::white);
        QPainter painter(&image);
        painter.setRenderHint(QPainter::Antialiasing);
        view.Render(&painter, QRectF(QPointF(0, 0), size));
        painter.end();
        ok = ok && image.save(&file, "PNG");
        break;
      }
      case ImageFormat::kSvg: {
        QSvgGenerator generator;
        generator.setOutputDevice(&file);
        generator.setSize(size);
        generator.setViewBox(QRect(QPoint(0, 0), size));
        generator.setTitle(chart->title());
        ok = ok && paint(&generator);
        break;
      }
      case ImageFormat::kPdf: {
        QPdfWriter writer(&file);
        writer.setPageSize(QPageSize(QSizeF(size), QPageSize::Point));
        writer.setPageMargins(QMarginsF(0, 0, 0, 0));
        writer.setResolution(72);
        writer.setTitle(chart->title());
        ok = ok && paint(&writer);
        break;
      }
    }
    ok = ok && file.commit();
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

}  // namespace filmdyn::ui
