#pragma once
/// @file Transient mass-conserving cavitation: the oscillatory squeeze film with its exact
/// solution (the first example of Ausas, Jai & Buscaglia 2009, J. Tribol. 131 031702), a
/// compressible squeeze, and a starved slider whose supply grows (the partial film's transport
/// and the moving front's jump condition), solved by the transient JFO model of ReynoldsFem, and
/// the rows of `filmdyn validate --suite cavitation`. The exact solutions are derived in
/// docs/validation/cavitation.md.
///
/// The oscillatory squeeze, a dimensionless problem: x in [0, 1], a uniform gap h(t) = 0.375 +
/// 0.125 cos(4 pi t) (period 1/2), pure squeeze (no sliding), div(h^3 grad p) = 2 d(theta h)/dt, p
/// = p0 = 0.025 at both ends, a full film (theta = 1) at t = 0. ReynoldsFem solves it with mu = 1/6
/// (then h^3/(12 mu) = h^3/2), in SI units whose numbers are the dimensionless ones.
#include <vector>

#include "core/base/validation_row.hpp"
#include "core/lubrication/reynolds_fem.hpp"

namespace filmdyn::lubrication {

/// The gap, its rate and the end pressure of the oscillatory squeeze problem.
struct OscillatorySqueeze {
  double p0 = 0.025;
  static double Gap(double t);
  static double GapRate(double t);
  /// Full film: p = p0 + (h'/h^3)(x^2 - x).
  double FullFilmPressure(double x, double t) const;
  /// Rupture starts when p(1/2) = 0, i.e. h' = 4 p0 h^3 (bisection, 1e-13).
  double RuptureTime() const;
  /// While the cavity grows: its right boundary 1 - sqrt(p0 h^3 / h') (left: 1 - that), and
  /// the pressure (h'/h^3)(x - front)^2 on [front, 1].
  double RuptureFront(double t) const;
  double RupturePressure(double x, double t) const;
  /// The time the rupture front stops growing (d front/dt = 0) and its position there.
  double PeakTime() const;
  /// Reformation: the front moves back into the cavity, whose oil content theta h was frozen at
  /// h(tau(x)) when the rupture front passed x. Full film on [front, 1] with
  /// p = (h'/h^3)(x - s)^2 + B (x - s), B = p0/(1 - s) - (h'/h^3)(1 - s), and the jump condition
  /// ds/dt = -h^3 B / (2 (h - h(tau(s)))). Integrated by classical Runge-Kutta (step 1e-5) from
  /// just after PeakTime() until the fronts meet at x = 1/2. Returns (t, front) samples.
  struct Trajectory {
    std::vector<double> t, front;
    double close_time = 0.0;  ///< the cavity has closed (front = 1/2)
  };
  Trajectory Reformation() const;
  /// The exact right front at time t (1/2 when there is no cavity), for t in [0, 1/2 + close].
  double Front(double t, const Trajectory& reform) const;
};

/// Numerical solution on a strip of `cells` elements with a fixed time step.
struct SqueezeRunOptions {
  int cells = 450;
  double time_step = 6.6e-4;
  double end_time = 0.8;
  CavitationModel model = CavitationModel::kJfo;
  double bulk_modulus = 0.0;  ///< ReynoldsParams::bulk_modulus (0: incompressible)
  DensityLaw density_law = DensityLaw::kLinear;  ///< ReynoldsParams::density_law
};
struct SqueezeRun {
  std::vector<double> t;         ///< step end times
  std::vector<double> front;     ///< right boundary of the cavity (1/2 without cavity)
  std::vector<double> p_mid;     ///< pressure at x = 3/4
  double rupture_time = -1.0;    ///< first step with a cavitated node
  double close_time = -1.0;      ///< first step without one after rupture
  double fraction_min = 1.0;     ///< smallest fluid fraction met
  double fraction_excess = 0.0;  ///< worst excursion of theta outside [0, 1]
  /// Oil balance over the run, relative to the larger of the oil that flowed in and out through
  /// the ends: inflow − outflow − change of the stored oil, the stored oil's full-film part
  /// integrated with the solver's own rates (see docs/validation/cavitation.md). Exact
  /// (round-off) for JFO.
  double mass_balance = 0.0;
  double inflow = 0.0;  ///< oil in through the ends over the run [m^3]
  ReynoldsStats stats;  ///< merged over the steps
};
SqueezeRun SolveOscillatorySqueeze(const OscillatorySqueeze& problem,
                                   const SqueezeRunOptions& options);

/// A compressible full film building up its squeeze pressure: the same strip, ends at p = 0, the
/// gap h0 uniform and the film given a closing rate dh/dt = -w from rest (p = 0) at t = 0 (the
/// gap itself held at h0: a closing much slower than the pressure's build-up). The film stores
/// h0 p / beta more oil than the gap holds, so (h0 / beta) dp/dt = (h0^3 / 2) p'' + w, whose
/// solution is the steady squeeze parabola less its decaying sine modes:
///   p(x, t) = (w / h0^3) [x (1 - x) - sum over odd n of 8 / (n pi)^3 sin(n pi x) exp(-n^2 t /
///   tau)],
/// tau = 2 / (pi^2 h0^2 beta).
struct CompressibleSqueeze {
  double h0 = 0.5;
  double w = 0.125;   ///< closing rate: the steady pressure at x = 1/2 is w / (4 h0^3) = 1/4
  double beta = 8.0;  ///< bulk modulus (dimensionless): tau = 0.101
  double TimeConstant() const;                ///< tau of the slowest mode
  double Pressure(double x, double t) const;  ///< the series to a term below 1e-16 of the first
};
/// SqueezeRun of the compressible squeeze (p_mid at x = 1/2; options.bulk_modulus is the
/// problem's).
SqueezeRun SolveCompressibleSqueeze(const CompressibleSqueeze& problem, SqueezeRunOptions options);

/// A converging slider starved at its inlet whose supply grows: the partial film carries its oil
/// downstream at U/2 and the full film's front moves upstream to take the extra oil (film
/// history with sliding, which the squeeze problems above do not have). A linear gap h(x) from
/// h_in to h_out over [0, L], one surface sliding at U, p = 0 at both ends, the inlet supplying
/// the fluid fraction Supply(t) (steady at theta_start before t = 0, then rising to theta_end
/// over ramp_time along (1 - cos)/2, or at once when `step`). In the partial film (p = 0) the oil
/// content c = theta h obeys dc/dt + (U/2) dc/dx = 0, so c(x, t) = h_in Supply(t - 2x/U). In the
/// full film on [x_f, L] (incompressible, the gap fixed in time) the flow is uniform,
/// q(x_f) = (U/2) J2/J3 with J_n = int_{x_f}^{L} h^-n dx (p(x_f) = p(L) = 0), and the front obeys
/// the jump condition dx_f/dt = (q(x_f) - (U/2) c) / (h(x_f) - c), c taken at the front.
struct StarvedSlider {
  double length = 0.01, h_in = 20e-6, h_out = 10e-6, speed = 2.0, viscosity = 0.02;
  double theta_start = 0.55, theta_end = 0.64, ramp_time = 4e-3;
  bool step = false;
  double Supply(double t) const;
  double Gap(double x) const;
  double FullFilmFlow(double front) const;  ///< q(x_f) per unit width [m^2/s]
  double SteadyFront(double theta) const;   ///< x_f where q(x_f) = (U/2) theta h_in (bisection)
  double Load(double front) const;          ///< int p dx per unit width [N/m], closed form
  /// The front from the steady one at t = 0 to end_time, classical Runge-Kutta at dt.
  struct Trajectory {
    std::vector<double> t, front;
  };
  Trajectory Front(double end_time, double dt = 1e-6) const;
  static double At(double t, const Trajectory& trajectory);  ///< linear interpolation
};
/// The slider on a strip of `cells` elements, stepped at the time step that moves the partial
/// film `courant` cells per step, from its steady state (a quasi-static JFO solve) at t = 0.
struct SliderRun {
  std::vector<double> t;      ///< step end times
  std::vector<double> front;  ///< between the last cavitated and the first full node [m]
  std::vector<double> load;   ///< int p dx per unit width [N/m]
  double mass_balance = 0.0;  ///< (oil in - oil out - change of stored oil) / oil in
  double fraction_excess = 0.0;
  ReynoldsStats stats;
};
SliderRun SolveStarvedSlider(const StarvedSlider& problem, int cells, double courant,
                             double end_time);
/// A run's errors against the exact solution over its steps: the front's largest and mean
/// [m], the load's largest relative to the final supply's steady load.
struct SliderErrors {
  double front_max = 0.0, front_mean = 0.0, load_max = 0.0;
};
SliderErrors CompareWithExact(const StarvedSlider& problem, const SliderRun& run,
                              const StarvedSlider::Trajectory& exact);

/// A partial film carried through a parallel gap: the film never fills the gap, so there is no
/// pressure anywhere and the fluid fraction is only transported, unchanged, at U/2. The film
/// entered through the inlet, whose supply rose smoothly from theta_start to theta_end over
/// ramp_time along (1 - cos)/2 and has since stayed at theta_end; at t = 0 the rise lies inside
/// the strip (it began `entered` before): theta(x, t) = Supply(entered + t - 2x/U). The exact
/// solution of the void transport alone, which shows its order in the cell size (the starved
/// slider's errors are its front's; here no front and no change at the inlet).
struct CarriedFilm {
  double length = 0.01, gap = 20e-6, speed = 2.0, viscosity = 0.02;
  double theta_start = 0.3, theta_end = 0.7, ramp_time = 4e-3, entered = 5e-3;
  /// Largest / smallest cell, graded smoothly (GradedWidth: the largest mid-strip); 1 = uniform.
  double grading = 1.0;
  double Supply(double t) const;
  double Exact(double x, double t) const { return Supply(entered + t - 2.0 * x / speed); }
};
/// |theta - exact| over the free nodes at the end of a run: mean and largest.
struct CarriedFilmError {
  double mean = 0.0, max = 0.0;
  double mass_balance = 0.0;  ///< (oil in - oil out - change of stored oil) / oil in
};
/// The carried film on a strip of `cells` elements from the exact film at t = 0, stepped by the
/// transient JFO solve (backward Euler) at the step that moves the film `courant` mean cells, to
/// end_time, carried by the given ReynoldsOptions::void_transport_order.
CarriedFilmError SolveCarriedFilm(const CarriedFilm& problem, int cells, double courant,
                                  double end_time, int transport_order);

/// The rows of `filmdyn validate --suite cavitation`.
std::vector<verification::ValidationRow> CavitationValidationRows();

}  // namespace filmdyn::lubrication
