#pragma once
/// @file Project files of the GUI: core's case file (core/io/case_file, one visitor) written
/// atomically with QSaveFile, so a project opens in `filmdyn run` unchanged. Curves given as CSV
/// files are read into inline tables on load, so they can be edited and the saved project is
/// self-contained.
#include <QString>
#include <QStringList>
#include <string>

#include "core/engine/engine_case.hpp"

namespace filmdyn::ui {

/// JSON text of a case (core's CaseToJson).
std::string CaseToJsonText(const engine::EngineCase& engine_case);
/// Parses and checks JSON text (core's CaseFromJson). Throws filmdyn::InputError naming the field.
engine::EngineCase CaseFromJsonText(const std::string& text);

/// Writes atomically (QSaveFile: the old file stays intact on any failure).
bool SaveCaseFile(const engine::EngineCase& engine_case, const QString& path, QString* error);
/// Reads a case file (core's LoadCase; empty path = the embedded default case) and turns file
/// curves into inline tables; false with *error naming the file and the field on failure. *notes
/// (when given) receives the reader's one-line notes, e.g. an older key read as its replacement.
bool LoadCaseFile(const QString& path, engine::EngineCase* engine_case, QString* error,
                  QStringList* notes = nullptr);

}  // namespace filmdyn::ui
