// The result plots as a reader meets them, on the samples of real runs (core's run job: a coupled
// Skirt-LBRBE run on coarse meshes and the Ideal model, whose film quantities are empty): round
// axis steps, non-negative quantities from zero, a legend that lists colour and line style and
// only series with data, the journal orbit filling its panel inside the clearance circle, the
// linked crank-angle cursor with the values of every visible series, hover, zoom and pan; the oil
// flows of each joint (core's flow columns) in their own plots.
#include <QChart>
#include <QChartView>
#include <QLineSeries>
#include <QMouseEvent>
#include <QTemporaryDir>
#include <QValueAxis>
#include <QWheelEvent>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/engine/run_job.hpp"
#include "core/io/case_file.hpp"
#include "core/io/results_writer.hpp"
#include "ui/charts/round_ticks.hpp"
#include "ui/plots/mark_labels.hpp"
#include "ui/plots/plot_export.hpp"
#include "ui/plots/plot_panel.hpp"
#include "ui/plots/study_charts.hpp"

namespace engine = filmdyn::engine;
namespace io = filmdyn::io;
using filmdyn::ui::Column;
using filmdyn::ui::PlotPanel;
using filmdyn::ui::PlotRun;

namespace {

// One reported cycle of a real run, as the plots receive it.
PlotRun RealRun(int id, engine::Model model, double rpm) {
  const io::LoadedCase loaded = io::LoadCase({});
  engine::RunConfig config =
      engine::MakeRunConfig(loaded.value, model, rpm, io::PressureCurveForSpeed(loaded, rpm));
  auto& c = config.engine_case;
  c.skirt.mesh_thrust = c.skirt.mesh_anti = 8;
  c.skirt.mesh_relief = 1;
  c.skirt.mesh_axial = 8;
  c.big_end.mesh_theta = 36;
  c.big_end.mesh_z = 6;
  c.solver.error_estimate = 0;
  c.solver.max_cycles = 1;
  const engine::RunResult result = engine::RunJob(config);
  return filmdyn::ui::PlotRunFromRows(id, config.engine_case, engine::ModelName(model), rpm,
                                      io::ResultRows(result, model), io::MotionRows(result, model));
}

bool IsRoundStep(double step) {
  const double decade = std::pow(10.0, std::floor(std::log10(step) + 1e-9));
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
    if (std::abs(step - m * decade) < 1e-9 * decade) return true;
  }
  return false;
}

QValueAxis* Axis(QChart* chart, Qt::Orientation o) {
  return static_cast<QValueAxis*>(chart->axes(o).first());
}

}  // namespace

class TestPlotPanel : public QObject {
  Q_OBJECT
  PlotRun coupled_, ideal_;

 private slots:
  void initTestCase() {
    coupled_ = RealRun(1, engine::Model::kSkirtLbrbe, 6000);
    ideal_ = RealRun(2, engine::Model::kIdeal, 4000);
    QVERIFY(coupled_.samples.size() >= 700);
  }

  // A study's factor values read as the case editor shows them: a run model by its title, a
  // choice by its title, numbers in the field's display unit.
  void studyFactorValuesReadAsTheEditorShowsThem() {
    const auto factor = [](const char* path, std::vector<std::string> text_levels) {
      filmdyn::batch::StudyFactor f;
      f.path = path;
      f.text_levels = std::move(text_levels);
      return f;
    };
    QCOMPARE(filmdyn::ui::FactorValueText(factor(filmdyn::batch::kModelFactor, {"only-lbrbe"}),
                                          "only-lbrbe", std::nullopt),
             QString("Only-LBRBE"));
    QCOMPARE(filmdyn::ui::FactorValueText(factor("big_end.cavitation", {"reynolds", "jfo"}), "jfo",
                                          std::nullopt),
             QString("JFO (mass-conserving)"));
    QCOMPARE(filmdyn::ui::FactorValueText(factor("lubricant.grade", {"0w-20", "15w-40"}), "15w-40",
                                          std::nullopt),
             QString("15W-40"));
    filmdyn::batch::StudyFactor viscosity = factor("lubricant.viscosity", {});
    viscosity.levels = {0.01, 0.02};
    viscosity.unit = "Pa*s";
    QCOMPARE(filmdyn::ui::FactorValueText(viscosity, "0.01", 0.01), QString("10"));
  }

  void roundStepsAndZeroBasedNonNegativeAxes() {
    PlotPanel panel;
    panel.resize(1400, 1200);
    panel.updateRun(coupled_);
    panel.updateRun(ideal_);
    const auto& specs = filmdyn::ui::StandardPlots();
    for (int i = 0; i < panel.chartCount(); ++i) {
      const auto& spec = specs[size_t(i)];
      for (Qt::Orientation o : {Qt::Horizontal, Qt::Vertical}) {
        QValueAxis* axis = Axis(panel.chart(i), o);
        const QString what = spec.id + (o == Qt::Horizontal ? " x" : " y");
        QCOMPARE(axis->tickType(), QValueAxis::TicksDynamic);
        // Crank angle steps by 90 °CA (the strokes' dead centres), every other axis round.
        const bool crank_angle = spec.crank_angle_axis && o == Qt::Horizontal;
        if (crank_angle) QCOMPARE(axis->tickInterval(), 90.0);
        QVERIFY2(crank_angle || IsRoundStep(axis->tickInterval()),
                 qPrintable(what + QString(" step %1").arg(axis->tickInterval())));
        QCOMPARE(axis->tickAnchor(), 0.0);
        QVERIFY2(!axis->titleText().isEmpty() && axis->titleText().contains('['),
                 qPrintable(what + " has no unit: " + axis->titleText()));
        if (!spec.equal_axes) {  // the range ends on whole steps
          const double step = axis->tickInterval();
          QVERIFY2(std::abs(axis->min() / step - std::round(axis->min() / step)) < 1e-6,
                   qPrintable(what));
          QVERIFY2(std::abs(axis->max() / step - std::round(axis->max() / step)) < 1e-6,
                   qPrintable(what));
        }
      }
      if (spec.non_negative) {
        QVERIFY2(Axis(panel.chart(i), Qt::Vertical)->min() == 0.0, qPrintable(spec.id));
      }
    }
    // The label format shows every tick exactly: 0.25 steps need two decimals.
    QCOMPARE(filmdyn::ui::DecimalsFor(0.25), 2);
    QCOMPARE(filmdyn::ui::DecimalsFor(2.5), 1);
    QCOMPARE(filmdyn::ui::DecimalsFor(50), 0);
    const auto r = filmdyn::ui::RoundRangeCovering(-1.0, 34.7, 4);
    QCOMPARE(r.step, 10.0);
    QCOMPARE(r.min, -10.0);
    QCOMPARE(r.max, 40.0);
  }

