#pragma once
/// @file Elastic surfaces: how the film's surfaces deform under the film and asperity pressure,
/// and the coupled (elastohydrodynamic) film solve that finds the pressure and the deformed film
/// together.
///
/// The deformation is linear in the load: delta = C (p + p_c) on the film's nodes, delta > 0
/// opening the film, so that the film is h = h_rigid + delta. C is built by one of
///  - the elastic layer (column model): a lining of thickness t bonded to a rigid backing, each
///    point compressed by its own pressure, delta = t (1 + nu)(1 - 2 nu) / (E (1 - nu)) p
///    (a laterally constrained column; e.g. Johnson, "Contact Mechanics", 1985, §5.9);
///  - the elastic half-space: both surfaces elastic half-spaces (the film thin against the
///    radius), delta(x) = 1/(pi E*) int p(x') / |x - x'| dA', 1/E* = (1 - nu1^2)/E1 +
///    (1 - nu2^2)/E2 (Boussinesq; Johnson §3.2), with the pressure constant over each node's
///    cell of the tensor mesh and each cell's integral in closed form (Love 1929, the uniformly
///    loaded rectangle). On a periodic (journal-bearing) mesh the distance along the
///    circumference is taken the short way round.
///
/// The coupled solve is Newton's method on the deformation, R(delta) = delta - C P(h_rigid +
/// delta) = 0 with P the film solver's map from a film to its load (with its own cavitation,
/// pressure and shear laws), the Newton equations (I - C P') s = -R solved by GMRES with the
/// products P' v taken as directional differences of film solves (a Jacobian-free
/// Newton-Krylov method; GCR whose directions are kept from solve to solve), globalised by a
/// backtracking line search on |R|. Because P is the film solver itself, every film model plugs
/// in unchanged; each Krylov product costs one warm-started film solve. In a time integration
/// Newton starts from a deformation predicted by a linear model of the last converged solves
/// over the film's inputs (docs/validation/ehd.md, "Where Newton starts").
#include <Eigen/Dense>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "core/lubrication/film_models.hpp"
#include "core/lubrication/imported_compliance.hpp"
#include "core/lubrication/reynolds_fem.hpp"
#include "core/lubrication/tri_mesh.hpp"

