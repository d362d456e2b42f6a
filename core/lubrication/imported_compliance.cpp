#include "core/lubrication/imported_compliance.hpp"

#include <fmt/format.h>
#include <Eigen/Cholesky>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "core/base/input_error.hpp"
#include "core/base/input_file.hpp"

namespace filmdyn::lubrication {

namespace {

double Number(const std::string& where, const std::string& text) {
  // ParseNumber, not strtod: the same in every locale (the GUI runs under the user's), and a value
  // below the smallest normal double (1e-309) reads as what it is, a finite number.
  double v = 0.0;
  if (ParseNumber(text, v) && std::isfinite(v)) return v;
  throw InputError(where, "\"" + text + "\"", "must be a finite number");
}

// The distinct values of v (to 1e-9 of their span), increasing.
std::vector<double> Distinct(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const double tol = 1e-9 * std::max(1e-300, v.back() - v.front());
  std::vector<double> out;
  for (double x : v)
    if (out.empty() || x - out.back() > tol) out.push_back(x);
  return out;
}

int IndexOf(const std::vector<double>& lines, double x) {
  const double tol = 1e-9 * std::max(1e-300, lines.back() - lines.front());
  auto it = std::lower_bound(lines.begin(), lines.end(), x - tol);
  if (it == lines.end() || std::abs(*it - x) > tol) return -1;
  return static_cast<int>(it - lines.begin());
}

}  // namespace

std::string NodesFileFor(const std::string& matrix_path) {
  return std::filesystem::path(matrix_path).replace_extension(".nodes.csv").string();
}

ImportedCompliance ReadImportedCompliance(const std::string& matrix_path) {
  return ReadImportedCompliance(matrix_path, NodesFileFor(matrix_path));
}

ImportedCompliance ReadImportedCompliance(const std::string& matrix_path,
                                          const std::string& nodes_path) {
  ImportedCompliance c;
  c.source = matrix_path;
  // Nodes first: they say the size. Regular files only (a FIFO would wait for a writer forever,
  // /dev/zero never end), bounded.
  RequireInputFile(nodes_path, "compliance nodes file", kMaxNodesFileBytes);
  RequireInputFile(matrix_path, "compliance matrix file", kMaxMatrixFileBytes);
  std::ifstream nodes(nodes_path);
  if (!nodes) throw InputError(nodes_path, "(unreadable)", "a readable nodes CSV file");
  std::string line;
  int line_number = 0;
  std::vector<double> xs, ys;
  bool header = false;
  while (std::getline(nodes, line)) {
    ++line_number;
    // A byte-order mark, as some editors write UTF-8, is no part of the header.
    if (line_number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    const std::string text = Trim(line);
    if (text.empty() || text[0] == '#') continue;
    const std::string where = nodes_path + ":" + std::to_string(line_number);
    if (!header) {
      std::string h = Lower(text);
      h.erase(std::remove(h.begin(), h.end(), ' '), h.end());
      if (h != "x[m],y[m]") throw InputError(where, "\"" + text + "\"", "the header x[m],y[m]");
      header = true;
      continue;
    }
    const auto comma = text.find(',');
    if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos)
      throw InputError(where, "\"" + text + "\"", "two numbers x,y [m]");
    xs.push_back(Number(where + " x[m]", Trim(text.substr(0, comma))));
    ys.push_back(Number(where + " y[m]", Trim(text.substr(comma + 1))));
  }
  if (!header) throw InputError(nodes_path, "(no header)", "the header x[m],y[m] and the nodes");
  if (xs.size() < 4) {
    throw InputError(nodes_path, std::to_string(xs.size()) + " nodes",
                     "at least 4 nodes (a 2 x 2 grid)");
  }
  if (xs.size() > kMaxImportedNodes) {
    throw InputError(nodes_path, std::to_string(xs.size()) + " nodes",
                     fmt::format("at most {} (the compliance matrix and its factor are dense: "
                                 "8 m^2 bytes each, 0.8 GB at that size)",
                                 kMaxImportedNodes));
  }
  c.x_lines = Distinct(xs);
  c.y_lines = Distinct(ys);
  const std::size_t m = xs.size();
  if (c.x_lines.size() < 2 || c.y_lines.size() < 2 || c.x_lines.size() * c.y_lines.size() != m) {
    throw InputError(
        nodes_path,
        fmt::format("{} nodes on {} x and {} y values", m, c.x_lines.size(), c.y_lines.size()),
        "nodes forming a tensor grid: every x with every y, once each");
  }
  // Row r of the file is grid node grid[r].
  const int nx = static_cast<int>(c.x_lines.size());
  std::vector<int> grid(m);
  std::vector<int> seen(m, -1);
  for (std::size_t r = 0; r < m; ++r) {
    const int g = IndexOf(c.x_lines, xs[r]) + nx * IndexOf(c.y_lines, ys[r]);
    if (seen[static_cast<std::size_t>(g)] >= 0) {
      throw InputError(nodes_path + " node " + std::to_string(r + 1),
                       fmt::format("({:g}, {:g})", xs[r], ys[r]),
                       "each grid point once (also node " +
                           std::to_string(seen[static_cast<std::size_t>(g)] + 1) + ")");
    }
    seen[static_cast<std::size_t>(g)] = static_cast<int>(r);
    grid[r] = g;
  }

  std::ifstream in(matrix_path);
  if (!in) throw InputError(matrix_path, "(unreadable)", "a readable Matrix Market file");
  line_number = 0;
  if (!std::getline(in, line)) throw InputError(matrix_path, "(empty)", "a Matrix Market file");
  ++line_number;
  std::istringstream banner(Lower(line));
  std::string tag, object, format, field, symmetry;
  banner >> tag >> object >> format >> field >> symmetry;
  if (tag != "%%matrixmarket" || object != "matrix" ||
      (format != "coordinate" && format != "array") || field != "real" ||
      (symmetry != "general" && symmetry != "symmetric")) {
    throw InputError(matrix_path + ":1", "\"" + Trim(line) + "\"",
                     "%%MatrixMarket matrix coordinate|array real general|symmetric");
  }
  const bool symmetric = symmetry == "symmetric";
  // Size line (after comments).
  std::string where;
  auto next = [&](std::string* text) {
    while (std::getline(in, line)) {
      ++line_number;
      *text = Trim(line);
      if (text->empty() || (*text)[0] == '%') continue;
      where = matrix_path + ":" + std::to_string(line_number);
      return true;
    }
    return false;
  };
  std::string text;
  if (!next(&text)) throw InputError(matrix_path, "(no size line)", "rows, columns [, entries]");
  std::istringstream size_line(text);
  long rows = 0, cols = 0, entries = 0;
  size_line >> rows >> cols;
  if (format == "coordinate") size_line >> entries;
  if (!size_line || rows != static_cast<long>(m) || cols != static_cast<long>(m)) {
    throw InputError(where, "\"" + text + "\"",
                     fmt::format("a {0} x {0} matrix: one row per node of {1}", m, nodes_path));
  }
  Eigen::MatrixXd a = Eigen::MatrixXd::Constant(static_cast<long>(m), static_cast<long>(m), NAN);
  auto put = [&](long i, long j, double v) {
    a(i, j) = v;
    if (symmetric) a(j, i) = v;
  };
  if (format == "coordinate") {
    for (long e = 0; e < entries; ++e) {
      if (!next(&text)) {
        throw InputError(matrix_path, fmt::format("{} of {} entries", e, entries),
                         "as many entries as its size line says");
      }
      std::istringstream row(text);
      long i = 0, j = 0;
      std::string value;
      row >> i >> j >> value;
      if (!row || i < 1 || j < 1 || i > rows || j > cols || (symmetric && j > i)) {
        throw InputError(where, "\"" + text + "\"",
                         symmetric ? "i j value with 1 <= j <= i <= " + std::to_string(rows)
                                   : "i j value with 1 <= i, j <= " + std::to_string(rows));
      }
      if (!std::isnan(a(i - 1, j - 1))) {  // an entry given twice: which one holds?
        throw InputError(where, "\"" + text + "\"",
                         fmt::format("each entry once: ({}, {}) is given again here", i, j));
      }
      put(i - 1, j - 1, Number(where, value));
    }
  } else {
    for (long j = 0; j < cols; ++j) {
      for (long i = symmetric ? j : 0; i < rows; ++i) {
        if (!next(&text)) {
          throw InputError(matrix_path, "(ends early)",
                           fmt::format("all {} values of the array",
                                       symmetric ? rows * (rows + 1) / 2 : rows * cols));
        }
        put(i, j, Number(where, text));
      }
    }
  }
  // Nothing but comments after the last entry (more values: a different matrix than its size
  // line says, or two files joined).
  if (next(&text)) {
    throw InputError(where, "\"" + text.substr(0, 60) + "\"",
                     "nothing after the last entry the size line announces (comments aside)");
  }
  for (long i = 0; i < a.rows(); ++i) {
    for (long j = 0; j < a.cols(); ++j) {
      if (std::isnan(a(i, j))) {
        throw InputError(matrix_path, fmt::format("no entry ({}, {})", i + 1, j + 1),
                         "every entry of the compliance (a compliance is dense)");
      }
    }
  }
  const double largest = a.cwiseAbs().maxCoeff();
  const double asym = (a - a.transpose()).cwiseAbs().maxCoeff();
  if (asym > 1e-9 * largest) {
    throw InputError(matrix_path, fmt::format("asymmetry {:.3g} of {:.3g}", asym, largest),
                     "a symmetric matrix (to 1e-9 of its largest entry): a compliance is");
  }
  a = 0.5 * (a + a.transpose());
  Eigen::LLT<Eigen::MatrixXd> llt(a);
  if (llt.info() != Eigen::Success || !(a.diagonal().minCoeff() > 0.0)) {
    throw InputError(matrix_path, "not positive definite",
                     "a positive definite matrix (the compliance of a supported structure)");
  }
  // Into grid order.
  c.matrix.resize(static_cast<long>(m), static_cast<long>(m));
  for (std::size_t r = 0; r < m; ++r)
    for (std::size_t s = 0; s < m; ++s)
      c.matrix(grid[r], grid[s]) = a(static_cast<long>(r), static_cast<long>(s));
  return c;
}

void WriteImportedCompliance(const ImportedCompliance& c, const std::string& matrix_path,
                             const std::string& nodes_path) {
  std::ofstream mm(matrix_path);
  const long m = c.matrix.rows();
  mm << "%%MatrixMarket matrix array real symmetric\n"
     << "% normal-direction compliance [m/N] of the surface nodes in " << nodes_path << "\n"
     << m << " " << m << "\n";
  for (long j = 0; j < m; ++j)
    for (long i = j; i < m; ++i) mm << fmt::format("{:.17g}\n", c.matrix(i, j));
  std::ofstream nodes(nodes_path);
  nodes << "x[m],y[m]\n";
  for (double y : c.y_lines)
    for (double x : c.x_lines) nodes << fmt::format("{:.17g},{:.17g}\n", x, y);
}

ComplianceTransfer::ComplianceTransfer(std::shared_ptr<const ImportedCompliance> fe,
                                       const TriMesh& mesh, std::optional<double> mirror_y,
                                       std::optional<double> mirror_x, double period,
                                       const std::string& field)
    : fe_(std::move(fe)),
      film_x_(mesh.x),
      film_y_(mesh.y),
      area_(LumpedAreas(mesh)),
      mirror_y_(mirror_y),
      mirror_x_(mirror_x),
      period_(period),
      field_(field) {
  if (mirror_x_ && mirror_y_)
    throw std::logic_error("ComplianceTransfer: one mirror (x or y), not both");
  nonnegative_ = fe_->matrix.minCoeff() >= 0.0;
  // A surface's compliance decays with the distance between its nodes (fast for a shell on a
  // stiff backing): each row drops its smallest coefficients while their magnitudes sum to at
  // most kDroppedShare of the row's, and the product skips the unloaded (cavitated) nodes.
  const Eigen::MatrixXd& c = fe_->matrix;
  const int m = static_cast<int>(c.rows());
  std::vector<Eigen::Triplet<double>> kept;
  std::vector<int> order(static_cast<std::size_t>(m));
  for (int i = 0; i < m; ++i) {
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return std::abs(c(i, a)) < std::abs(c(i, b)); });
    const double allowed = kDroppedShare * c.row(i).cwiseAbs().sum();
    double dropped = 0.0;
    std::size_t first = 0;
    while (first < order.size() && dropped + std::abs(c(i, order[first])) <= allowed)
      dropped += std::abs(c(i, order[first++]));
    for (std::size_t q = first; q < order.size(); ++q)
      kept.emplace_back(i, order[q], c(i, order[q]));
  }
  kept_.resize(m, m);
  kept_.setFromTriplets(kept.begin(), kept.end());
  Compute();
}

