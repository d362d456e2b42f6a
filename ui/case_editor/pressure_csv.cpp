#include "ui/case_editor/pressure_csv.hpp"

#include <fmt/format.h>
#include <QFile>
#include <sstream>

#include "core/io/case_file.hpp"
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
    // The degrees that convert back to exactly the angles read (core's one inversion).
    const double rpm = curve->rpm;
    *curve = io::InlinePressureCurve(read, rpm);
  } catch (const std::exception& e) {
    *error = QString::fromStdString(e.what());
    return false;
  }
  return true;
}

bool ExportPressureCsv(const engine::PressureCurveSource& curve, const QString& path,
                       QString* error) {
  std::ostringstream out;
  io::WritePressureCsv(out, curve.crank_angle_deg, curve.pressure,
                       fmt::format("cylinder pressure at {} rpm, exported by FilmDyn", curve.rpm));
  return SaveTextFile(path, out.str(), error);
}

}  // namespace filmdyn::ui
