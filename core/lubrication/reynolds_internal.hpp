#pragma once
/// @file Helpers shared by the files of ReynoldsFem (not part of its interface).
#include <Eigen/SparseCore>
#include <algorithm>
#include <chrono>

namespace filmdyn::lubrication::reynolds_detail {

using Clock = std::chrono::steady_clock;
inline double Seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

/// Index of entry (row, col) in a compressed column-major matrix; -1 if structurally absent.
inline int FindPos(const Eigen::SparseMatrix<double>& m, int row, int col) {
  const int* inner = m.innerIndexPtr();
  const int begin = m.outerIndexPtr()[col], end = m.outerIndexPtr()[col + 1];
  const int* it = std::lower_bound(inner + begin, inner + end, row);
  return (it != inner + end && *it == row) ? static_cast<int>(it - inner) : -1;
}

}  // namespace filmdyn::lubrication::reynolds_detail
