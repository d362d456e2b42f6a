// The fields/ folder of a run: frames of the newest cycle only, one HDF5 + XDMF time series per
// joint with the crank angle of each frame, values identical to the solvers' fields (single
// precision), bearing geometry placed in the rod frame. Driven by real skirt and bearing solves;
// read back from the HDF5 files.
#include <QDir>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <numbers>

#include "core/io/field_output.hpp"
#include "core/io/field_series.hpp"
#include "core/lubrication/bearing_solver.hpp"
#include "core/lubrication/skirt_solver.hpp"

using namespace filmdyn;

namespace {

lubrication::SkirtConfig Skirt() {
  lubrication::SkirtConfig cfg;
  auto& g = cfg.geometry;
  g.radius = 0.0365;
  g.skirt_length = 0.028;
  g.radial_clearance = 25e-6;
  g.pin_position = 0.0118;
  g.alpha1 = g.alpha2 = 46.0 * std::numbers::pi / 180.0;
  g.profile = {{0.0, 0.014, 0.028}, {20e-6, 0.0, 20e-6}};
  cfg.viscosity = 0.02;
  cfg.mesh = {8, 2, 8, 6};
  return cfg;
}

lubrication::BearingConfig Bearing() {
  lubrication::BearingConfig cfg;
  cfg.geometry = {0.015, 0.022, 50e-6};
  cfg.viscosity = 0.02;
  cfg.mesh = {24, 4, false};
  return cfg;
}

// The values of array `name` of frame `frame`, or nullptr.
const std::vector<float>* Array(const io::FieldSeries& series, std::size_t frame,
                                const std::string& name) {
  for (std::size_t a = 0; a < series.array_names.size(); ++a) {
    if (series.array_names[a] == name) return &series.frames[frame].arrays[a];
  }
  return nullptr;
}

}  // namespace

class TestFieldOutput : public QObject {
  Q_OBJECT
 private slots:
  void writesNewestCycleWithSolverValues() {
    lubrication::SkirtSolver skirt(Skirt());
    lubrication::BearingSolver bearing(Bearing());
    io::FieldRecorder recorder;
    const engine::FieldCallback callback = recorder.Callback();
    engine::CrankTrainSample sample;
    const double phi = 0.7;  // eccentricity direction in the rod frame
    sample.bearing.journal_ecc_rod = {30e-6 * std::cos(phi), 30e-6 * std::sin(phi)};

    lubrication::SkirtState skirt_state;
    skirt_state.e0 = 10e-6;
    skirt_state.piston_velocity = 10.0;
    lubrication::BearingState bearing_state;
    bearing_state.eps = 0.6;
    bearing_state.omega_journal = 600.0;

    // Cycle 1 (3 steps), then cycle 2 (4 steps, last one with a different state): only cycle 2
    // may be written.
    for (int cycle = 1; cycle <= 2; ++cycle) {
      for (int step = 0; step < 2 + cycle; ++step) {
        skirt_state.e0 = (5.0 + step + 3 * cycle) * 1e-6;
        skirt.Solve(skirt_state);
        bearing.Solve(bearing_state);
        engine::FieldFrame frame;
        frame.cycle = cycle;
        frame.step = step;
        frame.crank_angle_deg = 180.0 * step;
        frame.sample = &sample;
        frame.skirt = &skirt;
        frame.bearing = &bearing;
        callback(frame);
      }
    }
    QCOMPARE(recorder.skirt_frames(), std::size_t(4));
    QCOMPARE(recorder.bearing_frames(), std::size_t(4));

    QTemporaryDir dir;
    recorder.Write(QDir(dir.path()).filePath("fields").toStdString());
    const QDir fields(dir.filePath("fields"));
    for (const char* file : {"skirt.h5", "skirt.xdmf", "bearing.h5", "bearing.xdmf"}) {
      QVERIFY2(fields.exists(file), file);
    }
    const io::FieldSeries skirt_series =
        io::ReadFieldSeries(fields.filePath("skirt.xdmf").toStdString());
    const io::FieldSeries bearing_series =
        io::ReadFieldSeries(fields.filePath("bearing.h5").toStdString());
    QCOMPARE(skirt_series.frames.size(), std::size_t(4));
    QCOMPARE(bearing_series.frames.size(), std::size_t(4));
    // The time value of each frame is its crank angle.
    for (std::size_t i = 0; i < 4; ++i) {
      QCOMPARE(skirt_series.frames[i].crank_angle_deg, 180.0 * double(i));
      QCOMPARE(bearing_series.frames[i].crank_angle_deg, 180.0 * double(i));
    }

    // The last skirt frame holds the last solve's values (float precision).
    QCOMPARE(skirt_series.points.size(), std::size_t(skirt.mesh().NodeCount()));
    QCOMPARE(skirt_series.triangles.size(), skirt.mesh().triangles.size());
    const std::vector<float>* p = Array(skirt_series, 3, "pressure[Pa]");
    const std::vector<float>* h = Array(skirt_series, 3, "film_thickness[m]");
    QVERIFY(p && h && Array(skirt_series, 3, "contact_pressure[Pa]"));
    // Reynolds films: no fluid fraction (their solution's ones would show a full film where it
    // cavitates); a mass-conserving film writes its own (the field view's tests read it back).
    QVERIFY(!Array(skirt_series, 3, "fluid_fraction[-]"));
    QVERIFY(!Array(bearing_series, 3, "fluid_fraction[-]"));
    double p_max = 0;
    for (int k = 0; k < skirt.mesh().NodeCount(); ++k) {
      QVERIFY(std::abs((*p)[k] - skirt.fields().pressure[k]) <=
              1e-6 * std::max(1.0, std::abs(skirt.fields().pressure[k])));
      QVERIFY(std::abs((*h)[k] - skirt.film_thickness()[k]) <= 1e-6 * 1e-4);
      p_max = std::max(p_max, double((*p)[k]));
      // Skirt nodes lie on the piston radius, below the skirt top.
      const auto& x = skirt_series.points[k];
      QVERIFY(std::abs(std::hypot(x[0], x[1]) - 0.0365) < 1e-12);
      QVERIFY(x[2] <= 1e-15);
    }
    QVERIFY(p_max > 0.0);  // a real film, not zeros

    // Bearing: the maximum film (θ = 0) sits opposite the eccentricity, at ψ = φ + π.
    h = Array(bearing_series, 0, "film_thickness[m]");
    const auto points = io::FramePoints(bearing_series, 0);
    std::size_t thickest = 0;
    for (std::size_t k = 0; k < points.size(); ++k) {
      if ((*h)[k] > (*h)[thickest]) thickest = k;
    }
    const double psi = std::atan2(points[thickest][1], points[thickest][0]);
    QVERIFY2(std::abs(std::remainder(psi - (phi + std::numbers::pi), 2 * std::numbers::pi)) <
                 2 * std::numbers::pi / 24 + 1e-9,
             "maximum film not opposite the eccentricity");
  }

  void idealRunWritesNothing() {
    io::FieldRecorder recorder;
    QTemporaryDir dir;
    recorder.Write(QDir(dir.path()).filePath("fields").toStdString());
    QVERIFY(!QDir(dir.filePath("fields")).exists());
  }
};

QTEST_GUILESS_MAIN(TestFieldOutput)
#include "test_field_output.moc"
