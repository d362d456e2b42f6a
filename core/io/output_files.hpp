#pragma once
/// @file How every output file is written, and the output folder of a run.
///
/// Files: written under a temporary name beside the target, flushed and synced to the disk,
/// every write checked, then renamed into place — a reader (or a later run) sees the old file
/// or the whole new one, never a cut one. A failed write throws OutputError naming the file and
/// the reason (e.g. "No space left on device") and leaves no temporary behind.
///
/// Folders: a run's folder is locked against a second FilmDyn writer for the run's lifetime
/// (an advisory flock(2) on `.filmdyn.lock`, released by the kernel if the process dies), and a
/// folder holding an earlier run is refused unless the caller asks to replace it; replacing
/// removes only FilmDyn's own files (docs/outputs.md, "Output folders").
#include <filesystem>
#include <stdexcept>
#include <string>
#include <cstdint>
#include <string_view>

namespace filmdyn::io {

/// An output could not be written: the message names the file and the reason.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Writes `bytes` to `file` (created or truncated), flushed and synced to the disk. Messages
/// name `shown_as` (the file the user knows; `file` may be its temporary). Throws OutputError;
/// `file` is left as it is (the caller removes its temporary).
void WriteAndSync(const std::filesystem::path& file, const std::filesystem::path& shown_as,
                  std::string_view bytes);
/// Renames `from` to `to` (atomic on one file system). Throws OutputError naming `to`.
void RenameInto(const std::filesystem::path& from, const std::filesystem::path& to);
/// The temporary name WriteFileAtomically uses for `target`: "<name>.tmp" beside it.
std::filesystem::path TemporaryFor(const std::filesystem::path& target);
/// Writes `bytes` to a temporary beside `target`, syncs it and renames it into place.
void WriteFileAtomically(const std::filesystem::path& target, std::string_view bytes);

/// An exclusive advisory lock (flock) on `file` (created when missing), waited for and held
/// while the object lives: for short writes several processes may make at once (a study's tables,
/// written by the study and by any number of `collect`s). Throws InputError naming `option` and
/// the file when it cannot be opened or the file system has no locks.
class WaitedLock {
 public:
  WaitedLock(const std::filesystem::path& file, const std::string& option);
  ~WaitedLock();
  WaitedLock(const WaitedLock&) = delete;
  WaitedLock& operator=(const WaitedLock&) = delete;

 private:
  int fd_ = -1;
};

/// The output folder of one run (or of a sweep's comparison) while FilmDyn writes it.
class OutputFolder {
 public:
  enum class Reuse {
    kRefuse,   ///< a folder holding an earlier run is an input error naming `option`
    kReplace,  ///< FilmDyn's own files of the earlier run are removed first
  };
  /// The commands' rule: an --out given by the user is refused unless --overwrite; the default
  /// folder under results/ is FilmDyn's own and is replaced.
  static Reuse ReuseFor(bool explicit_out, bool overwrite) {
    return explicit_out && !overwrite ? Reuse::kRefuse : Reuse::kReplace;
  }
  /// Throws the input error (naming `option`) for `folder` holding an earlier run.
  [[noreturn]] static void RefuseEarlierRun(const std::filesystem::path& folder,
                                            const std::string& option);
  /// Creates `folder`, takes its lock (an input error naming `option` when another FilmDyn
  /// process holds it) and applies `reuse` to an earlier run's files in it. Throws InputError.
  OutputFolder(const std::filesystem::path& folder, Reuse reuse, const std::string& option);
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  const std::filesystem::path& path() const { return folder_; }
  /// True when an earlier run's files were found (and, with kReplace, removed).
  bool replaced_earlier_run() const { return replaced_; }

  /// The lock file a run holds in its folder (advisory flock, released when the process ends).
  static constexpr char kLockFile[] = ".filmdyn.lock";
  /// Whether another process holds `folder`'s lock (a run writing into it now).
  static bool IsLocked(const std::filesystem::path& folder);

  /// Whether `folder` holds files of an earlier FilmDyn run (results.csv, summary.json, fields/,
  /// plots/, comparison.csv/.md).
  static bool HoldsEarlierRun(const std::filesystem::path& folder);
  /// Removes FilmDyn's own files from `folder`: results.csv, summary.json, comparison.csv/.md,
  /// the .h5/.xdmf/.tmp files in fields/ and the .png/.svg/.tmp files in plots/ (each
  /// subfolder itself only when it is then empty). Anything else is left alone.
  static void RemoveEarlierRun(const std::filesystem::path& folder);

 private:
  std::filesystem::path folder_;
  int lock_fd_ = -1;
  bool replaced_ = false;
};

}  // namespace filmdyn::io

namespace filmdyn::io {

/// Creates `folder` (and its parents) when missing. Throws InputError(option, folder, "cannot
/// create the folder: <reason>") when that fails or the path is not a folder (a file).
void CreateFolder(const std::filesystem::path& folder, const std::string& option);

/// A case name as a folder name: path separators, "..", leading dots, control characters and
/// bytes that are not UTF-8 become '_' (a name can never point outside its parent); cut to 120
/// bytes at a character's start (a file name holds 255); empty → "case".
std::string SafeFolderName(const std::string& name);

/// A text as one CSV cell: quoted (its quotes doubled) when it holds a comma, a quote or a line
/// break; as it is otherwise.
std::string CsvCell(const std::string& text);

}  // namespace filmdyn::io
