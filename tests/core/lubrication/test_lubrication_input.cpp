// Bad input gives filmdyn::InputError naming the field and the allowed range; never a crash.
#include <QtTest>

#include <cmath>
#include <limits>

#include "core/base/input_error.hpp"
#include "core/lubrication/bearing_calculator.hpp"
#include "core/lubrication/bearing_solver.hpp"
#include "core/lubrication/skirt_solver.hpp"

using namespace filmdyn::lubrication;
using filmdyn::InputError;

namespace {
template <class F>
QString ErrorOf(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

BearingConfig GoodBearing() {
  BearingConfig cfg;
  cfg.geometry = {0.025, 0.025, 25e-6};
  cfg.viscosity = 0.01;
  return cfg;
}

SkirtConfig GoodSkirt() {
  SkirtConfig cfg;
  cfg.geometry.radius = 0.04;
  cfg.geometry.skirt_length = 0.03;
  cfg.geometry.radial_clearance = 20e-6;
  cfg.geometry.pin_position = 0.015;
  cfg.geometry.alpha1 = cfg.geometry.alpha2 = 0.8;
  cfg.geometry.profile = {{0.0, 0.03}, {10e-6, 10e-6}};
  cfg.viscosity = 0.008;
  return cfg;
}
}  // namespace

class TestLubricationInput : public QObject {
  Q_OBJECT
 private slots:
  void bearingGeometry() {
    auto cfg = GoodBearing();
    cfg.geometry.radial_clearance = -1e-5;
    QString msg = ErrorOf([&] { BearingSolver s(cfg); });
    QVERIFY(msg.startsWith("bearing.radial_clearance = -1e-05"));
    QVERIFY(msg.contains("> 0"));
    cfg = GoodBearing();
    cfg.viscosity = 0.0;
    QVERIFY(ErrorOf([&] { BearingSolver s(cfg); }).startsWith("bearing.viscosity = 0"));
    cfg = GoodBearing();
    cfg.geometry.length = std::numeric_limits<double>::quiet_NaN();
    QVERIFY(ErrorOf([&] { BearingSolver s(cfg); }).startsWith("bearing.length = nan"));
    cfg = GoodBearing();
    cfg.mesh.n_theta = 3;
    QVERIFY(ErrorOf([&] { BearingSolver s(cfg); }).startsWith("bearing.mesh.n_theta = 3"));
  }

  void bearingState() {
    BearingSolver solver(GoodBearing());
    BearingState s;
    s.eps = 1.0;
    QString msg = ErrorOf([&] { solver.Solve(s); });
    QVERIFY(msg.startsWith("bearing_state.eps = 1"));
    QVERIFY(msg.contains("[0, 1)"));
    s.eps = -0.1;
    QVERIFY(ErrorOf([&] { solver.Solve(s); }).startsWith("bearing_state.eps = -0.1"));
    s.eps = 0.5;
    s.omega_journal = std::numeric_limits<double>::infinity();
    QVERIFY(ErrorOf([&] { solver.Solve(s); }).startsWith("bearing_state.omega_journal = inf"));
  }

  void skirtTables() {
    auto cfg = GoodSkirt();
    cfg.geometry.profile = {};
    QVERIFY(ErrorOf([&] { SkirtSolver s(cfg); }).startsWith("skirt.profile = empty table"));
    cfg = GoodSkirt();
    cfg.geometry.profile = {{0.0, 0.02, 0.01}, {0.0, 1e-6, 2e-6}};
    QString msg = ErrorOf([&] { SkirtSolver s(cfg); });
    QVERIFY(msg.startsWith("skirt.profile.x[2] = 0.01"));
    QVERIFY(msg.contains("strictly increasing"));
    cfg = GoodSkirt();
    cfg.geometry.ovality = {{0.0, 1.0}, {0.0, std::nan("")}};
    QVERIFY(ErrorOf([&] { SkirtSolver s(cfg); }).startsWith("skirt.ovality.y[1] = nan"));
    cfg = GoodSkirt();
    cfg.geometry.profile = {{0.0, 0.01}, {1e-6}};
    QVERIFY(ErrorOf([&] { SkirtSolver s(cfg); }).startsWith("skirt.profile = "));
    cfg = GoodSkirt();
    cfg.geometry.alpha2 = 3.0;  // panels overlap
    QVERIFY(ErrorOf([&] { SkirtSolver s(cfg); }).startsWith("skirt.alpha2 = 3"));
    cfg = GoodSkirt();
    cfg.geometry.radial_clearance = 0.0;
    QVERIFY(ErrorOf([&] { SkirtSolver s(cfg); }).startsWith("skirt.radial_clearance = 0"));
  }

  void skirtState() {
    SkirtSolver solver(GoodSkirt());
    SkirtState s;
    s.piston_velocity = std::nan("");
    QVERIFY(ErrorOf([&] { solver.Solve(s); }).startsWith("skirt_state.piston_velocity = nan"));
  }

  void calculator() {
    BearingCalcInput in;
    QVERIFY(ErrorOf([&] { RunBearingCalculator(in); }).startsWith("bearing.mode"));
    in.eps = 0.5;
    in.load = 100.0;
    QVERIFY(ErrorOf([&] { RunBearingCalculator(in); }).startsWith("bearing.mode"));
    in.load.reset();
    in.eps = 1.2;
    QVERIFY(ErrorOf([&] { RunBearingCalculator(in); }).startsWith("bearing.eps = 1.2"));
    in.eps = 0.5;
    in.viscosity = -1.0;
    QVERIFY(ErrorOf([&] { RunBearingCalculator(in); }).startsWith("bearing.viscosity = -1"));
    // A load no film can carry is a status, not an exception or a hang.
    BearingCalcInput heavy;
    heavy.mesh = {40, 4, true};
    heavy.load = 1e12;
    const BearingCalcResult r = RunBearingCalculator(heavy);
    QVERIFY(!r.converged);
    QVERIFY(r.status.find("exceeds") != std::string::npos);
  }
};

QTEST_GUILESS_MAIN(TestLubricationInput)
#include "test_lubrication_input.moc"
