#include "ui/main_window.hpp"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QTabWidget>

#include "ui/about_info.hpp"

namespace filmdyn::ui {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
  setWindowTitle("FilmDyn");
  setObjectName("MainWindow");
  workspace_ = new QTabWidget(this);
  workspace_->setObjectName("workspace");
  workspace_->setDocumentMode(true);
  setCentralWidget(workspace_);
  createMenus();
  statusBar()->showMessage(tr("Ready"));
  restoreWindowState();
}

MainWindow::~MainWindow() = default;

void MainWindow::createMenus() {
  QMenu* file_menu = menuBar()->addMenu(tr("&File"));
  QAction* quit = file_menu->addAction(tr("&Quit"), this, &QWidget::close);
  quit->setShortcut(QKeySequence::Quit);

  QMenu* help_menu = menuBar()->addMenu(tr("&Help"));
  help_menu->addAction(tr("&About FilmDyn"), this, &MainWindow::showAbout);
}

void MainWindow::showAbout() {
  QString text =
      tr("<h3>FilmDyn</h3><p>Engine dynamics with lubricated piston skirt and big-end "
         "bearing: secondary motion, journal orbit, film thickness, friction.</p><table>");
  for (const auto& [name, version] : LibraryVersions()) {
    text += QString("<tr><td>%1</td><td>&nbsp;%2</td></tr>")
                .arg(QString::fromStdString(name), QString::fromStdString(version));
  }
  text += "</table>";
  QMessageBox::about(this, tr("About FilmDyn"), text);
}

void MainWindow::restoreWindowState() {
  QSettings settings;
  if (!restoreGeometry(settings.value("main_window/geometry").toByteArray())) resize(1280, 820);
  restoreState(settings.value("main_window/state").toByteArray());
}

void MainWindow::closeEvent(QCloseEvent* event) {
  QSettings settings;
  settings.setValue("main_window/geometry", saveGeometry());
  settings.setValue("main_window/state", saveState());
  event->accept();
}

}  // namespace filmdyn::ui
