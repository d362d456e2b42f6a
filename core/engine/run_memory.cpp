#include "core/engine/run_memory.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>

#include "core/base/input_error.hpp"
#include "core/engine/crank_train.hpp"
#include "core/engine/error_estimate.hpp"
#include "core/engine/film_joints.hpp"

namespace filmdyn::engine {

namespace {

// Peak resident bytes of a film system of n unknowns (see the file comment).
double SystemBytes(double n) {
  return n <= 0 ? 0.0 : n * (800.0 + 50.0 * std::log2(std::max(n, 2.0)));
}

// Resident size of the program before any film solver (libraries, mechanism, Qt): measured
// 70-80 MB for `filmdyn run` with the plotting libraries loaded.
constexpr double kBaseBytes = 80e6;
// Film fields: pressure, contact pressure and film thickness per surface node, single precision.
constexpr double kFieldBytesPerNode = 3 * sizeof(float);

// Which joints of a case have a film (their models set by ApplyModel).
struct Films {
  bool skirt = false, big_end = false;
};
Films FilmsOf(const EngineCase& c) {
  return {c.skirt.model == JointModel::kLubricated, c.big_end.model == JointModel::kLubricated};
}

// The dense half-space compliance of a film of n nodes (lubrication::SurfaceCompliance):
// n^2 doubles. Imported compliances are counted by their files' size when read, not here.
double ComplianceBytes(lubrication::ComplianceModel model, double n) {
  return model == lubrication::ComplianceModel::kHalfSpace ? n * n * sizeof(double) : 0.0;
}

double SolverBytes(const EngineCase& c) {
  const FilmMeshSizes m = FilmMeshSizesOf(c);
  const Films films = FilmsOf(c);
  double bytes = 0.0;
  if (films.skirt) {
    bytes += 2.0 * SystemBytes(m.skirt_unknowns / 2.0);
    bytes += 2.0 * ComplianceBytes(c.skirt.compliance, m.skirt_unknowns / 2.0);
  }
  if (films.big_end) {
    bytes += SystemBytes(m.big_end_unknowns);
    bytes += ComplianceBytes(c.big_end.compliance, m.big_end_unknowns);
  }
  return bytes;
}

// A joint's mesh in messages: the fields that set it, and their values.
struct MeshText {
  std::string field, value;
};
MeshText SkirtMeshText(const SkirtCase& s) {
  return {"skirt mesh (skirt.mesh_thrust + mesh_relief + mesh_anti × mesh_axial)",
          fmt::format("{} + {} + {} × {} elements", s.mesh_thrust, s.mesh_relief, s.mesh_anti,
                      s.mesh_axial)};
}
MeshText BigEndMeshText(const BigEndCase& b) {
  return {"big-end mesh (big_end.mesh_theta × big_end.mesh_z)",
          fmt::format("{} × {} elements", b.mesh_theta, b.mesh_z)};
}

double OutputStepsPerCycle(const EngineCase& c) {
  return std::ceil(4.0 * std::numbers::pi / c.solver.output_interval);
}

std::string Gigabytes(double bytes) {
  return bytes >= 1e9 ? fmt::format("{:.1f} GB", bytes / 1e9)
                      : fmt::format("{:.0f} MB", bytes / 1e6);
}

// The number after `key` in a "key value" text file (/proc/meminfo: "MemAvailable: 123 kB").
double ReadKeyedNumber(const char* path, const std::string& key) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(key, 0) == 0) {
      std::istringstream fields(line.substr(key.size()));
      double value = 0.0;
      if (fields >> value) return value;
    }
  }
  return -1.0;
}

double ReadNumberFile(const char* path) {
  std::ifstream in(path);
  double value = 0.0;
  if (in >> value) return value;
  return -1.0;  // missing, or "max" (no limit)
}

}  // namespace

FilmMeshSizes FilmMeshSizesOf(const EngineCase& c) {
  FilmMeshSizes m;
  const SkirtCase& s = c.skirt;
  const long axial_lines = s.mesh_axial + 1L;
  m.skirt_surface_nodes = (long(s.mesh_thrust) + s.mesh_relief + s.mesh_anti + 1) * axial_lines;
  m.skirt_unknowns = (long(s.mesh_thrust) + 1 + s.mesh_anti + 1) * axial_lines;
  const BigEndCase& b = c.big_end;
  m.big_end_surface_nodes = long(b.mesh_theta) * (b.mesh_z + 1);
  const long solved_rows = BigEndSolvesSymmetricHalf(b) ? b.mesh_z / 2 + 1 : b.mesh_z + 1;
  m.big_end_unknowns = long(b.mesh_theta) * solved_rows;
  return m;
}

