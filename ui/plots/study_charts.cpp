#include "ui/plots/study_charts.hpp"

#include <QBarCategoryAxis>
#include <QBarSet>
#include <QCategoryAxis>
#include <QChart>
#include <QDir>
#include <QFile>
#include <QFontMetricsF>
#include <QGraphicsObject>
#include <QHorizontalBarSeries>
#include <QLineSeries>
#include <QPainter>
#include <QScatterSeries>
#include <QValueAxis>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <numeric>
#include <random>

#include "core/base/input_error.hpp"
#include "core/engine/case_diff.hpp"
#include "core/engine/case_schema.hpp"
#include "core/io/run_comparison.hpp"
#include "ui/charts/chart_export.hpp"
#include "ui/charts/palette.hpp"
#include "ui/charts/round_ticks.hpp"

namespace filmdyn::ui {

namespace {

// Panel sizes of the pictures [logical px].
const QSize kScatterCell(360, 300);
constexpr int kMainEffectsColumns = 3;
// The most dots the scatter matrix is written as SVG with (beyond, as PNG only).
constexpr std::size_t kSvgDots = 10000;

bool Done(const batch::StudyRow& r) { return r.state == batch::PointState::kDone; }
// A done point that has figure k (what a plot of the figure can draw).
bool HasFigure(const batch::StudyRow& r, std::size_t k) {
  return Done(r) && k < r.figures.size() && r.figures[k].has_value();
}

QString Text(const std::string& text) { return QString::fromStdString(text); }

QString FactorTitle(const batch::StudyFactor& f) { return FactorDisplay(f).title; }

// The unit of a figure's display name ("min skirt MOFT [µm]" → "µm"; "" for "[-]" or none).
QString FigureUnit(const io::ComparisonFigure& figure) {
  const QString name = Text(figure.display_name);
  const qsizetype open = name.lastIndexOf('['), close = name.lastIndexOf(']');
  if (open < 0 || close < open) return {};
  const QString unit = name.mid(open + 1, close - open - 1);
  return unit == "-" ? QString() : unit;
}

// A figure's axis title: its display name, the unit on a line of its own when the name is long
// (a small panel's axis would cut it short).
QString AxisTitle(const io::ComparisonFigure& figure) {
  const QString name = Text(figure.display_name);
  const qsizetype open = name.lastIndexOf(" [");
  if (name.size() <= 24 || open < 0) return name;
  return name.left(open).toHtmlEscaped() + "<br>" + name.mid(open + 1).toHtmlEscaped();
}

// A value and its unit for a legend: four significant digits, whole numbers from 1000 up
// ("12800 N", not "1.28e+04 N").
QString Readout(double value, const QString& unit) {
  if (std::isfinite(value) && std::abs(value) >= 1000 && std::abs(value) < 1e9) {
    const QString text = QString::number(std::round(value), 'f', 0);
    return unit.isEmpty() ? text : text + QChar(0x202F) + unit;
  }
  return FormatReadout(value, unit);
}

// The axis over [lo, hi] with a little room either side, so that markers on the extremes are
// drawn whole; ticks on round steps (a constant gets a round step either side).
void SetPaddedAxis(QValueAxis* axis, double lo, double hi, int target) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi > lo)) {
    const RoundRange range = RoundRangeCovering(lo, hi, target);
    lo = range.min, hi = range.max;
  }
  const double step = RoundStep(hi - lo, target);
  const double pad = 0.06 * (hi - lo);
  axis->setTickType(QValueAxis::TicksDynamic);
  axis->setTickAnchor(0.0);
  axis->setTickInterval(step);
  axis->setLabelFormat(QString("%.%1f").arg(DecimalsFor(step)));
  axis->setRange(lo - pad, hi + pad);
}

// A factor's axis (FactorDisplay's units): labels in the shortest form ("2000", "0.015", "25").
void SetFactorAxis(QValueAxis* axis, double lo, double hi, int target) {
  SetPaddedAxis(axis, lo, hi, target);
  axis->setLabelFormat("%g");
}

