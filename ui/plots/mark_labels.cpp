#include "ui/plots/mark_labels.hpp"

#include <QLineF>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace filmdyn::ui {

namespace {

// Whether the segment a–b passes through `rect` (an end inside, or a crossing of an edge).
bool SegmentCrosses(const QRectF& rect, const QPointF& a, const QPointF& b) {
  if (rect.contains(a) || rect.contains(b)) return true;
  if (std::max(a.x(), b.x()) < rect.left() || std::min(a.x(), b.x()) > rect.right() ||
      std::max(a.y(), b.y()) < rect.top() || std::min(a.y(), b.y()) > rect.bottom())
    return false;
  const QLineF segment(a, b);
  const QLineF edges[] = {{rect.topLeft(), rect.topRight()},
                          {rect.topRight(), rect.bottomRight()},
                          {rect.bottomRight(), rect.bottomLeft()},
                          {rect.bottomLeft(), rect.topLeft()}};
  return std::any_of(std::begin(edges), std::end(edges), [&segment](const QLineF& edge) {
    return segment.intersects(edge, nullptr) == QLineF::BoundedIntersection;
  });
}

bool CrossesAnyCurve(const QRectF& rect, const std::vector<QPolygonF>& curves) {
  for (const QPolygonF& curve : curves) {
    if (curve.size() == 1 && rect.contains(curve.front())) return true;
    for (qsizetype i = 1; i < curve.size(); ++i)
      if (SegmentCrosses(rect, curve[i - 1], curve[i])) return true;
  }
  return false;
}

}  // namespace

std::vector<QRectF> PlaceMarkLabels(const std::vector<MarkLabel>& marks, QPointF origin,
                                    const QRectF& area, const std::vector<QPolygonF>& curves,
                                    const std::vector<QPointF>& dots) {
  std::vector<QRectF> placed(marks.size());
  std::vector<QRectF> taken;
  for (const QPointF& dot : dots)
    taken.emplace_back(dot - QPointF(kMarkDotHalf, kMarkDotHalf),
                       QSizeF(2 * kMarkDotHalf, 2 * kMarkDotHalf));
  for (std::size_t m = 0; m < marks.size(); ++m) {
    const QPointF at = marks[m].at;
    const QSizeF size = marks[m].size;
    const QPointF outward = at - origin;
    const double base = std::hypot(outward.x(), outward.y()) > 1e-6
                            ? std::atan2(outward.y(), outward.x())
                            : -std::numbers::pi / 4;
    QRectF chosen;
    // Clear of the curves first; where no such place is near, on them as a last resort.
    for (bool clear_of_curves : {true, false}) {
      for (double gap : {6.0, 16.0}) {
        // Outward first, then alternately a sixteenth of a turn either side of it.
        for (int i = 0; i < 16 && chosen.isNull(); ++i) {
          const double a = base + (i % 2 ? 1 : -1) * ((i + 1) / 2) * (std::numbers::pi / 8);
          const QPointF dir(std::cos(a), std::sin(a));
          const double reach =
              gap + 0.5 * (std::abs(dir.x()) * size.width() + std::abs(dir.y()) * size.height());
          const QRectF rect(at + dir * reach - QPointF(size.width() / 2, size.height() / 2), size);
          const bool free = std::none_of(taken.begin(), taken.end(),
                                         [&rect](const QRectF& r) { return r.intersects(rect); });
          if (free && area.contains(rect) && (!clear_of_curves || !CrossesAnyCurve(rect, curves)))
            chosen = rect;
        }
        if (!chosen.isNull()) break;
      }
      if (!chosen.isNull()) break;
    }
    if (chosen.isNull()) continue;
    taken.push_back(chosen);
    placed[m] = chosen;
  }
  return placed;
}

}  // namespace filmdyn::ui
