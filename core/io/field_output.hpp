#pragma once
/// @file The `fields/` folder of a run: the film fields of both lubricated joints at every
/// output step of the reported cycle, one time series per joint (`skirt.h5` + `skirt.xdmf`,
/// `bearing.h5` + `bearing.xdmf`; core/io/field_series.hpp has the layout): geometry stored once,
/// nodal arrays `pressure[Pa]`, `contact_pressure[Pa]`, `film_thickness[m]` (and
/// `fluid_fraction[-]` with mass-conserving cavitation) in single precision, compressed, the time
/// value of each frame its crank angle [°CA]. ParaView opens the `.xdmf` files with its Xdmf3
/// reader. Recorded through RunConfig's field callback; the newest cycle is kept, and the one
/// before it where memory allows (Attach): a run stopped in its second or later cycle reports
/// the last whole one.
///
/// 3D layout (metres): the bore axis is z, the skirt top at z = 0 and the skirt below it
/// (z = −y); the skirt is written as solved, α ∈ [0, π] from the thrust side (+x) — the film is
/// symmetric about the pin-axis plane (paper §2.1; ParaView's Reflect filter shows both halves).
/// The bearing is drawn in the connecting-rod frame of the journal orbit (x perpendicular to the
/// rod, y along the rod from the big end toward the small end), the film angle θ (from the
/// maximum film) placed at ψ = φ + π + θ, φ being the direction of the journal eccentricity in
/// the rod frame; z across the width.
#include <filesystem>
#include <memory>
#include <vector>

#include "core/engine/run_job.hpp"
#include "core/engine/run_memory.hpp"
#include "core/io/surface_field.hpp"

namespace filmdyn::io {

class FieldRecorder {
 public:
  FieldRecorder();
  ~FieldRecorder();
  /// The callback to put in RunConfig::field_callback (keeps a reference to this recorder).
  /// Everything needed later is copied: Write() works after the run's solvers are gone.
  engine::FieldCallback Callback();
  /// Records the run of `config`: sets its field callback and field_copies. Keeps the cycle
  /// before the newest too — the one a run stopped in its second or later cycle reports — when
  /// the run's memory estimate (engine::EstimateRunMemory) with two cycles of fields fits in
  /// `available` bytes (what this machine has); otherwise the newest only. Returns whether the
  /// previous cycle is kept.
  bool Attach(engine::RunConfig* config, double available = engine::AvailableMemoryBytes());
  /// Number of frames of the newest cycle recorded so far, per joint.
  std::size_t skirt_frames() const;
  std::size_t bearing_frames() const;
  /// Whether the recorder holds the frames of a run's reported samples (the same cycle, from its
  /// start): the newest cycle's, or the previous one's when it is kept. A run stopped in its
  /// second or later cycle reports the last whole one: without the previous cycle, not held. A
  /// run that failed in its run-in reports the run-in's part: held as the one frame of its last
  /// step, the failure (engine::FieldFrame::failure).
  bool Holds(const std::vector<engine::CrankTrainSample>& samples) const;
  /// Writes the frames of the reported `samples` when held (Holds); returns whether it wrote. A run
  /// folder's fields/ are never of other output steps than its results.csv.
  bool WriteReported(const std::filesystem::path& folder,
                     const std::vector<engine::CrankTrainSample>& samples) const;
  /// Writes the newest cycle: `<folder>/skirt.{h5,xdmf}` and `<folder>/bearing.{h5,xdmf}` for
  /// the joints that are lubricated; nothing for an ideal run. Time values are crank angles [°CA]
  /// within the cycle. Throws std::runtime_error naming the file on I/O failure.
  void Write(const std::filesystem::path& folder) const;

  /// The surface of one solve (exposed for tests and the GUI's field view).
  static SurfaceField SkirtSurface(const lubrication::SkirtSolver& skirt);
  static SurfaceField BearingSurface(const lubrication::BearingSolver& bearing,
                                     double eccentricity_angle_rod);

 private:
  struct Cycle;
  /// The cycle held whose frames are those of the reported `samples`; nullptr when none is.
  const Cycle* Reported(const std::vector<engine::CrankTrainSample>& samples) const;
  void Record(const engine::FieldFrame& frame);
  void Write(const std::filesystem::path& folder, const Cycle& cycle) const;
  struct Frames;
  std::unique_ptr<Frames> frames_;
};

}  // namespace filmdyn::io