double ComplianceTransfer::KeptShare() const {
  const double m = static_cast<double>(kept_.rows());
  return m > 0 ? static_cast<double>(kept_.nonZeros()) / (m * m) : 0.0;
}

void ComplianceTransfer::SetOffset(double offset) {
  if (offset == offset_) return;
  offset_ = offset;
  Compute();
}

ComplianceTransfer::AxisPart ComplianceTransfer::BoundedPart(const std::vector<double>& lines,
                                                             double v, const char* axis) const {
  const double tol = 1e-9 * (lines.back() - lines.front());
  if (v < lines.front() - tol || v > lines.back() + tol) {
    throw InputError(field_, fmt::format("film point {} = {:g} m", axis, v),
                     fmt::format("a film inside the FE surface's {} range [{:g}, {:g}] m", axis,
                                 lines.front(), lines.back()));
  }
  v = std::clamp(v, lines.front(), lines.back());
  int i = static_cast<int>(std::upper_bound(lines.begin(), lines.end(), v) - lines.begin()) - 1;
  i = std::clamp(i, 0, static_cast<int>(lines.size()) - 2);
  return {i, i + 1, (v - lines[i]) / (lines[i + 1] - lines[i])};
}

ComplianceTransfer::AxisPart ComplianceTransfer::YPart(double y) const {
  return BoundedPart(fe_->y_lines, y, "y");
}

