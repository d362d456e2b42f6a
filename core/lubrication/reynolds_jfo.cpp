// Mass-conserving (JFO / Elrod–Adams) cavitation: the complementarity formulation in pressure and
// void fraction.
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

bool ReynoldsFem::SolveJfo() {
  const int n = NodeCount();
  ReynoldsStats& st = sol_.stats;
  auto t_start = Clock::now();
  // Start from the Swift-Stieber active set (a good approximation of the cavitated zone).
  if (!SolveReynoldsLcp(false) && st.status == SolveStatus::kFactorizationFailed) return false;
  st.status = SolveStatus::kConverged;
  std::vector<std::uint8_t>& cav = active_;  // cavitated set, updated in place
  Eigen::VectorXd base = f_;                 // same symmetric elimination of prescribed pressures
  const double* kf = k_full_.valuePtr();
  for (int c = 0; c < n; ++c) {
    for (int q = k_full_.outerIndexPtr()[c]; q < k_full_.outerIndexPtr()[c + 1]; ++q) {
      const int r = k_full_.innerIndexPtr()[q];
      if (r != c && fixed_[c] && !fixed_[r]) base[r] -= kf[q] * p_fixed_[c];
    }
  }
  for (int k = 0; k < n; ++k)
    if (fixed_[k]) base[k] = kf[diag_pos_full_[k]] * p_fixed_[k];
  // Void transport coefficients: B_kk = -(|U|/2) h_k w_k - A_k phi_c dh/dt,
  // B_dk = +(|U|/2) h_k w_k (d = downstream neighbour of k).
  Eigen::VectorXd bdiag(n), boff(n);
  std::vector<int> bpos(n), bnode(n);
  for (int k = 0; k < n; ++k) {
    const double a = 0.5 * std::abs(u_sum_) * h_[k] * face_width_[k];
    bdiag[k] = -a - lumped_area_[k] * phi_c_[k] * dhdt_[k];
    if (std::abs(bdiag[k]) < 1e-14 * flow_scale_) bdiag[k] = -kf[diag_pos_full_[k]];  // r idle
    boff[k] = a;
    const bool plus = u_sum_ >= 0.0;
    bnode[k] = plus ? down_node_plus_[k] : down_node_minus_[k];
    bpos[k] = plus ? down_pos_plus_[k] : down_pos_minus_[k];
  }
  if (!lu_) lu_ = std::make_unique<Eigen::SparseLU<Eigen::SparseMatrix<double>>>();
  if (!lu_analyzed_) {
    lu_->analyzePattern(k_full_);
    lu_analyzed_ = true;
  }
  double* mv = m_full_.valuePtr();
  const int* inner = k_full_.innerIndexPtr();
  Eigen::VectorXd& p = sol_.pressure;
  Eigen::VectorXd r = Eigen::VectorXd::Zero(n);
  bool converged = false;
  st.complementarity_s += Seconds(t_start, Clock::now()) - 0.0;
  while (st.iterations < options_.max_iterations) {
    ThrowIfStopRequested(stop_check_);
    auto t0 = Clock::now();
    for (int c = 0; c < n; ++c) {
      const int begin = k_full_.outerIndexPtr()[c], end = k_full_.outerIndexPtr()[c + 1];
      for (int q = begin; q < end; ++q) {
        const int row = inner[q];
        double v;
        if (fixed_[row])
          v = (row == c) ? kf[q] : 0.0;  // prescribed-pressure row: identity
        else if (fixed_[c])
          v = 0.0;
        else if (cav[c])
          v = (q == diag_pos_full_[c]) ? bdiag[c] : (q == bpos[c] ? boff[c] : 0.0);
        else
          v = kf[q];
        mv[q] = v;
      }
    }
    auto t1 = Clock::now();
    st.complementarity_s += Seconds(t0, t1);
    lu_->factorize(m_full_);
    auto t2 = Clock::now();
    st.factorization_s += Seconds(t1, t2);
    ++st.iterations;
    ++st.jfo_iterations;
    if (lu_->info() != Eigen::Success) {
      st.status = SolveStatus::kFactorizationFailed;
      return false;
    }
    x_ = lu_->solve(base);
    const double p_tol = 1e-12 * std::max(x_.cwiseAbs().maxCoeff(), 1e-300);
    bool changed = false;
    for (int k = 0; k < n; ++k) {
      if (fixed_[k]) {
        p[k] = p_fixed_[k];
        r[k] = 0.0;
        continue;
      }
      p[k] = cav[k] ? 0.0 : x_[k];
      r[k] = cav[k] ? x_[k] : 0.0;
      const bool next = cav[k] ? (r[k] > -1e-12) : (p[k] < -p_tol);
      changed |= next != static_cast<bool>(cav[k]);
      next_active_[k] = next;
    }
    std::swap(cav, next_active_);
    st.complementarity_s += Seconds(t2, Clock::now());
    if (!changed) {
      converged = true;
      break;
    }
  }
  if (!converged) st.status = SolveStatus::kNotConverged;
  for (int k = 0; k < n; ++k) {
    if (!cav[k]) r[k] = 0.0;
    if (cav[k]) p[k] = 0.0;
  }
  // Mass balance w = K p - f + B r at every node (fixed nodes: minus the boundary outflow).
  work_.noalias() = k_lower_.selfadjointView<Eigen::Lower>() * p;
  work_ -= f_;
  for (int k = 0; k < n; ++k) {
    if (!cav[k] || fixed_[k]) continue;
    const double a = 0.5 * std::abs(u_sum_) * h_[k] * face_width_[k];
    work_[k] += (-a - lumped_area_[k] * phi_c_[k] * dhdt_[k]) * r[k];
    if (bnode[k] >= 0) work_[bnode[k]] += a * r[k];
  }
  double mass = 0.0;
  for (int k = 0; k < n; ++k)
    if (!fixed_[k]) mass = std::max(mass, std::abs(work_[k]));
  st.max_mass_residual = mass / flow_scale_;
  sol_.fluid_fraction = Eigen::VectorXd::Ones(n) - r;
  prev_active_ = cav;
  return converged;
}

}  // namespace filmdyn::lubrication
