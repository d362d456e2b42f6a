#include "ui/run/sample_conversion.hpp"

#include <limits>
#include <optional>

namespace filmdyn::ui {

std::array<const char*, kColumnCount> ColumnHeadersFromCore() {
  std::array<const char*, kColumnCount> headers{};
  const auto& columns = io::ResultColumns();
  for (int c = 0; c < kColumnCount; ++c) headers[std::size_t(c)] = columns[std::size_t(c)].header;
  return headers;
}

RunSample RunSampleFromRow(const io::OutputRow& row) {
  RunSample out;
  const auto& columns = io::ResultColumns();
  for (int c = 0; c < kColumnCount; ++c) {
    out.values[std::size_t(c)] = (row.*(columns[std::size_t(c)].member))
                                     .value_or(std::numeric_limits<double>::quiet_NaN());
  }
  return out;
}

std::vector<RunSample> RunSamplesFromRows(const std::vector<io::OutputRow>& rows) {
  std::vector<RunSample> samples;
  samples.reserve(rows.size());
  for (const auto& row : rows) samples.push_back(RunSampleFromRow(row));
  return samples;
}

}  // namespace filmdyn::ui
