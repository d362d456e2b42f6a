#pragma once
/// @file The engine KPIs of a run ("kpis" in summary.json): per lubricated joint, the extremes
/// of its film over the reported cycle with where in the cycle (and, for the minimum film, where
/// in the joint) they occur, its mean friction power and, for the skirt, the piston slap — the
/// piston's lateral kinetic energy at each change of thrust side. One row per run for design
/// studies; keys, units and definitions in docs/outputs.md.
#include <optional>
#include <vector>

#include "core/engine/piston_slap.hpp"
#include "core/engine/run_job.hpp"

namespace filmdyn::io {

/// Where the minimum film of a lubricated joint is at one sample. Skirt: angle from the thrust
/// axis [deg] (0 = thrust side, 180 = anti-thrust side) and distance below the skirt top [m].
/// Big end: direction of the journal's eccentricity in the rod-fixed frame, counter-clockwise
/// from the rod-frame x axis, in [0, 360) [deg] (90 = toward the small end); no axial position
/// (the film is uniform across an aligned bearing). The one rule of the KPIs and the film
/// warnings.
struct FilmPosition {
  double angle_deg = 0.0;
  std::optional<double> axial_m;  ///< skirt only
};
FilmPosition MinFilmPosition(const engine::CrankTrainSample& sample, bool skirt);

/// The piston slap (engine/piston_slap.hpp), kept under these names for the KPIs' readers.
using engine::PistonSlap;
using engine::SlapEvent;

/// The KPIs of one lubricated joint over the reported cycle. Crank angles [°CA] are within the
/// cycle, of the output step where the extreme occurs (the first on a tie).
struct JointKpis {
  double min_moft = 0.0;  ///< [m]
  double min_moft_crank_angle_deg = 0.0;
  FilmPosition min_moft_position;  ///< at min_moft_crank_angle_deg
  double peak_pressure = 0.0;      ///< largest hydrodynamic film pressure [Pa]
  /// None when the peak is 0 (no film pressure anywhere in the cycle): there is no "where".
  std::optional<double> peak_pressure_crank_angle_deg;
  double peak_contact_pressure = 0.0;  ///< largest asperity contact pressure [Pa]
  std::optional<double> peak_contact_pressure_crank_angle_deg;  ///< none when 0 (no contact)
  /// Largest film opening by the surfaces' elastic deformation [m] (0 when rigid).
  double max_deformation = 0.0;
  std::optional<double> max_deformation_crank_angle_deg;  ///< none when 0 (rigid surfaces)
  /// Mean friction power loss [W]: the headline figure's (engine::HeadlineFigures), the plain
  /// mean of the cycle's equally spaced output samples.
  std::optional<double> mean_fpl;
  /// Friction mean effective pressure: the friction work of the cycle (mean_fpl times the
  /// 720 °CA cycle's duration) per swept volume [Pa], and its share of the sum over the
  /// lubricated joints [-] (AddFrictionMep).
  std::optional<double> fmep, fmep_share;
  std::optional<double> max_eps;  ///< big end: largest eccentricity ratio [-]
  std::optional<double> max_eps_crank_angle_deg;
  std::optional<PistonSlap> slap;  ///< skirt only
  /// Oil into the film (big end: through the supply; skirt: at its inflow nodes) and out of it
  /// (big end: side leakage; skirt: outflow nodes) over the cycle [m^3]: mass-conserving films
  /// from their oil account (every integrator step booked) between the cycle's first and last
  /// output steps, scaled to the cycle's duration; other films the mean of the equally spaced
  /// output samples times the cycle's duration — except a Reynolds skirt's inflow, which is
  /// none (a mesh quantity: the film creates the oil it lacks where it reforms).
  std::optional<double> oil_in_per_cycle, oil_out_per_cycle;
  /// Mass-conserving (JFO) films: the oil balance between the cycle's first and last output
  /// steps relative to the oil supplied (coupling::OilAccount::BalanceSince); none otherwise.
  std::optional<double> oil_balance;
  std::optional<double> mean_wetted_fraction;  ///< skirt: oil-covered share of the panels [-]
};

/// The KPIs of a run: an entry per lubricated joint that has samples (none for the ideal model).
struct RunKpis {
  std::optional<JointKpis> skirt;
  std::optional<JointKpis> big_end;
};

/// The KPIs of a reported cycle's output samples and motion samples (engine::RunResult::samples
/// and ::motion). `piston_mass` [kg] and `piston_inertia` [kg·m²] (about the centre of mass)
/// weigh the slap energy. `whole_cycle`: the samples are one whole cycle, so the change of
/// thrust side between the last output step and the first counts too. Without motion samples
/// the slap's velocities come from the output samples themselves.
RunKpis ComputeRunKpis(const std::vector<engine::CrankTrainSample>& samples,
                       const std::vector<engine::MotionSample>& motion, double piston_mass,
                       double piston_inertia, bool whole_cycle);
/// Friction mean effective pressure of a mean friction power at `rpm`: its work over one 720 °CA
/// cycle per swept volume (engine::SweptVolume) [Pa].
double FrictionMep(double mean_fpl_w, const engine::CrankTrainGeometry& geometry, double rpm);
/// Fills each joint's fmep and fmep_share from its mean_fpl, at `rpm` for the swept volume of
/// `geometry` (engine::SweptVolume); a joint without mean_fpl gets none.
void AddFrictionMep(RunKpis* kpis, const engine::CrankTrainGeometry& geometry, double rpm);
/// The KPIs of a finished (or stopped) run: what it computed.
RunKpis RunKpisOf(const engine::RunConfig& config, const engine::RunResult& result);
/// The oil per cycle a run reports for a joint beside its other figures (comparisons, studies,
/// the GUI's run table): a mass-conserving film's (one that keeps an oil account, hence a
/// balance) over a whole reported cycle. None for a Reynolds film, which creates and loses oil
/// where it cavitates (and a Reynolds skirt's inflow falls with the mesh: docs/outputs.md).
std::optional<double> ReportedOilPerCycle(const std::optional<JointKpis>& joint);

}  // namespace filmdyn::io
