#pragma once
/// @file The skirt's load-capacity plots: film normal force, moment about the pin and MOFT
/// against e0 (steady sliding), one curve per tilt — drawn by `filmdyn skirt --map` and the GUI's
/// skirt calculator from the same points.
#include <QString>
#include <QStringList>
#include <memory>
#include <vector>

#include "core/lubrication/skirt_calculator.hpp"

QT_BEGIN_NAMESPACE
class QChart;
QT_END_NAMESPACE

namespace filmdyn::ui {

/// The quantities plotted against e0 (keys of io::SkirtQuantities), in file order.
const std::vector<std::string>& SkirtMapQuantities();

/// One chart: `key` (one of SkirtMapQuantities) against e0 [µm], a curve per run of equal tilt.
std::unique_ptr<QChart> MakeSkirtMapChart(const std::vector<lubrication::SkirtPoint>& points,
                                          const std::string& key);

/// Writes `<directory>/skirt_map_<key>.png` and `.svg` for each quantity. Returns the files
/// written; on failure what was written, with *error naming the file.
QStringList ExportSkirtMapPlots(const std::vector<lubrication::SkirtPoint>& points,
                                const QString& directory, QString* error = nullptr);

}  // namespace filmdyn::ui
