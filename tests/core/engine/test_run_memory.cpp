// The memory a run will need, estimated from its case: the mesh sizes it assumes are those the
// solvers build (checked against the real solvers), the estimate grows with meshes, fields and
// the companion as it says, a case above the mesh maximum is an input error naming the fields, a
// run the machine cannot hold is refused naming the mesh, and a stop request interrupts the
// sparse factorisation of a large film between its blocks of rows.
#include <QtTest>

#include <chrono>
#include <cmath>

#include "core/base/input_error.hpp"
#include "core/engine/case_schema.hpp"
#include "core/engine/film_joints.hpp"
#include "core/engine/run_job.hpp"
#include "core/engine/run_memory.hpp"
#include "core/io/case_file.hpp"
#include "core/lubrication/sparse_ldlt.hpp"

using namespace filmdyn;

namespace {

engine::EngineCase DefaultCase() { return io::LoadCase({}).value; }

engine::EngineCase Lubricated(engine::EngineCase c) {
  engine::ApplyModel(engine::Model::kSkirtLbrbe, &c);
  return c;
}

// The 2-D Laplacian of an nx × ny grid (5-point stencil + a small shift), lower triangle.
Eigen::SparseMatrix<double> GridLaplacian(int nx, int ny) {
  const int n = nx * ny;
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(3 * n);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int k = j * nx + i;
      t.emplace_back(k, k, 4.01);
      if (i + 1 < nx) t.emplace_back(k + 1, k, -1.0);
      if (j + 1 < ny) t.emplace_back(k + nx, k, -1.0);
    }
  }
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

}  // namespace

class TestRunMemory : public QObject {
  Q_OBJECT
 private slots:
  void meshSizesAreThoseTheSolversBuild() {
    engine::EngineCase c = DefaultCase();
    for (int z : {10, 7}) {  // the symmetric half and the whole width
      c.big_end.mesh_z = z;
      const engine::FilmMeshSizes m = engine::FilmMeshSizesOf(c);
      const lubrication::BearingSolver bearing(engine::BearingConfigFromCase(c));
      QCOMPARE(m.big_end_unknowns, long(bearing.mesh().NodeCount()));
      QCOMPARE(m.big_end_surface_nodes, long(bearing.full_width().mesh.NodeCount()));
    }
    const engine::FilmMeshSizes m = engine::FilmMeshSizesOf(c);
    const lubrication::SkirtSolver skirt(engine::SkirtConfigFromCase(c));
    QCOMPARE(m.skirt_surface_nodes, long(skirt.mesh().NodeCount()));
    QCOMPARE(m.skirt_unknowns, long(skirt.panel_nodes(0).size() + skirt.panel_nodes(1).size()));
  }

  void estimateFollowsMeshesFieldsAndCompanion() {
    const engine::EngineCase c = Lubricated(DefaultCase());
    const engine::MemoryEstimate with_fields = engine::EstimateRunMemory(c, 1.0);
    const engine::MemoryEstimate no_fields = engine::EstimateRunMemory(c, 0.0);
    QCOMPARE(no_fields.field_bytes, 0.0);
    // One cycle (720 output steps at 1 °CA) of 3 floats per surface node of both joints.
    const engine::FilmMeshSizes m = engine::FilmMeshSizesOf(c);
    const double steps = std::ceil(4 * M_PI / c.solver.output_interval);
    QCOMPARE(steps, 720.0);
    QCOMPARE(with_fields.field_bytes,
             steps * double(m.skirt_surface_nodes + m.big_end_surface_nodes) * 12.0);
    QVERIFY(with_fields.companion_bytes > 0.0);
    // Half the elements: about a quarter of the unknowns (plus its own output samples).
    QVERIFY(with_fields.companion_bytes - with_fields.sample_bytes <
            0.5 * with_fields.solver_bytes);
    engine::EngineCase off = c;
    off.solver.error_estimate = 0;
    QCOMPARE(engine::EstimateRunMemory(off, 1.0).companion_bytes, 0.0);
    // The default run fits in a few hundred MB (measured: ~110 MB resident).
    QVERIFY(with_fields.total() > 80e6 && with_fields.total() < 400e6);
    // The big end at 4000 × 400 (804 000 unknowns, measured 1.40 GB resident with its program):
    // the estimate is above the measurement by less than 15 %.
    engine::EngineCase big = DefaultCase();
    engine::ApplyModel(engine::Model::kOnlyLbrbe, &big);
    big.big_end.mesh_theta = 4000;
    big.big_end.mesh_z = 400;
    big.solver.error_estimate = 0;
    const double total = engine::EstimateRunMemory(big, 0.0).total();
    QVERIFY2(total > 1.40e9 && total < 1.15 * 1.40e9, qPrintable(QString::number(total)));
    // Ideal joints hold no film.
    engine::EngineCase ideal = DefaultCase();
    engine::ApplyModel(engine::Model::kIdeal, &ideal);
    const engine::MemoryEstimate e = engine::EstimateRunMemory(ideal, 1.0);
    QCOMPARE(e.solver_bytes + e.field_bytes + e.companion_bytes, 0.0);
  }

