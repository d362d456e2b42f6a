// The sparsity pattern (analysed once per mesh in the constructor) and the assembly of the average
// Reynolds equation on it (linear triangles, Galerkin).
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
  down_gap_plus_.assign(n, 0.0);
  down_gap_minus_.assign(n, 0.0);
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
        if (i + 1 < nx || mesh_.periodic_x) down_gap_plus_[k] = mesh_.ColumnWidth(i);
        if (i > 0)
          down_gap_minus_[k] = mesh_.ColumnWidth(i - 1);
        else if (mesh_.periodic_x)
          down_gap_minus_[k] = mesh_.ColumnWidth(nx - 1);
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
        if (j + 1 < ny) down_gap_plus_[k] = mesh_.y_lines[j + 1] - mesh_.y_lines[j];
        if (j > 0) down_gap_minus_[k] = mesh_.y_lines[j] - mesh_.y_lines[j - 1];
      }
      if (down_node_plus_[k] >= 0) down_pos_plus_[k] = FindPos(k_full_, down_node_plus_[k], k);
      if (down_node_minus_[k] >= 0) down_pos_minus_[k] = FindPos(k_full_, down_node_minus_[k], k);
    }
  }
  up_node_plus_.assign(n, -1);
  up_node_minus_.assign(n, -1);
  for (int k = 0; k < n; ++k) {
    if (down_node_plus_[k] >= 0) up_node_plus_[down_node_plus_[k]] = k;
    if (down_node_minus_[k] >= 0) up_node_minus_[down_node_minus_[k]] = k;
  }

  ldlt_ = SparseLdlt::Create(options_.backend);
  ldlt_->Analyze(k_lower_);  // ordering + symbolic factorisation, once per mesh

  h_ = Eigen::VectorXd::Constant(n, 1.0);
  dhdt_ = Eigen::VectorXd::Zero(n);
  p_fixed_ = Eigen::VectorXd::Zero(n);
  theta_fixed_ = Eigen::VectorXd::Ones(n);
  void_old_ = Eigen::VectorXd::Zero(n);
  f_ = rhs_ = x_ = work_ = phi_c_ = h_mean_ = Eigen::VectorXd::Zero(n);
  extra_fixed_.assign(n, 0);
  fixed_.assign(n, 0);
  active_.assign(n, 0);
  cut_.assign(n, 0);
  prev_active_.assign(n, 0);
  next_active_.assign(n, 0);
  factors_.assign(n, NodalFilmFactors{});
  sol_.pressure = sol_.contact_pressure = sol_.residual = Eigen::VectorXd::Zero(n);
  sol_.fluid_fraction = Eigen::VectorXd::Ones(n);
  sol_.void_content = Eigen::VectorXd::Zero(n);
  sol_.cavitated.assign(n, 0);
}

ReynoldsFem::~ReynoldsFem() = default;

