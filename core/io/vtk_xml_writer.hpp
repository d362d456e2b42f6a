#pragma once
/// @file Film fields as VTK XML files for ParaView and the GUI: one `.vtu` (unstructured grid of
/// linear triangles, point data) per output step and a `.pvd` collection indexing them by time.
/// Written without linking VTK (core stays std + Eigen + SuiteSparse + JSON): the documented VTK
/// XML format, "binary" inline data (base64 of a UInt32 byte count followed by the raw
/// little-endian values). Points are Float64, point data Float32 (display precision).
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace filmdyn::io {

/// One triangulated surface with nodal fields, e.g. the skirt or bearing film at one step.
struct SurfaceField {
  std::vector<std::array<double, 3>> points;  ///< node coordinates [m]
  std::vector<std::array<int, 3>> triangles;  ///< node indices, counter-clockwise
  /// (name, values) with one value per point, e.g. ("pressure[Pa]", p).
  std::vector<std::pair<std::string, std::vector<double>>> point_data;
};

/// Writes `field` to `path` (.vtu). Throws std::runtime_error naming the path when the file
/// cannot be written, and std::invalid_argument when a triangle index or an array length does
/// not match the points.
void WriteVtu(const std::string& path, const SurfaceField& field);

/// A ParaView collection (.pvd): time → file, written once all steps are known.
class PvdCollection {
 public:
  /// `file` is stored as given, normally relative to the .pvd's folder.
  void Add(double time, const std::string& file);
  /// Writes the collection atomically (temporary file + rename). Throws std::runtime_error.
  void Write(const std::string& path) const;
  std::size_t size() const { return entries_.size(); }

 private:
  std::vector<std::pair<double, std::string>> entries_;
};

/// Base64 encoding (RFC 4648, with padding), as VTK's binary inline format uses.
std::string Base64Encode(const unsigned char* data, std::size_t size);

}  // namespace filmdyn::io
