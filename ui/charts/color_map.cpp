#include "ui/charts/color_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace filmdyn::ui {

QColor Viridis(double t) {
  if (std::isnan(t)) return QColor(128, 128, 128);
  // matplotlib's viridis sampled at t = 0, 0.1, ..., 1; linear between the samples (the map is
  // nearly linear in RGB over a tenth of its range).
  static constexpr std::array<std::array<int, 3>, 11> kSamples = {{{68, 1, 84},
                                                                   {72, 36, 117},
                                                                   {65, 68, 135},
                                                                   {53, 95, 141},
                                                                   {42, 120, 142},
                                                                   {33, 145, 140},
                                                                   {34, 168, 132},
                                                                   {68, 191, 112},
                                                                   {122, 209, 81},
                                                                   {189, 223, 38},
                                                                   {253, 231, 37}}};
  const double x = std::clamp(t, 0.0, 1.0) * 10.0;
  const int i = std::min(static_cast<int>(x), 9);
  const double f = x - i;
  auto mix = [&](int c) {
    return static_cast<int>(
        std::lround(kSamples[i][c] + f * (kSamples[i + 1][c] - kSamples[i][c])));
  };
  return QColor(mix(0), mix(1), mix(2));
}

}  // namespace filmdyn::ui
