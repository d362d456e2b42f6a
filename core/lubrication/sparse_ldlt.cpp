#include "core/lubrication/sparse_ldlt.hpp"

#include <cholmod.h>
#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <memory>
#include <utility>
#include <vector>

namespace filmdyn::lubrication {

const char* ToString(LdltBackend backend) {
  switch (backend) {
    case LdltBackend::kEigenSimplicial:
      return "eigen-simplicial-ldlt";
    case LdltBackend::kCholmodSimplicial:
      return "cholmod-simplicial-ldlt";
    case LdltBackend::kCholmodModify:
      return "cholmod-ldlt-rowmod";
  }
  return "?";
}

namespace {

template <class Solver>
class LdltImpl final : public SparseLdlt {
 public:
  void Analyze(const Eigen::SparseMatrix<double>& lower) override { solver_.analyzePattern(lower); }
  bool Factorize(const Eigen::SparseMatrix<double>& lower, const StopCheck& /*stop*/) override {
    solver_.factorize(lower);
    return solver_.info() == Eigen::Success;
  }
  void Solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override { x = solver_.solve(b); }

 private:
  Solver solver_;
};

// Direct CHOLMOD (int API) simplicial LDL^T. Row modifications work on the factor of P A P^T,
// so indices are mapped through the fill-reducing permutation L->Perm.
class CholmodModifyLdlt final : public SparseLdlt {
 public:
  static constexpr std::size_t kRowsInOneCall = 20000;  // smaller factors: one cholmod_rowfac

  CholmodModifyLdlt() {
    cholmod_start(&common_);
    common_.supernodal = CHOLMOD_SIMPLICIAL;
    common_.final_ll = 0;  // keep LDL^T: required by rowadd/rowdel
  }
  ~CholmodModifyLdlt() override {
    if (factor_) cholmod_free_factor(&factor_, &common_);
    if (column_) cholmod_free_sparse(&column_, &common_);
    if (x_) cholmod_free_dense(&x_, &common_);
    if (y_) cholmod_free_dense(&y_, &common_);
    if (e_) cholmod_free_dense(&e_, &common_);
    cholmod_finish(&common_);
  }
  CholmodModifyLdlt(const CholmodModifyLdlt&) = delete;
  CholmodModifyLdlt& operator=(const CholmodModifyLdlt&) = delete;

