#pragma once
/// @file Writes a Qt Charts chart to PNG, SVG or PDF. The GUI's export menu and the headless
/// `filmdyn run` plots use this same function, so both produce the same pictures.
#include <QSize>
#include <QString>

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

}  // namespace filmdyn::ui
