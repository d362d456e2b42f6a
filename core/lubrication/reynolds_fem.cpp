#include "core/lubrication/reynolds_fem.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace filmdyn::lubrication {

const char* ToString(SolveStatus status) {
  switch (status) {
    case SolveStatus::kConverged:
      return "converged";
    case SolveStatus::kNotConverged:
      return "not-converged";
    case SolveStatus::kFactorizationFailed:
      return "factorization-failed";
  }
  return "?";
}

const char* ToString(CavitationModel model) {
  switch (model) {
    case CavitationModel::kReynolds:
      return "reynolds";
    case CavitationModel::kJfo:
      return "jfo";
    case CavitationModel::kNone:
      return "none";
  }
  return "?";
}

namespace {

using Clock = std::chrono::steady_clock;
double Seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

// Index of entry (row, col) in a compressed column-major matrix; -1 if structurally absent.
int FindPos(const Eigen::SparseMatrix<double>& m, int row, int col) {
  const int* inner = m.innerIndexPtr();
  const int begin = m.outerIndexPtr()[col], end = m.outerIndexPtr()[col + 1];
  const int* it = std::lower_bound(inner + begin, inner + end, row);
  return (it != inner + end && *it == row) ? static_cast<int>(it - inner) : -1;
}

}  // namespace

void ReynoldsStats::Add(const ReynoldsStats& o) {
  if (status == SolveStatus::kConverged) status = o.status;
  iterations += o.iterations;
  jfo_iterations += o.jfo_iterations;
  factorizations += o.factorizations;
  row_updates += o.row_updates;
  pcg_solves += o.pcg_solves;
  pcg_iterations += o.pcg_iterations;
  pcg_fallbacks += o.pcg_fallbacks;
  complementarity_residual = std::max(complementarity_residual, o.complementarity_residual);
  min_pressure = std::min(min_pressure, o.min_pressure);
  max_mass_residual = std::max(max_mass_residual, o.max_mass_residual);
  assembly_s += o.assembly_s;
  factorization_s += o.factorization_s;
  complementarity_s += o.complementarity_s;
}

