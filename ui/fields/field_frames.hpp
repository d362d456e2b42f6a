#pragma once
/// @file Film fields of a run for the 3D views: per joint and per output step one triangulated
/// surface (node coordinates [m]) with nodal arrays in SI named "pressure" [Pa],
/// "contact_pressure" [Pa], "film_thickness" [m] and, for a joint solved with mass-conserving
/// (JFO) cavitation, "fluid_fraction" [-] (θ, 1 = full film). The coupled lubricated run fills
/// this; the ideal model has no fields. The GUI's exports are core's files
/// (the run's writers), not these frames.
#include <QString>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/io/surface_field.hpp"

namespace filmdyn::ui {

/// One joint: the surface (points [m], triangles; fixed over the run) and per frame the nodal
/// arrays (name, values) in SI.
///
/// The film mesh is a tensor grid: node (i, j) of `mesh` is node i + angle_lines.size() · j, at
/// the circumferential angle angle_lines[i] and the axial position axial_lines[j] (core's
/// lubrication::TriMesh numbering). Skirt: α from the thrust side (0) to the anti-thrust side
/// (π), y below the skirt top, points (R cos α, R sin α, −y). Big end: θ from the maximum film
/// (the line-of-centres frame, turning with the journal), z across the width, points
/// (R cos θ, R sin θ, z); frame k is drawn turned by frame_rotation[k] about the bearing axis,
/// which places it in the rod frame (x ⟂ rod, y along the rod toward the small end).
struct JointFieldFrames {
  std::string name;       ///< "skirt", "big_end"
  io::SurfaceField mesh;  ///< point_data unused
  std::vector<std::vector<std::pair<std::string, std::vector<double>>>> frames;
  std::vector<double> angle_lines;  ///< circumferential angle of each node column [rad]
  std::vector<double> axial_lines;  ///< axial position of each node row [m]
  bool periodic = false;            ///< the angle wraps at 2π (the last column meets the first)
  /// The film is symmetric about the plane y = 0 (the skirt about its pin-axis plane): the
  /// 3D view draws the mirror image too, so the whole part is seen.
  bool mirrored = false;
  double radius = 0.0;  ///< [m]
  /// Angle intervals without film [rad], e.g. the skirt's pin-boss relief: not drawn as surface.
  std::vector<std::pair<double, double>> no_film;
  /// Per frame: the angle from the film's own frame to the body frame it is drawn in [rad]
  /// (big end: ψ = θ + frame_rotation, ψ in the rod frame). Empty: 0 for every frame.
  std::vector<double> frame_rotation;
  /// Per frame: the force on the bearing in the body frame (big end: crank pin on the rod, rod
  /// frame) [N]. Empty when not recorded (the skirt).
  std::vector<std::array<double, 2>> load;
  /// The film was solved with mass-conserving (JFO) cavitation: its frames carry the fluid
  /// fraction. With Reynolds (Swift–Stieber) cavitation there is none to show.
  bool mass_conserving = false;
  /// Whether the frames carry the array `name`.
  bool HasArray(const std::string& name) const;
  /// Frame k as a complete surface with its arrays.
  io::SurfaceField Frame(size_t k) const;
  /// Whether the angle [rad] lies strictly inside an interval without film.
  bool InNoFilm(double angle) const;
  /// The rotation of frame k [rad] (0 when none is recorded).
  double Rotation(size_t k) const { return k < frame_rotation.size() ? frame_rotation[k] : 0.0; }
  /// True when the grid is known and matches the mesh (node count = columns × rows).
  bool HasGrid() const {
    return !angle_lines.empty() && !axial_lines.empty() &&
           angle_lines.size() * axial_lines.size() == mesh.points.size();
  }
};

/// The values of the array `name` in one frame's arrays, or nullptr when the frame has none.
const std::vector<double>* FindFieldArray(
    const std::vector<std::pair<std::string, std::vector<double>>>& frame, const std::string& name);

struct FieldFrames {
  std::vector<double> crank_angle_deg;  ///< one per frame [°CA]
  std::vector<double> time;             ///< [s], same length
  std::vector<JointFieldFrames> joints;
  /// The frame of the output step where the run failed (its film in trouble), −1 for none: the
  /// last of a failed cycle's, or the only one of a run that failed in its run-in.
  int failure_frame = -1;
  bool empty() const { return crank_angle_deg.empty() || joints.empty(); }
};

/// The arrays the views offer: array name, title with display unit, display scale, the
/// quantity in words (for titles), the unit alone (for the colour bar), whether the
/// crank-angle map shows its minimum along the axis (film thickness, fluid fraction) rather than
/// its maximum, and a fixed colour range for a quantity whose range is known (the fluid
/// fraction: 0 to 1).
struct FieldArrayInfo {
  const char* name;
  const char* title;
  double scale;
  const char* words;
  const char* unit;
  bool minimum_matters;
  /// The colour range in display units whatever the values; NaN: from the values (rounded).
  double fixed_lo = std::numeric_limits<double>::quiet_NaN();
  double fixed_hi = std::numeric_limits<double>::quiet_NaN();
  /// The 3D colour bar's title when the unit alone says too little (a dimensionless quantity;
  /// Latin-1 only: VTK's font has no Greek); nullptr: the unit.
  const char* bar_title = nullptr;
  /// What the quantity is, for the selector's tooltip; nullptr: the title says it.
  const char* description = nullptr;
  bool HasFixedRange() const { return !std::isnan(fixed_lo) && !std::isnan(fixed_hi); }
};
const std::vector<FieldArrayInfo>& FieldArrays();


}  // namespace filmdyn::ui
