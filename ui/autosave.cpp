#include "ui/autosave.hpp"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLockFile>
#include <QObject>
#include <QSettings>
#include <QStandardPaths>
#include <algorithm>
#include <atomic>

#include "ui/case_editor/case_json.hpp"
#include "ui/save_text.hpp"

namespace filmdyn::ui {
namespace {

QString DataFolder() { return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation); }

// Earlier versions: one file for every window, its case file's path in the settings.
QString EarlierVersionsFile() { return QDir(DataFolder()).filePath("autosave.json"); }
constexpr const char* kEarlierVersionsSourceKey = "autosave/source";

QString LockPath(const QString& file) { return file + ".lock"; }
QString SourcePath(const QString& file) { return file + ".source"; }

// A lock on `file` for this process when no live process holds it (the lock of a process that
// is gone is stale and taken over), else null.
std::shared_ptr<QLockFile> Claim(const QString& file) {
  auto lock = std::make_shared<QLockFile>(LockPath(file));
  // Stale only when its process is gone, however old: a window may stay open for weeks.
  lock->setStaleLockTime(0);
  if (!lock->tryLock(0)) return nullptr;
  return lock;
}

LeftAutosave Left(const QString& file, std::shared_ptr<QLockFile> lock, bool earlier_version) {
  LeftAutosave left;
  left.file = file;
  left.written = QFileInfo(file).lastModified();
  left.lock = std::move(lock);
  if (earlier_version) {
    left.source = QSettings().value(kEarlierVersionsSourceKey).toString();
  } else if (QFile source(SourcePath(file)); source.open(QIODevice::ReadOnly)) {
    left.source = QString::fromUtf8(source.readAll()).trimmed();
  }
  return left;
}

}  // namespace

QString AutosaveFolder() { return QDir(DataFolder()).filePath("autosave"); }

AutosaveSlot::AutosaveSlot() {
  static std::atomic<int> count{0};
  QDir().mkpath(AutosaveFolder());
  // Unique among this process's windows and over time; the lock names the process.
  file_ = QDir(AutosaveFolder())
              .filePath(QStringLiteral("session-%1-%2-%3.json")
                            .arg(QCoreApplication::applicationPid())
                            .arg(QDateTime::currentMSecsSinceEpoch())
                            .arg(count++));
  lock_ = std::make_unique<QLockFile>(LockPath(file_));
  lock_->setStaleLockTime(0);
  // A fresh name: only a folder that cannot be written stops this, and then write() says so.
  lock_->tryLock(0);
}

AutosaveSlot::~AutosaveSlot() = default;

bool AutosaveSlot::write(const engine::EngineCase& engine_case, const QString& source,
                         QString* error) {
  QDir().mkpath(AutosaveFolder());
  if (!lock_->isLocked() && !lock_->tryLock(0)) {
    // Without its lock the file would look left by a gone window to every other one.
    if (error) {
      *error = QObject::tr("Cannot lock %1: the folder cannot be written")
                   .arg(QDir::toNativeSeparators(LockPath(file_)));
    }
    return false;
  }
  return SaveCaseFile(engine_case, file_, error) &&
         SaveTextFile(SourcePath(file_), source.toStdString() + "\n", error);
}

void AutosaveSlot::remove() {
  QFile::remove(file_);
  QFile::remove(SourcePath(file_));
}

void LeftAutosave::remove() const {
  QFile::remove(file);
  QFile::remove(SourcePath(file));
  if (file == EarlierVersionsFile()) QSettings().remove(kEarlierVersionsSourceKey);
}

std::vector<LeftAutosave> ClaimLeftAutosaves() {
  std::vector<LeftAutosave> left;
  const QDir folder(AutosaveFolder());
  // The lock of a window gone before it wrote anything: taken over and released, so removed.
  for (const QString& lock : folder.entryList({"*.json.lock"}, QDir::Files)) {
    const QString file = folder.filePath(lock.chopped(5));
    if (!QFileInfo::exists(file)) Claim(file);
  }
  for (const QFileInfo& info : folder.entryInfoList({"*.json"}, QDir::Files)) {
    if (auto lock = Claim(info.filePath())) left.push_back(Left(info.filePath(), lock, false));
  }
  if (QFileInfo::exists(EarlierVersionsFile())) {
    if (auto lock = Claim(EarlierVersionsFile())) {
      left.push_back(Left(EarlierVersionsFile(), lock, true));
    }
  }
  std::stable_sort(left.begin(), left.end(), [](const LeftAutosave& a, const LeftAutosave& b) {
    return a.written > b.written;
  });
  return left;
}

QString NotRecoveredPath(const LeftAutosave& left) {
  return QDir(DataFolder())
      .filePath(QStringLiteral("autosave-not-recovered-%1.json")
                    .arg(QFileInfo(left.file).completeBaseName()));
}

}  // namespace filmdyn::ui
