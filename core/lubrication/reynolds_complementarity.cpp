// Swift–Stieber cavitation as an exact complementarity problem (p ≥ 0, w ≥ 0, p·w = 0): the active-
// set iteration with factor row updates.
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

bool ReynoldsFem::SolveReynoldsLcp(bool unconstrained) {
  const int n = NodeCount();
  const double* kv = k_lower_.valuePtr();
  double* wv = work_lower_.valuePtr();
  const int nnz = static_cast<int>(k_lower_.nonZeros());
  // Right-hand side with the prescribed pressures moved over (symmetric elimination).
  Eigen::VectorXd& base = sol_.residual;  // temporary storage until the end of the solve
  base = f_;
  for (int p = 0; p < nnz; ++p) {
    const int r = nz_row_[p], c = nz_col_[p];
    if (r == c) continue;
    if (fixed_[c] && !fixed_[r]) base[r] -= kv[p] * p_fixed_[c];
    if (fixed_[r] && !fixed_[c]) base[c] -= kv[p] * p_fixed_[r];
  }
  // Diagonal entries sit first in each lower-triangular column (row >= col, sorted).
  const int* outer = k_lower_.outerIndexPtr();
  for (int k = 0; k < n; ++k)
    if (fixed_[k]) base[k] = kv[outer[k]] * p_fixed_[k];

  if (unconstrained) {
    std::fill(active_.begin(), active_.end(), 0);
  } else if (options_.warm_start && have_prev_) {
    active_ = prev_active_;
  } else {
    // Cold start: nodes with a net sink (f_k < 0, e.g. a diverging wedge) start cavitated.
    const bool sinks = options_.cold_start == ReynoldsOptions::ColdStart::kSinkNodes;
    for (int k = 0; k < n; ++k) active_[k] = sinks && f_[k] < 0.0;
  }
  for (int k = 0; k < n; ++k)
    if (fixed_[k]) active_[k] = 0;

  ReynoldsStats& st = sol_.stats;
  Eigen::VectorXd& p = sol_.pressure;
  bool converged = false;
  auto update_cut = [&] {
    for (int k = 0; k < n; ++k) cut_[k] = fixed_[k] ? 2 : (active_[k] ? 1 : 0);
  };
  update_cut();
  // The previous factor preconditions CG while its masked set is the current one; `exact` =
  // the factor is that of the current matrix (after a factorisation in this solve).
  bool refactorize = !(options_.reuse_factorization && factor_ready_ && factor_cut_ == cut_);
  bool exact = false;
  // CG starts from the pressure in p: the previous solve's (the state moved little), in later
  // iterations the last iterate.
  const bool have_guess = have_prev_;
  // Few changes: modify the factor row by row (CHOLMOD rowdel/rowadd) instead of refactorising.
  const bool modify = ldlt_->SupportsRowModify();
  const int modify_limit = std::max(16, n / 25);
  while (st.iterations < options_.max_iterations) {
    ThrowIfStopRequested(stop_check_);
    auto t0 = Clock::now();
    if (refactorize) {
      for (int q = 0; q < nnz; ++q) {
        const int r = nz_row_[q], c = nz_col_[q];
        const bool cut = fixed_[r] || fixed_[c] || active_[r] || active_[c];
        wv[q] = (r == c || !cut) ? kv[q] : 0.0;
      }
    }
    for (int k = 0; k < n; ++k) rhs_[k] = active_[k] ? 0.0 : base[k];
    auto t1 = Clock::now();
    st.complementarity_s += Seconds(t0, t1);
    if (refactorize) {
      factor_ready_ = false;  // a stop inside the factorisation leaves no usable factor
      const bool ok = ldlt_->Factorize(work_lower_, stop_check_);
      ++st.factorizations;
      factor_ready_ = ok;
      if (!ok) {
        st.status = SolveStatus::kFactorizationFailed;
        return false;
      }
      update_cut();  // the active set may have been swapped in without a row update
      factor_cut_ = cut_;
      exact = true;
    }
    auto t2 = Clock::now();
    st.factorization_s += Seconds(t1, t2);
    if (exact) {
      ldlt_->Solve(rhs_, p);
    } else if (!SolvePcg(p, have_guess)) {
      ++st.pcg_fallbacks;
      st.complementarity_s += Seconds(t2, Clock::now());
      refactorize = true;
      continue;
    }
    ++st.iterations;
    for (int k = 0; k < n; ++k) {
      if (active_[k]) p[k] = 0.0;
      if (fixed_[k]) p[k] = p_fixed_[k];
    }
    if (unconstrained) {
      converged = true;
      st.complementarity_s += Seconds(t2, Clock::now());
      break;
    }
    // Multiplier w = K p - f and the primal-dual active-set update (HIK 2003, Alg. 1):
    // A+ = { k : w_k - c p_k > 0 }, i.e. active nodes stay while w_k > 0, free nodes enter
    // when p_k < 0. Relative round-off tolerances keep the update from cycling at p ~ 0.
    work_.noalias() = k_lower_.selfadjointView<Eigen::Lower>() * p;
    work_ -= f_;
    // Round-off of the solve: ~1e-14 relative when exact, the CG tolerance otherwise.
    const double rel_tol = exact ? 1e-12 : std::max(1e-12, 10.0 * options_.pcg_tolerance);
    const double p_tol = rel_tol * std::max(p.cwiseAbs().maxCoeff(), 1e-300);
    const double w_tol = rel_tol * flow_scale_;
    int changes = 0;
    for (int k = 0; k < n; ++k) {
      if (fixed_[k]) {
        next_active_[k] = 0;
        continue;
      }
      next_active_[k] = active_[k] ? (work_[k] > -w_tol) : (p[k] < -p_tol);
      changes += next_active_[k] != active_[k];
    }
    auto t3 = Clock::now();
    st.complementarity_s += Seconds(t2, t3);
    if (changes == 0) {
      converged = true;
      break;
    }
    refactorize = !(modify && changes <= modify_limit);
    if (refactorize) {
      std::swap(active_, next_active_);
      continue;
    }
    // Deletions first (rows become identity), then additions against the current free set.
    // A stop request is seen every 256 row updates; the half-modified factor is then dropped.
    const auto stop_between_rows = [&] {
      if ((st.row_updates & 255) == 255 && stop_check_ && stop_check_()) {
        factor_ready_ = false;
        throw StopRequested();
      }
    };
    bool ok = true;
    for (int k = 0; k < n && ok; ++k) {
      if (next_active_[k] && !active_[k]) {
        stop_between_rows();
        ok = ldlt_->DeleteRow(k);
        active_[k] = 1;
        ++st.row_updates;
      }
    }
    const double* kf = k_full_.valuePtr();
    const int* kin = k_full_.innerIndexPtr();
    for (int k = 0; k < n && ok; ++k) {
      if (!next_active_[k] && active_[k]) {
        active_[k] = 0;
        add_rows_.clear();
        add_values_.clear();
        for (int q = k_full_.outerIndexPtr()[k]; q < k_full_.outerIndexPtr()[k + 1]; ++q) {
          const int r = kin[q];
          if (r == k || (!fixed_[r] && !active_[r])) {
            add_rows_.push_back(r);
            add_values_.push_back(kf[q]);
          }
        }
        stop_between_rows();
        ok = ldlt_->AddRow(k, add_rows_, add_values_);
        ++st.row_updates;
      }
    }
    st.factorization_s += Seconds(t3, Clock::now());
    for (int k = 0; k < n; ++k) active_[k] = next_active_[k];
    update_cut();
    factor_cut_ = cut_;  // the modified factor's set (exact stays as it was)
    if (!ok) {           // fall back to a full refactorisation of the new set
      refactorize = true;
      factor_ready_ = false;
    }
  }
  if (!converged) st.status = SolveStatus::kNotConverged;
  prev_active_ = active_;
  have_prev_ = true;
  return converged;
}

}  // namespace filmdyn::lubrication
