#include "core/engine/crank_train.hpp"

#include <cmath>
#include <numbers>

#include "core/base/angles.hpp"
#include "core/base/input_error.hpp"
#include "core/coupling/lubricated_big_end_element.hpp"
#include "core/multibody/joints.hpp"

namespace filmdyn::engine {

using multibody::Body;
using multibody::BodyState;
using multibody::kGround;

CrankTrain BuildCrankTrain(const EngineCase& c, double rpm, PressureCurve pressure,
                           const LubricatedJointFactories& factories) {
  const CrankTrainGeometry& g = c.geometry;
  RequirePositive("operating.rpm", rpm, "rpm");
  if (g.rod_length <= g.crank_radius + std::abs(g.pin_offset)) {
    throw InputError("geometry.rod_length", FormatValue(g.rod_length),
                     "must exceed crank_radius + |pin_offset| = " +
                         FormatValue(g.crank_radius + std::abs(g.pin_offset)) + " [m]");
  }
  CrankTrain train;
  train.system = std::make_unique<multibody::MultibodySystem>();
  multibody::MultibodySystem& sys = *train.system;
  CrankTrainLayout& lay = train.layout;
  lay.omega = rpm * 2.0 * std::numbers::pi / 60.0;
  lay.crank = sys.AddBody(Body{"crank", g.crank_mass, g.crank_inertia});
  lay.rod = sys.AddBody(Body{"connecting rod", g.rod_mass, g.rod_inertia});
  lay.piston = sys.AddBody(Body{"piston", g.piston_mass, g.piston_inertia});
  lay.crank_main_journal = {0.0, -g.crank_com_radius};
  lay.crank_pin = {0.0, g.crank_radius - g.crank_com_radius};
  lay.rod_big_end = {0.0, -g.rod_com_from_big_end};
  lay.rod_small_end = {0.0, g.rod_length - g.rod_com_from_big_end};
  lay.piston_pin_point = {g.pin_offset - g.piston_com_lateral_offset,
                          -(g.skirt_top_to_pin - g.skirt_top_to_com)};
  lay.piston_axis_point = {-g.piston_com_lateral_offset, 0.0};

  using multibody::DrivingConstraint;
  using multibody::PrismaticJoint;
  using multibody::RevoluteJoint;
  lay.main_bearing = sys.AddConstraint(std::make_unique<RevoluteJoint>(
      "main bearing", kGround, Eigen::Vector2d::Zero(), lay.crank, lay.crank_main_journal));
  lay.crank_drive = sys.AddConstraint(std::make_unique<DrivingConstraint>(
      "crank drive", kGround, lay.crank,
      multibody::AngleLaw::ConstantSpeed(c.operating.start_crank_angle, lay.omega)));
  lay.piston_pin = sys.AddConstraint(std::make_unique<RevoluteJoint>(
      "piston pin", lay.rod, lay.rod_small_end, lay.piston, lay.piston_pin_point));
  if (c.big_end.model == JointModel::kIdeal) {
    lay.big_end = sys.AddConstraint(std::make_unique<RevoluteJoint>(
        "big end", lay.crank, lay.crank_pin, lay.rod, lay.rod_big_end));
  }
  if (c.skirt.model == JointModel::kIdeal) {
    lay.liner = sys.AddConstraint(std::make_unique<PrismaticJoint>(
        "liner", kGround, Eigen::Vector2d::Zero(), Eigen::Vector2d(0.0, 1.0), lay.piston,
        lay.piston_axis_point));
  }
  sys.AddForceElement(
      std::make_unique<multibody::Gravity>(sys.Masses(), Eigen::Vector2d(0.0, -g.gravity)));
  auto gas =
      std::make_unique<GasForce>(std::move(pressure), c.operating.crankcase_pressure,
                                 g.liner_radius, lay.crank, 0.0, lay.piston, lay.piston_axis_point);
  train.gas_force = gas.get();
  sys.AddForceElement(std::move(gas));
  auto add_lubricated = [&](const JointForceFactory& factory, const char* field) {
    if (!factory) {
      throw InputError(field, "lubricated",
                       "no film model was given for this joint (BuildCrankTrain needs the "
                       "factories of engine::FilmJointFactories()); use \"ideal\" otherwise");
    }
    auto element = factory(c, lay);
    multibody::JointForceElement* raw = element.get();
    sys.AddForceElement(std::move(element));
    return raw;
  };
  if (c.skirt.model == JointModel::kLubricated) {
    train.skirt_element = add_lubricated(factories.skirt, "skirt.model");
  }
  if (c.big_end.model == JointModel::kLubricated) {
    train.big_end_element = add_lubricated(factories.big_end, "big_end.model");
  }
  sys.SetBaumgarte({c.solver.baumgarte_alpha, c.solver.baumgarte_beta});

  // Initial guess from the closed-form slider crank (the assembly then makes it exact).
  const double phi = c.operating.start_crank_angle;
  const double span = g.pin_offset + g.crank_radius * std::sin(phi);
  const double rod_angle = -std::asin(span / g.rod_length);
  multibody::SystemState state(sys.NumBodies());
  BodyState crank, rod, piston;
  crank.q << -g.crank_com_radius * std::sin(phi), g.crank_com_radius * std::cos(phi), phi;
  const Eigen::Vector2d pin_crank = g.crank_radius * Eigen::Vector2d(-std::sin(phi), std::cos(phi));
  const Eigen::Vector2d rod_com =
      pin_crank +
      g.rod_com_from_big_end * Eigen::Vector2d(-std::sin(rod_angle), std::cos(rod_angle));
  rod.q << rod_com, rod_angle;
  const Eigen::Vector2d pin =
      pin_crank + g.rod_length * Eigen::Vector2d(-std::sin(rod_angle), std::cos(rod_angle));
  piston.q << pin - lay.piston_pin_point, 0.0;
  state.SetBody(lay.crank, crank);
  state.SetBody(lay.rod, rod);
  state.SetBody(lay.piston, piston);
  state.v.setZero();
  // With a clearance joint the guess is the centred (ideal) position; Assemble keeps it.
  sys.Assemble(0.0, &state);
  train.initial_state = state;
  return train;
}

namespace {

struct SecondaryMotion {
  double lateral = 0.0, tilt = 0.0, lateral_velocity = 0.0, tilt_rate = 0.0;
  double com_lateral_velocity = 0.0;  // X velocity of the centre of mass (the body's own ẋ)
};

// The piston's secondary motion: e0 of the paper's eq. 2 — the piston axis at pin height, i.e.
// the pin minus C_p along the tilted pin arm (= pin X − C_p to second order in the tilt) — the
// tilt and their rates.
SecondaryMotion SecondaryMotionOf(const BodyState& piston, const CrankTrainLayout& lay,
                                  const EngineCase& c) {
  const Eigen::Vector2d arm = multibody::Rotation(piston.Angle()) * lay.piston_pin_point;
  SecondaryMotion m;
  m.lateral = piston.q[0] + arm.x() - c.geometry.pin_offset * std::cos(piston.Angle());
  m.lateral_velocity = multibody::PointVelocity(piston, lay.piston_pin_point).x() +
                       c.geometry.pin_offset * std::sin(piston.Angle()) * piston.AngularVelocity();
  m.tilt = piston.Angle();
  m.tilt_rate = piston.AngularVelocity();
  m.com_lateral_velocity = piston.Velocity().x();
  return m;
}

}  // namespace

CrankTrainSample SampleCrankTrain(CrankTrain& train, const EngineCase& c, double t,
                                  const multibody::SystemState& integrated) {
  multibody::MultibodySystem& sys = *train.system;
  const CrankTrainLayout& lay = train.layout;
  CrankTrainSample s;
  s.constraint_violation = sys.PositionViolation(t, integrated).lpNorm<Eigen::Infinity>();
  // The applied forces — the film joints above all — are evaluated at the integrated state: the
  // film outputs and the forces in the reactions are the ones that acted in the integration.
  // Kinematics, accelerations and reactions are then taken on the state projected onto Φ = 0,
  // Φ̇ = 0 with those forces, so the Baumgarte feedback β²Φ (1e8 · 5e-9 m = 0.5 m/s² with the
  // paper's β) does not pollute them. Evaluating the films at the projected state instead moves
  // the journal by the drift (~5e-9 m, 1-2 % of a 0.4 µm film): the cycle energy balance was
  // then off by 3.4 J (0.9 % of the gas work) and the film forces' ideal limit by up to 10 %
  // (docs/validation/coupling.md (a), (c)).
  const Eigen::VectorXd applied = sys.AppliedForces(t, integrated);
  multibody::SystemState state = integrated;
  sys.Assemble(t, &state, 1e-14);
  const multibody::DynamicsEvaluation eval = sys.EvaluateWithForces(t, state, applied);
  s.time = t;
  s.crank_angle = train.gas_force->CrankAngle(state);
  const BodyState piston = state.Body(lay.piston);
  const Eigen::Matrix2d rot_p = multibody::Rotation(piston.Angle());
  const Eigen::Vector2d pin_arm = rot_p * lay.piston_pin_point;
  s.piston_position = piston.q[1] + pin_arm.y();
  s.piston_velocity = multibody::PointVelocity(piston, lay.piston_pin_point).y();
  const double wp = piston.AngularVelocity();
  const Eigen::Vector2d pin_acc = eval.acceleration.segment<2>(3 * lay.piston) +
                                  eval.acceleration[3 * lay.piston + 2] * multibody::Perp(pin_arm) -
                                  wp * wp * pin_arm;
  s.piston_acceleration = pin_acc.y();
  // Secondary motion (zero for the ideal liner). With a lubricated skirt, of the
  // integrated state the film was solved at, so that a sample's piston state and its film
  // forces belong together (the projected state's lateral velocity differs by the constraint
  // drift, up to ~2e-5 m/s: a few per cent of the squeeze part of the film force).
  const SecondaryMotion secondary = SecondaryMotionOf(
      train.skirt_element != nullptr ? integrated.Body(lay.piston) : piston, lay, c);
  s.piston_lateral = secondary.lateral;
  s.piston_lateral_velocity = secondary.lateral_velocity;
  s.piston_tilt = secondary.tilt;
  s.piston_tilt_rate = secondary.tilt_rate;
  s.piston_com_lateral_velocity = secondary.com_lateral_velocity;
  const BodyState rod = state.Body(lay.rod);
  s.rod_angle = rod.Angle();
  s.rod_angular_velocity = rod.AngularVelocity();
  s.rod_angular_acceleration = eval.acceleration[3 * lay.rod + 2];
  s.cylinder_pressure = train.gas_force->CylinderPressure(s.crank_angle);
  s.gas_force = train.gas_force->Force(s.crank_angle);
  s.gas_power = -s.gas_force * multibody::PointVelocity(piston, lay.piston_axis_point).y();
  const Eigen::VectorXd& lambda = eval.multipliers;
  if (lay.liner >= 0) {
    const multibody::JointReaction r = sys.Reaction(lay.liner, t, state, lambda);
    s.liner_force_on_piston = r.on_j.head<2>();
    // Moment about the pin = moment about the CoM + (r_CoM − r_pin) × F.
    s.liner_moment_about_pin = r.on_j[2] + multibody::Cross(-pin_arm, r.on_j.head<2>());
  }
  if (lay.big_end >= 0) {
    s.big_end_force_on_rod = sys.Reaction(lay.big_end, t, state, lambda).on_j.head<2>();
  }
  s.pin_force_on_piston = sys.Reaction(lay.piston_pin, t, state, lambda).on_j.head<2>();
  s.main_bearing_force_on_crank = sys.Reaction(lay.main_bearing, t, state, lambda).on_j.head<2>();
  s.crank_torque = sys.Reaction(lay.crank_drive, t, state, lambda).on_j[2];
  // Film joints were just evaluated at the integrated state by sys.AppliedForces.
  for (multibody::JointForceElement* element : {train.skirt_element, train.big_end_element}) {
    if (auto* reporter = dynamic_cast<coupling::FilmReporter*>(element)) {
      reporter->ReportFilm(&s.skirt, &s.bearing);
      reporter->TakeSteps(t, &s.skirt, &s.bearing);
    }
  }
  if (s.bearing.present) s.big_end_force_on_rod = s.bearing.force_on_rod;
  if (s.skirt.present) {
    s.liner_force_on_piston = {s.skirt.normal_force, -s.skirt.friction_force};
    s.liner_moment_about_pin = s.skirt.moment_about_pin;
  }
  return s;
}

MotionSample SampleMotion(const CrankTrain& train, const EngineCase& c, double t,
                          const multibody::SystemState& state) {
  const CrankTrainLayout& lay = train.layout;
  MotionSample m;
  m.time = t;
  m.crank_angle = train.gas_force->CrankAngle(state);
  if (train.skirt_element != nullptr) {
    const SecondaryMotion secondary = SecondaryMotionOf(state.Body(lay.piston), lay, c);
    m.piston_present = true;
    m.piston_lateral = secondary.lateral;
    m.piston_tilt = secondary.tilt;
    m.piston_lateral_velocity = secondary.lateral_velocity;
    m.piston_tilt_rate = secondary.tilt_rate;
    m.piston_com_lateral_velocity = secondary.com_lateral_velocity;
  }
  if (const auto* big_end =
          dynamic_cast<const coupling::LubricatedBigEndElement*>(train.big_end_element)) {
    BearingFilmSample b;
    big_end->ReportMotion(state.Body(lay.crank), state.Body(lay.rod), &b);
    m.journal_present = true;
    m.journal_ecc_rod = b.journal_ecc_rod;
    m.eps = b.eps;
    m.eps_dot = b.eps_dot;
  }
  return m;
}

MotionSample MotionOf(const CrankTrainSample& s) {
  MotionSample m;
  m.time = s.time;
  m.crank_angle = s.crank_angle;
  m.piston_present = s.skirt.present;
  if (m.piston_present) {
    m.piston_lateral = s.piston_lateral;
    m.piston_tilt = s.piston_tilt;
    m.piston_lateral_velocity = s.piston_lateral_velocity;
    m.piston_tilt_rate = s.piston_tilt_rate;
    m.piston_com_lateral_velocity = s.piston_com_lateral_velocity;
  }
  m.journal_present = s.bearing.present;
  if (m.journal_present) {
    m.journal_ecc_rod = s.bearing.journal_ecc_rod;
    m.eps = s.bearing.eps;
    m.eps_dot = s.bearing.eps_dot;
  }
  return m;
}

std::size_t LapStart(const std::vector<double>& crank_angles_deg, std::size_t from) {
  std::size_t start = from;
  for (std::size_t k = from + 1; k < crank_angles_deg.size(); ++k)
    if (crank_angles_deg[k] < crank_angles_deg[k - 1]) start = k;
  return start;
}

double CycleCrankAngleDeg(double crank_angle) {
  double deg = std::fmod(crank_angle * kDegreesPerRadian, 720.0);
  if (deg < 0) deg += 720.0;
  // To 1e-9 °CA, far below what any run resolves: an output step's angle reads 411, not the
  // 411.0000000000002 of radians turned into degrees.
  deg = std::round(deg * 1e9) / 1e9;
  if (deg > 720.0 - 1e-9) deg = 0.0;
  return deg;
}

}  // namespace filmdyn::engine
