#pragma once
/// @file Structured meshes of linear (P1) triangles for the Reynolds equation.
/// Every mesh is a tensor grid of axis-aligned rectangles, each split into two right triangles
/// whose legs are parallel to the axes. With a diagonal conductivity tensor this makes the P1
/// stiffness matrix an M-matrix (the hypotenuse couplings vanish exactly, all other off-diagonals
/// are <= 0), which is what gives the primal-dual active-set LCP solver its finite termination
/// (Hintermueller, Ito & Kunisch 2003, SIAM J. Optim. 13(3) 865-888).
#include <array>
#include <cstdint>
#include <vector>

namespace filmdyn::lubrication {

/// A planar P1 triangle mesh on a (possibly x-periodic) rectangle. x is the first surface
/// coordinate (arc length [m]), y the second [m]. Nodes are numbered i + j * nx_nodes.
struct TriMesh {
  std::vector<double> x_lines;  ///< distinct node x coordinates [m], increasing
  std::vector<double> y_lines;  ///< distinct node y coordinates [m], increasing
  bool periodic_x = false;   ///< last x column wraps onto the first (x_lines excludes x = period)
  double x_period = 0.0;     ///< [m], only when periodic_x
  std::vector<double> x, y;  ///< node coordinates [m]
  std::vector<std::array<int, 3>> triangles;  ///< counter-clockwise, node 0 at the right angle
  std::vector<std::uint8_t> fixed;  ///< 1 where p is prescribed (Dirichlet) by the mesh itself

  int nx_nodes() const { return static_cast<int>(x_lines.size()); }
  int ny_nodes() const { return static_cast<int>(y_lines.size()); }
  int NodeCount() const { return static_cast<int>(x.size()); }
  int Node(int i, int j) const { return i + j * nx_nodes(); }
  /// Number of element columns along x (n for periodic meshes, n-1 otherwise).
  int ElementColumns() const { return periodic_x ? nx_nodes() : nx_nodes() - 1; }
  /// Width of element column i along x [m] (handles the periodic wrap).
  double ColumnWidth(int i) const;
};

/// Builds the tensor mesh on the given lines. For periodic meshes x_lines must start at 0 and
/// stay below `x_period`; the element between the last line and x_period wraps to node column 0.
TriMesh MakeTensorMesh(std::vector<double> x_lines, std::vector<double> y_lines, bool periodic_x,
                       double x_period);

/// A strip of n x 1 elements along x on [0, length] x [0, width], both ends' nodes fixed: the
/// mesh of one-dimensional verification problems (no flow across the strip's sides).
TriMesh MakeStripMesh(double length, int n, double width);
/// The same strip on given node lines along x (first 0, last the length).
TriMesh MakeStripMesh(std::vector<double> x_lines, double width);

/// Evenly spaced lines: n intervals on [a, b] (n + 1 values).
std::vector<double> Linspace(double a, double b, int n);

/// n intervals on [a, b] with a line on every break strictly inside (a, b) — the kinks of a
/// piecewise-linear surface table — and spacing as even as the breaks allow: the segments
/// between breaks share the n intervals so that the largest spacing is smallest, each segment
/// evenly divided. A film thickness with a kink between two nodes is interpolated across it,
/// an O(h) error that makes mesh convergence erratic; with the kinks on nodes it converges at
/// the scheme's order. Breaks closer than 1e-9 (b - a) to another line are ignored; with fewer
/// intervals than segments the lines are evenly spaced (Linspace).
std::vector<double> ConformingLines(double a, double b, int n, const std::vector<double>& breaks);

/// Per-node lumped area (integral of the shape function) [m^2].
std::vector<double> LumpedAreas(const TriMesh& mesh);

}  // namespace filmdyn::lubrication