void CheckFilmMeshSizes(const EngineCase& c) {
  const FilmMeshSizes m = FilmMeshSizesOf(c);
  const std::string allowed = fmt::format(
      "at most {} pressure unknowns per joint (a sparse factor of about {}); "
      "docs/reliability.md",
      kMaxFilmUnknowns, Gigabytes(SystemBytes(double(kMaxFilmUnknowns))));
  const auto refuse = [&allowed](const MeshText& mesh, long unknowns) {
    throw InputError(mesh.field, fmt::format("{}: {} unknowns", mesh.value, unknowns), allowed);
  };
  if (m.skirt_unknowns > kMaxFilmUnknowns) refuse(SkirtMeshText(c.skirt), m.skirt_unknowns);
  if (m.big_end_unknowns > kMaxFilmUnknowns) refuse(BigEndMeshText(c.big_end), m.big_end_unknowns);
}

std::string MemoryEstimate::Describe() const {
  std::string parts = "film solvers " + Gigabytes(solver_bytes);
  if (field_bytes > 0) parts += ", one cycle of film fields " + Gigabytes(field_bytes);
  if (companion_bytes > 0) parts += ", error-estimate companion " + Gigabytes(companion_bytes);
  parts += ", output samples " + Gigabytes(sample_bytes);
  parts += ", program " + Gigabytes(base_bytes);
  return "about " + Gigabytes(total()) + " (" + parts + ")";
}

MemoryEstimate EstimateRunMemory(const EngineCase& c, double field_copies) {
  MemoryEstimate e;
  e.base_bytes = kBaseBytes;
  e.solver_bytes = SolverBytes(c);
  const Films films = FilmsOf(c);
  const FilmMeshSizes m = FilmMeshSizesOf(c);
  const double surface_nodes = (films.skirt ? double(m.skirt_surface_nodes) : 0.0) +
                               (films.big_end ? double(m.big_end_surface_nodes) : 0.0);
  const double steps = OutputStepsPerCycle(c);
  e.field_bytes = field_copies * steps * surface_nodes * kFieldBytesPerNode;
  // The cycle being computed and the previous one (for the steady-state test), then the result.
  const double samples_bytes = 3.0 * steps * sizeof(CrankTrainSample);
  e.sample_bytes = samples_bytes;
  if ((films.skirt || films.big_end) && c.solver.error_estimate != 0) {
    e.companion_bytes = SolverBytes(MakeCoarseCompanion(c).engine_case) + samples_bytes;
  }
  return e;
}

double AvailableMemoryBytes() {
  double available = std::numeric_limits<double>::infinity();
  if (const double kb = ReadKeyedNumber("/proc/meminfo", "MemAvailable:"); kb >= 0) {
    available = kb * 1024.0;
  }
  // cgroup v2 (containers, Slurm jobs): the limit less what the group already uses.
  const double limit = ReadNumberFile("/sys/fs/cgroup/memory.max");
  const double used = ReadNumberFile("/sys/fs/cgroup/memory.current");
  if (limit > 0 && used >= 0) available = std::min(available, std::max(0.0, limit - used));
  return available;
}

void RequireMemory(const EngineCase& c, const MemoryEstimate& estimate, double available) {
  if (!(estimate.total() > available)) return;
  const FilmMeshSizes m = FilmMeshSizesOf(c);
  const Films films = FilmsOf(c);
  MeshText named{"solver.output_interval", FormatValue(c.solver.output_interval)};
  if (films.skirt && (!films.big_end || m.skirt_unknowns >= m.big_end_unknowns)) {
    named = SkirtMeshText(c.skirt);
  } else if (films.big_end) {
    named = BigEndMeshText(c.big_end);
  }
  throw InputError(named.field, named.value,
                   "the run needs " + estimate.Describe() + " of memory, " + Gigabytes(available) +
                       " are available: use coarser meshes, fewer output steps, no fields "
                       "(--no-fields) or no error estimate (solver.error_estimate = 0)");
}

}  // namespace filmdyn::engine