  void legendsShowStyleAndColourAndOnlySeriesWithData() {
    PlotPanel panel;
    panel.resize(1400, 1200);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.setRunsInChartLegends(true);  // as exported: each plot's legend names the runs
    panel.updateRun(ideal_);
    const int moft = panel.chartIndex("moft");
    QVERIFY(moft >= 0);
    // The Ideal model has no film: no legend entries, the title says so.
    QVERIFY(panel.legendEntries(moft).empty());
    QVERIFY(panel.chart(moft)->title().contains("no data"));
    panel.updateRun(coupled_);
    // Two runs: kinds by line style (skirt solid, big end dashed), then the one run with data.
    auto entries = panel.legendEntries(moft);
    QCOMPARE(int(entries.size()), 3);
    QCOMPARE(entries[0].first, QString("skirt"));
    QCOMPARE(entries[0].second.style(), Qt::SolidLine);
    QCOMPARE(entries[1].first, QString("big end"));
    QCOMPARE(entries[1].second.style(), Qt::DashLine);
    QCOMPARE(entries[2].first, coupled_.label);
    QCOMPARE(entries[2].second.color(), panel.runColour(coupled_.id));
    // A plot where both runs have data lists both runs, each in its own colour (the load
    // diagram: the ideal run has no secondary motion to plot, but a big-end load).
    const int load = panel.chartIndex("bigend_load_polar");
    entries = panel.legendEntries(load);
    QCOMPARE(int(entries.size()), 2);
    QVERIFY(entries[0].second.color() != entries[1].second.color());
    // One run shown: the run named once, each kind in its own colour and style.
    panel.setRunVisible(ideal_.id, false);
    entries = panel.legendEntries(moft);
    QCOMPARE(int(entries.size()), 3);
    QCOMPARE(entries[0].first, coupled_.label);
    QCOMPARE(entries[0].second.style(), Qt::NoPen);
    QVERIFY(entries[1].second.color() != entries[2].second.color());
    QVERIFY(entries[1].second.style() != entries[2].second.style());
    // Renaming reaches every legend.
    panel.setRunLabel(coupled_.id, "μ 10 mPa·s");
    QCOMPARE(panel.legendEntries(moft)[0].first, QString("μ 10 mPa·s"));
    // The legend never cuts a long label: it reserves the room it needs (up to a share of the
    // chart) and wraps beyond it.
    panel.setRunVisible(ideal_.id, true);
    const QString long_label = "Skirt-LBRBE 6000 rpm · μ 10 mPa·s · c_skirt 30 µm · 4000 rpm";
    panel.setRunLabel(coupled_.id, long_label);
    QCOMPARE(panel.legendEntries(moft).back().first, long_label);
    QVERIFY(panel.chart(moft)->margins().right() > 100);
    // On screen the runs are listed once above the plots, each in its colour; a plot's legend
    // keeps only its series kinds.
    panel.setRunsInChartLegends(false);
    entries = panel.legendEntries(moft);
    QCOMPARE(int(entries.size()), 2);
    QCOMPARE(entries[0].first, QString("skirt"));
    const QString shared = panel.runLegendText();
    QVERIFY(shared.contains(long_label.toHtmlEscaped()) && shared.contains(ideal_.label));
    QVERIFY(shared.contains(panel.runColour(coupled_.id).name()));
    QVERIFY(panel.legendEntries(load).empty());  // one kind: the shared legend says it all
    panel.setRunVisible(ideal_.id, false);
    QVERIFY(!panel.runLegendText().contains(ideal_.label));
    // Several runs whose data is of one kind only (an Only-LBRBE run beside an ideal one): that
    // kind is still named, so the dashed line reads as the big end's (it was unlabelled).
    panel.setRunVisible(coupled_.id, false);
    panel.setRunVisible(ideal_.id, true);
    panel.updateRun(RealRun(3, engine::Model::kOnlyLbrbe, 6000));
    entries = panel.legendEntries(moft);
    QCOMPARE(int(entries.size()), 1);
    QCOMPARE(entries[0].first, QString("big end"));
    QCOMPARE(entries[0].second.style(), Qt::DashLine);
  }

