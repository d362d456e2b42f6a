#pragma once
/// @file Galerkin P1 finite elements for the average Reynolds equation with exact cavitation.
///
/// Strong form (Patir & Cheng 1978 eq. 1 with the Wu & Zheng 1989 contact factor; dimensional, SI):
///   div( phi h^3/(12 mu) grad p ) = (U_sum/2) phi_c dh/ds + (U_diff/2) sigma dphi_s/ds
///                                   + phi_c dh/dt
/// with s the sliding direction (mesh axis x or y), U_sum = U1 + U2 (surface velocities in the
/// frame of the mesh), U_diff = U1 - U2 (surface 1 = the one whose roughness is sigma1).
/// Weak form: K p = f with K_kl = integral(k_x dN_k/dx dN_l/dx + k_y dN_k/dy dN_l/dy) and
///   f_k = -integral N_k [ (U_sum/2) phi_c dh/ds + (U_diff/2) sigma dphi_s/ds + phi_c dh/dt ],
/// every term integrated exactly for P1 nodal fields (element conductivity = mean of the nodal
/// phi h^3/(12 mu), which is the exact integral of its P1 interpolant).
///
/// Cavitation:
///  - kReynolds (Swift-Stieber): the LCP  p >= 0, w = K p - f >= 0, p.w = 0, solved by the
///    primal-dual active-set method (Hintermueller, Ito & Kunisch 2003), i.e. a semismooth Newton
///    method; for the M-matrices of our meshes it terminates finitely with the exact solution of
///    the discrete LCP. Rows/columns of active nodes are replaced by unit rows; the first
///    iteration is a numeric LDL^T factorisation on the pattern analysed once in the constructor,
///    later iterations that change few nodes delete/add those rows of the factor (CHOLMOD
///    rowdel/rowadd, backend kCholmodModify) instead of refactorising.
///  - kJfo: mass-conserving Jakobsson-Floberg-Olsson cavitation in the complementarity form of
///    Giacopini, Fowell, Dini & Strozzi (2010, J. Tribol. 132 041702): lubricant density ratio
///    1 - r, with p >= 0, r >= 0, p.r = 0 and one mass balance per node
///        (K p - f)_k + (B r)_k = 0,
///    B = finite-volume transport of the void content (U_sum/2) h_f r (and of the roughness's
///    shear flow's void part, (U_diff/2) sigma phi_s,f r, along its own direction) plus -r dh_T/dt,
///    on the dual cells of the structured mesh: the mean gap at the cell face h_f centred, the
///    fraction r of the upwind node (a full film's Couette flow second order, a cavity's first
///    order). The mean gap h_T = h + NodalFilmFactors::mean_gap_excess is the oil a full rough film
///    holds per unit area (dh_T/dh = phi_c; h for smooth surfaces and from H = 3 on). Solved by the
///    same active-set (semismooth Newton) iteration on the mixed unknowns (p on full-film nodes, r
///    on cavitated ones), started from the Reynolds solution; non-symmetric, so a sparse LU is
///    used. Quasi-static (ReynoldsParams::time_step = 0): d(r h_T)/dt ~ r phi_c dh/dt, no history.
///    Transient (time_step > 0): the void content V = r h_T of every node is carried from the
///    previous step (void_history()) and its rate is the backward difference (V - V_old) / dt
///    (lumped), while the full-film squeeze phi_c dh/dt keeps the exact dh/dt of the caller (a
///    function of the state, so an ODE integrator's error control covers it). The nodal balances
///    then conserve oil exactly through rupture and reformation: the void that collapses where the
///    film reforms must be filled by the flow (Elrod-Adams / JFO in the time-dependent form of
///    Ausas et al. 2009, J. Tribol. 131 031702). Fixed nodes carry a prescribed fluid fraction
///    (boundary_fraction(), default 1): a starved inlet brings the void 1 - theta into the film
///    with its Couette flow.
///  - kNone: full Sommerfeld film, negative pressures allowed (verification only).
#include <Eigen/Sparse>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/base/stop.hpp"
#include "core/lubrication/film_factors.hpp"
#include "core/lubrication/film_models.hpp"
#include "core/lubrication/oil.hpp"
#include "core/lubrication/sparse_ldlt.hpp"
#include "core/lubrication/sparse_lu.hpp"
#include "core/lubrication/tri_mesh.hpp"

