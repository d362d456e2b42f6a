#pragma once
/// @file results.csv of a run as SPEC §4 defines it (header with units, one row per output step,
/// empty cells for quantities the model does not have), written atomically.
#include <QString>
#include <vector>

#include "ui/run/result_columns.hpp"

namespace filmdyn::ui {

bool WriteResultsCsv(const std::vector<RunSample>& samples, const QString& path, QString* error);

}  // namespace filmdyn::ui
