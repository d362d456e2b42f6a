#include "ui/plots/mark_labels.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace filmdyn::ui {

std::vector<QRectF> PlaceMarkLabels(const std::vector<MarkLabel>& marks, QPointF origin,
                                    const QRectF& area) {
  std::vector<QRectF> placed(marks.size());
  std::vector<QRectF> taken;
  for (std::size_t m = 0; m < marks.size(); ++m) {
    const QPointF at = marks[m].at;
    const QSizeF size = marks[m].size;
    const QPointF outward = at - origin;
    const double base = std::hypot(outward.x(), outward.y()) > 1e-6
                            ? std::atan2(outward.y(), outward.x())
                            : -std::numbers::pi / 4;
    QRectF chosen;
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
        if (free && area.contains(rect)) chosen = rect;
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
