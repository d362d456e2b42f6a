#pragma once
/// @file A perceptually uniform colour map (viridis: dark blue → green → yellow, lightness rising
/// steadily, readable in grey and by colour-blind readers) for film maps and colour bars.
#include <QColor>

namespace filmdyn::ui {

/// The colour of `t` in [0, 1] (clamped; NaN gives grey).
QColor Viridis(double t);

}  // namespace filmdyn::ui
