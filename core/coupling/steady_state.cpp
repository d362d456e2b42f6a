#include "core/coupling/steady_state.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/base/input_error.hpp"

namespace filmdyn::coupling {

PeriodicSteadyState::PeriodicSteadyState(std::vector<TrackedQuantity> quantities,
                                         int samples_per_cycle, double tolerance)
    : quantities_(std::move(quantities)),
      samples_per_cycle_(samples_per_cycle),
      tolerance_(tolerance) {
  if (samples_per_cycle < 2) {
    throw InputError("solver.output_interval", std::to_string(samples_per_cycle) + " samples",
                     "must give at least 2 samples per cycle");
  }
  RequireInRange("solver.steady_state_tolerance", tolerance, 0.0, 1.0, true, false);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  current_.assign(quantities_.size(), std::vector<double>(samples_per_cycle, nan));
  previous_ = current_;
  recorded_.assign(quantities_.size(), std::vector<bool>(samples_per_cycle, false));
}

void PeriodicSteadyState::Record(int index, const std::vector<double>& values) {
  // Caller bugs, not user input: always-on checks.
  if (index < 0 || index >= samples_per_cycle_ || values.size() != quantities_.size()) {
    throw std::logic_error("PeriodicSteadyState::Record: index or value count out of range");
  }
  for (std::size_t q = 0; q < quantities_.size(); ++q) {
    current_[q][index] = values[q];
    recorded_[q][index] = true;
  }
}

CycleVerdict PeriodicSteadyState::EndCycle() {
  CycleVerdict verdict;
  verdict.cycle = ++cycle_;
  verdict.relative_change.assign(quantities_.size(), std::numeric_limits<double>::infinity());
  bool complete = true;
  for (const auto& flags : recorded_) {
    complete = complete && std::all_of(flags.begin(), flags.end(), [](bool b) { return b; });
  }
  if (have_previous_ && complete) {
    verdict.compared = true;
    verdict.converged = true;
    for (std::size_t q = 0; q < quantities_.size(); ++q) {
      const auto& now = current_[q];
      const auto& before = previous_[q];
      const auto [lo, hi] = std::minmax_element(now.begin(), now.end());
      const double range = std::max(*hi - *lo, quantities_[q].absolute_floor);
      double change = 0.0;
      bool finite = true;
      for (int k = 0; k < samples_per_cycle_; ++k) {
        const double d = std::abs(now[k] - before[k]);
        finite = finite && std::isfinite(d);
        change = std::max(change, d);
      }
      const double relative =
          !finite ? std::numeric_limits<double>::infinity()
                  : (range > 0.0 ? change / range
                                 : (change == 0.0 ? 0.0 : std::numeric_limits<double>::infinity()));
      verdict.relative_change[q] = relative;
      if (!(relative <= tolerance_)) verdict.converged = false;
      if (q == 0 || relative > verdict.worst_relative_change) {
        verdict.worst_relative_change = relative;
        verdict.worst_quantity = quantities_[q].name;
        verdict.worst_label = quantities_[q].label;
      }
    }
  }
  previous_.swap(current_);
  have_previous_ = complete;
  for (auto& flags : recorded_) std::fill(flags.begin(), flags.end(), false);
  return verdict;
}

}  // namespace filmdyn::coupling
