#include "core/io/output_files.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <initializer_list>
#include <system_error>
#include <vector>

#include "core/base/input_error.hpp"

namespace filmdyn::io {

void WriteAndSync(const std::filesystem::path& file, const std::filesystem::path& shown_as,
                  std::string_view bytes) {
  auto fail = [&shown_as](const char* what, int error) {
    throw OutputError("cannot write " + shown_as.string() + ": " + what + " (" +
                      std::strerror(error) + ")");
  };
  std::FILE* out = std::fopen(file.c_str(), "wb");
  if (out == nullptr) fail("cannot open for writing", errno);
  const bool written = std::fwrite(bytes.data(), 1, bytes.size(), out) == bytes.size() &&
                       std::fflush(out) == 0 && ::fsync(::fileno(out)) == 0;
  const int write_errno = errno;
  const bool closed = std::fclose(out) == 0;
  if (!written || !closed) fail("write failed", !written ? write_errno : errno);
}

void RenameInto(const std::filesystem::path& from, const std::filesystem::path& to) {
  std::error_code error;
  std::filesystem::rename(from, to, error);
  if (error) throw OutputError("cannot write " + to.string() + ": " + error.message());
}

std::filesystem::path TemporaryFor(const std::filesystem::path& target) {
  std::filesystem::path temporary = target;
  temporary += ".tmp";
  return temporary;
}

void WriteFileAtomically(const std::filesystem::path& target, std::string_view bytes) {
  const std::filesystem::path temporary = TemporaryFor(target);
  try {
    WriteAndSync(temporary, target, bytes);
    RenameInto(temporary, target);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
}

namespace {
constexpr const char* kRunFiles[] = {"results.csv",      "motion.csv",     "summary.json",
                                     "case-as-run.json", "comparison.csv", "comparison.md"};
// FilmDyn's files in its subfolders, by extension.
struct OwnFiles {
  const char* folder;
  std::initializer_list<const char*> extensions;
};
const OwnFiles kOwnSubfolders[] = {{"fields", {".h5", ".xdmf", ".tmp"}},
                                   {"plots", {".png", ".svg", ".tmp"}}};

bool IsOwnFile(const std::filesystem::path& file, const OwnFiles& own) {
  const std::string extension = file.extension().string();
  for (const char* e : own.extensions) {
    if (extension == e) return true;
  }
  return false;
}
}  // namespace

void OutputFolder::RefuseEarlierRun(const std::filesystem::path& folder,
                                    const std::string& option) {
  throw InputError(
      option, folder.string(),
      "holds an earlier run (results.csv, motion.csv, summary.json, fields/ or plots/); "
      "choose "
      "another folder, or pass --overwrite to replace FilmDyn's files in it");
}

bool OutputFolder::HoldsEarlierRun(const std::filesystem::path& folder) {
  std::error_code error;
  for (const char* name : kRunFiles) {
    if (std::filesystem::exists(folder / name, error)) return true;
  }
  for (const OwnFiles& own : kOwnSubfolders) {
    const std::filesystem::path sub = folder / own.folder;
    if (!std::filesystem::is_directory(sub, error)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(sub, error)) {
      if (IsOwnFile(entry.path(), own)) return true;
    }
  }
  return false;
}

void OutputFolder::RemoveEarlierRun(const std::filesystem::path& folder) {
  auto remove = [](const std::filesystem::path& file) {
    std::error_code error;
    std::filesystem::remove(file, error);
    if (error) {
      throw OutputError("cannot remove the earlier run's " + file.string() + ": " +
                        error.message());
    }
  };
  for (const char* name : kRunFiles) remove(folder / name);
  for (const OwnFiles& own : kOwnSubfolders) {
    const std::filesystem::path sub = folder / own.folder;
    std::error_code error;
    if (!std::filesystem::is_directory(sub, error)) continue;
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(sub, error)) {
      if (entry.is_regular_file(error) && IsOwnFile(entry.path(), own)) {
        files.push_back(entry.path());
      }
    }
    for (const auto& file : files) remove(file);
    if (std::filesystem::is_empty(sub, error)) std::filesystem::remove(sub, error);
  }
}

OutputFolder::OutputFolder(const std::filesystem::path& folder, Reuse reuse,
                           const std::string& option)
    : folder_(folder) {
  CreateFolder(folder, option);
  const std::filesystem::path lock = folder / kLockFile;
  lock_fd_ = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (lock_fd_ < 0) {
    throw InputError(option, folder.string(),
                     std::string("cannot write in the folder: ") + std::strerror(errno));
  }
  if (::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
    const int lock_error = errno;
    ::close(lock_fd_);
    lock_fd_ = -1;
    if (lock_error != EWOULDBLOCK) {  // a file system without locks (some NFS, Lustre mounts)
      throw InputError(option, folder.string(),
                       std::string("cannot lock ") + lock.string() + " (" +
                           std::strerror(lock_error) +
                           "): this file system does not support file locks; write the results "
                           "to a local or lock-capable file system");
    }
    throw InputError(option, folder.string(),
                     "another FilmDyn run is writing into this folder; wait for it or choose "
                     "another folder");
  }
  try {
    if (HoldsEarlierRun(folder)) {
      if (reuse == Reuse::kRefuse) RefuseEarlierRun(folder, option);
      RemoveEarlierRun(folder);
      replaced_ = true;
    }
  } catch (...) {
    ::close(lock_fd_);
    lock_fd_ = -1;
    throw;
  }
}

WaitedLock::WaitedLock(const std::filesystem::path& file, const std::string& option) {
  fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    throw InputError(option, file.string(), std::string("cannot write: ") + std::strerror(errno));
  }
  int status = 0;
  do {
    status = ::flock(fd_, LOCK_EX);
  } while (status != 0 && errno == EINTR);
  if (status != 0) {
    const int lock_error = errno;
    ::close(fd_);
    fd_ = -1;
    throw InputError(option, file.string(),
                     std::string("cannot lock (") + std::strerror(lock_error) +
                         "): this file system does not support file locks");
  }
}

