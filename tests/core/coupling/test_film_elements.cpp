// The lubricated joints as force elements: kinematics of e0/γ and of the
// eccentricity, Jacobians against central differences (JointJacobianMismatch), robustness at
// ε → 0 and past ε_max, virtual-work consistency of the skirt wrench; the case's ovality table and
// per-surface E, ν reach the solvers; the phase-in of a film and the last evaluation both joints
// keep. Coarse meshes: fast.
#include <QtTest>

#include <cmath>
#include <vector>

#include "core/coupling/film_joint.hpp"
#include "core/coupling/lubricated_big_end_element.hpp"
#include "core/coupling/lubricated_skirt_element.hpp"
#include "core/coupling/pressure_law_ramp.hpp"
#include "core/engine/crank_train.hpp"
#include "core/engine/film_joints.hpp"
#include "core/io/case_file.hpp"
#include "core/lubrication/surface_film.hpp"

using namespace filmdyn;
using multibody::BodyState;

namespace {

engine::EngineCase CoarseCase() {
  engine::EngineCase c = io::LoadCase({}).value;
  c.skirt.mesh_thrust = c.skirt.mesh_anti = 10;
  c.skirt.mesh_axial = 12;
  c.big_end.mesh_theta = 24;
  c.big_end.mesh_z = 6;
  // The element tests build the ideal crank train for its layout and add film elements by hand.
  c.skirt.model = c.big_end.model = engine::JointModel::kIdeal;
  return c;
}

// A piston displaced/tilted toward the thrust side, moving down with a lateral rate.
BodyState PistonState(const engine::EngineCase& c, const engine::CrankTrainLayout& lay) {
  BodyState p;
  const double theta = 4e-4;
  const Eigen::Vector2d arm = multibody::Rotation(theta) * lay.piston_pin_point;
  p.q << c.geometry.pin_offset * std::cos(theta) + 6e-6 - arm.x(), 0.15, theta;
  p.v << 0.02, -12.0, 3.0;
  return p;
}

// E' = 2/[(1−ν1²)/E1 + (1−ν2²)/E2] (Hu et al. 1994), written out independently.
double HuCompositeModulus(double e1, double nu1, double e2, double nu2) {
  return 2.0 / ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2);
}

// Asperity pressure the joint's film model gives at film thickness h.
double ContactPressureOf(const lubrication::FilmFactorModel& film, double h) {
  return film.At(h).contact_pressure;
}

// The velocity columns (v_i, v_j) of the element's Jacobian against central differences
// (multibody::JointJacobianByDifferences, step h·max(1, |v|)), as the largest difference over
// that block's largest entry: the columns that carry the film's squeeze damping, which dominates
// a stiff film's Newton matrix however small the position columns' share.
double VelocityColumnsMismatch(multibody::JointForceElement& element,
                               const multibody::JointForceInput& in, double h) {
  multibody::JointForceOutput analytic;
  element.EvaluateJoint(in, true, &analytic);
  const Eigen::Matrix<double, 6, 6> numeric =
      multibody::JointJacobianByDifferences(element, in, h).rightCols<6>();
  const Eigen::Matrix<double, 6, 6> block = analytic.jacobian.rightCols<6>();
  return (block - numeric).cwiseAbs().maxCoeff() / numeric.cwiseAbs().maxCoeff();
}

// The coarse case at a cranking speed's viscosity (a cold, thick oil): the films' squeeze
// damping is at its stiffest against the sliding's slow wedge.
engine::EngineCase ColdCoarseCase() {
  engine::EngineCase c = CoarseCase();
  c.big_end.mesh_theta = 100;  // the default case's big-end mesh: its cavitated set
  c.big_end.mesh_z = 10;       // switches at the resolution of a run
  c.lubricant.viscosity = 0.2;
  return c;
}

}  // namespace

