#pragma once
/// @file Periodic steady state of the crank train: quantities are sampled at the same
/// crank angles every 720 °CA cycle; the run is periodic when, for every quantity, the largest
/// change between the last two cycles at any sample is below `tolerance` × the quantity's range
/// over the last cycle (default 1 %, the paper's Table II "convergence criterion 1 %").
/// A quantity whose range is tiny (e.g. a MOFT that barely moves) is compared against its
/// absolute floor instead, so a flat trace cannot block convergence through round-off.
#include <string>
#include <vector>

namespace filmdyn::coupling {

struct TrackedQuantity {
  std::string name;           ///< e.g. "piston_lateral[m]"
  double absolute_floor = 0;  ///< smallest range that counts, in the quantity's unit
  std::string label;          ///< what messages call it, e.g. "piston lateral displacement"
};

/// The verdict after one complete cycle.
struct CycleVerdict {
  int cycle = 0;          ///< 1-based index of the cycle just completed
  bool compared = false;  ///< false for the first cycle (nothing to compare with)
  bool converged = false;
  /// Per quantity: max |change| / max(range, floor); converged when all ≤ tolerance.
  std::vector<double> relative_change;
  /// Name of the quantity furthest from convergence (for progress messages).
  std::string worst_quantity;
  std::string worst_label;  ///< its TrackedQuantity::label
  double worst_relative_change = 0;
};

class PeriodicSteadyState {
 public:
  /// samples_per_cycle: how many Record() calls make one cycle (e.g. 720 at 1 °CA).
  PeriodicSteadyState(std::vector<TrackedQuantity> quantities, int samples_per_cycle,
                      double tolerance = 0.01);

  /// Records sample `index` (0 … samples_per_cycle−1) of the current cycle; `values` holds one
  /// value per tracked quantity, in order. NaN is recorded and makes the cycle unconverged.
  void Record(int index, const std::vector<double>& values);
  /// Closes the current cycle and compares it with the previous one.
  CycleVerdict EndCycle();

  int samples_per_cycle() const { return samples_per_cycle_; }
  double tolerance() const { return tolerance_; }
  const std::vector<TrackedQuantity>& quantities() const { return quantities_; }

 private:
  std::vector<TrackedQuantity> quantities_;
  int samples_per_cycle_;
  double tolerance_;
  int cycle_ = 0;
  // [quantity][sample]
  std::vector<std::vector<double>> current_, previous_;
  std::vector<std::vector<bool>> recorded_;
  bool have_previous_ = false;
};

}  // namespace filmdyn::coupling
