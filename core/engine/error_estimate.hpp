#pragma once
/// @file The headline figures of a run and the estimate of their discretisation error.
///
/// Headline figures: what a designer reads first, over the reported cycle — the minimum film
/// thickness of each lubricated joint, the big end's largest eccentricity ratio, the peak film
/// pressure of each joint, the cycle-mean friction power loss of each joint, the piston's largest
/// lateral displacement and tilt, the largest skirt side force and big-end film force components,
/// the largest piston-slap energy and, for a mass-conserving film, the oil it takes in over the
/// cycle. This is their one definition: summary.json, the CLI, the GUI and the estimate all use it.
///
/// Estimate: a second, coarser run of the whole coupled model — every film mesh with half the
/// elements in each direction (same grading; spacing ratio r ≈ 2), the run's own integrator
/// tolerances (so that the time error is alike in both). Richardson's estimate of the run's
/// error is then (f − f_coarse) / (r^p − 1) with p = 2 the figures' observed order, signed:
/// converged value ≈ f + error. It sees the coupled result (the coarse films move the journal and
/// the piston). Justification and its check against converged solutions: docs/validation/errors.md.
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/engine/crank_train.hpp"
#include "core/engine/engine_case.hpp"

namespace filmdyn::engine {

/// One headline figure of a run.
struct HeadlineFigure {
  std::string key;    ///< e.g. "bearing_moft_min[m]" (summary.json key, unit in brackets)
  std::string label;  ///< e.g. "min big-end MOFT" (messages, GUI)
  double value = 0.0;  ///< SI
  bool big_end = false;  ///< the figure belongs to the big end (else the skirt)
  double order = 2.0;    ///< its observed order of convergence in the element size
};

/// What the largest piston-slap energy needs besides the output samples (SlapOf): the motion
/// samples between them and the piston's mass [kg] and inertia about its centre of mass [kg m²].
/// Without them (mass 0) the headline figures have no slap figure.
struct SlapInputs {
  const std::vector<MotionSample>* motion = nullptr;
  double mass = 0.0, inertia = 0.0;
};

/// The headline figures present for the samples' joints, in a fixed order: skirt MOFT min,
/// skirt peak pressure, skirt mean FPL, max |e0|, max |γ|, max |skirt F_n|, the largest
/// piston-slap energy (with `slap` given; none when the piston never changes side), skirt oil
/// per cycle, big-end MOFT min, max ε, big-end peak pressure, big-end mean FPL, max |big-end
/// F_x|, max |big-end F_y| (the film's force on the rod, global frame), big-end oil per cycle.
/// Means are plain means over the cycle's equally spaced output samples (the periodic
/// trapezoidal rule); the oil per cycle is AccountedOil's, present for mass-conserving films
/// only. Means and the oil per cycle are figures of a whole cycle: absent when the samples are
/// not one (SamplesSpanACycle: a run stopped before its first cycle ended). Empty when no sample
/// has a lubricated joint.
std::vector<HeadlineFigure> HeadlineFigures(const std::vector<CrankTrainSample>& samples,
                                            const SlapInputs& slap = {});

/// Oil into and out of a joint's film over a cycle [m^3].
struct OilPerCycle {
  double in = 0.0;   ///< big end: through its supply; skirt: at its inflow nodes
  double out = 0.0;  ///< big end: side leakage; skirt: at its outflow nodes
};
/// A mass-conserving film's oil per cycle from the account it books at every integrator step
/// (coupling::OilAccount): between the first and last of the equally spaced output samples,
/// scaled to the samples' whole span (their count times their interval: the cycle's duration for
/// a whole cycle). None when the joint keeps no account (a Reynolds film), there are fewer
/// than two samples, or they are not a whole cycle (SamplesSpanACycle).
std::optional<OilPerCycle> AccountedOil(const std::vector<CrankTrainSample>& samples, bool big_end);
/// Whether equally spaced output samples are one whole engine cycle (720 °CA: their count times
/// their interval, to within half an interval), so that the last is followed by the first. The
/// one definition of a whole cycle for every figure over the reported samples (oil per cycle,
/// peaks and ranges wrapped round the cycle, slap): a completed or not-converged run reports
/// one; a run stopped in its second or later cycle reports the last whole one; a run stopped
/// before its first cycle ended reports the part it computed (shorter than a cycle, or longer in
/// a run-in of more than 720 °CA), over which a figure "per cycle" would be that part's.
bool SamplesSpanACycle(const std::vector<CrankTrainSample>& samples);
/// The same rule for `count` equally spaced samples `interval` [rad] apart (samples held in
/// another form, e.g. the GUI's).
bool SpanIsACycle(std::size_t count, double interval);
/// The figure of a headline key with this value: label, joint and order from the table (an
/// unknown key keeps itself as label; "bearing_…" keys belong to the big end).
HeadlineFigure HeadlineFigureFor(const std::string& key, double value);

/// Ratio of a peak's largest output sample to the larger of the two samples beside it above
/// which the output samples do not resolve the peak in time. A peak shaped like a Gaussian whose
/// width at half height spans w output intervals is down to 2^(-4/w²) of its height one
/// interval away: 1/1.5 at w = 2.6. A narrower peak (an impact lasting a fraction of an output
/// interval) is reported at whatever height the samples happen to catch.
inline constexpr double kUnresolvedPeakRatio = 1.5;

/// The output samples beside sample `at` of `count`: the one before and the one after it, none
/// past an end of samples that are not a whole cycle (the last is beside the first when they
/// are). The one rule for every test of a spike between output samples.
struct SamplesBeside {
  std::optional<std::size_t> before, after;
};
SamplesBeside SamplesBesideOf(std::size_t count, std::size_t at, bool whole_cycle);

/// A sample's value over the larger of the two samples beside it (NaN: none there): infinite
/// when both are zero and the value is not, 1 without a neighbour. Above kUnresolvedPeakRatio
/// the value is a spike the output samples do not resolve.
double NeighbourRatio(double value, double before, double after);

/// A peak headline figure (a joint's peak film pressure) with the output samples beside it and,
/// for a mass-conserving film, the peak of its accepted integrator steps between the samples.
struct SampledPeak {
  HeadlineFigure figure;  ///< value = the largest sample
  std::size_t index = 0;  ///< that sample
  /// The samples before and after it; NaN past an end of samples that are not a whole cycle.
  double before = std::numeric_limits<double>::quiet_NaN();
  double after = std::numeric_limits<double>::quiet_NaN();
  /// The largest step_peak_pressure of the samples (NaN when the film books no steps) and the
  /// sample that took it (the steps since the sample before it).
  double step_peak = std::numeric_limits<double>::quiet_NaN();
  std::size_t step_index = 0;
  /// NeighbourRatio of the value.
  double Ratio() const { return NeighbourRatio(figure.value, before, after); }
  /// step_peak / value (1 without step peaks).
  double StepRatio() const;
  /// Either ratio above kUnresolvedPeakRatio: a spike the output samples do not resolve — they
  /// catch it only in part, or miss it and the steps between them show it.
  bool Unresolved() const {
    return Ratio() > kUnresolvedPeakRatio || StepRatio() > kUnresolvedPeakRatio;
  }
};

/// The peak figures of the samples' joints (skirt, then big end) with their neighbours.
/// `whole_cycle`: the samples are one periodic cycle, the last one beside the first.
std::vector<SampledPeak> SampledPeaks(const std::vector<CrankTrainSample>& samples,
                                      bool whole_cycle);

/// The coarse companion of a case: meshes with half the elements (never below each count's
/// minimum), the same gradings, the same tolerances (`tolerance_factor` = 1; kept in the
/// summary so that a reader sees what the companion used).
struct CoarseCompanion {
  EngineCase engine_case;
  double skirt_ratio = 2.0;        ///< h_coarse / h of the skirt mesh (√ of the element ratio)
  double big_end_ratio = 2.0;      ///< the same for the big-end mesh
  double tolerance_factor = 1.0;   ///< coarse tolerances / the run's
  /// The highest order of convergence the skirt's figures are taken at: 1 for a starved skirt
  /// (its inlet takes the liner's film half a cell late, a first-order lag; observed orders
  /// 1.1 for its friction and oil, 1.6-2 for its film: docs/validation/errors.md, section 6),
  /// else none below the figures' own.
  double skirt_max_order = 2.0;
  /// The same for the big end's figures but its oil per cycle: 1 for a mass-conserving big end
  /// fed through holes (its minimum film and friction power converged at observed orders
  /// 0.7-1.7 from the default mesh at 2000 rpm, and an order-2 estimate gave half the film's
  /// true error; its oil converged at 1.7-2.4 and keeps its own order: docs/validation/errors.md,
  /// section 6), else none below the figures' own.
  double big_end_max_order = 2.0;
};
CoarseCompanion MakeCoarseCompanion(const EngineCase& engine_case);

/// The estimate for one figure.
struct FigureError {
  HeadlineFigure figure;
  double coarse_value = 0.0;  ///< the same figure of the coarse run
  double error = 0.0;         ///< signed estimate: converged ≈ value + error (SI)
  double relative = 0.0;      ///< |error| / |value|
  /// false: a peak figure that the output samples of the run or of its companion do not resolve
  /// in time (SampledPeak::Unresolved); the two compared values are then whatever the samples
  /// caught, so the figure is left out of the worst estimate and the summary says so.
  bool resolved_in_time = true;
  /// A film's minimum or the eccentricity's maximum is the extreme of the curve the two runs'
  /// samples extrapolate to, sample by sample (EstimateErrors): the unwrapped crank angle [rad]
  /// of this run's sample where that extreme lies; empty for the other figures, or when the two
  /// runs' samples are not at the same crank angles (then the figures' own extremes are compared).
  std::optional<double> extrapolated_crank_angle;
  /// The unwrapped crank angle [rad] of this run's own extreme, beside the one above.
  std::optional<double> crank_angle;
  /// The extrapolated curve's extreme lies more than kElsewhereAngle from this run's own and
  /// beyond the extrapolated curve there by more than kElsewhereShare of the figure: the meshes
  /// disagree on where in the cycle the extreme lies (the summary line says so).
  bool extreme_elsewhere = false;
  /// The companion's figure lies more than kFarCompanion from this run's: its mesh is outside
  /// the range where the two meshes' difference measures the error, and the estimate is rough
  /// (the summary line says so).
  bool far_companion = false;
  /// How far the companion's figure lies from this run's: |coarse_value / value − 1| (0 for a
  /// figure of value 0).
  double CompanionDistance() const {
    return figure.value != 0.0 ? std::abs(coarse_value / figure.value - 1.0) : 0.0;
  }
};

/// When an extrapolated extreme counts as lying elsewhere in the cycle (FigureError): at least
/// this far from the run's own [°CA] ...
inline constexpr double kElsewhereAngle = 10.0;
/// ... and beyond the extrapolated curve at the run's own extreme by this share of the figure
/// (the estimate's noise floor, docs/validation/errors.md, section 3).
inline constexpr double kElsewhereShare = 0.0025;

/// A companion whose figure lies further than this share from the run's is far from the
/// asymptotic range (FigureError::far_companion). Measured: the default case's companions lie
/// within 8 % (17 % for the slap energy with mass-conserving films), a starved skirt's at 27 %
/// (the film: estimated 2.1 % against a true 4.5 %) and 69 % (the slap energy: 73 % against
/// 1.5 %), docs/validation/errors.md.
inline constexpr double kFarCompanion = 0.25;

/// What the summary line and the GUI say of a figure that is not resolved_in_time.
inline constexpr const char* kUnresolvedPeakNote = "not estimated (a spike between output samples)";

/// The estimate of a run.
/// What the estimate's summary adds for a run with a mass-conserving big end.
inline constexpr const char* kMassConservingNote =
    "a mass-conserving big end's oil per cycle converges more slowly with the mesh than its film "
    "(order 1.6); where its film is starved or fed by a hole its figures can lie outside the "
    "range where these meshes' difference measures the error (the default case at 4000 rpm and "
    "below), and there this estimate can understate the error by half or more, or overstate it "
    "twice (docs/validation/errors.md, section 6)";

struct ErrorEstimate {
  /// "estimated"; "off" (solver.error_estimate = 0); "not-applicable" (no lubricated joint);
  /// "unavailable" (the coarse run did not complete: `message` says why).
  std::string status = "off";
  std::string message;
  std::vector<FigureError> figures;
  double worst_relative = 0.0;   ///< the largest relative estimate (figures resolved in time)
  std::string worst_label;       ///< its figure
  double threshold = 0.01;       ///< a warning is due above this relative error
  double skirt_ratio = 0.0, big_end_ratio = 0.0, tolerance_factor = 0.0;
  double coarse_wall_time = 0.0;  ///< [s]
  long coarse_steps = 0;

