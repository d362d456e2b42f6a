// The main window opens with its menus and remembers its geometry between sessions.
#include <QMenuBar>
#include <QSettings>
#include <QStandardPaths>
#include <QTabWidget>
#include <QtTest>

#include "ui/about_info.hpp"
#include "ui/main_window.hpp"

class TestMainWindow : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName("FilmDynTest");
    QCoreApplication::setApplicationName("test_main_window");
    QSettings().clear();
  }

  void opensWithMenusAndWorkspace() {
    filmdyn::ui::MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QCOMPARE(window.windowTitle(), QString("FilmDyn"));
    QStringList menus;
    for (QAction* action : window.menuBar()->actions()) menus << action->text();
    QVERIFY(menus.contains("&File"));
    QVERIFY(menus.contains("&Help"));
    QVERIFY(window.workspace() != nullptr);
  }

  void remembersGeometry() {
    {
      filmdyn::ui::MainWindow window;
      window.show();
      QVERIFY(QTest::qWaitForWindowExposed(&window));
      window.resize(1011, 707);
      window.close();
    }
    filmdyn::ui::MainWindow again;
    QCOMPARE(again.size(), QSize(1011, 707));
  }

  void aboutListsLibraryVersions() {
    const auto versions = filmdyn::ui::LibraryVersions();
    QStringList names;
    for (const auto& [name, version] : versions) {
      names << QString::fromStdString(name);
      QVERIFY(!version.empty());
    }
    for (const char* expected : {"FilmDyn", "Qt", "VTK", "Eigen", "SuiteSparse"}) {
      QVERIFY2(names.contains(expected), expected);
    }
  }
};

QTEST_MAIN(TestMainWindow)
#include "test_main_window.moc"
