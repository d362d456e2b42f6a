#include "core/io/field_series.hpp"

#include "core/io/output_files.hpp"

// The HDF5 C API (Debian: libhdf5-dev; core/CMakeLists.txt links HDF5::HDF5 into this package).
#include <hdf5.h>
#include <optional>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <set>
#include <stdexcept>
#include <system_error>
#include <string_view>
#include <utility>

namespace filmdyn::io {

namespace {

constexpr char kFormat[] = "FilmDyn field series";
constexpr int kFormatVersion = 1;

// ---------------------------------------------------------------------------------------------
// HDF5 plumbing: handles closed on every path, errors turned into text instead of being printed.

// The library prints its error stack to stderr by default; we report it in the exception instead.
// The setting is per thread (the Debian build is thread-safe), restored on exit.
class QuietHdf5Errors {
 public:
  QuietHdf5Errors() {
    H5Eget_auto2(H5E_DEFAULT, &function_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietHdf5Errors() { H5Eset_auto2(H5E_DEFAULT, function_, data_); }
  QuietHdf5Errors(const QuietHdf5Errors&) = delete;
  QuietHdf5Errors& operator=(const QuietHdf5Errors&) = delete;

 private:
  H5E_auto2_t function_ = nullptr;
  void* data_ = nullptr;
};

herr_t CollectError(unsigned /*n*/, const H5E_error2_t* error, void* data) {
  auto* lines = static_cast<std::vector<std::string>*>(data);
  std::string line = std::string(error->func_name ? error->func_name : "?") + "(): ";
  line += error->desc ? error->desc : "";
  char minor[128] = "";
  if (H5Eget_msg(error->min_num, nullptr, minor, sizeof minor) > 0 &&
      line.find(minor) == std::string::npos) {
    line += std::string(" (") + minor + ")";
  }
  lines->push_back(std::move(line));
  return 0;
}

// The API call that failed and the innermost cause (e.g. "file write failed: ... errno = 28,
// error message = 'No space left on device'"); the frames in between add nothing for a user.
std::string Hdf5ErrorText() {
  std::vector<std::string> lines;  // innermost first
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, CollectError, &lines);
  H5Eclear2(H5E_DEFAULT);
  if (lines.empty()) return "no HDF5 error recorded";
  if (lines.size() == 1) return lines.front();
  return lines.back() + " <- " + lines.front();
}

// Owns one HDF5 identifier (file, group, dataset, dataspace, type, property list, attribute).
class Hid {
 public:
  using Closer = herr_t (*)(hid_t);
  Hid(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  Hid(Hid&& other) noexcept : id_(std::exchange(other.id_, -1)), closer_(other.closer_) {}
  Hid(const Hid&) = delete;
  Hid& operator=(const Hid&) = delete;
  Hid& operator=(Hid&&) = delete;
  ~Hid() {
    if (id_ >= 0) closer_(id_);
  }
  hid_t get() const { return id_; }
  /// Closes now and returns the library's status (closing a file flushes it).
  herr_t Close() { return id_ >= 0 ? closer_(std::exchange(id_, -1)) : 0; }

 private:
  hid_t id_;
  Closer closer_;
};

// Where an HDF5 failure happened: "cannot write <file>: <what> (HDF5: <cause>)".
class H5Context {
 public:
  H5Context(std::filesystem::path file, const char* verb) : file_(std::move(file)), verb_(verb) {}

  [[noreturn]] void Fail(const std::string& what) const {
    throw std::runtime_error(std::string("cannot ") + verb_ + " " + file_.string() + ": " + what +
                             " (HDF5: " + Hdf5ErrorText() + ")");
  }
  [[noreturn]] void Invalid(const std::string& what) const {
    throw std::runtime_error(std::string("cannot ") + verb_ + " " + file_.string() + ": " + what);
  }
  Hid Check(hid_t id, Hid::Closer closer, const std::string& what) const {
    if (id < 0) Fail(what);
    return Hid(id, closer);
  }
  void Check(herr_t status, const std::string& what) const {
    if (status < 0) Fail(what);
  }

