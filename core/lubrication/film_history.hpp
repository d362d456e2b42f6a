#pragma once
/// @file The film history a transient mass-conserving (JFO) solve steps from: the void content of
/// every node at the last few accepted time steps of the time integration.
///
/// A joint's film is solved many times per step of the integrator (Newton iterations, Jacobian
/// columns, rejected trial steps, output times interpolated inside a step); each of those
/// solves at time t steps from the latest accepted state before t, over dt = t - t_accepted, so
/// that every one of them is a function of (t, state) alone while the step is being taken. Once
/// the integrator accepts a step at t_n, the film's solution there becomes the next entry. An
/// output time inside the last step (t_{n-1}, t_n] therefore steps from t_{n-1}, as the step
/// itself did: the last three entries are kept.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <deque>
#include <vector>

namespace filmdyn::lubrication {

class FilmHistory {
 public:
  struct Entry {
    double time = 0.0;
    /// per Reynolds solver of the joint [m] (ReynoldsSolution::void_content: the void, less
    /// a compressible full film's compressed oil)
    std::vector<Eigen::VectorXd> void_content;
  };
  bool empty() const { return entries_.empty(); }
  void Clear() { entries_.clear(); }
  /// The latest entry strictly before t; nullptr when there is none.
  const Entry* Before(double t) const {
    for (auto it = entries_.rbegin(); it != entries_.rend(); ++it)
      if (it->time < t) return &*it;
    return nullptr;
  }
  /// Records the state at t. Entries at or after t (a restarted integration) are dropped.
  void Push(double t, std::vector<Eigen::VectorXd> void_content) {
    while (!entries_.empty() && entries_.back().time >= t) entries_.pop_back();
    entries_.push_back({t, std::move(void_content)});
    while (entries_.size() > kKept) entries_.pop_front();
  }
  const Entry& latest() const { return entries_.back(); }
  /// The next step that keeps the void content's local error (backward Euler: about
  /// Δt²/2 · |d²V/dt²|, from the last three entries) at `tolerance` [m] in the root mean square
  /// over the nodes; nodes whose void opened or closed within those entries are left out (their
  /// rate jumps by the complementarity, not by a lack of smoothness). The content of a
  /// compressible full film (its compressed oil, negative) is stepped alike and counted alike.
  /// 0: no limit (fewer than three entries, or no error).
  double NextStepLimit(double tolerance) const {
    if (entries_.size() < 3 || !(tolerance > 0.0)) return 0.0;
    const Entry& a = entries_[entries_.size() - 3];
    const Entry& b = entries_[entries_.size() - 2];
    const Entry& c = entries_.back();
    const double h1 = b.time - a.time, h2 = c.time - b.time;
    if (!(h1 > 0.0 && h2 > 0.0)) return 0.0;
    double sum = 0.0;
    long count = 0;
    const std::size_t solvers =
        std::min({a.void_content.size(), b.void_content.size(), c.void_content.size()});
    for (std::size_t s = 0; s < solvers; ++s) {
      const Eigen::VectorXd &va = a.void_content[s], &vb = b.void_content[s],
                            &vc = c.void_content[s];
      if (va.size() != vc.size() || vb.size() != vc.size()) continue;
      for (Eigen::Index i = 0; i < vc.size(); ++i) {
        ++count;
        // A void (content > 0), or a compressible full film's compressed oil (< 0), in all
        // three entries.
        if (!((va[i] > 0.0 && vb[i] > 0.0 && vc[i] > 0.0) ||
              (va[i] < 0.0 && vb[i] < 0.0 && vc[i] < 0.0)))
          continue;
        const double second = 2.0 * ((vc[i] - vb[i]) / h2 - (vb[i] - va[i]) / h1) / (h1 + h2);
        const double error = 0.5 * h2 * h2 * second;
        sum += (error / tolerance) * (error / tolerance);
      }
    }
    if (count == 0 || sum == 0.0) return 0.0;
    const double rms = std::sqrt(sum / double(count));
    return 0.9 * h2 * std::sqrt(1.0 / rms);
  }
  /// The time of the starting state of an integration whose first film solve is at t: just
  /// before it (1 ns, or 1e-12 of t), so that the first solve steps from it like any other.
  static double StartTime(double t) { return t - std::max(1e-9, 1e-12 * std::abs(t)); }

 private:
  static constexpr size_t kKept = 3;
  std::deque<Entry> entries_;
};

}  // namespace filmdyn::lubrication
