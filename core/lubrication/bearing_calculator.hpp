#pragma once
/// @file Steady journal-bearing calculator behind `filmdyn bearing`: journal rotating,
/// bearing at rest, constant load. Mode 1: eccentricity given. Mode 2: load and speed given, the
/// equilibrium eccentricity found by a bracketed root search (mixed lubrication included when a
/// surface pair is given). Dimensionless outputs follow Raimondi & Boyd (1958).
#include <optional>
#include <string>

#include "core/lubrication/bearing_solver.hpp"
#include "core/lubrication/surface/surface_model.hpp"

namespace filmdyn::lubrication {

struct BearingCalcInput {
  double radius = 0.025;            ///< journal radius R [m]
  double length = 0.025;            ///< bearing width L [m]
  double radial_clearance = 25e-6;  ///< c [m]
  double viscosity = 0.01;          ///< at zero gauge pressure [Pa s]
  /// Pressure-viscosity law: kBarus uses barus_alpha [1/Pa], kRoelands roelands_z [-] (oil.hpp).
  PressureLaw pressure_law = PressureLaw::kNone;
  double barus_alpha = 0.0;
  double roelands_z = 0.0;
  CrossLaw shear_thinning;          ///< at the oil's temperature (oil.hpp); inactive: Newtonian
  double speed_rpm = 3000.0;        ///< journal speed [rev/min]
  BearingMeshSpec mesh{100, 20, true};
  CavitationModel cavitation = CavitationModel::kReynolds;
  std::optional<SurfacePair> surfaces;  ///< rough surfaces (1 = journal, 2 = bearing)
  /// Elastic surfaces (film_compliance.hpp; rigid by default): the film and the deformation
  /// solved together at every eccentricity.
  ComplianceSpec compliance;
  std::optional<double> eps;            ///< mode 1
  std::optional<double> load;           ///< mode 2 [N]
  /// Throws filmdyn::InputError (fields "bearing.<name>").
  void Validate() const;
};

struct BearingCalcResult {
  double eps = 0.0;
  double attitude_deg = 0.0;
  double sommerfeld = 0.0;           ///< S = (mu N / P)(R/c)^2, N [rev/s], P = W/(2 R L)
  double friction_variable = 0.0;    ///< (R/c) f, f = |T_journal| / (R W)
  double side_flow = 0.0;            ///< Q_s [m^3/s], both edges
  double side_flow_variable = 0.0;   ///< Q_s / (R c N L) (Raimondi-Boyd normalisation)
  double inlet_flow = 0.0;           ///< Q, flow entering the pressure film [m^3/s]
  double inlet_flow_variable = 0.0;  ///< Q / (R c N L)
  double moft = 0.0;                 ///< [m]
  double friction_torque = 0.0;      ///< |T| on the journal [N m]
  double friction_power_loss = 0.0;  ///< [W]
  double load = 0.0;                 ///< film + asperity load [N]
  double contact_load = 0.0;         ///< asperity part [N]
  double max_pressure = 0.0;         ///< [Pa]
  double cavitated_fraction = 0.0;
  double max_deformation = 0.0;  ///< elastic surfaces: largest film opening [m]
  ElasticSolveStats elastic;     ///< elastic surfaces: the last coupled solve
  int reynolds_solves = 0;       ///< coupled solves (each one or more film solves)
  bool converged = true;  ///< false: root search or LCP did not converge (see status)
  std::string status = "converged";
  ReynoldsStats last_stats;
};

/// The input's pressure-viscosity law (kNone: an inactive one). Throws filmdyn::InputError.
PressureViscosity PressureViscosityOf(const BearingCalcInput& input);

/// Runs mode 1 (eps set) or mode 2 (load set). Bad input throws filmdyn::InputError; numerical
/// trouble is reported in status/converged.
BearingCalcResult RunBearingCalculator(const BearingCalcInput& input);

}  // namespace filmdyn::lubrication