class TestFilmElements : public QObject {
  Q_OBJECT
 private slots:
  // The phase-in of a pressure law over an engine run's start: scale 0 at t = 0, 1 from the end
  // time on, smooth and monotone between; the law changes only when the time does, and results
  // depend on the time only until the end.
  void pressureLawRampPhasesTheLawIn() {
    const lubrication::PressureViscosity barus = lubrication::PressureViscosity::Barus(2e-8);
    coupling::PressureLawRamp ramp(barus, 0.01);
    QCOMPARE(ramp.Scale(0.0), 0.0);
    QCOMPARE(ramp.Scale(0.01), 1.0);
    QCOMPARE(ramp.Scale(0.005), 0.5);
    double last = 0.0;
    for (int k = 1; k <= 100; ++k) {
      const double s = ramp.Scale(1e-4 * k);
      QVERIFY(s >= last);
      last = s;
    }
    QVERIFY(ramp.Update(0.0));
    QVERIFY(!ramp.law().active());
    QVERIFY(!ramp.Update(0.0));
    QVERIFY(ramp.Update(0.005));
    QCOMPARE(ramp.law().InitialCoefficient(), 1e-8);
    QVERIFY(ramp.VariesAfter(0.009));
    QVERIFY(!ramp.VariesAfter(0.01));
    QVERIFY(ramp.Update(0.02));
    QCOMPARE(ramp.law().InitialCoefficient(), 2e-8);
    QVERIFY(!ramp.Update(0.03));
    // Without a law nothing varies; an end time of 0 gives the full law from the start.
    QVERIFY(!coupling::PressureLawRamp({}, 0.01).VariesAfter(0.0));
    coupling::PressureLawRamp at_once(barus, 0.0);
    QVERIFY(!at_once.Update(0.0));
    QCOMPARE(at_once.law().InitialCoefficient(), 2e-8);
  }

  // A film's phase-in: the law as the ramp gives it, the compliance scale from 0 to 1 over the
  // run-in for elastic surfaces (never set for rigid ones), and results time-dependent until the
  // later of the two ends.
  void filmPhaseInSetsTheLawAndTheComplianceOfTheTime() {
    struct Recorder {
      std::vector<double> law_coefficients, compliance_scales;
      void SetPressureViscosity(const lubrication::PressureViscosity& law) {
        law_coefficients.push_back(law.InitialCoefficient());
      }
      void SetComplianceScale(double scale) { compliance_scales.push_back(scale); }
    };
    const lubrication::PressureViscosity barus = lubrication::PressureViscosity::Barus(2e-8);
    coupling::FilmPhaseIn elastic(barus, 0.01, false, 0.02);
    Recorder r;
    elastic.Apply(0.005, r);
    elastic.Apply(0.01, r);
    elastic.Apply(0.03, r);
    QCOMPARE(r.law_coefficients.size(), std::size_t{2});  // set when the law changes only
    QCOMPARE(r.law_coefficients[0], 1e-8);
    QCOMPARE(r.law_coefficients[1], 2e-8);
    QCOMPARE(r.compliance_scales,
             (std::vector<double>{coupling::RunInScale(0.005, 0.02), 0.5, 1.0}));
    QVERIFY(elastic.VariesAfter(0.015));  // the law is whole, the compliance not yet
    QVERIFY(!elastic.VariesAfter(0.02));
    coupling::FilmPhaseIn rigid(barus, 0.01, true, 0.02);
    Recorder rr;
    rigid.Apply(0.005, rr);
    QVERIFY(rr.compliance_scales.empty());
    QVERIFY(!rigid.VariesAfter(0.01));
    QVERIFY(!coupling::FilmPhaseIn().VariesAfter(0.0));
  }

