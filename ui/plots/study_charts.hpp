#pragma once
/// @file The plots of a design study (docs/study.md, "Plots"): main effects, a scatter matrix
/// and the best points, drawn from the rows of batch::CollectStudy with Qt Charts. `filmdyn
/// study` and `filmdyn study collect` write them to DIR/plots (ExportStudyPlots); the GUI's
/// study view shows the same charts. Values are in the figures' display units (the units of
/// study.md), the factors in the case editor's units (FactorDisplay). Every chart is new and owned
/// by the caller (a QChartView that shows it takes it over).
#include <QString>
#include <QStringList>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/batch/study.hpp"

QT_BEGIN_NAMESPACE
class QChart;
QT_END_NAMESPACE

namespace filmdyn::ui {

/// How a factor's values are shown in the study's plots and the GUI's study table: in the case
/// field's display unit, the one of the case editor (a clearance in µm, a viscosity in mPa·s, the
/// speed in rpm). `title` is "skirt.cold_clearance [µm]" ("model" for a text factor); a value
/// shown is the SI value / `scale`.
struct StudyFactorDisplay {
  QString title;
  QString unit;  ///< "µm"; empty for a text factor or a dimensionless one
  double scale = 1.0;
};
StudyFactorDisplay FactorDisplay(const batch::StudyFactor& factor);
/// A factor's value as shown: "30" (µm) for 3e-05 m, four significant digits; a run model by its
/// title ("Only-LBRBE"); any other text level as is.
QString FactorValueText(const batch::StudyFactor& factor, const std::string& value,
                        std::optional<double> number);

/// The figures worth a panel (indices in io::ComparisonFigures(), in their order): those that
/// at least one done point has and that take at least two different values over the done points.
std::vector<std::size_t> StudyPlotFigures(const std::vector<batch::StudyRow>& rows);

/// The most points a scatter plot draws. Qt Charts makes a graphics item of every dot, and its
/// cost grows faster than the number of dots (bench/bench_study_plots: 13 s for the 48 panels
/// of 2 000 points, 200 s for 10 000); beyond, a random sample of this many is drawn and the
/// chart's title says so.
inline constexpr std::size_t kMaxScatterDots = 2000;
/// The done rows that have `figure` (what a scatter plot of it would draw without the limit).
std::size_t StudyScatterCandidates(const std::vector<batch::StudyRow>& rows, std::size_t figure);

/// The rows drawn by MakeStudyScatterChart for `figure`, in the order of its series' points:
/// every done row that has the figure, in the order of `rows` (beyond kMaxScatterDots, a random
/// sample of kMaxScatterDots of them, the same on every call). Point k of the series
/// (QXYSeries::at(k)) is rows[StudyScatterRows(rows, figure)[k]]; a point that the series'
/// clicked(QPointF) signal gives is at k = series->points().indexOf(point) (the first of two
/// points drawn at the same place). The factor does not matter: every row has a value of every
/// factor.
std::vector<std::size_t> StudyScatterRows(const std::vector<batch::StudyRow>& rows,
                                          std::size_t figure);

/// `figure` (an index in io::ComparisonFigures(); display units, its display name on the y axis)
/// against the value of `factor` (an index in Study::factors; the x axis titled and scaled by
/// FactorDisplay). A text factor (the model, a joint model) is drawn as categories: position k
/// for its k-th level (the study's order; a one-at-a-time base value that is no level comes
/// after them), its tick labelled with the level's name. One QScatterSeries (the chart's only
/// series, named after the figure) holds one point per row of StudyScatterRows(rows, figure),
/// in that order; points that are not done, or have no such figure, are not drawn. No legend,
/// and no title unless the points are a sample ("a random 2000 of 10000 points"): the axes say
/// what is drawn.
QChart* MakeStudyScatterChart(const batch::Study& study, const std::vector<batch::StudyRow>& rows,
                              std::size_t factor, std::size_t figure);

/// The main effects (batch::MainEffects) on `figure`: one line with markers per factor with at
/// least two discrete levels, x = the level's place among the factor's levels from 0 (the
/// lowest number, or a text factor's first level) to 1 (the highest, or the last), y = the
/// figure's mean over the done points at that level (display units). All factors share the y
/// axis, so the steepest line is the factor that moves the figure most. A legend drawn below the
/// plot (a child item of the chart; QChart::legend() stays hidden) lists the factors from the
/// largest spread of the means (highest mean − lowest) to the smallest, each with its levels'
/// range and that spread; it reserves a line for every factor with levels, so that the charts
/// of one study have plots of one height. A factor keeps its colour in every figure's chart.
/// Levels where no done point has the figure are left out of the line. Null when no factor has
/// two levels with a mean.
QChart* MakeMainEffectsChart(const batch::Study& study, const std::vector<batch::StudyRow>& rows,
                             std::size_t figure);

/// Horizontal bars of the `n` best done points by `figure` (batch::RankedPoints: smallest first,
/// or largest when `largest_first`), the best at the top, each labelled "N: 25 µm · 10 mPa·s ·
/// 2000 rpm" (the point's number and its factors' values, in the order the axis title names
/// the factors by the last part of their paths) and with its value. Null when no done point has the
/// figure.
QChart* MakeBestPointsChart(const batch::Study& study, const std::vector<batch::StudyRow>& rows,
                            std::size_t figure, bool largest_first, std::size_t n = 10);

/// Writes the study's plots into `<directory>/plots/`, each as .png (2x) and .svg, when at least
/// one point is done:
///   main-effects     a grid of MakeMainEffectsChart, one panel per StudyPlotFigures figure
///                    (when a factor has discrete levels)
///   scatter-matrix   MakeStudyScatterChart panels: a row per StudyPlotFigures figure, a
///                    column per factor (its SVG only up to 10 000 dots in all: beyond, an SVG
///                    of a dot each would take tens of MB, and the PNG is written alone)
///   best-points      MakeBestPointsChart of the figure `rank_by` (a study.csv column), or of
///                    batch::DefaultRankFigure when `rank_by` is empty
/// A plot with nothing to draw is not written (and an older file of it removed). Returns the
/// files written; on failure (an unknown `rank_by`, a file that cannot be written) also sets
/// *error, naming the file.
QStringList ExportStudyPlots(const batch::Study& study, const std::vector<batch::StudyRow>& rows,
                             const QString& directory, const std::string& rank_by,
                             bool largest_first, QString* error = nullptr);

}  // namespace filmdyn::ui
