#include "core/lubrication/bearing_calculator.hpp"

#include <boost/math/tools/toms748_solve.hpp>

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
                     "give exactly one of --eps (mode 1) or --load (mode 2)");
  }
  if (eps) RequireInRange("bearing.eps", *eps, 0.0, 1.0, false, true);
  if (load) RequirePositive("bearing.load", *load, "N");
  if (surfaces) surfaces->Validate("bearing.surface");
  PressureViscosityOf(*this);  // validates the law's constants
}

PressureViscosity PressureViscosityOf(const BearingCalcInput& in) {
  switch (in.pressure_law) {
    case PressureLaw::kNone:
      return {};
    case PressureLaw::kBarus:
      return PressureViscosity::Barus(in.barus_alpha, "bearing.");
    case PressureLaw::kRoelands:
      return PressureViscosity::Roelands(in.roelands_z, in.viscosity, "bearing.");
  }
  return {};
}

BearingCalcResult RunBearingCalculator(const BearingCalcInput& in) {
  in.Validate();
  BearingConfig cfg;
  cfg.geometry = {in.radius, in.length, in.radial_clearance};
  cfg.viscosity = in.viscosity;
  cfg.pressure_viscosity = PressureViscosityOf(in);
  cfg.shear_thinning = in.shear_thinning;
  cfg.mesh = in.mesh;
  cfg.compliance = in.compliance;
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
    // Mode 2: g(eps) = ln(load(eps) / W) is increasing in eps: bracket [lo, hi], then
    // Alefeld–Potra–Shi's TOMS 748 (Boost.Math), which needs fewer Reynolds solves than bisection
    // or regula falsi on this smooth, steep function.
    const double W = *in.load;
    auto g = [&](double eps) { return std::log(std::max(solve(eps).load, 1e-300) / W); };
    const double lo = 1e-4, hi = 1.0 - 1e-7;
    const double glo = g(lo), ghi = g(hi);
    if (glo > 0.0) {
      out.converged = false;
      out.status = "load below the capacity at eps = 1e-4 (lightly loaded: eps < 1e-4)";
      solve(lo);
    } else if (ghi < 0.0) {
      out.converged = false;
      out.status = "load exceeds the film + asperity capacity at eps = 1 - 1e-7";
      solve(hi);
    } else {
      // Converged when the load is within 1e-9 relative (|g| < 1e-9) or the bracket < 1e-12.
      double last_g = 1.0;
      double best_eps = std::abs(glo) <= std::abs(ghi) ? lo : hi;
      double best_g = std::min(std::abs(glo), std::abs(ghi));
      auto g_tracked = [&](double eps) {
        last_g = g(eps);
        if (std::abs(last_g) < best_g) best_g = std::abs(last_g), best_eps = eps;
        return last_g;
      };
      auto close_enough = [&last_g](double a, double b) {
        return std::abs(last_g) < 1e-9 || b - a < 1e-12;
      };
      std::uintmax_t max_solves = 100;
      const auto [a, b] =
          boost::math::tools::toms748_solve(g_tracked, lo, hi, glo, ghi, close_enough, max_solves);
      if (!close_enough(a, b)) {
        out.converged = false;
        out.status = "equilibrium eccentricity search did not converge in 100 solves";
      }
      // Leave the solver at the best eccentricity found (its fields are reported).
      if (state.eps != best_eps) solve(best_eps);
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
  out.max_deformation = r.max_deformation;
  out.elastic = r.elastic;
  out.last_stats = r.stats;
  if (!std::isfinite(out.load) || !std::isfinite(out.friction_torque) ||
      !std::isfinite(out.max_pressure) || !std::isfinite(out.side_flow)) {
    // Inputs at the edge of floating point: no figure to report.
    out.converged = false;
    out.status = "the film's figures are not finite numbers (load " + FormatValue(out.load) +
                 " N): the inputs are beyond what the calculation can represent";
  } else if (!r.elastic.converged) {
    out.converged = false;
    out.status = "elastic film: " + r.elastic.message;
  } else if (r.stats.status != SolveStatus::kConverged) {
    out.converged = false;
    out.status = std::string("Reynolds solve: ") + ToString(r.stats.status);
  } else if (r.stats.capped_nodes > 0) {
    out.converged = false;
    out.status = "film beyond the pressure-viscosity limit at " +
                 std::to_string(r.stats.capped_nodes) +
                 " nodes (the isoviscous pressure exceeds the law's limit, 1/alpha for Barus: "
                 "no finite pressure carries this state)";
  }
  return out;
}

}  // namespace filmdyn::lubrication
