#include "core/multibody/multibody_system.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <stdexcept>

#include "core/base/input_error.hpp"

namespace filmdyn::multibody {

BodyIndex MultibodySystem::AddBody(Body body) {
  assert(body.mass > 0.0 && body.inertia > 0.0);
  bodies_.push_back(std::move(body));
  return NumBodies() - 1;
}

int MultibodySystem::AddConstraint(std::unique_ptr<Constraint> constraint) {
  assert(constraint->BodyI() < NumBodies() && constraint->BodyJ() < NumBodies());
  row_offsets_.push_back(num_rows_);
  num_rows_ += constraint->Rows();
  constraints_.push_back(std::move(constraint));
  return static_cast<int>(constraints_.size()) - 1;
}

ForceElement& MultibodySystem::AddForceElement(std::unique_ptr<ForceElement> element) {
  elements_.push_back(std::move(element));
  return *elements_.back();
}

std::vector<double> MultibodySystem::Masses() const {
  std::vector<double> masses;
  for (const Body& body : bodies_) masses.push_back(body.mass);
  return masses;
}

MultibodySystem::ConstraintSystem MultibodySystem::AssembleConstraints(
    double t, const SystemState& state) const {
  ConstraintSystem sys;
  sys.phi.setZero(num_rows_);
  sys.phi_t.setZero(num_rows_);
  sys.gamma.setZero(num_rows_);
  sys.jac.setZero(num_rows_, NumCoordinates());
  ConstraintBlock block;
  for (std::size_t c = 0; c < constraints_.size(); ++c) {
    const Constraint& con = *constraints_[c];
    const int rows = con.Rows(), r0 = row_offsets_[c];
    block.Resize(rows);
    con.Evaluate(t, state.Body(con.BodyI()), state.Body(con.BodyJ()), &block);
    sys.phi.segment(r0, rows) = block.phi;
    sys.phi_t.segment(r0, rows) = block.phi_t;
    sys.gamma.segment(r0, rows) = block.gamma;
    if (con.BodyI() != kGround) sys.jac.block(r0, 3 * con.BodyI(), rows, 3) += block.jac_i;
    if (con.BodyJ() != kGround) sys.jac.block(r0, 3 * con.BodyJ(), rows, 3) += block.jac_j;
  }
  return sys;
}

void MultibodySystem::SetThreads(int threads) {
  if (threads <= 1) {
    pool_.reset();
  } else if (!pool_ || pool_->Threads() != threads) {
    pool_ = std::make_unique<WorkerPool>(threads);
  }
}

int MultibodySystem::Threads() const { return pool_ ? pool_->Threads() : 1; }

namespace {
// Indices of the elements to evaluate side by side: the Concurrent() ones, when there are at
// least two of them and a pool to run them on.
std::vector<int> ConcurrentElements(const std::vector<std::unique_ptr<ForceElement>>& elements,
                                    const WorkerPool* pool) {
  std::vector<int> indices;
  if (!pool) return indices;
  for (int e = 0; e < static_cast<int>(elements.size()); ++e) {
    if (elements[e]->Concurrent()) indices.push_back(e);
  }
  if (indices.size() < 2) indices.clear();
  return indices;
}
}  // namespace

bool MultibodySystem::WantsAcceptedSteps() const {
  for (const auto& e : elements_)
    if (e->WantsAcceptedSteps()) return true;
  return false;
}

void MultibodySystem::OnStepAccepted(double t, const SystemState& state) {
  for (const auto& e : elements_)
    if (e->WantsAcceptedSteps()) e->OnStepAccepted(t, state);
}

double MultibodySystem::StepLimit(double length_tolerance) const {
  double limit = 0.0;
  for (const auto& e : elements_) {
    const double l = e->WantsAcceptedSteps() ? e->StepLimit(length_tolerance) : 0.0;
    if (l > 0.0 && (limit == 0.0 || l < limit)) limit = l;
  }
  return limit;
}

Eigen::VectorXd MultibodySystem::AppliedForces(double t, const SystemState& state) {
  ThrowIfStopRequested(stop_check_);
  if (observer_) observer_(t);
  const int n = NumCoordinates();
  Eigen::VectorXd q_force = Eigen::VectorXd::Zero(n);
  const std::vector<int> concurrent = ConcurrentElements(elements_, pool_.get());
  std::vector<Eigen::VectorXd> buffers(elements_.size());
  if (!concurrent.empty()) {
    pool_->Run(static_cast<int>(concurrent.size()), [&](int k) {
      Eigen::VectorXd& b = buffers[concurrent[k]];
      b.setZero(n);
      elements_[concurrent[k]]->AddForces(t, state, b, nullptr);
    });
  }
  // Summed in element order: the same sums as the sequential evaluation (0 + w = w exactly).
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    if (buffers[e].size() > 0) {
      q_force += buffers[e];
    } else {
      elements_[e]->AddForces(t, state, q_force, nullptr);
    }
  }
  return q_force;
}

