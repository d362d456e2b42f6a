#include "ui/charts/film_map_widget.hpp"

#include <QImage>
#include <QPainter>
#include <algorithm>
#include <cmath>

#include "ui/charts/color_map.hpp"

namespace filmdyn::ui {

std::vector<double> RoundTicks(double lo, double hi, int target) {
  std::vector<double> ticks;
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return ticks;
  const double raw = (hi - lo) / std::max(target, 1);
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10.0 * decade;
  for (double m : {1.0, 2.0, 2.5, 5.0}) {
    if (m * decade >= raw) {
      step = m * decade;
      break;
    }
  }
  for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + 1e-9 * step; t += step) {
    ticks.push_back(std::abs(t) < 1e-12 * step ? 0.0 : t);
  }
  return ticks;
}

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
  if (data_.values_from_zero) lo = std::min(lo, 0.0);
  if (!(hi > lo)) hi = lo + 1.0;
  const std::vector<double> ticks = RoundTicks(lo, hi, 5);
  scale_lo_ = lo, scale_hi_ = hi;
  if (ticks.size() >= 2) {  // round the bar's ends out to whole ticks
    const double step = ticks[1] - ticks[0];
    scale_lo_ = std::floor(lo / step + 1e-9) * step;
    scale_hi_ = std::ceil(hi / step - 1e-9) * step;
  }
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
    painter.save();
    painter.translate(band.center());
    painter.rotate(-90);
    painter.setPen(Qt::black);
    const QString text = fm.elidedText(d.no_film_label, Qt::ElideRight, plot.height() - 8);
    painter.drawText(QRectF(-plot.height() / 2.0, -line / 2.0, plot.height(), line),
                     Qt::AlignCenter, text);
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
  for (double t : RoundTicks(y0, y1, 6)) {
    const double y = py(t);
    painter.drawLine(QPointF(plot.left() - 4, y), QPointF(plot.left(), y));
    painter.drawText(QRectF(0, y - line / 2.0, plot.left() - 6, line),
                     Qt::AlignRight | Qt::AlignVCenter, TickText(t));
  }
  painter.drawText(QRectF(plot.left(), plot.bottom() + line + 6, plot.width(), line),
                   Qt::AlignHCenter, d.x_title);
  painter.save();
  painter.translate(line / 2.0 + 2, plot.center().y());
  painter.rotate(-90);
  painter.drawText(QRectF(-plot.height() / 2.0, -line / 2.0, plot.height(), line), Qt::AlignCenter,
                   d.y_title);
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
  painter.rotate(90);
  painter.drawText(QRectF(-bar.height() / 2.0, -line / 2.0, bar.height(), line), Qt::AlignCenter,
                   d.value_title);
  painter.restore();
}

}  // namespace filmdyn::ui
