#include "core/io/pressure_csv.hpp"

#include "core/base/angles.hpp"
#include "core/io/output_files.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "core/base/input_error.hpp"
#include "core/base/input_file.hpp"

namespace filmdyn::io {

namespace {

double ParseCell(const std::string& cell, const std::string& where, const char* column) {
  const std::string text = Trim(cell);
  double value = 0.0;
  if (!ParseNumber(text, value) || !std::isfinite(value)) {
    throw InputError(where + " " + column, "\"" + text + "\"", "must be a finite number");
  }
  return value;
}

}  // namespace

engine::PressureCurve ReadPressureCsv(std::istream& in, const std::string& source) {
  std::string line;
  int line_number = 0;
  bool header_seen = false;
  std::vector<double> angles_deg, pressures;
  std::vector<int> lines;  // each point's line in the file
  while (std::getline(in, line)) {
    ++line_number;
    // A UTF-8 byte-order mark (spreadsheets write one) is no part of the header.
    if (line_number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    const std::string text = Trim(line);
    if (text.empty() || text[0] == '#') continue;
    const std::string where = source + ":" + std::to_string(line_number);
    const auto comma = text.find(',');
    if (!header_seen) {
      std::string header = Lower(text);
      header.erase(std::remove_if(header.begin(), header.end(),
                                  [](unsigned char c) { return std::isspace(c); }),
                   header.end());
      if (header != "crank_angle[deg],pressure[pa]") {
        throw InputError(where + " header", "\"" + text + "\"",
                         "must be \"crank_angle[deg],pressure[Pa]\" (absolute pressure in Pa)");
      }
      header_seen = true;
      continue;
    }
    if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos) {
      throw InputError(where, "\"" + text + "\"", "must have exactly two columns: angle, pressure");
    }
    lines.push_back(line_number);
    angles_deg.push_back(ParseCell(text.substr(0, comma), where, "crank_angle[deg]"));
    pressures.push_back(ParseCell(text.substr(comma + 1), where, "pressure[Pa]"));
    if (pressures.back() < 0) {
      throw InputError(where + " pressure[Pa]", FormatValue(pressures.back()),
                       "must be an absolute pressure >= 0 [Pa]");
    }
    if (angles_deg.back() < 0 || angles_deg.back() > 720) {
      throw InputError(where + " crank_angle[deg]", FormatValueOutside(angles_deg.back(), 0, 720),
                       "must lie in [0, 720] °CA");
    }
  }
  if (!header_seen) throw InputError(source, "empty", "needs a header and rows covering 0–720 °CA");
  std::vector<double> angles(angles_deg.size());
  std::transform(angles_deg.begin(), angles_deg.end(), angles.begin(),
                 [](double d) { return d * kRadiansPerDegree; });
  // A point's error names its line, as the cells' errors above do.
  engine::CurveFields fields;
  fields.curve = source;
  fields.point = [source, lines](std::size_t k, bool angle) {
    return source + ":" + std::to_string(lines[k]) +
           (angle ? " crank_angle[deg]" : " pressure[Pa]");
  };
  return engine::PressureCurve(std::move(angles), std::move(pressures), fields);
}

engine::PressureCurve ReadPressureCsvFile(const std::filesystem::path& path,
                                          const std::string& field) {
  std::istringstream text(ReadInputFile(path, field, std::uintmax_t{64} << 20));
  return ReadPressureCsv(text, path.string());
}

void WritePressureCsv(std::ostream& out, const std::vector<double>& crank_angle_deg,
                      const std::vector<double>& pressure, const std::string& comment,
                      CsvDigits digits) {
  std::istringstream lines(comment);
  std::string line;
  while (std::getline(lines, line)) out << "# " << line << "\n";
  out << "crank_angle[deg],pressure[Pa]\n";
  for (std::size_t k = 0; k < crank_angle_deg.size(); ++k) {
    out << (digits == CsvDigits::kTable
                ? fmt::format("{:.2f},{:.1f}\n", crank_angle_deg[k], pressure[k])
                : fmt::format("{},{}\n", crank_angle_deg[k], pressure[k]));
  }
}

}  // namespace filmdyn::io
