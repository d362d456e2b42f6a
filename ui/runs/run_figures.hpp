#pragma once
/// @file The main figures of a run for the comparison table (and the summary of a finished run):
/// extremes and cycle means over the reported cycle, NaN when the model has no such quantity.
#include <vector>

#include "core/engine/run_job.hpp"
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
  /// max_big_end_force is a spike the output samples do not resolve (engine::NeighbourRatio
  /// above engine::kUnresolvedPeakRatio: an impact lasting a fraction of the output interval),
  /// its height whatever the samples caught; the samples beside it [N] (NaN: none).
  bool big_end_force_spike = false;
  double big_end_force_before = 0, big_end_force_after = 0;
};

/// The figures of a run of `model`: those of an ideal joint (no film: no secondary motion,
/// film or friction) are NaN, shown as "no such figure", not as a measured 0.
RunFigures ComputeRunFigures(const std::vector<RunSample>& samples, engine::Model model);

}  // namespace filmdyn::ui