  void Analyze(const Eigen::SparseMatrix<double>& lower) override {
    cholmod_sparse a = View(lower);
    if (factor_) cholmod_free_factor(&factor_, &common_);
    factor_ = cholmod_analyze(&a, &common_);
    const int n = static_cast<int>(lower.rows());
    inverse_perm_.resize(n);
    const int* perm = static_cast<const int*>(factor_->Perm);
    for (int i = 0; i < n; ++i) inverse_perm_[perm[i]] = i;
    if (column_) cholmod_free_sparse(&column_, &common_);
    column_ = cholmod_allocate_sparse(n, 1, n, 1, 1, 0, CHOLMOD_REAL, &common_);
  }
  // What cholmod_factorize does for a simplicial LDL^T of a lower-stored matrix (S = triu(P A
  // P^T), then cholmod_rowfac over all rows), with the rows in blocks so that a stop request is
  // seen between them: one factorisation of a mesh of 10^5-10^6 nodes takes seconds.
  bool Factorize(const Eigen::SparseMatrix<double>& lower, const StopCheck& stop) override {
    cholmod_sparse a = View(lower);
    const auto n = static_cast<std::size_t>(lower.rows());
    // S = triu(P A P^T), freed and CHOLMOD's growth setting restored however this ends.
    const auto free_sparse = [this](cholmod_sparse* m) { cholmod_free_sparse(&m, &common_); };
    const std::unique_ptr<cholmod_sparse, decltype(free_sparse)> s(
        cholmod_ptranspose(&a, 2, static_cast<int*>(factor_->Perm), nullptr, 0, &common_),
        free_sparse);
    if (!s) return false;
    struct RestoreGrow2 {
      cholmod_common& common;
      const std::size_t value;
      ~RestoreGrow2() { common.grow2 = value; }
    } restore_grow2{common_, common_.grow2};
    if (factor_->xtype == CHOLMOD_PATTERN && common_.final_pack) common_.grow2 = 0;
    factor_->is_ll = 0;
    if (factor_->xtype != CHOLMOD_PATTERN) {
      // A refactorisation by blocks: cholmod_rowfac resets the column counts and the failed
      // pivot itself only when called for all rows at once, so do it here (the rows are then
      // computed afresh, also after a factorisation a stop request left half done).
      factor_->minor = n;
      int* column_counts = static_cast<int*>(factor_->nz);
      std::fill(column_counts, column_counts + n, 1);
    }
    double beta[2] = {0.0, 0.0};
    // Blocks of rows: later rows of a nested-dissection ordering cost more, so 64 blocks keep
    // each well under the stop latency for the largest meshes the case accepts.
    const std::size_t block = stop && n > kRowsInOneCall ? (n + 63) / 64 : n;
    bool ok = true;
    for (std::size_t k0 = 0; ok && k0 < n; k0 += block) {
      if (k0 > 0) ThrowIfStopRequested(stop);
      ok = cholmod_rowfac(s.get(), nullptr, beta, k0, std::min(n, k0 + block), factor_, &common_) &&
           common_.status == CHOLMOD_OK;
    }
    return ok;
  }
  void Solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    cholmod_dense bd;
    bd.nrow = b.size();
    bd.ncol = 1;
    bd.nzmax = b.size();
    bd.d = b.size();
    bd.x = const_cast<double*>(b.data());
    bd.z = nullptr;
    bd.xtype = CHOLMOD_REAL;
    bd.dtype = CHOLMOD_DOUBLE;
    // cholmod_solve2 keeps its result and workspace between calls (no allocation per solve;
    // the CG path of ReynoldsFem calls this several times per Reynolds solve).
    cholmod_solve2(CHOLMOD_A, factor_, &bd, nullptr, &x_, nullptr, &y_, &e_, &common_);
    x = Eigen::Map<Eigen::VectorXd>(static_cast<double*>(x_->x), b.size());
  }
  bool SupportsRowModify() const override { return true; }
  bool DeleteRow(int k) override {
    return cholmod_rowdel(inverse_perm_[k], nullptr, factor_, &common_) != 0;
  }
  bool AddRow(int k, const std::vector<int>& rows, const std::vector<double>& values) override {
    // Column k of P A P^T: rows mapped through the permutation, sorted.
    entries_.clear();
    for (size_t q = 0; q < rows.size(); ++q)
      entries_.emplace_back(inverse_perm_[rows[q]], values[q]);
    std::sort(entries_.begin(), entries_.end());
    int* cp = static_cast<int*>(column_->p);
    int* ci = static_cast<int*>(column_->i);
    double* cx = static_cast<double*>(column_->x);
    cp[0] = 0;
    cp[1] = static_cast<int>(entries_.size());
    for (size_t q = 0; q < entries_.size(); ++q) {
      ci[q] = entries_[q].first;
      cx[q] = entries_[q].second;
    }
    return cholmod_rowadd(inverse_perm_[k], column_, factor_, &common_) != 0;
  }

 private:
  static cholmod_sparse View(const Eigen::SparseMatrix<double>& m) {
    cholmod_sparse a;
    a.nrow = m.rows();
    a.ncol = m.cols();
    a.nzmax = m.nonZeros();
    a.p = const_cast<int*>(m.outerIndexPtr());
    a.i = const_cast<int*>(m.innerIndexPtr());
    a.x = const_cast<double*>(m.valuePtr());
    a.z = nullptr;
    a.nz = nullptr;
    a.stype = -1;  // lower triangle stored
    a.itype = CHOLMOD_INT;
    a.xtype = CHOLMOD_REAL;
    a.dtype = CHOLMOD_DOUBLE;
    a.sorted = 1;
    a.packed = 1;
    return a;
  }
  cholmod_common common_;
  cholmod_factor* factor_ = nullptr;
  cholmod_sparse* column_ = nullptr;
  cholmod_dense *x_ = nullptr, *y_ = nullptr, *e_ = nullptr;  // cholmod_solve2 workspace
  std::vector<int> inverse_perm_;
  std::vector<std::pair<int, double>> entries_;
};

}  // namespace

std::unique_ptr<SparseLdlt> SparseLdlt::Create(LdltBackend backend) {
  using Mat = Eigen::SparseMatrix<double>;
  switch (backend) {
    case LdltBackend::kEigenSimplicial:
      return std::make_unique<
          LdltImpl<Eigen::SimplicialLDLT<Mat, Eigen::Lower, Eigen::AMDOrdering<int>>>>();
    case LdltBackend::kCholmodSimplicial:
      return std::make_unique<LdltImpl<Eigen::CholmodSimplicialLDLT<Mat, Eigen::Lower>>>();
    case LdltBackend::kCholmodModify:
      return std::make_unique<CholmodModifyLdlt>();
  }
  return nullptr;
}

}  // namespace filmdyn::lubrication
