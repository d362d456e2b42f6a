#include "ui/plots/plot_panel.hpp"

#include <QChart>
#include <QChartView>
#include <QFileDialog>
#include <QGraphicsItem>
#include <QGridLayout>
#include <QLabel>
#include <QLegendMarker>
#include <QLineSeries>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QScrollArea>
#include <QVBoxLayout>
#include <QValueAxis>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "core/engine/crank_train.hpp"
#include "core/engine/error_estimate.hpp"
#include "ui/charts/chart_export.hpp"
#include "ui/charts/palette.hpp"
#include "ui/charts/round_ticks.hpp"
#include "ui/plots/mark_labels.hpp"

namespace filmdyn::ui {

namespace {

const Qt::PenStyle kStyles[] = {Qt::SolidLine, Qt::DashLine, Qt::DotLine, Qt::DashDotLine};
constexpr double kLineWidth = 1.6;
constexpr int kLegendGap = 8;         // between plot area and legend [px]
constexpr double kLegendShare = 0.4;  // the legend takes at most this share of the chart width
constexpr int kReadoutWidth = 124;    // the cursor readout's column beside the plot [px]

QValueAxis* AxisX(QChart* chart) {
  return static_cast<QValueAxis*>(chart->axes(Qt::Horizontal).first());
}
QValueAxis* AxisY(QChart* chart) {
  return static_cast<QValueAxis*>(chart->axes(Qt::Vertical).first());
}

// One lap of a run's samples in crank-angle order, as the plots draw them: the samples of the last
// 720 °CA the run computed (all of a cycle's; of a run stopped late in a run-in longer than a
// cycle, whose crank angles are taken round 720 °CA, its last 720 °CA), from the lowest crank
// angle on — a cycle that starts elsewhere than 0 °CA (operating.start_crank_angle) passes
// 720 → 0 within it and is drawn from 0 °CA, joined where it started. No curve is drawn back
// across the chart, and each angle has one value. A run that has passed 720 → 0 but not yet
// computed a whole cycle (still running, or stopped) lacks the angles from where it is to where it
// started: its lap is drawn as two lines, apart there (`after_gap`, the index of the sample the
// second begins with).
struct Lap {
  std::vector<RunSample> samples;
  std::size_t after_gap = 0;  ///< 0: one line
};

Lap OneLap(const std::vector<RunSample>& samples) {
  if (samples.empty()) return {};
  std::vector<double> angle(samples.size());
  for (std::size_t k = 0; k < samples.size(); ++k) angle[k] = samples[k][Column::kCrankAngle];
  std::size_t from = samples.size() - 1;  // the lap: [from, end), less than 720 °CA long
  double span = 0.0, widest = 0.0;        // the lap's crank angles, its widest step
  for (; from > 0; --from) {
    double step = angle[from] - angle[from - 1];
    if (step < 0.0) step += 720.0;
    if (!(span + step < 720.0 - 1e-9)) break;
    span += step;
    widest = std::max(widest, step);
  }
  // A whole cycle's samples miss one step from the last back to the first.
  const bool whole = 720.0 - span < 1.5 * widest;
  const std::size_t wrap = engine::LapStart(angle, from);
  Lap lap;
  lap.samples.assign(samples.begin() + std::ptrdiff_t(wrap), samples.end());
  lap.samples.insert(lap.samples.end(), samples.begin() + std::ptrdiff_t(from),
                     samples.begin() + std::ptrdiff_t(wrap));
  if (!whole && wrap > from) lap.after_gap = samples.size() - wrap;
  return lap;
}

// A curve's points from a lap: apart where the lap has its gap.
CurvePoints LapCurve(const PlotCurve& curve, const Lap& lap) {
  if (lap.after_gap == 0) return curve.points(lap.samples);
  const auto split = lap.samples.begin() + std::ptrdiff_t(lap.after_gap);
  CurvePoints out = curve.points({lap.samples.begin(), split});
  const CurvePoints after = curve.points({split, lap.samples.end()});
  if (!out.xy.isEmpty() && !after.xy.isEmpty()) out.after_gap = out.xy.size();
  out.xy += after.xy;
  out.crank_angle.insert(out.crank_angle.end(), after.crank_angle.begin(), after.crank_angle.end());
  return out;
}

// Whether the curve's points k and k + 1 are joined.
bool Joined(const CurvePoints& curve, std::size_t k) { return curve.after_gap != qsizetype(k + 1); }

// Linear interpolation of a curve at a crank angle (NaN outside it or across a gap).
double ValueAtAngle(const CurvePoints& curve, double angle) {
  const auto& a = curve.crank_angle;
  for (size_t k = 0; k + 1 < a.size(); ++k) {
    if ((a[k] <= angle && angle <= a[k + 1]) && a[k + 1] > a[k] && Joined(curve, k)) {
      const double t = (angle - a[k]) / (a[k + 1] - a[k]);
      return curve.xy[qsizetype(k)].y() * (1 - t) + curve.xy[qsizetype(k + 1)].y() * t;
    }
  }
  if (!a.empty() && std::abs(a.back() - angle) < 1e-9) return curve.xy.back().y();
  return std::numeric_limits<double>::quiet_NaN();
}

// The point of an (x, y) curve at a crank angle, interpolated; nullopt outside.
std::optional<QPointF> PointAtAngle(const CurvePoints& curve, double angle) {
  const auto& a = curve.crank_angle;
  for (size_t k = 0; k + 1 < a.size(); ++k) {
    if (a[k] <= angle && angle <= a[k + 1] && a[k + 1] > a[k] && Joined(curve, k)) {
      const double t = (angle - a[k]) / (a[k + 1] - a[k]);
      return curve.xy[qsizetype(k)] * (1 - t) + curve.xy[qsizetype(k + 1)] * t;
    }
  }
  return std::nullopt;
}

// A run's spikes between output samples (an impact lasting a fraction of the output interval)
// would otherwise set a plot's range and flatten the rest of the curve. A point is a spike along
// a coordinate by the rule the run summary marks its extremes with: its magnitude over the
// larger magnitude beside it above engine::kUnresolvedPeakRatio. A side of the range that the
// spikes would widen by more than kSpikeClipShare of the other points' span is fitted to the
// other points: the spikes are drawn clipped and their values marked at the edge. A curve with
// fewer than kSpikeMinPoints points in view (zoomed onto the spike) is fitted whole.
constexpr double kSpikeClipShare = 0.5;
constexpr int kSpikeMinPoints = 40;

struct Extent {
  double lo = INFINITY, hi = -INFINITY;
  void Add(double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  bool Valid() const { return hi >= lo; }
};

// A spike up to this many points wide is found whole: a point beside a spike is judged again
// against its nearest neighbours that are no spikes (an impact caught by two samples, e.g. a
// mass-conserving big end's step peaks of 1548 and 554 MPa at 361 and 362 °CA beside ~60 MPa:
// the 554 MPa point hid behind the 1548 MPa one and set the plot's range).
constexpr int kSpikeMaxWidth = 3;

// Per point of the curve (the points [begin, end)): whether its y (or x) is a spike.
std::vector<bool> SpikePoints(const QList<QPointF>& xy, qsizetype begin, qsizetype end,
                              bool along_y) {
  std::vector<bool> spike(size_t(end - begin), false);
  if (end - begin < kSpikeMinPoints) return spike;
  const auto magnitude = [&](qsizetype k) { return std::abs(along_y ? xy[k].y() : xy[k].x()); };
  const auto is_spike = [&](qsizetype k) { return bool(spike[size_t(k - begin)]); };
  // The nearest point on one side that is no spike (NaN past the curve's end: judged by the
  // other side alone, as NeighbourRatio does).
  const auto beside = [&](qsizetype k, int step) {
    for (qsizetype j = k + step; j >= begin && j < end; j += step)
      if (!is_spike(j)) return magnitude(j);
    return std::numeric_limits<double>::quiet_NaN();
  };
  // Interior points only: the end of a curve still being computed is not judged by one side.
  for (int pass = 0; pass < kSpikeMaxWidth; ++pass) {
    std::vector<qsizetype> found;
    for (qsizetype k = begin + 1; k + 1 < end; ++k) {
      if (is_spike(k)) continue;
      // After the first pass only the points beside a spike are judged again.
      if (pass > 0 && !is_spike(k - 1) && !is_spike(k + 1)) continue;
      if (engine::NeighbourRatio(magnitude(k), beside(k, -1), beside(k, +1)) >
          engine::kUnresolvedPeakRatio)
        found.push_back(k);
    }
    if (found.empty()) break;
    for (qsizetype k : found) spike[size_t(k - begin)] = true;
  }
  return spike;
}

// The range to fit: `all` points', each side cut back to `smooth` (the points that are no
// spikes) where the spikes reach beyond it by more than kSpikeClipShare of its span.
Extent FitRange(const Extent& all, const Extent& smooth) {
  if (!smooth.Valid()) return all;
  const double reach = kSpikeClipShare * (smooth.hi - smooth.lo);
  Extent fit = all;
  if (all.hi - smooth.hi > reach) fit.hi = smooth.hi;
  if (smooth.lo - all.lo > reach) fit.lo = smooth.lo;
  return fit;
}

}  // namespace

/// Draws what Qt Charts does not: the legend beside the plot (colour and line style), the
/// crank-angle cursor with its readout, crank-angle marks and direction arrows. A child of the
/// chart, so exports (which render the chart's scene) contain it too.
class PlotPanel::Overlay : public QGraphicsItem {
 public:
  Overlay(const PlotPanel* panel, size_t index, QGraphicsItem* parent)
      : QGraphicsItem(parent), panel_(panel), index_(index) {
    setZValue(100);
    setAcceptedMouseButtons(Qt::NoButton);
  }
  QRectF boundingRect() const override { return static_cast<const QChart*>(parentItem())->rect(); }
  void paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) override {
    panel_->paintOverlay(panel_->charts_[index_], painter);
  }
  void refresh() {
    prepareGeometryChange();
    update();
  }