 private:
  std::filesystem::path file_;
  const char* verb_;
};

Hid Dataspace(const H5Context& h5, const std::vector<hsize_t>& dims) {
  return h5.Check(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose,
                  "creating a dataspace");
}

// UTF-8 because units contain '°'. Fixed length, NUL-terminated: readable by every HDF5 tool.
Hid StringType(const H5Context& h5, std::size_t length) {
  Hid type = h5.Check(H5Tcopy(H5T_C_S1), H5Tclose, "creating a string type");
  h5.Check(H5Tset_size(type.get(), length + 1), "sizing a string type");
  h5.Check(H5Tset_strpad(type.get(), H5T_STR_NULLTERM), "setting a string type's padding");
  h5.Check(H5Tset_cset(type.get(), H5T_CSET_UTF8), "setting a string type's character set");
  return type;
}

void WriteAttribute(const H5Context& h5, hid_t object, const char* name, const std::string& value) {
  const Hid type = StringType(h5, value.size());
  const Hid space = h5.Check(H5Screate(H5S_SCALAR), H5Sclose, "creating a dataspace");
  const std::string what = std::string("writing attribute '") + name + "'";
  const Hid attribute = h5.Check(
      H5Acreate2(object, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose, what);
  h5.Check(H5Awrite(attribute.get(), type.get(), value.c_str()), what);
}

void WriteAttribute(const H5Context& h5, hid_t object, const char* name, int value) {
  const Hid space = h5.Check(H5Screate(H5S_SCALAR), H5Sclose, "creating a dataspace");
  const std::string what = std::string("writing attribute '") + name + "'";
  const Hid attribute =
      h5.Check(H5Acreate2(object, name, H5T_STD_I32LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
               H5Aclose, what);
  h5.Check(H5Awrite(attribute.get(), H5T_NATIVE_INT, &value), what);
}

// Creation properties of a group or dataset without modification times: HDF5 stores them by
// default, and the same run must give the same bytes (the GUI's export and `filmdyn run`'s are
// compared byte for byte).
Hid UntimedProperties(const H5Context& h5, hid_t property_class) {
  Hid properties = h5.Check(H5Pcreate(property_class), H5Pclose, "creating object properties");
  h5.Check(H5Pset_obj_track_times(properties.get(), 0), "switching off modification times");
  return properties;
}

// Writes a whole dataset; `file_type` fixes the on-disk type whatever the platform.
Hid WriteDataset(const H5Context& h5, hid_t parent, const std::string& name, hid_t file_type,
                 hid_t memory_type, const std::vector<hsize_t>& dims, const void* data,
                 hid_t create_properties = H5P_DEFAULT) {
  const Hid space = Dataspace(h5, dims);
  const std::string what = "writing dataset '" + name + "'";
  std::optional<Hid> untimed;
  if (create_properties == H5P_DEFAULT) {
    untimed.emplace(UntimedProperties(h5, H5P_DATASET_CREATE));
    create_properties = untimed->get();
  }
  Hid dataset = h5.Check(H5Dcreate2(parent, name.c_str(), file_type, space.get(), H5P_DEFAULT,
                                    create_properties, H5P_DEFAULT),
                         H5Dclose, what);
  h5.Check(H5Dwrite(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), what);
  return dataset;
}

// ---------------------------------------------------------------------------------------------
// Names.

// "pressure[Pa]" -> ("pressure", "Pa"); "time" -> ("time", "").
std::pair<std::string, std::string> SplitUnits(const std::string& array_name) {
  const std::size_t open = array_name.find('[');
  if (open == std::string::npos) return {array_name, ""};
  std::string key = array_name.substr(0, open);
  while (!key.empty() && key.back() == ' ') key.pop_back();
  std::string units = array_name.substr(open + 1);
  if (!units.empty() && units.back() == ']') units.pop_back();
  return {key, units};
}

std::string XmlEscape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
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

// Shortest text that reads back as the same double (time values must match the .h5 exactly).
std::string RoundTrip(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

bool IsNameCharacter(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
}

std::filesystem::path WithSuffix(const std::filesystem::path& path, const char* suffix) {
  return std::filesystem::path(path.string() + suffix);
}

// ---------------------------------------------------------------------------------------------
// Writing.

// Chunked layout with shuffle + deflate for the per-frame datasets. A chunk holds whole frames:
// a reader of one frame inflates one chunk, and the shuffle filter (bytes of equal significance
// together) lets deflate find the repeated sign/exponent bytes of smooth fields and the runs of
// zeros of cavitated or contact-free regions.
Hid CompressedLayout(const H5Context& h5, const std::vector<hsize_t>& chunk,
                     const FieldSeriesOptions& options) {
  Hid create = UntimedProperties(h5, H5P_DATASET_CREATE);
  h5.Check(H5Pset_chunk(create.get(), static_cast<int>(chunk.size()), chunk.data()),
           "setting the chunk shape");
  if (options.deflate_level > 0) {
    if (H5Zfilter_avail(H5Z_FILTER_DEFLATE) <= 0) h5.Fail("the deflate filter is not available");
    h5.Check(H5Pset_shuffle(create.get()), "setting the shuffle filter");
    const auto level = static_cast<unsigned>(std::min(options.deflate_level, 9));
    h5.Check(H5Pset_deflate(create.get(), level), "setting the deflate filter");
  }
  return create;
}

// The whole .h5 as bytes. HDF5 builds the file in memory (core driver, no backing store) and
// WriteAndSync puts it on disk: when a flush to disk fails inside HDF5 (full disk), the library
// keeps the file open and HDF5 1.10.8 then crashes at exit closing it (measured with a file
// size limit), and its message hides errno. In memory nothing can fail that way, and our own
// write reports "No space left on device". The image is ~10 MB for a cycle of the skirt.
std::vector<unsigned char> Hdf5Image(const FieldSeries& series, const FieldSeriesOptions& options,
                                     const std::filesystem::path& shown_as) {
  const H5Context h5(shown_as, "write");
  const std::size_t n_frames = series.frames.size();
  const std::size_t n_points = series.points.size();
  const hsize_t chunk_rows =
      std::clamp<hsize_t>(static_cast<hsize_t>(std::max(options.frames_per_chunk, 1)), 1, n_frames);

  const Hid access = h5.Check(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "creating file properties");
  h5.Check(H5Pset_fapl_core(access.get(), std::size_t{1} << 20, /*backing_store=*/0),
           "selecting the in-memory driver");
  Hid h5_file = h5.Check(H5Fcreate(shown_as.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()),
                         H5Fclose, "creating the file");

  WriteAttribute(h5, h5_file.get(), "format", kFormat);
  WriteAttribute(h5, h5_file.get(), "format_version", kFormatVersion);
  WriteAttribute(h5, h5_file.get(), "name", series.name);
  WriteAttribute(h5, h5_file.get(), "rotating", series.rotating ? 1 : 0);

  {
    const Hid geometry =
        h5.Check(H5Gcreate2(h5_file.get(), "geometry", H5P_DEFAULT,
                            UntimedProperties(h5, H5P_GROUP_CREATE).get(), H5P_DEFAULT),
                 H5Gclose, "creating group /geometry");
    std::vector<double> xyz;
    xyz.reserve(3 * n_points);
    for (const auto& p : series.points) xyz.insert(xyz.end(), p.begin(), p.end());
    const Hid points = WriteDataset(h5, geometry.get(), "points", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                                    {n_points, 3}, xyz.data());
    WriteAttribute(h5, points.get(), "units", "m");
    std::vector<std::int32_t> nodes;
    nodes.reserve(3 * series.triangles.size());
    for (const auto& t : series.triangles) nodes.insert(nodes.end(), t.begin(), t.end());
    WriteDataset(h5, geometry.get(), "triangles", H5T_STD_I32LE, H5T_NATIVE_INT32,
                 {series.triangles.size(), 3}, nodes.data());
    if (series.rotating) {
      // For the XDMF readers, which cannot rotate: each frame's points as drawn. Float32 is
      // ample for a picture (~2 nm at a 24 mm radius) and halves the only per-frame geometry.
      std::vector<float> frame_xyz;
      frame_xyz.reserve(3 * n_points * n_frames);
      for (std::size_t i = 0; i < n_frames; ++i) {
        for (const auto& p : FramePoints(series, i)) {
          frame_xyz.insert(frame_xyz.end(), p.begin(), p.end());
        }
      }
      const Hid create = CompressedLayout(h5, {chunk_rows, n_points, 3}, options);
      const Hid frame_points =
          WriteDataset(h5, geometry.get(), "frame_points", H5T_IEEE_F32LE, H5T_NATIVE_FLOAT,
                       {n_frames, n_points, 3}, frame_xyz.data(), create.get());
      WriteAttribute(h5, frame_points.get(), "units", "m");
    }
  }
  {
    const Hid time =
        h5.Check(H5Gcreate2(h5_file.get(), "time", H5P_DEFAULT,
                            UntimedProperties(h5, H5P_GROUP_CREATE).get(), H5P_DEFAULT),
                 H5Gclose, "creating group /time");
    std::vector<double> values(n_frames);
    for (std::size_t i = 0; i < n_frames; ++i) values[i] = series.frames[i].crank_angle_deg;
    const Hid angle = WriteDataset(h5, time.get(), "crank_angle", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                                   {n_frames}, values.data());
    WriteAttribute(h5, angle.get(), "units", "°CA");
    if (series.rotating) {
      for (std::size_t i = 0; i < n_frames; ++i) values[i] = series.frames[i].rotation_z;
      const Hid rotation = WriteDataset(h5, time.get(), "rotation_z", H5T_IEEE_F64LE,
                                        H5T_NATIVE_DOUBLE, {n_frames}, values.data());
      WriteAttribute(h5, rotation.get(), "units", "rad");
    }
  }
  {
    // Creation order is tracked so that the arrays read back in the order they were given.
    const Hid group_properties = UntimedProperties(h5, H5P_GROUP_CREATE);
    h5.Check(H5Pset_link_creation_order(group_properties.get(),
                                        H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED),
             "tracking creation order");
    const Hid fields = h5.Check(
        H5Gcreate2(h5_file.get(), "fields", H5P_DEFAULT, group_properties.get(), H5P_DEFAULT),
        H5Gclose, "creating group /fields");
    const Hid create = CompressedLayout(h5, {chunk_rows, n_points}, options);
    std::vector<float> values(n_frames * n_points);
    for (std::size_t a = 0; a < series.array_names.size(); ++a) {
      for (std::size_t i = 0; i < n_frames; ++i) {
        std::copy(series.frames[i].arrays[a].begin(), series.frames[i].arrays[a].end(),
                  values.begin() + static_cast<std::ptrdiff_t>(i * n_points));
      }
      const auto [key, units] = SplitUnits(series.array_names[a]);
      const Hid dataset = WriteDataset(h5, fields.get(), key, H5T_IEEE_F32LE, H5T_NATIVE_FLOAT,
                                       {n_frames, n_points}, values.data(), create.get());
      WriteAttribute(h5, dataset.get(), "name", series.array_names[a]);
      WriteAttribute(h5, dataset.get(), "units", units);
    }
  }
  h5.Check(H5Fflush(h5_file.get(), H5F_SCOPE_GLOBAL), "flushing the file");
  const ssize_t size = H5Fget_file_image(h5_file.get(), nullptr, 0);
  if (size <= 0) h5.Fail("taking the file image");
  std::vector<unsigned char> image(static_cast<std::size_t>(size));
  if (H5Fget_file_image(h5_file.get(), image.data(), image.size()) != size) {
    h5.Fail("taking the file image");
  }
  h5.Check(h5_file.Close(), "closing the file");
  return image;
}

// The XDMF 3 index: one Uniform grid per frame in a Temporal collection, time = crank angle.
//
// Only what ParaView 5.11's Xdmf3 readers (Xdmf3ReaderS / Xdmf3ReaderT, the default for .xdmf)
// read correctly is used. Their VTK adapter asks an item for its number type before reading it,
// which HyperSlab and Function items cannot answer (the arrays are dropped, or the reader
// crashes), so one row of a [frames × points] dataset is selected with XDMF 3's hyperslab
// suffix on the HDF5 path, "file.h5:/path|start:stride:count:dataspace". The legacy XDMF 2
// reader ("XDMF Reader") does not know that suffix and reads geometry only.
// Every frame after the first takes topology (and fixed geometry) from the first frame through
// XInclude: element(/1/1/1/1/k) = Xdmf / Domain / collection / first frame / k-th child (Time is
// child 1), so nothing may be inserted before the first frame's Topology and Geometry.
std::string XdmfText(const FieldSeries& series, const std::string& h5_name) {
  const std::size_t n_frames = series.frames.size();
  const std::string n = std::to_string(series.points.size());
  const std::string m = std::to_string(series.triangles.size());
  const std::string f = std::to_string(n_frames);
  const std::string h5 = XmlEscape(h5_name) + ":";

  std::vector<std::pair<std::string, std::string>> arrays;  // (escaped name, dataset path)
  for (const std::string& name : series.array_names) {
    arrays.emplace_back(XmlEscape(name), h5 + "/fields/" + XmlEscape(SplitUnits(name).first));
  }

  std::string xml;
  xml.reserve(n_frames * (300 + 250 * arrays.size()) + 1000);
  xml += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!-- FilmDyn film fields of the " +
         XmlEscape(series.name) + " (data in " + XmlEscape(h5_name) +
         "), time = crank angle [°CA]. Open in ParaView with the Xdmf3 reader (S or T). -->\n"
         "<Xdmf xmlns:xi=\"http://www.w3.org/2001/XInclude\" Version=\"3.0\">\n <Domain>\n"
         "  <Grid Name=\"" +
         XmlEscape(series.name) + "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (std::size_t i = 0; i < n_frames; ++i) {
    const std::string row = std::to_string(i);
    xml += "   <Grid Name=\"" + XmlEscape(series.name) + "_" + row +
           "\" GridType=\"Uniform\">\n    <Time Value=\"" +
           RoundTrip(series.frames[i].crank_angle_deg) + "\"/>\n";
    if (i == 0) {
      xml += "    <Topology TopologyType=\"Triangle\" NumberOfElements=\"" + m +
             "\"><DataItem Dimensions=\"" + m +
             " 3\" NumberType=\"Int\" Precision=\"4\" Format=\"HDF\">" + h5 +
             "/geometry/triangles</DataItem></Topology>\n";
    } else {
      xml += "    <xi:include xpointer=\"element(/1/1/1/1/2)\"/>\n";
    }
    if (series.rotating) {
      xml += "    <Geometry GeometryType=\"XYZ\"><DataItem Dimensions=\"" + n +
             " 3\" NumberType=\"Float\" Precision=\"4\" Format=\"HDF\">" + h5 +
             "/geometry/frame_points|" + row + " 0 0:1 1 1:1 " + n + " 3:" + f + " " + n +
             " 3</DataItem></Geometry>\n";
    } else if (i == 0) {
      xml += "    <Geometry GeometryType=\"XYZ\"><DataItem Dimensions=\"" + n +
             " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" + h5 +
             "/geometry/points</DataItem></Geometry>\n";
    } else {
      xml += "    <xi:include xpointer=\"element(/1/1/1/1/3)\"/>\n";
    }
    for (const auto& [name, path] : arrays) {
      xml += "    <Attribute Name=\"" + name +
             "\" AttributeType=\"Scalar\" Center=\"Node\"><DataItem Dimensions=\"" + n +
             "\" NumberType=\"Float\" Precision=\"4\" Format=\"HDF\">" + path + "|" + row +
             " 0:1 1:1 " + n + ":" + f + " " + n + "</DataItem></Attribute>\n";
    }
    xml += "   </Grid>\n";
  }
  xml += "  </Grid>\n </Domain>\n</Xdmf>\n";
  return xml;
}

// ---------------------------------------------------------------------------------------------
// Reading.

std::string ReadStringAttribute(const H5Context& h5, hid_t object, const char* name) {
  const std::string what = std::string("reading attribute '") + name + "'";
  const Hid attribute = h5.Check(H5Aopen(object, name, H5P_DEFAULT), H5Aclose, what);
  const Hid type = h5.Check(H5Aget_type(attribute.get()), H5Tclose, what);
  if (H5Tget_class(type.get()) != H5T_STRING || H5Tis_variable_str(type.get()) > 0) {
    h5.Invalid("attribute '" + std::string(name) + "' is not a fixed-length string");
  }
  std::string value(H5Tget_size(type.get()), '\0');
  h5.Check(H5Aread(attribute.get(), type.get(), value.data()), what);
  value.resize(std::min(value.size(), value.find('\0')));
  return value;
}

int ReadIntAttribute(const H5Context& h5, hid_t object, const char* name) {
  const std::string what = std::string("reading attribute '") + name + "'";
  const Hid attribute = h5.Check(H5Aopen(object, name, H5P_DEFAULT), H5Aclose, what);
  int value = 0;
  h5.Check(H5Aread(attribute.get(), H5T_NATIVE_INT, &value), what);
  return value;
}

// Reads a whole dataset converted to `memory_type`; `dims` receives its shape, which must have
// `rank` dimensions.
template <typename T>
std::vector<T> ReadDataset(const H5Context& h5, hid_t file, const std::string& path,
                           hid_t memory_type, int rank, std::vector<hsize_t>* dims) {
  const std::string what = "reading dataset " + path;
  const Hid dataset = h5.Check(H5Dopen2(file, path.c_str(), H5P_DEFAULT), H5Dclose, what);
  const Hid space = h5.Check(H5Dget_space(dataset.get()), H5Sclose, what);
  if (H5Sget_simple_extent_ndims(space.get()) != rank) {
    h5.Invalid("dataset " + path + " does not have " + std::to_string(rank) + " dimensions");
  }
  dims->assign(static_cast<std::size_t>(rank), 0);
  H5Sget_simple_extent_dims(space.get(), dims->data(), nullptr);
  hsize_t count = 1;
  for (hsize_t d : *dims) count *= d;
  std::vector<T> values(count);
  if (count > 0) {
    h5.Check(H5Dread(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
             what);
  }
  return values;
}

// The .h5 an index refers to: the file part of its first HDF DataItem, relative to the index.
std::filesystem::path DataFileOf(const std::filesystem::path& xdmf) {
  std::ifstream in(xdmf, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + xdmf.string() + ": cannot open");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t item = text.find("Format=\"HDF\">");
  const std::size_t start = item == std::string::npos ? item : text.find('>', item) + 1;
  const std::size_t colon = start == std::string::npos ? start : text.find(':', start);
  if (colon == std::string::npos) {
    throw std::runtime_error("cannot read " + xdmf.string() + ": no HDF5 data item found");
  }
  std::string name = text.substr(start, colon - start);
  const auto blank = [](char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; };
  while (!name.empty() && blank(name.front())) name.erase(name.begin());
  while (!name.empty() && blank(name.back())) name.pop_back();
  return xdmf.parent_path() / name;
}

}  // namespace

// ---------------------------------------------------------------------------------------------

std::vector<std::array<double, 3>> FramePoints(const FieldSeries& series, std::size_t frame) {
  if (!series.rotating) return series.points;
  const double angle = series.frames.at(frame).rotation_z;
  const double c = std::cos(angle), s = std::sin(angle);
  std::vector<std::array<double, 3>> points;
  points.reserve(series.points.size());
  for (const auto& p : series.points) {
    points.push_back({c * p[0] - s * p[1], s * p[0] + c * p[1], p[2]});
  }
  return points;
}

void ValidateFieldSeries(const FieldSeries& series) {
  const std::string where = "field series '" + series.name + "': ";
  auto fail = [&where](const std::string& what) { throw std::invalid_argument(where + what); };
  if (series.name.empty() ||
      !std::all_of(series.name.begin(), series.name.end(), IsNameCharacter)) {
    fail("the name must be non-empty letters, digits, '_' or '-' (it names the files)");
  }
  const std::size_t n_points = series.points.size();
  if (n_points == 0) fail("no points");
  if (n_points > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
    fail("too many points for Int32 node indices");
  }
  for (std::size_t k = 0; k < n_points; ++k) {
    for (double x : series.points[k]) {
      if (!std::isfinite(x)) fail("point " + std::to_string(k) + " has a non-finite coordinate");
    }
  }
  if (series.triangles.empty()) fail("no triangles");
  for (std::size_t t = 0; t < series.triangles.size(); ++t) {
    for (int node : series.triangles[t]) {
      if (node < 0 || static_cast<std::size_t>(node) >= n_points) {
        fail("triangle " + std::to_string(t) + " has node index " + std::to_string(node) +
             " outside [0, " + std::to_string(n_points) + ")");
      }
    }
  }
  // The key becomes a dataset name and part of an XDMF path ("file.h5:/fields/key|slab"):
  // plain identifier characters keep both unambiguous.
  std::set<std::string> keys;
  for (const std::string& name : series.array_names) {
    const std::string key = SplitUnits(name).first;
    if (key.empty() || !std::all_of(key.begin(), key.end(), IsNameCharacter)) {
      fail("array name '" + name +
           "' needs letters, digits, '_' or '-' before its bracketed units");
    }
    if (!keys.insert(key).second) fail("two arrays are named '" + key + "'");
  }
  if (series.frames.empty()) fail("no frames");
  for (std::size_t i = 0; i < series.frames.size(); ++i) {
    const SeriesFrame& frame = series.frames[i];
    const std::string at =
        "frame " + std::to_string(i) + " (" + RoundTrip(frame.crank_angle_deg) + " °CA): ";
    if (!std::isfinite(frame.crank_angle_deg)) fail(at + "crank angle is not finite");
    // ParaView keys frames by time: equal or decreasing times would hide or reorder frames.
    if (i > 0 && !(frame.crank_angle_deg > series.frames[i - 1].crank_angle_deg)) {
      fail(at + "crank angle not greater than the previous frame's " +
           RoundTrip(series.frames[i - 1].crank_angle_deg));
    }
    if (!std::isfinite(frame.rotation_z)) fail(at + "rotation is not finite");
    if (!series.rotating && frame.rotation_z != 0.0) {
      fail(at + "rotation " + RoundTrip(frame.rotation_z) + " on a series that is not rotating");
    }
    if (frame.arrays.size() != series.array_names.size()) {
      fail(at + std::to_string(frame.arrays.size()) + " arrays for " +
           std::to_string(series.array_names.size()) + " array names");
    }
    for (std::size_t a = 0; a < frame.arrays.size(); ++a) {
      if (frame.arrays[a].size() != n_points) {
        fail(at + "array '" + series.array_names[a] + "' has " +
             std::to_string(frame.arrays[a].size()) + " values for " + std::to_string(n_points) +
             " points");
      }
    }
  }
}

void WriteFieldSeries(const std::filesystem::path& folder, const FieldSeries& series,
                      const FieldSeriesOptions& options) {
  ValidateFieldSeries(series);
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) {
    throw std::runtime_error("cannot create folder " + folder.string() + ": " + error.message());
  }
  const std::string h5_name = series.name + ".h5";
  const std::filesystem::path h5_path = folder / h5_name;
  const std::filesystem::path xdmf_path = folder / (series.name + ".xdmf");
  const std::filesystem::path h5_temporary = WithSuffix(h5_path, ".tmp");
  const std::filesystem::path xdmf_temporary = WithSuffix(xdmf_path, ".tmp");
  auto remove_temporaries = [&] {
    std::error_code ignored;
    std::filesystem::remove(h5_temporary, ignored);
    std::filesystem::remove(xdmf_temporary, ignored);
  };
  try {
    std::vector<unsigned char> image;
    {
      const QuietHdf5Errors quiet;
      image = Hdf5Image(series, options, h5_path);
    }
    WriteAndSync(h5_temporary, h5_path,
                 std::string_view(reinterpret_cast<const char*>(image.data()), image.size()));
    const std::string xdmf = XdmfText(series, h5_name);
    WriteAndSync(xdmf_temporary, xdmf_path, xdmf);
    // Old index first: between the two renames no index can pair new data with an old frame
    // list, and an old index never points at a half-replaced .h5 (each rename is atomic).
    std::filesystem::remove(xdmf_path, error);
    if (error) {
      throw std::runtime_error("cannot replace " + xdmf_path.string() + ": " + error.message());
    }
    RenameInto(h5_temporary, h5_path);
    RenameInto(xdmf_temporary, xdmf_path);
  } catch (...) {
    remove_temporaries();
    throw;
  }
}

FieldSeries ReadFieldSeries(const std::filesystem::path& xdmf_or_h5) {
  const std::string extension = xdmf_or_h5.extension().string();
  const std::filesystem::path file =
      extension == ".xdmf" || extension == ".xmf" ? DataFileOf(xdmf_or_h5) : xdmf_or_h5;
  const H5Context h5(file, "read");
  const QuietHdf5Errors quiet;
  Hid h5_file =
      h5.Check(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "opening the file");
  if (H5Aexists(h5_file.get(), "format") <= 0 ||
      ReadStringAttribute(h5, h5_file.get(), "format") != kFormat) {
    h5.Invalid(std::string("not a ") + kFormat + " (attribute 'format' missing or different)");
  }
  const int version = ReadIntAttribute(h5, h5_file.get(), "format_version");
  if (version < 1 || version > kFormatVersion) {
    h5.Invalid("format_version " + std::to_string(version) +
               " is not supported (newest: " + std::to_string(kFormatVersion) + ")");
  }

  FieldSeries series;
  series.name = ReadStringAttribute(h5, h5_file.get(), "name");
  series.rotating = ReadIntAttribute(h5, h5_file.get(), "rotating") != 0;

  std::vector<hsize_t> dims;
  const auto xyz =
      ReadDataset<double>(h5, h5_file.get(), "/geometry/points", H5T_NATIVE_DOUBLE, 2, &dims);
  if (dims[1] != 3) h5.Invalid("/geometry/points is not [points × 3]");
  const std::size_t n_points = dims[0];
  series.points.resize(n_points);
  for (std::size_t k = 0; k < n_points; ++k) {
    series.points[k] = {xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]};
  }
  const auto nodes = ReadDataset<std::int32_t>(h5, h5_file.get(), "/geometry/triangles",
                                               H5T_NATIVE_INT32, 2, &dims);
  if (dims[1] != 3) h5.Invalid("/geometry/triangles is not [triangles × 3]");
  series.triangles.resize(dims[0]);
  for (std::size_t t = 0; t < series.triangles.size(); ++t) {
    series.triangles[t] = {nodes[3 * t], nodes[3 * t + 1], nodes[3 * t + 2]};
  }

  const auto angles =
      ReadDataset<double>(h5, h5_file.get(), "/time/crank_angle", H5T_NATIVE_DOUBLE, 1, &dims);
  const std::size_t n_frames = angles.size();
  series.frames.resize(n_frames);
  for (std::size_t i = 0; i < n_frames; ++i) series.frames[i].crank_angle_deg = angles[i];
  if (series.rotating) {
    const auto rotation =
        ReadDataset<double>(h5, h5_file.get(), "/time/rotation_z", H5T_NATIVE_DOUBLE, 1, &dims);
    if (rotation.size() != n_frames) h5.Invalid("/time/rotation_z does not have one per frame");
    for (std::size_t i = 0; i < n_frames; ++i) series.frames[i].rotation_z = rotation[i];
  }

  const Hid fields =
      h5.Check(H5Gopen2(h5_file.get(), "/fields", H5P_DEFAULT), H5Gclose, "opening /fields");
  H5G_info_t info;
  h5.Check(H5Gget_info(fields.get(), &info), "listing /fields");
  for (hsize_t a = 0; a < info.nlinks; ++a) {
    const ssize_t length = H5Lget_name_by_idx(fields.get(), ".", H5_INDEX_CRT_ORDER, H5_ITER_INC, a,
                                              nullptr, 0, H5P_DEFAULT);
    if (length <= 0) h5.Fail("listing /fields");
    std::string key(static_cast<std::size_t>(length) + 1, '\0');
    if (H5Lget_name_by_idx(fields.get(), ".", H5_INDEX_CRT_ORDER, H5_ITER_INC, a, key.data(),
                           key.size(), H5P_DEFAULT) != length) {
      h5.Fail("listing /fields");
    }
    key.pop_back();
    const std::string path = "/fields/" + key;
    const auto values = ReadDataset<float>(h5, h5_file.get(), path, H5T_NATIVE_FLOAT, 2, &dims);
    if (dims[0] != n_frames || dims[1] != n_points) {
      h5.Invalid(path + " is not [" + std::to_string(n_frames) + " frames × " +
                 std::to_string(n_points) + " points]");
    }
    {
      const Hid dataset =
          h5.Check(H5Dopen2(h5_file.get(), path.c_str(), H5P_DEFAULT), H5Dclose, "opening " + path);
      series.array_names.push_back(ReadStringAttribute(h5, dataset.get(), "name"));
    }
    for (std::size_t i = 0; i < n_frames; ++i) {
      const auto row = values.begin() + static_cast<std::ptrdiff_t>(i * n_points);
      series.frames[i].arrays.emplace_back(row, row + static_cast<std::ptrdiff_t>(n_points));
    }
  }
  h5.Check(h5_file.Close(), "closing the file");
  try {
    ValidateFieldSeries(series);
  } catch (const std::invalid_argument& e) {
    h5.Invalid(std::string("inconsistent content: ") + e.what());
  }
  return series;
}

}  // namespace filmdyn::io
