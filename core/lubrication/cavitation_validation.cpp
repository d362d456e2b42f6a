#include "core/lubrication/cavitation_validation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/lubrication/bearing_solver.hpp"
#include "core/lubrication/tri_mesh.hpp"

namespace filmdyn::lubrication {

namespace {

constexpr double kPi = std::numbers::pi;

// Root of f on [a, b] by bisection (f(a) and f(b) of opposite signs) to an interval of 1e-13.
double Bisect(const std::function<double(double)>& f, double a, double b) {
  double fa = f(a);
  if (fa * f(b) > 0.0) throw std::logic_error("Bisect: no sign change");
  while (b - a > 1e-13) {
    const double m = 0.5 * (a + b);
    const double fm = f(m);
    if ((fm < 0.0) == (fa < 0.0)) {
      a = m;
      fa = fm;
    } else {
      b = m;
    }
  }
  return 0.5 * (a + b);
}

}  // namespace

double OscillatorySqueeze::Gap(double t) { return 0.375 + 0.125 * std::cos(4.0 * kPi * t); }
double OscillatorySqueeze::GapRate(double t) { return -0.5 * kPi * std::sin(4.0 * kPi * t); }

double OscillatorySqueeze::FullFilmPressure(double x, double t) const {
  const double h = Gap(t);
  return p0 + GapRate(t) / (h * h * h) * (x * x - x);
}

double OscillatorySqueeze::RuptureTime() const {
  // h' = 4 p0 h^3 first holds just after the gap's minimum at t = 1/4 (h' = 0 there).
  return Bisect([&](double t) { return GapRate(t) - 4.0 * p0 * std::pow(Gap(t), 3); }, 0.25, 0.3);
}

double OscillatorySqueeze::RuptureFront(double t) const {
  return 1.0 - std::sqrt(p0 * std::pow(Gap(t), 3) / GapRate(t));
}

double OscillatorySqueeze::RupturePressure(double x, double t) const {
  const double s = RuptureFront(t);
  if (x <= s) return 0.0;
  return GapRate(t) / std::pow(Gap(t), 3) * (x - s) * (x - s);
}

double OscillatorySqueeze::PeakTime() const {
  // d/dt (h^3 / h') = 0  <=>  3 h'^2 = h h'', with h'' = -2 pi^2 cos(4 pi t).
  return Bisect(
      [](double t) {
        const double h2 = -2.0 * kPi * kPi * std::cos(4.0 * kPi * t);
        return 3.0 * GapRate(t) * GapRate(t) - Gap(t) * h2;
      },
      RuptureTime(), 0.375);
}

OscillatorySqueeze::Trajectory OscillatorySqueeze::Reformation() const {
  const double t_rup = RuptureTime(), t_peak = PeakTime();
  const double s_peak = RuptureFront(t_peak);
  // tau(x): when the growing rupture front passed x in [1/2, s_peak].
  auto tau = [&](double x) {
    if (x <= 0.5) return t_rup;
    if (x >= s_peak) return t_peak;
    return Bisect([&](double t) { return RuptureFront(t) - x; }, t_rup, t_peak);
  };
  auto rate = [&](double t, double s) {
    const double h = Gap(t), h3 = h * h * h;
    const double b = p0 / (1.0 - s) - GapRate(t) / h3 * (1.0 - s);
    return -h3 * b / (2.0 * (h - Gap(tau(s))));
  };
  Trajectory tr;
  const double dt = 1e-5;
  double t = t_peak + 1e-7, s = s_peak;
  tr.t.push_back(t_peak);
  tr.front.push_back(s_peak);
  while (s > 0.5 && t < t_peak + 1.0) {
    const double k1 = rate(t, s);
    const double k2 = rate(t + 0.5 * dt, s + 0.5 * dt * k1);
    const double k3 = rate(t + 0.5 * dt, s + 0.5 * dt * k2);
    const double k4 = rate(t + dt, s + dt * k3);
    const double s_next = s + dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    if (s_next <= 0.5) {
      tr.close_time = t + dt * (s - 0.5) / (s - s_next);
      s = 0.5;
      t = tr.close_time;
    } else {
      s = s_next;
      t += dt;
    }
    tr.t.push_back(t);
    tr.front.push_back(s);
  }
  return tr;
}

double OscillatorySqueeze::Front(double t, const Trajectory& reform) const {
  const double t_rup = RuptureTime();
  if (t >= reform.close_time) t -= 0.5;  // the solution repeats once the first cavity closed
  if (t < t_rup) return 0.5;
  if (t <= reform.t.front()) return RuptureFront(t);
  const auto it = std::lower_bound(reform.t.begin(), reform.t.end(), t);
  if (it == reform.t.end()) return 0.5;
  const size_t i = static_cast<size_t>(it - reform.t.begin());
  const double w = (t - reform.t[i - 1]) / (reform.t[i] - reform.t[i - 1]);
  return reform.front[i - 1] + w * (reform.front[i] - reform.front[i - 1]);
}

namespace {

// A strip of options.cells elements, its ends at p_end, under a uniform gap gap(t) closing at
// rate(t), stepped with options.time_step from a full film at rest; the pressure sampled at
// x_probe.
SqueezeRun RunStrip(const std::function<double(double)>& gap,
                    const std::function<double(double)>& rate, double p_end, double x_probe,
                    const SqueezeRunOptions& options) {
  const double width = 0.01;
  ReynoldsOptions opt;
  opt.cavitation = options.model;
  ReynoldsFem fem(MakeStripMesh(1.0, options.cells, width), 0, opt);
  const TriMesh& m = fem.mesh();
  const int nx = m.nx_nodes();
  const int n = m.NodeCount();
  fem.boundary_pressure() = Eigen::VectorXd::Constant(n, p_end);
  ReynoldsParams params;
  params.viscosity = 1.0 / 6.0;  // h^3 / (12 mu) = h^3 / 2
  params.bulk_modulus = options.bulk_modulus;
  params.density_law = options.density_law;
  SqueezeRun run;
  const double dx = 1.0 / options.cells;
  const int i_probe = std::min(static_cast<int>(x_probe / dx), nx - 2);
  double net_in = 0.0, stored_change = 0.0, inflow = 0.0;
  const std::vector<double>& area = fem.lumped_area();
  auto void_total = [&](const Eigen::VectorXd& v) {
    double sum = 0.0;
    for (int k = 0; k < n; ++k) sum += area[k] * v[k];
    return sum;
  };
  const double v_start = void_total(fem.void_history());
  const int steps = static_cast<int>(std::lround(options.end_time / options.time_step));
  for (int step = 1; step <= steps; ++step) {
    const double t = step * options.time_step;
    fem.film_thickness().setConstant(gap(t));
    fem.film_rate().setConstant(rate(t));
    params.time_step = options.time_step;
    const ReynoldsSolution& sol = fem.Solve(params);
    run.stats.Add(sol.stats);
    // Oil in through the ends over the step, and the full-film part of the stored oil's change
    // at the solver's own rate, as the solve books it (ReynoldsSolution::squeeze_rate; the void
    // part, and a compressible film's compressed oil, telescope: their total is read at the
    // end).
    for (int k = 0; k < n; ++k) {
      if (!m.fixed[k]) continue;
      net_in += options.time_step * sol.residual[k];
      inflow += options.time_step * std::max(sol.residual[k], 0.0);
    }
    stored_change += options.time_step * sol.squeeze_rate;
    if (options.model == CavitationModel::kJfo) fem.void_history() = sol.void_content;
    double front = 0.5;
    bool any = false;
    for (int i = 0; i < nx; ++i) {
      const int k = m.Node(i, 0);
      run.fraction_min = std::min(run.fraction_min, sol.fluid_fraction[k]);
      if (sol.cavitated[k]) {
        any = true;
        front = std::max(front, m.x[k] + 0.5 * dx);
      }
    }
    run.fraction_excess = std::max(run.fraction_excess, sol.stats.fraction_excess);
    if (any && run.rupture_time < 0.0) run.rupture_time = t;
    if (!any && run.rupture_time >= 0.0 && run.close_time < 0.0) run.close_time = t;
    const double w = (x_probe - m.x[m.Node(i_probe, 0)]) / dx;
    run.p_mid.push_back((1.0 - w) * sol.pressure[m.Node(i_probe, 0)] +
                        w * sol.pressure[m.Node(i_probe + 1, 0)]);
    run.t.push_back(t);
    run.front.push_back(front);
  }
  stored_change -= void_total(fem.void_history()) - v_start;
  run.inflow = inflow;
  // Relative to the larger of the oil that flowed in and out (the compressible squeeze only
  // pushes oil out).
  const double outflow = inflow - net_in;
  run.mass_balance = (net_in - stored_change) / std::max({inflow, outflow, 1e-300});
  return run;
}

}  // namespace

SqueezeRun SolveOscillatorySqueeze(const OscillatorySqueeze& problem,
                                   const SqueezeRunOptions& options) {
  return RunStrip(OscillatorySqueeze::Gap, OscillatorySqueeze::GapRate, problem.p0, 0.75, options);
}

double CompressibleSqueeze::TimeConstant() const { return 2.0 / (kPi * kPi * h0 * h0 * beta); }

double CompressibleSqueeze::Pressure(double x, double t) const {
  const double tau = TimeConstant();
  double modes = 0.0;
  for (int k = 1;; k += 2) {
    const double term = 8.0 / std::pow(k * kPi, 3) * std::exp(-double(k) * k * t / tau);
    modes += term * std::sin(k * kPi * x);
    if (term < 1e-16 * 8.0 / std::pow(kPi, 3)) break;
  }
  return w / (h0 * h0 * h0) * (x * (1.0 - x) - modes);
}

SqueezeRun SolveCompressibleSqueeze(const CompressibleSqueeze& problem, SqueezeRunOptions options) {
  options.bulk_modulus = problem.beta;
  options.model = CavitationModel::kJfo;
  const double h0 = problem.h0, w = problem.w;
  return RunStrip([h0](double) { return h0; }, [w](double) { return -w; }, 0.0, 0.5, options);
}

double StarvedSlider::Supply(double t) const {
  if (t <= 0.0) return theta_start;
  if (step || t >= ramp_time) return theta_end;
  return theta_start + (theta_end - theta_start) * 0.5 * (1.0 - std::cos(kPi * t / ramp_time));
}

double StarvedSlider::Gap(double x) const { return h_in + (h_out - h_in) * x / length; }

namespace {

// int_a^b h^-2 dx and int_a^b h^-3 dx for the slider's linear gap (slope s).
double SliderJ2(const StarvedSlider& sl, double a, double b) {
  const double s = (sl.h_out - sl.h_in) / sl.length;
  return (1.0 / sl.Gap(a) - 1.0 / sl.Gap(b)) / s;
}
double SliderJ3(const StarvedSlider& sl, double a, double b) {
  const double s = (sl.h_out - sl.h_in) / sl.length;
  const double ha = sl.Gap(a), hb = sl.Gap(b);
  return (1.0 / (ha * ha) - 1.0 / (hb * hb)) / (2.0 * s);
}

}  // namespace

double StarvedSlider::FullFilmFlow(double front) const {
  return 0.5 * speed * SliderJ2(*this, front, length) / SliderJ3(*this, front, length);
}

double StarvedSlider::SteadyFront(double theta) const {
  const double c = theta * h_in;
  // q/(U/2) is a mean of the gap over [x_f, L] weighted by h^-3: from h_out (x_f -> L) up, so a
  // front exists for h_out < c; the partial film cannot hold more than the gap: x_f < x(h = c).
  if (!(c > h_out && c < h_in))
    throw std::invalid_argument("StarvedSlider: theta h_in must lie between h_out and h_in");
  const double x_fill = (c - h_in) / (h_out - h_in) * length;
  return Bisect([&](double x) { return FullFilmFlow(x) - 0.5 * speed * c; }, 0.0,
                std::min(x_fill, length * (1.0 - 1e-9)));
}

double StarvedSlider::Load(double front) const {
  // p(x) = 12 mu [(U/2) J2(x_f, x) - q J3(x_f, x)]; with int_{x_f}^{L} J2(x_f, x) dx =
  // ((L - x_f)/h_f - ln(h_L/h_f)/s)/s and int_{x_f}^{L} J3(x_f, x) dx =
  // ((L - x_f)/h_f^2 - J2(x_f, L))/(2 s).
  const double s = (h_out - h_in) / length;
  const double hf = Gap(front), span = length - front;
  const double a2 = (span / hf - std::log(h_out / hf) / s) / s;
  const double a3 = (span / (hf * hf) - SliderJ2(*this, front, length)) / (2.0 * s);
  return 12.0 * viscosity * (0.5 * speed * a2 - FullFilmFlow(front) * a3);
}

StarvedSlider::Trajectory StarvedSlider::Front(double end_time, double dt) const {
  // dx_f/dt = (q(x_f) - (U/2) c) / (h(x_f) - c), c = h_in Supply(t - 2 x_f / U).
  auto rate = [&](double t, double x) {
    const double c = h_in * Supply(t - 2.0 * x / speed);
    // The partial film reaches the front below the gap there (else it would fill the gap
    // upstream of the front: another problem).
    if (!(c < Gap(x))) throw std::invalid_argument("StarvedSlider: the partial film fills the gap");
    return (FullFilmFlow(x) - 0.5 * speed * c) / (Gap(x) - c);
  };
  Trajectory tr;
  double t = 0.0, x = SteadyFront(theta_start);
  tr.t.push_back(t);
  tr.front.push_back(x);
  while (t < end_time - 0.5 * dt) {
    const double k1 = rate(t, x);
    const double k2 = rate(t + 0.5 * dt, x + 0.5 * dt * k1);
    const double k3 = rate(t + 0.5 * dt, x + 0.5 * dt * k2);
    const double k4 = rate(t + dt, x + dt * k3);
    x += dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    t += dt;
    tr.t.push_back(t);
    tr.front.push_back(x);
  }
  return tr;
}

double StarvedSlider::At(double t, const Trajectory& tr) {
  if (t <= tr.t.front()) return tr.front.front();
  if (t >= tr.t.back()) return tr.front.back();
  const auto it = std::lower_bound(tr.t.begin(), tr.t.end(), t);
  const size_t i = static_cast<size_t>(it - tr.t.begin());
  const double w = (t - tr.t[i - 1]) / (tr.t[i] - tr.t[i - 1]);
  return tr.front[i - 1] + w * (tr.front[i] - tr.front[i - 1]);
}

namespace {

// The strip of the sliding problems: `cells` JFO elements, one surface sliding at `speed`, p = 0
// at both ends, the inlet's fixed nodes supplying a fluid fraction, the outlet's full.
struct SlidingStrip {
  static constexpr double kWidth = 1e-4;
  ReynoldsFem fem;
  ReynoldsParams params;
  double net_in = 0.0, inflow = 0.0;  // oil through the fixed nodes so far [m^3 per width]
  SlidingStrip(std::vector<double> x_lines, double speed, double viscosity, int transport_order)
      : fem(MakeStripMesh(x_lines, kWidth), 0, Options(transport_order)),
        half(0.5 * x_lines.back()) {
    fem.film_rate().setZero();
    params.viscosity = viscosity;
    params.u_sum = speed;
    params.u_diff = speed;
  }
  static ReynoldsOptions Options(int transport_order) {
    ReynoldsOptions opt;
    opt.cavitation = CavitationModel::kJfo;
    opt.void_transport_order = transport_order;
    return opt;
  }
  void SetSupply(double theta) {
    const TriMesh& m = fem.mesh();
    for (int k = 0; k < m.NodeCount(); ++k)
      fem.boundary_fraction()[k] = m.x[k] < half ? theta : 1.0;
  }
  // One transient step of dt from the history; books the flows through the fixed nodes and makes
  // the solution the next step's history. `what` names the problem in the error.
  const ReynoldsSolution& Step(double dt, const char* what) {
    params.time_step = dt;
    const ReynoldsSolution& sol = fem.Solve(params);
    if (sol.stats.status != SolveStatus::kConverged)
      throw std::runtime_error(std::string(what) + ": a transient solve did not converge");
    const TriMesh& m = fem.mesh();
    for (int k = 0; k < m.NodeCount(); ++k) {
      if (!m.fixed[k]) continue;
      net_in += dt * sol.residual[k];
      inflow += dt * std::max(sol.residual[k], 0.0);
    }
    fem.void_history() = sol.void_content;
    return sol;
  }
  // (oil in - oil out - change of stored oil) / oil in, from the voids' volume at the start and
  // now (the gap is fixed in time, so the stored oil changes as minus the voids').
  double MassBalance(double v_start, double v_end) const {
    return (net_in + (v_end - v_start)) / std::max(inflow, 1e-300);
  }
  double half;
};

}  // namespace

SliderRun SolveStarvedSlider(const StarvedSlider& problem, int cells, double courant,
                             double end_time) {
  SlidingStrip strip(Linspace(0.0, problem.length, cells), problem.speed, problem.viscosity, 2);
  ReynoldsFem& fem = strip.fem;
  const TriMesh& m = fem.mesh();
  const int nx = m.nx_nodes(), n = m.NodeCount();
  const double dx = problem.length / cells;
  for (int k = 0; k < n; ++k) fem.film_thickness()[k] = problem.Gap(m.x[k]);
  // The steady state at the starting supply (quasi-static: no history).
  strip.SetSupply(problem.theta_start);
  double v_start = 0.0, v_end = 0.0;  // the voids' volume at the start and the end
  {
    const ReynoldsSolution& sol = fem.Solve(strip.params);
    if (sol.stats.status != SolveStatus::kConverged)
      throw std::runtime_error("starved slider: the steady solve did not converge");
    fem.void_history() = sol.void_content;
    v_start = v_end = sol.void_volume;
  }
  SliderRun run;
  const double dt = courant * dx / (0.5 * problem.speed);
  const int steps = static_cast<int>(std::ceil(end_time / dt - 1e-9));
  for (int step = 1; step <= steps; ++step) {
    const double t = step * dt;
    strip.SetSupply(problem.Supply(t));
    const ReynoldsSolution& sol = strip.Step(dt, "starved slider");
    run.stats.Add(sol.stats);
    v_end = sol.void_volume;
    // The front: half-way between the last cavitated node and the full one after it (the inlet
    // when no node is cavitated; the outlet's node is prescribed, never cavitated).
    double front = 0.0;
    for (int i = nx - 1; i > 0; --i)
      if (sol.cavitated[m.Node(i - 1, 0)] && !sol.cavitated[m.Node(i, 0)]) {
        front = m.x[m.Node(i, 0)] - 0.5 * dx;
        break;
      }
    run.t.push_back(t);
    run.front.push_back(front);
    run.load.push_back(fem.Integrate(sol.pressure) / SlidingStrip::kWidth);
    run.fraction_excess = std::max(run.fraction_excess, sol.stats.fraction_excess);
  }
  run.mass_balance = strip.MassBalance(v_start, v_end);
  return run;
}

double CarriedFilm::Supply(double t) const {
  if (t <= 0.0) return theta_start;
  if (t >= ramp_time) return theta_end;
  return theta_start + (theta_end - theta_start) * 0.5 * (1.0 - std::cos(kPi * t / ramp_time));
}

CarriedFilmError SolveCarriedFilm(const CarriedFilm& problem, int cells, double courant,
                                  double end_time, int transport_order) {
  SlidingStrip strip(GradedWidth(cells, problem.length, problem.grading, false), problem.speed,
                     problem.viscosity, transport_order);
  ReynoldsFem& fem = strip.fem;
  const TriMesh& m = fem.mesh();
  const int n = m.NodeCount();
  fem.film_thickness().setConstant(problem.gap);
  // The exact film at t = 0 (smooth surfaces: the void content is (1 - theta) h).
  const std::vector<double> area = LumpedAreas(m);
  double v_start = 0.0, v_end = 0.0;
  fem.void_history().resize(n);
  for (int k = 0; k < n; ++k) {
    fem.void_history()[k] = m.fixed[k] ? 0.0 : (1.0 - problem.Exact(m.x[k], 0.0)) * problem.gap;
    v_start += area[k] * fem.void_history()[k];
  }
  const double dt = courant * (problem.length / cells) / (0.5 * problem.speed);
  const int steps = static_cast<int>(std::ceil(end_time / dt - 1e-9));
  Eigen::VectorXd fraction;
  for (int step = 1; step <= steps; ++step) {
    strip.SetSupply(problem.Exact(0.0, step * dt));
    const ReynoldsSolution& sol = strip.Step(dt, "carried film");
    v_end = sol.void_volume;
    fraction = sol.fluid_fraction;
  }
  CarriedFilmError e;
  int count = 0;
  for (int k = 0; k < n; ++k) {
    if (m.fixed[k]) continue;
    const double error = std::abs(fraction[k] - problem.Exact(m.x[k], steps * dt));
    e.mean += error;
    e.max = std::max(e.max, error);
    ++count;
  }
  e.mean /= std::max(count, 1);
  e.mass_balance = strip.MassBalance(v_start, v_end);
  return e;
}

SliderErrors CompareWithExact(const StarvedSlider& problem, const SliderRun& run,
                              const StarvedSlider::Trajectory& exact) {
  SliderErrors e;
  const double final_load = problem.Load(problem.SteadyFront(problem.theta_end));
  for (size_t i = 0; i < run.t.size(); ++i) {
    const double xf = StarvedSlider::At(run.t[i], exact);
    const double error = std::abs(run.front[i] - xf);
    e.front_max = std::max(e.front_max, error);
    e.front_mean += error / double(run.t.size());
    e.load_max = std::max(e.load_max, std::abs(run.load[i] - problem.Load(xf)) / final_load);
  }
  return e;
}

std::vector<verification::ValidationRow> CavitationValidationRows() {
  std::vector<verification::ValidationRow> rows;
  const OscillatorySqueeze problem;
  const OscillatorySqueeze::Trajectory reform = problem.Reformation();
  SqueezeRunOptions options;
  const SqueezeRun jfo = SolveOscillatorySqueeze(problem, options);
  const std::string src = "oscillatory squeeze, exact (Ausas et al. 2009 sec. 3)";
  const std::string grid = fmt::format("{} cells, dt {:g}", options.cells, options.time_step);
  rows.push_back({"cavitation", "squeeze: rupture onset time (" + grid + ")", src, jfo.rupture_time,
                  problem.RuptureTime(), 2.0 * options.time_step, false});
  // Largest cavity and the cavity's closing time (reformation: the JFO history at work).
  const double peak_num = *std::max_element(jfo.front.begin(), jfo.front.end());
  rows.push_back({"cavitation", "squeeze: largest cavity, right front x", src, peak_num,
                  problem.RuptureFront(problem.PeakTime()), 2.0 / options.cells, false});
  rows.push_back({"cavitation", "squeeze: cavity closing time (reformation)", src, jfo.close_time,
                  reform.close_time, 0.002, false});
  // The front at sampled times of the rupture and reformation phases.
  double worst = 0.0;
  for (size_t i = 0; i < jfo.t.size(); ++i) {
    if (jfo.t[i] > reform.close_time - 0.02 && jfo.t[i] < reform.close_time + 0.02) continue;
    worst = std::max(worst, std::abs(jfo.front[i] - problem.Front(jfo.t[i], reform)));
  }
  rows.push_back({"cavitation", "squeeze: front position, max error over the run", src, worst, 0.0,
                  3.0 / options.cells, false});
  // Pressure at x = 3/4 in the full-film and rupture phases, relative to the peak pressure.
  double p_err = 0.0, p_peak = 0.0;
  for (size_t i = 0; i < jfo.t.size(); ++i) {
    const double t = jfo.t[i];
    double exact;
    if (t < problem.RuptureTime() - options.time_step)
      exact = problem.FullFilmPressure(0.75, t);
    else if (t > problem.RuptureTime() + options.time_step && t < problem.PeakTime())
      exact = problem.RupturePressure(0.75, t);
    else
      continue;
    p_peak = std::max(p_peak, std::abs(exact));
    p_err = std::max(p_err, std::abs(jfo.p_mid[i] - exact));
  }
  // Linear elements reproduce the full film's parabola at the nodes, and the film's exact dh/dt
  // drives it: the error is the rupture phase's (measured 6.6e-6 on Ausas et al.'s grid).
  rows.push_back({"cavitation", "squeeze: pressure at x=3/4, max error / max pressure", src,
                  p_err / p_peak, 0.0, 1e-4, false});
  rows.push_back({"cavitation", "squeeze: oil balance over the run / inflow", "mass conservation",
                  jfo.mass_balance, 0.0, 1e-9, false});
  rows.push_back({"cavitation", "squeeze: fluid fraction excursion outside [0, 1]",
                  "0 <= theta <= 1", jfo.fraction_excess, 0.0, 1e-9, false});
  // A compressible oil: the build-up of the squeeze pressure against its series solution, the
  // oil balance with the compressed oil stored, and the incompressible limit of the cavitating
  // squeeze.
  const CompressibleSqueeze squeeze;
  SqueezeRunOptions build_up;
  build_up.cells = 200;
  build_up.time_step = squeeze.TimeConstant() / 100.0;
  build_up.end_time = 3.0 * squeeze.TimeConstant();
  const SqueezeRun compressible = SolveCompressibleSqueeze(squeeze, build_up);
  double c_err = 0.0;
  for (size_t i = 0; i < compressible.t.size(); ++i)
    c_err =
        std::max(c_err, std::abs(compressible.p_mid[i] - squeeze.Pressure(0.5, compressible.t[i])));
  const std::string c_src = "compressible squeeze build-up, series solution";
  const std::string c_grid = fmt::format("{} cells, dt = tau/100", build_up.cells);
  rows.push_back({"cavitation",
                  "compressible squeeze: p(1/2), max error / steady p (" + c_grid + ")", c_src,
                  c_err / squeeze.Pressure(0.5, 1e9), 0.0, 0.01, false});
  rows.push_back({"cavitation", "compressible squeeze: oil balance over the run / outflow",
                  "mass conservation", compressible.mass_balance, 0.0, 1e-9, false});
  // A starved slider fed a growing supply: the partial film carries the extra oil to the full
  // film's front, which moves upstream (sliding and history together). First order: the
  // front's and the load's largest errors over the run halve with each halving of cell and step.
  const StarvedSlider slider;
  const double slider_end = 0.025;
  const StarvedSlider::Trajectory slider_exact = slider.Front(slider_end);
  const SliderRun slider_run = SolveStarvedSlider(slider, 400, 1.0, slider_end);
  const SliderErrors e_coarse =
      CompareWithExact(slider, SolveStarvedSlider(slider, 200, 1.0, slider_end), slider_exact);
  const SliderErrors e_run = CompareWithExact(slider, slider_run, slider_exact);
  const std::string s_src = "starved slider, supply rising: partial film + front jump condition";
  rows.push_back({"cavitation", "starved slider: front, max error over the run [mm] (400 cells)",
                  s_src, e_run.front_max * 1e3, 0.0, 0.2, false});
  rows.push_back({"cavitation", "starved slider: load, max error / final load (400 cells)", s_src,
                  e_run.load_max, 0.0, 0.015, false});
  rows.push_back({"cavitation", "starved slider: order of the front error (200 -> 400 cells)",
                  "a moving front: first order", std::log2(e_coarse.front_max / e_run.front_max),
                  1.0, 0.3, false});
  rows.push_back({"cavitation", "starved slider: oil balance over the run / inflow",
                  "mass conservation", slider_run.mass_balance, 0.0, 1e-9, false});
  // A smooth partial film carried through a parallel gap: the void transport alone, second
  // order (the step shrinking as the cell squared, so that backward Euler's error falls alike).
  const CarriedFilm carried;
  const double carried_end = 3e-3;
  const CarriedFilmError c100 = SolveCarriedFilm(carried, 100, 0.2, carried_end, 2);
  const CarriedFilmError c200 = SolveCarriedFilm(carried, 200, 0.1, carried_end, 2);
  const CarriedFilmError u100 = SolveCarriedFilm(carried, 100, 0.2, carried_end, 1);
  const CarriedFilmError u200 = SolveCarriedFilm(carried, 200, 0.1, carried_end, 1);
  const std::string carried_src = "partial film carried at U/2 (exact: the inlet's history)";
  rows.push_back({"cavitation", "carried partial film: fraction, mean error (200 cells)",
                  carried_src, c200.mean, 0.0, 1e-3, false});
  rows.push_back({"cavitation", "carried partial film: order of the mean error (100 -> 200 cells)",
                  "second-order transport", std::log2(c100.mean / c200.mean), 2.0, 0.3, false});
  rows.push_back({"cavitation", "carried partial film, upwind fraction: order (100 -> 200 cells)",
                  "first-order transport (for comparison)", std::log2(u100.mean / u200.mean), 1.0,
                  0.3, false});
  rows.push_back({"cavitation", "carried partial film: oil balance over the run / inflow",
                  "mass conservation", c200.mass_balance, 0.0, 1e-9, false});
  SqueezeRunOptions stiff = options;
  stiff.bulk_modulus = 1e4;  // the film's time constant ~1e-4, below a step
  const SqueezeRun nearly = SolveOscillatorySqueeze(problem, stiff);
  rows.push_back({"cavitation", "squeeze, bulk modulus 1e4: cavity closing time", src,
                  nearly.close_time, reform.close_time, 0.002, false});
  return rows;
}

}  // namespace filmdyn::lubrication