  void meshesAboveTheMaximumAreInputErrors() {
    engine::EngineCase c = DefaultCase();
    c.big_end.mesh_theta = 5000;
    c.big_end.mesh_z = 2000;  // 5000 × 1001 unknowns
    try {
      engine::CheckCaseConsistency(c);
      QFAIL("a 5000 × 2000 big end was accepted");
    } catch (const InputError& e) {
      const QString what = e.what();
      QVERIFY2(what.contains("big_end.mesh_theta") && what.contains("5005000") &&
                   what.contains("500000"),
               qPrintable(what));
    }
    c = DefaultCase();
    c.skirt.mesh_thrust = 1500;
    c.skirt.mesh_anti = 1500;
    c.skirt.mesh_axial = 1000;
    QVERIFY_THROWS_EXCEPTION(InputError, engine::CheckCaseConsistency(c));
    c.skirt.mesh_axial = 150;  // (1501 + 1501) × 151 = 453 302 unknowns: accepted
    engine::CheckCaseConsistency(c);
  }

  void aRunTheMachineCannotHoldIsRefusedNamingTheMesh() {
    engine::EngineCase c = DefaultCase();
    engine::ApplyModel(engine::Model::kOnlyLbrbe, &c);
    const engine::MemoryEstimate e = engine::EstimateRunMemory(c, 1.0);
    engine::RequireMemory(c, e, e.total() * 1.01);  // fits
    try {
      engine::RequireMemory(c, e, e.total() * 0.5);
      QFAIL("refusal expected");
    } catch (const InputError& error) {
      const QString what = error.what();
      QVERIFY2(what.contains("big-end mesh") && what.contains("100 × 10") &&
                   what.contains("available") && what.contains("--no-fields"),
               qPrintable(what));
    }
    // What this machine reports is a positive size (Linux: MemAvailable).
    const double available = engine::AvailableMemoryBytes();
    QVERIFY(available > 0.0);
    // RunJob refuses before building anything: fields of 125 664 output steps per cycle on a
    // 2000 × 498 big end are terabytes.
    const io::LoadedCase loaded = io::LoadCase({});
    engine::EngineCase huge = loaded.value;
    huge.big_end.mesh_theta = 2000;
    huge.big_end.mesh_z = 498;
    huge.solver.output_interval = 1e-4;
    engine::RunConfig config = engine::MakeRunConfig(huge, engine::Model::kOnlyLbrbe, 6000,
                                                     io::PressureCurveForSpeed(loaded, 6000));
    config.field_callback = [](const engine::FieldFrame&) {};
    const auto start = std::chrono::steady_clock::now();
    QVERIFY_THROWS_EXCEPTION(
        InputError, engine::RunJob(config, [](const engine::RunProgress&) { return true; }));
    QVERIFY(std::chrono::steady_clock::now() - start < std::chrono::seconds(5));
  }

  void aStopRequestInterruptsALargeFactorisation() {
    // 400 × 400 = 160 000 unknowns: factorised in blocks of rows with the stop checked between.
    const Eigen::SparseMatrix<double> a = GridLaplacian(400, 400);
    Eigen::SparseMatrix<double> lower = a.triangularView<Eigen::Lower>();
    auto ldlt = lubrication::SparseLdlt::Create(lubrication::LdltBackend::kCholmodModify);
    ldlt->Analyze(lower);
    int checks = 0;
    QVERIFY_THROWS_EXCEPTION(StopRequested, ldlt->Factorize(lower, [&] { return ++checks >= 3; }));
    QCOMPARE(checks, 3);  // stopped at the third block boundary, not after the whole factor
    // The next factorisation starts afresh and is exact.
    QVERIFY(ldlt->Factorize(lower, [] { return false; }));
    Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(a.rows(), -1.0, 1.0), x;
    ldlt->Solve(b, x);
    const Eigen::VectorXd r = a.selfadjointView<Eigen::Lower>() * x - b;
    QVERIFY2(r.norm() < 1e-10 * b.norm(), qPrintable(QString::number(r.norm())));
    // Blocked and in one call give the same factor.
    auto whole = lubrication::SparseLdlt::Create(lubrication::LdltBackend::kCholmodModify);
    whole->Analyze(lower);
    QVERIFY(whole->Factorize(lower));
    Eigen::VectorXd y;
    whole->Solve(b, y);
    QVERIFY((x - y).norm() <= 1e-12 * y.norm());
  }
};

QTEST_APPLESS_MAIN(TestRunMemory)
#include "test_run_memory.moc"
