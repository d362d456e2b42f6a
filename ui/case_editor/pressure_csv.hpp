#pragma once
/// @file Cylinder-pressure CSV import/export for the editor through core/io/pressure_csv. Format:
/// header "crank_angle[deg],pressure[Pa]", absolute pressure, 0–720 °CA.
#include <QString>

#include "core/engine/engine_case.hpp"

namespace filmdyn::ui {

/// Reads `path` into curve->crank_angle_deg / pressure [Pa]. False with *error (file, line).
bool ImportPressureCsv(const QString& path, engine::PressureCurveSource* curve, QString* error);
/// Writes "crank_angle[deg],pressure[Pa]" and one row per point, atomically.
bool ExportPressureCsv(const engine::PressureCurveSource& curve, const QString& path,
                       QString* error);

}  // namespace filmdyn::ui
