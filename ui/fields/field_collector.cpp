#include "ui/fields/field_collector.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/engine/crank_train.hpp"
#include "core/lubrication/bearing_solver.hpp"
#include "core/lubrication/skirt_solver.hpp"

namespace filmdyn::ui {

namespace {

constexpr double kPi = std::numbers::pi;

/// The film plane (x = R·angle, y axial) as the grid of node columns and rows.
void SetGrid(const lubrication::TriMesh& mesh, double radius, JointFieldFrames* joint) {
  joint->radius = radius;
  joint->periodic = mesh.periodic_x;
  joint->angle_lines.clear();
  for (double x : mesh.x_lines) joint->angle_lines.push_back(x / radius);
  joint->axial_lines = mesh.y_lines;
  joint->mesh.triangles = mesh.triangles;
}

/// Skirt: the bore axis is z, the skirt top at z = 0 and the skirt below it (z = −y), α from
/// the thrust side (+x); the relief between the panels carries no film.
JointFieldFrames MakeSkirt(const lubrication::SkirtSolver& skirt) {
  JointFieldFrames joint;
  joint.name = "skirt";
  const lubrication::TriMesh& mesh = skirt.mesh();
  const lubrication::SkirtGeometry& g = skirt.config().geometry;
  SetGrid(mesh, g.radius, &joint);
  for (int n = 0; n < mesh.NodeCount(); ++n) {
    const double angle = std::min(mesh.x[size_t(n)] / g.radius, kPi);
    joint.mesh.points.push_back(
        {g.radius * std::cos(angle), g.radius * std::sin(angle), -mesh.y[size_t(n)]});
  }
  if (kPi - g.alpha2 > g.alpha1) joint.no_film.push_back({g.alpha1, kPi - g.alpha2});
  joint.mirrored = true;  // symmetric about the pin-axis plane (core solves one half)
  joint.mass_conserving = skirt.config().solver.cavitation == lubrication::CavitationModel::kJfo;
  return joint;
}

/// Big end: the whole width (also when the solver computes the symmetric half), θ from the
/// maximum film; each frame is turned into the rod frame (frame_rotation).
JointFieldFrames MakeBigEnd(const lubrication::BearingSolver& bearing) {
  JointFieldFrames joint;
  joint.name = "big_end";
  const lubrication::TriMesh& mesh = bearing.full_width().mesh;
  const double radius = bearing.config().geometry.radius;
  SetGrid(mesh, radius, &joint);
  for (int n = 0; n < mesh.NodeCount(); ++n) {
    const double angle = mesh.x[size_t(n)] / radius;
    joint.mesh.points.push_back(
        {radius * std::cos(angle), radius * std::sin(angle), mesh.y[size_t(n)]});
  }
  joint.mass_conserving = bearing.config().solver.cavitation == lubrication::CavitationModel::kJfo;
  return joint;
}

// `source`: the solver node of each displayed node (nullptr = the same numbering). The fluid
// fraction only with mass-conserving cavitation (with Reynolds cavitation core leaves it 1).
void Append(JointFieldFrames& joint, const lubrication::ReynoldsSolution& fields,
            const Eigen::VectorXd& film, const std::vector<int>* source = nullptr,
            const Eigen::VectorXd* deformation = nullptr) {
  auto vec = [source](const Eigen::VectorXd& v) {
    if (!source) return std::vector<double>(v.data(), v.data() + v.size());
    std::vector<double> out(source->size());
    for (std::size_t k = 0; k < source->size(); ++k) out[k] = v[(*source)[k]];
    return out;
  };
  joint.frames.push_back({{"pressure", vec(fields.pressure)},
                          {"contact_pressure", vec(fields.contact_pressure)},
                          {"film_thickness", vec(film)}});
  if (joint.mass_conserving && fields.fluid_fraction.size() == film.size()) {
    joint.frames.back().push_back({"fluid_fraction", vec(fields.fluid_fraction)});
  }
  // Elastic surfaces: the deformation that opened the film (film_thickness is the deformed film).
  if (deformation != nullptr && deformation->size() == film.size())
    joint.frames.back().push_back({"deformation", vec(*deformation)});
}

}  // namespace

FieldCollector::FieldCollector(int steps_per_cycle)
    : stride_(std::max(1, (steps_per_cycle + kMaxFrames - 1) / kMaxFrames)) {}

void FieldCollector::Add(const engine::FieldFrame& frame) {
  // A new cycle, or the run again from its start (a heat balance's next pass, its cycles from 1
  // again). (A run-in's failure: cycle 0, the first frame.)
  if (frame.cycle != cycle_ || frame.pass != pass_ || !frames_) {
    cycle_ = frame.cycle;
    pass_ = frame.pass;
    frames_ = std::make_shared<FieldFrames>();
  }
  // Every stride-th step, and the step where the run failed (the film a user wants to see).
  if (frame.step % stride_ != 0 && !frame.failure) return;
  if (frames_->joints.empty()) {
    if (frame.skirt) frames_->joints.push_back(MakeSkirt(*frame.skirt));
    if (frame.bearing) frames_->joints.push_back(MakeBigEnd(*frame.bearing));
  }
  if (frame.failure) frames_->failure_frame = int(frames_->crank_angle_deg.size());
  frames_->crank_angle_deg.push_back(frame.crank_angle_deg);
  frames_->time.push_back(frame.time);
  size_t j = 0;
  if (frame.skirt)
    Append(frames_->joints[j++], frame.skirt->fields(), frame.skirt->film_thickness(), nullptr,
           frame.skirt->config().compliance.rigid() ? nullptr : &frame.skirt->deformation());
  if (frame.bearing) {
    JointFieldFrames& joint = frames_->joints[j++];
    Append(joint, frame.bearing->fields(), frame.bearing->film_thickness(),
           &frame.bearing->full_width().source,
           frame.bearing->config().compliance.rigid() ? nullptr : &frame.bearing->deformation());
    if (frame.sample != nullptr) {
      // θ is measured from the maximum film, opposite the journal's eccentricity: ψ = φ + π + θ
      // with φ the eccentricity's direction in the rod frame (as core's field files draw it).
      const Eigen::Vector2d e = frame.sample->bearing.journal_ecc_rod;
      joint.frame_rotation.push_back(std::remainder(std::atan2(e.y(), e.x()) + kPi, 2 * kPi));
      // The crank pin's force on the rod, global → rod frame (the rod turned by its angle).
      const Eigen::Vector2d f = frame.sample->bearing.force_on_rod;
      const double c = std::cos(frame.sample->rod_angle), s = std::sin(frame.sample->rod_angle);
      joint.load.push_back({c * f.x() + s * f.y(), -s * f.x() + c * f.y()});
    }
  }
}

std::shared_ptr<const FieldFrames> FieldCollector::Result() const {
  if (!frames_) return frames_;
  const std::size_t wrap = engine::LapStart(frames_->crank_angle_deg);
  if (wrap == 0) return frames_;
  auto ordered = std::make_shared<FieldFrames>(*frames_);
  const auto turn = [wrap](auto& per_frame) {
    if (per_frame.size() > wrap)
      std::rotate(per_frame.begin(), per_frame.begin() + std::ptrdiff_t(wrap), per_frame.end());
  };
  if (ordered->failure_frame >= 0) {  // its place after the turn
    const std::size_t n = ordered->crank_angle_deg.size();
    ordered->failure_frame = int((std::size_t(ordered->failure_frame) + n - wrap) % n);
  }
  turn(ordered->crank_angle_deg);
  turn(ordered->time);
  for (JointFieldFrames& joint : ordered->joints) {
    turn(joint.frames);
    turn(joint.frame_rotation);
    turn(joint.load);
  }
  return ordered;
}

}  // namespace filmdyn::ui
