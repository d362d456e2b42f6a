// The pressure-field view under a real X server (xvfb-run): skirt and bearing surfaces built from
// FieldFrames render a non-blank, colour-mapped image; the crank-angle slider and play/pause
// change the frame and move the plot cursor. With the frames of a real short coupled run
// (core's run job through the GUI's field collector): the 3D views are viridis, unlit, their
// scalar bar beside the surface with round numbers, the sides named, the relief not drawn, the
// big end's load line along the crank pin's force; the unrolled map holds the nodal values, the
// crank-angle map the extremes along the axial lines; switching runs keeps the crank angle and
// "Same scale for all runs" gives them one colour range. With the frames of a real short
// Only-LBRBE run with mass-conserving (JFO) cavitation, collected live and read back from the
// fields/ files core writes, the view offers the fluid fraction θ on a fixed 0–1 scale; a joint
// solved with Reynolds cavitation says why it has none instead of showing its views.
// SyntheticFrames are analytic test data (pressure bumps), never shown to users.
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkLookupTable.h>
#include <vtkMapper.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QImage>
#include <QLabel>
#include <QSet>
#include <QSlider>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest>
#include <cmath>
#include <functional>
#include <memory>

#include "core/engine/run_job.hpp"
#include "core/io/case_file.hpp"
#include "core/io/field_output.hpp"
#include "ui/charts/color_map.hpp"
#include "ui/charts/film_map_widget.hpp"
#include "ui/fields/field_collector.hpp"
#include "ui/fields/field_frames.hpp"
#include "ui/fields/field_maps.hpp"
#include "ui/fields/field_view.hpp"
#include "ui/plots/plot_panel.hpp"
#include "ui/runs/run_store.hpp"
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
  for (int i = 0; i < 40; ++i) skirt.angle_lines.push_back(M_PI * i / 39);
  for (int j = 0; j < 16; ++j) skirt.axial_lines.push_back(28e-3 * j / 15);
  skirt.radius = 36.5e-3;
  for (int i = 0; i < 60; ++i) bearing.angle_lines.push_back(2 * M_PI * i / 59);
  for (int j = 0; j < 12; ++j) bearing.axial_lines.push_back(22e-3 * j / 11);
  bearing.radius = 15e-3;
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

// The frames of a real coupled run (default case, Skirt-LBRBE, 6000 rpm, 4 °CA output, one
// cycle after the run-in), collected as the GUI collects them.
std::shared_ptr<const filmdyn::ui::FieldFrames> RealRunFrames() {
  using namespace filmdyn;
  const io::LoadedCase loaded = io::LoadCase({});
  engine::EngineCase c = loaded.value;
  c.solver.output_interval = 4.0 * M_PI / 180.0;
  c.solver.max_cycles = 1;
  c.solver.error_estimate = 0;
  engine::ApplyModel(engine::Model::kSkirtLbrbe, &c);
  engine::RunConfig config = engine::MakeRunConfig(c, engine::Model::kSkirtLbrbe, 6000.0,
                                                   io::PressureCurveForSpeed(loaded, 6000.0));
  ui::FieldCollector collector(180);
  config.field_callback = [&collector](const engine::FieldFrame& f) { collector.Add(f); };
  const engine::RunResult result = engine::RunJob(config);
  qInfo("real run: %s, %zu samples, %.1f s", engine::StatusName(result.status).c_str(),
        result.samples.size(), result.wall_time);
  return collector.Result();
}

// One cycle of the big end alone (4 °CA output, after the run-in) of the default case adjusted by
// `adjust`: the frames as the GUI collects them live, and core's field files of the same run
// written to `fields_dir`; `used` the case as run. nullptr when the recorded frames are not the
// reported cycle's.
std::shared_ptr<const filmdyn::ui::FieldFrames> BigEndRunFrames(
    const QString& fields_dir, filmdyn::engine::EngineCase* used, double rpm,
    const std::function<void(filmdyn::engine::EngineCase&)>& adjust) {
  using namespace filmdyn;
  const io::LoadedCase loaded = io::LoadCase({});
  engine::EngineCase c = loaded.value;
  c.solver.output_interval = 4.0 * M_PI / 180.0;
  c.solver.max_cycles = 1;
  c.solver.error_estimate = 0;
  adjust(c);
  engine::ApplyModel(engine::Model::kOnlyLbrbe, &c);
  engine::RunConfig config = engine::MakeRunConfig(c, engine::Model::kOnlyLbrbe, rpm,
                                                   io::PressureCurveForSpeed(loaded, rpm));
  ui::FieldCollector collector(180);
  io::FieldRecorder recorder;
  config.field_callback = [&collector, record = recorder.Callback()](const engine::FieldFrame& f) {
    collector.Add(f);
    record(f);
  };
  const engine::RunResult result = engine::RunJob(config);
  qInfo("big-end run: %s, %zu samples, %.1f s", engine::StatusName(result.status).c_str(),
        result.samples.size(), result.wall_time);
  if (!recorder.Holds(result.samples)) return nullptr;  // not the reported cycle's frames
  recorder.Write(fields_dir.toStdString());
  *used = c;
  return collector.Result();
}

