#pragma once
/// @file Sparse LDL^T with the pattern analysed once and numeric refactorisation per solve,
/// behind one interface so the backends can be measured against each other
/// (docs/performance.md).
#include <Eigen/Sparse>
#include <memory>
#include <vector>

#include "core/base/stop.hpp"

namespace filmdyn::lubrication {

enum class LdltBackend {
  kEigenSimplicial,    ///< Eigen::SimplicialLDLT with AMD ordering
  kCholmodSimplicial,  ///< CHOLMOD simplicial LDL^T (via Eigen's CholmodSupport), AMD/METIS
  /// CHOLMOD simplicial LDL^T called directly, with row/column deletion and addition
  /// (cholmod_rowdel / cholmod_rowadd, Davis & Hager 2005) so that an active-set change of a
  /// few nodes modifies the factor instead of refactorising it.
  kCholmodModify,
};
const char* ToString(LdltBackend backend);

/// Symmetric matrices given by their lower triangle (column-major, compressed).
class SparseLdlt {
 public:
  virtual ~SparseLdlt() = default;
  /// Ordering + symbolic factorisation. Call once per pattern.
  virtual void Analyze(const Eigen::SparseMatrix<double>& lower) = 0;
  /// Numeric factorisation of a matrix with the analysed pattern. False on breakdown.
  /// `stop` is consulted between blocks of rows of a large factor (kCholmodModify only; the
  /// others factorise in one call): a stop request throws StopRequested and leaves no usable
  /// factor, so the next call factorises afresh.
  virtual bool Factorize(const Eigen::SparseMatrix<double>& lower, const StopCheck& stop = {}) = 0;
  /// x = A^-1 b with the last factorisation (x may alias nothing).
  virtual void Solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) = 0;
  /// Row/column modifications of the current factor (only when SupportsRowModify()).
  /// DeleteRow(k): row and column k of the factored matrix become those of the identity.
  /// AddRow(k, rows, values): row/column k (currently identity) becomes the given column of the
  /// symmetric matrix (rows in original numbering, including the diagonal k).
  virtual bool SupportsRowModify() const { return false; }
  virtual bool DeleteRow(int /*k*/) { return false; }
  virtual bool AddRow(int /*k*/, const std::vector<int>& /*rows*/,
                      const std::vector<double>& /*values*/) {
    return false;
  }
  static std::unique_ptr<SparseLdlt> Create(LdltBackend backend);
};

}  // namespace filmdyn::lubrication