// The legend of a main-effects chart: a line per factor below the plot, each with its colour's
// line and marker. (Qt's legend puts its entries side by side and cuts their texts short.) A
// child of the chart, so an export of the chart draws it.
class LegendBelow : public QGraphicsObject {
 public:
  struct Entry {
    QColor colour;
    QString text;
  };
  /// `lines`: the lines to reserve (at least the entries'), so that charts shown side by side
  /// keep plots of the same height.
  LegendBelow(QChart* chart, std::vector<Entry> entries, std::size_t lines)
      : QGraphicsObject(chart),
        chart_(chart),
        entries_(std::move(entries)),
        lines_(std::max(lines, entries_.size())) {
    font_ = chart->font();
    font_.setPointSizeF(std::max(7.0, font_.pointSizeF() * 0.9));
    setZValue(100);
    chart->setMargins(QMargins(2, 2, 2, 2 + int(std::ceil(Height()))));
    connect(chart, &QGraphicsWidget::geometryChanged, this, [this] { prepareGeometryChange(); });
  }
  QRectF boundingRect() const override {
    const QRectF r = chart_->rect();
    return QRectF(r.left(), r.bottom() - Height() - 4, r.width(), Height());
  }
  void paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) override {
    const QRectF area = boundingRect();
    const QFontMetricsF metrics(font_);
    painter->setFont(font_);
    const double left = area.left() + 14, text_left = left + kSwatch + 8;
    for (std::size_t k = 0; k < entries_.size(); ++k) {
      const double mid = area.top() + (double(k) + 0.5) * LineHeight();
      painter->setPen(QPen(entries_[k].colour, 2.0));
      painter->drawLine(QPointF(left, mid), QPointF(left + kSwatch, mid));
      painter->setBrush(entries_[k].colour);
      painter->drawEllipse(QPointF(left + kSwatch / 2, mid), 4.0, 4.0);
      painter->setPen(QColor(50, 50, 50));
      const QString text =
          metrics.elidedText(entries_[k].text, Qt::ElideRight, area.right() - 8 - text_left);
      painter->drawText(QPointF(text_left, mid + (metrics.ascent() - metrics.descent()) / 2), text);
    }
  }

 private:
  static constexpr double kSwatch = 26;  // the line sample's length [px]
  double LineHeight() const { return QFontMetricsF(font_).height() + 4; }
  double Height() const { return double(lines_) * LineHeight() + 4; }

  QChart* chart_;
  std::vector<Entry> entries_;
  std::size_t lines_;
  QFont font_;
};

QChart* NewChart() {
  auto* chart = new QChart;
  chart->setMargins(QMargins(2, 2, 2, 2));
  chart->legend()->hide();
  return chart;
}

// The value of factor f at a row as a number: the number, or for a text factor the position of
// its level in `categories` (appended when it is none of them).
double FactorPosition(const batch::StudyFactor& factor, const batch::StudyRow& row, std::size_t f,
                      std::vector<std::string>* categories) {
  if (!factor.is_text()) {
    const double scale = FactorDisplay(factor).scale;
    if (f < row.point.numbers.size() && row.point.numbers[f]) return *row.point.numbers[f] / scale;
    double value = std::numeric_limits<double>::quiet_NaN();
    ParseNumber(row.point.values[f], value);
    return value / scale;
  }
  const std::string& value = row.point.values[f];
  auto it = std::find(categories->begin(), categories->end(), value);
  if (it == categories->end()) it = categories->insert(categories->end(), value);
  return double(it - categories->begin());
}

// A short name of factor f: the last part of its path ("cold_clearance"), or the whole path
// when another factor's path ends the same way (skirt.model, big_end.model).
std::string ShortName(const batch::Study& study, std::size_t f) {
  auto last = [](const std::string& path) { return path.substr(path.rfind('.') + 1); };
  const std::string name = last(study.factors[f].path);
  for (std::size_t g = 0; g < study.factors.size(); ++g) {
    if (g != f && last(study.factors[g].path) == name) return study.factors[f].path;
  }
  return name;
}

}  // namespace

StudyFactorDisplay FactorDisplay(const batch::StudyFactor& factor) {
  StudyFactorDisplay d{Text(factor.path), {}, 1.0};
  if (factor.is_text()) return d;
  const engine::CaseField* field = engine::FindCaseField(factor.path);
  if (field != nullptr && !field->display_unit.empty()) {
    d.unit = Text(field->display_unit);
    d.scale = field->display_scale;
  } else {
    d.unit = Text(factor.unit);
  }
  if (d.unit == "-") d.unit.clear();
  if (!d.unit.isEmpty()) d.title += " [" + d.unit + "]";
  return d;
}

