// filmdyn: the desktop application when called alone, a headless command otherwise.
#include <sys/stat.h>
#include <unistd.h>
#include <QApplication>
#include <QTimer>

#include <clocale>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "app/cli/dispatcher.hpp"
#include "core/base/version.hpp"
#include "ui/main_window.hpp"
#include "ui/vtk/vtk_view_widget.hpp"

namespace {

bool HasDisplay() {
  auto set = [](const char* name) {
    const char* value = std::getenv(name);
    return value != nullptr && *value != '\0';
  };
  return set("DISPLAY") || set("WAYLAND_DISPLAY") || set("QT_QPA_PLATFORM");
}

// Headless machines (CI, batch nodes, ssh) often have no XDG_RUNTIME_DIR; Qt then falls back
// to /tmp/runtime-<user> but prints a warning into every command's output. Do what it does,
// without the warning: a private folder (0700) of this user.
void EnsureRuntimeDirectory() {
  const char* set = std::getenv("XDG_RUNTIME_DIR");
  if (set != nullptr && *set != '\0') return;
  const std::string dir = "/tmp/runtime-" + std::to_string(::getuid());
  ::mkdir(dir.c_str(), 0700);
  struct stat info {};
  if (::stat(dir.c_str(), &info) == 0 && S_ISDIR(info.st_mode) && info.st_uid == ::getuid() &&
      (info.st_mode & 0777) == 0700) {
    setenv("XDG_RUNTIME_DIR", dir.c_str(), 1);
  }
}

// Qt's application object sets the C library's locale from the environment (setlocale(LC_ALL,
// "")). Under a German or French LC_NUMERIC the C library then reads "1.5" as 1 and writes 1.5
// as "1,5" — in FilmDyn's own code every number is read and written locale-free, but libraries
// (VTK, HDF5, SUNDIALS' messages) use the C library's: numbers stay in the C form. QLocale, which
// formats the dates the GUI shows, still follows the user's settings.
void KeepNumbersInTheCForm() { std::setlocale(LC_NUMERIC, "C"); }

void SetApplicationIdentity() {
  QCoreApplication::setOrganizationName("FilmDyn");
  QCoreApplication::setApplicationName("FilmDyn");
  QCoreApplication::setApplicationVersion(QString::fromUtf8(filmdyn::Version().data()));
}

}  // namespace

int main(int argc, char** argv) {
  using filmdyn::cli::LaunchKind;
  const std::vector<std::string> args(argv + 1, argv + argc);
  const filmdyn::cli::Launch launch = filmdyn::cli::Classify(args);

  switch (launch.kind) {
    case LaunchKind::kHelp:
      std::cout << filmdyn::cli::GlobalUsage();
      return 0;
    case LaunchKind::kVersion:
      std::cout << "filmdyn " << filmdyn::Version() << "\n";
      return 0;
    case LaunchKind::kCommand:
      if (filmdyn::cli::CommandNeedsGuiApplication(launch.command)) {
        // Plots are rendered with Qt Charts; without a screen use the offscreen platform.
        if (!HasDisplay()) setenv("QT_QPA_PLATFORM", "offscreen", 1);
        EnsureRuntimeDirectory();
        QApplication app(argc, argv);
        KeepNumbersInTheCForm();
        SetApplicationIdentity();
        return filmdyn::cli::RunCommand(launch.command, launch.args);
      }
      return filmdyn::cli::RunCommand(launch.command, launch.args);
    case LaunchKind::kGui:
      break;
  }

  if (!HasDisplay()) {
    std::cerr << "filmdyn: no display (DISPLAY is not set): the desktop application needs one.\n"
                 "Run headless instead, e.g. 'filmdyn run', or see 'filmdyn --help'.\n";
    return 1;
  }
  filmdyn::ui::VtkViewWidget::SetDefaultSurfaceFormat();
  QApplication app(argc, argv);
  KeepNumbersInTheCForm();
  SetApplicationIdentity();
  filmdyn::ui::MainWindow window;
  window.show();
  // Unsaved edits of a session that crashed: offered back once the window is up.
  QTimer::singleShot(0, &window, &filmdyn::ui::MainWindow::offerRecovery);
  return app.exec();
}
