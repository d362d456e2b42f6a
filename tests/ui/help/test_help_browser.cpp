// The documentation inside the application: the Help menu lists the pages, a page opens in the
// help window from the bundled copy of docs/, a relative link clicked with the mouse opens the
// page it names, Back returns, pictures load (fitted to the window), the list of all pages names
// every page, and a link outside the documentation says so instead of showing nothing.
#include <QAction>
#include <QImage>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QScrollArea>
#include <QSettings>
#include <QStandardPaths>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextDocument>
#include <QtTest>

#include "ui/help/help_browser.hpp"
#include "ui/main_window.hpp"

using filmdyn::ui::HelpBrowser;

namespace {

// The first link in the page whose target is `href`, as a position in the document; -1 if none.
int LinkPosition(const QTextDocument* document, const QString& href) {
  for (QTextBlock block = document->begin(); block.isValid(); block = block.next()) {
    for (auto it = block.begin(); !it.atEnd(); ++it) {
      const QTextFragment fragment = it.fragment();
      if (fragment.charFormat().isAnchor() && fragment.charFormat().anchorHref() == href) {
        return fragment.position();
      }
    }
  }
  return -1;
}

// Clicks the link at `position` like a user: a mouse press and release over its text.
void ClickLink(QTextBrowser* browser, int position) {
  QTextCursor cursor(browser->document());
  cursor.setPosition(position + 1);
  browser->setTextCursor(cursor);
  browser->ensureCursorVisible();
  const QPoint at = browser->cursorRect(cursor).center() - QPoint(2, 0);
  QTest::mouseClick(browser->viewport(), Qt::LeftButton, {}, at);
}

void SaveScreenshot(QWidget* window, const QString& name) {
  if (const QString dir = qEnvironmentVariable("FILMDYN_SCREENSHOT_DIR"); !dir.isEmpty()) {
    QVERIFY(window->grab().save(dir + "/" + name + ".png"));
  }
}

}  // namespace