QString FactorValueText(const batch::StudyFactor& factor, const std::string& value,
                        std::optional<double> number) {
  // A run model by its title, as the run page and the case editor name it ("Only-LBRBE").
  if (factor.path == batch::kModelFactor) return Text(engine::ModelTitle(value));
  // A choice by its title, as the case editor shows it ("JFO (mass-conserving)", "0W-20").
  if (const engine::CaseField* field = engine::FindCaseField(factor.path);
      field != nullptr && field->kind == engine::FieldKind::kChoice) {
    if (const int k = field->ChoiceIndex(value); k >= 0)
      return Text(field->ChoiceTitle(std::size_t(k)));
  }
  if (factor.is_text() || !number) return Text(value);
  return QString::number(*number / FactorDisplay(factor).scale, 'g', 4);
}

std::vector<std::size_t> StudyPlotFigures(const std::vector<batch::StudyRow>& rows) {
  std::vector<std::size_t> figures;
  for (std::size_t k = 0; k < io::ComparisonFigures().size(); ++k) {
    double lo = INFINITY, hi = -INFINITY;
    for (const batch::StudyRow& r : rows) {
      if (!HasFigure(r, k)) continue;
      lo = std::min(lo, *r.figures[k]);
      hi = std::max(hi, *r.figures[k]);
    }
    if (hi > lo) figures.push_back(k);
  }
  return figures;
}

std::vector<std::size_t> StudyScatterRows(const std::vector<batch::StudyRow>& rows,
                                          std::size_t figure) {
  std::vector<std::size_t> drawn;
  for (std::size_t n = 0; n < rows.size(); ++n) {
    if (HasFigure(rows[n], figure)) drawn.push_back(n);
  }
  if (drawn.size() <= kMaxScatterDots) return drawn;
  // A uniform random sample, the same every time (a fixed seed; the first kMaxScatterDots of a
  // Fisher–Yates shuffle on the generator's raw output), in the order of `rows`. Not every k-th
  // row: a factorial's order would alias with its levels.
  std::mt19937_64 random(20261125);
  for (std::size_t i = 0; i < kMaxScatterDots; ++i) {
    const std::size_t j = i + std::size_t(random() % (drawn.size() - i));
    std::swap(drawn[i], drawn[j]);
  }
  drawn.resize(kMaxScatterDots);
  std::sort(drawn.begin(), drawn.end());
  return drawn;
}

std::size_t StudyScatterCandidates(const std::vector<batch::StudyRow>& rows, std::size_t figure) {
  return std::size_t(std::count_if(rows.begin(), rows.end(), [figure](const batch::StudyRow& r) {
    return HasFigure(r, figure);
  }));
}

QChart* MakeStudyScatterChart(const batch::Study& study, const std::vector<batch::StudyRow>& rows,
                              std::size_t factor, std::size_t figure) {
  const batch::StudyFactor& f = study.factors[factor];
  const io::ComparisonFigure& fig = io::ComparisonFigures()[figure];
  QChart* chart = NewChart();
  auto* series = new QScatterSeries;
  series->setName(Text(fig.display_name));
  series->setMarkerSize(9);
  series->setColor(kPalette[0]);
  series->setBorderColor(kPalette[0].darker(140));
  // The x range covers every point of the design (not only the done ones), so the panels of a
  // factor share their x axis whatever has finished.
  std::vector<std::string> categories = f.text_levels;
  double x0 = INFINITY, x1 = -INFINITY;
  for (const batch::StudyRow& r : rows) {
    const double x = FactorPosition(f, r, factor, &categories);
    x0 = std::min(x0, x);
    x1 = std::max(x1, x);
  }
  double y0 = INFINITY, y1 = -INFINITY;
  for (std::size_t n : StudyScatterRows(rows, figure)) {
    const double x = FactorPosition(f, rows[n], factor, &categories);
    const double y = *rows[n].figures[figure] * fig.display_scale;
    series->append(x, y);
    y0 = std::min(y0, y);
    y1 = std::max(y1, y);
  }
  chart->addSeries(series);

  QAbstractAxis* x_axis = nullptr;
  if (f.is_text()) {
    auto* x = new QCategoryAxis;
    x->setLabelsPosition(QCategoryAxis::AxisLabelsPositionCenter);
    x->setStartValue(-0.5);
    for (std::size_t k = 0; k < categories.size(); ++k)
      x->append(FactorValueText(f, categories[k], std::nullopt), k + 0.5);
    x->setRange(-0.5, double(categories.size()) - 0.5);
    x->setGridLineVisible(false);
    // Four model names side by side fit a small panel a little smaller than the other labels.
    QFont font = x->labelsFont();
    font.setPointSizeF(font.pointSizeF() * 0.85);
    x->setLabelsFont(font);
    x_axis = x;
  } else {
    auto* x = new QValueAxis;
    if (!(x1 >= x0)) x0 = 0, x1 = 1;
    SetFactorAxis(x, x0, x1, 4);
    x_axis = x;
  }
  x_axis->setTitleText(FactorTitle(f));
  chart->addAxis(x_axis, Qt::AlignBottom);
  series->attachAxis(x_axis);
  if (const std::size_t all = StudyScatterCandidates(rows, figure); all > kMaxScatterDots) {
    chart->setTitle(QString("a random %1 of %2 points").arg(kMaxScatterDots).arg(all));
  }
  auto* y = new QValueAxis;
  if (!(y1 >= y0)) y0 = 0, y1 = 1;
  SetPaddedAxis(y, y0, y1, 4);
  y->setTitleText(AxisTitle(fig));
  chart->addAxis(y, Qt::AlignLeft);
  series->attachAxis(y);
  return chart;
}

