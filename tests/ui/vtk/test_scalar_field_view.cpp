// The VTK-in-Qt-6 bridge really draws: a coloured scalar field with a scalar bar is rendered in a
// real window (under xvfb-run) and the grabbed framebuffer is checked by pixel statistics. The
// colours are the application's viridis, unlit; the bar sits in its own strip beside the surface
// with round numbers; scene labels and the arrow are drawn.
#include <vtkActor.h>
#include <vtkDoubleArray.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>
#include <vtkStructuredGrid.h>

#include <QImage>
#include <QSet>
#include <QtTest>
#include <cmath>

#include "ui/charts/color_map.hpp"
#include "ui/vtk/scalar_field_view.hpp"

namespace {

// A half cylinder (like a skirt panel) with a pressure-like bump: values 0 .. 1.
vtkSmartPointer<vtkStructuredGrid> MakeField(double peak_position) {
  const int n_theta = 40, n_z = 20;
  auto grid = vtkSmartPointer<vtkStructuredGrid>::New();
  grid->SetDimensions(n_theta, n_z, 1);
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> pressure;
  pressure->SetName("pressure");
  for (int k = 0; k < n_z; ++k) {
    for (int i = 0; i < n_theta; ++i) {
      const double theta = M_PI * i / (n_theta - 1);
      const double z = 1.5 * k / (n_z - 1);
      points->InsertNextPoint(std::cos(theta), std::sin(theta), z);
      const double s = theta / M_PI - peak_position;
      pressure->InsertNextValue(std::exp(-20.0 * s * s) * std::sin(M_PI * z / 1.5));
    }
  }
  grid->SetPoints(points);
  grid->GetPointData()->AddArray(pressure);
  return grid;
}

struct PixelStats {
  int distinct_colours = 0;
  double non_background_fraction = 0.0;
  int dark_violet = 0;  ///< viridis' low end
  int yellow = 0;       ///< viridis' high end
  int reddish = 0;      ///< the old rainbow's high end: none in viridis
};

PixelStats Analyse(const QImage& image, QRgb background) {
  PixelStats stats;
  QSet<QRgb> colours;
  int non_background = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const QRgb c = image.pixel(x, y) | 0xff000000u;
      colours.insert(c);
      const int dr = std::abs(qRed(c) - qRed(background));
      const int dg = std::abs(qGreen(c) - qGreen(background));
      const int db = std::abs(qBlue(c) - qBlue(background));
      if (dr + dg + db > 30) ++non_background;
      if (qRed(c) > 180 && qGreen(c) < 90 && qBlue(c) < 90) ++stats.reddish;
      if (qRed(c) < 90 && qGreen(c) < 40 && qBlue(c) > 70 && qBlue(c) < 130) ++stats.dark_violet;
      if (qRed(c) > 200 && qGreen(c) > 200 && qBlue(c) < 80) ++stats.yellow;
    }
  }
  stats.distinct_colours = colours.size();
  stats.non_background_fraction = double(non_background) / (image.width() * image.height());
  return stats;
}

}  // namespace

class TestScalarFieldView : public QObject {
  Q_OBJECT
 private slots:
  void rendersColouredFieldWithScalarBar() {
    filmdyn::ui::ScalarFieldView view;
    view.resize(640, 480);
    auto grid = MakeField(0.3);
    view.showField(grid, "pressure", "p [MPa]");
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    QTRY_VERIFY_WITH_TIMEOUT(view.renderedFrames() > 0, 10000);
    QVERIFY(view.scalarBar()->GetVisibility());

    const QImage image = view.grabFramebuffer();
    QVERIFY(!image.isNull());
    if (qEnvironmentVariableIsSet("FILMDYN_TEST_SAVE_IMAGES")) image.save("scalar_field_view.png");
    QCOMPARE(image.width(), int(640 * view.devicePixelRatioF()));
    // Background colour of the renderer (0.13, 0.14, 0.16).
    const QRgb background = qRgb(33, 36, 41);
    const PixelStats stats = Analyse(image, background);
    qInfo("distinct colours %d, covered %.3f, violet %d, yellow %d, red %d", stats.distinct_colours,
          stats.non_background_fraction, stats.dark_violet, stats.yellow, stats.reddish);
    // A blank or black frame has 1-2 colours; the shaded colour map plus bar has hundreds.
    QVERIFY2(stats.distinct_colours > 100, "image has too few colours: blank render?");
    QVERIFY2(stats.non_background_fraction > 0.10, "almost nothing drawn");
    QVERIFY2(stats.non_background_fraction < 0.95, "the whole frame is one colour block");
    // Both ends of viridis appear (field and scalar bar), no red.
    QVERIFY(stats.dark_violet > 200);
    QVERIFY(stats.yellow > 100);
    QCOMPARE(stats.reddish, 0);
    // The lookup table is ui::Viridis, sampled; the surface unlit.
    for (int i = 0; i < 256; i += 15) {
      double rgba[4];
      view.lookupTable()->GetTableValue(i, rgba);
      const QColor c = filmdyn::ui::Viridis(i / 255.0);
      QCOMPARE(int(std::lround(rgba[0] * 255)), c.red());
      QCOMPARE(int(std::lround(rgba[1] * 255)), c.green());
      QCOMPARE(int(std::lround(rgba[2] * 255)), c.blue());
    }
    QVERIFY(!view.surfaceActor()->GetProperty()->GetLighting());
    // The bar's strip lies beside the surface's viewport, not over it.
    const double* surface = view.renderer()->GetViewport();
    const double* bar = view.scalarBarRenderer()->GetViewport();
    QVERIFY(surface[2] <= bar[0] && bar[2] <= 1.0);
    QVERIFY(bar[2] - bar[0] > 0.05 && bar[2] - bar[0] < 0.3);
  }