ComplianceTransfer::AxisPart ComplianceTransfer::XPart(double x) const {
  const std::vector<double>& xl = fe_->x_lines;
  if (!(period_ > 0.0)) return BoundedPart(xl, x, "x");
  const int nx = static_cast<int>(xl.size());
  x = std::fmod(x - xl.front(), period_);
  if (x < 0.0) x += period_;
  x += xl.front();
  int i = static_cast<int>(std::upper_bound(xl.begin(), xl.end(), x) - xl.begin()) - 1;
  i = std::clamp(i, 0, nx - 1);
  const double right = i + 1 < nx ? xl[i + 1] : xl.front() + period_;
  return {i, (i + 1) % nx, (x - xl[i]) / (right - xl[i])};
}

void ComplianceTransfer::Compute() {
  const std::size_t n = film_x_.size();
  const bool mirrored = mirror_y_ || mirror_x_;
  if (x_keys_.empty()) {
    // Once: each film node's (and mirror image's) y part, which no offset changes, and its x
    // among the film's distinct x values (a film mesh has few: its x lines), whose parts are
    // all an offset changes.
    auto mirror_x = [&](std::size_t k) {
      return mirror_x_ ? 2.0 * *mirror_x_ - film_x_[k] : film_x_[k];
    };
    std::vector<double> xs(film_x_);
    if (mirror_x_)
      for (std::size_t k = 0; k < n; ++k) xs.push_back(mirror_x(k));
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    x_keys_ = std::move(xs);
    auto key = [&](double x) {
      return static_cast<int>(std::lower_bound(x_keys_.begin(), x_keys_.end(), x) -
                              x_keys_.begin());
    };
    key_own_.resize(n);
    y_own_.resize(n);
    key_mirror_.resize(mirrored ? n : 0);
    y_mirror_.resize(mirrored ? n : 0);
    for (std::size_t k = 0; k < n; ++k) {
      key_own_[k] = key(film_x_[k]);
      y_own_[k] = YPart(film_y_[k]);
      if (!mirrored) continue;
      key_mirror_[k] = key(mirror_x(k));
      y_mirror_[k] = YPart(mirror_y_ ? 2.0 * *mirror_y_ - film_y_[k] : film_y_[k]);
    }
  }
  x_parts_.resize(x_keys_.size());
  for (std::size_t u = 0; u < x_keys_.size(); ++u) x_parts_[u] = XPart(x_keys_[u] + offset_);
  const int nx = static_cast<int>(fe_->x_lines.size());
  auto combine = [nx](const AxisPart& a, const AxisPart& b) {
    Weights w;
    w.node = {a.i0 + nx * b.i0, a.i1 + nx * b.i0, a.i0 + nx * b.i1, a.i1 + nx * b.i1};
    w.w = {(1 - a.s) * (1 - b.s), a.s * (1 - b.s), (1 - a.s) * b.s, a.s * b.s};
    return w;
  };
  own_.resize(n);
  mirror_.resize(mirrored ? n : 0);
  for (std::size_t k = 0; k < n; ++k) {
    own_[k] = combine(x_parts_[static_cast<std::size_t>(key_own_[k])], y_own_[k]);
    if (mirrored)
      mirror_[k] = combine(x_parts_[static_cast<std::size_t>(key_mirror_[k])], y_mirror_[k]);
  }
}

