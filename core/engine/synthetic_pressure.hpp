#pragma once
/// @file A single-zone cylinder-pressure model for the synthetic default curves (the paper's
/// measured curves, its Fig. 5, are not published as data). Documented in
/// docs/pressure-model.md:
///  - closed cycle IVC → EVO: first law of a single zone with a constant polytropic exponent κ
///    (wall heat loss folded into κ and the heat-release efficiency), Heywood (1988) eq. 9.25:
///    dp/dφ = −κ p/V dV/dφ + (κ − 1)/V dQ/dφ;
///  - heat release: Wiebe function x_b = 1 − exp(−a ((φ − φ_0)/Δφ)^(m+1)), Heywood eq. 9.23;
///  - gas exchange: constant intake/exhaust pressures, exponential blow-down after EVO, a smooth
///    blend across the valve overlap at 0/720 °CA.
/// The volume follows the exact slider-crank kinematics of the case geometry (with pin offset).
#include <vector>

#include "core/engine/engine_case.hpp"

namespace filmdyn::engine {

struct SyntheticPressureParameters {
  double rpm = 6000.0;
  double intake_pressure = 0.95e5;        ///< manifold, absolute [Pa]
  double exhaust_pressure = 1.1e5;        ///< absolute [Pa]
  double intake_temperature = 330.0;      ///< charge at IVC [K]
  double ivc_deg = 225.0;                 ///< intake valve closing [°CA]
  double evo_deg = 490.0;                 ///< exhaust valve opening [°CA]
  double polytropic_exponent = 1.32;      ///< κ [-]
  double combustion_start_deg = 345.0;    ///< φ_0 [°CA]
  double combustion_duration_deg = 50.0;  ///< Δφ [°CA]
  double wiebe_a = 5.0, wiebe_m = 2.0;
  double air_fuel_ratio = 13.0;           ///< full load, slightly rich [-]
  double fuel_heating_value = 44.0e6;     ///< lower heating value [J/kg]
  double heat_release_efficiency = 0.72;  ///< net heat release / fuel energy [-]
  double blowdown_deg = 15.0;             ///< blow-down time constant [°CA]
  double overlap_blend_deg = 40.0;  ///< width of the exhaust→intake blend around 720/0 [°CA]

  /// The calibrated parameters of a naturally aspirated gasoline engine at full load at `rpm`
  /// (speed-dependent breathing and burn duration, docs/pressure-model.md table).
  static SyntheticPressureParameters ForSpeed(double rpm);
};

/// Absolute cylinder pressure [Pa] at each crank angle [°CA] in [0, 720].
std::vector<double> SyntheticCylinderPressure(const CrankTrainGeometry& geometry,
                                              const SyntheticPressureParameters& parameters,
                                              const std::vector<double>& crank_angle_deg);

}  // namespace filmdyn::engine
