#include "ui/case_editor/pressure_csv.hpp"

#include <QFile>
#include <numbers>
#include <sstream>

#include "core/io/pressure_csv.hpp"
#include "ui/save_text.hpp"

namespace filmdyn::ui {

// Reading and writing are core's (core/io/pressure_csv): the same files as `filmdyn run` reads,
// checked by core's PressureCurve rules.
bool ImportPressureCsv(const QString& path, engine::PressureCurveSource* curve, QString* error) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) {
    *error = QObject::tr("Cannot read %1: %2").arg(path, file.errorString());
    return false;
  }
  std::istringstream in(file.readAll().toStdString());
  try {
    const engine::PressureCurve read = io::ReadPressureCsv(in, path.toStdString());
    curve->file.clear();
    curve->crank_angle_deg.clear();
    for (double a : read.Angles()) curve->crank_angle_deg.push_back(a * 180.0 / std::numbers::pi);
    curve->pressure = read.Pressures();
  } catch (const std::exception& e) {
    *error = QString::fromStdString(e.what());
    return false;
  }
  return true;
}

bool ExportPressureCsv(const engine::PressureCurveSource& curve, const QString& path,
                       QString* error) {
  std::ostringstream out;
  io::WritePressureCsv(
      out, curve.crank_angle_deg, curve.pressure,
      "cylinder pressure at " + std::to_string(int(curve.rpm)) + " rpm, exported by FilmDyn");
  return SaveTextFile(path, out.str(), error);
}

}  // namespace filmdyn::ui