// One cycle of the big end alone on a coarse mesh at 6000 rpm, with JFO cavitation (or,
// `elastic`, with Reynolds cavitation and a soft elastic lining), live frames and core's files.
std::shared_ptr<const filmdyn::ui::FieldFrames> JfoRunFrames(const QString& fields_dir,
                                                             filmdyn::engine::EngineCase* used,
                                                             bool elastic = false) {
  using namespace filmdyn;
  return BigEndRunFrames(fields_dir, used, 6000.0, [elastic](engine::EngineCase& c) {
    c.big_end.mesh_theta = 48;
    c.big_end.mesh_z = 6;
    if (elastic) {
      c.big_end.compliance = lubrication::ComplianceModel::kElasticLayer;
      c.big_end.layer_thickness = 1e-3;
      c.big_end.modulus_bearing = 20e9;
    } else {
      c.big_end.cavitation = lubrication::CavitationModel::kJfo;
    }
  });
}

// A copy of a run's frames with every pressure multiplied by `factor` (a "second run").
std::shared_ptr<filmdyn::ui::FieldFrames> ScaledCopy(const filmdyn::ui::FieldFrames& frames,
                                                     double factor, double angle_shift) {
  auto copy = std::make_shared<filmdyn::ui::FieldFrames>(frames);
  for (double& a : copy->crank_angle_deg) a = std::fmod(a + angle_shift, 720.0);
  for (auto& joint : copy->joints) {
    for (auto& frame : joint.frames) {
      for (auto& [name, values] : frame) {
        if (name == "pressure")
          for (double& v : values) v *= factor;
      }
    }
  }
  return copy;
}

const filmdyn::ui::FieldArrayInfo& Array(const char* name) {
  for (const auto& info : filmdyn::ui::FieldArrays())
    if (std::string(info.name) == name) return info;
  qFatal("no array %s", name);
}

// The value of `name` at node (i, j) of frame k, in display units.
double NodeValue(const filmdyn::ui::JointFieldFrames& joint, size_t k, size_t i, size_t j,
                 const char* name) {
  for (const auto& [array, values] : joint.frames[k]) {
    if (array == name) return values[i + joint.angle_lines.size() * j] * Array(name).scale;
  }
  return NAN;
}

// Index of x in sorted lines (exact up to rounding), -1 when absent.
int LineIndex(const std::vector<double>& lines, double x) {
  for (size_t i = 0; i < lines.size(); ++i)
    if (std::abs(lines[i] - x) < 1e-9) return int(i);
  return -1;
}

