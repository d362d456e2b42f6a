#pragma once
/// @file The documentation inside the application: the pages of docs/ (Markdown, bundled as Qt
/// resources under :/docs, so they work offline and match the program) shown in a window with a
/// QTextBrowser — relative links between pages, pictures from docs/screenshots, back and forward,
/// and a generated list of every page ("All documentation").
#include <QScrollArea>
#include <QString>
#include <QStringList>
#include <QTextBrowser>
#include <QUrl>
#include <QWidget>

class QAction;

namespace filmdyn::ui {

/// The text browser of the help window: reads pages from the bundled documentation, makes up the
/// list of all pages, fits wide pictures to the window, and explains a link to a page that is not
/// bundled instead of showing an empty page.
class HelpTextBrowser : public QTextBrowser {
  Q_OBJECT

 public:
  explicit HelpTextBrowser(QWidget* parent = nullptr);
  QVariant loadResource(int type, const QUrl& name) override;
  /// Shows a bundled picture (":/docs/screenshots/…png") at full size in a window of its own
  /// (one, reused); what a click on a page's picture does. Returns that window.
  QWidget* showPicture(const QString& resource_path);

 protected:
  void doSetSource(const QUrl& name, QTextDocument::ResourceType type) override;

 private:
  QScrollArea* picture_window_ = nullptr;
};

class HelpBrowser : public QWidget {
  Q_OBJECT

 public:
  /// The list of every page (generated; not a file of docs/).
  static constexpr const char* kIndexPage = "index.md";

  explicit HelpBrowser(QWidget* parent = nullptr);

  /// Shows a page by its path under docs/ ("gui.md", "validation/errors.md", kIndexPage),
  /// optionally with an anchor ("outputs.md#columns").
  void showPage(const QString& page);
  /// The page shown, as a path under docs/ ("conventions.md"), without the anchor.
  QString currentPage() const;
  HelpTextBrowser* browser() const { return browser_; }

  /// Every bundled page, as paths under docs/, sorted ("case-file.md", "validation/errors.md").
  static QStringList pages();
  /// The page's title: its first "# " heading, or its file name.
  static QString pageTitle(const QString& page);
  /// qrc:/docs/<page>
  static QUrl pageUrl(const QString& page);

 private:
  HelpTextBrowser* browser_;
  QAction* back_;
  QAction* forward_;
};

/// Shows `page` in the help window of `parent` (created on first use, one per parent window) and
/// raises it; returns the window.
HelpBrowser* ShowHelp(QWidget* parent, const QString& page);

}  // namespace filmdyn::ui
