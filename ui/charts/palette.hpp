#pragma once
/// @file The plots' colour-blind-safe qualitative palette (Okabe–Ito, grey and black last): the
/// run curves, the study plots' factors and dots.
#include <QColor>

namespace filmdyn::ui {

inline const QColor kPalette[] = {QColor(0, 114, 178),   QColor(213, 94, 0),   QColor(0, 158, 115),
                                  QColor(204, 121, 167), QColor(86, 180, 233), QColor(230, 159, 0),
                                  QColor(120, 120, 120), QColor(0, 0, 0)};
inline constexpr int kPaletteSize = int(sizeof(kPalette) / sizeof(kPalette[0]));

}  // namespace filmdyn::ui