namespace filmdyn::lubrication {

/// Numerical status of one solve (numerical trouble is a status, never an exception: docs/conventions.md).
enum class SolveStatus { kConverged, kNotConverged, kFactorizationFailed };
const char* ToString(SolveStatus status);

struct ReynoldsOptions {
  CavitationModel cavitation = CavitationModel::kReynolds;
  LdltBackend backend = LdltBackend::kCholmodModify;  // fastest measured (docs/performance.md)
  int max_iterations = 200;  ///< active-set iterations before giving up (status kNotConverged)
  bool warm_start = true;    ///< start the active set from the previous solve's
  /// Active set of a cold start (no previous solve): kSinkNodes = nodes with f_k < 0 (a
  /// diverging wedge; fewer iterations on journal bearings), kUnconstrained = none, i.e. the
  /// first iteration is the unconstrained solve (fewer iterations on skirts, measured).
  enum class ColdStart { kSinkNodes, kUnconstrained };
  ColdStart cold_start = ColdStart::kSinkNodes;
  /// Factor reuse: a solve whose active set starts where the last one ended (warm start, the
  /// time-stepping case) first tries the conjugate-gradient method on the new matrix,
  /// preconditioned by the previous LDL^T factor (exact for the previous matrix, which differs
  /// from the new one by the small change of h between time steps / Newton iterates). Only when
  /// it has not converged after pcg_max_iterations is the matrix refactorised. Off = every solve
  /// refactorises (the reference; results agree to ~pcg_tolerance).
  bool reuse_factorization = true;
  int pcg_max_iterations = 6;
  /// Convergence: max|M^-1 r| <= pcg_tolerance * max|p| (M^-1 r is the correction the
  /// preconditioner would apply, i.e. ~ the error of p).
  double pcg_tolerance = 1e-11;
  /// JFO transient films: the fluid fraction the Couette flow carries through a dual-cell face.
  /// 2 (default): reconstructed at the face from the upwind node's fraction and its limited
  /// slope (minmod of the slopes on either side), the slope taken from the last accepted
  /// state's fractions (a deferred correction, so that each solve stays one linear complementarity
  /// problem) — second order where the partial film is smooth, and no new extremum.
  /// 1: the upwind node's own fraction (first order; kept for the verification's comparison).
  /// Quasi-static solves (time_step = 0) carry the upwind node's fraction in either case.
  int void_transport_order = 2;
};

/// Scalars of one solve. Nodal inputs are set through ReynoldsFem's mutable accessors.
struct ReynoldsParams {
  double viscosity = 0.0;                 ///< dynamic viscosity mu [Pa s]
  double u_sum = 0.0;                     ///< U1 + U2 along the sliding axis [m/s]
  double u_diff = 0.0;                    ///< U1 - U2 along the sliding axis [m/s]
  const FilmFactorModel* film = nullptr;  ///< nullptr = smooth surfaces
  /// JFO only: 0 = quasi-static; > 0 = transient, the time [s] since the state whose void
  /// content is in ReynoldsFem::void_history().
  double time_step = 0.0;
  /// JFO transient only: the oil's bulk modulus beta [Pa] at low pressure (0 = incompressible).
  /// The full film then stores h_T g(p) more oil than its gap holds at the cavitation pressure,
  /// g = rho / rho0 - 1 after `density_law` (Compression, oil.hpp); the fluxes keep the density
  /// rho0. Not with a pressure-dependent viscosity (the solve is in the reduced pressure there).
  double bulk_modulus = 0.0;
  DensityLaw density_law = DensityLaw::kLinear;
  /// Pressure-dependent viscosity (nullptr or law kNone: mu = viscosity everywhere): the film is
  /// solved for the reduced pressure and the pressure recovered (oil.hpp); `viscosity` is mu at
  /// zero gauge pressure.
  const PressureViscosity* pressure_viscosity = nullptr;
  /// Shear thinning (nullptr or inactive: Newtonian): each node's viscosity is `viscosity` times
  /// CrossLaw::InFilm(u_diff, h) (times the pressure law's ratio, which the reduced pressure
  /// carries).
  const CrossLaw* shear_thinning = nullptr;
};

/// Statistics of one solve.
struct ReynoldsStats {
  SolveStatus status = SolveStatus::kConverged;
  int iterations = 0;      ///< active-set iterations (linear solves)
  int jfo_iterations = 0;  ///< of which in the JFO stage
  int factorizations = 0;  ///< numeric LDL^T factorisations (Reynolds stage)
  int row_updates = 0;     ///< CHOLMOD row deletions/additions instead of those
  int pcg_solves = 0;      ///< linear solves by CG preconditioned with an earlier factor
  int pcg_iterations = 0;  ///< CG iterations of those (each: one product, one factor solve)
  int pcg_fallbacks = 0;   ///< CG attempts that did not converge (then refactorised)
  double complementarity_residual = 0;  ///< max_k |min(p_k/p_ref, w_k/w_ref)| over free nodes
  double min_pressure = 0;              ///< most negative nodal pressure [Pa] (0 when exact)
  double max_mass_residual = 0;         ///< JFO: max nodal mass-balance residual / flow scale
  /// JFO: how far the fluid fraction leaves [0, 1] (max of -theta and theta - 1, 0 when inside).
  double fraction_excess = 0;
  /// Pressure-dependent viscosity: nodes whose reduced pressure reached the law's limit (the
  /// pressure would be infinite; there it is capped at the law's largest finite value). A film
  /// with such nodes carries more than the oil can at these surfaces (oil.hpp).
  int capped_nodes = 0;
  double assembly_s = 0, factorization_s = 0, complementarity_s = 0;  ///< wall times [s]

