// The main window opens with its menus, remembers its geometry between sessions, asks before
// unsaved changes are lost (Cancel keeps the window, Discard closes, Save writes the file), and
// its keyboard shortcuts act (undo/redo of an edit, switching the workspace pages).
#include <QAbstractButton>
#include <QFile>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QStyle>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

#include "ui/about_info.hpp"
#include "ui/case_editor/case_document.hpp"
#include "ui/case_editor/case_parameters.hpp"
#include "ui/main_window.hpp"
#include "ui/run/run_controller.hpp"

namespace {
// Answers the next modal message box with `button` (from the event loop, as a user would) and
// records its title; the box must appear within a few seconds.
// Answers the next message box that has `button` (one without it is left to another answer),
// keeping its title and text.
void AnswerNextMessageBox(QMessageBox::StandardButton button, QString* title = nullptr,
                          QString* text = nullptr) {
  QTimer::singleShot(50, [button, title, text] {
    auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
    if (!box || !box->button(button)) {
      AnswerNextMessageBox(button, title, text);  // not shown yet: look again
      return;
    }
    if (title) *title = box->windowTitle();
    if (text) *text = box->text();
    // scripts/screenshots.sh-style runs keep a picture of every question asked.
    if (const QString dir = qEnvironmentVariable("FILMDYN_SCREENSHOT_DIR"); !dir.isEmpty()) {
      box->grab().save(dir + "/dialog-" + box->windowTitle().toLower().replace(' ', '-') + ".png");
    }
    box->button(button)->click();
  });
}
}  // namespace

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

  void finishedRunsAreNeverDroppedSilently() {
    // A finished run not yet saved with the project: closing asks first, like an edited case.
    QTemporaryDir dir;
    const QString path = dir.filePath("case.json");
    filmdyn::ui::MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    auto c = window.document()->engineCase();
    filmdyn::ui::ApplyRunModel(c, "ideal");
    c.solver.output_interval = 4.0 * M_PI / 180.0;
    window.document()->reset(c);
    QString error;
    QVERIFY2(window.saveProjectAs(path, &error), qPrintable(error));
    QVERIFY(!window.hasUnsavedRuns());
    QSignalSpy finished(window.runController(), &filmdyn::ui::RunController::runFinished);
    window.runAction()->trigger();
    QVERIFY(finished.wait(120000));
    QVERIFY(window.hasUnsavedRuns());
    QVERIFY(!window.document()->isModified());
    QString title;
    AnswerNextMessageBox(QMessageBox::Cancel, &title);
    QVERIFY(!window.close());
    QCOMPARE(title, QString("Unsaved changes"));
    // Saved with the project: nothing to ask any more.
    QVERIFY2(window.saveProjectAs(path, &error), qPrintable(error));
    QVERIFY(!window.hasUnsavedRuns());
    QVERIFY(window.close());
  }

  void unsavedChangesAreNeverLostSilently() {
    QTemporaryDir dir;
    const QString path = dir.filePath("case.json");
    filmdyn::ui::MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QString error;
    QVERIFY2(window.saveProjectAs(path, &error), qPrintable(error));
    QVERIFY(!window.document()->isModified());
    window.document()->setParameter("operating.rpm", 4321.5);
    QVERIFY(window.document()->isModified());
    QVERIFY(window.windowTitle().startsWith("case.json *"));

    // Cancel: the window stays open with the edit.
    QString title;
    AnswerNextMessageBox(QMessageBox::Cancel, &title);
    QVERIFY(!window.close());
    QCOMPARE(title, QString("Unsaved changes"));
    QVERIFY(window.isVisible());
    QCOMPARE(window.document()->engineCase().operating.rpm, 4321.5);

    // Save: written to the project file, then the window closes.
    title.clear();
    AnswerNextMessageBox(QMessageBox::Save, &title);
    QVERIFY(window.close());
    QCOMPARE(title, QString("Unsaved changes"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QVERIFY(file.readAll().contains("4321.5"));

    // Discard: closes without writing.
    filmdyn::ui::MainWindow other;
    other.show();
    QVERIFY(QTest::qWaitForWindowExposed(&other));
    QVERIFY(other.openProject(path, &error));
    other.document()->setParameter("operating.rpm", 1357.25);
    AnswerNextMessageBox(QMessageBox::Discard, &title);
    QVERIFY(other.close());
    QFile again(path);
    QVERIFY(again.open(QIODevice::ReadOnly));
    const QByteArray text = again.readAll();
    QVERIFY(text.contains("4321.5") && !text.contains("1357.25"));
  }

  // Destroying a window (or a document) with unsaved edits: the undo stack's clearing must not
  // signal anyone — the window that owns the document is half destroyed by then (caught by
  // UBSan: MainWindow::updateTitle ran on it).
  void destructionSignalsNobody() {
    int modified_signals = 0;
    {
      filmdyn::ui::CaseDocument document;
      document.setParameter("operating.rpm", 4321.5);
      QVERIFY(document.isModified());
      QObject::connect(&document, &filmdyn::ui::CaseDocument::modifiedChanged,
                       [&modified_signals](bool) { ++modified_signals; });
    }  // ~CaseDocument: ~QUndoStack clears the stack
    QCOMPARE(modified_signals, 0);
    auto* window = new filmdyn::ui::MainWindow;
    window->document()->setParameter("operating.rpm", 1234.5);
    QObject::connect(window->document(), &filmdyn::ui::CaseDocument::modifiedChanged,
                     [&modified_signals](bool) { ++modified_signals; });
    delete window;  // never shown: no close event, no question
    QCOMPARE(modified_signals, 0);
  }

  // Unsaved edits survive a crash: written to the autosave file (every minute; here at once),
  // left behind by a window that never closed normally, offered back by the next one on top of
  // the case file they belong to; saving or closing normally removes the file.
  void autosaveIsOfferedBackAfterACrash() {
    QTemporaryDir dir;
    const QString path = dir.filePath("case.json");
    QFile::remove(filmdyn::ui::MainWindow::autosavePath());
    {
      filmdyn::ui::MainWindow window;
      QString error;
      QVERIFY(window.saveProjectAs(path, &error));
      QVERIFY(window.autosaveNow());
      QVERIFY(!filmdyn::ui::MainWindow::hasRecovery());  // nothing unsaved: nothing written
      window.document()->setParameter("operating.rpm", 2468.5);
      QVERIFY2(window.autosaveNow(&error), qPrintable(error));
      QVERIFY(filmdyn::ui::MainWindow::hasRecovery());
    }  // "crash": destroyed without a close event
    QVERIFY(filmdyn::ui::MainWindow::hasRecovery());
    {
      filmdyn::ui::MainWindow next;
      QString error, title;
      next.show();
      AnswerNextMessageBox(QMessageBox::Yes, &title);
      next.offerRecovery();  // the question the next start asks (main.cpp), answered Yes
      QCOMPARE(title, QString("Recover unsaved edits"));
      QCOMPARE(next.document()->engineCase().operating.rpm, 2468.5);
      QVERIFY(next.document()->isModified());
      QCOMPARE(next.document()->filePath(), path);
      QVERIFY(!filmdyn::ui::MainWindow::hasRecovery());
      // Undo goes back to the saved file's value; saving removes any new autosave.
      QVERIFY(next.autosaveNow());
      QVERIFY(filmdyn::ui::MainWindow::hasRecovery());
      QVERIFY(next.saveProjectAs(path, &error));
      QVERIFY(!filmdyn::ui::MainWindow::hasRecovery());
    }
  }

  // A crash while a cell is marked invalid: the autosave holds the invalid value (a NaN, an
  // out-of-range number) beside the good edits. Recovery brings back every good edit and keeps
  // the saved value where the cell was invalid, and says which (it used to refuse the whole file
  // and the next minute's timer deleted it). A file that cannot be read at all is kept aside.
  void autosaveWithAnInvalidCellRecoversTheRest() {
    QTemporaryDir dir;
    const QString path = dir.filePath("case.json");
    QFile::remove(filmdyn::ui::MainWindow::autosavePath());
    double rod = 0.0;
    {
      filmdyn::ui::MainWindow window;
      QString error;
      QVERIFY(window.saveProjectAs(path, &error));
      rod = window.document()->engineCase().geometry.rod_length;
      window.document()->setParameter("operating.rpm", 2468.5);
      window.document()->setParameter("skirt.roughness_skirt", 0.85e-6);
      window.document()->setParameter("geometry.rod_length", std::nan(""));  // a cell cleared
      window.document()->setParameter("big_end.width", -0.01);               // out of range
      QVERIFY(window.document()->issues().size() >= 2);
      QVERIFY2(window.autosaveNow(&error), qPrintable(error));
    }  // "crash"
    {
      filmdyn::ui::MainWindow next;
      next.show();
      AnswerNextMessageBox(QMessageBox::Yes);
      next.offerRecovery();
      const auto& c = next.document()->engineCase();
      QCOMPARE(c.operating.rpm, 2468.5);
      QCOMPARE(c.skirt.roughness_skirt, 0.85e-6);
      QCOMPARE(c.geometry.rod_length, rod);  // the saved file's
      QVERIFY(c.big_end.width > 0.0);
      QVERIFY(next.document()->issues().empty());
      QVERIFY(next.document()->isModified());
      const QString message = next.statusBar()->currentMessage();
      QVERIFY2(message.contains("Recovered") && message.contains("geometry.rod_length") &&
                   message.contains("big_end.width"),
               qPrintable(message));
      QVERIFY(!filmdyn::ui::MainWindow::hasRecovery());
    }
    // Not a case file at all: the question's answer cannot recover it; it is kept aside.
    QFile broken(filmdyn::ui::MainWindow::autosavePath());
    QVERIFY(broken.open(QIODevice::WriteOnly));
    broken.write("{ \"geometry\": ");
    broken.close();
    {
      filmdyn::ui::MainWindow next;
      next.show();
      QString title, text;
      AnswerNextMessageBox(QMessageBox::Yes);
      AnswerNextMessageBox(QMessageBox::Ok, &title, &text);
      next.offerRecovery();
      QCOMPARE(title, QString("Cannot recover"));
      const QString kept = QFileInfo(filmdyn::ui::MainWindow::autosavePath())
                               .absoluteDir()
                               .filePath("autosave-not-recovered.json");
      QVERIFY2(text.contains(kept), qPrintable(text));
      QVERIFY(QFile::exists(kept));
      QVERIFY(!filmdyn::ui::MainWindow::hasRecovery());
      QFile::remove(kept);
    }
  }

  void shortcutsAct() {
    filmdyn::ui::MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    const double rpm = window.document()->engineCase().operating.rpm;
    window.document()->setParameter("operating.rpm", rpm + 100.0);
    QTest::keyClick(&window, Qt::Key_Z, Qt::ControlModifier);  // undo
    QCOMPARE(window.document()->engineCase().operating.rpm, rpm);
    QTest::keyClick(&window, Qt::Key_Y, Qt::ControlModifier);  // redo
    QCOMPARE(window.document()->engineCase().operating.rpm, rpm + 100.0);
    QTest::keyClick(&window, Qt::Key_3, Qt::ControlModifier);  // pressure fields page
    QCOMPARE(window.workspace()->currentIndex(), 2);
    QTest::keyClick(&window, Qt::Key_1, Qt::ControlModifier);  // case page
    QCOMPARE(window.workspace()->currentIndex(), 0);
    window.document()->reset(window.document()->engineCase());  // nothing to ask at close
  }

  // Undo and redo show hooked arrows, each the other's mirror, not the style's back and forward
  // arrows (a browser's navigation: they were those).
  void undoAndRedoAreHookedArrowsNotNavigation() {
    filmdyn::ui::MainWindow window;
    QAction *undo = nullptr, *redo = nullptr;
    for (QAction* action : window.findChildren<QAction*>()) {
      if (action->shortcut() == QKeySequence(QKeySequence::Undo)) undo = action;
      if (action->shortcuts().contains(QKeySequence("Ctrl+Y"))) redo = action;
    }
    QVERIFY(undo && redo);
    const QSize size(24, 24);
    const QImage u = undo->icon().pixmap(size).toImage().convertToFormat(QImage::Format_ARGB32);
    const QImage r = redo->icon().pixmap(size).toImage().convertToFormat(QImage::Format_ARGB32);
    QVERIFY(!u.isNull() && !r.isNull());
    // Each the other's mirror, to the antialiasing's rounding (a pixel's coverage may differ
    // by a few levels of 255 where the edge lies).
    const QImage mirror = u.mirrored(true, false);
    int largest = 0;
    for (int y = 0; y < u.height(); ++y)
      for (int x = 0; x < u.width(); ++x)
        largest = std::max(largest, std::abs(qAlpha(mirror.pixel(x, y)) - qAlpha(r.pixel(x, y))));
    qInfo("largest alpha difference from the mirror: %d", largest);
    QVERIFY2(largest <= 24, qPrintable(QString::number(largest)));
    for (const auto p : {QStyle::SP_ArrowBack, QStyle::SP_ArrowForward, QStyle::SP_ArrowLeft,
                         QStyle::SP_ArrowRight}) {
      const QImage nav =
          window.style()->standardIcon(p).pixmap(size).toImage().convertToFormat(u.format());
      QVERIFY(nav != u && nav != r);
    }
    // Something is drawn, on the upper left (the head) and not only there.
    int ink = 0, upper_left = 0;
    for (int y = 0; y < u.height(); ++y) {
      for (int x = 0; x < u.width(); ++x) {
        if (qAlpha(u.pixel(x, y)) > 128) {
          ++ink;
          if (x < u.width() / 2 && y < u.height() / 2) ++upper_left;
        }
      }
    }
    QVERIFY2(ink > 40 && upper_left > 10 && upper_left < ink, qPrintable(QString::number(ink)));
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
