#include "ui/charts/film_map_widget.hpp"

#include <QImage>
#include <QPainter>
#include <algorithm>
#include <cmath>
#include <tuple>

#include "ui/charts/color_map.hpp"
#include "ui/charts/round_ticks.hpp"

namespace filmdyn::ui {

namespace {

// Index of the interval of `lines` holding v and the fraction within it.
std::pair<int, double> Locate(const std::vector<double>& lines, double v) {
  const auto it = std::upper_bound(lines.begin(), lines.end(), v);
  const int i =
      std::clamp(static_cast<int>(it - lines.begin()) - 1, 0, static_cast<int>(lines.size()) - 2);
  const double w = lines[i + 1] - lines[i];
  return {i, w > 0 ? std::clamp((v - lines[i]) / w, 0.0, 1.0) : 0.0};
}

QString TickText(double v) { return QString::number(v, 'g', 6); }

}  // namespace

FilmMapWidget::FilmMapWidget(QWidget* parent) : QWidget(parent) { setObjectName("film_map"); }

void FilmMapWidget::setData(FilmMapData data) {
  data_ = std::move(data);
  double lo = 1e300, hi = -1e300;
  for (double v : data_.values) {
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  }
  if (std::isfinite(data_.scale_lo) && std::isfinite(data_.scale_hi)) {
    lo = data_.scale_lo, hi = data_.scale_hi;
  }
  if (data_.values_from_zero) lo = std::min(lo, 0.0);
  std::tie(scale_lo_, scale_hi_) = RoundedRange(lo, hi, 5);
  update();
}

void FilmMapWidget::setYLine(double y) {
  data_.y_line = y;
  update();
}

double FilmMapWidget::ValueAt(double x, double y) const {
  const auto& d = data_;
  const auto [i, fx] = Locate(d.x, x);
  const auto [j, fy] = Locate(d.y, y);
  const std::size_t nx = d.x.size();
  auto v = [&](int a, int b) { return d.values[a + nx * b]; };
  return (1 - fy) * ((1 - fx) * v(i, j) + fx * v(i + 1, j)) +
         fy * ((1 - fx) * v(i, j + 1) + fx * v(i + 1, j + 1));
}

void FilmMapWidget::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), palette().base());
  const auto& d = data_;
  if (d.x.size() < 2 || d.y.size() < 2 || d.values.size() != d.x.size() * d.y.size()) {
    painter.drawText(rect(), Qt::AlignCenter, tr("No film map yet"));
    return;
  }
  const QFontMetrics fm(font());
  const int line = fm.height();
  // Plot area: axis numbers and titles left and below, edge labels around, colour bar right.
  const QRect plot(fm.horizontalAdvance("0000.0") + line + 8, line + 6,
                   std::max(40, width() - (fm.horizontalAdvance("0000.0") + line + 8) -
                                    fm.horizontalAdvance("00000.00") - 3 * line - 30),
                   std::max(40, height() - 4 * line - 16));
  const double x0 = d.x.front(), x1 = d.x.back(), y0 = d.y.front(), y1 = d.y.back();
  auto px = [&](double x) { return plot.left() + (x - x0) / (x1 - x0) * plot.width(); };
  auto py = [&](double y) { return plot.top() + (y - y0) / (y1 - y0) * plot.height(); };

  QImage image(plot.size(), QImage::Format_RGB32);
  for (int r = 0; r < image.height(); ++r) {
    const double y = y0 + (r + 0.5) / image.height() * (y1 - y0);
    auto* row = reinterpret_cast<QRgb*>(image.scanLine(r));
    for (int c = 0; c < image.width(); ++c) {
      const double x = x0 + (c + 0.5) / image.width() * (x1 - x0);
      const double t = (ValueAt(x, y) - scale_lo_) / (scale_hi_ - scale_lo_);
      row[c] = Viridis(t).rgb();
    }
  }
  painter.drawImage(plot.topLeft(), image);
  for (const auto& [a, b] : d.no_film_x) {  // no film: grey, named
    const QRectF band(px(a), plot.top(), px(b) - px(a), plot.height());
    painter.fillRect(band, QColor(200, 200, 200));
    painter.fillRect(band, QBrush(QColor(150, 150, 150), Qt::BDiagPattern));
  }
  // Marker lines: black under white, visible on every colour of the map.
  auto marker = [&](QPointF a, QPointF b) {
    painter.setPen(QPen(Qt::black, 3));
    painter.drawLine(a, b);
    painter.setPen(QPen(Qt::white, 1));
    painter.drawLine(a, b);
  };
  if (std::isfinite(d.x_line) && d.x_line >= x0 && d.x_line <= x1) {
    const double x = px(d.x_line);
    marker(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
    if (!d.x_line_label.isEmpty()) {
      const int w = fm.horizontalAdvance(d.x_line_label) + 6;
      const QRectF box(std::clamp(x + 3, double(plot.left()), double(plot.right() - w)),
                       plot.top() + 3, w, line);
      painter.fillRect(box, QColor(255, 255, 255, 210));
      painter.setPen(Qt::black);
      painter.drawText(box, Qt::AlignCenter, d.x_line_label);
    }
  }
  if (!d.points.empty()) {
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(Qt::black, 1));
    painter.setBrush(QColor(255, 110, 80));
    painter.setClipRect(plot);
    for (const auto& [x, y] : d.points) painter.drawEllipse(QPointF(px(x), py(y)), 2.0, 2.0);
    painter.setClipping(false);
    if (!d.points_label.isEmpty()) {
      // The legend in the corner where it hides least: the fewest points, then the most uniform
      // map under it (it sat on the bright band at the end of the cycle, over the load's dots).
      const int w = fm.horizontalAdvance(d.points_label) + 20;
      const QRectF corners[] = {
          {plot.right() - w - 4.0, plot.bottom() - line - 4.0, double(w), double(line)},
          {plot.left() + 4.0, plot.bottom() - line - 4.0, double(w), double(line)},
          {plot.right() - w - 4.0, plot.top() + 4.0, double(w), double(line)},
          {plot.left() + 4.0, plot.top() + 4.0, double(w), double(line)}};
      auto hidden = [&](const QRectF& r) {
        int dots = 0;
        for (const auto& [x, y] : d.points) dots += r.contains(QPointF(px(x), py(y))) ? 1 : 0;
        double lo = HUGE_VAL, hi = -HUGE_VAL;
        for (int i = 0; i <= 6; ++i) {
          for (int j = 0; j <= 2; ++j) {
            const double x =
                x0 + (r.left() + r.width() * i / 6.0 - plot.left()) / plot.width() * (x1 - x0);
            const double y =
                y0 + (r.top() + r.height() * j / 2.0 - plot.top()) / plot.height() * (y1 - y0);
            const double v = ValueAt(x, y);
            if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
          }
        }
        const double spread = hi >= lo ? (hi - lo) / std::max(1e-300, scale_hi_ - scale_lo_) : 0.0;
        return dots + spread;  // a dot outweighs any spread (at most 1)
      };
      QRectF box = corners[0];
      double least = hidden(box);
      for (const QRectF& r : corners) {
        if (const double h = hidden(r); h < least - 1e-9) least = h, box = r;
      }
      points_legend_ = box;
      painter.fillRect(box, QColor(255, 255, 255, 210));
      painter.drawEllipse(QPointF(box.left() + 8, box.center().y()), 2.5, 2.5);
      painter.setPen(Qt::black);
      painter.drawText(box.adjusted(16, 0, 0, 0), Qt::AlignLeft | Qt::AlignVCenter, d.points_label);
    }
    painter.restore();
  }
  const bool has_y_line = std::isfinite(d.y_line) && d.y_line >= y0 && d.y_line <= y1;
  if (has_y_line) {
    const double y = py(d.y_line);
    marker(QPointF(plot.left(), y), QPointF(plot.right(), y));
  }
  // The no-film bands' name, upright along the band, in the half away from the horizontal line
  // (it crossed the name at mid-cycle); drawn after it on the band's grey, so that a name longer
  // than half the map is still read whole.
  no_film_labels_.clear();
  for (const auto& [a, b] : d.no_film_x) {
    const QString text = fm.elidedText(d.no_film_label, Qt::ElideRight, plot.height() - 8);
    const double length = fm.horizontalAdvance(text) + 6.0, middle = plot.center().y();
    double centre = middle;
    if (has_y_line) {
      const double upper = plot.top() + std::max(plot.height() / 4.0, length / 2.0 + 4.0);
      const double lower = plot.bottom() - std::max(plot.height() / 4.0, length / 2.0 + 4.0);
      centre = py(d.y_line) < middle ? std::max(lower, middle) : std::min(upper, middle);
    }
    const QRectF box((px(a) + px(b) - line) / 2.0, centre - length / 2.0, line, length);
    no_film_labels_.push_back(box);
    painter.fillRect(box, QColor(200, 200, 200));
    painter.save();
    painter.translate(box.center());
    painter.rotate(-90);
    painter.setPen(Qt::black);
    painter.drawText(QRectF(-length / 2.0, -line / 2.0, length, line), Qt::AlignCenter, text);
    painter.restore();
  }
  painter.setPen(palette().color(QPalette::Text));
  painter.drawRect(plot.adjusted(0, 0, -1, -1));

  // Axes: round ticks, whole numbers.
  for (double t : RoundTicks(x0, x1, 8)) {
    const double x = px(t);
    painter.drawLine(QPointF(x, plot.bottom()), QPointF(x, plot.bottom() + 4));
    painter.drawText(QRectF(x - 40, plot.bottom() + 5, 80, line), Qt::AlignHCenter | Qt::AlignTop,
                     TickText(t));
  }
  for (double t : d.y_ticks.empty() ? RoundTicks(y0, y1, 6) : d.y_ticks) {
    if (t < y0 || t > y1) continue;
    const double y = py(t);
    painter.drawLine(QPointF(plot.left() - 4, y), QPointF(plot.left(), y));
    painter.drawText(QRectF(0, y - line / 2.0, plot.left() - 6, line),
                     Qt::AlignRight | Qt::AlignVCenter, TickText(t));
  }
  painter.drawText(QRectF(plot.left(), plot.bottom() + line + 6, plot.width(), line),
                   Qt::AlignHCenter, d.x_title);
  // The y title beside the plot, longer than the plot if it must (a short map in a small
  // panel), within the widget; elided only when even that is too short.
  painter.save();
  const double room = height() - 4.0;
  const QString y_title = fm.elidedText(d.y_title, Qt::ElideRight, int(room));
  const double length = std::min(room, fm.horizontalAdvance(y_title) + 8.0);
  const double centre =
      std::clamp(double(plot.center().y()), 2.0 + length / 2.0, height() - 2.0 - length / 2.0);
  painter.translate(line / 2.0 + 2, centre);
  painter.rotate(-90);
  painter.drawText(QRectF(-length / 2.0, -line / 2.0, length, line), Qt::AlignCenter, y_title);
  painter.restore();
  // Edge cues.
  QFont bold = font();
  bold.setBold(true);
  painter.setFont(bold);
  const QRectF above(plot.left(), 2, plot.width(), line + 2);
  painter.drawText(above, Qt::AlignLeft | Qt::AlignVCenter, d.left);
  painter.drawText(above, Qt::AlignRight | Qt::AlignVCenter, d.right);
  painter.drawText(above, Qt::AlignHCenter | Qt::AlignVCenter, d.top);
  painter.drawText(QRectF(plot.left(), plot.bottom() + 2 * line + 8, plot.width(), line),
                   Qt::AlignHCenter, d.bottom);
  for (const auto& [x, text] : d.x_marks) {
    if (x < x0 || x > x1) continue;
    const double w = fm.horizontalAdvance(text) * 1.2 + 4;
    const double left = std::clamp(px(x) - w / 2, double(plot.left()), plot.right() - w);
    painter.drawText(QRectF(left, 2, w, line + 2), Qt::AlignCenter, text);
  }
  painter.setFont(font());

  // Colour bar beside the map, its numbers whole.
  const QRect bar(plot.right() + 16, plot.top(), 16, plot.height());
  for (int r = 0; r < bar.height(); ++r) {
    painter.setPen(Viridis(1.0 - (r + 0.5) / bar.height()));
    painter.drawLine(bar.left(), bar.top() + r, bar.right(), bar.top() + r);
  }
  painter.setPen(palette().color(QPalette::Text));
  painter.drawRect(bar.adjusted(0, 0, -1, -1));
  for (double t : RoundTicks(scale_lo_, scale_hi_, 5)) {
    const double y = bar.bottom() - (t - scale_lo_) / (scale_hi_ - scale_lo_) * bar.height();
    painter.drawLine(QPointF(bar.right(), y), QPointF(bar.right() + 4, y));
    painter.drawText(QRectF(bar.right() + 6, y - line / 2.0, 200, line),
                     Qt::AlignLeft | Qt::AlignVCenter, TickText(t));
  }
  painter.save();
  painter.translate(width() - line / 2.0 - 2, bar.center().y());
  painter.rotate(-90);  // read bottom-up, as the y axis's title
  painter.drawText(QRectF(-bar.height() / 2.0, -line / 2.0, bar.height(), line), Qt::AlignCenter,
                   d.value_title);
  painter.restore();
  // Disabled: a map of inputs no longer shown (its owner computes a new one, or could not), faded.
  if (!isEnabled()) painter.fillRect(rect(), QColor(255, 255, 255, 150));
}

void SetSkirtMapLabels(FilmMapData* d) {
  d->x_title = QObject::tr("Angle from the thrust side α [°]");
  d->y_title = QObject::tr("Distance below the skirt top [mm]");
  d->left = QObject::tr("◀ thrust side");
  d->right = QObject::tr("anti-thrust side ▶");
  d->top = QObject::tr("▲ skirt top");
  d->bottom = QObject::tr("skirt bottom (crank side) ▼");
  d->no_film_label = QObject::tr("pin-boss relief: no film");
}

}  // namespace filmdyn::ui
