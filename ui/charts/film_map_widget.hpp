#pragma once
/// @file An unrolled film map: one nodal field on a tensor grid (circumference × axial) drawn as
/// a colour image (viridis, bilinear between the nodes) with round-numbered axes, a colour bar
/// beside it and labels on its edges (which side is thrust, which end is the skirt top). Regions
/// without film (the pin-boss relief) are drawn grey and named.
#include <QRectF>
#include <QString>
#include <QWidget>
#include <cmath>
#include <utility>
#include <vector>

#include "ui/charts/round_ticks.hpp"

namespace filmdyn::ui {

struct FilmMapData {
  std::vector<double> x, y;    ///< grid lines in display units, increasing
  std::vector<double> values;  ///< x.size() × y.size(), value of node (i, j) at i + x.size() j
  QString x_title, y_title;    ///< with units
  QString value_title;         ///< e.g. "Film pressure [MPa]"
  QString left, right, top, bottom;  ///< edge labels, e.g. "thrust side"; empty: none
  std::vector<std::pair<double, double>> no_film_x;  ///< x intervals without film
  QString no_film_label;
  bool values_from_zero = true;  ///< the colour scale starts at 0 (pressures, thicknesses)
  /// A fixed colour range (e.g. over a whole cycle, so frames compare); NaN: from the values.
  double scale_lo = NAN, scale_hi = NAN;
  /// Named positions along x, written above the map (e.g. "rod side" at 90°).
  std::vector<std::pair<double, QString>> x_marks;
  /// A vertical line across the map at this x, named (e.g. the load line); NaN: none.
  double x_line = NAN;
  QString x_line_label;
  /// A horizontal line across the map at this y (e.g. the crank angle shown); NaN: none.
  double y_line = NAN;
  /// The y axis' numbered ticks (e.g. every 90 °CA); empty: round numbers (RoundTicks).
  std::vector<double> y_ticks;
  /// Points (x, y) marked on the map as dots, e.g. the load's direction at every crank angle,
  /// named in a small legend.
  std::vector<std::pair<double, double>> points;
  QString points_label;
};

/// The unrolled skirt's axes and edge labels (thrust side left, the skirt top up, the relief
/// named), one definition for the field view's and the skirt calculator's maps.
void SetSkirtMapLabels(FilmMapData* d);

class FilmMapWidget : public QWidget {
  Q_OBJECT

 public:
  explicit FilmMapWidget(QWidget* parent = nullptr);
  void setData(FilmMapData data);
  /// Moves the horizontal line (FilmMapData::y_line) without replacing the data.
  void setYLine(double y);
  const FilmMapData& data() const { return data_; }
  /// The colour scale's range (after rounding to its ticks).
  std::pair<double, double> scaleRange() const { return {scale_lo_, scale_hi_}; }
  /// Where the points' legend was last drawn [px] (null before; tests).
  QRectF pointsLegendRect() const { return points_legend_; }
  /// Where the no-film bands' names were last drawn [px], one box per band (tests).
  const std::vector<QRectF>& noFilmLabelRects() const { return no_film_labels_; }
  QSize sizeHint() const override { return {640, 360}; }
  QSize minimumSizeHint() const override { return {260, 180}; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  double ValueAt(double x, double y) const;
  FilmMapData data_;
  double scale_lo_ = 0.0, scale_hi_ = 1.0;
  QRectF points_legend_;
  std::vector<QRectF> no_film_labels_;
};

}  // namespace filmdyn::ui
