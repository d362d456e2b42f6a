#pragma once
/// @file The per-output-step quantities of a run: exactly the results.csv columns of SPEC §4, in
/// SI. A model that lacks a quantity leaves it NaN (an empty CSV cell).
#include <array>
#include <cstddef>
#include <limits>

namespace filmdyn::ui {

enum class Column {
  kCrankAngle,  ///< [deg], 0–720 within the reported cycle
  kTime,
  kPistonLateral,
  kPistonTilt,
  kPistonLateralVelocity,
  kPistonTiltRate,
  kSkirtNormalForce,
  kSkirtFrictionForce,
  kSkirtMoment,
  kSkirtMoft,
  kSkirtFpl,
  kJournalEccX,
  kJournalEccY,
  kBearingEps,
  kBearingMoft,
  kBearingFpl,
  kBigEndForceX,
  kBigEndForceY,
  kGasForce,
  kCount
};
constexpr int kColumnCount = int(Column::kCount);

/// results.csv header names with units, in Column order.
constexpr std::array<const char*, kColumnCount> kColumnHeaders = {"crank_angle[deg]",
                                                                  "time[s]",
                                                                  "piston_lateral[m]",
                                                                  "piston_tilt[rad]",
                                                                  "piston_lateral_velocity[m/s]",
                                                                  "piston_tilt_rate[rad/s]",
                                                                  "skirt_normal_force[N]",
                                                                  "skirt_friction_force[N]",
                                                                  "skirt_moment[N*m]",
                                                                  "skirt_moft[m]",
                                                                  "skirt_fpl[W]",
                                                                  "journal_ecc_x[m]",
                                                                  "journal_ecc_y[m]",
                                                                  "bearing_eps[-]",
                                                                  "bearing_moft[m]",
                                                                  "bearing_fpl[W]",
                                                                  "bigend_force_x[N]",
                                                                  "bigend_force_y[N]",
                                                                  "gas_force[N]"};

/// One output step.
struct RunSample {
  RunSample() { values.fill(std::numeric_limits<double>::quiet_NaN()); }
  double operator[](Column c) const { return values[std::size_t(c)]; }
  double& operator[](Column c) { return values[std::size_t(c)]; }
  std::array<double, kColumnCount> values;
};

}  // namespace filmdyn::ui
