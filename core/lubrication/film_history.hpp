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
    std::vector<Eigen::VectorXd> void_content;  ///< per Reynolds solver of the joint [m]
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
  /// The time of the starting state of an integration whose first film solve is at t: just
  /// before it (1 ns, or 1e-12 of t), so that the first solve steps from it like any other.
  static double StartTime(double t) { return t - std::max(1e-9, 1e-12 * std::abs(t)); }

 private:
  static constexpr size_t kKept = 3;
  std::deque<Entry> entries_;
};

}  // namespace filmdyn::lubrication