  /// Merges the statistics of an independent solve of the same step (e.g. the other panel of
  /// the skirt): counts and times add, residuals take the worst, a failure status is kept.
  void Add(const ReynoldsStats& other);
};

/// Fields of one solve; all vectors have one entry per mesh node.
struct ReynoldsSolution {
  Eigen::VectorXd pressure;             ///< p [Pa] (gauge, relative to the cavitation pressure)
  Eigen::VectorXd contact_pressure;     ///< asperity pressure p_c [Pa]
  Eigen::VectorXd fluid_fraction;       ///< JFO theta = 1 - r (1 in the full film) [-]
  /// JFO: the oil the node's film lacks against a full film at the cavitation pressure, per
  /// unit area [m]: the void content (1 - theta) h_T (h_T the mean gap), less the compressed oil
  /// h_T g(p) of a compressible full film (ReynoldsParams::bulk_modulus; negative there); 0 on
  /// fixed nodes. The next transient step's void_history().
  Eigen::VectorXd void_content;
  Eigen::VectorXd residual;             ///< w = K p - f (+B r): nodal net outflow [m^3/s]; at
                                        ///< fixed nodes minus the boundary outflow
  std::vector<std::uint8_t> cavitated;  ///< 1 where the film is cavitated (active set)
  /// The oil balance's terms: the sum of the fixed nodes' residuals (net flow into the film
  /// through its boundary) equals squeeze_rate - (void_volume - void volume of the history) / dt
  /// for a transient JFO solve (squeeze_rate alone when quasi-static or Reynolds, plus the
  /// Reynolds condition's unbalanced cavitated nodes).
  /// integral of phi_c dh/dt over the film [m^3/s], less (transient JFO) the void a step's
  /// rate makes beyond a cell's gap, sum of A r (c - h_T) / dt (SolveJfo: the void's capacity)
  double squeeze_rate = 0.0;
  double void_volume = 0.0;   ///< sum of lumped area x void_content [m^3]
  /// Oil-covered area [m^2]: the lumped integral of theta (JFO), of the uncavitated nodes
  /// (Reynolds, which tracks no oil in a cavity).
  double wetted_area = 0.0;
  ReynoldsStats stats;
};

/// A prescribed-pressure region whose edge lies between two nodes (an embedded Dirichlet
/// boundary, e.g. a round supply hole on a rectangular mesh): the mesh edge from the free node
/// to the fixed node crosses the region's boundary at `fraction` of its length from the free
/// node. The edge's pressure-flow conductance is taken over that shorter distance, K/fraction
/// (the symmetric embedded-boundary discretisation of Gibou, Fedkiw, Cheng & Kang 2002, J.
/// Comput. Phys. 176:205): the flow into the film then sees the region's true edge instead of
/// the nearest node's, second order where the node-held region is first, and it changes
/// continuously as the region moves over the mesh instead of a node at a time.
struct EmbeddedCut {
  int free_node = -1;
  int fixed_node = -1;
  double fraction = 1.0;  ///< in [0, 1]; taken as at least kMinFraction
  /// Shortest distance taken: the edge's conductance is at most 1/kMinFraction times the
  /// mesh's (a node this close is at the region's pressure to ~1e-3 of the drop anyway).
  static constexpr double kMinFraction = 1e-3;
};

/// Reusable Reynolds solver on one mesh: constructed once (pattern + symbolic analysis), then
/// Solve() any number of times without reallocating.
class ReynoldsFem {
 public:
  /// sliding_axis: 0 = mesh x, 1 = mesh y.
  ReynoldsFem(TriMesh mesh, int sliding_axis, ReynoldsOptions options);
  ~ReynoldsFem();
  ReynoldsFem(const ReynoldsFem&) = delete;
  ReynoldsFem& operator=(const ReynoldsFem&) = delete;

