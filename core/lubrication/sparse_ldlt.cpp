#include "core/lubrication/sparse_ldlt.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>

namespace filmdyn::lubrication {

const char* ToString(LdltBackend backend) {
  switch (backend) {
    case LdltBackend::kEigenSimplicial:
      return "eigen-simplicial-ldlt";
    case LdltBackend::kCholmodSimplicial:
      return "cholmod-simplicial-ldlt";
  }
  return "?";
}

namespace {

template <class Solver>
class LdltImpl final : public SparseLdlt {
 public:
  void Analyze(const Eigen::SparseMatrix<double>& lower) override { solver_.analyzePattern(lower); }
  bool Factorize(const Eigen::SparseMatrix<double>& lower) override {
    solver_.factorize(lower);
    return solver_.info() == Eigen::Success;
  }
  void Solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override { x = solver_.solve(b); }

 private:
  Solver solver_;
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
  }
  return nullptr;
}

}  // namespace filmdyn::lubrication