  // A label keeps off the diagram's curves where a place clear of them is near: a curve across
  // the outward place sends the label beside its mark instead; with no free place it still shows.
  void crankAngleLabelsKeepOffTheCurves() {
    const QSizeF size(34.0, 14.0);
    const QRectF area(0.0, 0.0, 400.0, 400.0);
    const QPointF origin(100.0, 200.0);
    const std::vector<filmdyn::ui::MarkLabel> mark = {{QPointF(200.0, 200.0), size}};
    const QRectF outward = filmdyn::ui::PlaceMarkLabels(mark, origin, area).front();
    QVERIFY(outward.left() > 200.0);  // outward: to the right of the mark
    // A vertical curve through that place (two polylines, one of a single segment).
    const QPolygonF wall({QPointF(220.0, 0.0), QPointF(220.0, 150.0), QPointF(220.0, 400.0)});
    const QRectF beside = filmdyn::ui::PlaceMarkLabels(mark, origin, area, {wall}).front();
    QVERIFY(!beside.isNull());
    QVERIFY2(beside.right() < 220.0 || beside.left() > 220.0,
             qPrintable(QString("label at %1..%2").arg(beside.left()).arg(beside.right())));
    QVERIFY(std::hypot(beside.center().x() - 200.0, beside.center().y() - 200.0) <
            16.0 + size.width());
    // Curves everywhere near (a dense grid): the label still shows, where it would without them.
    std::vector<QPolygonF> grid;
    for (double x = 150.0; x <= 260.0; x += 4.0)
      grid.push_back(QPolygonF({QPointF(x, 140.0), QPointF(x, 260.0)}));
    QCOMPARE(filmdyn::ui::PlaceMarkLabels(mark, origin, area, grid).front(), outward);
    // Another mark's dot where the label would go (another run's or cycle's mark): the label
    // goes elsewhere, clear of that dot and of its own — beside a dot it would read as its label.
    const QPointF other = outward.center();
    const QRectF clear =
        filmdyn::ui::PlaceMarkLabels(mark, origin, area, {}, {other, mark[0].at}).front();
    QVERIFY(!clear.isNull());
    const double half = filmdyn::ui::kMarkDotHalf;
    for (const QPointF& dot : {other, mark[0].at})
      QVERIFY2(!clear.intersects(QRectF(dot - QPointF(half, half), QSizeF(2 * half, 2 * half))),
               qPrintable(QString("label at %1,%2").arg(clear.left()).arg(clear.top())));
  }

  void crankAngleLabelsNeverOverlap() {
    // The marks of an orbit every 90 °CA (eight per cycle) on a ring of radius 20-120 px around
    // the origin, two cycles' marks close together (the curve passes a spot twice), in a small
    // and a large diagram: every label placed lies in the plot, none overlaps another; in a large
    // diagram every label finds a place; a crowded one leaves some out rather than overlap.
    const QSizeF size(34.0, 14.0);  // "630°" in a 9-10 pt font
    for (double radius : {20.0, 60.0, 120.0}) {
      const QRectF area(0.0, 0.0, 6.0 * radius + 120.0, 6.0 * radius + 120.0);
      const QPointF origin = area.center();
      std::vector<filmdyn::ui::MarkLabel> marks;
      for (int mark = 0; mark < 720; mark += 90) {
        const double a = mark * std::numbers::pi / 180.0;
        const double r = radius * (mark < 360 ? 1.0 : 1.04);  // the second pass 4 % outside
        marks.push_back({origin + QPointF(r * std::cos(a), r * std::sin(a)), size});
      }
      const std::vector<QRectF> placed = filmdyn::ui::PlaceMarkLabels(marks, origin, area);
      QCOMPARE(placed.size(), marks.size());
      int shown = 0;
      for (std::size_t i = 0; i < placed.size(); ++i) {
        if (placed[i].isNull()) continue;
        ++shown;
        QVERIFY(area.contains(placed[i]));
        QCOMPARE(placed[i].size(), size);
        for (std::size_t j = 0; j < i; ++j)
          QVERIFY2(
              placed[j].isNull() || !placed[j].intersects(placed[i]),
              qPrintable(QString("radius %1: labels %2 and %3 overlap").arg(radius).arg(j).arg(i)));
        // Near its mark: within the farther reach and the label's own size.
        const QPointF d = placed[i].center() - marks[i].at;
        QVERIFY(std::hypot(d.x(), d.y()) < 16.0 + size.width());
      }
      qInfo("marks on a ring of %g px: %d of %zu labels shown", radius, shown, marks.size());
      if (radius >= 120.0) QCOMPARE(shown, int(marks.size()));
      QVERIFY(shown >= 4);  // at least half of them
    }
    // A diagram too small for its labels (eight marks on a ring of 8 px in 90 × 60 px): some are
    // left out, and those shown still never overlap (drawing them anyway would).
    std::vector<filmdyn::ui::MarkLabel> crowded;
    const QRectF small(0.0, 0.0, 90.0, 60.0);
    for (int mark = 0; mark < 720; mark += 90) {
      const double a = mark * std::numbers::pi / 180.0;
      crowded.push_back({small.center() + QPointF(8.0 * std::cos(a), 8.0 * std::sin(a)), size});
    }
    const std::vector<QRectF> placed = filmdyn::ui::PlaceMarkLabels(crowded, small.center(), small);
    const auto left_out =
        std::count_if(placed.begin(), placed.end(), [](const QRectF& r) { return r.isNull(); });
    qInfo("a 90 x 60 px diagram: %d of 8 labels left out", int(left_out));
    QVERIFY(left_out > 0 && left_out < 8);
    for (std::size_t i = 0; i < placed.size(); ++i) {
      if (placed[i].isNull()) continue;
      QVERIFY(small.contains(placed[i]));
      for (std::size_t j = 0; j < i; ++j)
        QVERIFY(placed[j].isNull() || !placed[i].intersects(placed[j]));
    }
  }