  bool Estimated() const { return status == "estimated"; }
  /// Above the threshold, or unavailable although films were computed.
  bool Warn() const { return (Estimated() && worst_relative > threshold) || status == "unavailable"; }
  /// One line for a terminal or a status bar, e.g. "estimated discretisation error ≤ 0.4 %
  /// (largest: min big-end MOFT)"; a warning names the figure and what to refine.
  std::string Summary() const;
};

/// How a person reads a headline figure: its unit from the key ("bearing_moft_min[m]") — lengths
/// in µm, pressures in MPa, the rest in SI — and the factor from SI.
struct DisplayUnit {
  std::string unit;  ///< UTF-8, empty for a ratio
  double scale = 1.0;
};
DisplayUnit HeadlineDisplayUnit(const std::string& key);

/// How a headline figure scattered over the last cycles of a run that found no periodic steady
/// state: the smallest and largest of its per-cycle values.
struct FigureScatter {
  HeadlineFigure figure;  ///< the reported (last) cycle's value
  double min = 0.0, max = 0.0;
  /// false: a peak figure the reported cycle's output samples do not resolve in time
  /// (SampledPeak::Unresolved): its values are whatever the samples caught of a spike, so its
  /// scatter is not counted in the largest one (FigureError::resolved_in_time alike).
  bool resolved_in_time = true;
  /// (max − min) / 2 over |the reported value| (0 when the value is 0 and nothing moved).
  double RelativeHalfSpread() const;
};

/// The scatter of a run's headline figures over its last cycles.
struct CycleScatter {
  int first_cycle = 0, last_cycle = 0;  ///< 1-based, inclusive
  std::vector<FigureScatter> figures;
  /// One sentence: "over cycles 8–12 the headline figures moved by up to ±2.7 % of the reported
  /// values: min skirt MOFT 5.56–5.87 µm (±2.7 %), …" — the figures that moved by more than
  /// ±0.1 %, largest first; then the figures not resolved in time, "not counted: peak big-end
  /// film pressure 1422–1835 MPa (a spike between output samples)".
  std::string Summary() const;
};

/// Cycles a scatter spans: the last kScatterCycles, leaving out the first (the start-up
/// transient) when at least two others remain.
inline constexpr int kScatterCycles = 5;

/// The scatter of the headline figures over the last cycles, from each cycle's figures in
/// cycle order (RunResult::cycle_headlines). Empty with fewer than two cycles.
/// `reported_samples`: the last cycle's samples (`whole_cycle` as for SampledPeaks), which tell the
/// peaks that are spikes between output samples.
std::optional<CycleScatter> ScatterOverCycles(
    const std::vector<std::vector<HeadlineFigure>>& per_cycle,
    const std::vector<CrankTrainSample>& reported_samples, bool whole_cycle);

/// A relative figure in percent as the messages write it: "0.93", "4.4", "790" (two significant
/// digits, whole numbers from 10 on, never an exponent).
std::string PercentText(double fraction);

/// How a run stopped at solver.max_cycles approached its periodic state, from its cycle-to-cycle
/// changes (RunResult::cycle_changes, relative to the range) and the tolerance: "the change after
/// each cycle from cycle 2 on: 22, 4.3, 1.2 %", then from the last two changes either "falling by
/// about ×3.6 per cycle: about 1 more cycle would reach the tolerance if it keeps falling so" (a
/// last ratio below kFallingRatio; the count assumes a geometric fall) or "not falling (×0.93 …)"
/// with what may lower such a floor. Empty with fewer than two changes.
std::string CycleChangeTrend(const std::vector<double>& changes, double tolerance);
/// The ratio of two successive cycle-to-cycle changes below which the change counts as falling.
inline constexpr double kFallingRatio = 0.8;

/// Richardson's estimate from the run's and the coarse run's reported cycles (with each run's
/// SlapInputs, the largest slap energy's too: left out when only one of the runs has it).
ErrorEstimate EstimateErrors(const std::vector<CrankTrainSample>& samples,
                             const std::vector<CrankTrainSample>& coarse_samples,
                             const CoarseCompanion& companion, const SlapInputs& slap = {},
                             const SlapInputs& coarse_slap = {});

}  // namespace filmdyn::engine