  // A joint's last evaluation serves a repeated request for the same state (the time too when
  // results depend on it), with a Jacobian only when one was kept; an evaluation whose Jacobian
  // was never completed (its film solves failed) still serves its own wrenches, never an earlier
  // state's; an accepted step drops it.
  void lastEvaluationServesOnlyItsOwnState() {
    coupling::LastEvaluation last;
    multibody::JointForceOutput out;
    multibody::JointForceInput a;
    a.t = 1.0;
    a.body_j.q << 1e-6, 0.0, 0.0;
    QVERIFY(!last.Serve(a, false, false, &out));  // nothing kept
    multibody::JointForceOutput first;
    first.wrench_j << 1.0, 2.0, 3.0;
    last.Keep(a, first);
    QVERIFY(last.Serve(a, true, false, &out));
    QCOMPARE(out.wrench_j, first.wrench_j);
    QVERIFY(!last.Serve(a, true, true, &out));  // no Jacobian kept
    multibody::JointForceInput later = a;
    later.t = 2.0;
    QVERIFY(last.Serve(later, false, false, &out));  // the time does not matter
    QVERIFY(!last.Serve(later, true, false, &out));  // it does
    multibody::JointForceInput moved = a;
    moved.body_i.v[2] = 1.0;  // either body's state counts
    QVERIFY(!last.Serve(moved, false, false, &out));
    QVERIFY(last.SolverHoldsAt(1.0) && !last.SolverHoldsAt(2.0));

    // The next state's wrenches kept, its Jacobian's difference solves begun and never finished.
    multibody::JointForceOutput second;
    second.wrench_j << 4.0, 5.0, 6.0;
    second.jacobian.setConstant(7.0);
    last.Keep(moved, second);
    last.SolverMovedOn();
    QVERIFY(!last.SolverHoldsAt(1.0) && last.SolverMovedOnFromIt());
    QVERIFY(last.Serve(moved, true, false, &out));
    QCOMPARE(out.wrench_j, second.wrench_j);
    QVERIFY(out.jacobian.isZero());  // a Jacobian not kept is never served
    last.KeepJacobian(second);
    QVERIFY(last.Serve(moved, true, true, &out));
    QCOMPARE(out.jacobian, second.jacobian);
    QVERIFY(last.Serve(moved, true, false, &out));
    QVERIFY(out.jacobian.isZero());  // not asked for
    last.SolverHoldsIt();
    QVERIFY(last.SolverHoldsAt(1.0) && !last.SolverMovedOnFromIt());

    last.Drop();
    QVERIFY(!last.Serve(moved, false, false, &out));
    QVERIFY(!last.SolverHoldsAt(1.0) && !last.SolverMovedOnFromIt());
    QCOMPARE(last.input().t, 1.0);  // the time of the last evaluation stays readable
  }

  void skirtOvalityFromTheCaseWidensTheFilm() {
    engine::EngineCase c = CoarseCase();
    lubrication::SkirtSolver round(engine::SkirtConfigFromCase(c));
    // Gap grows linearly from 0 on the thrust axis to 30 µm at the pin axis (α = π/2).
    c.skirt.ovality_alpha = {0.0, M_PI / 2};
    c.skirt.ovality_h = {0.0, 30e-6};
    lubrication::SkirtSolver oval(engine::SkirtConfigFromCase(c));
    lubrication::SkirtState centred;  // e0 = γ = 0: h = c_p + h_profile(y) + h_ovality(α)
    centred.piston_velocity = -5.0;
    round.Solve(centred);
    oval.Solve(centred);
    const auto& alpha = oval.alpha();
    const auto& y = oval.mesh().y;
    int at_thrust = -1, at_pin_axis = -1;
    for (int k = 0; k < int(alpha.size()); ++k) {
      // The film differs from the round skirt's exactly by the table, node by node.
      const double expected = std::min(alpha[k], M_PI / 2) / (M_PI / 2) * 30e-6;
      QVERIFY(std::abs(oval.film_thickness()[k] - round.film_thickness()[k] - expected) < 1e-15);
      if (at_thrust < 0 && alpha[k] == 0.0 && y[k] > 0.0) at_thrust = k;
    }
    QVERIFY(at_thrust >= 0);
    for (int k = 0; k < int(alpha.size()); ++k) {
      if (std::abs(alpha[k] - M_PI / 2) < 1e-12 && y[k] == y[at_thrust]) at_pin_axis = k;
    }
    QVERIFY2(at_pin_axis >= 0, "the relief mesh (2 elements, α1 = α2) has a node at π/2");
    // Same y, so the profile cancels: h(π/2) − h(0) is the table value.
    QVERIFY(std::abs(oval.film_thickness()[at_pin_axis] - oval.film_thickness()[at_thrust] -
                     30e-6) < 1e-15);
    QVERIFY(std::abs(round.film_thickness()[at_pin_axis] - round.film_thickness()[at_thrust]) <
            1e-15);
  }

