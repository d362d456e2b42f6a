// The Reynolds solver's entry point: one solve (assembly, then the cavitation model), its
// statistics and the integrals over the mesh.
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
  fraction_excess = std::max(fraction_excess, o.fraction_excess);
  capped_nodes += o.capped_nodes;
  assembly_s += o.assembly_s;
  factorization_s += o.factorization_s;
  complementarity_s += o.complementarity_s;
}

const ReynoldsSolution& ReynoldsFem::Solve(const ReynoldsParams& params) {
  const int n = NodeCount();
  if (!(params.time_step >= 0.0) || !std::isfinite(params.time_step))
    throw std::logic_error("ReynoldsFem::Solve: time_step must be finite and >= 0");
  if (!(params.bulk_modulus >= 0.0) || !std::isfinite(params.bulk_modulus))
    throw std::logic_error("ReynoldsFem::Solve: bulk_modulus must be finite and >= 0");
  sol_.stats = ReynoldsStats{};
  capacity_rate_ = 0.0;
  auto t0 = Clock::now();
  for (int k = 0; k < n; ++k) fixed_[k] = mesh_.fixed[k] || extra_fixed_[k];
  Assemble(params);
  ApplyEmbeddedCuts();
  sol_.stats.assembly_s = Seconds(t0, Clock::now());
  sol_.fluid_fraction.setOnes();
  sol_.void_content.setZero();
  // Pressure-dependent viscosity: solve for the reduced pressure q (boundary values and the
  // previous solution, the warm start, in q too), then recover p node by node.
  const PressureViscosity* pv = params.pressure_viscosity;
  if (pv != nullptr && !pv->active()) pv = nullptr;
  if (pv != nullptr && compression_.compressibility > 0.0)
    throw std::logic_error("ReynoldsFem::Solve: a compressible film with a pressure-viscosity law");
  if (pv != nullptr) {
    boundary_saved_ = p_fixed_;
    for (int k = 0; k < n; ++k) p_fixed_[k] = pv->Reduced(p_fixed_[k]);
    if (reduced_.size() == n) sol_.pressure.swap(reduced_);
  }
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
  FinishStats();  // residuals (flows) and complementarity: the same in q as in p
  if (pv != nullptr) {
    p_fixed_ = boundary_saved_;
    reduced_ = sol_.pressure;
    // Nodes beyond the limit keep the largest finite pressure of the law, and are counted.
    const double q_top = pv->ReducedLimit() * (1.0 - 1e-12);
    for (int k = 0; k < n; ++k) {
      sol_.stats.capped_nodes += reduced_[k] >= q_top;
      sol_.pressure[k] = pv->Pressure(std::min(reduced_[k], q_top));
    }
  }
  double squeeze = 0.0, voids = 0.0, wetted = 0.0;
  for (const Element& e : elements_) {
    const auto& nd = e.node;
    squeeze += e.area / 3.0 *
               (phi_c_[nd[0]] * dhdt_[nd[0]] + phi_c_[nd[1]] * dhdt_[nd[1]] +
                phi_c_[nd[2]] * dhdt_[nd[2]]);
  }
  for (int k = 0; k < n; ++k) {
    voids += lumped_area_[k] * sol_.void_content[k];
    // JFO: the oil fraction; Reynolds: the film is whole where it is not cavitated.
    const bool jfo = options_.cavitation == CavitationModel::kJfo;
    wetted += lumped_area_[k] * (jfo ? sol_.fluid_fraction[k] : (sol_.cavitated[k] ? 0.0 : 1.0));
  }
  sol_.squeeze_rate = squeeze - capacity_rate_;
  sol_.void_volume = voids;
  sol_.wetted_area = wetted;
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