WaitedLock::~WaitedLock() {
  if (fd_ >= 0) ::close(fd_);
}

bool OutputFolder::IsLocked(const std::filesystem::path& folder) {
  const int fd = ::open((folder / kLockFile).c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  // Only a lock another process holds counts (a file system without locks holds none).
  const bool held = ::flock(fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  ::close(fd);
  return held;
}

OutputFolder::~OutputFolder() {
  if (lock_fd_ >= 0) ::close(lock_fd_);  // releases the flock
}

}  // namespace filmdyn::io

namespace filmdyn::io {

void CreateFolder(const std::filesystem::path& folder, const std::string& option) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (!error && !std::filesystem::is_directory(folder, error)) {
    throw InputError(option, folder.string(), "cannot create the folder: a file has its name");
  }
  if (error)
    throw InputError(option, folder.string(), "cannot create the folder: " + error.message());
}

std::string SafeFolderName(const std::string& name) {
  std::string safe = IsUtf8(name) ? name : std::string();
  if (safe.empty() && !name.empty()) {  // not UTF-8: keep the ASCII, mark the rest
    for (char c : name) safe += static_cast<unsigned char>(c) < 0x80 ? c : '_';
  }
  for (char& c : safe) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '/' || c == '\\' || u < 0x20 || u == 0x7F || c == ':') c = '_';
  }
  for (std::size_t i = 0; i < safe.size() && safe[i] == '.'; ++i) safe[i] = '_';
  // A file name holds at most 255 bytes; the folder adds "-<model>-<rpm>" to it. Cut at a
  // character's start (a UTF-8 continuation byte is 10xxxxxx).
  constexpr std::size_t kMaxBytes = 120;
  if (safe.size() > kMaxBytes) {
    std::size_t cut = kMaxBytes;
    while (cut > 0 && (static_cast<unsigned char>(safe[cut]) & 0xC0) == 0x80) --cut;
    safe.resize(cut);
  }
  if (safe.empty()) safe = "case";
  return safe;
}

std::string CsvCell(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

}  // namespace filmdyn::io
