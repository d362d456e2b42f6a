// The pressure-field view under a real X server (xvfb-run): skirt and bearing surfaces built from
// FieldFrames render a non-blank, colour-mapped image; the crank-angle slider and play/pause
// change the frame and move the plot cursor.
// The frames here are SYNTHETIC test data (analytic pressure bumps), never shown to users.
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <QComboBox>
#include <QImage>
#include <QSet>
#include <QSlider>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <memory>

#include "ui/fields/field_frames.hpp"
#include "ui/fields/field_view.hpp"
#include "ui/plots/plot_panel.hpp"
#include "ui/vtk/scalar_field_view.hpp"
#include "ui/vtk/vtk_view_widget.hpp"

namespace {

// A cylindrical surface (angle span × width) triangulated on a grid.
filmdyn::io::SurfaceField Surface(double radius, double span, double width, int n_angle,
                                  int n_axial) {
  filmdyn::io::SurfaceField f;
  for (int j = 0; j < n_axial; ++j) {
    for (int i = 0; i < n_angle; ++i) {
      const double a = span * i / (n_angle - 1), z = width * j / (n_axial - 1);
      f.points.push_back({radius * std::cos(a), radius * std::sin(a), z});
    }
  }
  for (int j = 0; j + 1 < n_axial; ++j) {
    for (int i = 0; i + 1 < n_angle; ++i) {
      const int a = j * n_angle + i;
      f.triangles.push_back({a, a + 1, a + n_angle + 1});
      f.triangles.push_back({a, a + n_angle + 1, a + n_angle});
    }
  }
  return f;
}

// A pressure bump at `bump` (fraction of the span), a contact pressure and a film thickness.
std::vector<std::pair<std::string, std::vector<double>>> Arrays(double span, double width,
                                                                int n_angle, int n_axial,
                                                                double bump) {
  std::vector<double> p, pc, h;
  for (int j = 0; j < n_axial; ++j) {
    for (int i = 0; i < n_angle; ++i) {
      const double a = span * i / (n_angle - 1), z = width * j / (n_axial - 1);
      const double s = a / span - bump;
      const double axial = std::sin(M_PI * z / width);
      p.push_back(20e6 * std::exp(-30 * s * s) * axial);
      pc.push_back(1e6 * std::exp(-200 * s * s) * axial);
      h.push_back(5e-6 + 20e-6 * s * s);
    }
  }
  return {{"pressure", p}, {"contact_pressure", pc}, {"film_thickness", h}};
}

std::shared_ptr<filmdyn::ui::FieldFrames> SyntheticFrames(int count) {
  auto frames = std::make_shared<filmdyn::ui::FieldFrames>();
  filmdyn::ui::JointFieldFrames skirt, bearing;
  skirt.name = "skirt";
  bearing.name = "big_end";
  skirt.mesh = Surface(36.5e-3, M_PI, 28e-3, 40, 16);
  bearing.mesh = Surface(15e-3, 2 * M_PI, 22e-3, 60, 12);
  for (int k = 0; k < count; ++k) {
    frames->crank_angle_deg.push_back(720.0 * k / count);
    frames->time.push_back(1e-4 * k);
    const double bump = 0.2 + 0.6 * k / std::max(1, count - 1);
    skirt.frames.push_back(Arrays(M_PI, 28e-3, 40, 16, bump));
    bearing.frames.push_back(Arrays(2 * M_PI, 22e-3, 60, 12, bump));
  }
  frames->joints = {skirt, bearing};
  return frames;
}

int DistinctColours(const QImage& image) {
  QSet<QRgb> colours;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) colours.insert(image.pixel(x, y) | 0xff000000u);
  }
  return int(colours.size());
}

}  // namespace

class TestFieldView : public QObject {
  Q_OBJECT
 private slots:
  void rendersBothJointsAndFollowsTheSlider() {
    filmdyn::ui::FieldView view;
    filmdyn::ui::PlotPanel plots;
    QObject::connect(&view, &filmdyn::ui::FieldView::crankAngleChanged, &plots,
                     &filmdyn::ui::PlotPanel::setCursorAngle);
    view.resize(900, 480);
    view.setFrames(SyntheticFrames(12), "test");
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    filmdyn::ui::ScalarFieldView* skirt = view.jointView(0);
    filmdyn::ui::ScalarFieldView* bearing = view.jointView(1);
    QVERIFY(skirt != nullptr && bearing != nullptr);
    QTRY_VERIFY_WITH_TIMEOUT(skirt->renderedFrames() > 0 && bearing->renderedFrames() > 0, 10000);
    const QImage first = skirt->grabFramebuffer();
    if (qEnvironmentVariableIsSet("FILMDYN_TEST_SAVE_IMAGES")) first.save("field_view_skirt.png");
    const int colours = DistinctColours(first);
    qInfo("skirt view: %d distinct colours", colours);
    QVERIFY2(colours > 100, "blank render?");
    QVERIFY(DistinctColours(bearing->grabFramebuffer()) > 100);

    // Slider: new frame, new picture, cursor on the plots at that crank angle.
    QSignalSpy angle(&view, &filmdyn::ui::FieldView::crankAngleChanged);
    const int frames_before = skirt->renderedFrames();
    view.slider()->setValue(9);
    QCOMPARE(angle.count(), 1);
    QCOMPARE(angle.first().first().toDouble(), 540.0);
    QCOMPARE(plots.cursorAngle(), 540.0);
    QTRY_VERIFY_WITH_TIMEOUT(skirt->renderedFrames() > frames_before, 10000);
    QVERIFY(skirt->grabFramebuffer() != first);

    // A crank angle from a click on a plot selects the nearest frame.
    view.setCrankAngle(181.0);
    QCOMPARE(view.frameIndex(), 3);  // 12 frames, 60 °CA apart
    QCOMPARE(plots.cursorAngle(), 180.0);

    // Another array (film thickness) also renders.
    view.arraySelector()->setCurrentIndex(2);
    QTRY_VERIFY_WITH_TIMEOUT(DistinctColours(skirt->grabFramebuffer()) > 100, 10000);

    // Play advances the frames; pause stops.
    view.setPlaying(true);
    QVERIFY(view.isPlaying());
    QTRY_VERIFY_WITH_TIMEOUT(view.frameIndex() != 9, 5000);
    view.setPlaying(false);
    const int stopped = view.frameIndex();
    QTest::qWait(200);
    QCOMPARE(view.frameIndex(), stopped);
  }

  void withoutFieldsShowsWhy() {
    filmdyn::ui::FieldView view;
    view.setFrames(nullptr, "Ideal 6000 rpm");
    QVERIFY(view.jointView(0) == nullptr);
    QVERIFY(!view.slider()->isEnabled());
  }
};

int main(int argc, char** argv) {
  filmdyn::ui::VtkViewWidget::SetDefaultSurfaceFormat();
  QApplication app(argc, argv);
  TestFieldView test;
  return QTest::qExec(&test, argc, argv);
}
#include "test_field_view.moc"