  const TriMesh& mesh() const { return mesh_; }
  const ReynoldsOptions& options() const { return options_; }
  /// Called at every iteration of a solve (active set, JFO, CG): when it returns true the solve
  /// throws filmdyn::StopRequested (a cancel honoured within one iteration on any mesh). The
  /// solver must not be used again after that.
  void SetStopCheck(StopCheck check) { stop_check_ = std::move(check); }
  /// 0 = mesh x, 1 = mesh y (the constructor's sliding_axis).
  int sliding_axis() const { return axis_; }
  void set_cavitation(CavitationModel model) { options_.cavitation = model; }
  int NodeCount() const { return mesh_.NodeCount(); }

  /// Nodal inputs, filled by the caller before each Solve().
  Eigen::VectorXd& film_thickness() { return h_; }           ///< h [m], must be > 0
  Eigen::VectorXd& film_rate() { return dhdt_; }             ///< dh/dt [m/s]
  Eigen::VectorXd& boundary_pressure() { return p_fixed_; }  ///< p on fixed nodes [Pa] (>= 0)
  std::vector<std::uint8_t>& extra_fixed() { return extra_fixed_; }  ///< per-solve Dirichlet
  /// Per-solve embedded edges of the extra_fixed() regions (empty: a region ends at its fixed
  /// nodes, the pressure falling from them over whole mesh edges: the plain finite-element
  /// boundary).
  std::vector<EmbeddedCut>& embedded_cuts() { return cuts_; }
  /// JFO: fluid fraction theta on fixed nodes, in (0, 1] (default 1: a flooded boundary).
  Eigen::VectorXd& boundary_fraction() { return theta_fixed_; }
  /// JFO: the oil content theta h_T [m] a starved fixed node holds (empty, or <= 0 at a node:
  /// boundary_fraction() holds there). Where it is > 0, each solve takes that node's fraction
  /// as oil / h_T at its own mean gap h_T, 1 where h_T <= oil (a closed gap too), and writes it
  /// into boundary_fraction(), where it stays: a caller that later stops giving a node oil
  /// sets its fraction again. The supply then stays the given oil when the gap changes from
  /// solve to solve, as an elastic surface's deformation changes it within one step.
  Eigen::VectorXd& boundary_oil() { return oil_fixed_; }
  /// Transient JFO: the void content [m] per node at the start of the step (the previous
  /// solve's ReynoldsSolution::void_content; zero = a full film).
  Eigen::VectorXd& void_history() { return void_old_; }
  /// The mean gap h_T = h + NodalFilmFactors::mean_gap_excess [m] of the last solve.
  const Eigen::VectorXd& mean_gap() const { return h_mean_; }
  const Eigen::VectorXd& film_thickness() const { return h_; }
  const Eigen::VectorXd& film_rate() const { return dhdt_; }

  /// Solves for the current nodal inputs. Returns a reference valid until the next Solve().
  const ReynoldsSolution& Solve(const ReynoldsParams& params);
  const ReynoldsSolution& solution() const { return sol_; }

