#pragma once
/// @file The FilmDyn main window: menus, central workspace tabs, status bar. Window geometry
/// and state are remembered between sessions (QSettings).
#include <QMainWindow>

class QTabWidget;

namespace filmdyn::ui {

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  QTabWidget* workspace() const { return workspace_; }

 public slots:
  void showAbout();

 protected:
  void closeEvent(QCloseEvent* event) override;

 private:
  void createMenus();
  void restoreWindowState();

  QTabWidget* workspace_ = nullptr;
};

}  // namespace filmdyn::ui
