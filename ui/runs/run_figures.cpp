#include "ui/runs/run_figures.hpp"

#include <cmath>
#include <limits>

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

RunFigures ComputeRunFigures(const std::vector<RunSample>& samples) {
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
  f.max_big_end_force = Reduce(
      samples,
      [](const RunSample& s) {
        return std::hypot(s[Column::kBigEndForceX], s[Column::kBigEndForceY]);
      },
      true);
  f.max_skirt_normal = Reduce(samples, abs_of(Column::kSkirtNormalForce), true);
  return f;
}

}  // namespace filmdyn::ui