ReynoldsFem::ReynoldsFem(TriMesh mesh, int sliding_axis, ReynoldsOptions options)
    : mesh_(std::move(mesh)), axis_(sliding_axis), options_(options) {
  if (axis_ != 0 && axis_ != 1) throw std::logic_error("ReynoldsFem: sliding_axis must be 0 or 1");
  const int n = mesh_.NodeCount();
  // Element geometry (P1 shape-function gradients, e.g. Zienkiewicz & Taylor, vol. 1, ch. 4).
  elements_.reserve(mesh_.triangles.size());
  for (const auto& t : mesh_.triangles) {
    double px[3], py[3];
    for (int k = 0; k < 3; ++k) {
      px[k] = mesh_.x[t[k]];
      py[k] = mesh_.y[t[k]];
      if (mesh_.periodic_x) {  // unwrap the column that closes the circle
        if (px[k] - px[0] > 0.5 * mesh_.x_period) px[k] -= mesh_.x_period;
        if (px[k] - px[0] < -0.5 * mesh_.x_period) px[k] += mesh_.x_period;
      }
    }
    const double two_a = (px[1] - px[0]) * (py[2] - py[0]) - (px[2] - px[0]) * (py[1] - py[0]);
    if (!(two_a > 0.0)) throw std::logic_error("ReynoldsFem: degenerate or clockwise element");
    Element e;
    e.node = t;
    e.area = 0.5 * two_a;
    for (int k = 0; k < 3; ++k) {
      const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
      e.dndx[k] = (py[k1] - py[k2]) / two_a;
      e.dndy[k] = (px[k2] - px[k1]) / two_a;
    }
    elements_.push_back(e);
  }
  lumped_area_ = LumpedAreas(mesh_);

  // Sparsity patterns: every node pair sharing an element, fixed for the life of the solver.
  std::vector<Eigen::Triplet<double>> lower, full;
  lower.reserve(elements_.size() * 6);
  full.reserve(elements_.size() * 9);
  // Pairs whose coupling vanishes identically for a diagonal conductivity (the hypotenuse of an
  // axis-aligned right triangle: dN_a/dx dN_b/dx = dN_a/dy dN_b/dy = 0) are left out: a 5-point
  // pattern instead of 7 roughly halves the fill of the LDL^T factor.
  auto structural = [](const Element& e, int a, int b) {
    return a == b || e.dndx[a] * e.dndx[b] != 0.0 || e.dndy[a] * e.dndy[b] != 0.0;
  };
  for (const auto& e : elements_) {
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) {
        if (!structural(e, a, b)) continue;
        full.emplace_back(e.node[a], e.node[b], 0.0);
        if (e.node[a] >= e.node[b]) lower.emplace_back(e.node[a], e.node[b], 0.0);
      }
    }
  }
  k_lower_.resize(n, n);
  k_lower_.setFromTriplets(lower.begin(), lower.end());
  k_lower_.makeCompressed();
  k_full_.resize(n, n);
  k_full_.setFromTriplets(full.begin(), full.end());
  k_full_.makeCompressed();
  work_lower_ = k_lower_;
  m_full_ = k_full_;
  elem_pos_lower_.resize(elements_.size());
  elem_pos_full_.resize(elements_.size());
  static constexpr int kPairs[6][2] = {{0, 0}, {1, 1}, {2, 2}, {1, 0}, {2, 0}, {2, 1}};
  for (size_t ie = 0; ie < elements_.size(); ++ie) {
    const auto& nd = elements_[ie].node;
    for (int q = 0; q < 6; ++q) {
      const int r = std::max(nd[kPairs[q][0]], nd[kPairs[q][1]]);
      const int c = std::min(nd[kPairs[q][0]], nd[kPairs[q][1]]);
      elem_pos_lower_[ie][q] = FindPos(k_lower_, r, c);
    }
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) elem_pos_full_[ie][3 * a + b] = FindPos(k_full_, nd[a], nd[b]);
  }
  // Geometric parts of the element matrices: K_e = kx_e G_x + ky_e G_y per node pair.
  elem_geometry_.resize(elements_.size());
  for (size_t ie = 0; ie < elements_.size(); ++ie) {
    const Element& e = elements_[ie];
    for (int q = 0; q < 6; ++q) {
      const int r = kPairs[q][0], c = kPairs[q][1];
      elem_geometry_[ie][q] = e.area * e.dndx[r] * e.dndx[c];
      elem_geometry_[ie][6 + q] = e.area * e.dndy[r] * e.dndy[c];
    }
  }
  nz_row_.resize(k_lower_.nonZeros());
  nz_col_.resize(k_lower_.nonZeros());
  for (int c = 0; c < n; ++c) {
    for (int p = k_lower_.outerIndexPtr()[c]; p < k_lower_.outerIndexPtr()[c + 1]; ++p) {
      nz_row_[p] = k_lower_.innerIndexPtr()[p];
      nz_col_[p] = c;
    }
  }
  full_col_of_.resize(k_full_.nonZeros());
  for (int c = 0; c < n; ++c)
    for (int p = k_full_.outerIndexPtr()[c]; p < k_full_.outerIndexPtr()[c + 1]; ++p)
      full_col_of_[p] = c;

  // JFO transport: downstream neighbours along +s and -s and the dual-cell face widths.
  const int nx = mesh_.nx_nodes(), ny = mesh_.ny_nodes();
  diag_pos_full_.resize(n);
  down_node_plus_.assign(n, -1);
  down_node_minus_.assign(n, -1);
  down_pos_plus_.assign(n, -1);
  down_pos_minus_.assign(n, -1);
  face_width_.assign(n, 0.0);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int k = mesh_.Node(i, j);
      diag_pos_full_[k] = FindPos(k_full_, k, k);
      if (axis_ == 0) {
        if (i + 1 < nx)
          down_node_plus_[k] = mesh_.Node(i + 1, j);
        else if (mesh_.periodic_x)
          down_node_plus_[k] = mesh_.Node(0, j);
        if (i > 0)
          down_node_minus_[k] = mesh_.Node(i - 1, j);
        else if (mesh_.periodic_x)
          down_node_minus_[k] = mesh_.Node(nx - 1, j);
        double w = 0.0;
        if (j > 0) w += 0.5 * (mesh_.y_lines[j] - mesh_.y_lines[j - 1]);
        if (j + 1 < ny) w += 0.5 * (mesh_.y_lines[j + 1] - mesh_.y_lines[j]);
        face_width_[k] = w;
      } else {
        if (j + 1 < ny) down_node_plus_[k] = mesh_.Node(i, j + 1);
        if (j > 0) down_node_minus_[k] = mesh_.Node(i, j - 1);
        double w = 0.0;
        if (i + 1 < nx || mesh_.periodic_x) w += 0.5 * mesh_.ColumnWidth(i);
        if (i > 0)
          w += 0.5 * mesh_.ColumnWidth(i - 1);
        else if (mesh_.periodic_x)
          w += 0.5 * mesh_.ColumnWidth(nx - 1);
        face_width_[k] = w;
      }
      if (down_node_plus_[k] >= 0) down_pos_plus_[k] = FindPos(k_full_, down_node_plus_[k], k);
      if (down_node_minus_[k] >= 0) down_pos_minus_[k] = FindPos(k_full_, down_node_minus_[k], k);
    }
  }

  ldlt_ = SparseLdlt::Create(options_.backend);
  ldlt_->Analyze(k_lower_);  // ordering + symbolic factorisation, once per mesh

  h_ = Eigen::VectorXd::Constant(n, 1.0);
  dhdt_ = Eigen::VectorXd::Zero(n);
  p_fixed_ = Eigen::VectorXd::Zero(n);
  f_ = rhs_ = x_ = work_ = phi_c_ = Eigen::VectorXd::Zero(n);
  extra_fixed_.assign(n, 0);
  fixed_.assign(n, 0);
  active_.assign(n, 0);
  cut_.assign(n, 0);
  prev_active_.assign(n, 0);
  next_active_.assign(n, 0);
  factors_.assign(n, NodalFilmFactors{});
  sol_.pressure = sol_.contact_pressure = sol_.residual = Eigen::VectorXd::Zero(n);
  sol_.fluid_fraction = Eigen::VectorXd::Ones(n);
  sol_.cavitated.assign(n, 0);
}

