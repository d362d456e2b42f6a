#pragma once
/// @file Cylinder-pressure tables as CSV: a header `crank_angle[deg],pressure[Pa]` (absolute
/// pressure), one row per crank angle covering 0–720 °CA; lines starting with '#' are comments.
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "core/engine/pressure_curve.hpp"

namespace filmdyn::io {

/// Parses CSV text; `source` names the file in errors ("curve.csv:12"). Throws InputError.
engine::PressureCurve ReadPressureCsv(std::istream& in, const std::string& source);
/// Reads the file (a regular file of at most 64 MB); errors name `field` (the option or case
/// field that gave the path) and the file's line.
engine::PressureCurve ReadPressureCsvFile(const std::filesystem::path& path,
                                          const std::string& field = "--pressure-curve");

/// How many digits WritePressureCsv writes: kExact, every number as the shortest text that
/// reads back as the same double (an export the import gives back bit for bit); kTable, 0.01 °CA
/// and 0.1 Pa (the shipped synthetic tables).
enum class CsvDigits { kExact, kTable };
/// Writes the table with the standard header, after `comment` lines (each prefixed "# ").
void WritePressureCsv(std::ostream& out, const std::vector<double>& crank_angle_deg,
                      const std::vector<double>& pressure, const std::string& comment,
                      CsvDigits digits = CsvDigits::kExact);

}  // namespace filmdyn::io