QChart* MakeMainEffectsChart(const batch::Study& study, const std::vector<batch::StudyRow>& rows,
                             std::size_t figure) {
  const io::ComparisonFigure& fig = io::ComparisonFigures()[figure];
  const QString unit = FigureUnit(fig);
  // One line per factor: its points (place 0…1, mean) and the spread of its means.
  struct Line {
    std::size_t factor;
    QList<QPointF> points;
    double spread;
    QString levels;  // "2000 → 6000"
  };
  std::vector<Line> lines;
  double y0 = INFINITY, y1 = -INFINITY;
  for (const batch::MainEffect& effect : batch::MainEffects(study, rows)) {
    const batch::StudyFactor& factor = study.factors[effect.factor];
    const std::size_t n = effect.levels.size();
    if (n < 2) continue;
    // The levels from low to high (a text factor: in the study's order).
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t(0));
    if (!factor.is_text()) {
      std::stable_sort(order.begin(), order.end(), [&effect](std::size_t a, std::size_t b) {
        return *effect.levels[a].value < *effect.levels[b].value;
      });
    }
    // The levels' range: "2000 → 6000"; a text factor's levels in their order (the reader finds
    // each one's place), the middle ones left out when there are more than four.
    auto label = [&](std::size_t k) {
      return FactorValueText(factor, effect.levels[k].label, effect.levels[k].value);
    };
    QString levels = label(order.front());
    if (factor.is_text() && n <= 4) {
      for (std::size_t rank = 1; rank + 1 < n; ++rank) levels += " → " + label(order[rank]);
    } else if (factor.is_text()) {
      levels += " → …";
    }
    levels += " → " + label(order.back());
    Line line{effect.factor, {}, 0.0, levels};
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t rank = 0; rank < n; ++rank) {
      const auto& mean = effect.levels[order[rank]].means[figure];
      if (!mean) continue;
      const double y = *mean * fig.display_scale;
      line.points.append(QPointF(double(rank) / double(n - 1), y));
      lo = std::min(lo, y);
      hi = std::max(hi, y);
    }
    if (line.points.size() < 2) continue;  // one level with a mean shows no effect
    line.spread = hi - lo;
    y0 = std::min(y0, lo);
    y1 = std::max(y1, hi);
    lines.push_back(std::move(line));
  }
  if (lines.empty()) return nullptr;
  // The legend lists the factor that moves the figure most first.
  std::stable_sort(lines.begin(), lines.end(),
                   [](const Line& a, const Line& b) { return a.spread > b.spread; });

  QChart* chart = NewChart();
  chart->setTitle(Text(fig.display_name));
  auto* x = new QCategoryAxis;
  x->setLabelsPosition(QCategoryAxis::AxisLabelsPositionOnValue);
  x->setRange(-0.06, 1.06);
  x->setStartValue(-0.06);
  x->append("low", 0.0);
  x->append("high", 1.0);
  x->setTitleText("level (low → high)");
  chart->addAxis(x, Qt::AlignBottom);
  auto* y = new QValueAxis;
  SetPaddedAxis(y, y0, y1, 4);
  y->setTitleText(unit.isEmpty() ? QString("mean") : "mean [" + unit + "]");
  chart->addAxis(y, Qt::AlignLeft);
  std::vector<LegendBelow::Entry> legend;
  for (const Line& line : lines) {
    const batch::StudyFactor& factor = study.factors[line.factor];
    auto* series = new QLineSeries;
    series->setName(QString("%1 %2: spread %3")
                        .arg(FactorTitle(factor), line.levels, Readout(line.spread, unit)));
    const QColor colour = kPalette[int(line.factor) % kPaletteSize];
    series->setPen(QPen(colour, 2.0));
    series->append(line.points);
    chart->addSeries(series);
    series->setPointsVisible(true);
    series->setMarkerSize(4.5);  // the points' radius
    series->attachAxis(x);
    series->attachAxis(y);
    legend.push_back({colour, series->name()});
  }
  // A line reserved for every factor with levels, so that the charts of one study have plots of
  // one height.
  std::size_t factors = 0;
  for (const batch::StudyFactor& f : study.factors) factors += f.level_count() >= 2;
  new LegendBelow(chart, std::move(legend), factors);  // the chart owns it
  return chart;
}

