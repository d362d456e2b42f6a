#pragma once
/// @file Sparse LU of one non-symmetric pattern, factorised many times: KLU (Davis & Palamadai
/// Natarajan 2010, SuiteSparse), ordered once per pattern, refactorised with the previous pivot
/// sequence when that stays well conditioned. Used by the mass-conserving cavitation solve, whose
/// matrix changes column by column with the cavitated set.
#include <Eigen/Sparse>
#include <memory>

namespace filmdyn::lubrication {

class SparseLu {
 public:
  SparseLu();
  ~SparseLu();
  SparseLu(const SparseLu&) = delete;
  SparseLu& operator=(const SparseLu&) = delete;

  /// Fill-reducing ordering of the pattern (column-major, compressed). Call once per pattern.
  void Analyze(const Eigen::SparseMatrix<double>& m);
  /// Numeric factorisation of a matrix with the analysed pattern: a refactorisation with the
  /// last pivot sequence when there is one and its reciprocal pivot ratio min|u_kk| / max|u_kk|
  /// stays above 1e-12, else a factorisation with partial pivoting. False when singular.
  bool Factorize(const Eigen::SparseMatrix<double>& m);
  /// b := M^-1 b with the last factorisation.
  void Solve(Eigen::VectorXd& b);

  long factorizations() const { return factorizations_; }
  long refactorizations() const { return refactorizations_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  long factorizations_ = 0, refactorizations_ = 0;
};

}  // namespace filmdyn::lubrication