void ReynoldsFem::Assemble(const ReynoldsParams& params) {
  const int n = NodeCount();
  const double sigma = params.film ? params.film->sigma() : 0.0;
  const double inv12mu = 1.0 / (12.0 * params.viscosity);
  const CrossLaw* shear = params.shear_thinning != nullptr && params.shear_thinning->active()
                              ? params.shear_thinning
                              : nullptr;
  // Nodal factors and conductivities phi h^3 / (12 mu) along x and y (reuse work_/x_ storage).
  Eigen::VectorXd& kx = work_;
  Eigen::VectorXd& ky = x_;
  for (int k = 0; k < n; ++k) {
    factors_[k] = params.film ? params.film->At(h_[k]) : NodalFilmFactors{};
    const NodalFilmFactors& fc = factors_[k];
    double h3 = h_[k] * h_[k] * h_[k] * inv12mu;
    if (shear != nullptr) h3 /= shear->InFilm(params.u_diff, h_[k]);
    kx[k] = (axis_ == 0 ? fc.phi_along : fc.phi_across) * h3;
    ky[k] = (axis_ == 0 ? fc.phi_across : fc.phi_along) * h3;
    phi_c_[k] = fc.phi_contact;
    h_mean_[k] = h_[k] + fc.mean_gap_excess;
    sol_.contact_pressure[k] = fc.contact_pressure;
  }
  if (oil_fixed_.size() == n)
    for (int k = 0; k < n; ++k)
      if (fixed_[k] && oil_fixed_[k] > 0.0)
        theta_fixed_[k] = h_mean_[k] > oil_fixed_[k] ? oil_fixed_[k] / h_mean_[k] : 1.0;
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
    const double sum_c = phi_c_[n0] + phi_c_[n1] + phi_c_[n2];
    const double g[3] = {phi_c_[n0] * dhdt_[n0], phi_c_[n1] * dhdt_[n1], phi_c_[n2] * dhdt_[n2]};
    const double sum_g = g[0] + g[1] + g[2];
    // The roughness shear flow q = (U1 - U2)/2 sigma phi_s, weak form integrated by parts:
    // -int q dN_r/ds over the element (q at its mean: P1). Free nodes get the same as the source
    // form int N_r dq/ds; a fixed node's reaction then holds the shear flow through the boundary
    // too, so that the boundary flows add up to the change of stored oil (without it, a skirt,
    // open along the sliding direction, lost the oil its edges' shear flows carry). JFO: face
    // fluxes carrying the upwind fluid fraction instead (below).
    const double q_mean =
        jfo ? 0.0
            : 0.5 * params.u_diff * sigma *
                  (factors_[n0].phi_shear + factors_[n1].phi_shear + factors_[n2].phi_shear) / 3.0;
    const double wedge = jfo ? 0.0 : 0.5 * params.u_sum * dhds * a / 12.0;  // JFO: see below
    // JFO: the squeeze term lumped (below), like the void's storage, so that a node's oil
    // balance holds only its own cell's storage and a cavity cannot give away oil it lacks.
    const double squeeze = jfo ? 0.0 : 1.0;
    for (int r = 0; r < 3; ++r) {
      const int node = e.node[r];
      f_[node] -=
          wedge * (sum_c + phi_c_[node]) - a * ds[r] * q_mean + squeeze * a / 12.0 * (sum_g + g[r]);
    }
  }
  if (jfo) {
    for (int k = 0; k < n; ++k) f_[k] -= lumped_area_[k] * phi_c_[k] * dhdt_[k];
    // JFO: the Couette transport is written as finite-volume face fluxes on the dual cells,
    // (|U|/2) w_k h_f (1 - r_k) from node k to its downstream neighbour d, for the full-film part
    // (here) and the void part (matrix B in SolveJfo) alike: the mean gap at the face, h_f =
    // (h_T,k + h_T,d)/2 (a known field; h_T = h + the roughness's mean-gap excess, so that with
    // rough surfaces the flow carries the oil the film holds, as phi_c dh/ds = dh_T/ds does in the
    // Reynolds films: left at h, the JFO load differed from the Reynolds one by 1.9 % at H = 1.5
    // on every mesh), times the fluid fraction of the upwind node. A full film's Couette
    // flow is then centred, second order like the Galerkin wedge term of the Reynolds films (with
    // the upwind gap h_k its source sat half a cell upstream: first order, the steady bearing's
    // load 14 % high on 60 cells); a cavity still sends on only the oil it holds (no flow out of
    // an empty cell, so theta stays in [0, 1]). A starved boundary node (fluid fraction < 1)
    // supplies its own content, (|U|/2) w theta_b h_T,k: a partial film carries its content
    // theta h_T unchanged, and the supply is then exactly the one given. A centred full-film flux
    // with a separate upwind void flux, (|U|/2) w (h_f - h_k r_k), was tried first: an empty cell
    // then still sent oil on, theta left [0, 1] at film steps and the active-set iteration cycled
    // (pocketed slider).
    const bool plus = params.u_sum >= 0.0;
    h_face_.resize(n);
    for (int k = 0; k < n; ++k) {
      const int d = plus ? down_node_plus_[k] : down_node_minus_[k];
      const bool starved_edge = fixed_[k] && theta_fixed_[k] < 1.0;
      h_face_[k] = d >= 0 && !starved_edge ? 0.5 * (h_mean_[k] + h_mean_[d]) : h_mean_[k];
      if (d < 0) continue;
      const double flux = 0.5 * std::abs(params.u_sum) * face_width_[k] * h_face_[k];
      f_[k] -= flux;
      f_[d] += flux;
    }
    // The roughness's shear flow q_s = (U1 - U2)/2 sigma phi_s as face fluxes alike, carrying the
    // upwind node's fluid fraction (its void part in SolveJfo): a partial film carries the shear
    // flow of the oil it holds, a dry one none. phi_s has one sign over the film (that of the
    // surfaces' variance ratios Vr1 - Vr2), so the flow runs one way everywhere: along +s where
    // (U1 - U2) phi_s > 0. phi_s at the face centred; a starved boundary node sends its own.
    double phi_s_sum = 0.0;
    for (int k = 0; k < n; ++k) phi_s_sum += factors_[k].phi_shear;
    shear_plus_ = params.u_diff * phi_s_sum >= 0.0;
    shear_face_.setZero(n);
    if (sigma > 0.0 && params.u_diff != 0.0 && phi_s_sum != 0.0) {
      for (int k = 0; k < n; ++k) {
        const int d = shear_plus_ ? down_node_plus_[k] : down_node_minus_[k];
        if (d < 0) continue;
        const bool starved_edge = fixed_[k] && theta_fixed_[k] < 1.0;
        const double phi_s = starved_edge ? factors_[k].phi_shear
                                          : 0.5 * (factors_[k].phi_shear + factors_[d].phi_shear);
        const double flux = 0.5 * std::abs(params.u_diff * phi_s) * sigma * face_width_[k];
        shear_face_[k] = flux;
        f_[k] -= flux;
        f_[d] += flux;
      }
    }
  }
  u_sum_ = params.u_sum;
  time_step_ = jfo ? params.time_step : 0.0;
  compression_ =
      time_step_ > 0.0 ? Compression::Of(params.bulk_modulus, params.density_law) : Compression{};
  // Flow scale for relative tolerances: the Couette and squeeze flows through one cell.
  double scale = f_.cwiseAbs().maxCoeff();
  for (int k = 0; k < n; ++k) {
    scale = std::max(scale, 0.5 * std::abs(params.u_sum) * h_[k] * face_width_[k]);
  }
  flow_scale_ = scale > 0.0 ? scale : 1e-300;
}