namespace filmdyn::lubrication {

/// A joint's surface compliance and the coupled solve's controls.
struct ComplianceSpec {
  ComplianceModel model = ComplianceModel::kRigid;
  double layer_thickness = 0.0;  ///< elastic layer: lining thickness t [m]
  double layer_modulus = 0.0;    ///< elastic layer: lining Young's modulus E [Pa]
  double layer_poisson = 0.3;    ///< elastic layer: lining Poisson ratio nu, in (-1, 0.5)
  /// Half-space: the two surfaces' Young's moduli [Pa] and Poisson ratios.
  double modulus1 = 0.0, poisson1 = 0.3, modulus2 = 0.0, poisson2 = 0.3;
  /// Imported: the FE surface's compliance (ReadImportedCompliance), and for a bearing the body
  /// angle [rad] of its nodes' psi = 0 (0: the bearing body's own x axis).
  std::shared_ptr<const ImportedCompliance> imported;
  double imported_reference_angle = 0.0;
  /// Converged when max_k |delta_k - (C P)_k| <= tolerance * min_k h_k (the film right to this
  /// fraction of the thinnest film).
  double tolerance = 1e-4;
  int max_iterations = 30;  ///< Newton iterations before the solve is declared not converged
  bool rigid() const { return model == ComplianceModel::kRigid; }
};

/// The field names a ComplianceSpec's validation uses (the joint's case fields or the
/// calculator's options).
struct ComplianceFields {
  std::string layer_thickness, layer_modulus, layer_poisson;
  std::string modulus1, poisson1, modulus2, poisson2;
  std::string tolerance, max_iterations;
  std::string imported;  ///< the compliance file
};

/// Throws filmdyn::InputError naming the field: thickness and moduli must be > 0, Poisson ratios
/// in (-1, 0.5), the tolerance in (0, 0.01], iterations in [1, 1000]. Only the chosen model's
/// fields are checked.
void ValidateCompliance(const ComplianceSpec& spec, const ComplianceFields& names);

/// The largest film (nodes) the half-space model takes: its influence matrix is dense (8 n^2
/// bytes: 800 MB here, and n^2 of Love's rectangles to build).
inline constexpr long kMaxHalfSpaceNodes = 10000;
/// Throws InputError naming `field` when the half-space model is chosen for a film of more than
/// kMaxHalfSpaceNodes nodes (`mesh_fields` names the mesh to coarsen).
void RequireHalfSpaceSize(const ComplianceSpec& spec, long nodes, const std::string& field,
                          const std::string& mesh_fields);

/// The elastic layer's compliance t (1 + nu)(1 - 2 nu) / (E (1 - nu)) [m/Pa].
double LayerCompliance(double thickness, double modulus, double poisson);
/// The pair's 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 [1/Pa].
double CompositeCompliance(double e1, double nu1, double e2, double nu2);
/// The integral of 1/r over the rectangle [x1, x2] x [y1, y2] seen from the origin [m] (Love's
/// closed form): a uniform pressure p on it deflects the origin by p I / (pi E*).
double BoussinesqRectangle(double x1, double x2, double y1, double y2);

/// A linear map from nodal load [Pa] to nodal deformation [m]: none, diagonal or dense.
class SurfaceCompliance {
 public:
  SurfaceCompliance() = default;
  static SurfaceCompliance Diagonal(Eigen::VectorXd coefficients);
  static SurfaceCompliance Dense(Eigen::MatrixXd matrix);
  /// The spec's compliance on `mesh`. `mirror_y`: the mesh is one half of a film symmetric about
  /// the line y = mirror_y (the other half's load deforms this half too); `mirror_x` likewise
  /// about x = mirror_x (not on a periodic mesh). `imported_period`: an imported grid's period
  /// in x when the film mesh itself is not periodic (a skirt panel on a whole-skirt FE model;
  /// 0: none, a periodic film mesh's own period is used).
  static SurfaceCompliance Build(const ComplianceSpec& spec, const TriMesh& mesh,
                                 std::optional<double> mirror_y,
                                 std::optional<double> mirror_x = std::nullopt,
                                 double imported_period = 0.0);
  bool rigid() const { return kind_ == Kind::kNone; }
  /// out = C load.
  void Apply(const Eigen::VectorXd& load, Eigen::VectorXd& out) const;
  /// Imported compliances on a periodic film mesh: the film's x is the FE surface's minus
  /// `offset` [m] (a bearing's film turns with its line of centres). Others: no effect (on a
  /// film mesh that is not periodic the imported compliance is formed once on the film nodes).
  void SetOffset(double offset);
  /// Whether the compliance moves over the film (an imported one on a periodic film: the film
  /// turns against the body, SetOffset).
  bool Moves() const { return kind_ == Kind::kTransfer && transfer_->Moves(); }
  /// The diagonal coefficient of node k [m/Pa].
  double Diagonal(int k) const;
  const Eigen::MatrixXd& dense() const { return dense_; }
  /// No negative coefficient: a load anywhere opens the film everywhere (or nowhere).
  bool nonnegative() const { return nonnegative_; }

 private:
  enum class Kind { kNone, kDiagonal, kDense, kTransfer };
  Kind kind_ = Kind::kNone;
  bool nonnegative_ = true;
  Eigen::VectorXd diagonal_;
  Eigen::MatrixXd dense_;
  std::shared_ptr<ComplianceTransfer> transfer_;
};

/// Outcome of one coupled solve.
struct ElasticSolveStats {
  bool converged = true;
  int iterations = 0;            ///< Newton iterations (all continuation stages)
  int film_solves = 0;           ///< film solves in all (residuals, Krylov products, line search)
  int krylov_iterations = 0;     ///< Krylov (GCR) products in all
  int recycled_steps = 0;        ///< Newton steps tried in the directions kept from earlier solves
  double residual = 0.0;         ///< max_k |delta_k - (C P)_k| at the end [m]
  double tolerance = 0.0;        ///< the residual allowed [m]
  double max_deformation = 0.0;  ///< max_k delta_k [m]
  std::string message;           ///< why it did not converge (empty when it did)
  /// Not converged because the surfaces meet: the film is closed past the rigid surfaces'
  /// position and no deformation opens it (or the surfaces are rigid). No smaller step cures it.
  bool surfaces_touch = false;
};

/// The coupled film solve of one joint, holding the deformation between solves (the next
/// solve starts from it).
class ElasticFilm {
 public:
  ElasticFilm() = default;
  ElasticFilm(SurfaceCompliance compliance, const ComplianceSpec& spec);
  bool rigid() const { return compliance_.rigid(); }
  /// Solves film and deformation together: on entry fem.film_thickness() holds the rigid film,
  /// and the film's other inputs (rate, boundary) are set; on return the fem holds the deformed
  /// film and its solution. Rigid: one plain solve.
  const ElasticSolveStats& Solve(ReynoldsFem& fem, const ReynoldsParams& params);
  /// Solve with the film's inputs: the numbers the rigid film, its rate and the speeds are made
  /// from (e.g. an eccentricity, its rate, the surface speeds, the cosine and sine of an angle),
  /// each smooth in time. Newton then starts from the deformation a linear model of the last
  /// converged solves predicts for these inputs (instead of the last deformation): in a time
  /// integration the solves follow the state, and the prediction starts Newton within a few
  /// tolerances far more often.
  const ElasticSolveStats& Solve(ReynoldsFem& fem, const ReynoldsParams& params,
                                 const Eigen::VectorXd& inputs);
  const Eigen::VectorXd& deformation() const { return delta_; }
  const ElasticSolveStats& stats() const { return stats_; }
  const SurfaceCompliance& compliance() const { return compliance_; }
  /// See SurfaceCompliance::SetOffset.
  void SetOffset(double offset) { compliance_.SetOffset(offset); }
  /// Forgets the deformation (the next solve starts from the rigid film).
  void Reset() {
    delta_.resize(0);
    last_min_film_ = 0.0;
    last_h_rigid_.resize(0);
    solved_.clear();
    ForgetDirections();
  }
  /// The share of the compliance applied, in [0, 1] (1 = the surfaces' own): an engine run
  /// phases the compliance in over its run-in, as it does the pressure law.
  void SetScale(double share) { target_ = share; }

