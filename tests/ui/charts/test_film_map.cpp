// The film map's legend of its points goes to the corner where it hides least: it sat in the
// bottom-right corner on the bright band at the cycle's end and over the load's dots.
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
};

QTEST_MAIN(TestFilmMap)
#include "test_film_map.moc"
