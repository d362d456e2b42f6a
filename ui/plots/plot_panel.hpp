#pragma once
/// @file The result plots of all runs kept in the session, overlaid: one chart per standard plot
/// (plot_specs.hpp). With one run shown, each series kind has its own colour and line style; with
/// several, each run has one colour and each series kind one line style. The legend sits beside
/// the plot and wraps (never cuts) run labels; kinds or runs without data are not listed.
///
/// Axes step in round numbers (1, 2, 2.5, 5 × 10ⁿ); quantities that cannot be negative start at
/// zero. The journal orbit fills its panel inside the clearance circle; orbit and load diagram
/// carry crank-angle marks every 90 °CA and arrows for the direction of travel.
///
/// Reading values: moving the mouse over a crank-angle plot moves one crank-angle cursor through
/// every plot (over an orbit or phase portrait: to the nearest point's angle), and each plot lists
/// the values of its visible series there. A click pins the cursor (and moves the field view).
/// Wheel: zoom (crank-angle plots along x); Shift + drag or middle drag: pan; double click or the
/// context menu: reset. Series are updated with QXYSeries::replace() (never clear + append).
#include <QMap>
#include <QPen>
#include <QWidget>
#include <array>
#include <limits>
#include <optional>
#include <vector>

#include "ui/charts/chart_export.hpp"
#include "ui/plots/plot_run.hpp"
#include "ui/plots/plot_specs.hpp"
#include "ui/run/run_record.hpp"

QT_BEGIN_NAMESPACE
class QChart;
class QChartView;
class QLabel;
class QLineSeries;
class QPainter;
QT_END_NAMESPACE

namespace filmdyn::ui {

class PlotPanel : public QWidget {
  Q_OBJECT

 public:
  explicit PlotPanel(QWidget* parent = nullptr);
  ~PlotPanel() override;

  /// Adds the run if new (at the end of the order), then redraws its series from its current
  /// samples; the label is taken from `run` every time (renames show at once).
  void updateRun(const RunHandle& run) { updateRun(PlotRunOf(*run)); }
  void updateRun(const PlotRun& run);
  void removeRun(int run_id);
  void setRunVisible(int run_id, bool visible);
  bool isRunVisible(int run_id) const;
  /// Renames a run in every legend and readout.
  void setRunLabel(int run_id, const QString& label);
  /// Orders runs in legends and readouts as `run_ids` (ids not listed keep their place after).
  void setRunOrder(const std::vector<int>& run_ids);

  int chartCount() const { return int(charts_.size()); }
  QChart* chart(int index) const;
  QChartView* chartView(int index) const;
  QString chartId(int index) const;
  int chartIndex(const QString& id) const;  ///< -1 when there is no such plot
  /// Points currently drawn for a run over all its series (tests, status).
  int pointCount(int run_id) const;
  double cursorAngle() const { return cursor_angle_; }
  /// The angle the plots show values at: the hovered one while the mouse is over a plot, else
  /// the pinned cursor (NaN: none).
  double shownAngle() const;

