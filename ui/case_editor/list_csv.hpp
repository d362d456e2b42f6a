#pragma once
/// @file CSV import and export of a list table of the case (CaseListTable: the supply-pressure
/// curve, the supply holes, the liner oil film, the skirt profile and ovality), one implementation
/// for all of them, driven by the table's schema columns. Format: lines starting with '#' are
/// comments and blank lines are skipped (as in core's pressure CSV); then a header naming the
/// table's columns exactly as the table shows them, display unit in brackets
/// ("crank angle [°],gauge pressure [MPa]"); then one row per table row, one cell per column, in
/// those display units (degrees where the case file stores radians). Reading checks each cell:
/// a finite number ('.' decimal point) within its field's range; the rules that tie rows together
/// (increasing positions, a curve's steps) stay core's, shown on the table after the import.
#include <QString>
#include <string>
#include <vector>

#include "core/engine/engine_case.hpp"
#include "ui/case_editor/case_parameters.hpp"

namespace filmdyn::ui {

/// The header line: the table's column titles (CaseListColumnTitle) joined by commas.
std::string ListCsvHeader(const CaseListTable& table);

/// Parses CSV text into one list per column, in SI. `source` names the file in errors, which
/// read "<source>:<line> <column> = "<value>": <what is allowed>". Throws InputError: no header
/// (an empty file), a header that is not the table's, a row with another number of cells, a cell
/// that is no finite number or outside its field's range. A header and no rows is a table with
/// no rows.
std::vector<std::vector<double>> ParseListCsv(const CaseListTable& table, const std::string& text,
                                              const std::string& source);

/// Reads the file at `path` (a regular file of at most 16 MB, UTF-8) with ParseListCsv. False
/// with *error (the file, the line, the value and what is allowed); *columns is then unchanged.
bool ReadListCsv(const CaseListTable& table, const QString& path,
                 std::vector<std::vector<double>>* columns, QString* error);

/// The CSV text of the table in `c`: two comment lines (which table, the units), the header, one
/// row per table row with 15 significant digits (reading it back gives the same digits).
/// Throws InputError naming the row and column of a cell that is not a number.
std::string ListCsvText(const CaseListTable& table, const engine::EngineCase& c);

/// Writes ListCsvText to `path` atomically (a temporary file renamed over it). False with
/// *error; an existing file is then left as it was.
bool WriteListCsv(const CaseListTable& table, const engine::EngineCase& c, const QString& path,
                  QString* error);

}  // namespace filmdyn::ui
