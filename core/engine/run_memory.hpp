#pragma once
/// @file What a run will hold in memory, estimated from its case before anything is built, and
/// the check that refuses a run this machine cannot hold (docs/reliability.md, "Memory").
///
/// The film solvers dominate: per lubricated system of n unknowns (the skirt's two panels, the
/// big end's width or symmetric half) the sparse LDL^T factor, the matrices and the per-node
/// arrays take n · (800 + 50 · log2 n) bytes — fitted to peak resident sizes measured for 1.3·10^5
/// to 8·10^5 unknowns, and above every one of them by up to 11 %. The film fields are held until
/// they are written (3 single-precision values per surface node per output step; one cycle, or
/// two where they fit: io::FieldRecorder::Attach), and the output samples of two cycles.
#include <string>

#include "core/engine/engine_case.hpp"

namespace filmdyn::engine {

/// Film-mesh sizes of a case, whether or not the joints are lubricated.
struct FilmMeshSizes {
  long skirt_surface_nodes = 0;    ///< nodes of the skirt's mesh (relief included)
  long skirt_unknowns = 0;         ///< pressure unknowns of the two lubricated panels together
  long big_end_surface_nodes = 0;  ///< nodes over the whole bearing width
  long big_end_unknowns = 0;       ///< unknowns solved (the symmetric half when it applies)
};
FilmMeshSizes FilmMeshSizesOf(const EngineCase& engine_case);

/// Upper limit on each joint's pressure unknowns the case file accepts: a factor of ~0.9 GB, one
/// factorisation of several seconds, and a set-up (mesh, matrix pattern, ordering) of under a
/// second per joint, so that a stop request is honoured within about a second from the start
/// (docs/reliability.md has the measured sizes and times).
constexpr long kMaxFilmUnknowns = 500'000;
/// Throws InputError naming the mesh fields when a joint's mesh exceeds kMaxFilmUnknowns.
void CheckFilmMeshSizes(const EngineCase& engine_case);

struct MemoryEstimate {
  double base_bytes = 0.0;       ///< program, libraries, mechanism
  double solver_bytes = 0.0;     ///< the run's film solvers
  double companion_bytes = 0.0;  ///< the error estimate's companion run (solvers, samples)
  double field_bytes = 0.0;      ///< film fields held until written (field_copies cycles)
  double sample_bytes = 0.0;     ///< output samples (two cycles)
  double total() const {
    return base_bytes + solver_bytes + companion_bytes + field_bytes + sample_bytes;
  }
  std::string Describe() const;  ///< "about 9.2 GB (film solvers 7.1 GB, …)"
};

/// `engine_case` with its joint models set (ApplyModel). `field_copies`: how many copies of one
/// cycle's film fields the run's consumers hold (0 = none written; the run folder's recorder: 1).
MemoryEstimate EstimateRunMemory(const EngineCase& engine_case, double field_copies);

/// Memory this process may still take [bytes]: MemAvailable of /proc/meminfo, lowered by a
/// cgroup limit when one applies; +infinity where neither can be read.
double AvailableMemoryBytes();

/// Throws InputError naming the largest film mesh when `estimate` exceeds `available` bytes.
void RequireMemory(const EngineCase& engine_case, const MemoryEstimate& estimate, double available);

}  // namespace filmdyn::engine
