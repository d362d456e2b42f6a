#include "core/engine/film_joints.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numbers>
#include <tuple>

#include "core/base/input_error.hpp"
#include "core/coupling/lubricated_big_end_element.hpp"
#include "core/coupling/lubricated_skirt_element.hpp"
#include "core/engine/pressure_curve.hpp"
#include "core/engine/slider_crank_reference.hpp"
#include "core/lubrication/surface_film.hpp"

namespace filmdyn::engine {

const lubrication::OilSpec& JointOilSpec(const EngineCase& c, const JointOil& oil) {
  if (oil.source == OilSource::kOwn) return oil.own;
  return c.lubricant;
}

bool TemperatureFreeOil(const EngineCase& c, const JointOil& oil) {
  return JointOilSpec(c, oil).model == lubrication::ViscosityModel::kConstant;
}

std::string JointOilPrefix(const JointOil& oil, const std::string& joint) {
  return oil.source == OilSource::kOwn ? joint + ".oil." : "lubricant.";
}

lubrication::OilSpec::AtTemperature JointOilAt(const EngineCase& c, const JointOil& oil,
                                               const std::string& joint) {
  return JointOilSpec(c, oil).At(oil.temperature, JointOilPrefix(oil, joint),
                                 joint + ".oil.temperature");
}

double StartFilmTemperature(const EngineCase& c, const JointOil& oil) {
  if (oil.temperature_mode == FilmTemperature::kHeatBalance)
    return std::max(oil.temperature, c.lubricant.supply_temperature);
  return oil.temperature;
}

void CheckJointOils(const EngineCase& c) {
  for (const auto& [model, oil, joint] : {std::tuple{c.skirt.model, &c.skirt.oil, "skirt"},
                                          std::tuple{c.big_end.model, &c.big_end.oil, "big_end"}}) {
    if (model != JointModel::kLubricated) continue;
    JointOil start = *oil;
    start.temperature = StartFilmTemperature(c, *oil);
    JointOilAt(c, start, joint);
  }
}

double JointBulkModulus(const EngineCase& c, const JointOil& oil, const std::string& joint,
                        lubrication::CavitationModel cavitation) {
  const lubrication::OilSpec& spec = JointOilSpec(c, oil);
  const std::string prefix = JointOilPrefix(oil, joint);
  spec.CheckBulkModulus(prefix);
  if (cavitation != lubrication::CavitationModel::kJfo || spec.bulk_modulus == 0.0) return 0.0;
  if (spec.pressure_law != lubrication::PressureLaw::kNone) {
    throw InputError(prefix + "bulk_modulus", FormatValue(spec.bulk_modulus) + " Pa",
                     "0 (incompressible) while the oil has a pressure-viscosity law: a "
                     "compressible " +
                         joint + " film needs pressure_viscosity \"none\"");
  }
  return spec.bulk_modulus;
}

namespace {

// An imported compliance named in the case (`field`): a relative name is resolved against the
// case's folder.
std::shared_ptr<const lubrication::ImportedCompliance> ReadComplianceFile(
    const std::string& field, const std::string& file,
    const std::filesystem::path& case_directory) {
  if (file.empty()) {
    throw InputError(field, "\"\"",
                     "a Matrix Market file (with its .nodes.csv beside it) when the compliance "
                     "is \"imported\"");
  }
  std::filesystem::path matrix(file);
  if (matrix.is_relative() && !case_directory.empty()) matrix = case_directory / matrix;
  if (!std::filesystem::exists(matrix)) {
    throw InputError(field, "\"" + file + "\"",
                     "an existing file (looked for " + matrix.string() + ")");
  }
  return std::make_shared<const lubrication::ImportedCompliance>(
      lubrication::ReadImportedCompliance(matrix.string()));
}

}  // namespace

lubrication::SkirtConfig SkirtConfigFromCase(const EngineCase& c,
                                             const std::filesystem::path& case_directory) {
  const SkirtCase& sk = c.skirt;
  lubrication::SkirtConfig config;
  lubrication::SkirtGeometry& g = config.geometry;
  const JointFit fit = SkirtFit(c);
  g.radius = fit.inner_radius;
  g.skirt_length = sk.length;
  g.radial_clearance = fit.hot_clearance;
  if (!(g.radial_clearance > 0.0) || !(g.radius > 0.0)) {
    throw InputError("skirt.cold_clearance", FormatValue(sk.cold_clearance),
                     "must be > 0 and smaller than geometry.liner_radius = " +
                         FormatValue(c.geometry.liner_radius) + " [m]");
  }
  g.pin_position = c.geometry.skirt_top_to_pin;
  g.alpha1 = sk.thrust_half_width;
  g.alpha2 = sk.anti_thrust_half_width;
  g.profile.x = sk.profile_y;
  g.profile.y = sk.profile_h;
  g.ovality.x = sk.ovality_alpha;  // empty = round skirt
  g.ovality.y = sk.ovality_h;
  const lubrication::OilSpec::AtTemperature oil = JointOilAt(c, sk.oil, "skirt");
  config.viscosity = oil.viscosity;
  config.pressure_viscosity = oil.pressure;
  config.shear_thinning = oil.shear;
  config.bulk_modulus = JointBulkModulus(c, sk.oil, "skirt", sk.cavitation);
  config.density_law = JointOilSpec(c, sk.oil).density_law;
  config.mesh.n_thrust = sk.mesh_thrust;
  config.mesh.n_relief = sk.mesh_relief;
  config.mesh.n_anti = sk.mesh_anti;
  config.mesh.n_axial = sk.mesh_axial;
  config.solver.cavitation = sk.cavitation;
  config.supply = sk.supply;
  config.oil_film = sk.oil_film;
  config.oil_film_table.x = sk.oil_film_positions;
  config.oil_film_table.y = sk.oil_film_values;
  config.compliance.model = sk.compliance;
  config.compliance.layer_thickness = sk.layer_thickness;
  config.compliance.layer_modulus = sk.modulus_skirt;
  config.compliance.layer_poisson = sk.poisson_skirt;
  config.compliance.modulus1 = sk.modulus_skirt;
  config.compliance.poisson1 = sk.poisson_skirt;
  config.compliance.modulus2 = sk.modulus_liner;
  config.compliance.poisson2 = sk.poisson_liner;
  if (sk.compliance == lubrication::ComplianceModel::kImported)
    config.compliance.imported =
        ReadComplianceFile("skirt.compliance_file", sk.compliance_file, case_directory);
  lubrication::SurfacePair pair;
  pair.sigma1 = sk.roughness_skirt;
  pair.sigma2 = sk.roughness_liner;
  pair.peklenik = sk.peklenik;
  pair.E1 = sk.modulus_skirt;  // surface 1 = skirt, 2 = liner; the pair forms E' (Hu et al.)
  pair.nu1 = sk.poisson_skirt;
  pair.E2 = sk.modulus_liner;
  pair.nu2 = sk.poisson_liner;
  pair.gt_k = c.lubricant.greenwood_tripp_k;
  pair.boundary_friction = sk.boundary_friction;
  pair.Validate("skirt");
  config.film = lubrication::MakeSurfaceFilm(pair);
  return config;
}

std::unique_ptr<multibody::JointForceElement> MakeLubricatedSkirt(
    const EngineCase& c, const CrankTrainLayout& layout,
    const std::filesystem::path& case_directory) {
  coupling::SkirtMounting mount;
  mount.com_lateral_offset = c.geometry.piston_com_lateral_offset;
  mount.skirt_top_to_com = c.geometry.skirt_top_to_com;
  mount.skirt_top_to_pin = c.geometry.skirt_top_to_pin;
  mount.pin_offset = c.geometry.pin_offset;
  // Top dead centre: the highest pin position over a crank revolution (sampled every 0.05°,
  // then the parabola through the best three samples).
  const int n = 7200;
  auto height = [&](int k) {
    return ExactSliderCrank(c.geometry, 2.0 * std::numbers::pi * k / n, 0.0, 0.0).piston_position;
  };
  int best = 0;
  for (int k = 1; k < n; ++k)
    if (height(k) > height(best)) best = k;
  const double y0 = height(best - 1), y1 = height(best), y2 = height(best + 1);
  const double den = y0 - 2.0 * y1 + y2;
  mount.pin_y_at_tdc = den < 0.0 ? y1 - 0.125 * (y2 - y0) * (y2 - y0) / den : y1;
  return std::make_unique<coupling::LubricatedSkirtElement>(SkirtConfigFromCase(c, case_directory),
                                                            layout.piston, mount);
}

bool BigEndSolvesSymmetricHalf(const BigEndCase& be) {
  // An odd count has no node row on the mid-plane; 2 elements are too few for a half (it needs
  // two of its own).
  return be.mesh_z % 2 == 0 && be.mesh_z >= 4;
}

lubrication::BearingConfig BearingConfigFromCase(const EngineCase& c,
                                                 const std::filesystem::path& case_directory) {
  const BigEndCase& be = c.big_end;
  lubrication::BearingConfig config;
  const JointFit fit = BigEndFit(c);
  config.geometry.radius = fit.inner_radius;
  config.geometry.length = be.width;
  config.geometry.radial_clearance = fit.hot_clearance;
  if (!(config.geometry.radial_clearance > 0.0)) {
    throw InputError("big_end.journal_radius", FormatValue(be.journal_radius),
                     "must be smaller than big_end.bearing_radius = " +
                         FormatValue(be.bearing_radius) + " [m] (no clearance)");
  }
  const lubrication::OilSpec::AtTemperature oil = JointOilAt(c, be.oil, "big_end");
  config.viscosity = oil.viscosity;
  config.pressure_viscosity = oil.pressure;
  config.shear_thinning = oil.shear;
  config.bulk_modulus = JointBulkModulus(c, be.oil, "big_end", be.cavitation);
  config.density_law = JointOilSpec(c, be.oil).density_law;
  config.mesh.n_theta = be.mesh_theta;
  // The half has the same nodes and half the unknowns; the outputs show the whole width.
  config.mesh.symmetric_half = BigEndSolvesSymmetricHalf(be);
  config.mesh.n_z = config.mesh.symmetric_half ? be.mesh_z / 2 : be.mesh_z;
  config.mesh.theta_grading = be.mesh_theta_grading;
  config.mesh.z_grading = be.mesh_z_grading;
  config.solver.cavitation = be.cavitation;
  config.feed.kind = be.supply;
  config.feed.hole_angles = be.supply_hole_angles;
  config.feed.hole_diameter = be.supply_hole_diameter;
  config.feed.groove_start = be.groove_start_angle;
  config.feed.groove_end = be.groove_end_angle;
  config.feed.groove_width = be.groove_width;
  config.feed.pressure = be.oil_feed_pressure;
  config.compliance.model = be.compliance;
  config.compliance.layer_thickness = be.layer_thickness;
  config.compliance.layer_modulus = be.modulus_bearing;
  config.compliance.layer_poisson = be.poisson_bearing;
  config.compliance.modulus1 = be.modulus_journal;
  config.compliance.poisson1 = be.poisson_journal;
  config.compliance.modulus2 = be.modulus_bearing;
  config.compliance.poisson2 = be.poisson_bearing;
  if (be.compliance == lubrication::ComplianceModel::kImported)
    config.compliance.imported =
        ReadComplianceFile("big_end.compliance_file", be.compliance_file, case_directory);
  lubrication::SurfacePair pair;
  pair.sigma1 = be.roughness_journal;
  pair.sigma2 = be.roughness_bearing;
  pair.peklenik = be.peklenik;
  pair.E1 = be.modulus_journal;  // surface 1 = journal, 2 = bearing; the pair forms E'
  pair.nu1 = be.poisson_journal;
  pair.E2 = be.modulus_bearing;
  pair.nu2 = be.poisson_bearing;
  pair.gt_k = c.lubricant.greenwood_tripp_k;
  pair.boundary_friction = be.boundary_friction;
  pair.Validate("big_end");
  config.film = lubrication::MakeSurfaceFilm(pair);
  return config;
}

std::unique_ptr<multibody::JointForceElement> MakeLubricatedBigEnd(
    const EngineCase& c, const CrankTrainLayout& layout,
    const std::filesystem::path& case_directory) {
  coupling::BigEndMounting mount;
  mount.journal_point = layout.crank_pin;
  mount.bearing_point = layout.rod_big_end;
  lubrication::BearingConfig config = BearingConfigFromCase(c, case_directory);
  // The case's supply angles are measured from the rod axis (toward the small end) and from the
  // crank web's axis (main journal to pin); the solver's, from each body's own x axis.
  auto axis_angle = [](const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
    return std::atan2(to.y() - from.y(), to.x() - from.x());
  };
  const double rod_axis = axis_angle(layout.rod_big_end, layout.rod_small_end);
  // An imported compliance's nodes are placed from the rod axis too.
  config.compliance.imported_reference_angle = rod_axis;
  const double web_axis = axis_angle(layout.crank_main_journal, layout.crank_pin);
  const bool pin = lubrication::HasPinHoles(config.feed.kind);
  for (double& a : config.feed.hole_angles) a += pin ? web_axis : rod_axis;
  config.feed.groove_start += rod_axis;
  config.feed.groove_end += rod_axis;
  auto element = std::make_unique<coupling::LubricatedBigEndElement>(
      std::move(config), layout.crank, layout.rod, mount);
  const BigEndCase& be = c.big_end;
  if (!be.supply_pressure_angles.empty()) {
    // The crank body's orientation is the crank angle (the gas force's convention).
    auto curve = std::make_shared<const PressureCurve>(
        be.supply_pressure_angles, be.supply_pressure_values, "big_end.supply_pressure_values");
    element->SetSupplyPressure(
        [curve](double crank_angle) { return curve->Pressure(crank_angle); });
  }
  return element;
}

LubricatedJointFactories FilmJointFactories(const std::filesystem::path& case_directory) {
  LubricatedJointFactories f;
  f.skirt = [case_directory](const EngineCase& c, const CrankTrainLayout& layout) {
    return MakeLubricatedSkirt(c, layout, case_directory);
  };
  f.big_end = [case_directory](const EngineCase& c, const CrankTrainLayout& layout) {
    return MakeLubricatedBigEnd(c, layout, case_directory);
  };
  return f;
}

std::string DescribeMeshes(const EngineCase& c) {
  const SkirtCase& s = c.skirt;
  const BigEndCase& b = c.big_end;
  const std::string big_end_grading =
      b.mesh_theta_grading != 1.0 || b.mesh_z_grading != 1.0
          ? fmt::format(", graded {:g}:1 around and {:g}:1 across", b.mesh_theta_grading,
                        b.mesh_z_grading)
          : std::string(", uniform");
  return fmt::format("skirt {} + {} + {} x {} elements; big end {} x {} elements{}",
                     s.mesh_thrust, s.mesh_relief, s.mesh_anti, s.mesh_axial, b.mesh_theta,
                     b.mesh_z, big_end_grading);
}

void UsePaperMeshes(EngineCase* c) {
  c->skirt.mesh_thrust = 30;
  c->skirt.mesh_relief = 2;
  c->skirt.mesh_anti = 30;
  c->skirt.mesh_axial = 40;
  c->big_end.mesh_theta = 50;
  c->big_end.mesh_z = 10;
  c->big_end.mesh_theta_grading = 1.0;
  c->big_end.mesh_z_grading = 1.0;
}

}  // namespace filmdyn::engine