 private:
  const PlotPanel* panel_;
  size_t index_;
};

PlotPanel::PlotPanel(QWidget* parent) : QWidget(parent) {
  auto* outer = new QVBoxLayout(this);
  outer->setContentsMargins(0, 0, 0, 0);
  run_legend_ = new QLabel(this);
  run_legend_->setObjectName("run_legend");
  run_legend_->setWordWrap(true);
  run_legend_->setTextFormat(Qt::RichText);
  run_legend_->setContentsMargins(8, 2, 8, 2);
  run_legend_->setVisible(false);
  outer->addWidget(run_legend_);
  auto* scroll = new QScrollArea(this);
  scroll->setWidgetResizable(true);
  auto* grid_host = new QWidget(scroll);
  auto* grid = new QGridLayout(grid_host);
  grid->setSpacing(2);
  const auto& specs = StandardPlots();
  charts_.reserve(specs.size());
  for (size_t i = 0; i < specs.size(); ++i) {
    ChartEntry entry;
    entry.spec = &specs[i];
    entry.chart = new QChart;
    entry.chart->setTitle(specs[i].title);
    entry.chart->setMargins(QMargins(2, 2, 2, 2));
    entry.chart->legend()->hide();  // our own legend (Overlay) shows line styles and wraps
    auto* x = new QValueAxis;
    auto* y = new QValueAxis;
    x->setTitleText(specs[i].x_title);
    y->setTitleText(specs[i].y_title);
    if (specs[i].crank_angle_axis) SetRoundAxis(x, 0, 720, 90);
    entry.chart->addAxis(x, Qt::AlignBottom);
    entry.chart->addAxis(y, Qt::AlignLeft);
    entry.anchor = new QLineSeries;
    entry.chart->addSeries(entry.anchor);
    entry.anchor->attachAxis(x);
    entry.anchor->attachAxis(y);
    if (specs[i].clearance_circle) {
      entry.clearance_circle = new QLineSeries;
      entry.clearance_circle->setName(tr("clearance"));
      entry.clearance_circle->setPen(QPen(QColor(60, 60, 60), 1.2));
      entry.chart->addSeries(entry.clearance_circle);
      entry.clearance_circle->attachAxis(x);
      entry.clearance_circle->attachAxis(y);
    }
    entry.overlay = new Overlay(this, i, entry.chart);
    const size_t index = i;
    connect(entry.chart, &QChart::plotAreaChanged, this, [this, index](const QRectF& area) {
      ChartEntry& e = charts_[index];
      e.overlay->refresh();
      if (!e.spec->equal_axes) return;
      // Re-fit after a resize; small changes (axis labels) are ignored so this cannot loop.
      const double aspect = area.height() > 10 ? area.width() / area.height() : 1.0;
      if (e.fitted_aspect > 0 && std::abs(aspect - e.fitted_aspect) < 0.03 * e.fitted_aspect) {
        return;
      }
      // At once (exports render right after a resize, with no event loop in between); the
      // threshold above ends the recursion when the new labels shift the area a little.
      rescale(e);
    });
    connect(entry.chart, &QGraphicsWidget::geometryChanged, this,
            [this, index] { relayoutLegend(charts_[index]); });
    entry.view = new QChartView(entry.chart, grid_host);
    entry.view->setObjectName("chart_" + specs[i].id);
    entry.view->setRenderHint(QPainter::Antialiasing);
    entry.view->setMinimumSize(330, 250);
    entry.view->setMouseTracking(true);
    entry.view->viewport()->setMouseTracking(true);
    entry.view->setContextMenuPolicy(Qt::CustomContextMenu);
    const int chart_index = int(i);
    connect(entry.view, &QWidget::customContextMenuRequested, this,
            [this, chart_index](QPoint pos) {
              QMenu menu;
              menu.addAction(tr("Export plot (PNG, SVG, PDF)…"), this,
                             [this, chart_index] { exportChartInteractive(chart_index); });
              QAction* reset = menu.addAction(tr("Reset zoom"), this,
                                              [this, chart_index] { resetZoom(chart_index); });
              reset->setEnabled(isZoomed(chart_index));
              menu.exec(charts_[size_t(chart_index)].view->mapToGlobal(pos));
            });
    entry.view->viewport()->installEventFilter(this);
    grid->addWidget(entry.view, int(i) / 3, int(i) % 3);
    charts_.push_back(entry);
  }
  for (ChartEntry& entry : charts_) rescale(entry);
  scroll->setWidget(grid_host);
  outer->addWidget(scroll);
}

PlotPanel::~PlotPanel() = default;

QChart* PlotPanel::chart(int index) const { return charts_[size_t(index)].chart; }
QChartView* PlotPanel::chartView(int index) const { return charts_[size_t(index)].view; }
QString PlotPanel::chartId(int index) const { return charts_[size_t(index)].spec->id; }
int PlotPanel::chartIndex(const QString& id) const {
  for (size_t i = 0; i < charts_.size(); ++i) {
    if (charts_[i].spec->id == id) return int(i);
  }
  return -1;
}

int PlotPanel::entryOfViewport(QObject* watched) const {
  for (size_t i = 0; i < charts_.size(); ++i) {
    if (charts_[i].view->viewport() == watched) return int(i);
  }
  return -1;
}

bool PlotPanel::eventFilter(QObject* watched, QEvent* event) {
  const int index = entryOfViewport(watched);
  if (index < 0) return QWidget::eventFilter(watched, event);
  ChartEntry& entry = charts_[size_t(index)];
  auto value_at = [&entry](QPointF widget_pos) {
    const QPointF scene = entry.view->mapToScene(widget_pos.toPoint());
    return entry.chart->mapToValue(entry.chart->mapFromScene(scene), entry.anchor);
  };
  auto in_plot = [&entry](QPointF widget_pos) {
    const QPointF scene = entry.view->mapToScene(widget_pos.toPoint());
    return entry.chart->plotArea().contains(entry.chart->mapFromScene(scene));
  };
  switch (event->type()) {
    case QEvent::MouseMove: {
      auto* mouse = static_cast<QMouseEvent*>(event);
      if (panning_) {
        const QPointF value = value_at(mouse->position());
        panChart(index, pan_last_value_ - value);
        pan_last_value_ = value_at(mouse->position());
        return true;
      }
      if (!in_plot(mouse->position())) {
        setHoverAngle(std::numeric_limits<double>::quiet_NaN());
        break;
      }
      const QPointF value = value_at(mouse->position());
      if (entry.spec->crank_angle_axis) {
        setHoverAngle(std::clamp(value.x(), 0.0, 720.0));
        break;
      }
      // Orbit / portrait: the crank angle of the nearest drawn point (in pixels).
      double best = INFINITY, angle = std::numeric_limits<double>::quiet_NaN();
      const QPointF mouse_pos = entry.chart->mapFromScene(entry.view->mapToScene(mouse->pos()));
      for (int id : visibleRunsWithData(entry)) {
        for (const CurvePoints& curve : entry.run_points.value(id)) {
          for (qsizetype k = 0; k < curve.xy.size(); ++k) {
            const QPointF p = entry.chart->mapToPosition(curve.xy[k], entry.anchor);
            const double d = std::hypot(p.x() - mouse_pos.x(), p.y() - mouse_pos.y());
            if (d < best) best = d, angle = curve.crank_angle[size_t(k)];
          }
        }
      }
      setHoverAngle(best < 40 ? angle : std::numeric_limits<double>::quiet_NaN());
      break;
    }
    case QEvent::Leave:
      setHoverAngle(std::numeric_limits<double>::quiet_NaN());
      break;
    case QEvent::MouseButtonPress: {
      auto* mouse = static_cast<QMouseEvent*>(event);
      press_pos_ = mouse->pos();
      if (mouse->button() == Qt::MiddleButton ||
          (mouse->button() == Qt::LeftButton && (mouse->modifiers() & Qt::ShiftModifier))) {
        panning_ = true;
        pan_last_value_ = value_at(mouse->position());
        return true;
      }
      break;
    }
    case QEvent::MouseButtonRelease: {
      auto* mouse = static_cast<QMouseEvent*>(event);
      if (panning_) {
        panning_ = false;
        return true;
      }
      const bool click = (mouse->pos() - press_pos_).manhattanLength() < 4;
      if (mouse->button() == Qt::LeftButton && click && in_plot(mouse->position())) {
        const double angle =
            entry.spec->crank_angle_axis ? value_at(mouse->position()).x() : hover_angle_;
        if (std::isfinite(angle)) emit crankAngleClicked(std::clamp(angle, 0.0, 720.0));
      }
      break;
    }
    case QEvent::MouseButtonDblClick:
      resetZoom(index);
      return true;
    case QEvent::Wheel: {
      auto* wheel = static_cast<QWheelEvent*>(event);
      if (!in_plot(wheel->position())) break;
      const double notches = wheel->angleDelta().y() / 120.0;
      if (notches == 0) break;
      zoomChart(index, std::pow(0.8, notches), value_at(wheel->position()));
      return true;
    }
    default:
      break;
  }
  return QWidget::eventFilter(watched, event);
}

void PlotPanel::updateRun(const PlotRun& run) {
  const int id = run.id;
  if (!runs_.contains(id)) {
    RunEntry r;
    r.colour = kPalette[colours_used_++ % kPaletteSize];
    runs_[id] = r;
    order_.push_back(id);
  }
  RunEntry& r = runs_[id];
  r.label = run.label;
  r.clearance_um = run.bearing_clearance * 1e6;
  const Lap samples = OneLap(run.samples), motion = OneLap(run.motion);
  for (ChartEntry& entry : charts_) {
    auto& series = entry.run_series[id];
    const auto new_line = [&](size_t kind) {
      auto* s = new QLineSeries;
      s->setName(entry.spec->curves[kind].name);
      entry.chart->addSeries(s);
      s->attachAxis(AxisX(entry.chart));
      s->attachAxis(AxisY(entry.chart));
      s->setVisible(r.visible);
      return s;
    };
    if (series.empty()) {
      // The part after a gap only when a run has one (every series costs time to draw).
      for (size_t k = 0; k < entry.spec->curves.size(); ++k)
        series.push_back({new_line(k), nullptr});
    }
    auto& points = entry.run_points[id];
    points.resize(series.size());
    for (size_t k = 0; k < series.size(); ++k) {
      const PlotCurve& curve = entry.spec->curves[k];
      // A quantity of a film the run has not (an ideal joint's zeros) is no data.
      const bool has_film = curve.film == FilmOf::kNone ||
                            (curve.film == FilmOf::kSkirt ? run.skirt_film : run.big_end_film);
      points[k] = has_film ? LapCurve(curve, curve.from_motion && !motion.samples.empty() ? motion
                                                                                          : samples)
                           : CurvePoints{};
      const qsizetype gap = points[k].after_gap < 0 ? points[k].xy.size() : points[k].after_gap;
      series[k][0]->replace(points[k].xy.first(gap));
      if (points[k].after_gap >= 0 && series[k][1] == nullptr) series[k][1] = new_line(k);
      if (series[k][1] != nullptr) series[k][1]->replace(points[k].xy.sliced(gap));
    }
  }
  restyle();
}

void PlotPanel::removeRun(int run_id) {
  for (ChartEntry& entry : charts_) {
    for (const auto& lines : entry.run_series.value(run_id)) {
      for (QLineSeries* s : lines) {
        if (s == nullptr) continue;
        entry.chart->removeSeries(s);
        delete s;
      }
    }
    entry.run_series.remove(run_id);
    entry.run_points.remove(run_id);
  }
  runs_.remove(run_id);
  order_.erase(std::remove(order_.begin(), order_.end(), run_id), order_.end());
  restyle();
}

void PlotPanel::setRunVisible(int run_id, bool visible) {
  if (!runs_.contains(run_id)) return;
  runs_[run_id].visible = visible;
  for (ChartEntry& entry : charts_) {
    for (const auto& lines : entry.run_series.value(run_id))
      for (QLineSeries* s : lines)
        if (s != nullptr) s->setVisible(visible);
  }
  restyle();
}

bool PlotPanel::isRunVisible(int run_id) const {
  return runs_.contains(run_id) && runs_[run_id].visible;
}

void PlotPanel::setRunLabel(int run_id, const QString& label) {
  if (!runs_.contains(run_id)) return;
  runs_[run_id].label = label;
  restyle();
}

void PlotPanel::setRunOrder(const std::vector<int>& run_ids) {
  std::vector<int> order;
  for (int id : run_ids) {
    if (runs_.contains(id) && std::find(order.begin(), order.end(), id) == order.end()) {
      order.push_back(id);
    }
  }
  for (int id : order_) {
    if (std::find(order.begin(), order.end(), id) == order.end()) order.push_back(id);
  }
  order_ = order;
  restyle();
}

int PlotPanel::pointCount(int run_id) const {
  int count = 0;
  for (const ChartEntry& entry : charts_) {
    for (const auto& lines : entry.run_series.value(run_id))
      for (QLineSeries* s : lines) count += s != nullptr ? int(s->count()) : 0;
  }
  return count;
}

std::vector<int> PlotPanel::visibleRunsWithData(const ChartEntry& entry) const {
  std::vector<int> ids;
  for (int id : order_) {
    if (!runs_.value(id).visible) continue;
    for (const CurvePoints& c : entry.run_points.value(id)) {
      if (!c.xy.isEmpty()) {
        ids.push_back(id);
        break;
      }
    }
  }
  return ids;
}

std::vector<size_t> PlotPanel::kindsWithData(const ChartEntry& entry) const {
  std::vector<size_t> kinds;
  for (size_t k = 0; k < entry.spec->curves.size(); ++k) {
    for (int id : order_) {
      if (!runs_.value(id).visible) continue;
      const auto points = entry.run_points.value(id);
      if (k < points.size() && !points[k].xy.isEmpty()) {
        kinds.push_back(k);
        break;
      }
    }
  }
  return kinds;
}

bool PlotPanel::singleRunMode() const {
  int visible = 0;
  for (int id : order_) visible += runs_.value(id).visible ? 1 : 0;
  return visible <= 1;
}

QPen PlotPanel::seriesPen(int run_id, size_t kind) const {
  const QColor colour =
      singleRunMode() ? kPalette[kind % kPaletteSize] : runs_.value(run_id).colour;
  return QPen(colour, kLineWidth, kStyles[kind % 4], Qt::RoundCap);
}

void PlotPanel::restyle() {
  for (ChartEntry& entry : charts_) {
    for (auto it = entry.run_series.begin(); it != entry.run_series.end(); ++it) {
      for (size_t k = 0; k < it.value().size(); ++k) {
        for (QLineSeries* s : it.value()[k])
          if (s != nullptr) s->setPen(seriesPen(it.key(), k));
      }
    }
    rescale(entry);
    relayoutLegend(entry);
  }
  const QString legend = runLegendText();
  run_legend_->setText(legend);
  run_legend_->setVisible(!legend.isEmpty() && !runs_in_chart_legends_);
}

QString PlotPanel::runLegendText() const {
  QStringList items;
  const bool single = singleRunMode();
  for (int id : order_) {
    const RunEntry& r = runs_[id];
    if (!r.visible) continue;
    const QString swatch =
        single ? QString()
               : QString("<span style=\"color:%1\"><b>━━━</b></span>&nbsp;").arg(r.colour.name());
    items << swatch + r.label.toHtmlEscaped();
  }
  if (items.isEmpty()) return {};
  return (single ? tr("Run shown: ") : tr("Runs shown: ")) +
         items.join("&nbsp;&nbsp;&nbsp;&nbsp; ");
}

void PlotPanel::setRunsInChartLegends(bool on) {
  runs_in_chart_legends_ = on;
  restyle();
}

bool PlotPanel::exportChart(int index, const QString& path, ImageFormat format, const QSize& size,
                            QString* error) {
  const bool was = runs_in_chart_legends_;
  exporting_ = true;
  runs_in_chart_legends_ = true;
  relayoutLegend(charts_[size_t(index)]);
  const bool ok = ExportChart(chart(index), path, format, size, error);
  runs_in_chart_legends_ = was;
  exporting_ = false;
  relayoutLegend(charts_[size_t(index)]);
  return ok;
}

std::vector<std::pair<QString, QPen>> PlotPanel::legendEntries(int index) const {
  const ChartEntry& entry = charts_[size_t(index)];
  std::vector<std::pair<QString, QPen>> out;
  const std::vector<int> runs = visibleRunsWithData(entry);
  const std::vector<size_t> kinds = kindsWithData(entry);
  if (runs.empty()) return out;
  const bool single = singleRunMode();
  if (single) {
    // One run: named (when the plot stands alone), each kind in its own colour and style.
    if (runs_in_chart_legends_) out.emplace_back(runs_.value(runs.front()).label, QPen(Qt::NoPen));
    if (entry.spec->curves.size() > 1) {
      for (size_t k : kinds)
        out.emplace_back(entry.spec->curves[k].name, seriesPen(runs.front(), k));
    }
    return out;
  }
  // Several runs: kinds by line style (in grey), runs by colour. A plot of several kinds names
  // the kinds with data even when only one has any (its line style says which it is).
  if (entry.spec->curves.size() > 1) {
    for (size_t k : kinds) {
      out.emplace_back(entry.spec->curves[k].name,
                       QPen(QColor(70, 70, 70), kLineWidth, kStyles[k % 4]));
    }
  }
  if (runs_in_chart_legends_) {
    for (int id : runs) {
      out.emplace_back(runs_.value(id).label, QPen(runs_.value(id).colour, 2.4, Qt::SolidLine));
    }
  }
  return out;
}

namespace {

QFont LegendFont(const QChart* chart) {
  QFont font = chart->font();
  font.setPointSizeF(std::max(7.0, font.pointSizeF() * 0.85));
  return font;
}
constexpr int kSwatch = 26;  // legend line sample length [px]

}  // namespace

void PlotPanel::relayoutLegend(ChartEntry& entry) {
  const int index = int(&entry - charts_.data());
  const auto entries = legendEntries(index);
  int width = 0;
  if (!entries.empty()) {
    const QFontMetricsF metrics(LegendFont(entry.chart));
    double widest = 0;
    for (const auto& [text, pen] : entries) {
      widest = std::max(
          widest, metrics.horizontalAdvance(text) + (pen.style() == Qt::NoPen ? 0 : kSwatch + 6));
    }
    const double limit = std::max(80.0, entry.chart->size().width() * kLegendShare);
    width = int(std::ceil(std::min(widest, limit))) + kLegendGap + 6;
  }
  // On screen the column beside the plot also holds the cursor readout: reserved whenever the
  // plot has data, so that hovering never shifts the plot.
  if (!exporting_ && !runs_in_chart_legends_ && !visibleRunsWithData(entry).empty()) {
    width = std::max(width, kReadoutWidth + kLegendGap + 6);
  }
  const QMargins margins(2, 2, 2 + width, 2);
  if (entry.chart->margins() != margins) entry.chart->setMargins(margins);
  entry.overlay->refresh();
}

void PlotPanel::rescale(ChartEntry& entry) {
  double clearance = 0;
  int points = 0;
  const std::vector<int> runs = visibleRunsWithData(entry);
  for (int id : order_) {
    if (!runs_.value(id).visible) continue;
    clearance = std::max(clearance, runs_.value(id).clearance_um);
    for (const CurvePoints& c : entry.run_points.value(id)) points += int(c.xy.size());
  }
  // Every shown point with crank angles in [from, to] (all of an x–y plot's), told whether it is
  // a spike between output samples (never on the journal orbit, whose clearance bounds it).
  const bool clip_spikes = !entry.spec->clearance_circle;
  const auto each_point = [&](double from, double to, const auto& visit) {
    for (int id : runs) {
      const auto found = entry.run_points.constFind(id);
      if (found == entry.run_points.cend()) continue;
      const std::vector<CurvePoints>& curves = found.value();
      for (size_t k = 0; k < curves.size(); ++k) {
        const CurvePoints& c = curves[k];
        qsizetype begin = 0, end = c.xy.size();
        if (entry.spec->crank_angle_axis) {
          while (begin < end && c.xy[begin].x() < from) ++begin;
          while (end > begin && c.xy[end - 1].x() > to) --end;
        }
        const std::vector<bool> none(size_t(end - begin), false);
        const std::vector<bool> spike_y = clip_spikes ? SpikePoints(c.xy, begin, end, true) : none;
        const std::vector<bool> spike_x = clip_spikes && !entry.spec->crank_angle_axis
                                              ? SpikePoints(c.xy, begin, end, false)
                                              : none;
        for (qsizetype i = begin; i < end; ++i)
          visit(id, k, c.xy[i], c.crank_angle[size_t(i)],
                spike_x[size_t(i - begin)] || spike_y[size_t(i - begin)]);
      }
    }
  };
  // The ranges to fit the points in [from, to] (spikes cut back: FitRange).
  const auto fit = [&](double from, double to, Extent* x, Extent* y) {
    Extent all_x, all_y, smooth_x, smooth_y;
    each_point(from, to, [&](int, size_t, QPointF p, double, bool spike) {
      all_x.Add(p.x());
      all_y.Add(p.y());
      if (!spike) smooth_x.Add(p.x()), smooth_y.Add(p.y());
    });
    *x = FitRange(all_x, smooth_x);
    *y = FitRange(all_y, smooth_y);
  };
  Extent fit_x, fit_y;
  fit(-INFINITY, INFINITY, &fit_x, &fit_y);
  double x0 = fit_x.lo, x1 = fit_x.hi, y0 = fit_y.lo, y1 = fit_y.hi;
  // Say so when the shown runs' model has no such quantity (e.g. MOFT of the Ideal model).
  const bool any_run =
      std::any_of(order_.begin(), order_.end(), [this](int id) { return runs_.value(id).visible; });
  entry.chart->setTitle(any_run && points == 0
                            ? tr("%1 — no data for the model(s) shown").arg(entry.spec->title)
                            : entry.spec->title);
  if (entry.clearance_circle) {
    QList<QPointF> circle;
    if (clearance > 0 && !runs.empty()) {
      for (int k = 0; k <= 180; ++k) {
        const double a = 2 * std::numbers::pi * k / 180;
        circle.append(QPointF(clearance * std::cos(a), clearance * std::sin(a)));
      }
    }
    entry.clearance_circle->replace(circle);
  }
  QValueAxis* ax = AxisX(entry.chart);
  QValueAxis* ay = AxisY(entry.chart);
  if (entry.spec->equal_axes) {
    // Same units per pixel on both axes. The orbit is centred on the bearing and fits the
    // clearance circle (the data may leave it only by asperity penetration); a load diagram
    // fits its data and the origin (the bearing centre the load acts through).
    const QRectF area = entry.chart->plotArea();
    const double aspect = area.height() > 10 ? area.width() / area.height() : 1.0;
    entry.fitted_aspect = aspect;
    double cx = 0, cy = 0, hx = 1, hy = 1;
    if (entry.spec->clearance_circle) {
      double r = 0;
      if (x1 >= x0) r = std::max({std::abs(x0), std::abs(x1), std::abs(y0), std::abs(y1)});
      if (clearance > 0) r = std::max(r, clearance);
      if (!(r > 0)) r = 1;
      const double step = RoundStep(2 * r, 4);
      hx = hy = std::ceil(r / step - 1e-9) * step;
    } else if (x1 >= x0) {
      x0 = std::min(x0, 0.0), x1 = std::max(x1, 0.0), y0 = std::min(y0, 0.0),
      y1 = std::max(y1, 0.0);
      const double span = std::max({x1 - x0, y1 - y0, 1e-9});
      const double step = RoundStep(span, 5);
      const RoundRange rx{std::floor(x0 / step) * step, std::ceil(x1 / step) * step, step, 0};
      const RoundRange ry{std::floor(y0 / step) * step, std::ceil(y1 / step) * step, step, 0};
      cx = 0.5 * (rx.min + rx.max), cy = 0.5 * (ry.min + ry.max);
      hx = 0.5 * (rx.max - rx.min), hy = 0.5 * (ry.max - ry.min);
    }
    // Widen the shorter side to the plot area's aspect.
    if (hx / hy < aspect)
      hx = hy * aspect;
    else
      hy = hx / aspect;
    entry.full = QRectF(QPointF(cx - hx, cy - hy), QPointF(cx + hx, cy + hy));
    const QRectF shown = entry.zoom.value_or(entry.full);
    const double shown_step = RoundStep(std::min(shown.width(), shown.height()), 4);
    SetRoundAxis(ax, shown.left(), shown.right(), shown_step);
    SetRoundAxis(ay, shown.top(), shown.bottom(), shown_step);
  } else {
    if (!(x1 >= x0)) x0 = 0, x1 = 1;
    if (!(y1 >= y0)) y0 = 0, y1 = 1;
    if (entry.spec->non_negative && y0 >= 0) y0 = 0;
    if (entry.spec->x_non_negative && x0 >= 0) x0 = 0;
    if (entry.spec->crank_angle_axis) x0 = 0, x1 = 720;
    const RoundRange ry = RoundRangeCovering(y0, y1, 5);
    const RoundRange rx =
        entry.spec->crank_angle_axis ? RoundRange{0, 720, 90, 0} : RoundRangeCovering(x0, x1, 5);
    entry.full = QRectF(QPointF(rx.min, ry.min), QPointF(rx.max, ry.max));
    if (entry.zoom) {
      const QRectF z = *entry.zoom;
      // Crank-angle plots zoom along x; y re-fits the data inside the shown crank angles.
      if (entry.spec->crank_angle_axis) {
        Extent zx, zy;
        fit(z.left(), z.right(), &zx, &zy);
        double zy0 = zy.lo, zy1 = zy.hi;
        if (!(zy1 >= zy0)) zy0 = ry.min, zy1 = ry.max;
        if (entry.spec->non_negative && zy0 >= 0) zy0 = 0;
        const RoundRange zr = RoundRangeCovering(zy0, zy1, 5);
        SetRoundAxis(ax, z.left(), z.right(), RoundStep(z.width(), 6));
        SetRoundAxis(ay, zr.min, zr.max, zr.step);
      } else {
        SetRoundAxis(ax, z.left(), z.right(), RoundStep(z.width(), 5));
        SetRoundAxis(ay, z.top(), z.bottom(), RoundStep(z.height(), 5));
      }
    } else {
      SetRoundAxis(ax, rx.min, rx.max, rx.step);
      SetRoundAxis(ay, ry.min, ry.max, ry.step);
    }
  }
  // The spikes left outside the shown range, marked at its edge by the overlay.
  entry.clipped.clear();
  const QRectF shown(QPointF(ax->min(), ay->min()), QPointF(ax->max(), ay->max()));
  each_point(ax->min(), ax->max(), [&](int id, size_t k, QPointF p, double angle, bool spike) {
    if (spike && !shown.contains(p)) entry.clipped.push_back({id, k, p, angle});
  });
  entry.overlay->refresh();
}

bool PlotPanel::isZoomed(int index) const { return charts_[size_t(index)].zoom.has_value(); }

void PlotPanel::zoomChart(int index, double factor, QPointF about) {
  ChartEntry& entry = charts_[size_t(index)];
  QRectF r = entry.zoom.value_or(entry.full);
  auto scale = [factor](double lo, double hi, double at, double* out_lo, double* out_hi) {
    at = std::clamp(at, lo, hi);
    *out_lo = at - (at - lo) * factor;
    *out_hi = at + (hi - at) * factor;
  };
  double x0, x1, y0 = r.top(), y1 = r.bottom();
  scale(r.left(), r.right(), about.x(), &x0, &x1);
  if (!entry.spec->crank_angle_axis) scale(r.top(), r.bottom(), about.y(), &y0, &y1);
  // Both axes scale by the same factor, so equal-scale plots keep their aspect.
  QRectF zoomed(QPointF(x0, y0), QPointF(x1, y1));
  // Zooming out past the full range is the full range.
  if (zoomed.width() >= entry.full.width() * (1 - 1e-9)) {
    entry.zoom.reset();
  } else {
    if (entry.spec->crank_angle_axis) {
      const double w = zoomed.width();
      zoomed.moveLeft(std::clamp(zoomed.left(), 0.0, 720.0 - w));
    }
    entry.zoom = zoomed;
  }
  rescale(entry);
}

void PlotPanel::panChart(int index, QPointF delta) {
  ChartEntry& entry = charts_[size_t(index)];
  if (!entry.zoom) return;  // nothing to pan at full range
  QRectF z = entry.zoom->translated(delta.x(), entry.spec->crank_angle_axis ? 0 : delta.y());
  if (entry.spec->crank_angle_axis) z.moveLeft(std::clamp(z.left(), 0.0, 720.0 - z.width()));
  entry.zoom = z;
  rescale(entry);
}

void PlotPanel::resetZoom(int index) {
  charts_[size_t(index)].zoom.reset();
  rescale(charts_[size_t(index)]);
}

double PlotPanel::shownAngle() const {
  return std::isfinite(hover_angle_) ? hover_angle_ : cursor_angle_;
}

void PlotPanel::setCursorAngle(double crank_angle_deg) {
  cursor_angle_ = crank_angle_deg;
  for (ChartEntry& entry : charts_) entry.overlay->refresh();
}

void PlotPanel::setHoverAngle(double crank_angle_deg) {
  if (std::isnan(crank_angle_deg) && std::isnan(hover_angle_)) return;
  hover_angle_ = crank_angle_deg;
  for (ChartEntry& entry : charts_) entry.overlay->refresh();
}

std::vector<PlotPanel::ReadoutEntry> PlotPanel::readoutEntries(int index) const {
  const ChartEntry& entry = charts_[size_t(index)];
  std::vector<ReadoutEntry> out;
  const double angle = shownAngle();
  if (!std::isfinite(angle)) return out;
  const std::vector<int> runs = visibleRunsWithData(entry);
  if (runs.empty()) return out;
  const bool single = singleRunMode();
  const bool several_kinds = kindsWithData(entry).size() > 1;
  out.push_back({QPen(Qt::NoPen), QString(), tr("%1 °CA").arg(QString::number(angle, 'f', 1))});
  for (int id : runs) {
    const auto points = entry.run_points.value(id);
    for (size_t k = 0; k < points.size(); ++k) {
      if (points[k].xy.isEmpty()) continue;
      QString who;
      if (several_kinds) who = entry.spec->curves[k].name;
      if (!single)
        who = who.isEmpty() ? runs_.value(id).label : who + " · " + runs_.value(id).label;
      QString value;
      if (entry.spec->crank_angle_axis) {
        value = FormatReadout(ValueAtAngle(points[k], angle), entry.spec->y_unit);
      } else if (const auto p = PointAtAngle(points[k], angle)) {
        value = entry.spec->x_unit == entry.spec->y_unit
                    ? FormatReadoutPair(p->x(), p->y(), entry.spec->y_unit)
                    : QString("%1, %2").arg(FormatReadout(p->x(), entry.spec->x_unit),
                                            FormatReadout(p->y(), entry.spec->y_unit));
      } else {
        value = "–";
      }
      out.push_back({seriesPen(id, k), who, value});
    }
  }
  return out;
}

std::vector<PlotPanel::ReadoutEntry> PlotPanel::compactReadoutEntries(int index) const {
  const ChartEntry& entry = charts_[size_t(index)];
  std::vector<ReadoutEntry> out;
  const double angle = shownAngle();
  if (!std::isfinite(angle) || !entry.spec->crank_angle_axis || singleRunMode()) return out;
  const std::vector<size_t> kinds = kindsWithData(entry);
  const std::vector<int> runs = visibleRunsWithData(entry);
  if (kinds.size() < 2 || runs.empty()) return out;
  out.push_back({QPen(Qt::NoPen), QString(), tr("%1 °CA").arg(QString::number(angle, 'f', 1))});
  // Thin spaces around the slashes: the column is narrow.
  const QString slash = QString(QChar(0x2009)) + "/" + QChar(0x2009);
  QStringList names;
  for (size_t k : kinds) names << entry.spec->curves[k].name;
  out.push_back(
      {QPen(Qt::NoPen), QString(),
       names.join(slash) +
           (entry.spec->y_unit.isEmpty() ? QString() : QString(" [%1]").arg(entry.spec->y_unit))});
  for (int id : runs) {
    const auto points = entry.run_points.value(id);
    std::vector<double> values;
    for (size_t k : kinds) {
      values.push_back(k < points.size() && !points[k].xy.isEmpty()
                           ? ValueAtAngle(points[k], angle)
                           : std::numeric_limits<double>::quiet_NaN());
    }
    // One run's values in one unit with common decimals ("-0.04 / -11.22 / 22.17").
    out.push_back({QPen(runs_.value(id).colour, 2.4, Qt::SolidLine), runs_.value(id).label,
                   FormatReadoutValues(values, slash)});
  }
  return out;
}

QStringList PlotPanel::readoutLines(int index) const {
  QStringList lines;
  for (const ReadoutEntry& e : readoutEntries(index)) {
    lines << (e.who.isEmpty() ? e.value : e.who + ": " + e.value);
  }
  return lines;
}

void PlotPanel::paintOverlay(const ChartEntry& entry, QPainter* painter) const {
  const int index = int(&entry - charts_.data());
  const QRectF area = entry.chart->plotArea();
  if (!area.isValid()) return;
  painter->save();
  painter->setRenderHint(QPainter::Antialiasing);
  const QFont font = LegendFont(entry.chart);
  painter->setFont(font);
  const QFontMetricsF metrics(font);
  const bool single = singleRunMode();
  const std::vector<int> runs = visibleRunsWithData(entry);
  auto to_pos = [&entry](QPointF value) { return entry.chart->mapToPosition(value, entry.anchor); };

  // Crank-angle marks every 90 °CA and arrows along the direction of travel (orbit, load).
  if (entry.spec->equal_axes) {
    painter->setClipRect(area);
    // Labels placed by PlaceMarkLabels: outward, else beside their mark, clear of the curves
    // and of every mark's dot where it can, else on a curve (on a light backing), else left out
    // (the mark's dot stays and the cursor readout names it).
    const QPointF origin = to_pos(QPointF(0, 0));
    struct PendingLabel {
      QPointF at;
      int mark;
      QColor colour;
    };
    std::vector<PendingLabel> pending;
    std::vector<QPointF> dots;
    for (int id : runs) {
      const auto points = entry.run_points.value(id);
      for (size_t k = 0; k < points.size(); ++k) {
        const QColor colour = single ? kPalette[k % kPaletteSize] : runs_.value(id).colour;
        for (int mark = 0; mark < 720; mark += 90) {
          if (const auto p = PointAtAngle(points[k], mark)) {
            const QPointF at = to_pos(*p);
            painter->setPen(QPen(Qt::white, 1));
            painter->setBrush(colour);
            painter->drawEllipse(at, 3.5, 3.5);
            // Labels once (the first run; the others' marks align), drawn over every run's
            // marks and arrows below.
            if (id == runs.front()) pending.push_back({at, mark, colour.darker(130)});
            dots.push_back(at);
          }
          // An arrowhead half way to the next mark, along the local tangent.
          const auto a = PointAtAngle(points[k], mark + 44.0);
          const auto b = PointAtAngle(points[k], mark + 46.0);
          if (a && b) {
            const QPointF pa = to_pos(*a), pb = to_pos(*b);
            const QPointF d = pb - pa;
            const double len = std::hypot(d.x(), d.y());
            if (len > 1e-6) {
              const QPointF u = d / len, n(-u.y(), u.x());
              QPainterPath head;
              head.moveTo(pb + u * 4.0);
              head.lineTo(pb - u * 5.0 + n * 4.0);
              head.lineTo(pb - u * 5.0 - n * 4.0);
              head.closeSubpath();
              painter->setPen(Qt::NoPen);
              painter->setBrush(colour);
              painter->drawPath(head);
            }
          }
        }
      }
    }
    std::vector<MarkLabel> marks;
    for (const PendingLabel& label : pending)
      marks.push_back({label.at, metrics.size(0, QString("%1°").arg(label.mark))});
    // Every shown run's curves, in pixels: the labels keep off them where they can.
    std::vector<QPolygonF> curves;
    for (int id : runs) {
      for (const CurvePoints& curve : entry.run_points.value(id)) {
        QPolygonF line;
        for (qsizetype i = 0; i < curve.xy.size(); ++i) {
          if (i == curve.after_gap && !line.isEmpty()) curves.push_back(std::exchange(line, {}));
          line << to_pos(curve.xy[i]);
        }
        if (!line.isEmpty()) curves.push_back(line);
      }
    }
    const std::vector<QRectF> placed = PlaceMarkLabels(marks, origin, area, curves, dots);
    for (std::size_t i = 0; i < pending.size(); ++i) {
      if (placed[i].isNull()) continue;
      painter->setPen(Qt::NoPen);
      painter->setBrush(QColor(255, 255, 255, 215));  // readable where it lies on a curve
      painter->drawRoundedRect(placed[i], 3.0, 3.0);
      painter->setPen(pending[i].colour);
      painter->drawText(placed[i], Qt::AlignCenter, QString("%1°").arg(pending[i].mark));
    }
    painter->setClipping(false);
  }

  // Spikes left outside the range (ClippedSpike): a triangle at the edge the curve leaves by,
  // pointing out, and the spike's value beside it inside the plot.
  if (!entry.clipped.empty()) {
    std::vector<QRectF> taken;
    for (const ClippedSpike& spike : entry.clipped) {
      const QColor colour = seriesPen(spike.run_id, spike.curve).color();
      const QPointF raw = to_pos(spike.value);
      const QPointF at(std::clamp(raw.x(), area.left(), area.right()),
                       std::clamp(raw.y(), area.top(), area.bottom()));
      QPointF out = raw - at;
      const double length = std::hypot(out.x(), out.y());
      if (!(length > 1e-9)) continue;
      out /= length;
      const QPointF side(-out.y(), out.x());
      QPainterPath head;
      head.moveTo(at);
      head.lineTo(at - out * 9.0 + side * 5.0);
      head.lineTo(at - out * 9.0 - side * 5.0);
      head.closeSubpath();
      painter->setPen(QPen(Qt::white, 1));
      painter->setBrush(colour);
      painter->drawPath(head);
      const QString value =
          entry.spec->crank_angle_axis
              ? FormatReadout(spike.value.y(), entry.spec->y_unit)
              : FormatReadoutPair(spike.value.x(), spike.value.y(), entry.spec->y_unit);
      const QString text =
          tr("%1 at %2 °CA").arg(value, QString::number(spike.crank_angle, 'f', 1));
      const QSizeF size = metrics.size(0, text) + QSizeF(6, 2);
      // Beside the triangle, inside the plot; stacked inward past labels already drawn.
      QPointF corner(at.x() + 8, out.y() > 0.5 ? at.y() - size.height() - 2 : at.y() + 2);
      if (std::abs(out.x()) > 0.5) {
        corner = QPointF(out.x() > 0 ? at.x() - size.width() - 12 : at.x() + 12,
                         at.y() - size.height() / 2);
      }
      // Inside the plot where it fits (a label wider than the plot starts at its left edge).
      corner.setX(std::max(area.left() + 1, std::min(corner.x(), area.right() - size.width() - 1)));
      corner.setY(
          std::max(area.top() + 1, std::min(corner.y(), area.bottom() - size.height() - 1)));
      QRectF box(corner, size);
      const double step = (out.y() > 0.5 ? -1.0 : 1.0) * (size.height() + 1);
      for (int tries = 0; tries < 8; ++tries) {
        if (std::none_of(taken.begin(), taken.end(),
                         [&box](const QRectF& r) { return r.intersects(box); }))
          break;
        box.translate(0, step);
      }
      taken.push_back(box);
      painter->setPen(QPen(colour.darker(130), 0.8));
      painter->setBrush(QColor(255, 255, 255, 225));
      painter->drawRect(box);
      painter->setPen(Qt::black);
      painter->drawText(box, Qt::AlignCenter, text);
    }
  }

  // The crank-angle cursor: a line on crank-angle plots, a marker on the others.
  const double angle = exporting_ ? std::numeric_limits<double>::quiet_NaN() : shownAngle();
  if (std::isfinite(angle) && !runs.empty()) {
    painter->setClipRect(area);
    if (entry.spec->crank_angle_axis) {
      const double x = to_pos(QPointF(angle, 0)).x();
      painter->setPen(QPen(QColor(80, 80, 80), 1, Qt::DashLine));
      painter->drawLine(QPointF(x, area.top()), QPointF(x, area.bottom()));
      for (int id : runs) {
        const auto points = entry.run_points.value(id);
        for (size_t k = 0; k < points.size(); ++k) {
          const double y = ValueAtAngle(points[k], angle);
          if (!std::isfinite(y)) continue;
          const QColor colour = single ? kPalette[k % kPaletteSize] : runs_.value(id).colour;
          painter->setPen(QPen(Qt::white, 1));
          painter->setBrush(colour);
          painter->drawEllipse(to_pos(QPointF(angle, y)), 3, 3);
        }
      }
    } else {
      for (int id : runs) {
        const auto points = entry.run_points.value(id);
        for (size_t k = 0; k < points.size(); ++k) {
          if (const auto p = PointAtAngle(points[k], angle)) {
            const QColor colour = single ? kPalette[k % kPaletteSize] : runs_.value(id).colour;
            painter->setPen(QPen(colour.darker(150), 1.5));
            painter->setBrush(Qt::white);
            painter->drawEllipse(to_pos(*p), 5, 5);
          }
        }
      }
    }
    painter->setClipping(false);
  }

  // The legend beside the plot: a line sample in the series' colour and style, wrapped text.
  const auto entries = legendEntries(index);
  double legend_bottom = area.top();
  if (!entries.empty()) {
    const double left = area.right() + kLegendGap;
    const double width = entry.chart->size().width() - left - 4;
    double& y = legend_bottom;
    for (const auto& [text, pen] : entries) {
      const bool heading = pen.style() == Qt::NoPen;
      const double text_left = heading ? left : left + kSwatch + 6;
      const QRectF text_box(text_left, y, std::max(20.0, width - (text_left - left)), 1000);
      const QRectF used =
          painter->boundingRect(text_box, Qt::TextWordWrap | Qt::AlignLeft | Qt::AlignTop, text);
      if (!heading) {
        QPen sample = pen;
        sample.setCapStyle(Qt::FlatCap);
        painter->setPen(sample);
        const double ly = y + metrics.ascent() * 0.6;
        painter->drawLine(QPointF(left, ly), QPointF(left + kSwatch, ly));
      }
      QFont f = font;
      f.setBold(heading);
      painter->setFont(f);
      painter->setPen(Qt::black);
      painter->drawText(text_box, Qt::TextWordWrap | Qt::AlignLeft | Qt::AlignTop, text);
      painter->setFont(font);
      y += used.height() + 3;
    }
  }
  // The cursor readout in the column beside the plot, under the legend: each value after a
  // sample of its series' line (colour = run, style = kind; the legends say which is which).
  std::vector<ReadoutEntry> readout =
      std::isfinite(angle) ? readoutEntries(index) : std::vector<ReadoutEntry>{};
  if (!readout.empty()) {
    const double left = area.right() + kLegendGap;
    double top = legend_bottom + (legend_bottom > area.top() ? 6 : 0);
    // As many lines as fit above the plot area's bottom (many runs overlaid ran past the card
    // and over the axis); too many: a line per run, and what still does not fit summed up in a
    // last line.
    const std::size_t fit = static_cast<std::size_t>(
        std::max(1.0, std::floor((area.bottom() - top - 6) / metrics.lineSpacing())));
    if (readout.size() > fit) {
      std::vector<ReadoutEntry> compact = compactReadoutEntries(index);
      if (!compact.empty() && compact.size() < readout.size()) readout = std::move(compact);
    }
    const std::size_t shown = readout.size() <= fit ? readout.size() : fit - 1;
    const std::size_t lines = shown < readout.size() ? shown + 1 : shown;
    const double h = metrics.lineSpacing() * double(lines) + 6;
    const QRectF box(left, top, entry.chart->size().width() - left - 4, h);
    painter->setPen(QPen(QColor(190, 190, 190), 0.8));
    painter->setBrush(QColor(248, 248, 248));
    painter->drawRect(box);
    if (shown < readout.size()) {
      painter->setPen(Qt::black);
      painter->drawText(QPointF(box.left() + 4, box.top() + 3 + metrics.ascent() +
                                                    double(shown) * metrics.lineSpacing()),
                        tr("… %n more", "", int(readout.size() - shown)));
    }
    for (size_t i = 0; i < shown; ++i) {
      const double baseline = box.top() + 3 + metrics.ascent() + double(i) * metrics.lineSpacing();
      double x = box.left() + 4;
      if (readout[i].pen.style() != Qt::NoPen) {
        QPen sample = readout[i].pen;
        sample.setCapStyle(Qt::FlatCap);
        painter->setPen(sample);
        const double ly = baseline - metrics.ascent() * 0.35;
        painter->drawLine(QPointF(x, ly), QPointF(x + 18, ly));
        x += 24;
      }
      QFont f = font;
      f.setBold(readout[i].pen.style() == Qt::NoPen);
      painter->setFont(f);
      painter->setPen(Qt::black);
      // Within the box: a line longer than the column (the compact readout's kinds) elided.
      painter->drawText(QPointF(x, baseline),
                        QFontMetricsF(f).elidedText(readout[i].value, Qt::ElideRight,
                                                    std::max(10.0, box.right() - 2 - x)));
      painter->setFont(font);
    }
  }
  painter->restore();
}

void PlotPanel::exportChartInteractive(int index) {
  const QString id = chartId(index);
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Export plot"), id + ".png",
      tr("PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)"));
  if (path.isEmpty()) return;
  ImageFormat format;
  if (!FormatFromSuffix(path, &format)) {
    emit statusMessage(tr("Unknown file type: %1 (use .png, .svg or .pdf)").arg(path));
    return;
  }
  QString error;
  if (exportChart(index, path, format, QSize(960, 600), &error)) {
    emit statusMessage(tr("Wrote %1").arg(path));
  } else {
    emit statusMessage(error);
  }
}

PlotRun PlotRunOf(const RunRecord& run) {
  const engine::Model model = engine::ParseModel(run.request().model);
  return {run.id(),
          run.legendLabel(),
          engine::BigEndFit(run.request().engine_case).hot_clearance,
          engine::SkirtLubricated(model),
          engine::BigEndLubricated(model),
          run.samples(),
          run.motion()};
}

}  // namespace filmdyn::ui