 private:
  // Loads the film solve at delta, returns the residual delta - C P into r; false when the film
  // solve failed.
  bool Residual(ReynoldsFem& fem, const ReynoldsParams& params, const Eigen::VectorXd& delta,
                Eigen::VectorXd& r);
  // Newton's method from delta_ on the compliance scaled by scale_; false (and why) when it
  // does not converge.
  bool Newton(ReynoldsFem& fem, const ReynoldsParams& params, std::string& why);
  // The deformation a linear model of the converged solves kept predicts at `inputs` (false
  // when there are too few to fit one).
  bool Predict(const Eigen::VectorXd& inputs, Eigen::VectorXd& delta) const;
  // Drops the Krylov directions kept for the next Newton steps.
  void ForgetDirections();
  // Ends a solve: on failure the fem is left at delta_ and the status says why.
  const ElasticSolveStats& Finish(ReynoldsFem& fem, const ReynoldsParams& params,
                                  const std::string& failure);

  SurfaceCompliance compliance_;
  ComplianceSpec spec_;
  Eigen::VectorXd h_rigid_, delta_, load_, cload_;
  Eigen::VectorXd last_h_rigid_;  // the rigid film of the last converged solve (with delta_)
  double scale_ = 1.0;   // continuation: the share of the compliance applied
  double target_ = 1.0;  // the share a solve must reach (SetScale)
  double last_min_film_ = 0.0;  // the thinnest film of the last converged solve [m]
  ElasticSolveStats stats_;
  // Krylov directions U of earlier Newton steps and their orthonormal images (I - C P') U at
  // the point they were made: the next steps try them first (at most kKrylov).
  static constexpr int kKrylov = 40;
  // A failed Newton step this many times the residual it answers is reported as a turning
  // point of the equilibrium (measured 200 at the CalculiX skirt's; about 1 in a good step).
  static constexpr double kTurningGain = 20.0;
  // A film thinner than this (a molecule's size) at a failed solve is reported as the surfaces
  // touching [m].
  static constexpr double kTouching = 1e-9;
  std::vector<Eigen::VectorXd> recycled_u_, recycled_c_;
  // The predictor's data: the last converged solves that came with inputs (the compliance's
  // share appended), newest last, at most kPredictorPoints. `field` is the film's deformation
  // or, where the compliance moves over the film, its load (film + asperity pressure): the
  // deformation then also changes as the film's nodes pass the FE grid's lines, which C at the
  // new offset applied to the predicted load carries exactly.
  struct Solved {
    Eigen::VectorXd inputs, field;
  };
  static constexpr int kPredictorPoints = 10;
  // The predictor's ridge on the fitted weights (inputs measured by their spread).
  static constexpr double kRidge = 0.01;
  std::deque<Solved> solved_;
  Eigen::VectorXd inputs_;  // the current solve's (empty: no prediction)
};

}  // namespace filmdyn::lubrication
