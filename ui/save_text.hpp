#pragma once
/// @file Writing a text file whole or not at all: QSaveFile writes under a temporary name and
/// renames it into place only when everything was written, so a failed or interrupted save
/// never leaves a cut file and an existing file stays as it was.
#include <QString>
#include <string_view>

namespace filmdyn::ui {

/// Writes `text` to `path` atomically. False with *error ("Cannot write <path>: <reason>") when
/// `error` is given.
bool SaveTextFile(const QString& path, std::string_view text, QString* error);

}  // namespace filmdyn::ui
