#pragma once
/// @file An unrolled film map: one nodal field on a tensor grid (circumference × axial) drawn as
/// a colour image (viridis, bilinear between the nodes) with round-numbered axes, a colour bar
/// beside it and labels on its edges (which side is thrust, which end is the skirt top). Regions
/// without film (the pin-boss relief) are drawn grey and named.
#include <QString>
#include <QWidget>
#include <utility>
#include <vector>

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
};

/// Round tick positions covering [lo, hi]: steps of 1, 2, 2.5 or 5 × 10ⁿ, about `target` of them.
std::vector<double> RoundTicks(double lo, double hi, int target = 6);

class FilmMapWidget : public QWidget {
  Q_OBJECT

 public:
  explicit FilmMapWidget(QWidget* parent = nullptr);
  void setData(FilmMapData data);
  const FilmMapData& data() const { return data_; }
  /// The colour scale's range (after rounding to its ticks).
  std::pair<double, double> scaleRange() const { return {scale_lo_, scale_hi_}; }
  QSize sizeHint() const override { return {640, 360}; }
  QSize minimumSizeHint() const override { return {260, 180}; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  double ValueAt(double x, double y) const;
  FilmMapData data_;
  double scale_lo_ = 0.0, scale_hi_ = 1.0;
};

}  // namespace filmdyn::ui