  void orbitFillsItsPanelInsideTheClearance() {
    PlotPanel panel;
    panel.resize(1400, 1200);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.updateRun(coupled_);
    QCoreApplication::processEvents();
    const int orbit = panel.chartIndex("journal_orbit");
    const double clearance_um = coupled_.bearing_clearance * 1e6;
    QValueAxis* x = Axis(panel.chart(orbit), Qt::Horizontal);
    QValueAxis* y = Axis(panel.chart(orbit), Qt::Vertical);
    // The shorter axis spans the clearance circle with at most one round step to spare.
    const double half = std::min(x->max(), y->max());
    QVERIFY2(
        half >= clearance_um && half <= 1.25 * clearance_um,
        qPrintable(QString("half range %1 µm for a %2 µm clearance").arg(half).arg(clearance_um)));
    // Equal scale: µm per pixel the same on both axes (the circle is a circle).
    const QRectF area = panel.chart(orbit)->plotArea();
    const double sx = (x->max() - x->min()) / area.width();
    const double sy = (y->max() - y->min()) / area.height();
    QVERIFY2(std::abs(sx / sy - 1) < 0.05, qPrintable(QString("%1 vs %2").arg(sx).arg(sy)));
  }

  void linkedCursorShowsTheValuesOfEveryVisibleSeries() {
    PlotPanel panel;
    panel.resize(1400, 1200);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.updateRun(coupled_);
    panel.updateRun(ideal_);
    // The sample at 90 °CA (output steps are whole degrees here).
    const filmdyn::ui::RunSample* at90 = nullptr;
    for (const auto& s : coupled_.samples) {
      if (std::abs(s[Column::kCrankAngle] - 90.0) < 1e-9) at90 = &s;
    }
    QVERIFY(at90 != nullptr);
    panel.setCursorAngle(90.0);
    const int moft = panel.chartIndex("moft");
    const QStringList lines = panel.readoutLines(moft);
    const QString skirt = filmdyn::ui::FormatReadout((*at90)[Column::kSkirtMoft] * 1e6, "µm");
    const QString big_end = filmdyn::ui::FormatReadout((*at90)[Column::kBearingMoft] * 1e6, "µm");
    QVERIFY2(lines.join("\n").contains(skirt) && lines.join("\n").contains(big_end),
             qPrintable(lines.join(" | ") + " lacks " + skirt + " / " + big_end));
    QVERIFY(lines.join("\n").contains(coupled_.label));
    // A point of two forces in one unit reads with common decimals: 23 N beside 11.2 kN is
    // "0.02, -11.22 kN", not "0.02296, -11.22 kN".
    QCOMPARE(filmdyn::ui::FormatReadoutPair(0.02296, -11.22, "kN"),
             QString("0.02, -11.22") + QChar(0x202F) + "kN");
    QCOMPARE(filmdyn::ui::FormatReadoutPair(-4.303, -45.36), QString("-4.30, -45.36"));
    QCOMPARE(filmdyn::ui::FormatReadoutPair(-0.001, 250.0), QString("0.0, 250.0"));
    QCOMPARE(filmdyn::ui::FormatReadoutPair(0.0, 0.0), QString("0, 0"));
    // The compact readout (for a column too short for a line per run and kind): a line naming
    // the kinds, then a line per run with its values in that order, the same numbers.
    const int forces = panel.chartIndex("bigend_forces");
    const auto full = panel.readoutEntries(forces);
    const auto compact = panel.compactReadoutEntries(forces);
    QCOMPARE(int(full.size()), 1 + 2 * 3);
    QCOMPARE(int(compact.size()), 2 + 2);
    QCOMPARE(compact[0].value, full[0].value);  // the crank angle
    const QString slash = QString(QChar(0x2009)) + "/" + QChar(0x2009);
    QCOMPARE(compact[1].value, QString("F_x%1F_y%1gas [kN]").arg(slash));
    for (int run = 0; run < 2; ++run) {
      // The same values (each line's with common decimals: within half its last digit of the
      // full readout's four significant digits).
      const QStringList shown = compact[size_t(2 + run)].value.split(slash);
      QCOMPARE(shown.size(), 3);
      const int decimals =
          shown[0].contains('.') ? int(shown[0].size() - shown[0].indexOf('.') - 1) : 0;
      for (int k = 0; k < 3; ++k) {
        QString v = full[size_t(1 + 3 * run + k)].value;
        const double reference = v.left(v.indexOf(QChar(0x202F))).toDouble();
        QVERIFY2(std::abs(shown[k].toDouble() - reference) <=
                     0.5 * std::pow(10.0, -decimals) + 5e-4 * std::abs(reference) + 1e-12,
                 qPrintable(shown[k] + " vs " + v));
      }
      QVERIFY(compact[size_t(2 + run)].pen.color() == full[size_t(1 + 3 * run)].pen.color());
    }
    // Common decimals: the -0.03768, -11.22, 0.0293 kN of one run read as below.
    QCOMPARE(filmdyn::ui::FormatReadoutValues({-0.03768, -11.22, 0.0293}, " / "),
             QString("-0.04 / -11.22 / 0.03"));
    QCOMPARE(filmdyn::ui::FormatReadoutValues({std::nan(""), 2.5}, ", "), QString("–, 2.5"));
    QVERIFY(panel.compactReadoutEntries(panel.chartIndex("piston_lateral")).empty());  // one kind
    // Every crank-angle plot shows values at the same angle; the orbit shows its point there.
    for (int i = 0; i < panel.chartCount(); ++i) {
      QVERIFY2(!panel.readoutLines(i).isEmpty() || panel.chart(i)->title().contains("no data"),
               qPrintable(panel.chartId(i)));
    }
    // Hovering a crank-angle plot moves the cursor of every plot; leaving returns to the pin.
    QChartView* view = panel.chartView(moft);
    const QRectF area = panel.chart(moft)->plotArea();
    const QPointF value_pos = panel.chart(moft)->mapToPosition(QPointF(450, 5));
    const QPoint widget_pos = view->mapFromScene(panel.chart(moft)->mapToScene(value_pos));
    QVERIFY(area.contains(value_pos));
    QMouseEvent move(QEvent::MouseMove, widget_pos, view->viewport()->mapToGlobal(widget_pos),
                     Qt::NoButton, Qt::NoButton, Qt::NoModifier);
    QCoreApplication::sendEvent(view->viewport(), &move);
    QVERIFY2(std::abs(panel.shownAngle() - 450) < 2.0,
             qPrintable(QString::number(panel.shownAngle())));
    QVERIFY(panel.readoutLines(panel.chartIndex("piston_tilt")).first().startsWith("45"));
    QEvent leave(QEvent::Leave);
    QCoreApplication::sendEvent(view->viewport(), &leave);
    QCOMPARE(panel.shownAngle(), 90.0);
  }