QChart* MakeBestPointsChart(const batch::Study& study, const std::vector<batch::StudyRow>& rows,
                            std::size_t figure, bool largest_first, std::size_t n) {
  const io::ComparisonFigure& fig = io::ComparisonFigures()[figure];
  std::vector<std::size_t> ranked = batch::RankedPoints(rows, figure, largest_first);
  if (ranked.empty()) return nullptr;
  ranked.resize(std::min(n, ranked.size()));
  QChart* chart = NewChart();
  // Each bar is labelled with the point's number and its factors' values with their units, in
  // the order the axis title names the factors (full names would be cut short by the axis).
  QStringList names;
  for (std::size_t f = 0; f < study.factors.size(); ++f) names << Text(ShortName(study, f));
  chart->setTitle(QString("Best points by %1 (%2 first)")
                      .arg(Text(fig.display_name), largest_first ? "largest" : "smallest"));
  auto* set = new QBarSet(Text(fig.display_name));
  set->setColor(kPalette[0]);
  set->setBorderColor(kPalette[0].darker(140));
  set->setLabelColor(Qt::black);
  QStringList labels;
  double lo = 0.0, hi = 0.0;  // bars start at zero
  // Qt draws the first category at the bottom: the best goes last.
  for (auto it = ranked.rbegin(); it != ranked.rend(); ++it) {
    const batch::StudyRow& r = rows[*it];
    const double v = *r.figures[figure] * fig.display_scale;
    set->append(v);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    QString label = QString("%1:").arg(r.point.number);
    for (std::size_t f = 0; f < study.factors.size(); ++f) {
      const batch::StudyFactor& factor = study.factors[f];
      QString value = FactorValueText(factor, r.point.values[f], r.point.numbers[f]);
      if (const QString unit = FactorDisplay(factor).unit; !unit.isEmpty() && r.point.numbers[f])
        value += QChar(0x202F) + unit;
      label += (f ? " · " : " ") + value;
    }
    labels << label;
  }
  auto* series = new QHorizontalBarSeries;
  series->append(set);
  series->setBarWidth(0.7);
  series->setLabelsVisible(true);
  series->setLabelsPosition(QAbstractBarSeries::LabelsOutsideEnd);
  series->setLabelsFormat("@value");
  series->setLabelsPrecision(4);
  chart->addSeries(series);
  auto* y = new QBarCategoryAxis;
  y->append(labels);
  y->setGridLineVisible(false);
  y->setTitleText("point: " + names.join(" · "));
  chart->addAxis(y, Qt::AlignLeft);
  series->attachAxis(y);
  auto* x = new QValueAxis;
  // Room beyond the longest bar for its value.
  const double span = hi - lo > 0 ? hi - lo : std::max(std::abs(hi), 1.0);
  SetRoundAxis(
      x, RoundRangeCovering(lo < 0 ? lo - 0.15 * span : 0.0, hi > 0 ? hi + 0.15 * span : 0.0, 5));
  x->setTitleText(Text(fig.display_name));
  chart->addAxis(x, Qt::AlignBottom);
  series->attachAxis(x);
  return chart;
}