DynamicsEvaluation MultibodySystem::Evaluate(double t, const SystemState& state) {
  return EvaluateWithForces(t, state, AppliedForces(t, state));
}

namespace {
Eigen::VectorXd InverseMassDiagonal(const std::vector<Body>& bodies) {
  Eigen::VectorXd inv(3 * bodies.size());
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    inv[3 * k] = inv[3 * k + 1] = 1.0 / bodies[k].mass;
    inv[3 * k + 2] = 1.0 / bodies[k].inertia;
  }
  return inv;
}
}  // namespace

DynamicsEvaluation MultibodySystem::EvaluateWithForces(double t, const SystemState& state,
                                                       const Eigen::VectorXd& applied_force) const {
  DynamicsEvaluation eval;
  eval.applied_force = applied_force;
  const Eigen::VectorXd m_inv = InverseMassDiagonal(bodies_);
  if (num_rows_ == 0) {
    eval.acceleration = m_inv.cwiseProduct(applied_force);
    eval.multipliers.resize(0);
    return eval;
  }
  const ConstraintSystem sys = AssembleConstraints(t, state);
  // eq. 39: right-hand side of the constraint rows.
  const Eigen::VectorXd phi_dot = sys.jac * state.v + sys.phi_t;
  const Eigen::VectorXd rhs =
      sys.gamma - 2.0 * baumgarte_.alpha * phi_dot - baumgarte_.beta * baumgarte_.beta * sys.phi;
  // Schur complement: (Φ_q M⁻¹ Φ_qᵀ) λ = Φ_q M⁻¹ Q − rhs;  q̈ = M⁻¹ (Q − Φ_qᵀ λ).
  const Eigen::MatrixXd jm = sys.jac * m_inv.asDiagonal();
  const Eigen::MatrixXd schur = jm * sys.jac.transpose();
  eval.multipliers = schur.ldlt().solve(jm * applied_force - rhs);
  eval.acceleration = m_inv.cwiseProduct(applied_force - sys.jac.transpose() * eval.multipliers);
  return eval;
}

Eigen::VectorXd MultibodySystem::PositionViolation(double t, const SystemState& state) const {
  return AssembleConstraints(t, state).phi;
}

Eigen::VectorXd MultibodySystem::VelocityViolation(double t, const SystemState& state) const {
  const ConstraintSystem sys = AssembleConstraints(t, state);
  return sys.jac * state.v + sys.phi_t;
}

JointReaction MultibodySystem::Reaction(int index, double t, const SystemState& state,
                                        const Eigen::VectorXd& multipliers) const {
  const Constraint& con = *constraints_.at(index);
  ConstraintBlock block;
  block.Resize(con.Rows());
  con.Evaluate(t, state.Body(con.BodyI()), state.Body(con.BodyJ()), &block);
  const Eigen::VectorXd lambda = multipliers.segment(row_offsets_[index], con.Rows());
  JointReaction reaction;
  reaction.on_i = -block.jac_i.transpose() * lambda;  // eq. 35: −Φ_qᵀ λ
  reaction.on_j = -block.jac_j.transpose() * lambda;
  return reaction;
}

void MultibodySystem::Assemble(double t, SystemState* state, double tolerance) const {
  if (num_rows_ == 0) return;
  for (int iteration = 0;; ++iteration) {
    const ConstraintSystem sys = AssembleConstraints(t, *state);
    if (sys.phi.lpNorm<Eigen::Infinity>() <= tolerance) break;
    if (iteration >= 50) {
      throw std::runtime_error("the joints cannot be assembled: constraint violation " +
                               FormatValue(sys.phi.lpNorm<Eigen::Infinity>()) +
                               " after 50 Newton iterations");
    }
    // Least-norm correction Δq = −Φ_qᵀ (Φ_q Φ_qᵀ)⁻¹ Φ.
    const Eigen::MatrixXd jjt = sys.jac * sys.jac.transpose();
    state->q -= sys.jac.transpose() * jjt.ldlt().solve(sys.phi);
  }
  const ConstraintSystem sys = AssembleConstraints(t, *state);
  const Eigen::MatrixXd jjt = sys.jac * sys.jac.transpose();
  state->v -= sys.jac.transpose() * jjt.ldlt().solve(sys.jac * state->v + sys.phi_t);
}