ReynoldsFem::~ReynoldsFem() = default;

void ReynoldsFem::Assemble(const ReynoldsParams& params) {
  const int n = NodeCount();
  const double sigma = params.film ? params.film->sigma() : 0.0;
  const double inv12mu = 1.0 / (12.0 * params.viscosity);
  // Nodal factors and conductivities phi h^3 / (12 mu) along x and y (reuse work_/x_ storage).
  Eigen::VectorXd& kx = work_;
  Eigen::VectorXd& ky = x_;
  for (int k = 0; k < n; ++k) {
    factors_[k] = params.film ? params.film->At(h_[k]) : NodalFilmFactors{};
    const NodalFilmFactors& fc = factors_[k];
    const double h3 = h_[k] * h_[k] * h_[k] * inv12mu;
    kx[k] = (axis_ == 0 ? fc.phi_along : fc.phi_across) * h3;
    ky[k] = (axis_ == 0 ? fc.phi_across : fc.phi_along) * h3;
    phi_c_[k] = fc.phi_contact;
    sol_.contact_pressure[k] = fc.contact_pressure;
  }
  std::fill(k_lower_.valuePtr(), k_lower_.valuePtr() + k_lower_.nonZeros(), 0.0);
  const bool jfo = options_.cavitation == CavitationModel::kJfo;
  const bool full = jfo || ldlt_->SupportsRowModify();  // full matrix: JFO LU, row additions
  if (full) std::fill(k_full_.valuePtr(), k_full_.valuePtr() + k_full_.nonZeros(), 0.0);
  full_assembled_ = full;
  f_.setZero();
  double* kl = k_lower_.valuePtr();
  double* kf = k_full_.valuePtr();
  for (size_t ie = 0; ie < elements_.size(); ++ie) {
    const Element& e = elements_[ie];
    const int n0 = e.node[0], n1 = e.node[1], n2 = e.node[2];
    const double a = e.area;
    const double kxe = (kx[n0] + kx[n1] + kx[n2]) / 3.0;  // exact integral of the P1 interpolant
    const double kye = (ky[n0] + ky[n1] + ky[n2]) / 3.0;
    const std::array<double, 12>& geo = elem_geometry_[ie];
    double ke[6];  // per node pair (00, 11, 22, 10, 20, 21)
    for (int q = 0; q < 6; ++q) ke[q] = kxe * geo[q] + kye * geo[6 + q];
    for (int q = 0; q < 6; ++q) {
      const int pos = elem_pos_lower_[ie][q];
      if (pos >= 0) kl[pos] += ke[q];
    }
    if (full) {
      static constexpr int kPairOf[9] = {0, 3, 4, 3, 1, 5, 4, 5, 2};  // (r, c) -> pair
      for (int rc = 0; rc < 9; ++rc) {
        const int pos = elem_pos_full_[ie][rc];
        if (pos >= 0) kf[pos] += ke[kPairOf[rc]];
      }
    }
    // Right-hand side, integrated exactly for P1 nodal fields (int N_a N_b = A/12 (1 + d_ab)).
    const auto& ds = axis_ == 0 ? e.dndx : e.dndy;
    const double dhds = ds[0] * h_[n0] + ds[1] * h_[n1] + ds[2] * h_[n2];
    const double dphis = ds[0] * factors_[n0].phi_shear + ds[1] * factors_[n1].phi_shear +
                         ds[2] * factors_[n2].phi_shear;
    const double sum_c = phi_c_[n0] + phi_c_[n1] + phi_c_[n2];
    const double g[3] = {phi_c_[n0] * dhdt_[n0], phi_c_[n1] * dhdt_[n1], phi_c_[n2] * dhdt_[n2]};
    const double sum_g = g[0] + g[1] + g[2];
    const double shear_flow = 0.5 * params.u_diff * sigma * dphis * a / 3.0;
    const double wedge = jfo ? 0.0 : 0.5 * params.u_sum * dhds * a / 12.0;  // JFO: see below
    for (int r = 0; r < 3; ++r) {
      const int node = e.node[r];
      f_[node] -= wedge * (sum_c + phi_c_[node]) + shear_flow + a / 12.0 * (sum_g + g[r]);
    }
  }
  if (jfo) {
    // JFO: the Couette transport is written as first-order upwind finite-volume face fluxes on
    // the dual cells, (|U|/2) w_k h_k (1 - r_k) from node k to its downstream neighbour, for the
    // full-film part (here) and the void part (matrix B in SolveJfo) alike. A central full-film
    // flux with an upwind void flux was tried first: it let theta leave [0, 1] at film steps
    // and made the active-set iteration cycle (pocketed slider).
    const bool plus = params.u_sum >= 0.0;
    for (int k = 0; k < n; ++k) {
      const int d = plus ? down_node_plus_[k] : down_node_minus_[k];
      if (d < 0) continue;
      const double flux = 0.5 * std::abs(params.u_sum) * face_width_[k] * h_[k];  // upwind
      f_[k] -= flux;
      f_[d] += flux;
    }
  }
  u_sum_ = params.u_sum;
  // Flow scale for relative tolerances: the Couette and squeeze flows through one cell.
  double scale = f_.cwiseAbs().maxCoeff();
  for (int k = 0; k < n; ++k) {
    scale = std::max(scale, 0.5 * std::abs(params.u_sum) * h_[k] * face_width_[k]);
  }
  flow_scale_ = scale > 0.0 ? scale : 1e-300;
}

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
      const bool ok = ldlt_->Factorize(work_lower_);
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
    bool ok = true;
    for (int k = 0; k < n && ok; ++k) {
      if (next_active_[k] && !active_[k]) {
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

const ReynoldsSolution& ReynoldsFem::Solve(const ReynoldsParams& params) {
  const int n = NodeCount();
  sol_.stats = ReynoldsStats{};
  auto t0 = Clock::now();
  for (int k = 0; k < n; ++k) fixed_[k] = mesh_.fixed[k] || extra_fixed_[k];
  Assemble(params);
  sol_.stats.assembly_s = Seconds(t0, Clock::now());
  sol_.fluid_fraction.setOnes();
  switch (options_.cavitation) {
    case CavitationModel::kNone:
      SolveReynoldsLcp(true);
      break;
    case CavitationModel::kReynolds:
      SolveReynoldsLcp(false);
      break;
    case CavitationModel::kJfo:
      SolveJfo();
      break;
  }
  FinishStats();
  return sol_;
}

void ReynoldsFem::FinishStats() {
  const int n = NodeCount();
  ReynoldsStats& st = sol_.stats;
  Eigen::VectorXd& p = sol_.pressure;
  if (options_.cavitation != CavitationModel::kJfo) {
    work_.noalias() = k_lower_.selfadjointView<Eigen::Lower>() * p;
    work_ -= f_;
  }
  sol_.residual = work_;
  const double p_ref = std::max(p.maxCoeff(), 1e-300);
  double comp = 0.0, pmin = 0.0;
  for (int k = 0; k < n; ++k) {
    sol_.cavitated[k] = (options_.cavitation != CavitationModel::kNone) && active_[k] && !fixed_[k];
    if (fixed_[k]) continue;
    pmin = std::min(pmin, p[k]);
    if (options_.cavitation == CavitationModel::kReynolds) {
      comp = std::max(comp, std::abs(std::min(p[k] / p_ref, work_[k] / flow_scale_)));
    } else if (options_.cavitation == CavitationModel::kJfo) {
      comp = std::max(comp, std::abs(std::min(p[k] / p_ref, 1.0 - sol_.fluid_fraction[k])));
    }
  }
  st.complementarity_residual = comp;
  st.min_pressure = pmin;
}

double ReynoldsFem::IntegrateProduct(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const {
  double sum = 0.0;
  for (const auto& e : elements_) {
    const double sa = a[e.node[0]] + a[e.node[1]] + a[e.node[2]];
    const double sb = b[e.node[0]] + b[e.node[1]] + b[e.node[2]];
    const double dot =
        a[e.node[0]] * b[e.node[0]] + a[e.node[1]] * b[e.node[1]] + a[e.node[2]] * b[e.node[2]];
    sum += e.area / 12.0 * (sa * sb + dot);
  }
  return sum;
}

double ReynoldsFem::Integrate(const Eigen::VectorXd& a) const {
  double sum = 0.0;
  for (const auto& e : elements_)
    sum += e.area / 3.0 * (a[e.node[0]] + a[e.node[1]] + a[e.node[2]]);
  return sum;
}

bool ReynoldsFem::LastMatrixIsMMatrix() const {
  const double* kv = k_lower_.valuePtr();
  double dmax = 0.0;
  for (size_t q = 0; q < nz_row_.size(); ++q)
    if (nz_row_[q] == nz_col_[q]) dmax = std::max(dmax, kv[q]);
  for (size_t q = 0; q < nz_row_.size(); ++q) {
    if (nz_row_[q] == nz_col_[q]) {
      if (!(kv[q] > 0.0)) return false;
    } else if (kv[q] > 1e-14 * dmax) {
      return false;
    }
  }
  return true;
}

}  // namespace filmdyn::lubrication
