#include "ui/save_text.hpp"

#include <QObject>
#include <QSaveFile>

namespace filmdyn::ui {

bool SaveTextFile(const QString& path, std::string_view text, QString* error) {
  QSaveFile file(path);
  const auto size = static_cast<qint64>(text.size());
  if (!file.open(QIODevice::WriteOnly) || file.write(text.data(), size) != size || !file.commit()) {
    if (error) *error = QObject::tr("Cannot write %1: %2").arg(path, file.errorString());
    return false;
  }
  return true;
}

}  // namespace filmdyn::ui
