#include "ui/case_editor/list_csv.hpp"

#include <QObject>
#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>

#include "core/base/input_error.hpp"
#include "core/base/input_file.hpp"
#include "core/io/output_files.hpp"
#include "ui/case_editor/field_tooltip.hpp"
#include "ui/save_text.hpp"

namespace filmdyn::ui {

namespace {

constexpr std::uintmax_t kMaxCsvBytes = std::uintmax_t{16} << 20;

// A cell without the spaces around it and one pair of double quotes (a spreadsheet's quoting).
std::string Cell(const std::string& text) {
  std::string cell = Trim(text);
  if (cell.size() >= 2 && cell.front() == '"' && cell.back() == '"') {
    cell = Trim(cell.substr(1, cell.size() - 2));
  }
  return cell;
}

std::vector<std::string> SplitCells(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    cells.push_back(Cell(line.substr(start, comma - start)));
    if (comma == std::string::npos) return cells;
    start = comma + 1;
  }
}

// A header cell compared loosely: case and spaces ignored, "deg" for "°", "u" for "µ" (what a
// file written without those characters has), a crank angle's "°CA" as "°" (files exported
// before the supply curve's crank angles were labelled °CA).
QString HeaderKey(const std::string& cell) {
  QString key = QString::fromStdString(cell).toLower();
  key.remove(QChar(' ')).remove(QChar('\t'));
  key.replace(QChar(0x00B0), "deg").replace(QChar(0x00B5), "u").replace(QChar(0x03BC), "u");
  key.replace("[degca]", "[deg]");
  return key;
}

std::string ColumnTitle(const engine::CaseField& field) {
  return CaseListColumnTitle(field).toStdString();
}

// "one cell: angles [°]", "2 cells: crank angle [°], gauge pressure [MPa]".
std::string CellsText(const CaseListTable& table) {
  std::string names;
  for (const engine::CaseField* field : table.columns) {
    names += (names.empty() ? "" : ", ") + ColumnTitle(*field);
  }
  const std::size_t n = table.columns.size();
  return (n == 1 ? std::string("one cell") : std::to_string(n) + " cells") + ": " + names;
}

double ParseValue(const std::string& cell, const engine::CaseField& field,
                  const std::string& where) {
  const std::string column = where + " " + ColumnTitle(field);
  double value = 0.0;
  if (!ParseNumber(cell, value) || !std::isfinite(value)) {
    throw InputError(column, "\"" + cell + "\"",
                     "must be a finite number (with '.' as the decimal point)");
  }
  const double si = engine::ScaleFromDisplay(value, field.display_scale);
  try {
    field.Check(si);
  } catch (const InputError&) {
    throw InputError(column, "\"" + cell + "\"",
                     "outside the allowed values (" + DisplayRangeText(field).toStdString() + ")");
  }
  return si;
}

}  // namespace

std::string ListCsvHeader(const CaseListTable& table) {
  std::string header;
  for (const engine::CaseField* field : table.columns) {
    if (!header.empty()) header += ',';
    header += ColumnTitle(*field);
  }
  return header;
}

std::vector<std::vector<double>> ParseListCsv(const CaseListTable& table, const std::string& text,
                                              const std::string& source) {
  RequireUtf8(source, text);
  const std::size_t n = table.columns.size();
  std::vector<std::vector<double>> columns(n);
  bool header_seen = false;
  int line_number = 0;
  std::size_t start = 0;
  // A byte-order mark (spreadsheets write one) is no part of the header.
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) start = 3;
  while (start < text.size()) {
    std::size_t stop = text.find('\n', start);
    if (stop == std::string::npos) stop = text.size();
    const std::string line = Trim(text.substr(start, stop - start));
    start = stop + 1;
    ++line_number;
    if (line.empty() || line[0] == '#') continue;
    const std::string where = source + ":" + std::to_string(line_number);
    const std::vector<std::string> cells = SplitCells(line);
    if (!header_seen) {
      bool same = cells.size() == n;
      for (std::size_t c = 0; same && c < n; ++c) {
        same = HeaderKey(cells[c]) == HeaderKey(ColumnTitle(*table.columns[c]));
      }
      if (!same) {
        throw InputError(where + " header", "\"" + line + "\"",
                         "must be \"" + ListCsvHeader(table) +
                             "\": the table's columns, values in the units in brackets");
      }
      header_seen = true;
      continue;
    }
    if (cells.size() != n) {
      throw InputError(
          where, "\"" + line + "\"",
          "must have " + CellsText(table) + " (found " + std::to_string(cells.size()) + ")");
    }
    for (std::size_t c = 0; c < n; ++c) {
      columns[c].push_back(ParseValue(cells[c], *table.columns[c], where));
    }
  }
  if (!header_seen) {
    throw InputError(source, "empty",
                     "needs the header \"" + ListCsvHeader(table) + "\" and one row per point");
  }
  return columns;
}

bool ReadListCsv(const CaseListTable& table, const QString& path,
                 std::vector<std::vector<double>>* columns, QString* error) {
  try {
    const std::string file = path.toStdString();
    const std::string text = ReadInputFile(std::filesystem::path(file), "CSV file", kMaxCsvBytes);
    *columns = ParseListCsv(table, text, file);
  } catch (const std::exception& e) {
    *error = QString::fromStdString(e.what());
    return false;
  }
  return true;
}

std::string ListCsvText(const CaseListTable& table, const engine::EngineCase& c) {
  auto& located = const_cast<engine::EngineCase&>(c);  // the accessors only locate the lists
  std::string fields;
  std::size_t rows = 0;
  for (const engine::CaseField* field : table.columns) {
    fields += (fields.empty() ? "" : ", ") + field->path + " [" + field->unit + "]";
    rows = std::max(rows, field->list(located).size());
  }
  std::string text = "# " + table.title.toStdString() + ", exported by FilmDyn\n";
  text +=
      "# values in the units of the header, as the case editor shows them; the case file "
      "stores SI: " +
      fields + "\n";
  text += ListCsvHeader(table) + "\n";
  for (std::size_t row = 0; row < rows; ++row) {
    std::string line;
    for (const engine::CaseField* field : table.columns) {
      const std::vector<double>& values = field->list(located);
      const double display = row < values.size()
                                 ? engine::ScaleToDisplay(values[row], field->display_scale)
                                 : std::nan("");
      if (!std::isfinite(display)) {
        throw InputError(table.title.toStdString() + " row " + std::to_string(row + 1) + " " +
                             ColumnTitle(*field),
                         row < values.size() ? FormatValue(values[row]) : "(missing)",
                         "must be a number to be exported: correct the table first");
      }
      if (!line.empty()) line += ',';
      line += QString::number(display, 'g', 15).toStdString();
    }
    text += line + "\n";
  }
  return text;
}

bool WriteListCsv(const CaseListTable& table, const engine::EngineCase& c, const QString& path,
                  QString* error) {
  std::string text;
  try {
    text = ListCsvText(table, c);
  } catch (const std::exception& e) {
    *error = QString::fromStdString(e.what());
    return false;
  }
  return SaveTextFile(path, text, error);
}

}  // namespace filmdyn::ui