  void oilFlowPlotsShowEachJointsFlows() {
    // The flow columns are core's results.csv columns, in core's order.
    const std::pair<Column, const char*> columns[] = {
        {Column::kSkirtInflow, "skirt_inflow[m^3/s]"},
        {Column::kSkirtOutflow, "skirt_outflow[m^3/s]"},
        {Column::kSkirtWettedFraction, "skirt_wetted_fraction[-]"},
        {Column::kBearingSupplyFlow, "bearing_supply_flow[m^3/s]"},
        {Column::kBearingSideFlow, "bearing_side_flow[m^3/s]"}};
    for (const auto& [column, header] : columns) {
      QCOMPARE(QString(filmdyn::ui::kColumnHeaders[size_t(column)]), QString(header));
    }
    PlotPanel panel;
    panel.resize(1400, 1200);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.updateRun(coupled_);
    const filmdyn::ui::RunSample* at = nullptr;
    for (const auto& s : coupled_.samples) {
      if (std::abs(s[Column::kCrankAngle] - 400.0) < 1e-9) at = &s;
    }
    QVERIFY(at != nullptr);
    panel.setCursorAngle(400.0);
    struct Expected {
      const char* plot;
      std::vector<std::pair<QString, QString>> series;  // legend name, readout value
    };
    const Expected plots[] = {
        {"bigend_oil_flow",
         {{"supply", filmdyn::ui::FormatReadout((*at)[Column::kBearingSupplyFlow] * 1e6, "cm³/s")},
          {"side leakage",
           filmdyn::ui::FormatReadout((*at)[Column::kBearingSideFlow] * 1e6, "cm³/s")}}},
        // The run's skirt is a Reynolds film: its outflow only (its inflow is no figure).
        {"skirt_oil_flow",
         {{"out", filmdyn::ui::FormatReadout((*at)[Column::kSkirtOutflow] * 1e6, "cm³/s")}}},
        {"skirt_wetted_fraction",
         {{"skirt", filmdyn::ui::FormatReadout((*at)[Column::kSkirtWettedFraction], "")}}}};
    for (const Expected& e : plots) {
      const int i = panel.chartIndex(e.plot);
      QVERIFY2(i >= 0, e.plot);
      QVERIFY2(!panel.chart(i)->title().contains("no data"), e.plot);
      QStringList legend;
      for (const auto& [text, pen] : panel.legendEntries(i)) legend << text;
      const QString readout = panel.readoutLines(i).join("\n");
      for (const auto& [name, value] : e.series) {
        // (A plot of one series names none: its title and axis say what it is.)
        if (e.series.size() > 1) QVERIFY2(legend.contains(name), qPrintable(legend.join(" | ")));
        QVERIFY2(readout.contains(value), qPrintable(readout + " lacks " + value));
      }
    }
    // The Reynolds skirt's inflow (an empty results.csv cell) is neither drawn nor listed.
    QVERIFY(std::isnan((*at)[Column::kSkirtInflow]));
    {
      const int i = panel.chartIndex("skirt_oil_flow");
      QStringList legend;
      for (const auto& [text, pen] : panel.legendEntries(i)) legend << text;
      QVERIFY2(!legend.contains("in"), qPrintable(legend.join(" | ")));
      for (const QString& line : panel.readoutLines(i))
        QVERIFY2(!line.startsWith("in:"), qPrintable(line));
    }
    // The skirt's flows cannot be negative, nor the oil-covered share: their axes start at 0.
    QCOMPARE(Axis(panel.chart(panel.chartIndex("skirt_oil_flow")), Qt::Vertical)->min(), 0.0);
    QCOMPARE(Axis(panel.chart(panel.chartIndex("skirt_wetted_fraction")), Qt::Vertical)->min(),
             0.0);
    // The Ideal model has no film: its flow plots say so.
    PlotPanel ideal;
    ideal.updateRun(ideal_);
    QVERIFY(ideal.chart(ideal.chartIndex("bigend_oil_flow"))->title().contains("no data"));
    // Nor secondary motion, orbit or friction: "no data", not the ideal joints' zero lines
    // (the piston's four plots drew flat zeros).
    for (const char* id :
         {"piston_lateral", "piston_tilt", "piston_lateral_velocity", "piston_tilt_rate",
          "journal_orbit", "phase_eps", "phase_tilt", "fpl", "friction_split"}) {
      QVERIFY2(ideal.chart(ideal.chartIndex(id))->title().contains("no data"), id);
    }
    // The liner forces: the ideal joint's reaction, drawn; its friction (none) not.
    const int liner = ideal.chartIndex("liner_forces");
    QVERIFY(!ideal.chart(liner)->title().contains("no data"));
    std::vector<QString> drawn;
    for (const auto& [name, pen] : ideal.legendEntries(liner)) drawn.push_back(name);
    QVERIFY2(std::find(drawn.begin(), drawn.end(), QString("friction")) == drawn.end(),
             qPrintable(QStringList(drawn.begin(), drawn.end()).join(", ")));
    // Beside a lubricated run the ideal run adds nothing to those plots, and the lubricated
    // run's curves are all there.
    ideal.updateRun(coupled_);
    QVERIFY(!ideal.chart(ideal.chartIndex("piston_lateral"))->title().contains("no data"));
  }

