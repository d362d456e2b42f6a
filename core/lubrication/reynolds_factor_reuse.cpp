// Factor reuse across solves: conjugate gradients on the masked system, preconditioned by the
// previous LDLᵀ factor and warm-started from the previous pressure.
#include "core/lubrication/reynolds_fem.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "core/lubrication/reynolds_internal.hpp"

namespace filmdyn::lubrication {

using reynolds_detail::Clock;
using reynolds_detail::FindPos;
using reynolds_detail::Seconds;

void ReynoldsFem::ApplyMasked(const Eigen::VectorXd& in, Eigen::VectorXd& out) {
  const int n = NodeCount();
  if (full_assembled_) {  // row k of the symmetric K = its column k: one gather pass
    const double* kf = k_full_.valuePtr();
    const int* inner = k_full_.innerIndexPtr();
    const int* outer = k_full_.outerIndexPtr();
    for (int k = 0; k < n; ++k) {
      if (cut_[k]) {
        out[k] = kf[diag_pos_full_[k]] * in[k];
        continue;
      }
      double sum = 0.0;
      for (int q = outer[k]; q < outer[k + 1]; ++q)
        if (!cut_[inner[q]]) sum += kf[q] * in[inner[q]];
      out[k] = sum;
    }
    return;
  }
  pcg_t_ = in;
  for (int k = 0; k < n; ++k)
    if (cut_[k]) pcg_t_[k] = 0.0;
  out.noalias() = k_lower_.selfadjointView<Eigen::Lower>() * pcg_t_;
  const double* kv = k_lower_.valuePtr();
  const int* outer = k_lower_.outerIndexPtr();
  for (int k = 0; k < n; ++k)
    if (cut_[k]) out[k] = kv[outer[k]] * in[k];  // diagonal first in each lower column
}

bool ReynoldsFem::SolvePcg(Eigen::VectorXd& x, bool x_is_guess) {
  // Conjugate gradients on W x = rhs_ (W symmetric positive definite: a Dirichlet-masked
  // stiffness matrix), preconditioned by the LDL^T factor M of a nearby matrix. Start: the
  // given x (the previous iterate / solve, masked), else x0 = M^-1 rhs_.
  ReynoldsStats& st = sol_.stats;
  const int n = NodeCount();
  pcg_q_.resize(n);
  if (x_is_guess) {
    for (int k = 0; k < n; ++k)
      if (cut_[k]) x[k] = cut_[k] == 2 ? p_fixed_[k] : 0.0;
  } else {
    ldlt_->Solve(rhs_, x);
  }
  ApplyMasked(x, pcg_q_);
  pcg_r_ = rhs_ - pcg_q_;
  ldlt_->Solve(pcg_r_, pcg_z_);
  const double tol = options_.pcg_tolerance * std::max(x.cwiseAbs().maxCoeff(), 1e-300);
  if (pcg_z_.cwiseAbs().maxCoeff() <= tol) {
    x += pcg_z_;
    ++st.pcg_solves;
    return true;
  }
  pcg_d_ = pcg_z_;
  double rz = pcg_r_.dot(pcg_z_);
  for (int it = 1; it <= options_.pcg_max_iterations; ++it) {
    ThrowIfStopRequested(stop_check_);
    ApplyMasked(pcg_d_, pcg_q_);
    const double dq = pcg_d_.dot(pcg_q_);
    if (!(dq > 0.0)) return false;  // not SPD in floating point: refactorise
    const double alpha = rz / dq;
    x += alpha * pcg_d_;
    pcg_r_ -= alpha * pcg_q_;
    ldlt_->Solve(pcg_r_, pcg_z_);
    ++st.pcg_iterations;
    if (pcg_z_.cwiseAbs().maxCoeff() <= tol) {
      x += pcg_z_;
      ++st.pcg_solves;
      return true;
    }
    const double rz_next = pcg_r_.dot(pcg_z_);
    pcg_d_ = pcg_z_ + (rz_next / rz) * pcg_d_;
    rz = rz_next;
  }
  return false;
}

}  // namespace filmdyn::lubrication
