#pragma once
/// @file The film fields of one joint over one cycle as a time series: `<name>.h5` (HDF5, every
/// number) plus `<name>.xdmf` (an XDMF 3 index that ParaView's Xdmf3 readers open as a temporal
/// collection whose time values are the crank angles [°CA]; the legacy XDMF 2 "Xdmf Reader"
/// cannot read it, see XdmfText in the .cpp). Geometry is stored once; per-frame nodal arrays
/// are Float32 in one compressed 2-D dataset per array, one row per frame.
///
/// HDF5 layout (format_version 1), all names fixed:
///   /                        attributes `format` = "FilmDyn field series", `format_version` = 1,
///                            `name` (the joint), `rotating` (0 or 1)
///   /geometry/points         Float64 [points × 3], metres; for a rotating series the reference
///                            position, frame i being these points rotated about z by
///                            /time/rotation_z[i]
///   /geometry/triangles      Int32 [triangles × 3], 0-based node indices, counter-clockwise
///   /geometry/frame_points   Float32 [frames × points × 3] (rotating series only): each frame's
///                            points as drawn, for the XDMF readers, which cannot rotate
///   /time/crank_angle        Float64 [frames], °CA within the cycle, strictly increasing
///   /time/rotation_z         Float64 [frames], rad (rotating series only)
///   /fields/<key>            Float32 [frames × points], chunked, shuffle + deflate; attributes
///                            `name` (the full array name, e.g. "pressure[Pa]") and `units`
///                            ("Pa"); <key> is the name without its bracketed units ("pressure");
///                            the group keeps the arrays' order (link creation order)
///
/// Why Float32 for nodal arrays: a 24-bit mantissa holds ~7 significant digits (relative
/// rounding ≤ 6e-8), far beyond what a colour map or a plot resolves (3–4 digits) and beyond
/// the accuracy of the solution itself (mesh and solver tolerances, inputs known to a few
/// digits). Halving the bytes matters: one cycle of the skirt is 720 frames × 2 542 nodes × 4
/// arrays. Fixed points stay Float64: written once, they cost little and read back
/// bit-identical to what the solver used.
///
/// Rotating geometry (the big-end bearing, drawn in the rod frame at each frame's eccentricity
/// angle): the series keeps one reference position and one angle per frame; the per-frame points
/// the viewers need are derived from them when writing (/geometry/frame_points).
#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace filmdyn::io {

/// The values of every array at one output step.
struct SeriesFrame {
  double crank_angle_deg = 0.0;  ///< time value [°CA] within the cycle
  /// Rotation of the points about the z axis for this frame [rad], counter-clockwise seen from
  /// +z; must be 0 unless FieldSeries::rotating.
  double rotation_z = 0.0;
  /// One array per FieldSeries::array_names entry, one value per point.
  std::vector<std::vector<float>> arrays;
};

/// One joint's film over a cycle: fixed triangles, fixed (or rigidly rotating) points, frames.
struct FieldSeries {
  /// Joint name, used as the file stem and grid name: letters, digits, '_' and '-' only.
  std::string name;
  /// Node coordinates [m]; the reference position when `rotating`.
  std::vector<std::array<double, 3>> points;
  /// Node indices (0-based) of each triangle, counter-clockwise.
  std::vector<std::array<int, 3>> triangles;
  /// Array names with units in brackets, e.g. "pressure[Pa]", "fluid_fraction[-]". The part
  /// before '[' names the HDF5 dataset: unique, made of letters, digits, '_' and '-'.
  std::vector<std::string> array_names;
  /// Whether each frame's points are `points` rotated about z by SeriesFrame::rotation_z.
  bool rotating = false;
  /// Output steps in increasing crank angle.
  std::vector<SeriesFrame> frames;
};

/// How WriteFieldSeries compresses. The defaults are the measured choice: one cycle of the skirt
/// (720 frames × 2 542 nodes × 4 arrays, 29 MB raw) gives 10.2 MB in 0.37 s at level 1, 10.0 MB
/// in 0.46 s at 4, 9.8 MB in 0.49 s at 6, 9.7 MB in 2.1 s at 9; 16 frames a chunk divides 720 and
/// is within 2 % of 64, while a reader of one frame inflates only 16.
struct FieldSeriesOptions {
  int deflate_level = 6;      ///< 0 (off) … 9
  int frames_per_chunk = 16;  ///< rows of a chunk of the per-frame arrays
};

/// The points of frame `frame` of `series` (its `points` rotated when it is rotating).
std::vector<std::array<double, 3>> FramePoints(const FieldSeries& series, std::size_t frame);

/// Throws std::invalid_argument naming the series and what is wrong: a bad name, no points, no
/// triangles or no frames, a non-finite coordinate, a triangle index outside the points, an array
/// name whose part before '[' is empty, duplicated or not an identifier, a frame whose array
/// count or array length does not match, crank angles not finite or not strictly increasing, a
/// rotation on a non-rotating series.
void ValidateFieldSeries(const FieldSeries& series);

/// Writes `<folder>/<name>.h5` and `<folder>/<name>.xdmf` (folder created). Both are written to
/// `.tmp` names first; the old index is removed before the new files are renamed into place, so
/// an interrupted write never leaves an index describing data that is not all there. Validates
/// first (std::invalid_argument); throws std::runtime_error naming the file and the HDF5 or file
/// system failure (e.g. a full disk) on I/O errors, leaving no temporary file behind.
void WriteFieldSeries(const std::filesystem::path& folder, const FieldSeries& series,
                      const FieldSeriesOptions& options = {});

/// Reads a series written by WriteFieldSeries, given either its `.xdmf` (the `.h5` it names is
/// read) or its `.h5`. Everything comes from the HDF5 file: values are exactly those written.
/// Throws std::runtime_error naming the file and what is missing or inconsistent.
FieldSeries ReadFieldSeries(const std::filesystem::path& xdmf_or_h5);

}  // namespace filmdyn::io