  void orbitAndPortraitsFollowTheMotionBetweenOutputSteps() {
    // The orbit and the phase portraits are drawn through the run's motion samples (8 per output
    // step), with the exact rates they carry; a run saved without them (an earlier version's
    // project: no motion, no ε̇ column) still draws its portrait from central differences.
    QVERIFY(coupled_.motion.size() >= 8 * (coupled_.samples.size() - 1));
    PlotPanel panel;
    panel.updateRun(coupled_);
    auto curve = [&panel](const QString& chart, const QString& name) -> QList<QPointF> {
      for (QAbstractSeries* s : panel.chart(panel.chartIndex(chart))->series()) {
        if (auto* line = qobject_cast<QLineSeries*>(s); line && line->name() == name)
          return line->points();
      }
      return {};
    };
    const QList<QPointF> orbit = curve("journal_orbit", "orbit");
    const QList<QPointF> eps = curve("phase_eps", "ε");
    const QList<QPointF> tilt = curve("phase_tilt", "γ");
    QCOMPARE(orbit.size(), qsizetype(coupled_.motion.size()));
    QCOMPARE(eps.size(), qsizetype(coupled_.motion.size()));
    QCOMPARE(tilt.size(), qsizetype(coupled_.motion.size()));
    for (qsizetype k = 0; k < eps.size(); k += 97) {
      const auto& m = coupled_.motion[size_t(k)];
      QCOMPARE(eps[k].x(), m[Column::kBearingEps]);
      QCOMPARE(eps[k].y(), m[Column::kBearingEpsRate]);
      QCOMPARE(orbit[k].x(), m[Column::kJournalEccX] * 1e6);
      QCOMPARE(tilt[k].y(), m[Column::kPistonTiltRate]);
    }
    // Consecutive orbit points at most 1/8 °CA apart: no straight segment over an output step.
    const auto& motion = coupled_.motion;
    for (std::size_t k = 1; k < motion.size(); ++k) {
      QVERIFY(motion[k][Column::kCrankAngle] - motion[k - 1][Column::kCrankAngle] < 0.126);
    }

    PlotRun saved_before = coupled_;
    saved_before.id = 3;
    saved_before.motion.clear();
    for (auto& sample : saved_before.samples) sample[Column::kBearingEpsRate] = std::nan("");
    PlotPanel old;
    old.updateRun(saved_before);
    QList<QPointF> old_eps;
    for (QAbstractSeries* s : old.chart(old.chartIndex("phase_eps"))->series()) {
      auto* line = qobject_cast<QLineSeries*>(s);
      if (line && line->name() == "ε" && old_eps.isEmpty()) old_eps = line->points();
    }
    QCOMPARE(old_eps.size(), qsizetype(saved_before.samples.size() - 2));
    // Central differences over 2 °CA against the exact rate of the same output step.
    double worst = 0.0, largest = 0.0;
    for (qsizetype k = 0; k < old_eps.size(); ++k) {
      const double exact = coupled_.samples[size_t(k + 1)][Column::kBearingEpsRate];
      worst = std::max(worst, std::abs(old_eps[k].y() - exact));
      largest = std::max(largest, std::abs(exact));
    }
    qInfo("ε̇ by central differences over 2 °CA: off by up to %.1f %% of the largest rate",
          100 * worst / largest);
  }

