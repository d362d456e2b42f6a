// Mass-conserving (JFO / Elrod–Adams) cavitation: the complementarity formulation in pressure and
// void fraction.
#include "core/lubrication/reynolds_fem.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "core/lubrication/reynolds_internal.hpp"
#include "core/lubrication/sparse_lu.hpp"

namespace filmdyn::lubrication {

using reynolds_detail::Clock;
using reynolds_detail::FindPos;
using reynolds_detail::Seconds;

bool ReynoldsFem::SolveJfo() {
  const int n = NodeCount();
  ReynoldsStats& st = sol_.stats;
  auto t_start = Clock::now();
  // Start from the last JFO solve's cavitated set when there is one (the time-stepping case: the
  // zone moved little), else from the Swift-Stieber active set (a good approximation of it).
  if (options_.warm_start && jfo_warm_) {
    active_ = prev_active_;
    for (int k = 0; k < n; ++k)
      if (fixed_[k]) active_[k] = 0;
  } else {
    if (!SolveReynoldsLcp(false) && st.status == SolveStatus::kFactorizationFailed) return false;
    st.status = SolveStatus::kConverged;
  }
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
  // Void transport coefficients: B_kk = -(|U|/2) h_f w_k - A_k s_k, B_dk = +(|U|/2) h_f w_k
  // (d = downstream neighbour of k, h_f the mean gap at their face), where s_k = phi_c dh/dt =
  // dh_T/dt (quasi-static) or c_k / dt (transient: the backward difference of the void
  // content, r c_k against the void's capacity c_k below, its old part moved to `base`). h_T is
  // the mean gap, the oil a full film holds per unit area (h for smooth surfaces and from H = 3
  // on).
  const bool transient = time_step_ > 0.0;
  const double inv_dt = transient ? 1.0 / time_step_ : 0.0;
  // The void's capacity c_k (transient). A cavitated node's void steps with the film's rate,
  // V = V_old + dt dh_T/dt - dt (net oil outflow), dh_T/dt from the integrator's velocities at
  // the new state (as in the full film's squeeze term), while its oil is h_T - V at the new gap.
  // Where dt dh_T/dt overstates the gap's own change since the last accepted state (a step in a
  // violent transient, where the rate and the positions differ by far more than in a smooth
  // step; a quasi-static deformation closing a cavity, which is in no rate) the void can
  // outgrow the gap: the oil would go below zero. So the void fraction r is taken against
  // c_k = max(h_T, X_k), X_k = V_old + dt dh_T/dt the void the step would make with no flow:
  // the node's oil in the step is (1 - r) c_k, never below zero (its upwind inflow is never
  // negative, nor is the pressure flow into a cavity while K's off-diagonals are <= 0), and at
  // r = 0 its equation is the full film's, so the complementarity keeps one equation per node
  // in either state. c_k = h_T wherever X_k fits in the gap, and there the scheme is unchanged;
  // in a cell the step would overfill the fraction changes even where oil flowing in would have
  // kept it in [0, 1]. The void kept is r h_T (at the true gap); the difference r (c_k - h_T), a
  // void no gap holds, is booked in the squeeze rate (capacity_rate_), so the oil account
  // closes to round-off.
  Eigen::VectorXd& capacity = void_capacity_;
  capacity = h_mean_;
  auto no_flow_void = [&](int k) { return void_old_[k] + time_step_ * phi_c_[k] * dhdt_[k]; };
  if (transient)
    for (int k = 0; k < n; ++k)
      if (!fixed_[k]) capacity[k] = std::max(h_mean_[k], no_flow_void(k));
  auto storage = [&](int k) { return transient ? capacity[k] * inv_dt : phi_c_[k] * dhdt_[k]; };
  // The roughness's shear flow carries the upwind fraction too: its void part, soff_k r_k from k
  // to its neighbour along the shear flow (Assemble: shear_face_), adds -soff_k to B_kk and
  // +soff_k to B_sk.
  Eigen::VectorXd bdiag(n), boff(n), r_fixed(n);
  std::vector<int> bpos(n), bnode(n);
  const bool plus = u_sum_ >= 0.0;
  const std::vector<int>& snode = shear_plus_ ? down_node_plus_ : down_node_minus_;
  const std::vector<int>& spos = shear_plus_ ? down_pos_plus_ : down_pos_minus_;
  const Eigen::VectorXd& soff = shear_face_;
  for (int k = 0; k < n; ++k) {
    bnode[k] = plus ? down_node_plus_[k] : down_node_minus_[k];
    bpos[k] = plus ? down_pos_plus_[k] : down_pos_minus_[k];
    // No downstream neighbour (an open end): no Couette flux, as in the full-film assembly.
    const double a = bnode[k] >= 0 ? 0.5 * std::abs(u_sum_) * h_face_[k] * face_width_[k] : 0.0;
    bdiag[k] = -a - soff[k] - lumped_area_[k] * storage(k);
    if (std::abs(bdiag[k]) < 1e-14 * flow_scale_) bdiag[k] = -kf[diag_pos_full_[k]];  // r idle
    boff[k] = a;
    r_fixed[k] = fixed_[k] ? 1.0 - theta_fixed_[k] : 0.0;
  }
  // A compressible full film (transient) stores h_T g(p) more oil at node k (g = rho/rho0 - 1,
  // Compression): the backward difference of that content, A_k h_T,k g(p_k) / dt, is in node k's
  // row (its old part is in the node's old content, V_old, below). A linear law (g = p / beta)
  // adds A_k h_T,k / (beta dt) to the pressure column's diagonal. A nonlinear one is linearised
  // about the last iterate p*, g(p*) + g'(p*) (p - p*): the slope on the diagonal, the known
  // rest on the right-hand side of a full node, and the iterations below go on until the
  // linearisation's error is below kCompressionTolerance (Newton's method on the full nodes;
  // g is increasing and concave, so each linear system keeps the structure of the linear law's).
  Eigen::VectorXd& compress = compress_;
  Eigen::VectorXd& compress_known = compress_known_;
  compress.setZero(n);  // allocated once per solver
  compress_known.setZero(n);
  const Compression& g = compression_;
  const bool compressible = g.compressibility > 0.0;
  const bool nonlinear_density = compressible && g.limit > 0.0;
  constexpr double kCompressionTolerance = 1e-12;  // of g, i.e. of the oil a full gap holds
  Eigen::VectorXd& p_star = compress_about_;
  auto linearise = [&](const Eigen::VectorXd& about) {
    for (int k = 0; k < n; ++k) {
      if (fixed_[k]) continue;
      const double scale = lumped_area_[k] * h_mean_[k] * inv_dt;
      compress[k] = scale * g.Slope(about[k]);
      compress_known[k] = scale * (g.At(about[k]) - g.Slope(about[k]) * about[k]);
    }
  };
  if (nonlinear_density) {
    // About the last solve's pressures (a nearby state's; none: p* = 0, the linear law's slope).
    const Eigen::VectorXd& last = sol_.pressure;
    p_star.setZero(n);
    if (last.size() == n)
      for (int k = 0; k < n; ++k)
        if (std::isfinite(last[k])) p_star[k] = std::max(last[k], 0.0);
    linearise(p_star);
  } else if (compressible) {
    for (int k = 0; k < n; ++k)
      if (!fixed_[k]) compress[k] = lumped_area_[k] * h_mean_[k] * g.compressibility * inv_dt;
  }
  // Second-order transport (ReynoldsOptions::void_transport_order): the fraction carried
  // through the face from k to d is the upwind node's, 1 - r_k, less the limited slope's part
  // over the half gap to the face, c_k = (gap_kd / 2) minmod(s_uk, s_kd), where the slopes come
  // from the last accepted state's void fractions (the history's content over h_T). c_k is
  // known, so the flux a (1 - r_k - c_k) keeps the solve linear in (p, r): its c part is a known
  // flow from k to d, booked on the right-hand side (and in the mass balance below). minmod keeps
  // the face's fraction between the two nodes' (no new extremum). The flows out of and into a
  // fixed node (a supply, whose flow is booked as the supply) and out of a node without an
  // upstream neighbour keep the upwind fraction.
  // The known flow drains one cell, k where c_k < 0 (more oil through the face than k's
  // fraction), d where c_k > 0 (a flow back from d): as the slopes are the last accepted
  // state's, a cell the step empties could still send oil on. So each correction is held to
  // half the oil its drained cell keeps with no flow at all, A_j max(0, h_T - V_old - dt
  // dh_T/dt) / dt (half: a cell is drained through two faces at most): with what the upwind
  // fluxes bring, which is never negative, no cell then sends on more oil than it holds. It
  // acts only where the step's squeeze or a large Courant number leaves a cell little oil.
  Eigen::VectorXd& correction = face_correction_;
  correction.setZero(n);
  if (transient && options_.void_transport_order >= 2) {
    const std::vector<int>& up = plus ? up_node_plus_ : up_node_minus_;
    const std::vector<double>& gap = plus ? down_gap_plus_ : down_gap_minus_;
    Eigen::VectorXd& old = fraction_old_;
    old.resize(n);
    for (int k = 0; k < n; ++k) {
      const double h_t = h_mean_[k];
      old[k] = fixed_[k] ? r_fixed[k] : h_t > 0.0 ? std::clamp(void_old_[k] / h_t, 0.0, 1.0) : 0.0;
    }
    // The oil flow [m^3/s] that would empty each cell within the step, with no flow in or out:
    // its oil with no flow, c - X >= 0, over the step.
    auto drain_limit = [&](int j) {
      return lumped_area_[j] * (capacity[j] - no_flow_void(j)) * inv_dt;
    };
    for (int k = 0; k < n; ++k) {
      const int d = bnode[k], u = up[k];
      if (d < 0 || u < 0 || fixed_[k] || fixed_[d]) continue;
      const double s_up = (old[k] - old[u]) / gap[u], s_down = (old[d] - old[k]) / gap[k];
      if (!(s_up * s_down > 0.0)) continue;
      const double slope = s_up > 0.0 ? std::min(s_up, s_down) : std::max(s_up, s_down);
      double c = 0.5 * gap[k] * slope;
      const double budget = 0.5 * drain_limit(c < 0.0 ? k : d);
      if (boff[k] * std::abs(c) > budget) c = std::copysign(budget / boff[k], c);
      correction[k] = c;
      base[k] += boff[k] * correction[k];
      base[d] -= boff[k] * correction[k];
    }
  }
  // Known void terms: the old void content of every free node (transient), and the void a
  // starved fixed node sends downstream with its Couette flow.
  for (int k = 0; k < n; ++k) {
    if (transient && !fixed_[k]) base[k] -= lumped_area_[k] * void_old_[k] * inv_dt;
    if (fixed_[k] && r_fixed[k] != 0.0 && bnode[k] >= 0 && !fixed_[bnode[k]])
      base[bnode[k]] -= boff[k] * r_fixed[k];
    if (fixed_[k] && r_fixed[k] != 0.0 && snode[k] >= 0 && !fixed_[snode[k]])
      base[snode[k]] -= soff[k] * r_fixed[k];
  }
  if (!lu_) {
    lu_ = std::make_unique<SparseLu>();
    lu_->Analyze(k_full_);
  }
  // A void column is scaled so that its diagonal has the size of the pressure column it
  // replaces (r_k = scale_k x_k): the columns then stay diagonally dominant whichever nodes are
  // cavitated, so the pivot sequence of an earlier factorisation remains a stable one.
  Eigen::VectorXd void_scale(n);
  for (int k = 0; k < n; ++k) void_scale[k] = kf[diag_pos_full_[k]] / std::abs(bdiag[k]);
  double* mv = m_full_.valuePtr();
  const int* inner = k_full_.innerIndexPtr();
  Eigen::VectorXd& p = sol_.pressure;
  Eigen::VectorXd r = Eigen::VectorXd::Zero(n);
  bool converged = false;
  st.complementarity_s += Seconds(t_start, Clock::now()) - 0.0;
  for (int iteration = 0; iteration < options_.max_iterations; ++iteration) {
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
          v = void_scale[c] * ((q == diag_pos_full_[c]) ? bdiag[c]
                                                        : (q == bpos[c] ? boff[c] : 0.0) +
                                                              (q == spos[c] ? soff[c] : 0.0));
        else
          v = q == diag_pos_full_[c] ? kf[q] + compress[c] : kf[q];
        mv[q] = v;
      }
    }
    auto t1 = Clock::now();
    st.complementarity_s += Seconds(t0, t1);
    const bool factored = lu_->Factorize(m_full_);
    auto t2 = Clock::now();
    st.factorization_s += Seconds(t1, t2);
    ++st.iterations;
    ++st.jfo_iterations;
    if (!factored) {
      st.status = SolveStatus::kFactorizationFailed;
      return false;
    }
    x_ = base;
    if (nonlinear_density)
      for (int k = 0; k < n; ++k)
        if (!fixed_[k] && !cav[k]) x_[k] -= compress_known[k];
    lu_->Solve(x_);
    double p_max = 0.0;
    for (int k = 0; k < n; ++k)
      if (!cav[k]) p_max = std::max(p_max, std::abs(x_[k]));
    const double p_tol = 1e-12 * std::max(p_max, 1e-300);
    bool changed = false;
    for (int k = 0; k < n; ++k) {
      if (fixed_[k]) {
        p[k] = p_fixed_[k];
        r[k] = r_fixed[k];
        continue;
      }
      p[k] = cav[k] ? 0.0 : x_[k];
      r[k] = cav[k] ? void_scale[k] * x_[k] : 0.0;
      const bool next = cav[k] ? (r[k] > -1e-12) : (p[k] < -p_tol);
      changed |= next != static_cast<bool>(cav[k]);
      next_active_[k] = next;
    }
    if (nonlinear_density) {
      // The linearisation's error at the new pressures; then linearise about them.
      double error = 0.0;
      for (int k = 0; k < n; ++k) {
        if (fixed_[k] || cav[k]) continue;
        const double about = p_star[k];
        error =
            std::max(error, std::abs(g.At(p[k]) - g.At(about) - g.Slope(about) * (p[k] - about)));
      }
      for (int k = 0; k < n; ++k) p_star[k] = fixed_[k] || next_active_[k] ? 0.0 : p[k];
      if (error > kCompressionTolerance) {
        changed = true;
        linearise(p_star);
      }
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
    if (fixed_[k]) continue;
    if (!cav[k]) r[k] = 0.0;
    if (cav[k]) p[k] = 0.0;
  }
  // Mass balance w = K p - f + B r (+ A V_old / dt) at every node; at fixed nodes it is minus
  // the flow leaving the film there.
  work_.noalias() = k_lower_.selfadjointView<Eigen::Lower>() * p;
  work_ -= f_;
  double excess = 0.0;
  for (int k = 0; k < n; ++k) {
    // The old void of every node is filled or carried on: on a node fixed now (a supply hole
    // that has moved onto it) the supply fills it within the step, which its residual (the
    // supply flow) counts.
    if (transient) work_[k] += lumped_area_[k] * void_old_[k] * inv_dt;
    if (nonlinear_density) {
      if (!fixed_[k]) work_[k] += lumped_area_[k] * h_mean_[k] * g.At(p[k]) * inv_dt;
    } else {
      work_[k] += compress[k] * p[k];
    }
    if (correction[k] != 0.0) {  // the second-order part of the Couette flow from k to d
      work_[k] -= boff[k] * correction[k];
      work_[bnode[k]] += boff[k] * correction[k];
    }
    if (!fixed_[k]) excess = std::max({excess, r[k] - 1.0, -r[k]});
    if (r[k] == 0.0) continue;
    const double a = boff[k];
    if (!fixed_[k]) {
      work_[k] += (-a - soff[k] - lumped_area_[k] * storage(k)) * r[k];
    } else {
      work_[k] -= (a + soff[k]) * r[k];  // a starved boundary node sends less oil downstream
    }
    if (bnode[k] >= 0) work_[bnode[k]] += a * r[k];
    if (snode[k] >= 0) work_[snode[k]] += soff[k] * r[k];
  }
  // Relative to the flow scale, which for a transient solve includes the flow that fills a
  // node's cell within the step.
  double mass = 0.0, scale = flow_scale_;
  for (int k = 0; k < n; ++k) {
    if (fixed_[k]) continue;
    mass = std::max(mass, std::abs(work_[k]));
    if (transient) scale = std::max(scale, lumped_area_[k] * h_mean_[k] * inv_dt);
  }
  st.max_mass_residual = mass / scale;
  st.fraction_excess = excess;
  sol_.fluid_fraction = Eigen::VectorXd::Ones(n) - r;
  capacity_rate_ = 0.0;
  for (int k = 0; k < n; ++k) {
    sol_.void_content[k] = fixed_[k] ? 0.0 : h_mean_[k] * (r[k] - g.At(p[k]));
    if (transient && !fixed_[k])
      capacity_rate_ += lumped_area_[k] * r[k] * (capacity[k] - h_mean_[k]) * inv_dt;
  }
  prev_active_ = cav;
  jfo_warm_ = converged;
  return converged;
}

}  // namespace filmdyn::lubrication
