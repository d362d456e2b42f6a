#pragma once
/// @file Writes a Qt Charts chart to PNG, SVG or PDF. The GUI's export menu and the headless
/// `filmdyn run` plots use this same function, so both produce the same pictures.
#include <QSize>
#include <QString>
#include <vector>

QT_BEGIN_NAMESPACE
class QChart;
QT_END_NAMESPACE

namespace filmdyn::ui {

enum class ImageFormat { kPng, kSvg, kPdf };

/// The format implied by a file name's suffix (.png, .svg, .pdf, case-insensitive), or an
/// empty optional-like false return when it is none of them.
bool FormatFromSuffix(const QString& path, ImageFormat* format);

/// Renders the chart at `size` (logical pixels; PNG at 2x for sharp text) into `path`.
/// Returns false and sets *error (naming the path) when the file cannot be written.
bool ExportChart(QChart* chart, const QString& path, ImageFormat format,
                 const QSize& size = QSize(960, 600), QString* error = nullptr);

/// Renders several charts into one picture: a grid of `columns` cells to a row, each chart at
/// `cell` (logical pixels), in the order given (null entries leave their cell empty), under a
/// `heading` line when one is given. PNG at 2x (1x when the 2x image would exceed 50 million
/// pixels), SVG or PDF. The charts are borrowed as by ExportChart (one shown in a view is put
/// back). Returns false and sets *error (naming the path) when the file cannot be written.
bool ExportChartGrid(const std::vector<QChart*>& charts, int columns, const QString& path,
                     ImageFormat format, const QSize& cell = QSize(480, 320),
                     const QString& heading = {}, QString* error = nullptr);

}  // namespace filmdyn::ui
