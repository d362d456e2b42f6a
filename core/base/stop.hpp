#pragma once
/// @file A stop request (cancel, time limit) honoured inside long computations: the caller
/// installs a StopCheck; the computation calls it at its natural checkpoints (each film
/// evaluation, each iteration of a film solve) and throws StopRequested when it returns true.
/// The run catches it and ends with what it has computed.
#include <functional>
#include <stdexcept>

namespace filmdyn {

using StopCheck = std::function<bool()>;

class StopRequested : public std::runtime_error {
 public:
  StopRequested() : std::runtime_error("stop requested") {}
};

/// Throws StopRequested when `check` is set and returns true.
inline void ThrowIfStopRequested(const StopCheck& check) {
  if (check && check()) throw StopRequested();
}

}  // namespace filmdyn
