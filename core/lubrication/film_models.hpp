#pragma once
/// @file The named model choices of the film solvers (cavitation, oil supply), kept apart from
/// the solvers so that a case can name them without the solvers' headers.

namespace filmdyn::lubrication {

/// kReynolds: Swift-Stieber (p >= 0, oil not conserved where a film reforms); kJfo: mass-
/// conserving Jakobsson-Floberg-Olsson (transient in time integrations); kNone: full Sommerfeld
/// film, negative pressures allowed (verification only).
enum class CavitationModel { kReynolds, kJfo, kNone };

/// "reynolds", "jfo", "none".
const char* ToString(CavitationModel model);

/// Where a bearing's film is fed (OilFeed in bearing_solver.hpp says what each means).
enum class OilFeedKind { kLineOfCentres, kShellHoles, kPinHoles, kGroove, kPinHolesAndGroove };
/// "line_of_centres", "shell_holes", "pin_holes", "groove", "pin_holes_and_groove" (case-file
/// names).
const char* ToString(OilFeedKind kind);
/// Whether the supply has holes (in the shell or the pin), holes in the pin, a shell groove.
constexpr bool HasHoles(OilFeedKind kind) {
  return kind == OilFeedKind::kShellHoles || kind == OilFeedKind::kPinHoles ||
         kind == OilFeedKind::kPinHolesAndGroove;
}
constexpr bool HasPinHoles(OilFeedKind kind) {
  return kind == OilFeedKind::kPinHoles || kind == OilFeedKind::kPinHolesAndGroove;
}
constexpr bool HasGroove(OilFeedKind kind) {
  return kind == OilFeedKind::kGroove || kind == OilFeedKind::kPinHolesAndGroove;
}

/// How a piston skirt is fed: fully flooded (a full film enters at its leading edge), or
/// starved, from the oil film the ring pack leaves on the liner (SkirtConfig).
enum class SkirtSupply { kFlooded, kStarved };
/// "flooded", "starved".
const char* ToString(SkirtSupply supply);

/// How the film's surfaces deform under the film and asperity pressure (film_compliance.hpp):
/// kRigid (no deformation), kElasticLayer (a thin lining on a rigid backing, each point
/// independent), kHalfSpace (both surfaces elastic half-spaces, Boussinesq).
/// kImported: a compliance exported by a finite-element code (imported_compliance.hpp).
enum class ComplianceModel { kRigid, kElasticLayer, kHalfSpace, kImported };
/// "rigid", "elastic_layer", "half_space", "imported".
const char* ToString(ComplianceModel model);

}  // namespace filmdyn::lubrication
