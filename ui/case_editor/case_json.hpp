#pragma once
/// @file The one place where the GUI maps an EngineCase to and from its JSON project file.
/// TODO(core case_file): when core/io/case_file lands, these call its load/save (one visitor)
/// and this file shrinks to the atomic QSaveFile write. Keys are the struct's dotted paths.
#include <QString>
#include <string>

#include "core/engine/engine_case.hpp"

namespace filmdyn::ui {

/// JSON text of a case (SI values, as core reads them).
std::string CaseToJsonText(const engine::EngineCase& engine_case);
/// Parses JSON text; unknown keys are an error naming them; missing keys keep their default.
/// Throws filmdyn::InputError naming the field.
engine::EngineCase CaseFromJsonText(const std::string& text);

/// Writes atomically (QSaveFile: the old file stays intact on any failure).
bool SaveCaseFile(const engine::EngineCase& engine_case, const QString& path, QString* error);
/// Reads a case file; false with *error naming the file and the field on failure.
bool LoadCaseFile(const QString& path, engine::EngineCase* engine_case, QString* error);

}  // namespace filmdyn::ui
