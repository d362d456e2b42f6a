#pragma once
/// @file Piston slap: the piston's lateral kinetic energy at each change of thrust side over a
/// cycle (summary.json's kpis, the comparison's slap figures and the headline figure of the
/// largest one). One definition for the KPIs and the error estimate.
#include <optional>
#include <vector>

#include "core/engine/crank_train.hpp"

namespace filmdyn::engine {

/// One change of thrust side of the piston.
struct SlapEvent {
  double crank_angle_deg = 0.0;  ///< within the cycle, [0, 720)
  double energy = 0.0;           ///< ½ m v_x² + ½ I ω² of the piston there [J]
  bool to_thrust = false;        ///< onto the major-thrust wall (else onto the anti-thrust wall)
};

/// The piston slap of a cycle: every change of thrust side in time order, the largest energy
/// (with its crank angle; none without an event) and the sum (a whole cycle's only: none for the
/// part of a cycle a run stopped in its run-in computed).
struct PistonSlap {
  std::vector<SlapEvent> events;
  std::optional<double> energy_max;  ///< [J]
  std::optional<double> energy_max_crank_angle_deg;
  std::optional<double> energy_sum;  ///< [J]
};

/// The slap of the samples: where the skirt's normal force changes sign between output steps (a
/// step with no side force between them moves the instant to where the new side's force begins),
/// the piston's energy ½ m v_x² + ½ I ω² from the motion samples interpolated to that instant
/// (from the output samples when `motion` is empty). `whole_cycle`: the samples are one periodic
/// cycle (the last step is beside the first, and the sum is given).
PistonSlap SlapOf(const std::vector<CrankTrainSample>& samples,
                  const std::vector<MotionSample>& motion, double mass, double inertia,
                  bool whole_cycle);

}  // namespace filmdyn::engine
