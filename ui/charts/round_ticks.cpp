#include "ui/charts/round_ticks.hpp"

#include <QStringList>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <vector>

namespace filmdyn::ui {

double RoundStep(double span, int target) {
  const double raw = span / std::max(target, 1);
  if (!(raw > 0) || !std::isfinite(raw)) return 1.0;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 2.5, 5.0}) {
    if (m * decade >= raw * (1 - 1e-12)) return m * decade;
  }
  return 10.0 * decade;
}

int DecimalsFor(double step) {
  for (int d = 0; d < 12; ++d) {
    const double scaled = step * std::pow(10.0, d);
    if (std::abs(scaled - std::round(scaled)) < 1e-6 * std::max(1.0, scaled)) return d;
  }
  return 12;
}

RoundRange RoundRangeCovering(double lo, double hi, int target) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) lo = 0, hi = 1;
  if (hi < lo) std::swap(lo, hi);
  if (hi - lo <= 1e-12 * std::max(std::abs(lo), std::abs(hi))) {
    // A constant: a range one round step either side of it (0 ± 1 for zero).
    const double half = hi == 0 ? 1.0 : RoundStep(std::abs(hi), 2);
    lo -= half;
    hi += half;
  }
  RoundRange range;
  range.step = RoundStep(hi - lo, target);
  range.min = std::floor(lo / range.step + 1e-9) * range.step;
  range.max = std::ceil(hi / range.step - 1e-9) * range.step;
  if (std::abs(range.min) < 1e-12 * range.step) range.min = 0.0;
  if (std::abs(range.max) < 1e-12 * range.step) range.max = 0.0;
  range.decimals = DecimalsFor(range.step);
  return range;
}

std::vector<double> RoundTicks(double lo, double hi, int target) {
  std::vector<double> ticks;
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return ticks;
  const double step = RoundStep(hi - lo, target);
  for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + 1e-9 * step; t += step) {
    ticks.push_back(std::abs(t) < 1e-12 * step ? 0.0 : t);
  }
  return ticks;
}

std::pair<double, double> RoundedRange(double lo, double hi, int target) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) return {0.0, 1.0};
  if (!(hi > lo)) hi = lo + 1.0;
  const std::vector<double> ticks = RoundTicks(lo, hi, target);
  if (ticks.size() < 2) return {lo, hi};
  const double step = ticks[1] - ticks[0];  // round the ends out to whole ticks
  return {std::floor(lo / step + 1e-9) * step, std::ceil(hi / step - 1e-9) * step};
}

std::optional<int> CommonDecimals(const std::vector<double>& values) {
  double larger = 0.0;
  for (double v : values) {
    if (std::isfinite(v)) larger = std::max(larger, std::abs(v));
  }
  if (!(larger > 0.0) || larger >= 1e6 || larger < 1e-4) return std::nullopt;
  return std::clamp(3 - int(std::floor(std::log10(larger))), 0, 6);
}

QString FormatReadoutValues(const std::vector<double>& values, const QString& separator) {
  const bool finite =
      std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
  const std::optional<int> decimals = finite ? CommonDecimals(values) : std::nullopt;
  QStringList texts;
  if (!decimals) {
    // "–", zeros and magnitudes better read in 'g' form: each as it is.
    for (double v : values) texts << FormatReadout(v);
    return texts.join(separator);
  }
  for (double v : values) texts << FixedDecimals(v, *decimals);
  return texts.join(separator);
}

QString FixedDecimals(double value, int decimals) {
  const QString text = QString::number(value, 'f', decimals);
  const QString zero = QString::number(0.0, 'f', decimals);
  return text == "-" + zero ? zero : text;
}

QString FormatReadoutPair(double x, double y, const QString& unit) {
  const QString pair = FormatReadoutValues({x, y}, ", ");
  return unit.isEmpty() ? pair : pair + QChar(0x202F) + unit;
}

QString FormatReadout(double value, const QString& unit) {
  if (!std::isfinite(value)) return QStringLiteral("–");
  QString text = QString::number(value, 'g', 4);
  return unit.isEmpty() ? text : text + QChar(0x202F) + unit;
}

void SetRoundAxis(QValueAxis* axis, double lo, double hi, double step) {
  axis->setTickType(QValueAxis::TicksDynamic);
  axis->setTickAnchor(0.0);
  axis->setTickInterval(step);
  axis->setLabelFormat(QString("%.%1f").arg(DecimalsFor(step)));
  axis->setRange(lo, hi);
}

void SetRoundAxis(QValueAxis* axis, const RoundRange& range) {
  SetRoundAxis(axis, range.min, range.max, range.step);
}

}  // namespace filmdyn::ui
