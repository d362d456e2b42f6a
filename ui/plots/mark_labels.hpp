#pragma once

#include <QPointF>
#include <QPolygonF>
#include <QRectF>
#include <QSizeF>
#include <vector>

namespace filmdyn::ui {

/// A crank-angle mark's label to place: the mark's position and the label's text size [px].
struct MarkLabel {
  QPointF at;
  QSizeF size;
};

/// Places the labels of an orbit's or a load diagram's crank-angle marks, in order: each goes
/// outward from the diagram's origin (the bearing centre, the zero load) or, where an earlier
/// label took that place (the curve passes a spot twice, e.g. 270° and 630°), to the nearest
/// free place around its mark, a little farther out if none is free beside it. A place the
/// `curves` (the diagram's polylines [px]) pass through is taken only where no place clear of
/// them is near (the caller draws such a label on a light backing). No label covers one of the
/// `dots` (every mark drawn, of every run and cycle [px]: a label beside another mark's dot reads
/// as that mark's). Where none is free within `area` (marks crowded in a small diagram) the label
/// is left out: its rectangle is null. The placed rectangles lie within `area` and never overlap
/// one another.
std::vector<QRectF> PlaceMarkLabels(const std::vector<MarkLabel>& marks, QPointF origin,
                                    const QRectF& area, const std::vector<QPolygonF>& curves = {},
                                    const std::vector<QPointF>& dots = {});

/// The half size of the square a mark's dot is kept clear within [px] (the dot's 3.5 px radius
/// and its white rim).
inline constexpr double kMarkDotHalf = 4.5;

}  // namespace filmdyn::ui
