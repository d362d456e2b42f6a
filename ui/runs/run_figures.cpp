#include "ui/runs/run_figures.hpp"

#include <cmath>
#include <limits>

#include "core/engine/error_estimate.hpp"

namespace filmdyn::ui {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

template <typename F>
double Reduce(const std::vector<RunSample>& samples, F value, bool take_max) {
  double best = kNaN;
  for (const RunSample& s : samples) {
    const double v = value(s);
    if (!std::isfinite(v)) continue;
    if (std::isnan(best) || (take_max ? v > best : v < best)) best = v;
  }
  return best;
}

// Cycle mean: the plain mean of the cycle's equally spaced output samples (the periodic
// trapezoidal rule), as engine::HeadlineFigures defines it for summary.json; NaN without data.
double Mean(const std::vector<RunSample>& samples, Column column) {
  double sum = 0;
  int count = 0;
  for (const RunSample& s : samples) {
    if (std::isfinite(s[column])) {
      sum += s[column];
      ++count;
    }
  }
  return count > 0 ? sum / count : kNaN;
}

}  // namespace

RunFigures ComputeRunFigures(const std::vector<RunSample>& samples, engine::Model model) {
  RunFigures f;
  auto abs_of = [](Column c) { return [c](const RunSample& s) { return std::abs(s[c]); }; };
  auto of = [](Column c) { return [c](const RunSample& s) { return s[c]; }; };
  f.max_abs_lateral = Reduce(samples, abs_of(Column::kPistonLateral), true);
  f.max_abs_tilt = Reduce(samples, abs_of(Column::kPistonTilt), true);
  f.min_skirt_moft = Reduce(samples, of(Column::kSkirtMoft), false);
  f.min_bearing_moft = Reduce(samples, of(Column::kBearingMoft), false);
  f.max_bearing_eps = Reduce(samples, of(Column::kBearingEps), true);
  f.mean_skirt_fpl = Mean(samples, Column::kSkirtFpl);
  f.mean_bearing_fpl = Mean(samples, Column::kBearingFpl);
  auto force = [](const RunSample& s) {
    return std::hypot(s[Column::kBigEndForceX], s[Column::kBigEndForceY]);
  };
  f.max_big_end_force = Reduce(samples, force, true);
  // The samples beside the largest force (none past either end: a cycle being computed, or a
  // stopped run's, is not known to be whole).
  for (std::size_t k = 0; k < samples.size() && std::isfinite(f.max_big_end_force); ++k) {
    if (force(samples[k]) != f.max_big_end_force) continue;
    f.big_end_force_before = k > 0 ? force(samples[k - 1]) : kNaN;
    f.big_end_force_after = k + 1 < samples.size() ? force(samples[k + 1]) : kNaN;
    f.big_end_force_spike =
        engine::NeighbourRatio(f.max_big_end_force, f.big_end_force_before, f.big_end_force_after) >
        engine::kUnresolvedPeakRatio;
    break;
  }
  f.max_skirt_normal = Reduce(samples, abs_of(Column::kSkirtNormalForce), true);
  if (!engine::SkirtLubricated(model)) {
    f.max_abs_lateral = f.max_abs_tilt = f.min_skirt_moft = f.mean_skirt_fpl = kNaN;
  }
  if (!engine::BigEndLubricated(model)) {
    f.min_bearing_moft = f.max_bearing_eps = f.mean_bearing_fpl = kNaN;
  }
  return f;
}

}  // namespace filmdyn::ui
