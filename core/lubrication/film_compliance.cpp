#include "core/lubrication/film_compliance.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "core/base/input_error.hpp"

namespace filmdyn::lubrication {

const char* ToString(ComplianceModel model) {
  switch (model) {
    case ComplianceModel::kRigid:
      return "rigid";
    case ComplianceModel::kElasticLayer:
      return "elastic_layer";
    case ComplianceModel::kHalfSpace:
      return "half_space";
    case ComplianceModel::kImported:
      return "imported";
  }
  return "?";
}

namespace {

void RequirePoisson(const std::string& field, double nu) {
  RequireInRange(field, nu, -1.0, 0.5, true, true, "-");
}

// x asinh(y/|x|) + y asinh(x/|y|): the antiderivative of 1/r over x and y, without the terms
// x ln|x| + y ln|y| that cancel between the rectangle's corners (asinh(t) = ln(t + sqrt(1 +
// t^2)) is evaluated without cancellation for either sign).
double LoveCorner(double x, double y) {
  double g = 0.0;
  if (x != 0.0) g += x * std::asinh(y / std::abs(x));
  if (y != 0.0) g += y * std::asinh(x / std::abs(y));
  return g;
}

}  // namespace

void ValidateCompliance(const ComplianceSpec& s, const ComplianceFields& names) {
  switch (s.model) {
    case ComplianceModel::kRigid:
      return;
    case ComplianceModel::kElasticLayer:
      RequirePositive(names.layer_thickness, s.layer_thickness, "m");
      RequirePositive(names.layer_modulus, s.layer_modulus, "Pa");
      RequirePoisson(names.layer_poisson, s.layer_poisson);
      break;
    case ComplianceModel::kHalfSpace:
      RequirePositive(names.modulus1, s.modulus1, "Pa");
      RequirePoisson(names.poisson1, s.poisson1);
      RequirePositive(names.modulus2, s.modulus2, "Pa");
      RequirePoisson(names.poisson2, s.poisson2);
      break;
    case ComplianceModel::kImported:
      if (!s.imported) throw InputError(names.imported, "(none)", "a compliance file to import");
      break;
  }
  RequireInRange(names.tolerance, s.tolerance, 0.0, 0.01, true, false, "-");
  RequireInRange(names.max_iterations, s.max_iterations, 1, 1000);
}

void RequireHalfSpaceSize(const ComplianceSpec& spec, long nodes, const std::string& field,
                          const std::string& mesh_fields) {
  if (spec.model != ComplianceModel::kHalfSpace || nodes <= kMaxHalfSpaceNodes) return;
  throw InputError(field, "\"half_space\" on a film of " + std::to_string(nodes) + " nodes",
                   "a film of at most " + std::to_string(kMaxHalfSpaceNodes) +
                       " nodes (its influence matrix is dense): coarsen " + mesh_fields +
                       " or choose \"elastic_layer\"");
}

double LayerCompliance(double t, double e, double nu) {
  return t * (1.0 + nu) * (1.0 - 2.0 * nu) / (e * (1.0 - nu));
}

double CompositeCompliance(double e1, double nu1, double e2, double nu2) {
  return (1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2;
}

double BoussinesqRectangle(double x1, double x2, double y1, double y2) {
  return LoveCorner(x2, y2) - LoveCorner(x1, y2) - LoveCorner(x2, y1) + LoveCorner(x1, y1);
}

SurfaceCompliance SurfaceCompliance::Diagonal(Eigen::VectorXd coefficients) {
  SurfaceCompliance c;
  c.nonnegative_ = coefficients.minCoeff() >= 0.0;
  c.kind_ = Kind::kDiagonal;
  c.diagonal_ = std::move(coefficients);
  return c;
}

SurfaceCompliance SurfaceCompliance::Dense(Eigen::MatrixXd matrix) {
  SurfaceCompliance c;
  c.nonnegative_ = matrix.minCoeff() >= 0.0;
  c.kind_ = Kind::kDense;
  c.dense_ = std::move(matrix);
  return c;
}

SurfaceCompliance SurfaceCompliance::Build(const ComplianceSpec& spec, const TriMesh& mesh,
                                           std::optional<double> mirror_y,
                                           std::optional<double> mirror_x, double imported_period) {
  if (mirror_x && mesh.periodic_x)
    throw std::logic_error("SurfaceCompliance::Build: a periodic mesh has no mirror in x");
  const int n = mesh.NodeCount();
  switch (spec.model) {
    case ComplianceModel::kRigid:
      return {};
    case ComplianceModel::kElasticLayer:
      return Diagonal(Eigen::VectorXd::Constant(
          n, LayerCompliance(spec.layer_thickness, spec.layer_modulus, spec.layer_poisson)));
    case ComplianceModel::kHalfSpace:
      break;
    case ComplianceModel::kImported: {
      SurfaceCompliance c;
      c.kind_ = Kind::kTransfer;
      c.transfer_ = std::make_shared<ComplianceTransfer>(
          spec.imported, mesh, mirror_y, mirror_x,
          mesh.periodic_x ? mesh.x_period : imported_period, spec.imported->source);
      c.nonnegative_ = c.transfer_->Nonnegative();
      if (mesh.periodic_x) return c;  // a bearing: the weights follow its line of centres
      // A film that does not move over the FE surface (a skirt panel): its own matrix, formed
      // once column by column, costs n^2 per product instead of the FE grid's m^2.
      Eigen::MatrixXd film(n, n);
      Eigen::VectorXd unit = Eigen::VectorXd::Zero(n), column;
      for (int j = 0; j < n; ++j) {
        unit[j] = 1.0;
        c.transfer_->Apply(unit, column);
        film.col(j) = column;
        unit[j] = 0.0;
      }
      SurfaceCompliance d = Dense(std::move(film));
      d.nonnegative_ = c.nonnegative_;
      return d;
    }
  }
  // Each node's cell: from the midpoints to its neighbours (the mesh edge at the border).
  const int nx = mesh.nx_nodes(), ny = mesh.ny_nodes();
  std::vector<double> xl(nx), xr(nx), yl(ny), yr(ny);
  for (int i = 0; i < nx; ++i) {
    const double x = mesh.x_lines[i];
    if (mesh.periodic_x) {
      xl[i] = x - 0.5 * mesh.ColumnWidth(i == 0 ? nx - 1 : i - 1);
      xr[i] = x + 0.5 * mesh.ColumnWidth(i);
    } else {
      xl[i] = i == 0 ? x : 0.5 * (x + mesh.x_lines[i - 1]);
      xr[i] = i + 1 == nx ? x : 0.5 * (x + mesh.x_lines[i + 1]);
    }
  }
  for (int j = 0; j < ny; ++j) {
    const double y = mesh.y_lines[j];
    yl[j] = j == 0 ? y : 0.5 * (y + mesh.y_lines[j - 1]);
    yr[j] = j + 1 == ny ? y : 0.5 * (y + mesh.y_lines[j + 1]);
  }
  const double scale =
      CompositeCompliance(spec.modulus1, spec.poisson1, spec.modulus2, spec.poisson2) /
      std::numbers::pi;
  const double period = mesh.x_period;
  // dx from the receiver to the source column's node, the short way round on a periodic mesh.
  auto wrap = [&](double dx) {
    if (!mesh.periodic_x) return dx;
    dx = std::fmod(dx, period);
    if (dx > 0.5 * period) dx -= period;
    if (dx < -0.5 * period) dx += period;
    return dx;
  };
  // One coefficient: receiver (ir, jr), source cell (is, js) and its mirror images.
  auto coefficient = [&](int ir, int jr, int is, int js) {
    const double yr0 = mesh.y_lines[jr];
    const double dx = wrap(mesh.x_lines[is] - mesh.x_lines[ir]);
    const double x1 = dx + (xl[is] - mesh.x_lines[is]);
    const double x2 = dx + (xr[is] - mesh.x_lines[is]);
    const double y1 = yl[js] - yr0, y2 = yr[js] - yr0;
    double v = BoussinesqRectangle(x1, x2, y1, y2);
    // The mirror images of the source cell: about y = mirror_y, x = mirror_x, and both.
    double mx1 = 0.0, mx2 = 0.0, my1 = 0.0, my2 = 0.0;
    if (mirror_x) {
      const double xr0 = mesh.x_lines[ir];
      mx1 = 2.0 * *mirror_x - xr[is] - xr0;
      mx2 = 2.0 * *mirror_x - xl[is] - xr0;
      v += BoussinesqRectangle(mx1, mx2, y1, y2);
    }
    if (mirror_y) {
      my1 = 2.0 * *mirror_y - yr[js] - yr0;
      my2 = 2.0 * *mirror_y - yl[js] - yr0;
      v += BoussinesqRectangle(x1, x2, my1, my2);
    }
    if (mirror_x && mirror_y) v += BoussinesqRectangle(mx1, mx2, my1, my2);
    return scale * v;
  };
  // A uniform periodic mesh (a bearing without circumferential grading) is invariant under
  // turning: the coefficient depends on the column difference only, nx ny^2 of them instead of
  // (nx ny)^2.
  bool uniform = mesh.periodic_x;
  for (int i = 0; uniform && i < nx; ++i)
    uniform = std::abs(mesh.ColumnWidth(i) - mesh.ColumnWidth(0)) <= 1e-12 * mesh.ColumnWidth(0);
  Eigen::MatrixXd c(n, n);
  if (uniform) {
    std::vector<double> table(static_cast<std::size_t>(nx) * ny * ny);
    for (int d = 0; d < nx; ++d)
      for (int jr = 0; jr < ny; ++jr)
        for (int js = 0; js < ny; ++js)
          table[(static_cast<std::size_t>(d) * ny + jr) * ny + js] = coefficient(0, jr, d, js);
    for (int jr = 0; jr < ny; ++jr)
      for (int ir = 0; ir < nx; ++ir)
        for (int js = 0; js < ny; ++js)
          for (int is = 0; is < nx; ++is) {
            const int d = (is - ir + nx) % nx;
            c(mesh.Node(ir, jr), mesh.Node(is, js)) =
                table[(static_cast<std::size_t>(d) * ny + jr) * ny + js];
          }
    return Dense(std::move(c));
  }
  for (int jr = 0; jr < ny; ++jr)
    for (int ir = 0; ir < nx; ++ir)
      for (int js = 0; js < ny; ++js)
        for (int is = 0; is < nx; ++is)
          c(mesh.Node(ir, jr), mesh.Node(is, js)) = coefficient(ir, jr, is, js);
  return Dense(std::move(c));
}

void SurfaceCompliance::Apply(const Eigen::VectorXd& load, Eigen::VectorXd& out) const {
  switch (kind_) {
    case Kind::kNone:
      out.setZero(load.size());
      return;
    case Kind::kDiagonal:
      out = diagonal_.cwiseProduct(load);
      return;
    case Kind::kDense:
      // Column by column, skipping the unloaded (cavitated) nodes.
      out.setZero(load.size());
      for (Eigen::Index j = 0; j < load.size(); ++j)
        if (load[j] != 0.0) out.noalias() += load[j] * dense_.col(j);
      return;
    case Kind::kTransfer:
      transfer_->Apply(load, out);
      return;
  }
}

void SurfaceCompliance::SetOffset(double offset) {
  if (transfer_) transfer_->SetOffset(offset);
}

double SurfaceCompliance::Diagonal(int k) const {
  switch (kind_) {
    case Kind::kNone:
      return 0.0;
    case Kind::kDiagonal:
      return diagonal_[k];
    case Kind::kDense:
      return dense_(k, k);
    case Kind::kTransfer:
      return transfer_->Diagonal(k);
  }
  return 0.0;
}

ElasticFilm::ElasticFilm(SurfaceCompliance compliance, const ComplianceSpec& spec)
    : compliance_(std::move(compliance)), spec_(spec) {}

bool ElasticFilm::Residual(ReynoldsFem& fem, const ReynoldsParams& params,
                           const Eigen::VectorXd& delta, Eigen::VectorXd& r) {
  fem.film_thickness() = h_rigid_ + delta;
  const ReynoldsSolution& sol = fem.Solve(params);
  ++stats_.film_solves;
  if (sol.stats.status != SolveStatus::kConverged) return false;
  load_ = sol.pressure + sol.contact_pressure;
  compliance_.Apply(load_, cload_);
  r = delta - scale_ * cload_;
  return true;
}

const ElasticSolveStats& ElasticFilm::Solve(ReynoldsFem& fem, const ReynoldsParams& params,
                                            const Eigen::VectorXd& inputs) {
  inputs_.resize(inputs.size() + 1);
  inputs_ << inputs, target_;  // the compliance's share moves the deformation as an input does
  Solve(fem, params);
  inputs_.resize(0);
  return stats_;
}

bool ElasticFilm::Predict(const Eigen::VectorXd& z, Eigen::VectorXd& delta) const {
  const int m = static_cast<int>(solved_.size());
  if (z.size() == 0 || m < 2 || solved_.back().inputs.size() != z.size()) return false;
  // Each input measured by its spread over the points and the new one (an input that does not
  // change carries no weight); the reference is the point nearest the new one in that measure.
  const int d = static_cast<int>(z.size());
  Eigen::VectorXd spread = (z - solved_.back().inputs).cwiseAbs();
  for (const Solved& s : solved_)
    spread = spread.cwiseMax((s.inputs - solved_.back().inputs).cwiseAbs());
  Eigen::VectorXd w(d);
  for (int j = 0; j < d; ++j) w[j] = spread[j] > 0.0 ? 1.0 / spread[j] : 0.0;
  int ref = m - 1;
  double nearest = (z - solved_[ref].inputs).cwiseProduct(w).squaredNorm();
  for (int i = 0; i < m - 1; ++i) {
    const double dist = (z - solved_[i].inputs).cwiseProduct(w).squaredNorm();
    if (dist < nearest) {
      nearest = dist;
      ref = i;
    }
  }
  const Solved& r = solved_[ref];
  Eigen::VectorXd field = r.field;
  if (nearest > 0.0) {
    // delta(z) ~ delta_ref + sum_i x_i (delta_i - delta_ref), the weights x fitting the inputs'
    // differences in least squares, ridge-regularised: points much nearer to the reference than
    // the new one (a Newton iterate, a Jacobian column) carry little weight, so that their
    // deformations' noise (the tolerance) is not extrapolated. Where the compliance moves over
    // the film, the fit is made on the film's load and the deformation is C (at the new offset)
    // times the predicted load: on the film nodes the deformation also changes with the offset,
    // as they pass the FE grid's lines, which a fit of the deformation itself misses (in the
    // default engine run by 16-64 tolerances where the load's misses by 1-4).
    Eigen::MatrixXd a(d, m - 1);
    for (int i = 0, col = 0; i < m; ++i)
      if (i != ref) a.col(col++) = (solved_[i].inputs - r.inputs).cwiseProduct(w);
    const Eigen::VectorXd b = (z - r.inputs).cwiseProduct(w);
    Eigen::MatrixXd g = a.transpose() * a;
    g.diagonal().array() += kRidge * kRidge;
    const Eigen::VectorXd x = g.ldlt().solve(a.transpose() * b);
    for (int i = 0, col = 0; i < m; ++i)
      if (i != ref) field += x[col++] * (solved_[i].field - r.field);
  }
  if (compliance_.Moves()) {
    compliance_.Apply(field, delta);  // C at the current offset: one product
    delta *= target_;
  } else {
    delta = std::move(field);
  }
  return delta.size() == delta_.size() && delta.allFinite();
}

const ElasticSolveStats& ElasticFilm::Solve(ReynoldsFem& fem, const ReynoldsParams& params) {
  stats_ = ElasticSolveStats{};
  const int n = fem.NodeCount();
  if (compliance_.rigid() || !(target_ > 0.0)) {
    delta_.setZero(n);
    if (!compliance_.rigid() && fem.film_thickness().minCoeff() <= 0.0) {
      stats_.converged = false;
      stats_.message = "the film is closed (h <= 0) and the surfaces are rigid";
      stats_.surfaces_touch = true;
      return stats_;
    }
    fem.Solve(params);
    stats_.film_solves = 1;
    return stats_;
  }
  h_rigid_ = fem.film_thickness();
  std::string why;
  // A continuation: a share raised from 0 to `to` in steps, the first `first`, doubled after a
  // success and quartered after a failure down to `smallest`; each stage is set by `stage`, which
  // returns the film's parameters for it, and solved by Newton from the last converged
  // deformation (`converged`: the start). Returns the share reached (`to` when it got there),
  // delta_ at the last converged stage.
  auto continuation = [&](double to, double first, double smallest, Eigen::VectorXd converged,
                          const auto& stage) {
    double done = 0.0, step = first;
    while (step >= smallest) {
      const double share = std::min(to, done + step);
      const ReynoldsParams& stage_params = stage(share);
      delta_ = converged;
      if (Newton(fem, stage_params, why)) {
        done = share;
        converged = delta_;
        if (done == to) break;
        step *= 2.0;
      } else {
        step *= 0.25;
      }
    }
    delta_ = converged;
    return done;
  };
  // A rigid film closed somewhere (the journal or piston past the rigid wall): only the deformation
  // can open it, so the solve must start from one that does.
  const int closed = static_cast<int>((h_rigid_.array() <= 0.0).count());
  // From the last solve's deformation (the state moves little between the solves of a time
  // integration or a root search).
  if (delta_.size() == n) {
    scale_ = target_;
    const Eigen::VectorXd last_delta = delta_;
    Eigen::VectorXd predicted;
    if (Predict(inputs_, predicted)) {
      delta_ = predicted;
      if (compliance_.nonnegative()) delta_ = delta_.cwiseMax(0.0);
    }
    // Where that leaves the film thinner than half the last solution's thinnest, open it to
    // that much (the film cannot close faster between two nearby solves).
    if (last_min_film_ > 0.0)
      delta_ = delta_.cwiseMax((0.5 * last_min_film_ - h_rigid_.array()).matrix());
    if (Newton(fem, params, why)) return Finish(fem, params, "");
    // Continuation in the rigid film, from the last converged solve's to this one, in steps
    // (halved first, doubled after a success, quartered after a failure): each stage starts
    // inside Newton's basin. It also takes a film the rigid surfaces close (the piston or the
    // journal past the rigid wall) from the last open one.
    if (last_h_rigid_.size() == n) {
      const Eigen::VectorXd h_target = h_rigid_, h_last = last_h_rigid_;
      const double reached = continuation(1.0, 0.5, 1.0 / 1024.0, last_delta,
                                          [&](double share) -> const ReynoldsParams& {
                                            h_rigid_ = h_last + share * (h_target - h_last);
                                            return params;
                                          });
      if (reached == 1.0) return Finish(fem, params, "");
      h_rigid_ = h_target;
      delta_ = last_delta;
    }
  }
  if (closed > 0) {
    stats_.converged = false;
    stats_.surfaces_touch = true;
    stats_.message =
        "the rigid film is closed at " + std::to_string(closed) +
        " nodes (the surfaces are past each other's rigid position) and the deformation " +
        (delta_.size() == n ? "of the last solve does not open it (" + why + ")"
                            : "is not known yet (no earlier solve)");
    if (delta_.size() != n) delta_.setZero(n);
    return stats_;
  }
  // Continuation in the compliance: the rigid film's pressure can be far too high for the
  // elastic one (a Newton start far outside its basin), so the compliance grows from zero in
  // steps that double after a success and shrink fourfold after a failure, each stage starting
  // from the last converged deformation.
  auto compliance_continuation = [&](const ReynoldsParams& film_params) {
    const double reached =
        continuation(target_, target_, target_ / 4096.0, Eigen::VectorXd::Zero(n),
                     [&](double share) -> const ReynoldsParams& {
                       scale_ = share;
                       return film_params;
                     });
    scale_ = target_;
    return reached;
  };
  const double done = compliance_continuation(params);
  if (done == target_) return Finish(fem, params, "");
  const Eigen::VectorXd partial = delta_;
  const std::string partial_why = why;
  // Continuation in the pressure-viscosity law at the full compliance: where the rigid film has
  // no finite piezoviscous pressure (its isoviscous pressure past the law's limit, 1/alpha for
  // Barus), the continuation in the compliance starts where there is no solution, while the
  // elastic isoviscous film always has one; from it the law's strength grows from zero in steps
  // that double after a success and shrink fourfold after a failure.
  const PressureViscosity* law = params.pressure_viscosity;
  double strength = -1.0;  // the law's share reached from the elastic isoviscous film
  if (law != nullptr && law->active()) {
    PressureViscosity weakened;  // none: isoviscous
    ReynoldsParams weak = params;
    weak.pressure_viscosity = &weakened;
    if (compliance_continuation(weak) == target_) {
      strength =
          continuation(1.0, 1.0, 1.0 / 1024.0, delta_, [&](double share) -> const ReynoldsParams& {
            if (share == 1.0) return params;  // the law itself: nothing to weaken
            weakened = law->Weakened(share);
            return weak;
          });
      if (strength == 1.0) return Finish(fem, params, "");
    }
  }
  delta_ = partial;
  scale_ = target_;
  return Finish(fem, params,
                "deformation not converged: the compliance could be raised only to " +
                    FormatValue(done / target_) + " of its value (" + partial_why + ")" +
                    (strength >= 0.0 ? "; from the elastic isoviscous film the pressure law "
                                       "only to " +
                                           FormatValue(strength) + " of its strength (" + why + ")"
                                     : std::string()));
}

const ElasticSolveStats& ElasticFilm::Finish(ReynoldsFem& fem, const ReynoldsParams& params,
                                             const std::string& failure) {
  if (!failure.empty()) {
    // Leave the solver at the residual of the deformation kept, for the partial results.
    Eigen::VectorXd r;
    Residual(fem, params, delta_, r);
    stats_.residual = r.cwiseAbs().maxCoeff();
    stats_.converged = false;
    stats_.message = failure;
  }
  stats_.max_deformation = delta_.maxCoeff();
  if (stats_.converged) {
    last_min_film_ = (h_rigid_ + delta_).minCoeff();
    last_h_rigid_ = h_rigid_;
    if (inputs_.size() > 0) {
      if (!solved_.empty() && solved_.back().inputs.size() != inputs_.size()) solved_.clear();
      if (solved_.size() == static_cast<std::size_t>(kPredictorPoints)) solved_.pop_front();
      solved_.push_back({inputs_, compliance_.Moves() ? load_ : delta_});
    }
  }
  return stats_;
}

bool ElasticFilm::Newton(ReynoldsFem& fem, const ReynoldsParams& params, std::string& why) {
  const int n = fem.NodeCount();
  Eigen::VectorXd r(n), r_trial(n), cload0(n), step(n), trial(n), res(n), v(n), w(n);
  auto fail = [&](const std::string& reason) {
    why = reason;
    return false;
  };
  if (!Residual(fem, params, delta_, r)) return fail("film solve failed");
  if (recycled_u_.size() > 0 && recycled_u_.front().size() != n) ForgetDirections();
  // Tries delta_ + lambda step for lambda = 1, 1/2, ... (up to `cuts` halvings): the first trial
  // that lowers |R|_2 by the factor `decrease` (relative to lambda) is taken into delta_ and r.
  auto line_search = [&](int cuts, double decrease) {
    const Eigen::VectorXd delta0 = delta_, load0 = load_, cload0 = cload_;
    const double norm0 = r.norm();
    double lambda = 1.0;
    for (int ls = 0; ls <= cuts; ++ls, lambda *= 0.5) {
      trial = delta0 + lambda * step;
      // A compliance with no negative coefficient opens the film wherever it is loaded: the
      // solution has delta >= 0, and iterates are kept there (projected steps), away from the
      // films thinner than the rigid one where the asperity pressure rises without bound.
      if (compliance_.nonnegative()) trial = trial.cwiseMax(0.0);
      // The film may not close by more than three quarters at any node in one step.
      if ((trial - delta0).cwiseQuotient(h_rigid_ + delta0).minCoeff() < -0.75) continue;
      if (!Residual(fem, params, trial, r_trial)) continue;
      if (r_trial.norm() <= (1.0 - decrease * lambda) * norm0) {
        delta_ = trial;
        r = r_trial;
        return true;
      }
    }
    // Leave the film solver's inputs, the load and its C P at the iterate kept.
    fem.film_thickness() = h_rigid_ + delta_;
    load_ = load0;
    cload_ = cload0;
    return false;
  };
  for (int it = 0;; ++it) {
    const double h_min = (h_rigid_ + delta_).minCoeff();
    stats_.tolerance = spec_.tolerance * h_min;
    stats_.residual = r.cwiseAbs().maxCoeff();
    if (it > 0) ++stats_.iterations;
    if (stats_.residual <= stats_.tolerance) return true;
    if (it == spec_.max_iterations) {
      return fail("deformation not converged in " + std::to_string(it) +
                  " Newton iterations (residual " + FormatValue(stats_.residual) + " m, allowed " +
                  FormatValue(stats_.tolerance) + " m)");
    }
    const double beta = r.norm();
    // The Newton equations (I - C P') s = -r, first in the directions kept from earlier solves
    // (their images under an earlier Jacobian: the state, hence P', moves little from one solve
    // to the next), at the price of one film solve for the trial. Where those directions
    // resolve little of r, or the trial does not lower the residual by half, fresh ones.
    // A full set is dropped whole (keeping the newest directions instead measured slower: the
    // oldest images are the stalest).
    if (recycled_u_.size() >= static_cast<std::size_t>(kKrylov)) ForgetDirections();
    step.setZero(n);
    res = -r;
    for (std::size_t i = 0; i < recycled_u_.size(); ++i) {
      const double a = recycled_c_[i].dot(res);
      step += a * recycled_u_[i];
      res -= a * recycled_c_[i];
    }
    bool stale = !recycled_u_.empty();
    if (stale) {
      if (res.norm() <= 0.5 * beta) {
        ++stats_.recycled_steps;
        if (line_search(0, 0.5)) continue;
        ForgetDirections();
        stale = false;
        step.setZero(n);
        res = -r;
      }
    }
    // GCR with a right preconditioner; P' v ~ (P(h + tau v) - P(h)) / tau, differencing the base
    // point's C P (C is linear). The directions U and their orthonormal images J U are kept for
    // the next iterations and solves.
    cload0 = cload_;
    const Eigen::VectorXd delta0 = delta_;
    const Eigen::VectorXd load0 = load_;
    // Right preconditioner: I + C_kk 2 P_k / h_k, the local part of I - C P' with the film's
    // own scaling (a film opened uniformly by dh carries the pressure P (1 - 2 dh / h): p ~
    // 1/h^2 for Reynolds' equation), which takes the steep, thin-film modes out of GCR's way.
    Eigen::VectorXd precond(n);
    for (int k = 0; k < n; ++k) {
      precond[k] = 1.0 + 2.0 * scale_ * compliance_.Diagonal(k) * std::max(load0[k], 0.0) /
                             (h_rigid_[k] + delta0[k]);
    }
    const double goal = 1e-3 * beta;  // the linear equations solved to 1e-3 of the residual
    bool film_failed = false;
    auto solved = [&] {
      return res.norm() <= goal || res.cwiseAbs().maxCoeff() <= 0.25 * stats_.tolerance;
    };
    while (recycled_u_.size() < static_cast<std::size_t>(kKrylov) && !solved()) {
      v = res.cwiseQuotient(precond);
      const double tau = 1e-6 * h_min / std::max(v.cwiseAbs().maxCoeff(), 1e-300);
      if (!Residual(fem, params, delta0 + tau * v, r_trial)) {
        film_failed = true;
        break;
      }
      ++stats_.krylov_iterations;
      w = v - (scale_ / tau) * (cload_ - cload0);
      for (std::size_t i = 0; i < recycled_u_.size(); ++i) {  // modified Gram-Schmidt
        const double a = recycled_c_[i].dot(w);
        w -= a * recycled_c_[i];
        v -= a * recycled_u_[i];
      }
      const double norm_w = w.norm();
      if (!(norm_w > 1e-14 * beta)) break;
      recycled_c_.push_back(w / norm_w);
      recycled_u_.push_back(v / norm_w);
      const double a = recycled_c_.back().dot(res);
      step += a * recycled_u_.back();
      res -= a * recycled_c_.back();
    }
    // The base point's solution and C P, for the line search's reference.
    load_ = load0;
    cload_ = cload0;
    if (film_failed || recycled_u_.empty()) {
      ForgetDirections();
      return fail("film solve failed during the Newton iteration");
    }
    // Backtracking on |R|_2 (the film must stay open: h > 0 everywhere). No decrease down to a
    // step of 1/64 is the sign of a start outside Newton's basin: the continuations (Solve) then
    // take a smaller step in the rigid film or the compliance.
    if (!line_search(6, 1e-4)) {
      ForgetDirections();
      if (stale) continue;  // again, with fresh directions only
      // A Newton step far larger than the residual it answers: I - C P' is nearly singular,
      // the film-surface equilibrium turns here (docs/validation/ehd.md, known limits).
      const double gain = step.norm() / beta;
      // The residual allowed is a share of the thinnest film: nothing where the film is held
      // open by the deformation alone down to molecular size (a journal or skirt pressed past
      // the rigid wall): the surfaces touch there, which no film solve can carry.
      const double h_min = (h_rigid_ + delta_).minCoeff();
      return fail("line search found no decrease of the deformation residual (residual " +
                  FormatValue(stats_.residual) + " m" +
                  (h_min < kTouching
                       ? "; the thinnest film is " + FormatValue(h_min) + " m: the surfaces touch"
                       : ", allowed " + FormatValue(stats_.tolerance) + " m") +
                  (gain > kTurningGain
                       ? "; the Newton step is " + FormatValue(std::round(gain)) +
                             " times the residual: the film-surface equilibrium has a turning "
                             "point here, past which the quasi-static elastic model has no "
                             "nearby solution"
                       : std::string()) +
                  ")");
    }
  }
}

void ElasticFilm::ForgetDirections() {
  recycled_u_.clear();
  recycled_c_.clear();
}

}  // namespace filmdyn::lubrication
