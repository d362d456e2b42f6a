#include "core/lubrication/sparse_lu.hpp"

#include <klu.h>

#include <stdexcept>

namespace filmdyn::lubrication {

struct SparseLu::Impl {
  klu_common common{};
  klu_symbolic* symbolic = nullptr;
  klu_numeric* numeric = nullptr;
  int n = 0;

  Impl() { klu_defaults(&common); }
  ~Impl() {
    if (numeric) klu_free_numeric(&numeric, &common);
    if (symbolic) klu_free_symbolic(&symbolic, &common);
  }
};

SparseLu::SparseLu() : impl_(std::make_unique<Impl>()) {}
SparseLu::~SparseLu() = default;

void SparseLu::Analyze(const Eigen::SparseMatrix<double>& m) {
  if (!m.isCompressed() || m.rows() != m.cols())
    throw std::logic_error("SparseLu::Analyze: a square compressed matrix is required");
  Impl& k = *impl_;
  if (k.numeric) klu_free_numeric(&k.numeric, &k.common);
  if (k.symbolic) klu_free_symbolic(&k.symbolic, &k.common);
  k.n = static_cast<int>(m.rows());
  // KLU takes non-const pointers but does not write through them.
  k.symbolic = klu_analyze(k.n, const_cast<int*>(m.outerIndexPtr()),
                           const_cast<int*>(m.innerIndexPtr()), &k.common);
  if (!k.symbolic) throw std::runtime_error("SparseLu::Analyze: KLU could not order the pattern");
}

bool SparseLu::Factorize(const Eigen::SparseMatrix<double>& m) {
  Impl& k = *impl_;
  if (!k.symbolic) throw std::logic_error("SparseLu::Factorize before Analyze");
  int* ap = const_cast<int*>(m.outerIndexPtr());
  int* ai = const_cast<int*>(m.innerIndexPtr());
  double* ax = const_cast<double*>(m.valuePtr());
  if (k.numeric) {
    if (klu_refactor(ap, ai, ax, k.symbolic, k.numeric, &k.common) &&
        klu_rcond(k.symbolic, k.numeric, &k.common) && k.common.rcond > 1e-12) {
      ++refactorizations_;
      return true;
    }
    klu_free_numeric(&k.numeric, &k.common);
  }
  k.numeric = klu_factor(ap, ai, ax, k.symbolic, &k.common);
  ++factorizations_;
  return k.numeric != nullptr && k.common.status == KLU_OK;
}

void SparseLu::Solve(Eigen::VectorXd& b) {
  Impl& k = *impl_;
  if (!k.numeric) throw std::logic_error("SparseLu::Solve without a factorisation");
  klu_solve(k.symbolic, k.numeric, k.n, 1, b.data(), &k.common);
}

}  // namespace filmdyn::lubrication
