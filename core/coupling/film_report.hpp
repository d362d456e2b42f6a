#pragma once
/// @file What a lubricated joint element reports about its film at one instant: plain structs
/// filled by the coupling elements and copied into the engine's samples. Knows nothing of the
/// engine; the engine's crank-train sample holds one of each.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace filmdyn::lubrication {
struct ReynoldsStats;
struct ElasticSolveStats;
enum class CavitationModel;
}  // namespace filmdyn::lubrication

namespace filmdyn::coupling {

/// A mass-conserving (JFO) film's oil account, updated at every accepted time step of the
/// integration (the film content's backward-Euler steps): running totals since the run began.
/// Between any two accounts, (supplied - lost) - (squeezed - change of void_volume) is zero to
/// the film solver's round-off: the film neither creates nor destroys oil.
struct OilAccount {
  bool kept = false;  ///< false: the joint's cavitation model does not conserve oil
  /// The largest excursion of the film fraction outside [0, 1] at any accepted step so far
  /// (ReynoldsStats::fraction_excess). Diagnostic: the solve keeps every cell's oil >= 0 (the
  /// void's capacity, docs/validation/cavitation.md), so this is round-off unless the solve
  /// itself failed.
  double fraction_excess = 0.0;
  double time = 0.0;         ///< of the last accepted step [s]
  double supplied = 0.0;     ///< oil in through the supply (big end) / inflow nodes (skirt) [m^3]
  double lost = 0.0;         ///< oil out through the edges (big end) / outflow nodes (skirt) [m^3]
  double squeezed = 0.0;     ///< time integral of the full film's storage rate [m^3]
  double void_volume = 0.0;  ///< void (gas) volume of the film at `time` [m^3]
  /// The last step booked: its start and its supply and loss rates [m^3/s], at which its oil
  /// passed all the step long (backward Euler).
  double step_start = 0.0, supply_rate = 0.0, loss_rate = 0.0;
  /// Books an accepted step ending at t, the film content's backward-Euler step of length dt
  /// from the last accepted one: the flows [m^3/s] of the film solved at t, its void volume.
  void Book(double t, double dt, double supply_rate_now, double loss_rate_now, double squeeze_rate,
            double void_now, double excess) {
    kept = true;
    fraction_excess = std::max(fraction_excess, excess);
    time = t;
    step_start = t - dt;
    supply_rate = supply_rate_now;
    loss_rate = loss_rate_now;
    supplied += dt * supply_rate;
    lost += dt * loss_rate;
    squeezed += dt * squeeze_rate;
    void_volume = void_now;
  }
  /// The oil supplied and lost up to t within the last step booked [m^3] (at its rates).
  double SuppliedAt(double t) const {
    return supplied - (time - std::clamp(t, step_start, time)) * supply_rate;
  }
  double LostAt(double t) const {
    return lost - (time - std::clamp(t, step_start, time)) * loss_rate;
  }
  /// The balance between this account and an earlier one, relative to the oil supplied between
  /// them (0 when none was).
  double BalanceSince(const OilAccount& earlier) const {
    const double in = supplied - earlier.supplied;
    const double residual = in - (lost - earlier.lost) - (squeezed - earlier.squeezed) +
                            (void_volume - earlier.void_volume);
    return in != 0.0 ? residual / std::abs(in) : 0.0;
  }
};

/// The peak film pressure of every accepted time step of a mass-conserving (JFO) film, whose
/// steps the element sees one by one, until an output sample takes them: a spike between two
/// output samples (an impact lasting a fraction of the output interval) is then not lost.
class StepPeaks {
 public:
  /// Books the accepted step at t; entries at or after t (a restarted integration) are dropped.
  void Book(double t, double peak_pressure) {
    while (!entries_.empty() && entries_.back().first >= t) entries_.pop_back();
    entries_.emplace_back(t, peak_pressure);
  }
  /// The largest of the entries at or before t, which are removed; NaN when there is none.
  double Take(double t) {
    double largest = std::numeric_limits<double>::quiet_NaN();
    std::size_t taken = 0;
    while (taken < entries_.size() && entries_[taken].first <= t) {
      if (!(entries_[taken].second <= largest)) largest = entries_[taken].second;
      ++taken;
    }
    entries_.erase(entries_.begin(), entries_.begin() + static_cast<std::ptrdiff_t>(taken));
    return largest;
  }

 private:
  std::vector<std::pair<double, double>> entries_;  // (time [s], peak film pressure [Pa])
};

/// The mean flows of a mass-conserving film over each output interval, from its oil account:
/// the oil supplied and lost between two output times over the time between them (the account
/// taken at each output time within the step that holds it). Over a cycle of equal output
/// intervals they add up exactly to the account's oil, spikes between the samples included,
/// which the flows at the sampled instants do not.
class IntervalFlows {
 public:
  /// At the output time t (within the account's last step): sets `*in` and `*out` [m^3/s] to the
  /// mean rates since the previous call and returns true; false, leaving them, when the account
  /// is not kept or at the first call (no interval yet).
  bool Take(double t, const OilAccount& now, double* in, double* out) {
    if (!now.kept) return false;
    const double supplied = now.SuppliedAt(t), lost = now.LostAt(t);
    const bool interval = have_ && t > last_time_;  // else the first, or a restarted run
    if (interval) {
      *in = (supplied - last_supplied_) / (t - last_time_);
      *out = (lost - last_lost_) / (t - last_time_);
    }
    have_ = true;
    last_time_ = t;
    last_supplied_ = supplied;
    last_lost_ = lost;
    return interval;
  }

