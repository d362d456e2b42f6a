// The film map's legend of its points goes to the corner where it hides least: it sat in the
// bottom-right corner on the bright band at the cycle's end and over the load's dots. The name
// of a band without film keeps clear of the crank-angle line (the line crossed it mid-cycle).
#include <QImage>
#include <QtTest>
#include <cmath>

#include "ui/charts/film_map_widget.hpp"

using filmdyn::ui::FilmMapData;
using filmdyn::ui::FilmMapWidget;

class TestFilmMap : public QObject {
  Q_OBJECT
 private slots:
  void thePointsLegendTakesTheCornerItHidesLeastIn() {
    // A map over 0–360 × 0–720 whose lower right carries a sharp ridge and the points, the
    // other corners uniform except the lower left, which has a gentler slope.
    FilmMapData d;
    for (int i = 0; i <= 36; ++i) d.x.push_back(10.0 * i);
    for (int j = 0; j <= 72; ++j) d.y.push_back(10.0 * j);
    for (double y : d.y) {
      for (double x : d.x) {
        const double ridge = std::exp(-std::pow((x - 330.0) / 20.0, 2)) * (y > 600 ? 1.0 : 0.0);
        const double slope = x < 90 && y > 600 ? 0.2 * x / 90.0 : 0.0;
        d.values.push_back(ridge + slope);
      }
    }
    for (double y = 620; y <= 720; y += 5) d.points.push_back({330.0 + (y - 620) * 0.2, y});
    d.points_label = "load direction";
    FilmMapWidget map;
    map.resize(600, 500);
    map.setData(d);
    (void)map.grab();  // paint
    const QRectF legend = map.pointsLegendRect();
    QVERIFY(!legend.isNull());
    // Top of the map (uniform there), not the lower right (ridge and dots) nor the lower left
    // (its slope).
    QVERIFY2(legend.center().y() < map.height() / 2.0,
             qPrintable(QString("legend at %1,%2").arg(legend.left()).arg(legend.top())));
    // With the ridge and the points at the top instead, the legend goes to the bottom.
    for (auto& [x, y] : d.points) y = 720.0 - y;
    std::vector<double> flipped(d.values.size());
    const std::size_t nx = d.x.size(), ny = d.y.size();
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) flipped[i + nx * j] = d.values[i + nx * (ny - 1 - j)];
    d.values = flipped;
    map.setData(d);
    (void)map.grab();
    QVERIFY(map.pointsLegendRect().center().y() > map.height() / 2.0);
  }

  void theNoFilmNameKeepsClearOfTheCrankAngleLine() {
    // The skirt's map: film either side of a relief band in the middle, the crank angle's line
    // at each of several angles.
    FilmMapData d;
    for (int i = 0; i <= 36; ++i) d.x.push_back(5.0 * i);
    for (int j = 0; j <= 72; ++j) d.y.push_back(10.0 * j);
    d.values.assign(d.x.size() * d.y.size(), 0.0);
    d.no_film_x = {{45.0, 135.0}};
    d.no_film_label = "pin-boss relief: no film";
    FilmMapWidget map;
    map.resize(600, 600);
    for (const double angle : {10.0, 180.0, 350.0, 360.0, 380.0, 540.0, 710.0}) {
      d.y_line = angle;
      map.setData(d);
      const QImage image = map.grab().toImage();
      QCOMPARE(map.noFilmLabelRects().size(), std::size_t(1));
      const QRectF label = map.noFilmLabelRects().front();
      // The line's row: white between black in a film column (left of the band).
      const int column = int(label.left()) - 60;
      int row = -1;
      for (int r = 1; r + 1 < image.height(); ++r) {
        if (image.pixelColor(column, r) == QColor(Qt::white) &&
            image.pixelColor(column, r - 1) == QColor(Qt::black) &&
            image.pixelColor(column, r + 1) == QColor(Qt::black)) {
          row = r;
        }
      }
      QVERIFY2(row >= 0, qPrintable(QString("no line found at %1 °CA").arg(angle)));
      QVERIFY2(row < label.top() - 2 || row > label.bottom() + 2,
               qPrintable(QString("%1 °CA: the line at row %2 crosses the name at %3–%4")
                              .arg(angle)
                              .arg(row)
                              .arg(label.top())
                              .arg(label.bottom())));
      // The name is whole: inside the map's height, as long as its text.
      QVERIFY(label.top() >= 0 && label.bottom() <= map.height());
      QVERIFY(label.height() >= map.fontMetrics().horizontalAdvance(d.no_film_label));
    }
  }
};

QTEST_MAIN(TestFilmMap)
#include "test_film_map.moc"
