#pragma once
/// @file Sparse LDL^T with the pattern analysed once and numeric refactorisation per solve,
/// behind one interface so the backends can be measured against each other (stack-notes.md).
#include <Eigen/Sparse>
#include <memory>

namespace filmdyn::lubrication {

enum class LdltBackend {
  kEigenSimplicial,    ///< Eigen::SimplicialLDLT with AMD ordering
  kCholmodSimplicial,  ///< CHOLMOD simplicial LDL^T (via Eigen's CholmodSupport), AMD/METIS
};
const char* ToString(LdltBackend backend);

/// Symmetric matrices given by their lower triangle (column-major, compressed).
class SparseLdlt {
 public:
  virtual ~SparseLdlt() = default;
  /// Ordering + symbolic factorisation. Call once per pattern.
  virtual void Analyze(const Eigen::SparseMatrix<double>& lower) = 0;
  /// Numeric factorisation of a matrix with the analysed pattern. False on breakdown.
  virtual bool Factorize(const Eigen::SparseMatrix<double>& lower) = 0;
  /// x = A^-1 b with the last factorisation (x may alias nothing).
  virtual void Solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) = 0;
  static std::unique_ptr<SparseLdlt> Create(LdltBackend backend);
};

}  // namespace filmdyn::lubrication
