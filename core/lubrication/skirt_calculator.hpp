#pragma once
/// @file Steady piston-skirt calculator behind `filmdyn skirt` and the GUI's skirt calculator:
/// the film of one skirt (SkirtSolver) at a given secondary-motion state (mode 1), or the
/// equilibrium state that balances a given side force and moment in steady sliding (mode 2),
/// plus the load-capacity map (film force, moment and MOFT against e0 at a tilt and a speed).
///
/// Conventions are the skirt solver's: e0 > 0 moves the piston toward the thrust side (α = 0),
/// tilt γ > 0 moves the skirt below the pin toward the thrust side, the speed u_p is the
/// piston's velocity along the skirt axis, + toward the crank. Forces and moments act on the
/// piston: the film's lateral force is + toward the thrust side, its moment about the pin is the
/// generalised force on γ. The applied load of mode 2 uses the same senses: a side force > 0
/// pushes the piston toward the thrust side, a moment > 0 turns the skirt bottom toward it.
///
/// Mode 2 solves F_film(e0, γ) + F = 0, M_film(e0, γ) + M = 0 (ė0 = γ̇ = 0) by Newton's method
/// with a finite-difference Jacobian, a line search on the scaled residual and a
/// fraction-to-the-wall rule: no step uses more than 90 % of the distance between the present
/// film and the floor `min_equilibrium_film`, so every iterate has a positive film everywhere.
/// A load whose equilibrium would need a thinner film than the floor is beyond what the skirt
/// carries: the largest multiple of the load that it does carry is found by bisection and
/// reported in the InputError. Where Newton's method fails with the film well above the floor
/// (a mass-conserving film's force is only piecewise smooth), two nested bracketed roots take
/// over (docs/skirt-calculator.md).
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/lubrication/skirt_solver.hpp"

namespace filmdyn::lubrication {

/// Names used in error messages for the calculator's inputs (CLI options, GUI labels).
struct SkirtInputNames {
  std::string e0 = "e0", tilt = "tilt", speed = "speed", e0_rate = "e0_rate",
              tilt_rate = "tilt_rate", side_force = "side_force", moment = "moment";
  /// How an input's value reads in a message, with its unit (the GUI's display units: "40 µm"),
  /// given the input's name above and its SI value. Empty: the SI number, with its SI unit where
  /// the message gives one ("e0 = 4e-05", "at tilt = 0.001 rad", "… < e0 < 2e-05 [m]").
  std::function<std::string(const std::string& name, double si)> show = {};
};

/// Mode 2's load: what the rest of the engine applies to the piston.
struct SkirtLoad {
  double side_force = 0.0;       ///< + toward the thrust side [N]
  double moment = 0.0;           ///< about the pin, + turns the skirt bottom toward thrust [N m]
  double piston_velocity = 0.0;  ///< u_p, + toward the crank [m/s]
};

/// The calculator's answer at one state.
struct SkirtPoint {
  SkirtState state;
  SkirtResult film;
  double normal_moment = 0.0;  ///< film pressure + asperity part of film.moment_about_pin [N m]
  SkirtGap min_gap;
};

/// Mode 2's answer.
struct SkirtEquilibrium {
  SkirtPoint point;
  bool converged = false;
  std::string status;            ///< "converged" or why not
  int iterations = 0;            ///< Newton iterations (the fallback: tilts tried)
  int reynolds_solves = 0;       ///< skirt solves, Jacobian columns included
  double force_residual = 0.0;   ///< film + applied lateral force at the answer [N]
  double moment_residual = 0.0;  ///< film + applied moment at the answer [N m]
};

class SkirtCalculator {
 public:
  explicit SkirtCalculator(SkirtConfig config, SkirtInputNames names = {});

  /// Mode 1: the film at a state. Throws InputError naming the e0 or tilt input (with the range
  /// that keeps the film positive) when the skirt would be in the liner anywhere, or naming any
  /// input that is not finite.
  SkirtPoint AtState(const SkirtState& state);
  /// Mode 2: the steady-sliding equilibrium under `load`. Throws InputError naming the side force
  /// (the moment when the side force is zero) with the largest load carried when the equilibrium
  /// would need a film thinner than min_equilibrium_film(); numerical failures are reported in
  /// the result (converged = false).
  SkirtEquilibrium AtLoad(const SkirtLoad& load);
  /// The load-capacity curve: AtState at each e0 (steady sliding at `speed`, tilt fixed).
  std::vector<SkirtPoint> Map(const std::vector<double>& e0_values, double tilt, double speed);

  /// Smallest geometric film at (e0, γ) over the lubricated panels.
  SkirtGap MinGap(double e0, double tilt) const;
  /// The e0 for which the film is at least `margin` everywhere at this tilt: [lo, hi]; lo > hi
  /// when there is none.
  std::pair<double, double> E0Range(double tilt, double margin = 0.0) const;
  /// The tilts for which the film is at least `margin` everywhere at this e0.
  std::pair<double, double> TiltRange(double e0, double margin = 0.0) const;
  /// The thinnest film an equilibrium may have: 0.1 % of the radial clearance, at least the
  /// solver's clamp [m].
  double min_equilibrium_film() const;

  /// Checked before every solve (and inside them): true abandons the calculation with
  /// StopRequested.
  void SetStopCheck(const StopCheck& check);
  const SkirtSolver& solver() const { return solver_; }
  const SkirtConfig& config() const { return solver_.config(); }

 private:
  SkirtPoint Evaluate(const SkirtState& state);
  void CheckState(const SkirtState& state) const;
  // An input's value in a message (SkirtInputNames::show): alone, with its unit, and an interval
  // "lo < symbol < hi" of it.
  std::string Value(const std::string& name, double si) const;
  std::string WithUnit(const std::string& name, double si, const char* si_unit) const;
  std::string Between(const std::string& name, const char* symbol, double lo, double hi,
                      const char* si_unit) const;
  // Newton's method from x0 = (e0, γ); returns converged and leaves the best point in *eq.
  bool Newton(const SkirtLoad& load, double e0, double tilt, SkirtEquilibrium* eq);
  // The fallback where Newton's method fails on a film whose force is only piecewise smooth:
  // for each tilt the e0 that carries the side force, and the tilt whose moment balances, each
  // a bracketed one-dimensional root (regula falsi), the tilt searched outward from `tilt`.
  bool Nested(const SkirtLoad& load, double tilt, SkirtEquilibrium* eq);

  SkirtSolver solver_;
  SkirtInputNames names_;
  StopCheck stop_;
  std::vector<int> nodes_;  // the lubricated panels' nodes (the solver's gap geometry)
};

}  // namespace filmdyn::lubrication
