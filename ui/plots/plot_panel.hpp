#pragma once
/// @file The result plots of all runs kept in the session, overlaid: one chart per standard plot,
/// one series per (run, curve), colour by run, line style by curve. Series are updated with
/// QXYSeries::replace() (never clear + append). A vertical cursor on the crank-angle plots
/// follows the field view.
#include <QMap>
#include <QWidget>
#include <vector>

#include "ui/plots/plot_specs.hpp"
#include "ui/plots/plot_run.hpp"
#include "ui/run/run_record.hpp"

QT_BEGIN_NAMESPACE
class QChart;
class QChartView;
class QLineSeries;
QT_END_NAMESPACE

namespace filmdyn::ui {

class PlotPanel : public QWidget {
  Q_OBJECT

 public:
  explicit PlotPanel(QWidget* parent = nullptr);

  /// Adds the run if new, then redraws its series from its current samples.
  void updateRun(const RunHandle& run) { updateRun(PlotRunOf(*run)); }
  void updateRun(const PlotRun& run);
  void removeRun(int run_id);
  void setRunVisible(int run_id, bool visible);
  bool isRunVisible(int run_id) const;

  int chartCount() const { return int(charts_.size()); }
  QChart* chart(int index) const;
  QString chartId(int index) const;
  /// Points currently drawn for a run over all its series (tests, status).
  int pointCount(int run_id) const;
  double cursorAngle() const { return cursor_angle_; }

 public slots:
  /// Crank angle [°CA] of the cursor line (NaN hides it).
  void setCursorAngle(double crank_angle_deg);
  /// Asks for a file and exports one chart (PNG/SVG/PDF by suffix).
  void exportChartInteractive(int index);

 signals:
  void statusMessage(const QString& message);
  /// The user clicked a crank-angle plot at this angle [°CA] (moves the field view).
  void crankAngleClicked(double crank_angle_deg);

 private:
  struct ChartEntry {
    const PlotSpec* spec;
    QChart* chart;
    QChartView* view;
    QLineSeries* cursor = nullptr;
    QLineSeries* clearance_circle = nullptr;
    double fitted_aspect = 0;  ///< plot-area aspect the equal-axes ranges were fitted to
    QMap<int, std::vector<QLineSeries*>> run_series;
  };
  void rescale(ChartEntry& entry);
  void updateCursor(ChartEntry& entry);
  QColor runColour(int run_id);
  bool eventFilter(QObject* watched, QEvent* event) override;

  std::vector<ChartEntry> charts_;
  QMap<int, bool> visible_;
  QMap<int, QColor> colours_;
  QMap<int, double> clearance_um_;
  double cursor_angle_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace filmdyn::ui