  void aCycleIsDrawnInCrankAngleOrder() {
    // Samples whose crank angles pass 720 → 0 are drawn as one lap from 0 °CA, never a line back
    // across the chart: a cycle that starts at 90 °CA (operating.start_crank_angle; 90 … 719,
    // 0 … 89) and a run stopped 100 °CA into its second lap of a run-in longer than a cycle
    // (0 … 719, 0 … 99: its last 720 °CA shown). Both hold the same samples as the cycle from 0:
    // every curve, the portraits' too, is drawn exactly as for it.
    PlotPanel cycle;
    cycle.updateRun(coupled_);
    const std::size_t n = coupled_.samples.size(), m = coupled_.motion.size();
    QCOMPARE(n, std::size_t(720));
    PlotRun from_90 = coupled_, long_run_in = coupled_;
    from_90.id = long_run_in.id = 4;
    std::rotate(from_90.samples.begin(), from_90.samples.begin() + 90, from_90.samples.end());
    std::rotate(from_90.motion.begin(), from_90.motion.begin() + 8 * 90, from_90.motion.end());
    for (std::size_t k = 0; k < 100; ++k) long_run_in.samples.push_back(coupled_.samples[k]);
    for (std::size_t k = 0; k < 8 * 100; ++k) long_run_in.motion.push_back(coupled_.motion[k]);
    QVERIFY(m > 8 * 100);
    for (const PlotRun* run : {&from_90, &long_run_in}) {
      PlotPanel panel;
      panel.updateRun(*run);
      int checked = 0;
      for (const auto& spec : filmdyn::ui::StandardPlots()) {
        const int i = panel.chartIndex(spec.id);
        const QList<QAbstractSeries*> series = panel.chart(i)->series(),
                                      expected = cycle.chart(i)->series();
        QCOMPARE(series.size(), expected.size());
        for (qsizetype k = 0; k < series.size(); ++k) {
          auto* line = qobject_cast<QLineSeries*>(series[k]);
          if (!line || line->name().isEmpty()) continue;  // marks, circles
          const std::string where = (spec.id + ": " + line->name()).toStdString();
          QVERIFY2(line->points() == qobject_cast<QLineSeries*>(expected[k])->points(),
                   where.c_str());
          if (spec.crank_angle_axis) {
            const QList<QPointF> points = line->points();
            for (qsizetype j = 1; j < points.size(); ++j)
              QVERIFY2(points[j].x() > points[j - 1].x(), where.c_str());
          }
          checked += line->count() > 0;
        }
      }
      QVERIFY(checked > 10);
    }

    // A run from 90 °CA stopped (or still running) at 30 °CA, its first cycle not yet whole
    // (90 … 719, 0 … 29): nothing is drawn between 29 and 90 °CA. Each curve is the cycle's curve
    // without the angles missing, in two lines; every line is one unbroken piece of the cycle's.
    PlotRun stopped = from_90;
    stopped.samples.resize(630 + 30);
    std::size_t kept = 0;  // the motion samples up to 29 °CA after 720 → 0
    for (bool wrapped = false; kept < stopped.motion.size(); ++kept) {
      const double a = stopped.motion[kept][Column::kCrankAngle];
      wrapped = wrapped || (kept > 0 && a < stopped.motion[kept - 1][Column::kCrankAngle]);
      if (wrapped && a > 29.0 + 1e-9) break;
    }
    stopped.motion.resize(kept);
    PlotPanel panel;
    panel.updateRun(stopped);
    int split = 0;
    // A chart's lines of one kind, in the order drawn.
    const auto lines_of = [](QChart* chart, const QString& name) {
      QList<QLineSeries*> lines;
      for (QAbstractSeries* s : chart->series()) {
        auto* line = qobject_cast<QLineSeries*>(s);
        if (line && line->name() == name) lines.append(line);
      }
      return lines;
    };
    for (const auto& spec : filmdyn::ui::StandardPlots()) {
      const int i = panel.chartIndex(spec.id);
      for (const auto& curve : spec.curves) {
        const std::string where = (spec.id + ": " + curve.name).toStdString();
        // The whole cycle: one line per kind (a part after a gap is made only when needed).
        const QList<QLineSeries*> cycle_lines = lines_of(cycle.chart(i), curve.name);
        QVERIFY2(cycle_lines.size() == 1, where.c_str());
        const QList<QPointF> whole = cycle_lines.front()->points();
        const QList<QLineSeries*> lines = lines_of(panel.chart(i), curve.name);
        if (whole.isEmpty()) {
          for (QLineSeries* line : lines) QVERIFY2(line->count() == 0, where.c_str());
          continue;
        }
        // The samples 0 … 29 °CA, then 90 … 719 °CA: one per degree, or the motion's 8.
        QVERIFY2(lines.size() == 2, where.c_str());
        const qsizetype per = whole.size() == 720 ? 1 : 8;
        QVERIFY2(lines[0]->points() == whole.first(29 * per + 1), where.c_str());
        QVERIFY2(lines[1]->points() == whole.sliced(90 * per), where.c_str());
        ++split;
      }
    }
    QVERIFY(split > 10);
    // The cursor reads nothing in the gap, values on both sides.
    const int moft = panel.chartIndex("moft");
    panel.setCursorAngle(60.0);
    QVERIFY2(!panel.readoutLines(moft).join(" ").contains("µm"),
             qPrintable(panel.readoutLines(moft).join(" | ")));
    panel.setCursorAngle(100.0);
    QVERIFY2(panel.readoutLines(moft).join(" ").contains("µm"),
             qPrintable(panel.readoutLines(moft).join(" | ")));
  }

