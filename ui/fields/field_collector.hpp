#pragma once
/// @file Fills the field view's FieldFrames from core's per-step field callback
/// (engine::RunConfig::field_callback): per joint the film surface, its tensor grid (angle and
/// axial lines, the skirt's pin-boss relief as an interval without film) and per frame the nodal
/// arrays (the fluid fraction of a joint solved with JFO cavitation too); for the big end also the
/// frame's turn into the rod frame and the crank pin's force on the rod in that frame. Keeps the
/// newest cycle only (the one a run reports) and at most kMaxFrames frames of it, so that a 1 °CA
/// run does not hold 720 copies in memory.
#include <memory>

#include "core/engine/engine_case.hpp"
#include "core/engine/run_job.hpp"
#include "ui/fields/field_frames.hpp"

namespace filmdyn::ui {

class FieldCollector {
 public:
  static constexpr int kMaxFrames = 240;

  /// `steps_per_cycle`: output steps per cycle of the run (every stride-th step is kept).
  explicit FieldCollector(int steps_per_cycle);

  /// Records one output step (called from the run's field callback, on the run's thread).
  void Add(const engine::FieldFrame& frame);
  /// The frames of the newest cycle recorded (nullptr before the first step), in crank-angle
  /// order as the run folder's fields/ are: a cycle that starts elsewhere than 0 °CA passes
  /// 720 → 0 within it and is given from 0 °CA on.
  std::shared_ptr<const FieldFrames> Result() const;

 private:
  int stride_;
  int cycle_ = 0;
  int pass_ = 1;  ///< engine::FieldFrame::pass of the frames kept
  std::shared_ptr<FieldFrames> frames_;
};

}  // namespace filmdyn::ui
