#include "ui/plots/plot_panel.hpp"

#include <QChart>
#include <QChartView>
#include <QFileDialog>
#include <QGridLayout>
#include <QLegendMarker>
#include <QLineSeries>
#include <QMenu>
#include <QMouseEvent>
#include <QScrollArea>
#include <QTimer>
#include <QVBoxLayout>
#include <QValueAxis>
#include <cmath>
#include <numbers>

#include "ui/charts/chart_export.hpp"

namespace filmdyn::ui {

namespace {

const QColor kPalette[] = {QColor(31, 119, 180),  QColor(214, 39, 40),   QColor(44, 160, 44),
                           QColor(255, 127, 14),  QColor(148, 103, 189), QColor(140, 86, 75),
                           QColor(227, 119, 194), QColor(23, 190, 207)};
const Qt::PenStyle kStyles[] = {Qt::SolidLine, Qt::DashLine, Qt::DotLine, Qt::DashDotLine};

QValueAxis* AxisX(QChart* chart) {
  return static_cast<QValueAxis*>(chart->axes(Qt::Horizontal).first());
}
QValueAxis* AxisY(QChart* chart) {
  return static_cast<QValueAxis*>(chart->axes(Qt::Vertical).first());
}

}  // namespace

PlotPanel::PlotPanel(QWidget* parent) : QWidget(parent) {
  auto* outer = new QVBoxLayout(this);
  outer->setContentsMargins(0, 0, 0, 0);
  auto* scroll = new QScrollArea(this);
  scroll->setWidgetResizable(true);
  auto* grid_host = new QWidget(scroll);
  auto* grid = new QGridLayout(grid_host);
  grid->setSpacing(2);
  const auto& specs = StandardPlots();
  for (size_t i = 0; i < specs.size(); ++i) {
    ChartEntry entry;
    entry.spec = &specs[i];
    entry.chart = new QChart;
    entry.chart->setTitle(specs[i].title);
    entry.chart->setMargins(QMargins(2, 2, 2, 2));
    entry.chart->legend()->setAlignment(Qt::AlignBottom);
    entry.chart->legend()->setFont(QFont(entry.chart->legend()->font().family(), 7));
    auto* x = new QValueAxis;
    auto* y = new QValueAxis;
    x->setTitleText(specs[i].x_title);
    y->setTitleText(specs[i].y_title);
    if (specs[i].crank_angle_axis) {
      x->setRange(0, 720);
      x->setTickCount(9);
      x->setLabelFormat("%.0f");
    }
    entry.chart->addAxis(x, Qt::AlignBottom);
    entry.chart->addAxis(y, Qt::AlignLeft);
    if (specs[i].crank_angle_axis) {
      entry.cursor = new QLineSeries;
      entry.cursor->setName(tr("cursor"));
      entry.cursor->setPen(QPen(QColor(90, 90, 90), 1, Qt::DashLine));
      entry.chart->addSeries(entry.cursor);
      entry.cursor->attachAxis(x);
      entry.cursor->attachAxis(y);
      for (QLegendMarker* m : entry.chart->legend()->markers(entry.cursor)) m->setVisible(false);
    }
    if (specs[i].equal_axes) {
      entry.clearance_circle = new QLineSeries;
      entry.clearance_circle->setName(tr("clearance"));
      entry.clearance_circle->setPen(QPen(Qt::black, 1.2));
      entry.chart->addSeries(entry.clearance_circle);
      entry.clearance_circle->attachAxis(x);
      entry.clearance_circle->attachAxis(y);
    }
    if (specs[i].equal_axes) {
      const size_t index = i;
      connect(entry.chart, &QChart::plotAreaChanged, this, [this, index](const QRectF& area) {
        // Re-fit after a resize; small changes (axis labels) are ignored so this cannot loop.
        const double aspect = area.height() > 10 ? area.width() / area.height() : 1.0;
        const double fitted = charts_[index].fitted_aspect;
        if (fitted > 0 && std::abs(aspect - fitted) < 0.03 * fitted) return;
        QTimer::singleShot(0, this, [this, index] { rescale(charts_[index]); });
      });
    }
    entry.view = new QChartView(entry.chart, grid_host);
    entry.view->setObjectName("chart_" + specs[i].id);
    entry.view->setRenderHint(QPainter::Antialiasing);
    entry.view->setMinimumSize(330, 250);
    entry.view->setContextMenuPolicy(Qt::CustomContextMenu);
    const int index = int(i);
    connect(entry.view, &QWidget::customContextMenuRequested, this, [this, index](QPoint pos) {
      QMenu menu;
      menu.addAction(tr("Export plot (PNG, SVG, PDF)…"), this,
                     [this, index] { exportChartInteractive(index); });
      menu.exec(charts_[size_t(index)].view->mapToGlobal(pos));
    });
    if (specs[i].crank_angle_axis) entry.view->viewport()->installEventFilter(this);
    grid->addWidget(entry.view, int(i) / 3, int(i) % 3);
    charts_.push_back(entry);
    rescale(charts_.back());
  }
  scroll->setWidget(grid_host);
  outer->addWidget(scroll);
}

bool PlotPanel::eventFilter(QObject* watched, QEvent* event) {
  if (event->type() == QEvent::MouseButtonPress &&
      static_cast<QMouseEvent*>(event)->button() == Qt::LeftButton) {
    for (ChartEntry& entry : charts_) {
      if (entry.view->viewport() != watched) continue;
      const QPointF scene = entry.view->mapToScene(static_cast<QMouseEvent*>(event)->pos());
      const QPointF chart_pos = entry.chart->mapFromScene(scene);
      if (entry.chart->plotArea().contains(chart_pos)) {
        emit crankAngleClicked(entry.chart->mapToValue(chart_pos).x());
      }
    }
  }
  return QWidget::eventFilter(watched, event);
}

QChart* PlotPanel::chart(int index) const { return charts_[size_t(index)].chart; }
QString PlotPanel::chartId(int index) const { return charts_[size_t(index)].spec->id; }

QColor PlotPanel::runColour(int run_id) {
  if (!colours_.contains(run_id)) {
    colours_[run_id] = kPalette[colours_.size() % (sizeof(kPalette) / sizeof(kPalette[0]))];
  }
  return colours_[run_id];
}

PlotRun PlotRunOf(const RunRecord& run) {
  const engine::BigEndCase& big_end = run.request().engine_case.big_end;
  return {run.id(), run.label(), big_end.bearing_radius - big_end.journal_radius, run.samples()};
}

void PlotPanel::updateRun(const PlotRun& run) {
  const int id = run.id;
  const std::vector<RunSample>& samples = run.samples;
  if (!visible_.contains(id)) visible_[id] = true;
  clearance_um_[id] = run.bearing_clearance * 1e6;
  const QString label = run.label;
  for (ChartEntry& entry : charts_) {
    auto& series = entry.run_series[id];
    if (series.empty()) {
      for (size_t k = 0; k < entry.spec->curves.size(); ++k) {
        auto* s = new QLineSeries;
        const QString curve = entry.spec->curves[k].name;
        s->setName(entry.spec->curves.size() > 1 ? curve + " · " + label : label);
        QPen pen(runColour(id), 1.6, kStyles[k % 4]);
        s->setPen(pen);
        entry.chart->addSeries(s);
        s->attachAxis(AxisX(entry.chart));
        s->attachAxis(AxisY(entry.chart));
        s->setVisible(visible_[id]);
        series.push_back(s);
      }
    }
    for (size_t k = 0; k < series.size(); ++k) {
      series[k]->replace(entry.spec->curves[k].points(samples));
    }
    rescale(entry);
  }
}

void PlotPanel::removeRun(int run_id) {
  for (ChartEntry& entry : charts_) {
    for (QLineSeries* s : entry.run_series.value(run_id)) {
      entry.chart->removeSeries(s);
      delete s;
    }
    entry.run_series.remove(run_id);
    rescale(entry);
  }
  visible_.remove(run_id);
  clearance_um_.remove(run_id);
}

void PlotPanel::setRunVisible(int run_id, bool visible) {
  visible_[run_id] = visible;
  for (ChartEntry& entry : charts_) {
    for (QLineSeries* s : entry.run_series.value(run_id)) s->setVisible(visible);
    rescale(entry);
  }
}

bool PlotPanel::isRunVisible(int run_id) const { return visible_.value(run_id, false); }

int PlotPanel::pointCount(int run_id) const {
  int count = 0;
  for (const ChartEntry& entry : charts_) {
    for (QLineSeries* s : entry.run_series.value(run_id)) count += int(s->count());
  }
  return count;
}

void PlotPanel::rescale(ChartEntry& entry) {
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  double clearance = 0;
  int points = 0, runs = 0;
  for (auto it = entry.run_series.begin(); it != entry.run_series.end(); ++it) {
    if (!visible_.value(it.key(), true)) continue;
    clearance = std::max(clearance, clearance_um_.value(it.key(), 0.0));
    ++runs;
    for (QLineSeries* s : it.value()) {
      points += int(s->count());
      for (const QPointF& p : s->points()) {
        x0 = std::min(x0, p.x());
        x1 = std::max(x1, p.x());
        y0 = std::min(y0, p.y());
        y1 = std::max(y1, p.y());
      }
    }
  }
  // Say so when the shown runs' model has no such quantity (e.g. MOFT of the Ideal model).
  entry.chart->setTitle(runs > 0 && points == 0
                            ? tr("%1 — no data for the model(s) shown").arg(entry.spec->title)
                            : entry.spec->title);
  if (entry.clearance_circle) {
    QList<QPointF> circle;
    if (clearance > 0) {
      for (int k = 0; k <= 120; ++k) {
        const double a = 2 * std::numbers::pi * k / 120;
        circle.append(QPointF(clearance * std::cos(a), clearance * std::sin(a)));
      }
      x0 = std::min(x0, -clearance);
      x1 = std::max(x1, clearance);
      y0 = std::min(y0, -clearance);
      y1 = std::max(y1, clearance);
    }
    entry.clearance_circle->replace(circle);
  }
  if (!(x1 >= x0)) x0 = 0, x1 = 1;
  if (!(y1 >= y0)) y0 = 0, y1 = 1;
  if (entry.spec->equal_axes) {
    // Same µm per pixel on both axes, so the clearance circle is a circle.
    const double r = std::max({std::abs(x0), std::abs(x1), std::abs(y0), std::abs(y1)}) * 1.05;
    const QRectF area = entry.chart->plotArea();
    const double aspect = area.height() > 10 ? area.width() / area.height() : 1.0;
    entry.fitted_aspect = aspect;
    x0 = -r * std::max(1.0, aspect);
    x1 = -x0;
    y0 = -r * std::max(1.0, 1.0 / aspect);
    y1 = -y0;
  }
  if (y1 - y0 < 1e-12 * std::max(1.0, std::abs(y1))) {
    const double pad = std::max(1.0, std::abs(y1) * 0.1);
    y0 -= pad;
    y1 += pad;
  }
  const double pad = entry.spec->equal_axes ? 0 : 0.05 * (y1 - y0);
  if (!entry.spec->crank_angle_axis) AxisX(entry.chart)->setRange(x0, x1 > x0 ? x1 : x0 + 1);
  AxisY(entry.chart)->setRange(y0 - pad, y1 + pad);
  if (entry.cursor) updateCursor(entry);
}

void PlotPanel::updateCursor(ChartEntry& entry) {
  QList<QPointF> line;
  if (std::isfinite(cursor_angle_)) {
    line << QPointF(cursor_angle_, AxisY(entry.chart)->min())
         << QPointF(cursor_angle_, AxisY(entry.chart)->max());
  }
  entry.cursor->replace(line);
}

void PlotPanel::setCursorAngle(double crank_angle_deg) {
  cursor_angle_ = crank_angle_deg;
  for (ChartEntry& entry : charts_) {
    if (entry.cursor) updateCursor(entry);
  }
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
  if (ExportChart(chart(index), path, format, QSize(960, 600), &error)) {
    emit statusMessage(tr("Wrote %1").arg(path));
  } else {
    emit statusMessage(error);
  }
}

}  // namespace filmdyn::ui