QStringList ExportStudyPlots(const batch::Study& study, const std::vector<batch::StudyRow>& rows,
                             const QString& directory, const std::string& rank_by,
                             bool largest_first, QString* error) {
  QStringList written;
  if (error) error->clear();
  if (std::none_of(rows.begin(), rows.end(), Done)) return written;
  std::size_t rank_figure = 0;
  try {
    rank_figure =
        rank_by.empty() ? batch::DefaultRankFigure(rows) : batch::StudyFigureIndex(rank_by);
  } catch (const InputError& e) {
    if (error) *error = QString::fromUtf8(e.what());
    return written;
  }
  const QString plots = QDir(directory).filePath("plots");
  if (!QDir().mkpath(plots)) {
    if (error) *error = "cannot create " + plots;
    return written;
  }
  const QString name = Text(study.name);
  const std::vector<std::size_t> figures = StudyPlotFigures(rows);
  // Writes <plots>/<base>.png and .svg of the charts (deleted afterwards); with no chart, removes
  // an older picture of that name (its study has changed since).
  // `svg` false: the PNG only (an SVG of that name removed).
  auto write = [&](const QString& base, std::vector<std::unique_ptr<QChart>> charts, int columns,
                   const QSize& cell, const QString& heading, bool svg = true) {
    std::vector<QChart*> raw;
    for (const auto& c : charts) raw.push_back(c.get());
    for (const QString& suffix : {QString("png"), QString("svg")}) {
      const QString path = QDir(plots).filePath(base + "." + suffix);
      if (raw.empty() || (suffix == "svg" && !svg)) {
        QFile::remove(path);
        continue;
      }
      const ImageFormat format = suffix == "png" ? ImageFormat::kPng : ImageFormat::kSvg;
      const bool ok = raw.size() == 1 && heading.isEmpty()
                          ? ExportChart(raw.front(), path, format, cell, error)
                          : ExportChartGrid(raw, columns, path, format, cell, heading, error);
      if (!ok) return false;
      written << path;
    }
    return true;
  };

  // Main effects: a panel per figure.
  {
    std::vector<std::unique_ptr<QChart>> charts;
    for (std::size_t k : figures) {
      if (QChart* chart = MakeMainEffectsChart(study, rows, k)) charts.emplace_back(chart);
    }
    // The legend below each plot takes a line per factor.
    int factors = 0;
    for (const batch::StudyFactor& f : study.factors) factors += f.level_count() >= 2;
    const QSize cell(500, 300 + 20 * factors);
    const int columns = std::min<int>(kMainEffectsColumns, int(charts.size()));
    if (!write("main-effects", std::move(charts), columns, cell,
               QString("%1 — main effects: the mean of each figure over the done points at each "
                       "level of a factor")
                   .arg(name)))
      return written;
  }
  // Scatter matrix: a row per figure, a column per factor.
  {
    std::vector<std::unique_ptr<QChart>> charts;
    for (std::size_t k : figures) {
      for (std::size_t f = 0; f < study.factors.size(); ++f)
        charts.emplace_back(MakeStudyScatterChart(study, rows, f, k));
    }
    // An SVG holds every dot as an element of its own (about 1 kB each: 43 MB for 1000 points
    // and 16 figures of 3 factors, bench/bench_study_plots): beyond kSvgDots, the PNG only.
    const std::size_t done = std::size_t(std::count_if(rows.begin(), rows.end(), Done));
    const bool svg = done * charts.size() <= kSvgDots;
    if (!write("scatter-matrix", std::move(charts), int(study.factors.size()), kScatterCell,
               QString("%1 — every figure against every factor (done points)").arg(name), svg))
      return written;
  }
  // Best points.
  {
    constexpr std::size_t kBest = 10;
    std::vector<std::unique_ptr<QChart>> charts;
    if (QChart* chart = MakeBestPointsChart(study, rows, rank_figure, largest_first, kBest))
      charts.emplace_back(chart);
    // A row of about 34 px a bar, under the title and above the value axis.
    const std::size_t bars = std::min(kBest, batch::RankedPoints(rows, rank_figure, false).size());
    if (!write("best-points", std::move(charts), 1, QSize(960, 130 + 34 * int(bars)), {}))
      return written;
  }
  return written;
}

}  // namespace filmdyn::ui