  /// What a plot's legend lists, top to bottom: (text, pen) — pen style Qt::NoPen for a heading.
  /// On screen the runs are listed once, above all plots (runLegendText()), and a plot's legend
  /// lists its series kinds; an exported plot stands alone and lists the runs too.
  std::vector<std::pair<QString, QPen>> legendEntries(int index) const;
  /// The shared legend above the plots (rich text): each shown run in its colour.
  QString runLegendText() const;
  /// Writes one plot as it stands alone in a report: its legend lists the runs, no cursor.
  bool exportChart(int index, const QString& path, ImageFormat format, const QSize& size,
                   QString* error = nullptr);
  /// Runs listed in every plot's own legend (headless exports) instead of once above the plots.
  void setRunsInChartLegends(bool on);
  /// The readout a plot shows at the shown angle: the crank angle, then per visible series its
  /// pen, who it is (kind and/or run) and its value with unit. Drawn as a line sample + value.
  struct ReadoutEntry {
    QPen pen;
    QString who;
    QString value;
  };
  std::vector<ReadoutEntry> readoutEntries(int index) const;
  /// The same readout with one line per run — its series' values in the order of the plot's
  /// kinds, named with the unit in a line of their own ("F_x / F_y / gas [kN]") — for a readout of
  /// several runs and kinds too long for its column (the lines past it were left out, the newest
  /// run's first). Empty for a plot of one kind or one run.
  std::vector<ReadoutEntry> compactReadoutEntries(int index) const;
  /// The same as text lines ("who: value"; the first line the crank angle; empty when none).
  QStringList readoutLines(int index) const;
  /// The colour a run's series are drawn in when several runs are shown.
  QColor runColour(int run_id) const { return runs_.value(run_id).colour; }
  /// Zoom: scales the visible range of a plot by `factor` (< 1 zooms in) about a value point.
  void zoomChart(int index, double factor, QPointF about);
  /// A spike between output samples that a plot's range leaves out (an impact lasting a
  /// fraction of the output interval that would flatten the rest of the curve): drawn clipped,
  /// its value marked at the plot's edge. Zoomed onto it, the plot shows it whole.
  struct ClippedSpike {
    int run_id = 0;
    size_t curve = 0;
    QPointF value;           ///< the point (display units)
    double crank_angle = 0;  ///< [°CA]
  };
  const std::vector<ClippedSpike>& clippedSpikes(int index) const {
    return charts_[size_t(index)].clipped;
  }
  void panChart(int index, QPointF delta_value);
  void resetZoom(int index);
  bool isZoomed(int index) const;

 public slots:
  /// Crank angle [°CA] of the pinned cursor (NaN hides it).
  void setCursorAngle(double crank_angle_deg);
  /// The hovered angle (NaN: the mouse left the plots).
  void setHoverAngle(double crank_angle_deg);
  /// Asks for a file and exports one chart (PNG/SVG/PDF by suffix).
  void exportChartInteractive(int index);

 signals:
  void statusMessage(const QString& message);
  /// The user clicked a plot at this angle [°CA] (moves the field view).
  void crankAngleClicked(double crank_angle_deg);

 private:
  class Overlay;
  friend class Overlay;
  struct ChartEntry {
    const PlotSpec* spec = nullptr;
    QChart* chart = nullptr;
    QChartView* view = nullptr;
    QLineSeries* anchor = nullptr;  ///< empty, first series: maps values to positions
    QLineSeries* clearance_circle = nullptr;
    Overlay* overlay = nullptr;
    double fitted_aspect = 0;  ///< plot-area aspect the equal-axes ranges were fitted to
    std::optional<QRectF> zoom;  ///< the visible value range when zoomed
    QRectF full;                 ///< the automatic (unzoomed) value range
    /// Per run, per kind of curve: its line and the line of its part after a gap (a run that
    /// has not computed a whole cycle yet; nullptr until a run has one, empty after).
    QMap<int, std::vector<std::array<QLineSeries*, 2>>> run_series;
    QMap<int, std::vector<CurvePoints>> run_points;
    std::vector<ClippedSpike> clipped;  ///< spikes outside the shown range (rescale)
  };
  struct RunEntry {
    QString label;
    bool visible = true;
    QColor colour;
    double clearance_um = 0;
  };
  void rescale(ChartEntry& entry);
  void restyle();
  void relayoutLegend(ChartEntry& entry);
  void paintOverlay(const ChartEntry& entry, QPainter* painter) const;
  std::vector<int> visibleRunsWithData(const ChartEntry& entry) const;
  std::vector<size_t> kindsWithData(const ChartEntry& entry) const;
  bool singleRunMode() const;
  bool eventFilter(QObject* watched, QEvent* event) override;
  int entryOfViewport(QObject* watched) const;

  QPen seriesPen(int run_id, size_t kind) const;

  std::vector<ChartEntry> charts_;
  QLabel* run_legend_ = nullptr;
  bool runs_in_chart_legends_ = false;
  bool exporting_ = false;
  QMap<int, RunEntry> runs_;
  std::vector<int> order_;
  int colours_used_ = 0;
  double cursor_angle_ = std::numeric_limits<double>::quiet_NaN();
  double hover_angle_ = std::numeric_limits<double>::quiet_NaN();
  QPoint press_pos_;
  bool panning_ = false;
  QPointF pan_last_value_;
};

}  // namespace filmdyn::ui
