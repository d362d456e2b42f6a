#pragma once
/// @file The one mapping from core's output rows (io::RowFromSample, which also writes
/// results.csv) to the GUI's samples, so plots, tables and files always show the same numbers.
#include <vector>

#include "core/io/results_writer.hpp"
#include "ui/run/result_columns.hpp"

namespace filmdyn::ui {

/// Copies the documented results.csv columns; columns the row lacks stay NaN.
RunSample RunSampleFromRow(const io::OutputRow& row);
std::vector<RunSample> RunSamplesFromRows(const std::vector<io::OutputRow>& rows);

}  // namespace filmdyn::ui
