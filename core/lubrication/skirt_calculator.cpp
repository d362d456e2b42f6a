#include "core/lubrication/skirt_calculator.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "core/base/angles.hpp"
#include "core/base/input_error.hpp"

namespace filmdyn::lubrication {

namespace {

constexpr int kMaxNewtonIterations = 60;
constexpr double kTolerance = 1e-8;      // scaled residual: film + applied, over the load scale
constexpr int kCapacityBisections = 12;  // the largest load carried to 2^-12 = 0.025 %

// A feasible interval [lo, hi] of x from constraints a x <= b (one per node).
struct Interval {
  double lo = -1e300, hi = 1e300;
  void Add(double a, double b) {
    if (a > 1e-14) {
      hi = std::min(hi, b / a);
    } else if (a < -1e-14) {
      lo = std::max(lo, b / a);
    } else if (b < 0.0) {
      lo = 1.0, hi = -1.0;  // no x satisfies it
    }
  }
};

}  // namespace

SkirtCalculator::SkirtCalculator(SkirtConfig config, SkirtInputNames names)
    : solver_(std::move(config)), names_(std::move(names)) {
  for (int p = 0; p < SkirtSolver::kPanels; ++p)
    for (int node : solver_.panel_nodes(p)) nodes_.push_back(node);
}

void SkirtCalculator::SetStopCheck(const StopCheck& check) {
  stop_ = check;
  solver_.SetStopCheck(check);
}

double SkirtCalculator::min_equilibrium_film() const {
  return std::max(solver_.config().min_film, 1e-3 * solver_.config().geometry.radial_clearance);
}

SkirtGap SkirtCalculator::MinGap(double e0, double tilt) const {
  return solver_.MinRigidGap(e0, tilt);
}

std::pair<double, double> SkirtCalculator::E0Range(double tilt, double margin) const {
  Interval range;  // cos e0 <= static - margin - arm tilt cos
  for (const int k : nodes_) {
    range.Add(solver_.cos_alpha()[k], solver_.RigidGap(k, 0.0, tilt) - margin);
  }
  return {range.lo, range.hi};
}

std::pair<double, double> SkirtCalculator::TiltRange(double e0, double margin) const {
  Interval range;  // arm cos tilt <= static - margin - e0 cos
  for (const int k : nodes_) {
    range.Add(solver_.arm()[k] * solver_.cos_alpha()[k], solver_.RigidGap(k, e0, 0.0) - margin);
  }
  return {range.lo, range.hi};
}

std::string SkirtCalculator::Value(const std::string& name, double si) const {
  return names_.show ? names_.show(name, si) : FormatValue(si);
}

std::string SkirtCalculator::WithUnit(const std::string& name, double si,
                                      const char* si_unit) const {
  return names_.show ? names_.show(name, si) : FormatValue(si) + " " + si_unit;
}

std::string SkirtCalculator::Between(const std::string& name, const char* symbol, double lo,
                                     double hi, const char* si_unit) const {
  if (names_.show)
    return fmt::format("{} < {} < {}", names_.show(name, lo), symbol, names_.show(name, hi));
  return fmt::format("{:.4g} < {} < {:.4g} [{}]", lo, symbol, hi, si_unit);
}

void SkirtCalculator::CheckState(const SkirtState& s) const {
  RequireFinite(names_.e0, s.e0, "m");
  RequireFinite(names_.tilt, s.gamma, "rad");
  RequireFinite(names_.speed, s.piston_velocity, "m/s");
  RequireFinite(names_.e0_rate, s.e0_dot, "m/s");
  RequireFinite(names_.tilt_rate, s.gamma_dot, "rad/s");
  const SkirtGap gap = MinGap(s.e0, s.gamma);
  if (gap.gap > 0.0) return;
  const std::string where = fmt::format(
      "puts the skirt into the liner at {:.1f}° from the thrust side, {:.2f} mm below the skirt "
      "top (film {:.3g} µm)",
      gap.alpha * kDegreesPerRadian, gap.y * 1e3, gap.gap * 1e6);
  const auto [lo, hi] = E0Range(s.gamma);
  if (lo < hi) {
    throw InputError(
        names_.e0, Value(names_.e0, s.e0),
        fmt::format("{}; at {} = {} the film is positive for {}", where, names_.tilt,
                    WithUnit(names_.tilt, s.gamma, "rad"), Between(names_.e0, "e0", lo, hi, "m")));
  }
  const auto [tlo, thi] = TiltRange(0.0);
  throw InputError(names_.tilt, Value(names_.tilt, s.gamma),
                   fmt::format("{}; no e0 keeps the film positive at this tilt, which must lie "
                               "within {}",
                               where, Between(names_.tilt, "tilt", tlo, thi, "rad")));
}

SkirtPoint SkirtCalculator::Evaluate(const SkirtState& state) {
  ThrowIfStopRequested(stop_);
  SkirtPoint point;
  point.state = state;
  point.film = solver_.Solve(state);
  point.normal_moment = point.film.moment_about_pin - point.film.friction_moment_about_pin;
  point.min_gap = MinGap(state.e0, state.gamma);
  return point;
}

SkirtPoint SkirtCalculator::AtState(const SkirtState& state) {
  CheckState(state);
  return Evaluate(state);
}

std::vector<SkirtPoint> SkirtCalculator::Map(const std::vector<double>& e0_values, double tilt,
                                             double speed) {
  std::vector<SkirtPoint> points;
  for (double e0 : e0_values) {
    SkirtState s;
    s.e0 = e0;
    s.gamma = tilt;
    s.piston_velocity = speed;
    points.push_back(AtState(s));
  }
  return points;
}

namespace {
constexpr double kSecantStep = 1e-2;  // Newton's difference step after a stall (see Newton)
constexpr int kRootIterations = 100;  // per one-dimensional root of the nested fallback

// Residuals are scaled by the load (a moment by the load times the skirt length L).
double LoadScale(const SkirtLoad& load, double L) {
  return std::max({std::abs(load.side_force), std::abs(load.moment) / L, 1e-3});
}

// A root of f in the bracket [a, b] (f(a), f(b) of opposite signs, given) by the Illinois
// variant of regula falsi, until |f| <= tol, the bracket has shrunk to round-off, or f has no
// value at a point (NaN); the caller keeps the best point it evaluated. f is monotone here but
// only piecewise smooth, which regula falsi with bracketing survives where Newton's method need
// not.
template <class F>
void BracketedRoot(const F& f, double a, double fa, double b, double fb, double tol) {
  double best = std::min(std::abs(fa), std::abs(fb));
  int side = 0;
  for (int it = 0; it < kRootIterations && best > tol; ++it) {
    double x = (a * fb - b * fa) / (fb - fa);
    if (!(x > std::min(a, b) && x < std::max(a, b))) x = 0.5 * (a + b);
    if (std::abs(b - a) <= 1e-14 * std::max(std::abs(a), std::abs(b))) break;
    const double fx = f(x);
    if (!std::isfinite(fx)) break;
    best = std::min(best, std::abs(fx));
    if ((fx < 0.0) == (fb < 0.0)) {
      b = x, fb = fx;
      if (side == -1) fa *= 0.5;
      side = -1;
    } else {
      a = x, fa = fx;
      if (side == 1) fb *= 0.5;
      side = 1;
    }
  }
}
}  // namespace

bool SkirtCalculator::Nested(const SkirtLoad& load, double tilt, SkirtEquilibrium* eq) {
  const double L = solver_.config().geometry.skirt_length;
  const double c = solver_.config().geometry.radial_clearance;
  const double floor = min_equilibrium_film();
  const double scale = LoadScale(load, L);
  struct Carried {
    SkirtPoint point;
    double force = 0.0, moment = 0.0;  // scaled residuals
  };
  int tilts = 0;
  // The tilt's force equilibrium: the e0 that carries the side force, and the moment left there
  // (nullopt: no e0 carries it at this tilt with the film above the floor).
  auto carry = [&](double gamma) -> std::optional<Carried> {
    ++tilts;
    const auto [lo, hi] = E0Range(gamma, floor);
    if (!(lo < hi)) return std::nullopt;
    std::optional<Carried> best;
    auto force = [&](double e0) {
      SkirtState s;
      s.e0 = e0;
      s.gamma = gamma;
      s.piston_velocity = load.piston_velocity;
      ++eq->reynolds_solves;
      Carried p{Evaluate(s)};
      p.force = (p.point.film.lateral_force + load.side_force) / scale;
      p.moment = (p.point.film.moment_about_pin + load.moment) / (scale * L);
      if (!best || std::abs(p.force) < std::abs(best->force)) best = p;
      return p.force;
    };
    const double f_lo = force(lo), f_hi = force(hi);
    if ((f_lo < 0.0) == (f_hi < 0.0)) return std::nullopt;
    BracketedRoot(force, lo, f_lo, hi, f_hi, 0.1 * kTolerance);
    return best;
  };
  // The tilt whose moment balances; the best point of every tilt tried is kept.
  std::optional<Carried> best;
  auto moment = [&](double gamma) {
    std::optional<Carried> p = carry(gamma);
    if (!p) return std::numeric_limits<double>::quiet_NaN();
    const double m = p->moment;
    if (!best || std::abs(m) < std::abs(best->moment)) best = std::move(p);
    return m;
  };
  const double m_tilt = moment(tilt);
  if (!std::isfinite(m_tilt)) return false;
  // Bracket the root: tilts stepped outward on both sides, doubling from 2 % of c / L.
  const double step0 = 0.02 * c / L;
  bool bracketed = false;
  for (int k = 0; k < 12 && !bracketed; ++k) {
    for (const double sign : {1.0, -1.0}) {
      const double g = tilt + sign * step0 * std::ldexp(1.0, k);
      const double m = moment(g);
      if (std::isfinite(m) && (m < 0.0) != (m_tilt < 0.0)) {
        BracketedRoot(moment, tilt, m_tilt, g, m, kTolerance);
        bracketed = true;
        break;
      }
    }
  }
  if (!bracketed) return false;
  eq->iterations = tilts;
  eq->point = best->point;
  eq->force_residual = best->force * scale;
  eq->moment_residual = best->moment * scale * L;
  const double residual = std::max(std::abs(best->force), std::abs(best->moment));
  eq->converged = residual <= kTolerance;
  eq->status = eq->converged
                   ? "converged"
                   : fmt::format("no equilibrium found (scaled residual {:.2g})", residual);
  return eq->converged;
}

bool SkirtCalculator::Newton(const SkirtLoad& load, double e0, double tilt, SkirtEquilibrium* eq) {
  const double L = solver_.config().geometry.skirt_length;
  const double floor = min_equilibrium_film();
  const double scale = LoadScale(load, L);
  auto residual = [&](const SkirtPoint& p) {
    return Eigen::Vector2d((p.film.lateral_force + load.side_force) / scale,
                           (p.film.moment_about_pin + load.moment) / (scale * L));
  };
  auto evaluate = [&](const Eigen::Vector2d& x) {
    SkirtState s;
    s.e0 = x[0];
    s.gamma = x[1];
    s.piston_velocity = load.piston_velocity;
    ++eq->reynolds_solves;
    return Evaluate(s);
  };
  Eigen::Vector2d x(e0, tilt);
  SkirtPoint point = evaluate(x);
  Eigen::Vector2d r = residual(point);
  eq->converged = false;  // every way out of the loop below sets the status
  std::vector<double> history;  // |r| after each Newton step
  // Forward-difference step of the Jacobian, relative to the film. A mass-conserving film's force
  // is only piecewise smooth (nodes switch between full and cavitated, each switch a small jump):
  // a difference of 1e-5 of the film can straddle one switch and point Newton nowhere. When the
  // iteration stalls it goes on once with differences of 1 % of the film, a secant over them.
  double fd_step = 1e-5;
  for (int it = 0;; ++it) {
    eq->point = point;
    eq->force_residual = r[0] * scale;
    eq->moment_residual = r[1] * scale * L;
    if (r.lpNorm<Eigen::Infinity>() <= kTolerance) {
      eq->converged = true;
      eq->status = "converged";
      return true;
    }
    if (it == kMaxNewtonIterations) {
      eq->status =
          fmt::format("no equilibrium within {} Newton iterations (scaled residual {:.2g})", it,
                      r.lpNorm<Eigen::Infinity>());
      return false;
    }
    eq->iterations = it + 1;
    // Jacobian by forward differences: the film force changes on the scale of the film itself.
    const double de = fd_step * std::max(point.min_gap.gap, floor);
    Eigen::Matrix2d jac;
    jac.col(0) = (residual(evaluate(x + Eigen::Vector2d(de, 0.0))) - r) / de;
    jac.col(1) = (residual(evaluate(x + Eigen::Vector2d(0.0, de / L))) - r) / (de / L);
    Eigen::Vector2d dx = jac.fullPivLu().solve(-r);
    // Where the film force does not change (no sliding, no squeeze, no contact yet) the piston
    // moves where the net force pushes it, up to the fraction-to-the-floor limit below.
    const bool push = !dx.allFinite() || !(dx.norm() > 0.0) ||
                      std::abs(jac.determinant()) < 1e-12 * jac.squaredNorm();
    if (push) {
      const double c = solver_.config().geometry.radial_clearance;
      dx = Eigen::Vector2d(r[0], r[1] / L) * (c / r.norm());
    }
    // Fraction to the floor: every node keeps at least 10 % of its distance to the floor.
    double t_max = 1.0;
    for (const int k : nodes_) {
      const double gap = solver_.RigidGap(k, x[0], x[1]);
      const double change = -(dx[0] + solver_.arm()[k] * dx[1]) * solver_.cos_alpha()[k];
      if (change < 0.0) t_max = std::min(t_max, 0.9 * std::max(gap - floor, 0.0) / -change);
    }
    if (point.min_gap.gap - floor < 1e-3 * floor && t_max < 1e-2) {
      eq->status = "the equilibrium needs a film thinner than the floor";
      return false;
    }
    if (push) {
      x += t_max * dx;
      point = evaluate(x);
      r = residual(point);
      continue;
    }
    // Stalled: the residual fell by less than 1 % over the last 5 Newton steps.
    history.push_back(r.norm());
    if (history.size() > 5 && history.back() > 0.99 * history[history.size() - 6]) {
      if (fd_step < kSecantStep) {
        fd_step = kSecantStep;
        history.clear();
        continue;
      }
      eq->status = fmt::format("Newton's method stalled (scaled residual {:.2g})",
                               r.lpNorm<Eigen::Infinity>());
      return false;
    }
    // Backtracking on |r|^2 (Armijo, sufficient decrease 1e-4). No decrease along the step:
    // the differences straddled a switch of the film (see above); once more with the secant.
    double t = t_max;
    bool secant_again = false;
    for (;;) {
      const Eigen::Vector2d trial_x = x + t * dx;
      SkirtPoint trial = evaluate(trial_x);
      const Eigen::Vector2d trial_r = residual(trial);
      if (trial_r.squaredNorm() <= (1.0 - 2e-4 * t) * r.squaredNorm()) {
        x = trial_x;
        point = std::move(trial);
        r = trial_r;
        break;
      }
      t *= 0.5;
      if (t < 1e-10 && fd_step < kSecantStep) {
        secant_again = true;
        break;
      }
      if (t < 1e-10) {
        eq->status = fmt::format("the line search stalled (scaled residual {:.2g})",
                                 r.lpNorm<Eigen::Infinity>());
        return false;
      }
    }
    if (secant_again) {
      fd_step = kSecantStep;
      history.clear();
    }
  }
}

SkirtEquilibrium SkirtCalculator::AtLoad(const SkirtLoad& load) {
  RequireFinite(names_.side_force, load.side_force, "N");
  RequireFinite(names_.moment, load.moment, "N*m");
  RequireFinite(names_.speed, load.piston_velocity, "m/s");
  const double floor = min_equilibrium_film();
  // Start centred: the middle of the e0 range at zero tilt (e0 = 0 for a round skirt).
  const auto [lo, hi] = E0Range(0.0, floor);
  if (!(lo < hi)) {
    throw InputError("skirt.radial_clearance", FormatValue(config().geometry.radial_clearance),
                     "leaves no room for the piston in the liner");
  }
  const double start = std::clamp(0.0, lo + 0.25 * (hi - lo), hi - 0.25 * (hi - lo));
  SkirtEquilibrium eq;
  if (Newton(load, start, 0.0, &eq)) return eq;
  // Failing with a film of a few per cent of the clearance: the load is (close to) beyond what
  // the skirt carries. Elsewhere it is a numerical failure (a mass-conserving film's force is
  // only piecewise smooth, and Newton can stall on one of its steps): the continuation below
  // is tried all the same, and if it too fails the failure is reported, not an input error.
  const double thin = 0.05 * config().geometry.radial_clearance;
  const bool numerical = eq.point.min_gap.gap > thin;
  if (numerical) {
    SkirtEquilibrium nested;
    nested.reynolds_solves = eq.reynolds_solves;
    if (Nested(load, eq.point.state.gamma, &nested)) return nested;
    eq.reynolds_solves = nested.reynolds_solves;
  }

  // The largest fraction of the load carried, by bisection, each Newton started from the last
  // equilibrium found.
  int solves = eq.reynolds_solves;
  double carried = 0.0, beyond = 1.0;
  SkirtEquilibrium at;
  Eigen::Vector2d from(start, 0.0);
  for (int k = 0; k <= kCapacityBisections; ++k) {
    const double fraction = k == 0 ? 0.0 : 0.5 * (carried + beyond);
    const SkirtLoad scaled{fraction * load.side_force, fraction * load.moment,
                           load.piston_velocity};
    SkirtEquilibrium trial;
    const bool ok = Newton(scaled, from[0], from[1], &trial);
    solves += trial.reynolds_solves;
    if (ok) {
      carried = fraction;
      from = {trial.point.state.e0, trial.point.state.gamma};
    } else if (k == 0) {
      break;  // not even the unloaded skirt: carries nothing
    } else {
      beyond = fraction;
    }
  }
  // Newton from the centred start can miss an equilibrium that exists (a load just above one
  // whose film is already thin): continued from the largest fraction carried, it is found.
  if (carried > 0.0) {
    SkirtEquilibrium continued;
    const bool ok = Newton(load, from[0], from[1], &continued);
    solves += continued.reynolds_solves;
    if (ok) {
      continued.reynolds_solves = solves;
      return continued;
    }
  }
  if (numerical) {
    eq.reynolds_solves = solves;
    return eq;
  }
  const bool force_named = load.side_force != 0.0;
  const std::string with_other =
      force_named && load.moment != 0.0
          ? fmt::format(" with {} = {} (both scaled alike)", names_.moment,
                        WithUnit(names_.moment, load.moment, "N*m"))
          : "";
  const double limit = carried * (force_named ? std::abs(load.side_force) : std::abs(load.moment));
  const std::string& named = force_named ? names_.side_force : names_.moment;
  const std::string most = names_.show ? names_.show(named, limit)
                                       : fmt::format("{:.4g} {}", limit, force_named ? "N" : "N*m");
  throw InputError(
      named, Value(named, force_named ? load.side_force : load.moment),
      fmt::format("beyond what the skirt carries at {} = {}{}: at most about {} (the film would "
                  "have to be thinner than {:.3g} µm; {} skirt solves)",
                  names_.speed, WithUnit(names_.speed, load.piston_velocity, "m/s"), with_other,
                  most, floor * 1e6, solves));
}

}  // namespace filmdyn::lubrication
