#include "ui/fields/field_frames.hpp"

#include <QDir>
#include <QObject>
#include <cstdio>

namespace filmdyn::ui {

const std::vector<FieldArrayInfo>& FieldArrays() {
  static const std::vector<FieldArrayInfo> arrays = {
      {"pressure", "p [MPa]", 1e-6},
      {"contact_pressure", "p_c [MPa]", 1e-6},
      {"film_thickness", "h [µm]", 1e6},
  };
  return arrays;
}

io::SurfaceField JointFieldFrames::Frame(size_t k) const {
  io::SurfaceField f = mesh;
  f.point_data = frames[k];
  return f;
}

bool ExportFieldFrames(const FieldFrames& frames, const QString& directory, QString* error) {
  if (!QDir().mkpath(directory)) {
    if (error) *error = QObject::tr("Cannot create %1").arg(directory);
    return false;
  }
  try {
    for (const JointFieldFrames& joint : frames.joints) {
      io::PvdCollection pvd;
      for (size_t k = 0; k < joint.frames.size(); ++k) {
        char name[64];
        std::snprintf(name, sizeof name, "%s_%04zu.vtu", joint.name.c_str(), k);
        io::WriteVtu(QDir(directory).filePath(name).toStdString(), joint.Frame(k));
        pvd.Add(k < frames.time.size() ? frames.time[k] : double(k), name);
      }
      pvd.Write(
          QDir(directory).filePath(QString::fromStdString(joint.name) + ".pvd").toStdString());
    }
  } catch (const std::exception& e) {
    if (error) *error = QString::fromUtf8(e.what());
    return false;
  }
  return true;
}

}  // namespace filmdyn::ui