// Round: a whole multiple of a step of 1, 2, 2.5 or 5 × 10ⁿ that the ticks share.
bool RoundNumbers(const std::vector<double>& ticks) {
  if (ticks.size() < 2) return false;
  const double step = ticks[1] - ticks[0];
  const double decade = std::pow(10.0, std::floor(std::log10(step)));
  const double m = step / decade;
  if (!(std::abs(m - 1) < 1e-9 || std::abs(m - 2) < 1e-9 || std::abs(m - 2.5) < 1e-9 ||
        std::abs(m - 5) < 1e-9 || std::abs(m - 10) < 1e-9))
    return false;
  for (double t : ticks) {
    if (std::abs(t / step - std::round(t / step)) > 1e-9) return false;
  }
  return true;
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
    // Nothing to show: nothing to choose or play either.
    QVERIFY(!view.arraySelector()->isEnabled());
    QVERIFY(!view.playButton()->isEnabled());
    QVERIFY(!view.sameScaleBox()->isEnabled());
    view.setFrames(SyntheticFrames(4), "test");
    QVERIFY(view.arraySelector()->isEnabled() && view.playButton()->isEnabled());
    view.setFrames(nullptr, "Ideal 4000 rpm");
    QVERIFY(!view.arraySelector()->isEnabled() && !view.playButton()->isEnabled());
  }

  void initTestCase() {
    real_ = RealRunFrames();
    QVERIFY(real_ && !real_->empty());
    QCOMPARE(int(real_->joints.size()), 2);
  }

  // What core knows reaches the frames: the tensor grid, the relief, the big end's turn into the
  // rod frame and the load, and they agree with the fields.
  void realFramesCarryTheGridTheReliefAndTheLoad() {
    const auto& skirt = real_->joints[0];
    const auto& big_end = real_->joints[1];
    QCOMPARE(skirt.name, std::string("skirt"));
    QVERIFY(skirt.HasGrid() && !skirt.periodic);
    QCOMPARE(int(skirt.no_film.size()), 1);
    // Table I: both panels 46° half-widths, so the relief spans 46° … 134°.
    QVERIFY(std::abs(skirt.no_film[0].first * 180 / M_PI - 46.0) < 1e-6);
    QVERIFY(std::abs(skirt.no_film[0].second * 180 / M_PI - 134.0) < 1e-6);
    const size_t nx = skirt.angle_lines.size();
    for (size_t k = 0; k < skirt.frames.size(); k += 7) {
      for (size_t n = 0; n < skirt.mesh.points.size(); ++n) {
        const double a = skirt.angle_lines[n % nx];
        if (a > skirt.no_film[0].first + 1e-9 && a < skirt.no_film[0].second - 1e-9)
          QCOMPARE(NodeValue(skirt, k, n % nx, n / nx, "pressure"), 0.0);
      }
    }
    QCOMPARE(big_end.name, std::string("big_end"));
    QVERIFY(big_end.HasGrid() && big_end.periodic);
    QCOMPARE(big_end.frame_rotation.size(), big_end.frames.size());
    QCOMPARE(big_end.load.size(), big_end.frames.size());
    // The load line points at the pressure lobe: at the frame of the largest load the node of
    // highest film pressure lies near the load's direction (both in the rod frame).
    size_t heaviest = 0;
    for (size_t k = 0; k < big_end.load.size(); ++k) {
      if (std::hypot(big_end.load[k][0], big_end.load[k][1]) >
          std::hypot(big_end.load[heaviest][0], big_end.load[heaviest][1]))
        heaviest = k;
    }
    const size_t bx = big_end.angle_lines.size();
    size_t peak = 0;
    for (size_t n = 0; n < big_end.mesh.points.size(); ++n) {
      if (NodeValue(big_end, heaviest, n % bx, n / bx, "pressure") >
          NodeValue(big_end, heaviest, peak % bx, peak / bx, "pressure"))
        peak = n;
    }
    const double peak_angle = filmdyn::ui::ColumnAngleDeg(big_end, peak % bx, heaviest);
    const auto& f = big_end.load[heaviest];
    const double load_angle = std::atan2(f[1], f[0]) * 180 / M_PI;
    const double off = std::abs(std::remainder(peak_angle - load_angle, 360.0));
    qInfo("largest load %.0f N at %.0f °CA toward %.1f° (rod frame); pressure peak at %.1f°",
          std::hypot(f[0], f[1]), real_->crank_angle_deg[heaviest], load_angle, peak_angle);
    QVERIFY2(off < 45.0, qPrintable(QString::number(off)));
  }

  void unrolledMapHoldsTheNodalValues() {
    filmdyn::ui::FieldView view;
    view.resize(1200, 700);
    view.setFrames(real_, "Skirt-LBRBE 6000 rpm");
    view.setCrankAngle(380.0);
    const size_t k = size_t(view.frameIndex());
    QVERIFY(std::abs(real_->crank_angle_deg[k] - 380.0) < 1e-6);
    QCOMPARE(view.title(), QString("Skirt-LBRBE 6000 rpm — film pressure at 380 °CA"));
    for (int jj = 0; jj < 2; ++jj) {
      const auto& joint = real_->joints[size_t(jj)];
      const filmdyn::ui::FilmMapData& d = view.unrolledMap(jj)->data();
      const size_t nx = joint.angle_lines.size(), ny = joint.axial_lines.size();
      QCOMPARE(d.y.size(), ny);
      int checked = 0;
      for (size_t i = 0; i < nx; i += 3) {
        for (size_t j = 0; j < ny; j += 2) {
          const int ix = LineIndex(d.x, filmdyn::ui::ColumnAngleDeg(joint, i, k));
          QVERIFY(ix >= 0);
          QCOMPARE(d.y[j], joint.axial_lines[j] * 1e3);
          QCOMPARE(d.values[size_t(ix) + d.x.size() * j], NodeValue(joint, k, i, j, "pressure"));
          ++checked;
        }
      }
      QVERIFY(checked > 50);
      // The colour scale is the 3D view's.
      QCOMPARE(view.unrolledMap(jj)->scaleRange(), view.colourRange(jj));
    }
    // The big end's map is in the rod frame, with the load line at the force's direction.
    const filmdyn::ui::FilmMapData& big = view.unrolledMap(1)->data();
    QCOMPARE(big.x.front(), 0.0);
    QCOMPARE(big.x.back(), 360.0);
    const auto& f = real_->joints[1].load[k];
    double load_angle = std::atan2(f[1], f[0]) * 180 / M_PI;
    if (load_angle < 0) load_angle += 360;
    QVERIFY(std::abs(big.x_line - load_angle) < 1e-9);
    QVERIFY(big.x_line_label.startsWith("load"));
    QVERIFY(big.x_title.contains("rod frame"));
    // The skirt's relief is named on the map.
    QCOMPARE(int(view.unrolledMap(0)->data().no_film_x.size()), 1);
    // Its edges as the skirt calculator's map names them (one definition: they differed,
    // "toward the crank ▼" against "skirt bottom (crank side) ▼"); the crank-angle map keeps
    // the sides only (its y is crank angle).
    filmdyn::ui::FilmMapData expected;
    filmdyn::ui::SetSkirtMapLabels(&expected);
    const filmdyn::ui::FilmMapData& skirt = view.unrolledMap(0)->data();
    QCOMPARE(skirt.top, expected.top);
    QCOMPARE(skirt.bottom, expected.bottom);
    QCOMPARE(skirt.left, expected.left);
    QCOMPARE(skirt.y_title, expected.y_title);
    const filmdyn::ui::FilmMapData& crank = view.crankAngleMap(0)->data();
    QCOMPARE(crank.left, expected.left);
    QVERIFY(crank.top.isEmpty() && crank.bottom.isEmpty());
    QCOMPARE(crank.y_title, QString("Crank angle [°CA]"));
  }

  void crankAngleMapRowsAreTheExtremesAlongTheAxis() {
    filmdyn::ui::FieldView view;
    view.resize(1200, 700);
    view.setFrames(real_, "Skirt-LBRBE 6000 rpm");
    view.setCrankAngle(380.0);
    const auto& skirt = real_->joints[0];
    const size_t nx = skirt.angle_lines.size(), ny = skirt.axial_lines.size();
    for (const char* array : {"pressure", "film_thickness"}) {
      const bool minimum = std::string(array) == "film_thickness";
      view.arraySelector()->setCurrentIndex(minimum ? 2 : 0);
      const filmdyn::ui::FilmMapData& d = view.crankAngleMap(0)->data();
      QCOMPARE(d.x.size(), nx);
      // A whole cycle's frames wrap round: the map reaches from 0 to 720 °CA, the row one
      // cycle on from the first (or back from the last) holding that row's values.
      const std::vector<double>& angles = real_->crank_angle_deg;
      const size_t frames = angles.size();
      const bool ahead = angles.front() > 0.0;
      QCOMPARE(d.y.size(), frames + 1 + (ahead ? 1 : 0));
      QVERIFY2(d.y.front() <= 0.0 && d.y.back() >= 720.0,
               qPrintable(QString("%1 .. %2").arg(d.y.front()).arg(d.y.back())));
      const size_t first = ahead ? 1 : 0, wrapped = first + frames;
      QCOMPARE(d.y[wrapped], d.y[first] + 720.0);
      for (size_t i = 0; i < nx; ++i)
        QCOMPARE(d.values[i + nx * wrapped], d.values[i + nx * first]);
      QCOMPARE(d.y_line, real_->crank_angle_deg[size_t(view.frameIndex())]);
      for (size_t k : {size_t(0), size_t(17), size_t(95), real_->crank_angle_deg.size() - 1}) {
        const int row = LineIndex(d.y, real_->crank_angle_deg[k]);
        QVERIFY(row >= 0);
        for (size_t i = 0; i < nx; ++i) {
          double expected = minimum ? INFINITY : -INFINITY;
          for (size_t j = 0; j < ny; ++j) {
            const double v = NodeValue(skirt, k, i, j, array);
            expected = minimum ? std::min(expected, v) : std::max(expected, v);
          }
          QCOMPARE(d.values[i + nx * size_t(row)], expected);
        }
      }
    }
    // The big end turns with the journal: its rows are resampled on the rod frame's angles and
    // keep the frame's peak (within the resampling between columns).
    view.arraySelector()->setCurrentIndex(0);
    const auto& big_end = real_->joints[1];
    const filmdyn::ui::FilmMapData& d = view.crankAngleMap(1)->data();
    QCOMPARE(d.x.front(), 0.0);
    QCOMPARE(d.x.back(), 360.0);
    const size_t k = 95;
    const int row = LineIndex(d.y, real_->crank_angle_deg[k]);
    double map_max = 0, frame_max = 0;
    for (size_t i = 0; i < d.x.size(); ++i)
      map_max = std::max(map_max, d.values[i + d.x.size() * size_t(row)]);
    for (size_t n = 0; n < big_end.mesh.points.size(); ++n)
      frame_max = std::max(frame_max, NodeValue(big_end, k, n % big_end.angle_lines.size(),
                                                n / big_end.angle_lines.size(), "pressure"));
    qInfo("big end at %.0f °CA: frame peak %.2f MPa, crank-angle map row peak %.2f MPa",
          real_->crank_angle_deg[k], frame_max, map_max);
    QVERIFY(map_max <= frame_max * (1 + 1e-12));
    QVERIFY(map_max >= 0.8 * frame_max);
    // The load's direction is marked on every frame's row (once: not on the rows wrapped round
    // the cycle): at frame k the force's angle in the rod frame.
    QCOMPARE(d.points.size(), real_->crank_angle_deg.size());
    const auto& f = big_end.load[k];
    double load_angle = std::atan2(f[1], f[0]) * 180 / M_PI;
    if (load_angle < 0) load_angle += 360;
    const auto at_k = std::find_if(d.points.begin(), d.points.end(), [&](const auto& p) {
      return p.second == real_->crank_angle_deg[k];
    });
    QVERIFY(at_k != d.points.end());
    QCOMPARE(at_k->first, load_angle);
  }

  void threeDViewsAreViridisUnlitWithTheBarBeside() {
    filmdyn::ui::FieldView view;
    view.resize(1400, 820);
    view.setFrames(real_, "Skirt-LBRBE 6000 rpm");
    view.setCrankAngle(380.0);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    for (int jj = 0; jj < 2; ++jj) {
      filmdyn::ui::ScalarFieldView* v = view.jointView(jj);
      QVERIFY(v != nullptr);
      QTRY_VERIFY_WITH_TIMEOUT(v->renderedFrames() > 0, 10000);
      // The lookup table is the application's viridis.
      for (int i : {0, 40, 128, 200, 255}) {
        double rgba[4];
        v->lookupTable()->GetTableValue(i, rgba);
        const QColor expected = filmdyn::ui::Viridis(i / 255.0);
        QCOMPARE(int(std::lround(rgba[0] * 255)), expected.red());
        QCOMPARE(int(std::lround(rgba[1] * 255)), expected.green());
        QCOMPARE(int(std::lround(rgba[2] * 255)), expected.blue());
      }
      // Unlit: the colour is the value's wherever the surface faces.
      vtkProperty* property = v->surfaceActor()->GetProperty();
      QVERIFY(!property->GetLighting());
      QCOMPARE(property->GetAmbient(), 1.0);
      QCOMPARE(property->GetDiffuse(), 0.0);
      // The bar: round numbers from end to end of the shared range, in its own strip.
      const std::vector<double> labels = v->barLabels();
      QVERIFY2(RoundNumbers(labels), "bar labels are not round");
      QCOMPARE(labels.front(), view.colourRange(jj).first);
      QCOMPARE(labels.back(), view.colourRange(jj).second);
      QCOMPARE(v->scalarRange()[1], view.colourRange(jj).second);
      const double* surface = v->renderer()->GetViewport();
      const double* bar = v->scalarBarRenderer()->GetViewport();
      QVERIFY(surface[2] <= bar[0]);
      QVERIFY(v->scalarBarRenderer()->HasViewProp(v->scalarBar()));
      QVERIFY(!v->renderer()->HasViewProp(v->scalarBar()));
      // No rainbow red left (viridis has none): the old blue-to-red map is gone.
      const QImage image = v->grabFramebuffer();
      int reddish = 0;
      for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
          const QRgb c = image.pixel(x, y);
          if (qRed(c) > 180 && qGreen(c) < 90 && qBlue(c) < 90) ++reddish;
        }
      QVERIFY(DistinctColours(image) > 100);
      if (!v->arrowVisible()) QCOMPARE(reddish, 0);  // the load arrow is the only red
    }
    // The sides are named; the skirt's relief carries no surface; the big end shows its load.
    const auto skirt_labels = view.jointView(0)->labelTexts();
    for (const char* text : {"thrust side", "anti-thrust side", "skirt top",
                             "skirt bottom (crank side)", "pin-boss relief: no film"}) {
      QVERIFY2(
          std::find(skirt_labels.begin(), skirt_labels.end(), QString(text)) != skirt_labels.end(),
          text);
    }
    const auto big_labels = view.jointView(1)->labelTexts();
    QVERIFY(std::find(big_labels.begin(), big_labels.end(), QString("rod side")) !=
            big_labels.end());
    QVERIFY(std::find(big_labels.begin(), big_labels.end(), QString("cap side")) !=
            big_labels.end());
    QVERIFY(view.jointView(1)->arrowVisible());
    QVERIFY(big_labels.back().startsWith("load ") && big_labels.back().endsWith(" kN"));
    QVERIFY(!view.jointView(0)->arrowVisible());
    const auto& skirt = real_->joints[0];
    auto* drawn =
        vtkPolyData::SafeDownCast(view.jointView(0)->surfaceActor()->GetMapper()->GetInput());
    QVERIFY(drawn != nullptr);
    size_t relief = 0;
    const size_t nx = skirt.angle_lines.size();
    for (const auto& t : skirt.mesh.triangles) {
      bool inside = true;
      for (int n : t) {
        const double a = skirt.angle_lines[size_t(n) % nx];
        inside =
            inside && a >= skirt.no_film[0].first - 1e-9 && a <= skirt.no_film[0].second + 1e-9;
      }
      relief += inside;
    }
    QVERIFY(relief > 0);
    // Both halves of the skirt (mirrored about the pin-axis plane), each without its relief.
    QVERIFY(skirt.mirrored);
    QCOMPARE(size_t(drawn->GetNumberOfPolys()), 2 * (skirt.mesh.triangles.size() - relief));

    if (const QString dir = qEnvironmentVariable("FILMDYN_SCREENSHOT_DIR"); !dir.isEmpty()) {
      QDir().mkpath(dir);
      const char* names[] = {"field_view_3d.png", "field_view_unrolled.png",
                             "field_view_crank_angle.png"};
      for (int tab = 0; tab < 3; ++tab) {
        for (int jj = 0; jj < 2; ++jj) view.jointTabs(jj)->setCurrentIndex(tab);
        QTest::qWait(400);
        view.grab().save(dir + "/" + names[tab]);
      }
      view.resize(1011, 620);  // the page inside the main window at its smallest size
      QTest::qWait(400);
      view.grab().save(dir + "/field_view_crank_angle_small.png");
      for (int jj = 0; jj < 2; ++jj) view.jointTabs(jj)->setCurrentIndex(0);
      QTest::qWait(400);
      view.grab().save(dir + "/field_view_3d_small.png");
    }
  }

  // A cycle that starts at 90 °CA (operating.start_crank_angle) passes 720 → 0 within it: the
  // live frames come in crank-angle order from 0 °CA, each with its own arrays and rotation, as
  // core's files hold them.
  void framesOfACycleStartingAt90DegreesAreInCrankAngleOrder() {
    using namespace filmdyn;
    QTemporaryDir dir;
    engine::EngineCase c;
    const auto live = BigEndRunFrames(dir.path(), &c, 3000.0, [](engine::EngineCase& c) {
      c.big_end.mesh_theta = 24;
      c.big_end.mesh_z = 4;
      c.operating.start_crank_angle = M_PI / 2;
    });
    QVERIFY(live && live->crank_angle_deg.size() == 180);
    // 90, 94, … 718 °CA, then 2, 6, … 86 °CA: from 2 °CA on, the frame computed last just before.
    for (std::size_t k = 0; k < 180; ++k) QCOMPARE(live->crank_angle_deg[k], 2.0 + 4.0 * double(k));
    const double step = live->time[1] - live->time[0];
    QVERIFY(step > 0.0 && std::abs(live->time.front() - live->time.back() - step) < 1e-9 * step);
    const auto stored = ui::ReadFieldFrames(dir.path(), c, 3000.0);
    QVERIFY(stored && stored->crank_angle_deg.size() == 180);
    const auto& a = live->joints[0];
    const auto& b = stored->joints[0];
    for (std::size_t k = 0; k < 180; k += 7) {
      QCOMPARE(stored->crank_angle_deg[k], live->crank_angle_deg[k]);
      QVERIFY(std::abs(std::remainder(a.Rotation(k) - b.Rotation(k), 2 * M_PI)) < 1e-6);
      const auto& p = *ui::FindFieldArray(a.frames[k], "pressure");
      const auto& q = *ui::FindFieldArray(b.frames[k], "pressure");
      QCOMPARE(p.size(), q.size());
      double peak = 1.0;
      for (double v : p) peak = std::max(peak, std::abs(v));
      for (std::size_t n = 0; n < p.size(); ++n) QVERIFY(std::abs(p[n] - q[n]) <= 1e-6 * peak);
    }
    if (const QString shots = qEnvironmentVariable("FILMDYN_SCREENSHOT_DIR"); !shots.isEmpty()) {
      ui::FieldView view;  // to look at: the crank-angle chart from 0 °CA, the frame at 100 °CA
      view.resize(1400, 820);
      view.setFrames(live, "Only-LBRBE 3000 rpm, cycle from 90 °CA");
      view.setCrankAngle(100.0);
      view.show();
      QVERIFY(QTest::qWaitForWindowExposed(&view));
      QDir().mkpath(shots);
      for (const int tab : {0, 2}) {
        view.jointTabs(0)->setCurrentIndex(tab);
        QTest::qWait(400);
        view.grab().save(shots + QString("/field_view_start_90_tab%1.png").arg(tab));
      }
    }
  }

  // Elastic surfaces: the deformation, live and read back from core's files, the film the
  // rigid one plus it, drawn by the view (and pictured); a rigid run says why it has none.
  void deformationOfAnElasticRunLiveAndReadBack() {
    QTemporaryDir dir;
    filmdyn::engine::EngineCase used;
    const auto live = JfoRunFrames(dir.path(), &used, true);
    QVERIFY(live && !live->empty());
    const auto& joint = live->joints[0];
    QVERIFY(joint.HasArray("deformation"));
    double hi = 0.0, lo = INFINITY;
    for (const auto& frame : joint.frames) {
      for (double v : *filmdyn::ui::FindFieldArray(frame, "deformation"))
        lo = std::min(lo, v), hi = std::max(hi, v);
    }
    qInfo("deformation over the cycle: %g … %g m", lo, hi);
    QVERIFY(lo >= 0.0 && hi > 0.1e-6);
    const auto stored = filmdyn::ui::ReadFieldFrames(dir.path(), used, 6000.0);
    QVERIFY(stored && stored->joints[0].HasArray("deformation"));
    for (size_t k = 0; k < joint.frames.size(); k += 13) {
      const auto& a = *filmdyn::ui::FindFieldArray(joint.frames[k], "deformation");
      const auto& b = *filmdyn::ui::FindFieldArray(stored->joints[0].frames[k], "deformation");
      QCOMPARE(a.size(), b.size());
      for (size_t n = 0; n < a.size(); ++n) QVERIFY(std::abs(a[n] - b[n]) <= 1e-6 * hi);
    }
    filmdyn::ui::FieldView view;
    view.resize(1200, 700);
    view.setFrames(live, "Only-LBRBE 6000 rpm, elastic lining");
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    const int index = view.arraySelector()->findData("deformation");
    QVERIFY(index >= 0);
    QCOMPARE(view.arraySelector()->itemText(index), QString("Surface deformation [µm]"));
    view.arraySelector()->setCurrentIndex(index);
    view.setCrankAngle(380.0);
    QVERIFY(view.title().contains("surface deformation"));
    QVERIFY(view.missingNote(0)->isHidden());
    if (filmdyn::ui::ScalarFieldView* v = view.jointView(0)) {
      QTRY_VERIFY_WITH_TIMEOUT(v->renderedFrames() > 0, 10000);
      QVERIFY(DistinctColours(v->grabFramebuffer()) > 20);
    }
    if (const QString shots = qEnvironmentVariable("FILMDYN_SCREENSHOT_DIR"); !shots.isEmpty()) {
      QTest::qWait(400);
      view.grab().save(shots + "/field_view_deformation.png");
    }
    view.setFrames(real_, "Skirt-LBRBE 6000 rpm");
    QVERIFY(view.missingNote(1)->isVisible());
    QVERIFY2(view.missingNote(1)->text().contains("rigid"),
             qPrintable(view.missingNote(1)->text()));
  }

  void fluidFractionOfAJfoRunLiveAndReadBack() {
    QTemporaryDir dir;
    filmdyn::engine::EngineCase jfo_case;
    const auto live = JfoRunFrames(dir.path(), &jfo_case);
    QVERIFY(live && !live->empty());
    QCOMPARE(int(live->joints.size()), 1);
    const auto& joint = live->joints[0];
    QCOMPARE(joint.name, std::string("big_end"));
    QVERIFY(joint.mass_conserving);
    QVERIFY(joint.HasArray("fluid_fraction"));
    // θ within [0, 1] everywhere, and the film breaks up somewhere in the cycle.
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& frame : joint.frames) {
      for (double v : *filmdyn::ui::FindFieldArray(frame, "fluid_fraction")) {
        lo = std::min(lo, v), hi = std::max(hi, v);
      }
    }
    qInfo("fluid fraction over the cycle: %g … %g", lo, hi);
    QVERIFY(lo >= -1e-9 && hi <= 1.0 + 1e-9);
    QVERIFY(lo < 0.9 && hi > 0.999);

    // Read back from core's files (the path of a saved run or a study point): the same values
    // (single precision).
    const auto stored = filmdyn::ui::ReadFieldFrames(dir.path(), jfo_case, 6000.0);
    QVERIFY(stored && stored->joints.size() == 1);
    const auto& back = stored->joints[0];
    QVERIFY(back.mass_conserving && back.HasArray("fluid_fraction"));
    QCOMPARE(back.frames.size(), joint.frames.size());
    for (size_t k = 0; k < joint.frames.size(); k += 11) {
      const auto& a = *filmdyn::ui::FindFieldArray(joint.frames[k], "fluid_fraction");
      const auto& b = *filmdyn::ui::FindFieldArray(back.frames[k], "fluid_fraction");
      QCOMPARE(a.size(), b.size());
      for (size_t n = 0; n < a.size(); ++n) QVERIFY(std::abs(a[n] - b[n]) < 1e-6);
    }
    // The same files read for a case with Reynolds cavitation carry no fluid fraction.
    filmdyn::engine::EngineCase reynolds = jfo_case;
    reynolds.big_end.cavitation = filmdyn::lubrication::CavitationModel::kReynolds;
    const auto without = filmdyn::ui::ReadFieldFrames(dir.path(), reynolds, 6000.0);
    QVERIFY(!without->joints[0].mass_conserving && !without->joints[0].HasArray("fluid_fraction"));

    // The view lists the quantity; chosen, it is drawn on a fixed 0–1 scale in every view.
    filmdyn::ui::FieldView view;
    view.resize(1200, 700);
    view.setFrames(live, "Only-LBRBE 6000 rpm");
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    const int fraction = view.arraySelector()->findData("fluid_fraction");
    QVERIFY(fraction >= 0);
    QCOMPARE(view.arraySelector()->itemText(fraction), QString("Fluid fraction θ [-]"));
    QVERIFY(!view.arraySelector()->itemData(fraction, Qt::ToolTipRole).toString().isEmpty());
    view.arraySelector()->setCurrentIndex(fraction);
    view.setCrankAngle(380.0);
    const size_t k = size_t(view.frameIndex());
    QVERIFY(view.title().startsWith("Only-LBRBE 6000 rpm — fluid fraction θ at "));
    QVERIFY(view.missingNote(0)->isHidden() && view.jointTabs(0)->isVisible());
    QCOMPARE(view.colourRange(0), std::make_pair(0.0, 1.0));
    QCOMPARE(view.unrolledMap(0)->scaleRange(), std::make_pair(0.0, 1.0));
    QCOMPARE(view.crankAngleMap(0)->scaleRange(), std::make_pair(0.0, 1.0));
    // The unrolled map holds the nodal values of the frame shown.
    const filmdyn::ui::FilmMapData& d = view.unrolledMap(0)->data();
    const auto& values = *filmdyn::ui::FindFieldArray(joint.frames[k], "fluid_fraction");
    double map_lo = INFINITY, node_lo = INFINITY;
    for (double v : d.values) map_lo = std::min(map_lo, v);
    for (double v : values) node_lo = std::min(node_lo, v);
    QVERIFY(std::abs(map_lo - node_lo) < 1e-12);
    // The crank-angle map: the smallest θ across the width.
    QVERIFY(view.crankAngleMap(0)->data().value_title.contains("smallest"));
    if (filmdyn::ui::ScalarFieldView* v = view.jointView(0)) {
      QTRY_VERIFY_WITH_TIMEOUT(v->renderedFrames() > 0, 10000);
      QCOMPARE(v->scalarRange()[0], 0.0);
      QCOMPARE(v->scalarRange()[1], 1.0);
      QCOMPARE(v->barLabels().front(), 0.0);
      QCOMPARE(v->barLabels().back(), 1.0);
      QVERIFY(DistinctColours(v->grabFramebuffer()) > 20);
    }

    // A run with Reynolds cavitation (the coupled run): each joint says why it has no fluid
    // fraction, naming the case field that chooses JFO; back to the pressure, the views return.
    view.setFrames(real_, "Skirt-LBRBE 6000 rpm");
    QCOMPARE(view.arraySelector()->currentIndex(), fraction);
    for (int jj = 0; jj < 2; ++jj) {
      QVERIFY(view.jointTabs(jj)->isHidden());
      QVERIFY(view.missingNote(jj)->isVisible());
      const QString note = view.missingNote(jj)->text();
      QVERIFY2(note.contains("\"reynolds\"") && note.contains("\"jfo\"") &&
                   note.contains("cavitation model"),
               qPrintable(note));
    }
    QVERIFY(view.missingNote(0)->text().contains("piston skirt"));
    QVERIFY(view.missingNote(1)->text().contains("big-end bearing"));
    view.arraySelector()->setCurrentIndex(0);
    for (int jj = 0; jj < 2; ++jj) {
      QVERIFY(view.jointTabs(jj)->isVisible());
      QVERIFY(view.missingNote(jj)->isHidden());
    }
  }

  void switchingRunsKeepsTheCrankAngleAndSameScaleSharesTheRange() {
    // A second run: the same fields at 1.6 × the pressure, its frames 1 °CA later.
    const auto second = ScaledCopy(*real_, 1.6, 1.0);
    filmdyn::ui::FieldView view;
    view.resize(1200, 700);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.setFrames(real_, "A");
    view.setCrankAngle(380.0);
    QVERIFY(std::abs(real_->crank_angle_deg[size_t(view.frameIndex())] - 380.0) < 1e-6);
    const auto range_a = view.colourRange(0);
    view.setFrames(second, "B");
    // The nearest frame of the new run.
    QVERIFY(std::abs(second->crank_angle_deg[size_t(view.frameIndex())] - 381.0) < 1e-6);
    QVERIFY(view.title().endsWith("at 381 °CA"));
    const auto range_b = view.colourRange(0);
    qInfo("own ranges: A %g–%g MPa, B %g–%g MPa", range_a.first, range_a.second, range_b.first,
          range_b.second);
    QVERIFY(range_b.second > range_a.second);
    // Back to A: the frame nearest to 381 °CA.
    view.setFrames(real_, "A");
    QVERIFY(std::abs(real_->crank_angle_deg[size_t(view.frameIndex())] - 380.0) < 1e-6);

    // One scale over both runs, in every view.
    view.setScaleFrames({real_, second, nullptr});
    view.sameScaleBox()->setChecked(true);
    const auto shared_a = view.colourRange(0);
    QCOMPARE(shared_a, range_b);
    QCOMPARE(view.jointView(0)->scalarRange()[1], shared_a.second);
    QCOMPARE(view.unrolledMap(0)->scaleRange(), shared_a);
    QCOMPARE(view.crankAngleMap(0)->scaleRange(), shared_a);
    view.setFrames(second, "B");
    QCOMPARE(view.colourRange(0), shared_a);
    view.setFrames(real_, "A");
    const auto big_a = view.colourRange(1);
    view.setFrames(second, "B");
    QCOMPARE(view.colourRange(1), big_a);
    view.sameScaleBox()->setChecked(false);
    QCOMPARE(view.colourRange(0), range_b);
  }

 private:
  std::shared_ptr<const filmdyn::ui::FieldFrames> real_;
};

int main(int argc, char** argv) {
  filmdyn::ui::VtkViewWidget::SetDefaultSurfaceFormat();
  QApplication app(argc, argv);
  TestFieldView test;
  return QTest::qExec(&test, argc, argv);
}
#include "test_field_view.moc"