  /// Nodal roughness factors of the last solve.
  const std::vector<NodalFilmFactors>& factors() const { return factors_; }
  /// Integral of the product of two P1 fields over the mesh (exact) [unit a * unit b * m^2].
  double IntegrateProduct(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const;
  /// Integral of one P1 field.
  double Integrate(const Eigen::VectorXd& a) const;
  /// Lumped nodal areas [m^2].
  const std::vector<double>& lumped_area() const { return lumped_area_; }
  /// Element geometry: area and shape-function gradients.
  struct Element {
    std::array<int, 3> node;
    double area;
    std::array<double, 3> dndx, dndy;
  };
  const std::vector<Element>& elements() const { return elements_; }
  /// True when every off-diagonal of the last assembled matrix is <= 0 (M-matrix check).
  bool LastMatrixIsMMatrix() const;
  /// The last assembled stiffness matrix (lower triangle) and load vector, for benchmarks.
  const Eigen::SparseMatrix<double>& stiffness_lower() const { return k_lower_; }
  const Eigen::VectorXd& load() const { return f_; }

 private:
  void Assemble(const ReynoldsParams& params);
  void ApplyEmbeddedCuts();
  bool SolveReynoldsLcp(bool unconstrained);
  // x = W^-1 rhs_ by CG preconditioned with the current factor (W = K with the cut rows and
  // columns of `cut_` replaced by their diagonal). False when not converged in the budget.
  bool SolvePcg(Eigen::VectorXd& x, bool x_is_guess);
  void ApplyMasked(const Eigen::VectorXd& in, Eigen::VectorXd& out);
  bool SolveJfo();
  void FinishStats();

  TriMesh mesh_;
  int axis_;
  ReynoldsOptions options_;
  StopCheck stop_check_;
  std::vector<Element> elements_;
  std::vector<double> lumped_area_;
  // Lower-triangular stiffness (SPD solver) and its full version (JFO LU), same element maps.
  Eigen::SparseMatrix<double> k_lower_, work_lower_, k_full_, m_full_;
  std::vector<std::array<int, 6>> elem_pos_lower_;  // (00,11,22,10,20,21) -> value index
  std::vector<std::array<int, 9>> elem_pos_full_;
  std::vector<std::array<double, 12>> elem_geometry_;  // A dN_r/dx dN_c/dx, then the y parts
  std::vector<int> nz_row_, nz_col_;                   // lower pattern: row/col of each value
  std::vector<int> full_col_of_;                       // full pattern: col of each value
  std::vector<int> diag_pos_full_, down_pos_plus_, down_pos_minus_;  // JFO transport slots
  std::vector<int> down_node_plus_, down_node_minus_;
  std::vector<double> face_width_;  // dual-cell width across the sliding direction [m]
  std::vector<double> down_gap_plus_, down_gap_minus_;  // distance to that neighbour [m]
  std::vector<int> up_node_plus_, up_node_minus_;       // the node whose downstream is k
  Eigen::VectorXd fraction_old_, face_correction_;      // JFO second-order transport (scratch)
  Eigen::VectorXd h_face_;  // JFO: mean gap carried by the Couette flux from node k downstream [m]
  /// JFO: the roughness's shear flow through the face from node k to its neighbour along
  /// shear_plus_ ? +s : -s (|(U1 - U2)/2 sigma phi_s| w) [m^3/s]; 0 without one.
  Eigen::VectorXd shear_face_;
  bool shear_plus_ = true;
  std::unique_ptr<SparseLdlt> ldlt_;
  std::unique_ptr<SparseLu> lu_;  // JFO: the mixed (p, r) system
  Eigen::VectorXd h_, dhdt_, p_fixed_, f_, rhs_, x_, work_, theta_fixed_, void_old_, oil_fixed_;
  Eigen::VectorXd reduced_, boundary_saved_;  // pressure-dependent viscosity: q, and p_fixed_
  double time_step_ = 0.0;
  Compression compression_;  // JFO transient: the oil's g(p) (none: incompressible)
  // JFO: each free node's compressed-oil storage A h_T g'(p*) / dt, and the part of its
  // linearisation about p* that is known, A h_T (g(p*) - g'(p*) p*) / dt (0 for a linear law).
  Eigen::VectorXd compress_, compress_known_, compress_about_;
  std::vector<EmbeddedCut> cuts_;
  std::vector<std::uint8_t> extra_fixed_, fixed_, active_, prev_active_, next_active_;
  bool have_prev_ = false;
  bool jfo_warm_ = false;  // prev_active_ holds the cavitated set of a converged JFO solve
  // The matrix the LDL^T factor belongs to: per node 0 free, 1 active (cavitated), 2 fixed
  // (unit or diagonal row); factor_ready_ once a factorisation succeeded.
  std::vector<std::uint8_t> cut_, factor_cut_;
  bool factor_ready_ = false, full_assembled_ = false;
  Eigen::VectorXd pcg_r_, pcg_z_, pcg_d_, pcg_q_, pcg_t_;
  std::vector<NodalFilmFactors> factors_;
  std::vector<int> add_rows_;
  std::vector<double> add_values_;
  Eigen::VectorXd phi_c_, source_scale_;
  Eigen::VectorXd void_capacity_;  // JFO transient: the void's capacity per node (scratch) [m]
  /// JFO transient: the storage rate the capacity's excess over the gap takes from the film
  /// (SolveJfo) [m^3/s], booked in ReynoldsSolution::squeeze_rate.
  double capacity_rate_ = 0.0;
  /// The mean gap h_T = h + NodalFilmFactors::mean_gap_excess [m]: a JFO film's oil capacity and
  /// what its Couette flow carries (h for smooth surfaces and from H = 3 on).
  Eigen::VectorXd h_mean_;
  double u_sum_ = 0, flow_scale_ = 1;
  ReynoldsSolution sol_;
};

}  // namespace filmdyn::lubrication
