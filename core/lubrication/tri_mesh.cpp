#include "core/lubrication/tri_mesh.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <stdexcept>

namespace filmdyn::lubrication {

double TriMesh::ColumnWidth(int i) const {
  const int n = nx_nodes();
  if (periodic_x && i == n - 1) return x_period - x_lines[n - 1];
  return x_lines[i + 1] - x_lines[i];
}

TriMesh MakeStripMesh(double length, int n, double width) {
  return MakeStripMesh(Linspace(0.0, length, n), width);
}

TriMesh MakeStripMesh(std::vector<double> x_lines, double width) {
  TriMesh mesh = MakeTensorMesh(std::move(x_lines), Linspace(0.0, width, 1), false, 0.0);
  const int nx = mesh.nx_nodes();
  for (int j = 0; j < 2; ++j) {
    mesh.fixed[mesh.Node(0, j)] = 1;
    mesh.fixed[mesh.Node(nx - 1, j)] = 1;
  }
  return mesh;
}

std::vector<double> Linspace(double a, double b, int n) {
  std::vector<double> v(n + 1);
  for (int k = 0; k <= n; ++k) v[k] = a + (b - a) * static_cast<double>(k) / n;
  v[n] = b;  // exact end point
  return v;
}

std::vector<double> ConformingLines(double a, double b, int n, const std::vector<double>& breaks) {
  const double tiny = 1e-9 * (b - a);
  std::vector<double> ends{a};
  std::vector<double> inside(breaks);
  std::sort(inside.begin(), inside.end());
  for (double x : inside) {
    if (x > ends.back() + tiny && x < b - tiny) ends.push_back(x);
  }
  ends.push_back(b);
  const int segments = static_cast<int>(ends.size()) - 1;
  if (segments == 1 || n < segments) return Linspace(a, b, n);
  // Each segment gets one interval, then each further interval goes to the segment whose
  // spacing is largest (greedy: minimises the largest spacing).
  std::vector<int> count(static_cast<std::size_t>(segments), 1);
  auto spacing = [&](int s) { return (ends[s + 1] - ends[s]) / count[s]; };
  for (int k = segments; k < n; ++k) {
    int widest = 0;
    for (int s = 1; s < segments; ++s) {
      if (spacing(s) > spacing(widest) * (1.0 + 1e-12)) widest = s;
    }
    ++count[widest];
  }
  std::vector<double> lines{a};
  for (int s = 0; s < segments; ++s) {
    const std::vector<double> part = Linspace(ends[s], ends[s + 1], count[s]);
    lines.insert(lines.end(), part.begin() + 1, part.end());
  }
  return lines;
}

TriMesh MakeTensorMesh(std::vector<double> x_lines, std::vector<double> y_lines, bool periodic_x,
                       double x_period) {
  // Meshes are built by our own joint code from validated counts: bad sizes here are bugs.
  if (x_lines.size() < 2 || y_lines.size() < 2) {
    throw std::logic_error("MakeTensorMesh: need at least 2 lines per direction");
  }
  TriMesh m;
  m.x_lines = std::move(x_lines);
  m.y_lines = std::move(y_lines);
  m.periodic_x = periodic_x;
  m.x_period = x_period;
  const int nx = m.nx_nodes();
  const int ny = m.ny_nodes();
  m.x.resize(static_cast<size_t>(nx) * ny);
  m.y.resize(m.x.size());
  m.fixed.assign(m.x.size(), 0);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      m.x[m.Node(i, j)] = m.x_lines[i];
      m.y[m.Node(i, j)] = m.y_lines[j];
    }
  }
  const int ncol = m.ElementColumns();
  m.triangles.reserve(static_cast<size_t>(2) * ncol * (ny - 1));
  for (int j = 0; j + 1 < ny; ++j) {
    for (int i = 0; i < ncol; ++i) {
      const int i1 = (i + 1) % nx;
      const int a = m.Node(i, j), b = m.Node(i1, j), c = m.Node(i1, j + 1), d = m.Node(i, j + 1);
      // Two right triangles per rectangle, right angles at a and c: legs along x and y.
      m.triangles.push_back({a, b, d});
      m.triangles.push_back({c, d, b});
    }
  }
  return m;
}

std::vector<double> LumpedAreas(const TriMesh& mesh) {
  std::vector<double> area(mesh.NodeCount(), 0.0);
  for (const auto& t : mesh.triangles) {
    // Right triangle with legs along the axes: node 0 is the right angle (see MakeTensorMesh).
    const double lx = std::abs(mesh.x[t[1]] - mesh.x[t[0]]);
    const double ly = std::abs(mesh.y[t[2]] - mesh.y[t[0]]);
    double wx = lx;
    if (mesh.periodic_x && lx > 0.5 * mesh.x_period) wx = mesh.x_period - lx;  // wrap column
    const double third = 0.5 * wx * ly / 3.0;  // integral of N_k over a triangle is A/3
    for (int k = 0; k < 3; ++k) area[t[k]] += third;
  }
  return area;
}

}  // namespace filmdyn::lubrication
