#include "ui/run/sample_conversion.hpp"

#include <limits>
#include <optional>

namespace filmdyn::ui {

RunSample RunSampleFromRow(const io::OutputRow& row) {
  RunSample out;
  auto set = [&out](Column column, const std::optional<double>& value) {
    out[column] = value.value_or(std::numeric_limits<double>::quiet_NaN());
  };
  set(Column::kCrankAngle, row.crank_angle_deg);
  set(Column::kTime, row.time);
  set(Column::kPistonLateral, row.piston_lateral);
  set(Column::kPistonTilt, row.piston_tilt);
  set(Column::kPistonLateralVelocity, row.piston_lateral_velocity);
  set(Column::kPistonTiltRate, row.piston_tilt_rate);
  set(Column::kSkirtNormalForce, row.skirt_normal_force);
  set(Column::kSkirtFrictionForce, row.skirt_friction_force);
  set(Column::kSkirtMoment, row.skirt_moment);
  set(Column::kSkirtMoft, row.skirt_moft);
  set(Column::kSkirtFpl, row.skirt_fpl);
  set(Column::kJournalEccX, row.journal_ecc_x);
  set(Column::kJournalEccY, row.journal_ecc_y);
  set(Column::kBearingEps, row.bearing_eps);
  set(Column::kBearingMoft, row.bearing_moft);
  set(Column::kBearingFpl, row.bearing_fpl);
  set(Column::kBigEndForceX, row.bigend_force_x);
  set(Column::kBigEndForceY, row.bigend_force_y);
  set(Column::kGasForce, row.gas_force);
  return out;
}

std::vector<RunSample> RunSamplesFromRows(const std::vector<io::OutputRow>& rows) {
  std::vector<RunSample> samples;
  samples.reserve(rows.size());
  for (const auto& row : rows) samples.push_back(RunSampleFromRow(row));
  return samples;
}

}  // namespace filmdyn::ui