void MultibodySystem::AccelerationJacobian(double t, const SystemState& state,
                                           Eigen::MatrixXd* d_acc_dq, Eigen::MatrixXd* d_acc_dv) {
  ThrowIfStopRequested(stop_check_);
  const int n = NumCoordinates();
  d_acc_dq->setZero(n, n);
  d_acc_dv->setZero(n, n);
  const Eigen::VectorXd q_force = AppliedForces(t, state);
  // (1) Constraint, Baumgarte and mass terms at frozen Q: central differences (cheap).
  SystemState x = state;
  for (int c = 0; c < 2 * n; ++c) {
    double& entry = c < n ? x.q[c] : x.v[c - n];
    const double saved = entry;
    const double h = 1e-6 * std::max(1.0, std::abs(saved));
    entry = saved + h;
    const Eigen::VectorXd plus = EvaluateWithForces(t, x, q_force).acceleration;
    entry = saved - h;
    const Eigen::VectorXd minus = EvaluateWithForces(t, x, q_force).acceleration;
    entry = saved;
    (c < n ? d_acc_dq->col(c) : d_acc_dv->col(c - n)) = (plus - minus) / (2.0 * h);
  }
  if (elements_.empty()) return;
  // (2) Force elements: dQ/dx, mapped by P = ∂q̈/∂Q = M⁻¹ − M⁻¹Φ_qᵀ S⁻¹ Φ_q M⁻¹.
  ForceJacobian dq_force;
  dq_force.Reset(n);
  // Concurrent elements with analytic Jacobians (the film joints: several film solves each)
  // side by side, each into its own zeroed Jacobian, summed in element order below.
  std::vector<int> concurrent;
  for (int e : ConcurrentElements(elements_, pool_.get())) {
    if (elements_[e]->ProvidesJacobian()) concurrent.push_back(e);
  }
  std::vector<ForceJacobian> own(elements_.size());
  if (concurrent.size() >= 2) {
    pool_->Run(static_cast<int>(concurrent.size()), [&](int k) {
      own[concurrent[k]].Reset(n);
      Eigen::VectorXd scratch = Eigen::VectorXd::Zero(n);
      elements_[concurrent[k]]->AddForces(t, state, scratch, &own[concurrent[k]]);
    });
  }
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    auto& element = elements_[e];
    if (own[e].dq.size() > 0) {
      dq_force.dq += own[e].dq;
      dq_force.dv += own[e].dv;
      continue;
    }
    if (element->ProvidesJacobian()) {
      Eigen::VectorXd scratch = Eigen::VectorXd::Zero(n);
      element->AddForces(t, state, scratch, &dq_force);
      continue;
    }
    Eigen::VectorXd base = Eigen::VectorXd::Zero(n);
    element->AddForces(t, state, base, nullptr);
    for (BodyIndex body : element->Bodies()) {
      for (int k = 0; k < 6; ++k) {
        const int col = 3 * body + k % 3;
        double& entry = k < 3 ? x.q[col] : x.v[col];
        const double saved = entry;
        const double h = 1e-7 * std::max(1.0, std::abs(saved));
        entry = saved + h;
        Eigen::VectorXd plus = Eigen::VectorXd::Zero(n);
        element->AddForces(t, x, plus, nullptr);
        entry = saved;
        (k < 3 ? dq_force.dq.col(col) : dq_force.dv.col(col)) += (plus - base) / h;
      }
    }
  }
  const Eigen::VectorXd m_inv = InverseMassDiagonal(bodies_);
  Eigen::MatrixXd projector = m_inv.asDiagonal();
  if (num_rows_ > 0) {
    const ConstraintSystem sys = AssembleConstraints(t, state);
    const Eigen::MatrixXd jm = sys.jac * m_inv.asDiagonal();
    const Eigen::MatrixXd schur = jm * sys.jac.transpose();
    projector -= jm.transpose() * schur.ldlt().solve(jm);
  }
  *d_acc_dq += projector * dq_force.dq;
  *d_acc_dv += projector * dq_force.dv;
}

}  // namespace filmdyn::multibody
