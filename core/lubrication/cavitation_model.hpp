#pragma once
/// @file The cavitation models of the Reynolds solver (ReynoldsFem), named for case files.

namespace filmdyn::lubrication {

/// kReynolds: Swift-Stieber (p >= 0, oil not conserved where a film reforms); kJfo: mass-
/// conserving Jakobsson-Floberg-Olsson (transient in time integrations); kNone: full Sommerfeld
/// film, negative pressures allowed (verification only).
enum class CavitationModel { kReynolds, kJfo, kNone };

/// "reynolds", "jfo", "none".
const char* ToString(CavitationModel model);

}  // namespace filmdyn::lubrication
