// filmdyn: the desktop application when called alone, a headless command otherwise.
#include <QApplication>
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
        QApplication app(argc, argv);
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
  SetApplicationIdentity();
  filmdyn::ui::MainWindow window;
  window.show();
  return app.exec();
}