  void barNumbersAreRoundAndLabelsDrawn() {
    filmdyn::ui::ScalarFieldView view;
    view.resize(500, 400);
    // An odd range: the bar widens it to round ends and writes round ticks.
    view.setScalarRange(0.0, 79.3);
    view.showField(MakeField(0.5), "pressure", "MPa");
    QCOMPARE(view.scalarRange()[0], 0.0);
    QCOMPARE(view.scalarRange()[1], 80.0);
    const std::vector<double> expected = {0, 20, 40, 60, 80};
    QCOMPARE(view.barLabels(), expected);
    view.setScalarRange(0.0, 5.44);
    QCOMPARE(view.scalarRange()[1], 6.0);
    QCOMPARE(view.barLabels().front(), 0.0);
    QCOMPARE(view.barLabels().back(), 6.0);
    for (double t : view.barLabels()) QCOMPARE(t, std::round(t));  // whole numbers
    // Labels in the scene and the arrow change the picture.
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    QTRY_VERIFY_WITH_TIMEOUT(view.renderedFrames() > 0, 10000);
    const QImage plain = view.grabFramebuffer();
    view.setLabels({{"thrust side", {1.2, 0.0, 0.75}}});
    view.showArrow({0, 0, 0.75}, {0, 1.3, 0.75}, "load 20.0 kN");
    const int frames = view.renderedFrames();
    QTRY_VERIFY_WITH_TIMEOUT(view.renderedFrames() > frames, 10000);
    const QImage with_arrow = view.grabFramebuffer();
    QVERIFY(with_arrow != plain);
    QCOMPARE(view.labelTexts(), (std::vector<QString>{"thrust side", "load 20.0 kN"}));
    // The load's label keeps off its arrow (it sat on the shaft): the box of its dark red
    // background and the box of the arrow's bright red pixels do not meet.
    QRect arrow_box, label_box;
    for (int y = 0; y < with_arrow.height(); ++y) {
      for (int x = 0; x < with_arrow.width(); ++x) {
        const QColor c = with_arrow.pixelColor(x, y);
        if (c.red() > 200 && c.green() < 140 && c.blue() < 120) arrow_box |= QRect(x, y, 1, 1);
        if (c.red() > 60 && c.red() < 120 && c.green() < 45 && c.blue() < 45)
          label_box |= QRect(x, y, 1, 1);
      }
    }
    QVERIFY(!arrow_box.isEmpty() && !label_box.isEmpty());
    QVERIFY2(!arrow_box.intersects(label_box),
             qPrintable(QString("arrow %1,%2 %3x%4, label %5,%6 %7x%8")
                            .arg(arrow_box.x())
                            .arg(arrow_box.y())
                            .arg(arrow_box.width())
                            .arg(arrow_box.height())
                            .arg(label_box.x())
                            .arg(label_box.y())
                            .arg(label_box.width())
                            .arg(label_box.height())));
    view.hideArrow();
    QCOMPARE(view.labelTexts(), (std::vector<QString>{"thrust side"}));
  }

  void updatingTheFieldChangesThePicture() {
    filmdyn::ui::ScalarFieldView view;
    view.resize(400, 300);
    view.setScalarRange(0.0, 1.0);
    view.showField(MakeField(0.15), "pressure", "p");
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    QTRY_VERIFY_WITH_TIMEOUT(view.renderedFrames() > 0, 10000);
    const QImage first = view.grabFramebuffer();
    const int frames = view.renderedFrames();
    view.showField(MakeField(0.85), "pressure", "p");
    QTRY_VERIFY_WITH_TIMEOUT(view.renderedFrames() > frames, 10000);
    const QImage second = view.grabFramebuffer();
    QVERIFY(first != second);
  }
};

QTEST_MAIN(TestScalarFieldView)
#include "test_scalar_field_view.moc"