  void contactPressureUsesTheCompositeModulusOfBothSurfaces() {
    engine::EngineCase c = CoarseCase();
    const double k = c.lubricant.greenwood_tripp_k;
    // Skirt: Al-Si 75 GPa/0.33 on cast iron 110 GPa/0.26 → E' = 98.24 GPa, within 0.05 % of the
    // 98.2 GPa the case gave as one number before.
    const auto& sk = c.skirt;
    const double e_skirt =
        HuCompositeModulus(sk.modulus_skirt, sk.poisson_skirt, sk.modulus_liner, sk.poisson_liner);
    QVERIFY(std::abs(e_skirt / 9.82e10 - 1.0) < 5e-4);
    const auto skirt_film = engine::SkirtConfigFromCase(c).film;
    const double sigma_s = std::hypot(sk.roughness_skirt, sk.roughness_liner);
    for (double H : {0.5, 1.5, 3.0}) {
      const double expected = k * e_skirt * lubrication::GreenwoodTrippF52Fit(H);
      QVERIFY(std::abs(ContactPressureOf(*skirt_film, H * sigma_s) / expected - 1.0) < 1e-12);
    }
    // Big end: steel 210 GPa/0.30 in Al-Sn 70 GPa/0.33 → E' = 117.21 GPa (was 117.2 GPa).
    const auto& be = c.big_end;
    const double e_big_end = HuCompositeModulus(be.modulus_journal, be.poisson_journal,
                                                be.modulus_bearing, be.poisson_bearing);
    QVERIFY(std::abs(e_big_end / 1.172e11 - 1.0) < 5e-4);
    const auto bearing_film = engine::BearingConfigFromCase(c).film;
    const double sigma_b = std::hypot(be.roughness_journal, be.roughness_bearing);
    const double expected_b = k * e_big_end * lubrication::GreenwoodTrippF52Fit(1.0);
    QVERIFY(std::abs(ContactPressureOf(*bearing_film, sigma_b) / expected_b - 1.0) < 1e-12);
    // Each surface's own E and ν count: a stiffer liner and a different ν change p_c by E'.
    c.skirt.modulus_liner = 200e9;
    c.skirt.poisson_skirt = 0.2;
    const double e_new = HuCompositeModulus(75e9, 0.2, 200e9, 0.26);
    const double h = 1.5 * sigma_s;
    QVERIFY(std::abs(ContactPressureOf(*engine::SkirtConfigFromCase(c).film, h) /
                         ContactPressureOf(*skirt_film, h) -
                     e_new / e_skirt) < 1e-12);
  }

