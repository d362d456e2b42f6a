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

#include "tests/ui/answer_message_box.hpp"
#include "ui/about_info.hpp"
#include "ui/autosave.hpp"
#include "ui/case_editor/case_document.hpp"
#include "ui/case_editor/case_json.hpp"
#include "ui/case_editor/case_parameters.hpp"
#include "ui/main_window.hpp"
#include "ui/run/run_controller.hpp"

// POSIX, after the project's headers (its macros clash with their names).
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>

namespace {
// No autosave left by an earlier test or a window of this user.
void ForgetLeftAutosaves() {
  for (const auto& left : filmdyn::ui::ClaimLeftAutosaves()) left.remove();
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
    filmdyn::test::AnswerNextMessageBox(QMessageBox::Cancel, &title);
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
    filmdyn::test::AnswerNextMessageBox(QMessageBox::Cancel, &title);
    QVERIFY(!window.close());
    QCOMPARE(title, QString("Unsaved changes"));
    QVERIFY(window.isVisible());
    QCOMPARE(window.document()->engineCase().operating.rpm, 4321.5);

    // Save: written to the project file, then the window closes.
    title.clear();
    filmdyn::test::AnswerNextMessageBox(QMessageBox::Save, &title);
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
    filmdyn::test::AnswerNextMessageBox(QMessageBox::Discard, &title);
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

  // Unsaved edits survive a crash: written to the window's autosave file (every minute; here at
  // once), left behind by a window that never closed normally, offered back by the next one on
  // top of the case file they belong to; saving or closing normally removes the file.
  void autosaveIsOfferedBackAfterACrash() {
    QTemporaryDir dir;
    const QString path = dir.filePath("case.json");
    ForgetLeftAutosaves();
    {
      filmdyn::ui::MainWindow window;
      QString error;
      QVERIFY(window.saveProjectAs(path, &error));
      QVERIFY(window.autosaveNow());
      QVERIFY(!QFile::exists(window.autosavePath()));  // nothing unsaved: nothing written
      window.document()->setParameter("operating.rpm", 2468.5);
      QVERIFY2(window.autosaveNow(&error), qPrintable(error));
      QVERIFY(QFile::exists(window.autosavePath()));
      QVERIFY(!filmdyn::ui::MainWindow::hasRecovery());  // its window is alive
    }  // "crash": destroyed without a close event
    QVERIFY(filmdyn::ui::MainWindow::hasRecovery());
    {
      filmdyn::ui::MainWindow next;
      QString error, title, text;
      next.show();
      filmdyn::test::AnswerNextMessageBox(QMessageBox::Yes, &title, &text);
      next.offerRecovery();  // the question the next start asks (main.cpp), answered Yes
      QCOMPARE(title, QString("Recover unsaved edits"));
      QVERIFY2(text.contains(QDir::toNativeSeparators(path)), qPrintable(text));
      QCOMPARE(next.document()->engineCase().operating.rpm, 2468.5);
      QVERIFY(next.document()->isModified());
      QCOMPARE(next.document()->filePath(), path);
      QVERIFY(!filmdyn::ui::MainWindow::hasRecovery());
      // At once in the new window's own file; saving removes it.
      QVERIFY(QFile::exists(next.autosavePath()));
      QVERIFY(next.saveProjectAs(path, &error));
      QVERIFY(!QFile::exists(next.autosavePath()));
    }
    QVERIFY(!filmdyn::ui::MainWindow::hasRecovery());
  }

  // Two windows open at once each keep their own autosave: an idle one does not remove the
  // other's (one shared file used to be removed by whichever window had nothing unsaved). After
  // both are gone, the next start offers each, the newest first; the one restored is this
  // window's, the other waits for the next start. The one file of earlier versions is offered too.
  void windowsOpenAtOnceKeepTheirOwnAutosaves() {
    ForgetLeftAutosaves();
    QString text;
    {
      filmdyn::ui::MainWindow first;
      filmdyn::ui::MainWindow second;
      QVERIFY(first.autosavePath() != second.autosavePath());
      first.document()->setParameter("operating.rpm", 1111.0);
      QVERIFY(first.autosaveNow());
      QVERIFY(second.autosaveNow());  // nothing unsaved in the second window
      QVERIFY(QFile::exists(first.autosavePath()));
      QVERIFY(!filmdyn::ui::MainWindow::hasRecovery());
      QTest::qWait(20);  // a later modification time
      second.document()->setParameter("operating.rpm", 2222.0);
      QVERIFY(second.autosaveNow());
      QCOMPARE(filmdyn::ui::ClaimLeftAutosaves().size(), std::size_t{0});
    }  // both "crash"
    QCOMPARE(filmdyn::ui::ClaimLeftAutosaves().size(), std::size_t{2});
    {
      filmdyn::ui::MainWindow next;
      next.show();
      filmdyn::test::AnswerNextMessageBox(QMessageBox::Yes, nullptr, &text);
      next.offerRecovery();
      QVERIFY2(text.contains("1 of 2") && text.contains("a case not yet saved"), qPrintable(text));
      QCOMPARE(next.document()->engineCase().operating.rpm, 2222.0);  // the newest
      const QString message = next.statusBar()->currentMessage();
      QVERIFY2(message.contains("1 more session"), qPrintable(message));
      // While `next` lives, only the other one is left.
      QCOMPARE(filmdyn::ui::ClaimLeftAutosaves().size(), std::size_t{1});
      QTemporaryDir saved;
      QVERIFY(next.saveProjectAs(saved.filePath("case.json")));  // its own autosave gone
    }
    {
      filmdyn::ui::MainWindow later;
      later.show();
      filmdyn::test::AnswerNextMessageBox(QMessageBox::Yes);
      later.offerRecovery();
      QCOMPARE(later.document()->engineCase().operating.rpm, 1111.0);
      QCOMPARE(filmdyn::ui::ClaimLeftAutosaves().size(), std::size_t{0});
    }
    ForgetLeftAutosaves();  // `later` "crashed" with its edits

    // Earlier versions: autosave.json in the data folder, its case file in the settings.
    QTemporaryDir dir;
    const QString path = dir.filePath("case.json");
    {
      filmdyn::ui::MainWindow window;
      QVERIFY(window.saveProjectAs(path));
    }
    const QString earlier = QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
                                .filePath("autosave.json");
    filmdyn::engine::EngineCase edited;
    QVERIFY(filmdyn::ui::LoadCaseFile(path, &edited, nullptr));
    edited.operating.rpm = 3333.0;
    QVERIFY(filmdyn::ui::SaveCaseFile(edited, earlier, nullptr));
    QSettings().setValue("autosave/source", path);
    {
      filmdyn::ui::MainWindow next;
      next.show();
      filmdyn::test::AnswerNextMessageBox(QMessageBox::Yes);
      next.offerRecovery();
      QCOMPARE(next.document()->engineCase().operating.rpm, 3333.0);
      QCOMPARE(next.document()->filePath(), path);
      QVERIFY(!QFile::exists(earlier));
      QVERIFY(!QSettings().contains("autosave/source"));
    }
    ForgetLeftAutosaves();
  }

  // Across processes, as a real crash leaves it: a FilmDyn process that holds its autosave is
  // alive, and its file is nobody else's to offer or remove; once the process is killed (no
  // chance to clean up), the file is left and the next start offers it.
  void aKilledProcessLeavesItsAutosave() {
    ForgetLeftAutosaves();
    filmdyn::engine::EngineCase edited;
    QVERIFY(filmdyn::ui::LoadCaseFile({}, &edited, nullptr));
    edited.operating.rpm = 4321.0;
    int ready[2];
    QCOMPARE(pipe(ready), 0);
    const pid_t child = fork();
    QVERIFY(child >= 0);
    if (child == 0) {  // the other process: writes its autosave, then waits to be killed
      close(ready[0]);
      filmdyn::ui::AutosaveSlot slot;
      filmdyn::ui::AutosaveSlot idle;  // a second window with nothing to save: its lock only
      const char ok = slot.write(edited, {}, nullptr) ? '1' : '0';
      if (write(ready[1], &ok, 1) != 1) _exit(1);
      for (;;) pause();
    }
    close(ready[1]);
    char ok = 0;
    QCOMPARE(read(ready[0], &ok, 1), ssize_t{1});
    close(ready[0]);
    QCOMPARE(ok, '1');
    const QStringList files =
        QDir(filmdyn::ui::AutosaveFolder()).entryList({"*.json"}, QDir::Files);
    QCOMPARE(files.size(), 1);
    QVERIFY(!filmdyn::ui::MainWindow::hasRecovery());  // its process is alive
    QCOMPARE(kill(child, SIGKILL), 0);
    int status = 0;
    QCOMPARE(waitpid(child, &status, 0), child);
    {
      filmdyn::ui::MainWindow next;
      next.show();
      filmdyn::test::AnswerNextMessageBox(QMessageBox::Yes);
      next.offerRecovery();
      QCOMPARE(next.document()->engineCase().operating.rpm, 4321.0);
      QVERIFY(!QFile::exists(QDir(filmdyn::ui::AutosaveFolder()).filePath(files.front())));
      // The dead process's locks are gone too (the idle window's, which had no file, included);
      // only `next`'s own stays.
      QCOMPARE(QDir(filmdyn::ui::AutosaveFolder()).entryList({"*.lock"}, QDir::Files).size(), 1);
    }
    ForgetLeftAutosaves();
  }

  // A crash while a cell is marked invalid: the autosave holds the invalid value (a NaN, an
  // out-of-range number) beside the good edits. Recovery brings back every good edit and keeps
  // the saved value where the cell was invalid, and says which (it used to refuse the whole file
  // and the next minute's timer deleted it). A file that cannot be read at all is kept aside.
  void autosaveWithAnInvalidCellRecoversTheRest() {
    QTemporaryDir dir;
    const QString path = dir.filePath("case.json");
    ForgetLeftAutosaves();
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
      filmdyn::test::AnswerNextMessageBox(QMessageBox::Yes);
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
    ForgetLeftAutosaves();
    // Not a case file at all: the question's answer cannot recover it; it is kept aside.
    QFile broken(QDir(filmdyn::ui::AutosaveFolder()).filePath("session-broken.json"));
    QVERIFY(broken.open(QIODevice::WriteOnly));
    broken.write("{ \"geometry\": ");
    broken.close();
    {
      filmdyn::ui::MainWindow next;
      next.show();
      QString title, text;
      auto left = filmdyn::ui::ClaimLeftAutosaves();
      QCOMPARE(left.size(), std::size_t{1});
      const QString kept = filmdyn::ui::NotRecoveredPath(left.front());
      left.clear();  // released for the offer
      filmdyn::test::AnswerNextMessageBox(QMessageBox::Yes);
      filmdyn::test::AnswerNextMessageBox(QMessageBox::Ok, &title, &text);
      next.offerRecovery();
      QCOMPARE(title, QString("Cannot recover"));
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
