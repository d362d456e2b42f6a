#pragma once
/// @file The per-output-step quantities a run shows: the leading documented results.csv columns
/// (docs/outputs.md) of core's column table, in
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
  kSkirtPeakPressure,
  kSkirtPeakContactPressure,
  kSkirtContactFrictionForce,
  kSkirtContactFpl,
  kBearingPeakPressure,
  kBearingPeakContactPressure,
  kBearingFrictionForce,
  kBearingContactFrictionForce,
  kBearingContactFpl,
  kBigEndForceRodX,
  kBigEndForceRodY,
  kBearingEpsRate,
  kSkirtInflow,              ///< oil into the skirt film through its boundary [m^3/s]
  kSkirtOutflow,             ///< oil out of it [m^3/s]
  kSkirtWettedFraction,      ///< oil-covered share of the skirt panels [-]
  kBearingSupplyFlow,        ///< oil into the big-end film through its supply [m^3/s]
  kBearingSideFlow,          ///< oil out of the big end's edges [m^3/s]
  kSkirtStepPeakPressure,    ///< JFO skirt: peak pressure of the steps since the last row [Pa]
  kBearingStepPeakPressure,  ///< JFO big end: the same [Pa]
  kCount
};
constexpr int kColumnCount = int(Column::kCount);

/// results.csv header names with units, in Column order: the first kColumnCount columns of
/// core's one column table (io::ResultColumns), which the enum above indexes.
std::array<const char*, kColumnCount> ColumnHeadersFromCore();
inline const std::array<const char*, kColumnCount> kColumnHeaders = ColumnHeadersFromCore();

/// One output step.
struct RunSample {
  RunSample() { values.fill(std::numeric_limits<double>::quiet_NaN()); }
  double operator[](Column c) const { return values[std::size_t(c)]; }
  double& operator[](Column c) { return values[std::size_t(c)]; }
  std::array<double, kColumnCount> values;
};

}  // namespace filmdyn::ui
