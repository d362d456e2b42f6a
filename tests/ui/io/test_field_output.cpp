// The fields/ folder of a run: frames of the newest cycle only, one VTU per output step and a PVD
// per joint, values identical to the solvers' fields, bearing geometry placed in the rod frame.
// Driven by real skirt and bearing solves; read back with VTK's own readers.
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <QDir>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <numbers>

#include "core/io/field_output.hpp"
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

vtkSmartPointer<vtkUnstructuredGrid> Read(const QString& path) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.toUtf8().constData());
  reader->Update();
  return reader->GetOutput();
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
    QCOMPARE(fields.entryList({"skirt_*.vtu"}).size(), 4);
    QCOMPARE(fields.entryList({"bearing_*.vtu"}).size(), 4);
    QVERIFY(fields.exists("skirt.pvd"));
    QVERIFY(fields.exists("bearing.pvd"));

    // The last skirt frame holds the last solve's values (float precision).
    auto grid = Read(fields.filePath("skirt_0003.vtu"));
    QCOMPARE(grid->GetNumberOfPoints(), vtkIdType(skirt.mesh().NodeCount()));
    vtkDataArray* p = grid->GetPointData()->GetArray("pressure[Pa]");
    vtkDataArray* h = grid->GetPointData()->GetArray("film_thickness[m]");
    QVERIFY(p && h && grid->GetPointData()->GetArray("contact_pressure[Pa]"));
    double p_max = 0;
    for (int k = 0; k < skirt.mesh().NodeCount(); ++k) {
      QVERIFY(std::abs(p->GetTuple1(k) - skirt.fields().pressure[k]) <=
              1e-6 * std::max(1.0, std::abs(skirt.fields().pressure[k])));
      QVERIFY(std::abs(h->GetTuple1(k) - skirt.film_thickness()[k]) <= 1e-6 * 1e-4);
      p_max = std::max(p_max, p->GetTuple1(k));
      // Skirt nodes lie on the piston radius, below the skirt top.
      double x[3];
      grid->GetPoint(k, x);
      QVERIFY(std::abs(std::hypot(x[0], x[1]) - 0.0365) < 1e-12);
      QVERIFY(x[2] <= 1e-15);
    }
    QVERIFY(p_max > 0.0);  // a real film, not zeros

    // Bearing: the maximum film (θ = 0) sits opposite the eccentricity, at ψ = φ + π.
    grid = Read(fields.filePath("bearing_0000.vtu"));
    h = grid->GetPointData()->GetArray("film_thickness[m]");
    vtkIdType thickest = 0;
    for (vtkIdType k = 0; k < grid->GetNumberOfPoints(); ++k) {
      if (h->GetTuple1(k) > h->GetTuple1(thickest)) thickest = k;
    }
    double x[3];
    grid->GetPoint(thickest, x);
    const double psi = std::atan2(x[1], x[0]);
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

QTEST_MAIN(TestFieldOutput)
#include "test_field_output.moc"
