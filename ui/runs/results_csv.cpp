#include "ui/runs/results_csv.hpp"

#include <QObject>
#include <QSaveFile>
#include <cmath>

namespace filmdyn::ui {

bool WriteResultsCsv(const std::vector<RunSample>& samples, const QString& path, QString* error) {
  QByteArray text;
  for (int c = 0; c < kColumnCount; ++c) {
    if (c) text += ',';
    text += kColumnHeaders[size_t(c)];
  }
  text += '\n';
  for (const RunSample& s : samples) {
    for (int c = 0; c < kColumnCount; ++c) {
      if (c) text += ',';
      const double v = s.values[size_t(c)];
      if (std::isfinite(v)) text += QByteArray::number(v, 'g', 12);
    }
    text += '\n';
  }
  QSaveFile file(path);
  if (!file.open(QIODevice::WriteOnly) || file.write(text) != text.size() || !file.commit()) {
    if (error) *error = QObject::tr("Cannot write %1: %2").arg(path, file.errorString());
    return false;
  }
  return true;
}

}  // namespace filmdyn::ui
