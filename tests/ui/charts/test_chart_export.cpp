// Chart export on the `offscreen` platform (no X server): PNG, SVG and PDF files are written,
// are valid, and the PNG actually shows the curve.
#include <QChart>
#include <QChartView>
#include <QFile>
#include <QImage>
#include <QLineSeries>
#include <QTemporaryDir>
#include <QValueAxis>
#include <QXmlStreamReader>
#include <QtTest>
#include <cmath>

#include "ui/charts/chart_export.hpp"

namespace {

QChart* MakeChart() {
  auto* chart = new QChart;
  auto* series = new QLineSeries;
  series->setName("piston_lateral");
  series->setPen(QPen(QColor(220, 30, 30), 3));
  for (int i = 0; i <= 720; i += 2) series->append(i, std::sin(i * M_PI / 180.0));
  chart->addSeries(series);
  chart->createDefaultAxes();
  chart->setTitle("e0 over the cycle");
  return chart;
}

int CountRedPixels(const QImage& image) {
  int red = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const QRgb c = image.pixel(x, y);
      if (qRed(c) > 180 && qGreen(c) < 100 && qBlue(c) < 100) ++red;
    }
  }
  return red;
}

}  // namespace

class TestChartExport : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { QCOMPARE(QGuiApplication::platformName(), QString("offscreen")); }

  void exportsPngWithTheCurve() {
    QTemporaryDir dir;
    std::unique_ptr<QChart> chart(MakeChart());
    const QString path = dir.filePath("plot.png");
    QString error;
    QVERIFY2(filmdyn::ui::ExportChart(chart.get(), path, filmdyn::ui::ImageFormat::kPng,
                                      QSize(800, 500), &error),
             qPrintable(error));
    QImage image(path);
    QVERIFY(!image.isNull());
    QCOMPARE(image.size(), QSize(1600, 1000));
    QVERIFY2(CountRedPixels(image) > 2000, "the red curve is not in the picture");
  }

  void exportsValidSvg() {
    QTemporaryDir dir;
    std::unique_ptr<QChart> chart(MakeChart());
    const QString path = dir.filePath("plot.svg");
    QVERIFY(filmdyn::ui::ExportChart(chart.get(), path, filmdyn::ui::ImageFormat::kSvg));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QXmlStreamReader xml(&file);
    int paths = 0;
    bool saw_svg = false;
    while (!xml.atEnd()) {
      xml.readNext();
      if (xml.isStartElement() && xml.name() == QLatin1String("svg")) saw_svg = true;
      if (xml.isStartElement() &&
          (xml.name() == QLatin1String("path") || xml.name() == QLatin1String("polyline"))) {
        ++paths;
      }
    }
    QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
    QVERIFY(saw_svg);
    QVERIFY(paths > 3);
  }

  void exportsPdf() {
    QTemporaryDir dir;
    std::unique_ptr<QChart> chart(MakeChart());
    const QString path = dir.filePath("plot.pdf");
    QVERIFY(filmdyn::ui::ExportChart(chart.get(), path, filmdyn::ui::ImageFormat::kPdf));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray bytes = file.readAll();
    QVERIFY(bytes.startsWith("%PDF-"));
    QVERIFY(bytes.contains("%%EOF"));
    QVERIFY(bytes.size() > 2000);
  }

  void chartShownInAViewIsPutBack() {
    QTemporaryDir dir;
    QChartView view(MakeChart());
    view.resize(500, 300);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    const QRectF before = view.chart()->geometry();
    QVERIFY(filmdyn::ui::ExportChart(view.chart(), dir.filePath("x.png"),
                                     filmdyn::ui::ImageFormat::kPng, QSize(900, 600)));
    QCOMPARE(view.chart()->scene(), view.scene());
    QVERIFY(!before.isEmpty());
    QCOMPARE(view.chart()->geometry(), before);
  }

  void unwritablePathIsAnError() {
    std::unique_ptr<QChart> chart(MakeChart());
    QString error;
    QVERIFY(!filmdyn::ui::ExportChart(chart.get(), "/nonexistent-dir/x.png",
                                      filmdyn::ui::ImageFormat::kPng, QSize(100, 100), &error));
    QVERIFY(error.contains("/nonexistent-dir/x.png"));
  }

  void formatFromSuffix() {
    filmdyn::ui::ImageFormat format;
    QVERIFY(filmdyn::ui::FormatFromSuffix("a/b.PNG", &format));
    QCOMPARE(format, filmdyn::ui::ImageFormat::kPng);
    QVERIFY(filmdyn::ui::FormatFromSuffix("b.svg", &format));
    QCOMPARE(format, filmdyn::ui::ImageFormat::kSvg);
    QVERIFY(!filmdyn::ui::FormatFromSuffix("b.jpg", &format));
  }
};

QTEST_MAIN(TestChartExport)
#include "test_chart_export.moc"
