#pragma once
/// @file The main figures of a run for the comparison table (and the summary of a finished run):
/// extremes and cycle means over the reported cycle, NaN when the model has no such quantity.
#include <vector>

#include "ui/run/result_columns.hpp"

namespace filmdyn::ui {

struct RunFigures {
  double max_abs_lateral = 0;    ///< max |e0| [m]
  double max_abs_tilt = 0;       ///< max |γ| [rad]
  double min_skirt_moft = 0;     ///< [m]
  double min_bearing_moft = 0;   ///< [m]
  double max_bearing_eps = 0;    ///< [-]
  double mean_skirt_fpl = 0;     ///< cycle mean [W]
  double mean_bearing_fpl = 0;   ///< cycle mean [W]
  double max_big_end_force = 0;  ///< max |F| [N]
  double max_skirt_normal = 0;   ///< max |F_n| [N]
};

RunFigures ComputeRunFigures(const std::vector<RunSample>& samples);

}  // namespace filmdyn::ui
