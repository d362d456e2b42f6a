#include "ui/case_editor/case_json.hpp"

#include <QObject>
#include <nlohmann/json.hpp>

#include "core/base/input_error.hpp"
#include "core/io/case_file.hpp"
#include "ui/save_text.hpp"

namespace filmdyn::ui {

std::string CaseToJsonText(const engine::EngineCase& c) { return io::CaseToJson(c).dump(2) + "\n"; }

engine::EngineCase CaseFromJsonText(const std::string& text) {
  return io::LoadCaseText(text, "case file");
}

bool SaveCaseFile(const engine::EngineCase& c, const QString& path, QString* error) {
  return SaveTextFile(path, CaseToJsonText(c), error);
}

bool LoadCaseFile(const QString& path, engine::EngineCase* c, QString* error, QStringList* notes) {
  try {
    const io::LoadedCase loaded = io::LoadCase(path.toStdString());
    if (notes) {
      notes->clear();
      for (const std::string& note : loaded.notes) *notes << QString::fromStdString(note);
    }
    // Inline, in the degrees that convert back to exactly the angles the file gave.
    *c = io::CaseWithInlineCurves(loaded);
  } catch (const std::exception& e) {
    if (error) {
      *error = QObject::tr("%1: %2").arg(path.isEmpty() ? QObject::tr("default case") : path,
                                         QString::fromStdString(e.what()));
    }
    return false;
  }
  return true;
}

}  // namespace filmdyn::ui
