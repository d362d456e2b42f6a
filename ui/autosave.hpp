#pragma once
/// @file Autosave files of the case's unsaved edits, one per window. Each window writes its own
/// file in the application's data folder under autosave/ and holds a lock file beside it for as
/// long as it lives (QLockFile: the process id, host and program name), so that windows open at
/// once never touch each other's file. A file whose lock is stale — its window's process is gone
/// without closing normally (a crash, a killed session) — is "left": the next start finds it and
/// offers it back. The file of earlier versions (autosave.json in the data folder itself, its
/// case file named in the settings) is found as left too.
#include <QDateTime>
#include <QString>
#include <memory>
#include <vector>

class QLockFile;

namespace filmdyn::engine {
struct EngineCase;
}

namespace filmdyn::ui {

/// One window's autosave file and its lock, taken when made and released when destroyed. The
/// destructor leaves the file (a window that closes normally calls remove() first): a window
/// destroyed without closing leaves its edits to the next start, as a crash would.
class AutosaveSlot {
 public:
  AutosaveSlot();
  ~AutosaveSlot();
  AutosaveSlot(const AutosaveSlot&) = delete;
  AutosaveSlot& operator=(const AutosaveSlot&) = delete;

  /// The case file's path (<data>/autosave/session-<pid>-<time>-<n>.json).
  QString filePath() const { return file_; }
  /// Writes `engine_case` (atomically) and the path of the case file it belongs to (empty for a
  /// case never saved). False with *error when either cannot be written.
  bool write(const engine::EngineCase& engine_case, const QString& source, QString* error);
  /// Removes the file (nothing to recover); the lock stays until destruction.
  void remove();

 private:
  QString file_;
  std::unique_ptr<QLockFile> lock_;
};

/// An autosave whose window is gone, locked by this process while the object lives (another
/// window starting at the same moment does not offer it too).
struct LeftAutosave {
  QString file;                     ///< the case as it was, invalid cells included
  QString source;                   ///< the case file the edits belong to; empty for a new case
  QDateTime written;                ///< when the file was last written
  std::shared_ptr<QLockFile> lock;  ///< held while this object (and its copies) live

  /// Removes the file and what belongs to it (its case-file name; the lock when released).
  void remove() const;
};

/// The folder the autosave files are in (<data>/autosave).
QString AutosaveFolder();

/// Every autosave whose window is gone, newest first, each locked for the caller.
std::vector<LeftAutosave> ClaimLeftAutosaves();

/// Where a left autosave that cannot be read is kept aside (in the data folder, a name of its
/// own per file so that an earlier one is not replaced).
QString NotRecoveredPath(const LeftAutosave& left);

}  // namespace filmdyn::ui
