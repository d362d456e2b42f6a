#include "ui/case_editor/case_parameters.hpp"

#include <QObject>
#include <cmath>
#include <numbers>

#include "core/base/input_error.hpp"

namespace filmdyn::ui {

using engine::EngineCase;
using engine::JointModel;

QString CaseGroupTitle(CaseGroup group) {
  switch (group) {
    case CaseGroup::kGeometry:
      return QObject::tr("Geometry");
    case CaseGroup::kMasses:
      return QObject::tr("Masses and inertias");
    case CaseGroup::kSkirt:
      return QObject::tr("Piston skirt");
    case CaseGroup::kBigEnd:
      return QObject::tr("Big-end bearing");
    case CaseGroup::kLubricant:
      return QObject::tr("Lubricant");
    case CaseGroup::kOperating:
      return QObject::tr("Operating point");
    case CaseGroup::kSolver:
      return QObject::tr("Solver");
  }
  return {};
}

namespace {

constexpr double kMm = 1e-3;
constexpr double kUm = 1e-6;
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kMPa = 1e6;
constexpr double kGPa = 1e9;

using Check = std::function<void(const std::string&, double)>;

Check Positive(const char* unit) {
  return [unit](const std::string& f, double v) { RequirePositive(f, v, unit); };
}
Check NonNegative(const char* unit) {
  return [unit](const std::string& f, double v) { RequireNonNegative(f, v, unit); };
}
Check Finite(const char* unit) {
  return [unit](const std::string& f, double v) { RequireFinite(f, v, unit); };
}
Check Range(double lo, double hi, bool lo_open, bool hi_open, const char* unit) {
  return
      [=](const std::string& f, double v) { RequireInRange(f, v, lo, hi, lo_open, hi_open, unit); };
}

// Elastic constants per surface: the ranges of core's case file (E' needs E > 0, ν in (−1, 0.5)).
Check YoungsModulus() { return Range(0.0, 1e13, true, false, "Pa"); }
Check PoissonRatio() { return Range(-1.0, 0.5, true, true, ""); }

// Member-pointer accessors keep each row one line long.
template <typename Section, typename Field>
CaseParameter Row(CaseGroup group, std::string path, QString label, QString unit, double to_si,
                  Section EngineCase::*section, Field Section::*field, Check check) {
  CaseParameter p;
  p.group = group;
  p.path = std::move(path);
  p.label = std::move(label);
  p.unit = std::move(unit);
  p.to_si = to_si;
  p.integer = std::is_integral_v<Field>;
  p.get = [section, field](const EngineCase& c) { return double(c.*section.*field); };
  p.set = [section, field](EngineCase& c, double v) {
    if constexpr (std::is_integral_v<Field>) {
      c.*section.*field = std::isfinite(v) ? Field(std::lround(v)) : Field(-1);
    } else {
      c.*section.*field = v;
    }
  };
  p.check = std::move(check);
  return p;
}

std::vector<CaseParameter> MakeParameters() {
  using G = CaseGroup;
  using engine::BigEndCase;
  using engine::CrankTrainGeometry;
  using engine::LubricantCase;
  using engine::OperatingCase;
  using engine::SkirtCase;
  using engine::SolverCase;
  const auto geo = &EngineCase::geometry;
  const auto sk = &EngineCase::skirt;
  const auto be = &EngineCase::big_end;
  const auto lub = &EngineCase::lubricant;
  const auto op = &EngineCase::operating;
  const auto sol = &EngineCase::solver;
  std::vector<CaseParameter> p;
  // Geometry (Table I).
  p.push_back(Row(G::kGeometry, "geometry.crank_radius", "Crank radius L₁", "mm", kMm, geo,
                  &CrankTrainGeometry::crank_radius, Positive("m")));
  p.push_back(Row(G::kGeometry, "geometry.rod_length", "Connecting-rod length L₂", "mm", kMm, geo,
                  &CrankTrainGeometry::rod_length, Positive("m")));
  p.push_back(Row(G::kGeometry, "geometry.crank_com_radius", "Crank CoM radius L_r", "mm", kMm, geo,
                  &CrankTrainGeometry::crank_com_radius, NonNegative("m")));
  p.push_back(Row(G::kGeometry, "geometry.rod_com_from_big_end", "Rod CoM from big end L_c", "mm",
                  kMm, geo, &CrankTrainGeometry::rod_com_from_big_end, NonNegative("m")));
  p.push_back(Row(G::kGeometry, "geometry.pin_offset", "Pin offset C_p (+ thrust)", "mm", kMm, geo,
                  &CrankTrainGeometry::pin_offset, Finite("m")));
  p.push_back(Row(G::kGeometry, "geometry.piston_com_lateral_offset",
                  "Piston CoM offset c_g (+ thrust)", "mm", kMm, geo,
                  &CrankTrainGeometry::piston_com_lateral_offset, Finite("m")));
  p.push_back(Row(G::kGeometry, "geometry.skirt_top_to_pin", "Skirt top to pin a_p", "mm", kMm, geo,
                  &CrankTrainGeometry::skirt_top_to_pin, Finite("m")));
  p.push_back(Row(G::kGeometry, "geometry.skirt_top_to_com", "Skirt top to CoM b_p", "mm", kMm, geo,
                  &CrankTrainGeometry::skirt_top_to_com, Finite("m")));
  p.push_back(Row(G::kGeometry, "geometry.liner_radius", "Liner (bore) radius R_l", "mm", kMm, geo,
                  &CrankTrainGeometry::liner_radius, Positive("m")));
  p.push_back(Row(G::kGeometry, "geometry.gravity", "Gravity g", "m/s²", 1.0, geo,
                  &CrankTrainGeometry::gravity, NonNegative("m/s^2")));
  // Masses and inertias.
  p.push_back(Row(G::kMasses, "geometry.crank_mass", "Crank mass m₁", "kg", 1.0, geo,
                  &CrankTrainGeometry::crank_mass, Positive("kg")));
  p.push_back(Row(G::kMasses, "geometry.crank_inertia", "Crank inertia J₁ (CoM)", "kg·m²", 1.0, geo,
                  &CrankTrainGeometry::crank_inertia, Positive("kg*m^2")));
  p.push_back(Row(G::kMasses, "geometry.rod_mass", "Rod mass m₂", "kg", 1.0, geo,
                  &CrankTrainGeometry::rod_mass, Positive("kg")));
  p.push_back(Row(G::kMasses, "geometry.rod_inertia", "Rod inertia J₂ (CoM)", "kg·m²", 1.0, geo,
                  &CrankTrainGeometry::rod_inertia, Positive("kg*m^2")));
  p.push_back(Row(G::kMasses, "geometry.piston_mass", "Piston mass m₃", "kg", 1.0, geo,
                  &CrankTrainGeometry::piston_mass, Positive("kg")));
  p.push_back(Row(G::kMasses, "geometry.piston_inertia", "Piston inertia J₃ (CoM)", "kg·m²", 1.0,
                  geo, &CrankTrainGeometry::piston_inertia, Positive("kg*m^2")));
  // Skirt–liner joint.
  p.push_back(Row(G::kSkirt, "skirt.piston_radius", "Piston radius R", "mm", kMm, sk,
                  &SkirtCase::piston_radius, Positive("m")));
  p.push_back(Row(G::kSkirt, "skirt.length", "Skirt length L_skirt", "mm", kMm, sk,
                  &SkirtCase::length, Positive("m")));
  p.push_back(Row(G::kSkirt, "skirt.thrust_half_width", "Thrust panel half-width α₁", "°", kDeg, sk,
                  &SkirtCase::thrust_half_width,
                  Range(0, std::numbers::pi / 2, true, false, "rad")));
  p.push_back(Row(G::kSkirt, "skirt.anti_thrust_half_width", "Anti-thrust panel half-width α₂", "°",
                  kDeg, sk, &SkirtCase::anti_thrust_half_width,
                  Range(0, std::numbers::pi / 2, true, false, "rad")));
  p.push_back(Row(G::kSkirt, "skirt.roughness_skirt", "Skirt roughness σ_skirt", "µm", kUm, sk,
                  &SkirtCase::roughness_skirt, Positive("m")));
  p.push_back(Row(G::kSkirt, "skirt.roughness_liner", "Liner roughness σ_liner", "µm", kUm, sk,
                  &SkirtCase::roughness_liner, Positive("m")));
  p.push_back(Row(G::kSkirt, "skirt.peklenik", "Peklenik number γ", "–", 1.0, sk,
                  &SkirtCase::peklenik, Range(1.0 / 9.0, 9.0, false, false, "")));
  p.push_back(Row(G::kSkirt, "skirt.modulus_skirt", "Skirt Young's modulus E_skirt", "GPa", kGPa,
                  sk, &SkirtCase::modulus_skirt, YoungsModulus()));
  p.push_back(Row(G::kSkirt, "skirt.poisson_skirt", "Skirt Poisson ratio ν_skirt", "–", 1.0, sk,
                  &SkirtCase::poisson_skirt, PoissonRatio()));
  p.push_back(Row(G::kSkirt, "skirt.modulus_liner", "Liner Young's modulus E_liner", "GPa", kGPa,
                  sk, &SkirtCase::modulus_liner, YoungsModulus()));
  p.push_back(Row(G::kSkirt, "skirt.poisson_liner", "Liner Poisson ratio ν_liner", "–", 1.0, sk,
                  &SkirtCase::poisson_liner, PoissonRatio()));
  p.push_back(Row(G::kSkirt, "skirt.boundary_friction", "Boundary friction μ_f", "–", 1.0, sk,
                  &SkirtCase::boundary_friction, Range(0, 1, false, false, "")));
  // Big-end bearing.
  p.push_back(Row(G::kBigEnd, "big_end.bearing_radius", "Bearing radius R_b", "mm", kMm, be,
                  &BigEndCase::bearing_radius, Positive("m")));
  p.push_back(Row(G::kBigEnd, "big_end.journal_radius", "Journal radius R_j", "mm", kMm, be,
                  &BigEndCase::journal_radius, Positive("m")));
  p.push_back(Row(G::kBigEnd, "big_end.width", "Bearing width b", "mm", kMm, be, &BigEndCase::width,
                  Positive("m")));
  p.push_back(Row(G::kBigEnd, "big_end.roughness_journal", "Journal roughness σ_j", "µm", kUm, be,
                  &BigEndCase::roughness_journal, Positive("m")));
  p.push_back(Row(G::kBigEnd, "big_end.roughness_bearing", "Bearing roughness σ_b", "µm", kUm, be,
                  &BigEndCase::roughness_bearing, Positive("m")));
  p.push_back(Row(G::kBigEnd, "big_end.peklenik", "Peklenik number γ", "–", 1.0, be,
                  &BigEndCase::peklenik, Range(1.0 / 9.0, 9.0, false, false, "")));
  p.push_back(Row(G::kBigEnd, "big_end.modulus_journal", "Journal Young's modulus E_j", "GPa", kGPa,
                  be, &BigEndCase::modulus_journal, YoungsModulus()));
  p.push_back(Row(G::kBigEnd, "big_end.poisson_journal", "Journal Poisson ratio ν_j", "–", 1.0, be,
                  &BigEndCase::poisson_journal, PoissonRatio()));
  p.push_back(Row(G::kBigEnd, "big_end.modulus_bearing", "Bearing Young's modulus E_b", "GPa", kGPa,
                  be, &BigEndCase::modulus_bearing, YoungsModulus()));
  p.push_back(Row(G::kBigEnd, "big_end.poisson_bearing", "Bearing Poisson ratio ν_b", "–", 1.0, be,
                  &BigEndCase::poisson_bearing, PoissonRatio()));
  p.push_back(Row(G::kBigEnd, "big_end.boundary_friction", "Boundary friction μ_f", "–", 1.0, be,
                  &BigEndCase::boundary_friction, Range(0, 1, false, false, "")));
  p.push_back(Row(G::kBigEnd, "big_end.oil_feed_pressure", "Oil-feed pressure (gauge, 0 = none)",
                  "MPa", kMPa, be, &BigEndCase::oil_feed_pressure, NonNegative("Pa")));
  // Lubricant.
  p.push_back(Row(G::kLubricant, "lubricant.viscosity", "Dynamic viscosity μ", "mPa·s", 1e-3, lub,
                  &LubricantCase::viscosity, Positive("Pa*s")));
  p.push_back(Row(G::kLubricant, "lubricant.greenwood_tripp_k", "Greenwood–Tripp constant K", "–",
                  1.0, lub, &LubricantCase::greenwood_tripp_k, Positive("")));
  // Operating point.
  p.push_back(Row(G::kOperating, "operating.rpm", "Crank speed", "rpm", 1.0, op,
                  &OperatingCase::rpm, Positive("rpm")));
  p.push_back(Row(G::kOperating, "operating.crankcase_pressure", "Crankcase pressure (absolute)",
                  "MPa", kMPa, op, &OperatingCase::crankcase_pressure, NonNegative("Pa")));
  p.push_back(Row(G::kOperating, "operating.start_crank_angle", "Start crank angle", "°CA", kDeg,
                  op, &OperatingCase::start_crank_angle,
                  Range(0, 4 * std::numbers::pi, false, true, "rad")));
  // Solver.
  p.push_back(Row(G::kSolver, "solver.baumgarte_alpha", "Baumgarte 𝒢 (eq. 39)", "1/s", 1.0, sol,
                  &SolverCase::baumgarte_alpha, NonNegative("1/s")));
  p.push_back(Row(G::kSolver, "solver.baumgarte_beta", "Baumgarte ζ (eq. 39)", "1/s", 1.0, sol,
                  &SolverCase::baumgarte_beta, NonNegative("1/s")));
  p.push_back(Row(G::kSolver, "solver.relative_tolerance", "Relative tolerance", "–", 1.0, sol,
                  &SolverCase::relative_tolerance, Range(0, 0.1, true, false, "")));
  p.push_back(Row(G::kSolver, "solver.position_tolerance", "Absolute position tolerance", "µm", kUm,
                  sol, &SolverCase::position_tolerance, Positive("m")));
  p.push_back(Row(G::kSolver, "solver.output_interval", "Output interval", "°CA", kDeg, sol,
                  &SolverCase::output_interval, Range(0, 10 * kDeg, true, false, "rad")));
  p.push_back(Row(G::kSolver, "solver.steady_state_tolerance", "Steady-state tolerance", "–", 1.0,
                  sol, &SolverCase::steady_state_tolerance, Range(0, 1, true, false, "")));
  p.push_back(Row(G::kSolver, "solver.max_cycles", "Maximum cycles", "–", 1.0, sol,
                  &SolverCase::max_cycles, Range(1, 1000, false, false, "")));
  p.push_back(Row(G::kSolver, "solver.run_in_angle", "Run-in before the first cycle", "°CA", kDeg,
                  sol, &SolverCase::run_in_angle, Range(0, 1440 * kDeg, false, false, "rad")));
  // FEM meshes of the two Reynolds domains (paper Table II).
  p.push_back(Row(G::kSolver, "skirt.mesh_thrust", "Skirt mesh: elements over Ω₁ (thrust)", "–",
                  1.0, sk, &SkirtCase::mesh_thrust, Range(1, 1000, false, false, "")));
  p.push_back(Row(G::kSolver, "skirt.mesh_relief", "Skirt mesh: elements over Ω₂ (relief)", "–",
                  1.0, sk, &SkirtCase::mesh_relief, Range(1, 1000, false, false, "")));
  p.push_back(Row(G::kSolver, "skirt.mesh_anti", "Skirt mesh: elements over Ω₃ (anti-thrust)", "–",
                  1.0, sk, &SkirtCase::mesh_anti, Range(1, 1000, false, false, "")));
  p.push_back(Row(G::kSolver, "skirt.mesh_axial", "Skirt mesh: elements axially", "–", 1.0, sk,
                  &SkirtCase::mesh_axial, Range(1, 1000, false, false, "")));
  p.push_back(Row(G::kSolver, "big_end.mesh_theta", "Big-end mesh: elements around 360°", "–", 1.0,
                  be, &BigEndCase::mesh_theta, Range(3, 2000, false, false, "")));
  p.push_back(Row(G::kSolver, "big_end.mesh_z", "Big-end mesh: elements across the width", "–", 1.0,
                  be, &BigEndCase::mesh_z, Range(1, 1000, false, false, "")));
  p.push_back(Row(G::kOperating, "geometry.compression_ratio",
                  "Compression ratio (synthetic pressure model)", "–", 1.0, geo,
                  &CrankTrainGeometry::compression_ratio, Range(1, 30, true, false, "")));
  return p;
}

}  // namespace

const std::vector<CaseParameter>& CaseParameters() {
  static const std::vector<CaseParameter> parameters = MakeParameters();
  return parameters;
}

const CaseParameter* FindCaseParameter(const std::string& path) {
  for (const CaseParameter& p : CaseParameters()) {
    if (p.path == path) return &p;
  }
  return nullptr;
}

const std::vector<RunModel>& RunModels() {
  static const std::vector<RunModel> models = {
      {"skirt-lbrbe", "Skirt-LBRBE", JointModel::kLubricated, JointModel::kLubricated},
      {"only-skirt", "Only-Skirt", JointModel::kLubricated, JointModel::kIdeal},
      {"only-lbrbe", "Only-LBRBE", JointModel::kIdeal, JointModel::kLubricated},
      {"ideal", "Ideal", JointModel::kIdeal, JointModel::kIdeal},
  };
  return models;
}

QString RunModelKey(const EngineCase& engine_case) {
  for (const RunModel& m : RunModels()) {
    if (m.skirt == engine_case.skirt.model && m.big_end == engine_case.big_end.model) return m.key;
  }
  return "ideal";
}

void ApplyRunModel(EngineCase& engine_case, const QString& key) {
  for (const RunModel& m : RunModels()) {
    if (m.key == key) {
      engine_case.skirt.model = m.skirt;
      engine_case.big_end.model = m.big_end;
    }
  }
}

}  // namespace filmdyn::ui