class TestHelpBrowser : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName("FilmDynTest");
    QCoreApplication::setApplicationName("test_help");
    QSettings().clear();
  }

  void helpMenuOpensThePagesInTheApplication() {
    filmdyn::ui::MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QMenu* help = nullptr;
    for (QAction* action : window.menuBar()->actions()) {
      if (action->text() == "&Help") help = action->menu();
    }
    QVERIFY(help != nullptr);
    QStringList texts;
    for (QAction* action : help->actions()) {
      if (!action->isSeparator()) texts << action->text().remove('&');
    }
    QCOMPARE(texts, QStringList({"Getting started", "User guide", "Sign conventions", "Case fields",
                                 "Outputs", "All documentation…", "About FilmDyn"}));

    // Sign conventions: the page of docs/conventions.md, in a window of the application.
    auto* conventions = help->findChild<QAction*>("help_conventions");
    QVERIFY(conventions != nullptr);
    conventions->trigger();
    auto* browser_window = window.findChild<HelpBrowser*>("help_browser");
    QVERIFY(browser_window != nullptr);
    QVERIFY(QTest::qWaitForWindowExposed(browser_window));
    QCOMPARE(browser_window->currentPage(), QString("conventions.md"));
    const QString text = browser_window->browser()->toPlainText();
    QVERIFY2(text.contains("Frames and sign conventions"), qPrintable(text.left(300)));
    QVERIFY(text.contains("Piston skirt"));
    QVERIFY2(browser_window->windowTitle().startsWith("Conventions"),
             qPrintable(browser_window->windowTitle()));

    // Each menu entry opens its page in the same window.
    const QList<QPair<QString, QString>> entries = {{"help_getting_started", "getting-started.md"},
                                                    {"help_user_guide", "gui.md"},
                                                    {"help_case_fields", "case-file.md"},
                                                    {"help_outputs", "outputs.md"},
                                                    {"help_all", HelpBrowser::kIndexPage}};
    for (const auto& [name, page] : entries) {
      help->findChild<QAction*>(name)->trigger();
      QCOMPARE(window.findChildren<HelpBrowser*>().size(), qsizetype(1));
      QCOMPARE(browser_window->currentPage(), page);
      QVERIFY2(browser_window->browser()->toPlainText().size() > 200, qPrintable(page));
    }
  }

  void relativeLinksPicturesAndHistory() {
    HelpBrowser help;
    help.resize(1000, 800);
    help.show();
    QVERIFY(QTest::qWaitForWindowExposed(&help));
    help.showPage("getting-started.md");
    QTextBrowser* browser = help.browser();
    QVERIFY(browser->toPlainText().contains("Getting started"));
    SaveScreenshot(&help, "help_getting_started");

    // A relative link to the user guide, clicked with the mouse, opens that page.
    const int link = LinkPosition(browser->document(), "gui.md");
    QVERIFY2(link >= 0, "getting-started.md links to gui.md");
    ClickLink(browser, link);
    QTRY_COMPARE(help.currentPage(), QString("gui.md"));
    QVERIFY(browser->toPlainText().contains("The FilmDyn desktop application"));
    QVERIFY(help.windowTitle().startsWith("The FilmDyn desktop application"));
    // Back returns to where the link was, Forward goes again.
    browser->backward();
    QCOMPARE(help.currentPage(), QString("getting-started.md"));
    browser->forward();
    QCOMPARE(help.currentPage(), QString("gui.md"));

    // Pictures come from the bundled screenshots, fitted to the window.
    const QVariant picture = browser->loadResource(
        QTextDocument::ImageResource, HelpBrowser::pageUrl("screenshots/run_results_coupled.png"));
    const QImage image = picture.value<QImage>();
    QVERIFY(!image.isNull());
    QVERIFY2(image.width() <= browser->viewport()->width(),
             qPrintable(QString::number(image.width())));

    // A picture is a link to itself: a click (QTextBrowser resolves the link and sets it as the
    // source) shows it at full size in a window of its own, and the page stays.
    help.showPage("gui.md");
    const int picture_link =
        LinkPosition(browser->document(), "screenshots/run_table_identity.png");
    QVERIFY2(picture_link >= 0, "gui.md's embedded screenshot links to itself");
    browser->setSource(browser->source().resolved(QUrl("screenshots/run_table_identity.png")));
    QCOMPARE(help.currentPage(), QString("gui.md"));
    auto* full_size = help.findChild<QScrollArea*>("help_picture");
    QVERIFY(full_size != nullptr && full_size->isVisible());
    const auto* label = qobject_cast<QLabel*>(full_size->widget());
    QVERIFY(label != nullptr);
    QCOMPARE(label->pixmap().size(), QImage(":/docs/screenshots/run_table_identity.png").size());
    full_size->close();

    // The list of all pages links every bundled page, subfolders included.
    const QStringList pages = HelpBrowser::pages();
    QVERIFY(pages.contains("getting-started.md"));
    QVERIFY(pages.contains("conventions.md"));
    QVERIFY(pages.contains("validation/errors.md"));
    help.showPage(HelpBrowser::kIndexPage);
    for (const QString& page : pages) {
      QVERIFY2(LinkPosition(browser->document(), page) >= 0, qPrintable(page));
    }
    QCOMPARE(HelpBrowser::pageTitle("conventions.md"), QString("Conventions"));
    // A subfolder's heading is not read as a second page of its name ("Validation").
    QVERIFY(browser->toPlainText().contains("Validation pages"));
    SaveScreenshot(&help, "help_all_documentation");

    // A link into the source tree is not a page of the documentation: the window says so.
    help.showPage("../core/engine/case_schema.cpp");
    QVERIFY(browser->toPlainText().contains("Not in the bundled documentation"));
  }
};

QTEST_MAIN(TestHelpBrowser)
#include "test_help_browser.moc"
