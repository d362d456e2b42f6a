#pragma once
/// @file A surface compliance exported by a finite-element code, read from files and carried onto
/// the film's mesh.
///
/// Files (docs/compliance-files.md):
///  - the matrix, Matrix Market (`%%MatrixMarket matrix coordinate|array real
///    general|symmetric`): m x m, C_ij [m/N] = the film's opening at FE node i per unit normal
///    force at FE node j pushing the surfaces apart (the normal-direction compliance of the
///    surface: for an FE model, the inverse of its reduced stiffness projected on the normals);
///  - the nodes, CSV with the header `x[m],y[m]` and one row per matrix row, in the film's own
///    surface coordinates (a bearing: x = R psi around the bearing body from its reference axis,
///    y across the width from one edge; a skirt panel: x = R alpha from the thrust axis, y from the
///    skirt top). The nodes must form a tensor grid (every x with every y), in any order.
/// The matrix must be symmetric (to 1e-9 of its largest entry) and positive definite.
///
/// On the film: the pressure on each film node's lumped area is a force, spread to the FE nodes
/// by the bilinear weights of the node's position in the FE grid (and of its mirror image when
/// the film is a symmetric half); the FE nodes' displacements come back by the same weights. So
/// the film's compliance is T C T' A, applied in O(m^2 + n) without forming it.
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/lubrication/tri_mesh.hpp"

namespace filmdyn::lubrication {

struct ImportedCompliance {
  std::string source;           ///< the matrix file, for messages
  Eigen::MatrixXd matrix;       ///< m x m [m/N], in grid order (node i + j * nx)
  std::vector<double> x_lines;  ///< the grid's x, increasing [m]
  std::vector<double> y_lines;  ///< the grid's y, increasing [m]
  int NodeCount() const { return static_cast<int>(x_lines.size() * y_lines.size()); }
};

/// The nodes file that goes with a matrix file: its name with the extension replaced by
/// `.nodes.csv` (housing.mtx -> housing.nodes.csv).
std::string NodesFileFor(const std::string& matrix_path);

/// The most FE nodes an imported compliance may have: its matrix and the matrix's factor are
/// dense (8 m^2 bytes each: 0.8 GB at 10 000 nodes).
inline constexpr std::size_t kMaxImportedNodes = 10000;
/// The largest files read: a nodes file of that many rows is under 1 MB; a matrix of that size in
/// the coordinate format about 4 GB.
inline constexpr std::uintmax_t kMaxNodesFileBytes = std::uintmax_t{64} << 20;
inline constexpr std::uintmax_t kMaxMatrixFileBytes = std::uintmax_t{8} << 30;

/// Reads the matrix file and its nodes file (NodesFileFor).
ImportedCompliance ReadImportedCompliance(const std::string& matrix_path);

/// Reads and checks the two files. Throws filmdyn::InputError naming the file, the line and the
/// value: not a regular file or too large, not Matrix Market, not real, a size that does not match
/// the nodes, entries missing or not finite, not symmetric, not positive definite; a nodes file
/// without its header, with a row that is not two finite numbers, nodes that do not form a grid,
/// more than kMaxImportedNodes nodes.
ImportedCompliance ReadImportedCompliance(const std::string& matrix_path,
                                          const std::string& nodes_path);

/// Writes the two files (array format, symmetric; the nodes in grid order) [for tools, tests].
void WriteImportedCompliance(const ImportedCompliance& c, const std::string& matrix_path,
                             const std::string& nodes_path);

/// The imported compliance on a film mesh: film node k's bilinear weights in the FE grid (and
/// those of its mirror image).
class ComplianceTransfer {
 public:
  /// `mirror_y` (`mirror_x`): the film mesh is one half of a film symmetric about y = mirror_y
  /// (x = mirror_x), whose other half loads the FE surface too. `period`: the FE grid is periodic
  /// in x with this period (a whole bearing; 0: not periodic). Throws InputError naming `field`
  /// when a film node (or its mirror image) lies outside the FE grid.
  ComplianceTransfer(std::shared_ptr<const ImportedCompliance> fe, const TriMesh& mesh,
                     std::optional<double> mirror_y, std::optional<double> mirror_x, double period,
                     const std::string& field);
  /// The film's x is the FE grid's x minus `offset` [m] (a bearing's film turns with its line
  /// of centres): the weights are recomputed when it changes.
  void SetOffset(double offset);
  /// Whether the film moves over the FE grid (a periodic grid: SetOffset turns the film).
  bool Moves() const { return period_ > 0.0; }
  /// The film's deformation under `load` [Pa]: the FE matrix applied without its smallest
  /// coefficients (those of a row whose magnitudes sum to at most kDroppedShare of the row's):
  /// the deformation differs from the whole matrix's by at most kDroppedShare of the largest
  /// row sum times the largest load.
  void Apply(const Eigen::VectorXd& load, Eigen::VectorXd& out) const;
  double Diagonal(int k) const;
  bool Nonnegative() const { return nonnegative_; }
  static constexpr double kDroppedShare = 1e-6;
  /// Coefficients kept of the FE matrix (a share of its size).
  double KeptShare() const;

 private:
  struct Weights {
    std::array<int, 4> node{};
    std::array<double, 4> w{};
  };
  // One axis's bilinear part: the grid lines i0, i1 around the point and its share s of the way.
  struct AxisPart {
    int i0 = 0, i1 = 0;
    double s = 0.0;
  };
  AxisPart XPart(double x) const;  // throws InputError naming the film point outside the grid
  AxisPart YPart(double y) const;
  // A non-periodic axis: its grid lines, the point, the axis's name ("x", "y") for the error.
  AxisPart BoundedPart(const std::vector<double>& lines, double v, const char* axis) const;
  void Compute();

  std::shared_ptr<const ImportedCompliance> fe_;
  std::vector<double> film_x_, film_y_, area_;
  std::optional<double> mirror_y_, mirror_x_;
  double period_ = 0.0, offset_ = 0.0;
  std::string field_;
  std::vector<Weights> own_, mirror_;
  // Compute's cache: the film's distinct x values, each node's (and mirror image's) among them
  // and y part; the x parts at the current offset (kept to spare the allocation per offset).
  std::vector<double> x_keys_;
  std::vector<int> key_own_, key_mirror_;
  std::vector<AxisPart> y_own_, y_mirror_, x_parts_;
  bool nonnegative_ = false;
  Eigen::SparseMatrix<double> kept_;  // the FE matrix without its dropped coefficients
  mutable Eigen::VectorXd force_, displacement_;
};

}  // namespace filmdyn::lubrication