void ReynoldsFem::ApplyEmbeddedCuts() {
  for (const EmbeddedCut& cut : cuts_) {
    const int k = cut.free_node, j = cut.fixed_node;
    if (k < 0 || j < 0 || k >= NodeCount() || j >= NodeCount() || !fixed_[j] || fixed_[k])
      throw std::logic_error("ReynoldsFem: an embedded cut must join a free node to a fixed one");
    if (!(cut.fraction >= 0.0 && cut.fraction <= 1.0))
      throw std::logic_error("ReynoldsFem: an embedded cut's fraction must be in [0, 1]");
    const int lower = FindPos(k_lower_, std::max(k, j), std::min(k, j));
    if (lower < 0) continue;  // not neighbours in the pattern: no pressure flow between them
    // The edge's conductance c = -K_kj over the fraction of its length: the off-diagonals and
    // both diagonals (row sums stay zero, the matrix symmetric) change by c (1/s - 1).
    const double s = std::max(cut.fraction, EmbeddedCut::kMinFraction);
    double* kl = k_lower_.valuePtr();
    const double extra = -kl[lower] * (1.0 / s - 1.0);
    kl[lower] -= extra;
    kl[FindPos(k_lower_, k, k)] += extra;
    kl[FindPos(k_lower_, j, j)] += extra;
    if (full_assembled_) {
      double* kf = k_full_.valuePtr();
      kf[FindPos(k_full_, k, j)] -= extra;
      kf[FindPos(k_full_, j, k)] -= extra;
      kf[FindPos(k_full_, k, k)] += extra;
      kf[FindPos(k_full_, j, j)] += extra;
    }
  }
}

}  // namespace filmdyn::lubrication