void ComplianceTransfer::Apply(const Eigen::VectorXd& load, Eigen::VectorXd& out) const {
  const int m = fe_->NodeCount();
  force_.setZero(m);
  const std::size_t n = own_.size();
  for (std::size_t k = 0; k < n; ++k) {
    const double f = area_[k] * load[static_cast<long>(k)];
    for (int q = 0; q < 4; ++q) force_[own_[k].node[q]] += own_[k].w[q] * f;
    if (!mirror_.empty())
      for (int q = 0; q < 4; ++q) force_[mirror_[k].node[q]] += mirror_[k].w[q] * f;
  }
  displacement_.setZero(m);
  for (int j = 0; j < m; ++j) {
    const double f = force_[j];
    if (f == 0.0) continue;
    for (Eigen::SparseMatrix<double>::InnerIterator it(kept_, j); it; ++it)
      displacement_[it.row()] += it.value() * f;
  }
  out.resize(static_cast<long>(n));
  for (std::size_t k = 0; k < n; ++k) {
    double d = 0.0;
    for (int q = 0; q < 4; ++q) d += own_[k].w[q] * displacement_[own_[k].node[q]];
    out[static_cast<long>(k)] = d;
  }
}

double ComplianceTransfer::Diagonal(int k) const {
  const Weights& a = own_[static_cast<std::size_t>(k)];
  double d = 0.0;
  for (int p = 0; p < 4; ++p) {
    for (int q = 0; q < 4; ++q) {
      d += a.w[p] * fe_->matrix(a.node[p], a.node[q]) * a.w[q];
      if (!mirror_.empty()) {
        const Weights& b = mirror_[static_cast<std::size_t>(k)];
        d += a.w[p] * fe_->matrix(a.node[p], b.node[q]) * b.w[q];
      }
    }
  }
  return d * area_[static_cast<std::size_t>(k)];
}

}  // namespace filmdyn::lubrication
