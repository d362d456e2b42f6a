#include "core/io/vtk_xml_writer.hpp"

#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace filmdyn::io {

static_assert(std::endian::native == std::endian::little,
              "the VTU writer declares LittleEndian byte order");

std::string Base64Encode(const unsigned char* data, std::size_t size) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((size + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < size; i += 3) {
    const std::uint32_t v = (data[i] << 16) | (data[i + 1] << 8) | data[i + 2];
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += kAlphabet[(v >> 6) & 63];
    out += kAlphabet[v & 63];
  }
  if (i < size) {
    std::uint32_t v = data[i] << 16;
    if (i + 1 < size) v |= data[i + 1] << 8;
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += i + 1 < size ? kAlphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

namespace {

// VTK "binary" inline block: base64(UInt32 byte count + raw values), one encoding of the whole.
template <typename T>
std::string EncodeBlock(const std::vector<T>& values) {
  const auto bytes = static_cast<std::uint32_t>(values.size() * sizeof(T));
  std::vector<unsigned char> buffer(sizeof(bytes) + bytes);
  std::memcpy(buffer.data(), &bytes, sizeof(bytes));
  if (bytes > 0) std::memcpy(buffer.data() + sizeof(bytes), values.data(), bytes);
  return Base64Encode(buffer.data(), buffer.size());
}

std::string XmlEscape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// Writes through a temporary file renamed into place, so a crash never leaves half a file.
void WriteAtomically(const std::string& path, const std::string& content) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write " + path + ": cannot open for writing");
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    if (!out) throw std::runtime_error("cannot write " + path + ": write failed (disk full?)");
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write " + path + ": " + error.message());
  }
}

}  // namespace

void WriteVtu(const std::string& path, const SurfaceField& field) {
  const std::size_t n_points = field.points.size();
  for (const auto& triangle : field.triangles) {
    for (int node : triangle) {
      if (node < 0 || static_cast<std::size_t>(node) >= n_points) {
        throw std::invalid_argument("WriteVtu " + path + ": triangle node index " +
                                    std::to_string(node) + " outside [0, " +
                                    std::to_string(n_points) + ")");
      }
    }
  }
  for (const auto& [name, values] : field.point_data) {
    if (values.size() != n_points) {
      throw std::invalid_argument("WriteVtu " + path + ": array '" + name + "' has " +
                                  std::to_string(values.size()) + " values for " +
                                  std::to_string(n_points) + " points");
    }
  }

  std::vector<double> coordinates;
  coordinates.reserve(3 * n_points);
  for (const auto& p : field.points) coordinates.insert(coordinates.end(), p.begin(), p.end());
  std::vector<std::int32_t> connectivity, offsets;
  std::vector<std::uint8_t> types(field.triangles.size(), 5);  // VTK_TRIANGLE
  connectivity.reserve(3 * field.triangles.size());
  offsets.reserve(field.triangles.size());
  for (const auto& t : field.triangles) {
    connectivity.insert(connectivity.end(), t.begin(), t.end());
    offsets.push_back(static_cast<std::int32_t>(connectivity.size()));
  }

  std::ostringstream xml;
  xml << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt32\">\n<UnstructuredGrid>\n"
      << "<Piece NumberOfPoints=\"" << n_points << "\" NumberOfCells=\"" << field.triangles.size()
      << "\">\n<PointData";
  if (!field.point_data.empty()) {
    xml << " Scalars=\"" << XmlEscape(field.point_data.front().first) << "\"";
  }
  xml << ">\n";
  for (const auto& [name, values] : field.point_data) {
    const std::vector<float> single(values.begin(), values.end());
    xml << "<DataArray type=\"Float32\" Name=\"" << XmlEscape(name) << "\" format=\"binary\">"
        << EncodeBlock(single) << "</DataArray>\n";
  }
  xml << "</PointData>\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" "
         "format=\"binary\">"
      << EncodeBlock(coordinates) << "</DataArray>\n</Points>\n<Cells>\n"
      << "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"binary\">"
      << EncodeBlock(connectivity) << "</DataArray>\n"
      << "<DataArray type=\"Int32\" Name=\"offsets\" format=\"binary\">" << EncodeBlock(offsets)
      << "</DataArray>\n"
      << "<DataArray type=\"UInt8\" Name=\"types\" format=\"binary\">" << EncodeBlock(types)
      << "</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  WriteAtomically(path, xml.str());
}

void PvdCollection::Add(double time, const std::string& file) { entries_.emplace_back(time, file); }

void PvdCollection::Write(const std::string& path) const {
  std::ostringstream xml;
  xml.precision(12);
  xml << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\" "
         "byte_order=\"LittleEndian\">\n<Collection>\n";
  for (const auto& [time, file] : entries_) {
    xml << "<DataSet timestep=\"" << time << "\" part=\"0\" file=\"" << XmlEscape(file) << "\"/>\n";
  }
  xml << "</Collection>\n</VTKFile>\n";
  WriteAtomically(path, xml.str());
}

}  // namespace filmdyn::io