  void skirtKinematicsMatchTheSampleDefinition() {
    const engine::EngineCase c = CoarseCase();
    engine::CrankTrain train = engine::BuildCrankTrain(c, 6000, engine::PressureCurve{});
    auto element = engine::MakeLubricatedSkirt(c, train.layout);
    auto& skirt = dynamic_cast<coupling::LubricatedSkirtElement&>(*element);
    const BodyState p = PistonState(c, train.layout);
    const coupling::SkirtKinematics k = skirt.Kinematics(p);
    QVERIFY(std::abs(k.state.e0 - 6e-6) < 1e-15);  // axis at pin height: pin X − C_p cos θ
    QVERIFY(std::abs(k.state.gamma - std::sin(4e-4)) < 1e-15);
    // u_p (+ toward the crank) of a piston moving down at 12 m/s.
    QVERIFY(std::abs(k.state.piston_velocity - 12.0) < 0.01);
    // Rates = time derivatives of the positions (finite difference along the velocity).
    BodyState later = p;
    const double dt = 1e-7;
    later.q += dt * p.v;
    const coupling::SkirtKinematics k2 = skirt.Kinematics(later);
    QVERIFY(std::abs((k2.state.e0 - k.state.e0) / dt - k.state.e0_dot) < 1e-6);
    QVERIFY(std::abs((k2.state.gamma - k.state.gamma) / dt - k.state.gamma_dot) < 1e-6);
    // Smallest gap: the thrust edge at the barrel's waist (y = 14 mm, no profile drop; a mesh
    // line), c_p − (e0 + (y − a_p) γ).
    const double cp = engine::SkirtClearance(c);
    const double expected = cp - (6e-6 + (0.014 - c.geometry.skirt_top_to_pin) * std::sin(4e-4));
    QVERIFY(std::abs(k.min_gap - expected) < 1e-12);
  }

  // An ovality table that opens the gap at the thrust axis (20 um there, none from 0.3 rad on):
  // the smallest gap of the skirt moved toward thrust lies off the axis, where the film touches
  // first. It is the smallest over every node of the panels (it was taken on the thrust and
  // anti-thrust centre lines only: here the anti-thrust line's 31.9 um against 18.4 um).
  void skirtSmallestGapIsFoundOffTheAxis() {
    engine::EngineCase c = CoarseCase();
    c.skirt.ovality_alpha = {0.0, 0.3};
    c.skirt.ovality_h = {20e-6, 0.0};
    engine::CrankTrain train = engine::BuildCrankTrain(c, 6000, engine::PressureCurve{});
    auto element = engine::MakeLubricatedSkirt(c, train.layout);
    auto& skirt = dynamic_cast<coupling::LubricatedSkirtElement&>(*element);
    const coupling::SkirtKinematics k = skirt.Kinematics(PistonState(c, train.layout));
    const lubrication::SkirtSolver& solver = skirt.solver();
    const lubrication::SkirtGeometry& g = solver.config().geometry;
    double expected = 1e300, alpha_at = -1.0, on_axis = 1e300;
    for (int p = 0; p < lubrication::SkirtSolver::kPanels; ++p)
      for (const int node : solver.panel_nodes(p)) {
        const double a = solver.alpha()[node], y = solver.mesh().y[node];
        const double gap = g.radial_clearance + g.profile(y) + g.ovality(a) -
                           (k.state.e0 + (y - g.pin_position) * k.state.gamma) * std::cos(a);
        if (gap < expected) expected = gap, alpha_at = a;
        if (a == 0.0) on_axis = std::min(on_axis, gap);
      }
    qInfo(
        "smallest gap %.4f um at %.3f rad (on the thrust axis %.4f um); reported %.4f um at "
        "%.3f rad",
        expected * 1e6, alpha_at, on_axis * 1e6, k.min_gap * 1e6, k.min_gap_alpha);
    QVERIFY(alpha_at >= 0.3 - 1e-12 && on_axis > expected + 10e-6);
    QVERIFY(std::abs(k.min_gap - expected) < 1e-15);
    QCOMPARE(k.min_gap_alpha, alpha_at);
  }