 private:
  bool have_ = false;
  double last_time_ = 0.0, last_supplied_ = 0.0, last_lost_ = 0.0;
};

/// A mass-conserving film's books of its accepted steps, kept by both joints: the oil account,
/// the peak film pressure of each step, and from them what each output sample reports of the
/// interval before it.
struct FilmStepBooks {
  OilAccount oil;
  StepPeaks peaks;
  IntervalFlows flows;
  /// Books the accepted step ending at t [s], of length dt from the last one: the film solved at
  /// t — its supply and loss rates and full-film storage rate [m^3/s], its void volume [m^3], its
  /// film fraction's excursion outside [0, 1] and its peak pressure [Pa].
  void Book(double t, double dt, double supply_rate, double loss_rate, double squeeze_rate,
            double void_volume, double fraction_excess, double peak_pressure) {
    oil.Book(t, dt, supply_rate, loss_rate, squeeze_rate, void_volume, fraction_excess);
    peaks.Book(t, peak_pressure);
  }
  /// At the output time t [s]: the peak pressure of the steps since the last output (NaN: none)
  /// and the interval's mean supply and loss rates (IntervalFlows::Take; left alone without).
  void Take(double t, double* step_peak_pressure, double* supply_rate, double* loss_rate) {
    *step_peak_pressure = peaks.Take(t);
    flows.Take(t, oil, supply_rate, loss_rate);
  }
};

/// Film quantities of the lubricated skirt at one instant (present = false with an ideal liner).
/// Forces on the piston: lateral along +X (thrust side), friction along the bore, + toward the
/// crank (skirt solver convention), moment about the pin (generalised force on the tilt).
struct SkirtFilmSample {
  bool present = false;
  double normal_force = 0.0;          ///< [N] hydrodynamic + asperity, along +X
  double contact_normal_force = 0.0;  ///< asperity part [N]
  double friction_force = 0.0;        ///< [N] along +y of the skirt (toward the crank)
  double moment_about_pin = 0.0;      ///< [N·m]
  double moft = 0.0;                  ///< [m]
  double fpl = 0.0;                   ///< friction power loss [W]
  double max_pressure = 0.0;          ///< peak hydrodynamic film pressure [Pa]
  /// The largest peak film pressure of the accepted integrator steps since the previous output
  /// sample, up to this one [Pa] (StepPeaks; mass-conserving films only, NaN otherwise).
  double step_peak_pressure = std::numeric_limits<double>::quiet_NaN();
  double max_contact_pressure = 0.0;  ///< peak asperity contact pressure [Pa]
  /// Largest opening of the film by the surfaces' elastic deformation [m] (0 when rigid).
  double max_deformation = 0.0;
  /// Asperity (boundary-friction) part of friction_force [N]; the hydrodynamic part is
  /// friction_force − contact_friction_force.
  double contact_friction_force = 0.0;
  /// Asperity (boundary-friction) part of fpl [W]: AsperityFrictionPower.
  double contact_fpl = 0.0;
  /// Where the minimum film is: angle from the thrust axis [rad] and distance from the skirt
  /// top [m] (the solver's skirt coordinates).
  double moft_alpha = 0.0, moft_y = 0.0;
  double min_gap = 0.0;  ///< smallest geometric gap over the panels (< 0: piston in the liner) [m]
  /// The smallest rigid gap the film is solved at: 0 with rigid surfaces, below 0 with elastic
  /// ones (LubricatedSkirtElement::MinGapAllowed) [m].
  double min_gap_allowed = 0.0;
  long clamped_nodes = 0;
  double power = 0.0;  ///< power of the film forces on the piston, F ė0 + M γ̇ + F_f u_p [W] (≤ 0)
  /// The state the film was solved at (the integrated state; the skirt solver's conventions):
  /// e0 [m], γ = sin of the piston's rotation, their rates, u_p (+ toward the crank) [m/s].
  double e0 = 0.0, tilt = 0.0, e0_rate = 0.0, tilt_rate = 0.0, speed = 0.0;
  /// Oil entering / leaving the film through its boundary (skirt edges, relief edges) [m^3/s]:
  /// at this instant, or, for a mass-conserving film at an output sample, the means over the
  /// output interval ending here (IntervalFlows).
  double inflow = 0.0, outflow = 0.0;
  double wetted_fraction = 1.0;  ///< oil-covered share of the panels (SkirtResult) [-]
  /// How far the reported film's fraction leaves [0, 1] (ReynoldsStats::fraction_excess); the
  /// run ends when it exceeds kFractionTolerance.
  double fraction_excess = 0.0;
  /// Nodes at the pressure-viscosity limit (ReynoldsStats::capped_nodes); the run ends when > 0.
  int capped_nodes = 0;
  OilAccount oil;
};

/// Film quantities of the lubricated big end at one instant (present = false when ideal).
struct BearingFilmSample {
  bool present = false;
  Eigen::Vector2d journal_ecc_rod = Eigen::Vector2d::Zero();  ///< journal − bearing centre, rod
                                                              ///< frame [m]
  Eigen::Vector2d journal_ecc_global = Eigen::Vector2d::Zero();  ///< same, global frame [m]
  double eps = 0.0;                                              ///< ε [-]
  double eps_dot = 0.0;                                          ///< [1/s]
  /// The eccentricity where the joint's film ends and its contact penalty begins: just below 1
  /// with rigid surfaces, past 1 with elastic ones (LubricatedBigEndElement::EpsMax).
  double eps_max = 1.0 - 5e-4;
  double moft = 0.0;                                             ///< [m]
  double fpl = 0.0;                                              ///< [W]
  double max_pressure = 0.0;          ///< peak hydrodynamic film pressure [Pa]
  /// The largest peak film pressure of the accepted integrator steps since the previous output
  /// sample, up to this one [Pa] (StepPeaks; mass-conserving films only, NaN otherwise).
  double step_peak_pressure = std::numeric_limits<double>::quiet_NaN();
  double max_contact_pressure = 0.0;  ///< peak asperity contact pressure [Pa]
  /// Largest opening of the film by the surfaces' elastic deformation [m] (0 when rigid).
  double max_deformation = 0.0;
  /// Circumferential friction force on the journal surface (friction_torque_journal / R_j),
  /// + counter-clockwise [N], and its asperity (boundary-friction) part [N].
  double friction_force = 0.0;
  double contact_friction_force = 0.0;
  /// Asperity (boundary-friction) part of fpl [W]: AsperityFrictionPower.
  double contact_fpl = 0.0;
  Eigen::Vector2d force_on_rod = Eigen::Vector2d::Zero();        ///< film (crank pin) → rod [N]
  double friction_torque_journal = 0.0;                          ///< on the crank [N·m]
  double friction_torque_bearing = 0.0;                          ///< on the rod [N·m]
  double power = 0.0;  ///< power of the film on crank + rod, F·ė + T_j ω_j + T_b ω_b [W] (≤ 0)
  /// Oil into the film through the feed (or the film-start line) and out through both edges
  /// (BearingResult::feed_flow, side_flow) [m^3/s]: at this instant, or, for a mass-conserving
  /// film at an output sample, the means over the output interval ending here (IntervalFlows).
  double supply_flow = 0.0, side_flow = 0.0;
  double fraction_excess = 0.0;  ///< as SkirtFilmSample::fraction_excess
  int capped_nodes = 0;          ///< as SkirtFilmSample::capped_nodes
  OilAccount oil;
};

/// Largest excursion of a reported film fraction outside [0, 1] a run accepts.
inline constexpr double kFractionTolerance = 1e-6;

/// The power the asperities' friction dissipates [W], |F_c · u|, from a joint's friction power
/// loss fpl = |F · u| (F its friction force, u the sliding speed), F and its asperity part F_c
/// [N]. Boundary friction opposes the sliding, so this is never negative; the rest of fpl,
/// fpl − |F_c · u|, is the film's, which is negative where the film's pressure-driven shear
/// pushes the surface along (then the asperity part exceeds fpl). 0 without friction.
inline double AsperityFrictionPower(double fpl, double friction_force,
                                    double contact_friction_force) {
  return friction_force != 0.0 ? std::abs(contact_friction_force) * (fpl / std::abs(friction_force))
                               : 0.0;
}

/// A film solve that did not converge is never used as a force: throws
/// multibody::EvaluationFailure naming the joint, the status and the iterations (or, for elastic
/// surfaces, why the coupled solve stopped and its residual), so that the
/// integrator retries the step smaller (the solve usually converges closer to the last accepted
/// state) and names this failure if it gives up.
void RequireConvergedFilm(const lubrication::ReynoldsStats& stats, const char* joint,
                          lubrication::CavitationModel model,
                          const lubrication::ElasticSolveStats* elastic = nullptr);

/// Implemented by the lubricated joint elements so that whoever samples a system can fill the
/// film quantities without knowing their types. Called right after the element was evaluated at
/// the sampled state; each element fills its own joint's struct and leaves the other alone.
class FilmReporter {
 public:
  virtual ~FilmReporter() = default;
  virtual void ReportFilm(SkirtFilmSample* skirt, BearingFilmSample* bearing) const = 0;
  /// Called once per output sample at time t, after ReportFilm: fills what the joint's accepted
  /// steps since the previous sample give — step_peak_pressure (StepPeaks::Take) and, for a
  /// mass-conserving film, its flows' means over the interval (IntervalFlows). Default: nothing.
  virtual void TakeSteps(double /*t*/, SkirtFilmSample* /*skirt*/, BearingFilmSample* /*bearing*/) {
  }
};

}  // namespace filmdyn::coupling
