#pragma once
// The command-line suites' one way to run the real `filmdyn` executable (FILMDYN_EXECUTABLE,
// defined by each suite's CMake target) as a user would, and what it printed.
#include <QProcess>
#include <QProcessEnvironment>
#include <QString>
#include <QStringList>

struct Result {
  int exit_code = -1;  ///< -1: it did not end within the time given (and was killed)
  QString out;
  QString err;
};

inline Result RunFilmdyn(
    const QStringList& arguments, int timeout_ms,
    const QProcessEnvironment& env = QProcessEnvironment::systemEnvironment()) {
  QProcess process;
  process.setProcessEnvironment(env);
  process.start(FILMDYN_EXECUTABLE, arguments);
  if (!process.waitForFinished(timeout_ms)) {
    process.kill();
    return {};
  }
  return {process.exitCode(), QString::fromUtf8(process.readAllStandardOutput()),
          QString::fromUtf8(process.readAllStandardError())};
}