  void skirtWrenchIsTheVirtualWorkOfTheFilmForces() {
    const engine::EngineCase c = CoarseCase();
    engine::CrankTrain train = engine::BuildCrankTrain(c, 6000, engine::PressureCurve{});
    auto element = engine::MakeLubricatedSkirt(c, train.layout);
    auto& skirt = dynamic_cast<coupling::LubricatedSkirtElement&>(*element);
    multibody::JointForceInput in;
    in.body_j = PistonState(c, train.layout);
    multibody::JointForceOutput out;
    skirt.EvaluateJoint(in, false, &out);
    const lubrication::SkirtResult& r = skirt.last_result();
    QVERIFY(std::abs(r.lateral_force) > 1.0);  // the displaced skirt carries a load
    // Power: wrench · v = F ė0 + M γ̇ + F_f u_p for any velocity.
    const coupling::SkirtKinematics k = skirt.Kinematics(in.body_j);
    const double power = out.wrench_j.dot(in.body_j.v);
    const double film = r.lateral_force * k.state.e0_dot + r.moment_about_pin * k.state.gamma_dot +
                        r.friction_force * k.state.piston_velocity;
    QVERIFY(std::abs(power - film) <= 1e-9 * std::abs(film) + 1e-12);
    QVERIFY(power < 0.0);  // the film dissipates
  }

  void skirtJacobianMatchesCentralDifferences() {
    const engine::EngineCase c = CoarseCase();
    engine::CrankTrain train = engine::BuildCrankTrain(c, 6000, engine::PressureCurve{});
    auto element = engine::MakeLubricatedSkirt(c, train.layout);
    multibody::JointForceInput in;
    in.body_j = PistonState(c, train.layout);
    const double mismatch = multibody::JointJacobianMismatch(*element, in, 1e-9);
    qInfo("skirt Jacobian mismatch %.3e", mismatch);
    QVERIFY(mismatch < 2e-2);
  }

  // At 100 rpm and 0.2 Pa·s the films' squeeze damping makes an implicit step span ~100 of the
  // journal's and the skirt's relaxation times, so Newton's iteration converges only with
  // velocity columns accurate to well under 1 %; the difference increments follow the sliding's
  // own rates (a fixed 10 µm/s for the journal, 0.1 mm/s for the skirt gave secants 2–30 % off,
  // and such runs took ~0.4 million steps for 60 °CA).
  void velocityColumnsHoldAtCrankingSpeed() {
    const engine::EngineCase c = ColdCoarseCase();
    engine::CrankTrain train = engine::BuildCrankTrain(c, 100, engine::PressureCurve{});
    const double omega = 100.0 * 2.0 * M_PI / 60.0;
    {
      auto element = engine::MakeLubricatedBigEnd(c, train.layout);
      const multibody::SystemState& s = train.initial_state;
      multibody::JointForceInput in;
      in.body_i = s.Body(train.layout.crank);
      in.body_j = s.Body(train.layout.rod);
      in.body_i.v << 0.0, 0.0, omega;
      in.body_j.v << 0.0, 0.0, 0.31 * omega;
      // As a 100 rpm run's journal near bottom dead centre: ε = 0.953, moving off the wall at
      // 15 µm/s while the line of centres turns.
      in.body_i.q.head<2>() += Eigen::Vector2d(-2.415e-5, 4.110e-5);
      in.body_i.v.head<2>() += Eigen::Vector2d(-1.24e-5, -8.1e-6);
      const double mismatch = VelocityColumnsMismatch(*element, in, 1e-12);
      qInfo("big-end velocity columns at 100 rpm: mismatch %.3e", mismatch);
      QVERIFY(mismatch < 2e-3);
    }
    {
      auto element = engine::MakeLubricatedSkirt(c, train.layout);
      multibody::JointForceInput in;
      in.body_j = PistonState(c, train.layout);
      in.body_j.v << 2e-6, -0.2, 1e-4;
      const double mismatch = VelocityColumnsMismatch(*element, in, 1e-12);
      qInfo("skirt velocity columns at 100 rpm: mismatch %.3e", mismatch);
      QVERIFY(mismatch < 2e-3);
    }
  }

