#include "core/io/field_output.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/engine/crank_train.hpp"
#include "core/io/field_series.hpp"
#include "core/lubrication/bearing_solver.hpp"
#include "core/lubrication/skirt_solver.hpp"

namespace filmdyn::io {

// Per frame only the nodal values are kept (as float, the precision the files store); the
// geometry is rebuilt when writing. One cycle of the default skirt mesh is ~30 MB this way.
struct FrameValues {
  double crank_angle_deg = 0.0;
  double eccentricity_angle = 0.0;  // bearing: direction of the journal eccentricity, rod frame
  std::vector<std::vector<float>> arrays;
};

struct JointFrames {
  SurfaceField geometry;  // points (skirt) and triangles, array names, no values
  std::vector<FrameValues> frames;
};

// One cycle's frames of both joints.
struct FieldRecorder::Cycle {
  int pass = 1;  ///< FieldFrame::pass
  int cycle = 0;
  double first_time = 0.0;  ///< of the cycle's first frame [s]
  JointFrames skirt, bearing;
  std::size_t size() const { return skirt.frames.size() + bearing.frames.size(); }
  bool StartsAt(const std::vector<engine::CrankTrainSample>& samples) const {
    // The run job gives a cycle's first frame and sample the same time t: equal, not close.
    return size() > 0 && !samples.empty() && samples.front().time == first_time;
  }
  /// A run that failed in its run-in: the one frame of its last output step (the failure), for
  /// samples that end there.
  bool FailedRunInAt(const std::vector<engine::CrankTrainSample>& samples) const {
    return cycle == 0 && size() > 0 && !samples.empty() && samples.back().time == first_time;
  }
};

struct FieldRecorder::Frames {
  Cycle newest;
  Cycle previous;              ///< the cycle before the newest, when kept
  bool keep_previous = false;  ///< whether a new cycle keeps the one before it (Attach)
  // Bearing nodes in film coordinates (θ from the maximum film, z) and the radius: the points
  // of each frame follow from them and the frame's eccentricity angle.
  std::vector<double> bearing_theta, bearing_z;
  double bearing_radius = 0.0;
};

FieldRecorder::FieldRecorder() : frames_(std::make_unique<Frames>()) {}
FieldRecorder::~FieldRecorder() = default;

engine::FieldCallback FieldRecorder::Callback() {
  return [this](const engine::FieldFrame& frame) { Record(frame); };
}

std::size_t FieldRecorder::skirt_frames() const { return frames_->newest.skirt.frames.size(); }
std::size_t FieldRecorder::bearing_frames() const { return frames_->newest.bearing.frames.size(); }

bool FieldRecorder::Attach(engine::RunConfig* config, double available) {
  config->field_callback = Callback();
  config->field_copies = 2.0;
  const bool keep =
      engine::EstimateRunMemory(config->engine_case, config->field_copies).total() <= available;
  if (!keep) config->field_copies = 1.0;
  frames_->keep_previous = keep;
  return keep;
}

const FieldRecorder::Cycle* FieldRecorder::Reported(
    const std::vector<engine::CrankTrainSample>& samples) const {
  for (const Cycle* cycle : {&frames_->newest, &frames_->previous})
    if (cycle->StartsAt(samples)) return cycle;
  if (frames_->newest.FailedRunInAt(samples)) return &frames_->newest;
  return nullptr;
}

bool FieldRecorder::Holds(const std::vector<engine::CrankTrainSample>& samples) const {
  return Reported(samples) != nullptr;
}

bool FieldRecorder::WriteReported(const std::filesystem::path& folder,
                                  const std::vector<engine::CrankTrainSample>& samples) const {
  const Cycle* cycle = Reported(samples);
  if (cycle != nullptr) Write(folder, *cycle);
  return cycle != nullptr;
}

namespace {

// The three nodal fields every joint writes; the fluid fraction only of a mass-conserving film
// (a Reynolds film's solution holds ones, which would show a full film where it cavitates), the
// surfaces' deformation only when they are elastic (`deformation` not null).
void AddFilmArrays(const lubrication::ReynoldsSolution& solution, const Eigen::VectorXd& h,
                   const std::vector<int>& source, lubrication::CavitationModel cavitation,
                   SurfaceField* field, const Eigen::VectorXd* deformation = nullptr) {
  auto gather = [&source](const Eigen::VectorXd& values) {
    std::vector<double> out(source.size());
    for (std::size_t k = 0; k < source.size(); ++k) out[k] = values[source[k]];
    return out;
  };
  field->point_data.emplace_back("pressure[Pa]", gather(solution.pressure));
  field->point_data.emplace_back("contact_pressure[Pa]", gather(solution.contact_pressure));
  field->point_data.emplace_back("film_thickness[m]", gather(h));
  if (cavitation == lubrication::CavitationModel::kJfo &&
      solution.fluid_fraction.size() == h.size()) {
    field->point_data.emplace_back("fluid_fraction[-]", gather(solution.fluid_fraction));
  }
  if (deformation != nullptr && deformation->size() == h.size())
    field->point_data.emplace_back("deformation[m]", gather(*deformation));
}

}  // namespace

SurfaceField FieldRecorder::SkirtSurface(const lubrication::SkirtSolver& skirt) {
  const lubrication::TriMesh& mesh = skirt.mesh();
  const double radius = skirt.config().geometry.radius;
  SurfaceField field;
  std::vector<int> source;
  for (int k = 0; k < mesh.NodeCount(); ++k) {
    const double alpha = skirt.alpha()[k];
    field.points.push_back({radius * std::cos(alpha), radius * std::sin(alpha), -mesh.y[k]});
    source.push_back(k);
  }
  field.triangles = mesh.triangles;
  AddFilmArrays(skirt.fields(), skirt.film_thickness(), source, skirt.config().solver.cavitation,
                &field, skirt.config().compliance.rigid() ? nullptr : &skirt.deformation());
  return field;
}

namespace {

std::vector<std::array<double, 3>> BearingPoints(const std::vector<double>& theta,
                                                 const std::vector<double>& z, double radius,
                                                 double eccentricity_angle_rod) {
  std::vector<std::array<double, 3>> points;
  points.reserve(theta.size());
  for (std::size_t k = 0; k < theta.size(); ++k) {
    const double psi = eccentricity_angle_rod + std::numbers::pi + theta[k];
    points.push_back({radius * std::cos(psi), radius * std::sin(psi), z[k]});
  }
  return points;
}

std::vector<double> NodeAngles(const lubrication::BearingSolver& bearing) {
  std::vector<double> theta(bearing.full_width().mesh.x);
  for (double& t : theta) t /= bearing.config().geometry.radius;
  return theta;
}

// Keeps the values of a surface and, the first time, its geometry without values.
void Keep(const SurfaceField& surface, double crank_angle_deg, double eccentricity_angle,
          JointFrames* joint) {
  if (joint->geometry.triangles.empty()) {
    joint->geometry.points = surface.points;
    joint->geometry.triangles = surface.triangles;
    for (const auto& [name, values] : surface.point_data) {
      joint->geometry.point_data.emplace_back(name, std::vector<double>());
    }
  }
  FrameValues frame{crank_angle_deg, eccentricity_angle, {}};
  for (const auto& [name, values] : surface.point_data) {
    frame.arrays.emplace_back(values.begin(), values.end());
  }
  joint->frames.push_back(std::move(frame));
}

}  // namespace

SurfaceField FieldRecorder::BearingSurface(const lubrication::BearingSolver& bearing,
                                           double eccentricity_angle_rod) {
  SurfaceField field;
  // The whole width, also when the solver computes the symmetric half.
  const lubrication::FullWidthSurface& surface = bearing.full_width();
  field.points = BearingPoints(NodeAngles(bearing), surface.mesh.y,
                               bearing.config().geometry.radius, eccentricity_angle_rod);
  field.triangles = surface.mesh.triangles;
  AddFilmArrays(bearing.fields(), bearing.film_thickness(), surface.source,
                bearing.config().solver.cavitation, &field,
                bearing.config().compliance.rigid() ? nullptr : &bearing.deformation());
  return field;
}

void FieldRecorder::Record(const engine::FieldFrame& frame) {
  Cycle& newest = frames_->newest;
  if (frame.pass != newest.pass || frame.cycle != newest.cycle) {
    if (frame.pass != newest.pass) {
      // The run again from its start (a heat balance's next pass): nothing recorded so far is
      // of a cycle the run will report.
      frames_->previous = {};
    } else if (frames_->keep_previous) {
      // A new cycle. The one before it is what a run stopped in this one reports; older ones
      // are reported by no run.
      frames_->previous = std::move(newest);
    }
    newest = {};
    newest.pass = frame.pass;
    newest.cycle = frame.cycle;
    newest.first_time = frame.time;
  } else if (newest.size() == 0) {
    newest.first_time = frame.time;  // the run-in's failure: cycle 0, as the empty start
  }
  if (frame.skirt != nullptr) {
    Keep(SkirtSurface(*frame.skirt), frame.crank_angle_deg, 0.0, &newest.skirt);
  }
  if (frame.bearing != nullptr && frame.sample != nullptr) {
    const Eigen::Vector2d e = frame.sample->bearing.journal_ecc_rod;
    const double angle = std::atan2(e.y(), e.x());
    if (frames_->bearing_theta.empty()) {
      frames_->bearing_theta = NodeAngles(*frame.bearing);
      frames_->bearing_z = frame.bearing->full_width().mesh.y;
      frames_->bearing_radius = frame.bearing->config().geometry.radius;
    }
    Keep(BearingSurface(*frame.bearing, angle), frame.crank_angle_deg, angle, &newest.bearing);
  }
}

void FieldRecorder::Write(const std::filesystem::path& folder) const {
  Write(folder, frames_->newest);
}

void FieldRecorder::Write(const std::filesystem::path& folder, const Cycle& cycle) const {
  for (const auto& [name, joint] :
       {std::pair{"skirt", &cycle.skirt}, std::pair{"bearing", &cycle.bearing}}) {
    if (joint->frames.empty()) continue;
    const bool bearing = joint == &cycle.bearing;
    FieldSeries series;
    series.name = name;
    series.triangles = joint->geometry.triangles;
    for (const auto& [array_name, values] : joint->geometry.point_data) {
      series.array_names.push_back(array_name);
    }
    // The bearing turns with the journal's eccentricity direction: one reference position
    // (eccentricity along the rod axis) and an angle per frame.
    series.rotating = bearing;
    series.points = bearing ? BearingPoints(frames_->bearing_theta, frames_->bearing_z,
                                            frames_->bearing_radius, 0.0)
                            : joint->geometry.points;
    // In crank-angle order (the time a reader keys frames by): a cycle that starts elsewhere
    // than 0 °CA passes 720 → 0 within it, and is written from 0 °CA on.
    std::vector<double> angles;
    for (const FrameValues& frame : joint->frames) angles.push_back(frame.crank_angle_deg);
    const std::size_t n = angles.size(), start = engine::LapStart(angles);
    for (std::size_t i = 0; i < n; ++i) {
      const FrameValues& frame = joint->frames[(start + i) % n];
      series.frames.push_back(
          {frame.crank_angle_deg, bearing ? frame.eccentricity_angle : 0.0, frame.arrays});
    }
    WriteFieldSeries(folder, series);
  }
}

}  // namespace filmdyn::io
