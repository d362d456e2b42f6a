#pragma once
/// @file Engineering warnings about a finished run: the one definition of what FilmDyn warns
/// about once a run has ended — a film thinner than three times or than the surface roughness,
/// a big-end journal close to the bearing wall, a peak film pressure between output samples, no
/// periodic steady state, inputs still at the values the default case assumes, the synthetic
/// cylinder pressure. summary.json ("warnings"), the CLI and the GUI's run table show the same
/// list. Codes and keys: docs/outputs.md.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/engine/run_job.hpp"

namespace filmdyn::io {

/// Film thickness ratio λ = h_min / σ (σ = composite RMS roughness) below which the film is in
/// mixed lubrication, and below which the asperities carry load.
inline constexpr double kMixedLubricationRatio = 3.0;
inline constexpr double kAsperityContactRatio = 1.0;
/// Big-end eccentricity ratio above which the journal runs close to the bearing wall.
inline constexpr double kHighEccentricity = 0.95;
/// The lowest peak cylinder pressure [Pa, absolute] a running engine has: a motored engine of
/// compression ratio 8 compresses 1 bar to some 15 bar; below 5 bar the curve is more likely in
/// bar or MPa, or gauge, than a real cylinder's.
inline constexpr double kLowestPeakCylinderPressure = 5.0e5;
/// How far [°CA] a cylinder pressure's peak may lie from firing TDC (360 °CA): a fired engine
/// peaks some 5–40 °CA after it, a motored one just before it; a peak farther away is most likely
/// a curve whose firing TDC is at 0 °CA (a cycle counted from firing, not from intake TDC).
inline constexpr double kPeakFromFiringTdc = 90.0;

/// The highest oil-supply pressure [Pa, gauge] an engine's oil system delivers: galleries run at
/// 0.2–0.7 MPa, relief valves open below 1 MPa; above 2 MPa the value is more likely in the
/// wrong unit (kPa or bar typed as Pa are the low side, MPa typed as bar the high) than a real
/// feed, and the supply then carries load as a hydrostatic bearing would.
inline constexpr double kHighestSupplyPressure = 2.0e6;

/// The film pressure [Pa] above which a big end on rigid surfaces is warned of: at such pressures
/// the shell's elastic deformation spreads a thin film's load and lowers its peak, which the rigid
/// model leaves out (the default case at 1000 rpm: 352 MPa rigid, 238 MPa on the elastic layer;
/// at 6000 rpm 79 MPa, not warned).
inline constexpr double kRigidBigEndPeakPressure = 250e6;

/// The film pressure, as a fraction of its oil's bulk modulus, above which a compressible oil on
/// the linear density law is warned of: there the linear law compresses the oil by 28 % more
/// than Dowson and Higginson's law (0.1 against 0.078), and the gap grows fast beyond
/// (docs/validation/cavitation.md, section 1c).
inline constexpr double kLinearDensityPressureRatio = 0.1;

/// A supply hole of a mass-conserving big end is resolved when the film's node rows within 0.9
/// of its radius across the width number at least kHoleRowsAcross and the hole spans at least
/// kHoleElementsAround mean elements around (docs/validation/errors.md, section 6: with one row
/// across its oil per cycle was 7 % below the finest meshes', which the run's estimate sees).
inline constexpr int kHoleRowsAcross = 3;
inline constexpr double kHoleElementsAround = 4.0;

/// One warning. Stable codes: "asperity_contact", "mixed_lubrication" (film ratios; the worse
/// of the two per joint), "high_eccentricity", "not_periodic", "assumed_inputs",
/// "synthetic_pressure", "oil_extrapolated" (a catalogue oil outside its fit's temperatures;
/// value: the film temperature [K], limit: the bound it passes [K]), "unresolved_peak" (a peak
/// film pressure the output samples do not resolve, engine::SampledPeak; value: the larger of
/// its Ratio and StepRatio, limit: engine::kUnresolvedPeakRatio), "film_start_supply" (a
/// mass-conserving big end fed only by its film-start line at ambient pressure),
/// "supply_hole_mesh" (its supply holes on a mesh too coarse for them; value: the node rows
/// inside a hole across the width, limit: kHoleRowsAcross), "half_space_big_end" (a big end on
/// elastic half-spaces, a model engine runs outgrow), "high_supply_pressure" (the big end's
/// supply pressure above kHighestSupplyPressure; value: its peak [Pa], with the crank angle of a
/// curve's peak), "rigid_big_end_pressure" (a rigid big end's film pressure above
/// kRigidBigEndPeakPressure in the reported cycle's samples; value: the peak [Pa]),
/// "linear_density_law" (a compressible oil on the linear density law whose film pressure, in the
/// samples or at the steps, passed kLinearDensityPressureRatio of its bulk modulus; value: the
/// peak [Pa], limit: that fraction of the bulk modulus [Pa]).
struct RunWarning {
  std::string code;
  std::string joint;    ///< "skirt", "big_end", or empty (the whole run)
  std::string message;  ///< one sentence with the numbers, for people
  double value = 0.0;   ///< the worst value: λ, ε, the cycle-to-cycle change, a count of inputs
  double limit = 0.0;   ///< the limit it crosses (0 when there is none)
  /// Where in the reported cycle the worst value occurs [°CA].
  std::optional<double> crank_angle_deg;
  /// Intervals of the reported cycle [from, to] [°CA] where the limit is crossed (output steps
  /// that cross it); from > to: the interval wraps past 720 °CA into the next cycle.
  std::vector<std::pair<double, double>> crank_angle_ranges_deg;
  /// Where the minimum film is at crank_angle_deg. Skirt: angle from the thrust axis [deg] and
  /// distance below the skirt top [m]. Big end: direction of the journal's eccentricity in the
  /// rod-fixed frame (counter-clockwise from the rod-frame x axis; 90° = toward the small end)
  /// [deg], no axial position (the film is uniform across an aligned bearing).
  std::optional<double> position_angle_deg;
  std::optional<double> position_axial_m;
  /// assumed_inputs: the dotted case paths still at their assumed values; unused_inputs,
  /// implausible_proportions: the fields concerned.
  std::vector<std::string> fields;
};

/// The warnings of a run from its configuration and result (the reported cycle's samples; a
/// run that stopped early is judged on what it computed). Never throws for a run's numbers.
std::vector<RunWarning> RunWarnings(const engine::RunConfig& config,
                                    const engine::RunResult& result);

/// A few characters for a table cell, e.g. "h/σ 0.72 < 1", "ε 0.97 > 0.95".
std::string WarningShortText(const RunWarning& warning);

}  // namespace filmdyn::io