  void bigEndJacobianMatchesCentralDifferencesAndIsFiniteAtTheCentre() {
    const engine::EngineCase c = CoarseCase();
    engine::CrankTrain train = engine::BuildCrankTrain(c, 6000, engine::PressureCurve{});
    auto element = engine::MakeLubricatedBigEnd(c, train.layout);
    auto& big_end = dynamic_cast<coupling::LubricatedBigEndElement&>(*element);
    const multibody::SystemState& s = train.initial_state;
    multibody::JointForceInput in;
    in.body_i = s.Body(train.layout.crank);
    in.body_j = s.Body(train.layout.rod);
    in.body_i.v << 0.0, 0.0, 628.3;
    in.body_j.v << 0.0, 0.0, -150.0;
    const double cb = c.big_end.bearing_radius - c.big_end.journal_radius;
    // Journal moved to ε = 0.6 along (1, 1)/√2, approaching at 5 mm/s.
    BodyState moved = in.body_i;
    moved.q.head<2>() += 0.6 * cb * Eigen::Vector2d(1, 1).normalized();
    moved.v.head<2>() += 5e-3 * Eigen::Vector2d(1, 1).normalized();
    multibody::JointForceInput loaded = in;
    loaded.body_i = moved;
    const coupling::BigEndKinematics k = big_end.Kinematics(loaded.body_i, loaded.body_j);
    QVERIFY(std::abs(k.eps_true - 0.6) < 1e-9);
    const Eigen::Vector2d n = Eigen::Vector2d(1, 1).normalized();
    const Eigen::Vector2d ecc_rate =
        multibody::PointVelocity(loaded.body_i, train.layout.crank_pin) -
        multibody::PointVelocity(loaded.body_j, train.layout.rod_big_end);
    QVERIFY((k.ecc_rate - ecc_rate).norm() < 1e-12);
    QVERIFY(std::abs(k.state.eps_dot - n.dot(ecc_rate) / cb) < 1e-6);
    QVERIFY(std::abs(k.state.line_of_centres_angle - M_PI / 4) < 1e-12);
    const double mismatch = multibody::JointJacobianMismatch(big_end, loaded, 1e-9);
    qInfo("big-end Jacobian mismatch %.3e", mismatch);
    QVERIFY(mismatch < 2e-2);
    // Exactly centred, moving: finite forces and torques, ε̇ finite, φ̇ bounded.
    multibody::JointForceOutput out;
    multibody::JointForceInput centred = in;
    centred.body_i.v.head<2>() += Eigen::Vector2d(3e-3, 0.0);
    big_end.EvaluateJoint(centred, true, &out);
    QVERIFY(out.wrench_i.allFinite() && out.wrench_j.allFinite() && out.jacobian.allFinite());
    // Near the centre the force is continuous: e = 1e-9 c in two directions gives nearly the same.
    multibody::JointForceOutput a, b;
    multibody::JointForceInput pa = centred, pb = centred;
    pa.body_i.q.head<2>() += 1e-9 * cb * Eigen::Vector2d(1, 0);
    pb.body_i.q.head<2>() += 1e-9 * cb * Eigen::Vector2d(0, 1);
    big_end.EvaluateJoint(pa, false, &a);
    big_end.EvaluateJoint(pb, false, &b);
    QVERIFY(a.wrench_i.allFinite() && b.wrench_i.allFinite());
    // Past ε_max: the contact penalty pushes the journal back toward the centre.
    multibody::JointForceInput over = in;
    over.body_i.q.head<2>() += 1.0005 * cb * Eigen::Vector2d(0, 1);
    big_end.EvaluateJoint(over, false, &out);
    QVERIFY(out.wrench_i.allFinite());
    QVERIFY(out.wrench_i[1] < -1e5);
  }
};

QTEST_GUILESS_MAIN(TestFilmElements)
#include "test_film_elements.moc"
