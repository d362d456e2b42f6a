#pragma once
/// @file Transient mass-conserving cavitation: the oscillatory squeeze film with its exact
/// solution (the first example of Ausas, Jai & Buscaglia 2009, J. Tribol. 131 031702), solved
/// by the transient JFO model of ReynoldsFem, and the rows of `filmdyn validate --suite
/// cavitation`. The exact solution is derived in docs/validation/cavitation.md.
///
/// Dimensionless problem: x in [0, 1], a uniform gap h(t) = 0.375 + 0.125 cos(4 pi t) (period
/// 1/2), pure squeeze (no sliding), div(h^3 grad p) = 2 d(theta h)/dt, p = p0 = 0.025 at both
/// ends, a full film (theta = 1) at t = 0. ReynoldsFem solves it with mu = 1/6 (then
/// h^3/(12 mu) = h^3/2), in SI units whose numbers are the dimensionless ones.
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

/// The rows of `filmdyn validate --suite cavitation`.
std::vector<verification::ValidationRow> CavitationValidationRows();

}  // namespace filmdyn::lubrication
