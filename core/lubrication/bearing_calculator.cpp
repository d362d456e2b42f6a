#include "core/lubrication/bearing_calculator.hpp"

#include <cmath>
#include <numbers>

#include "core/base/input_error.hpp"
#include "core/lubrication/surface_film.hpp"

namespace filmdyn::lubrication {

void BearingCalcInput::Validate() const {
  RequirePositive("bearing.radius", radius, "m");
  RequirePositive("bearing.length", length, "m");
  RequirePositive("bearing.radial_clearance", radial_clearance, "m");
  RequirePositive("bearing.viscosity", viscosity, "Pa*s");
  RequirePositive("bearing.speed_rpm", speed_rpm, "rev/min");
  if (eps.has_value() == load.has_value()) {
    throw InputError("bearing.mode", eps ? "both --eps and --load" : "neither --eps nor --load",
                     "give exactly one of eps (mode 1) or load (mode 2)");
  }
  if (eps) RequireInRange("bearing.eps", *eps, 0.0, 1.0, false, true);
  if (load) RequirePositive("bearing.load", *load, "N");
  if (surfaces) surfaces->Validate("bearing.surface");
}

BearingCalcResult RunBearingCalculator(const BearingCalcInput& in) {
  in.Validate();
  BearingConfig cfg;
  cfg.geometry = {in.radius, in.length, in.radial_clearance};
  cfg.viscosity = in.viscosity;
  cfg.mesh = in.mesh;
  cfg.solver.cavitation = in.cavitation;
  if (in.surfaces) cfg.film = MakeSurfaceFilm(*in.surfaces);
  BearingSolver solver(cfg);  // validates geometry and mesh
  const double omega = in.speed_rpm * 2.0 * std::numbers::pi / 60.0;
  BearingCalcResult out;
  BearingState state;
  state.omega_journal = omega;

  auto solve = [&](double eps) -> const BearingResult& {
    state.eps = eps;
    ++out.reynolds_solves;
    return solver.Solve(state);
  };

  if (in.eps) {
    solve(*in.eps);
  } else {
    // Mode 2: g(eps) = ln(load(eps) / W) is increasing in eps; bracket [lo, hi] and use the
    // Illinois variant of regula falsi (Dowell & Jarratt 1971) with bisection safeguard.
    const double W = *in.load;
    double lo = 1e-4, hi = 1.0 - 1e-7;
    double glo = std::log(std::max(solve(lo).load, 1e-300) / W);
    double ghi = std::log(std::max(solve(hi).load, 1e-300) / W);
    if (glo > 0.0) {
      out.converged = false;
      out.status = "load below the capacity at eps = 1e-4 (lightly loaded: eps < 1e-4)";
      solve(lo);
    } else if (ghi < 0.0) {
      out.converged = false;
      out.status = "load exceeds the film + asperity capacity at eps = 1 - 1e-7";
      solve(hi);
    } else {
      int side = 0;
      double eps = 0.5 * (lo + hi);
      bool done = false;
      for (int it = 0; it < 100 && !done; ++it) {
        double trial = (lo * ghi - hi * glo) / (ghi - glo);
        if (!(trial > lo && trial < hi)) trial = 0.5 * (lo + hi);
        eps = trial;
        const double g = std::log(std::max(solve(eps).load, 1e-300) / W);
        if (std::abs(g) < 1e-9 || hi - lo < 1e-12) done = true;
        if (g > 0.0) {
          hi = eps, ghi = g;
          if (side == 1) glo *= 0.5;
          side = 1;
        } else {
          lo = eps, glo = g;
          if (side == -1) ghi *= 0.5;
          side = -1;
        }
      }
      if (!done) {
        out.converged = false;
        out.status = "equilibrium eccentricity search did not converge in 100 solves";
      }
    }
  }
  const BearingResult& r = solver.result();
  const double N = in.speed_rpm / 60.0;
  const double P = r.load / (2.0 * in.radius * in.length);
  const double rc = in.radius / in.radial_clearance;
  out.eps = state.eps;
  out.attitude_deg = r.attitude_deg;
  out.load = r.load;
  out.contact_load = std::hypot(r.contact_force_n, r.contact_force_t);
  out.sommerfeld = P > 0 ? in.viscosity * N / P * rc * rc : INFINITY;
  out.friction_torque = std::abs(r.friction_torque_journal);
  out.friction_variable = r.load > 0 ? rc * out.friction_torque / (in.radius * r.load) : INFINITY;
  out.side_flow = r.side_flow;
  out.side_flow_variable = r.side_flow / (in.radius * in.radial_clearance * N * in.length);
  out.inlet_flow = r.inlet_flow;
  out.inlet_flow_variable = r.inlet_flow / (in.radius * in.radial_clearance * N * in.length);
  out.moft = r.moft;
  out.friction_power_loss = r.friction_power_loss;
  out.max_pressure = r.max_pressure;
  out.cavitated_fraction = r.cavitated_fraction;
  out.last_stats = r.stats;
  if (r.stats.status != SolveStatus::kConverged) {
    out.converged = false;
    out.status = std::string("Reynolds solve: ") + ToString(r.stats.status);
  }
  return out;
}

}  // namespace filmdyn::lubrication