  void zoomPanAndReset() {
    PlotPanel panel;
    panel.resize(1400, 1200);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.updateRun(coupled_);
    const int fpl = panel.chartIndex("fpl");
    QValueAxis* x = Axis(panel.chart(fpl), Qt::Horizontal);
    QChartView* view = panel.chartView(fpl);
    const QPointF pos = panel.chart(fpl)->mapToPosition(QPointF(360, 10));
    const QPoint widget_pos = view->mapFromScene(panel.chart(fpl)->mapToScene(pos));
    QWheelEvent wheel(widget_pos, view->viewport()->mapToGlobal(widget_pos), QPoint(),
                      QPoint(0, 240), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(view->viewport(), &wheel);
    QVERIFY(panel.isZoomed(fpl));
    QVERIFY(x->max() - x->min() < 500 && x->min() <= 360 && x->max() >= 360);
    QVERIFY(IsRoundStep(x->tickInterval()));
    const double before = x->min();
    panel.panChart(fpl, QPointF(30, 0));
    QVERIFY(std::abs(x->min() - before - 30) < 1e-6);
    QMouseEvent dbl(QEvent::MouseButtonDblClick, widget_pos,
                    view->viewport()->mapToGlobal(widget_pos), Qt::LeftButton, Qt::LeftButton,
                    Qt::NoModifier);
    QCoreApplication::sendEvent(view->viewport(), &dbl);
    QVERIFY(!panel.isZoomed(fpl));
    QCOMPARE(x->min(), 0.0);
    QCOMPARE(x->max(), 720.0);
  }

  // An impact lasting a fraction of the output interval (a mass-conserving big end's void
  // collapse) is one sample far above its neighbours: the plots fit the rest of the curve, draw
  // the spike clipped and mark its value at the edge; zoomed onto it, they show it whole. A
  // peak that the samples resolve (wider than an interval) sets the range as before.
  void spikesBetweenSamplesAreClippedAndMarked() {
    PlotRun spiking = coupled_;
    spiking.id = 7;
    std::size_t at = 0;
    for (std::size_t k = 0; k < spiking.samples.size(); ++k)
      if (std::abs(spiking.samples[k][Column::kCrankAngle] - 361.0) <
          std::abs(spiking.samples[at][Column::kCrankAngle] - 361.0))
        at = k;
    double smooth_lo = INFINITY, smooth_hi = -INFINITY;
    for (const auto& s : spiking.samples) {
      smooth_lo = std::min(smooth_lo, s[Column::kBigEndForceX] * 1e-3);
      smooth_hi = std::max(smooth_hi, s[Column::kBigEndForceX] * 1e-3);
    }
    const double spike_kn = smooth_lo - 10.0 * (smooth_hi - smooth_lo);
    spiking.samples[at][Column::kBigEndForceX] = spike_kn * 1e3;
    const double angle = spiking.samples[at][Column::kCrankAngle];

    PlotPanel panel;
    panel.resize(1400, 1200);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.updateRun(spiking);
    const int forces = panel.chartIndex("bigend_forces");
    QValueAxis* y = Axis(panel.chart(forces), Qt::Vertical);
    // The axis covers the curve without the spike (and the gas force), not the spike.
    QVERIFY2(
        y->min() <= smooth_lo && y->min() > spike_kn,
        qPrintable(
            QString("y from %1 (curve %2, spike %3)").arg(y->min()).arg(smooth_lo).arg(spike_kn)));
    QCOMPARE(panel.clippedSpikes(forces).size(), std::size_t(1));
    const auto& clipped = panel.clippedSpikes(forces).front();
    QCOMPARE(clipped.run_id, 7);
    QCOMPARE(clipped.curve, std::size_t(0));  // F_x
    QCOMPARE(clipped.value.y(), spike_kn);
    QCOMPARE(clipped.crank_angle, angle);
    // The load diagram leaves it out too (its x is the rod-frame force, spiking with it only
    // when the spike is set there: unchanged here).
    QVERIFY(panel.clippedSpikes(panel.chartIndex("bigend_load_polar")).empty());
    // The other plots have no spike.
    QVERIFY(panel.clippedSpikes(panel.chartIndex("fpl")).empty());
    // A plain run marks nothing; its force axis is where it was.
    PlotPanel plain;
    plain.resize(1400, 1200);
    plain.updateRun(coupled_);
    QVERIFY(plain.clippedSpikes(forces).empty());
    QCOMPARE(Axis(plain.chart(forces), Qt::Vertical)->min(), y->min());

    // Zoomed onto the spike (fewer than 40 samples in view): shown whole, nothing marked.
    panel.zoomChart(forces, 30.0 / 720.0, QPointF(angle, 0));
    QVERIFY(panel.isZoomed(forces));
    QVERIFY(y->min() <= spike_kn);
    QVERIFY(panel.clippedSpikes(forces).empty());
    // Zoomed out to 90 °CA around it: clipped again.
    panel.resetZoom(forces);
    panel.zoomChart(forces, 90.0 / 720.0, QPointF(angle, 0));
    QVERIFY(y->min() > spike_kn);
    QCOMPARE(panel.clippedSpikes(forces).size(), std::size_t(1));
    panel.resetZoom(forces);

    // Resolved: the same height over three samples sets the range.
    PlotRun broad = spiking;
    broad.id = 8;
    broad.samples[at - 1][Column::kBigEndForceX] = spike_kn * 1e3 * 0.8;
    broad.samples[at + 1][Column::kBigEndForceX] = spike_kn * 1e3 * 0.8;
    PlotPanel resolved;
    resolved.resize(1400, 1200);
    resolved.updateRun(broad);
    QVERIFY(resolved.clippedSpikes(forces).empty());
    QVERIFY(Axis(resolved.chart(forces), Qt::Vertical)->min() <= spike_kn);

    // An impact caught by two samples (the second a third of the first, still far above the
    // curve: a mass-conserving big end's step peaks): both are the spike, the range the curve's.
    PlotRun twin = spiking;
    twin.id = 10;
    twin.samples[at + 1][Column::kBigEndForceX] = spike_kn * 1e3 / 3.0;
    PlotPanel two;
    two.resize(1400, 1200);
    two.updateRun(twin);
    QCOMPARE(two.clippedSpikes(forces).size(), std::size_t(2));
    QVERIFY2(Axis(two.chart(forces), Qt::Vertical)->min() > spike_kn / 3.0,
             qPrintable(QString::number(Axis(two.chart(forces), Qt::Vertical)->min())));

    // A spike of little height is drawn whole (it widens the range by less than half).
    PlotRun small = coupled_;
    small.id = 9;
    small.samples[at][Column::kBigEndForceX] = (smooth_lo - 0.3 * (smooth_hi - smooth_lo)) * 1e3;
    PlotPanel low;
    low.resize(1400, 1200);
    low.updateRun(small);
    QVERIFY(low.clippedSpikes(forces).empty());
    QVERIFY(Axis(low.chart(forces), Qt::Vertical)->min() <=
            small.samples[at][Column::kBigEndForceX] * 1e-3);

    // Exported alone (a report's plot), the spike is clipped the same way.
    QTemporaryDir dir;
    QVERIFY(panel.exportChart(forces, dir.filePath("forces.png"), filmdyn::ui::ImageFormat::kPng,
                              QSize(960, 600)));
    QVERIFY(y->min() > spike_kn);
  }
};

QTEST_MAIN(TestPlotPanel)
#include "test_plot_panel.moc"
