#include "ui/help/help_browser.hpp"

#include <QAction>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QPixmap>
#include <QRegularExpression>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QStyle>
#include <QTextDocument>
#include <QToolBar>
#include <QVBoxLayout>
#include <algorithm>

namespace filmdyn::ui {

namespace {

constexpr const char* kRoot = ":/docs/";

// Resource path (":/docs/gui.md") of a qrc:/docs/… URL; empty for anything else.
QString ResourcePath(const QUrl& url) {
  if (url.scheme() != "qrc") return {};
  return ":" + url.path();
}

QString PageOf(const QUrl& url) {
  const QString path = url.path();
  return path.startsWith("/docs/") ? path.mid(6) : path;
}

// The list of every page, grouped as the folder is: top-level pages first, then each subfolder.
QString IndexMarkdown() {
  QString text = QObject::tr(
      "# FilmDyn documentation\n\n"
      "Every page of the documentation that comes with this version of FilmDyn. Start with "
      "[Getting started](getting-started.md) if you are new.\n\n");
  QString folder;
  for (const QString& page : HelpBrowser::pages()) {
    const QString dir = QFileInfo(page).path();
    if (dir != "." && dir != folder) {
      folder = dir;
      // "Validation pages": not a second "Validation" under the page of that name.
      text += "\n## " + QObject::tr("%1 pages").arg(dir.left(1).toUpper() + dir.mid(1)) + "\n\n";
    }
    text += "- [" + HelpBrowser::pageTitle(page) + "](" + page + ")\n";
  }
  return text;
}

// Markdown → HTML. A page is shown as the HTML of its Markdown: QTextEdit::setMarkdown lays a
// long table out again for every row it adds (case-file.md: 4–5 s), the HTML takes 0.1 s.
QString MarkdownToHtml(const QString& markdown) {
  QTextDocument document;
  document.setMarkdown(markdown);
  // Every picture is a link to itself: a click shows it at full size (on the page it is fitted
  // to the window, its text too small to read).
  QString html = document.toHtml();
  static const QRegularExpression kImage(R"re((<img src="([^"]+)"[^>]*>))re");
  html.replace(kImage, R"re(<a href="\2">\1</a>)re");
  return html;
}

bool IsPicture(const QString& path) {
  return path.endsWith(".png", Qt::CaseInsensitive) || path.endsWith(".jpg", Qt::CaseInsensitive);
}

}  // namespace

HelpTextBrowser::HelpTextBrowser(QWidget* parent) : QTextBrowser(parent) {
  setOpenExternalLinks(true);  // http(s) links go to the system's browser
  setViewportMargins(16, 8, 16, 8);
  setSearchPaths({kRoot});
}

QVariant HelpTextBrowser::loadResource(int type, const QUrl& name) {
  const QString path = ResourcePath(name);
  if (type == QTextDocument::HtmlResource && path.endsWith(".md")) {
    if (PageOf(name) == HelpBrowser::kIndexPage && !QFile::exists(path)) {
      return MarkdownToHtml(IndexMarkdown());
    }
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return {};
    return MarkdownToHtml(QString::fromUtf8(file.readAll()));
  }
  if (type == QTextDocument::ImageResource) {
    // Screenshots are 1600 px wide: fit them to the window so a page reads without scrolling
    // sideways.
    QImage image(ResourcePath(name));
    if (!image.isNull()) {
      const int width = std::max(400, viewport()->width() - 40);
      if (image.width() > width) {
        image = image.scaledToWidth(width, Qt::SmoothTransformation);
      }
      return image;
    }
  }
  return QTextBrowser::loadResource(type, name);
}

void HelpTextBrowser::doSetSource(const QUrl& name, QTextDocument::ResourceType type) {
  const QString path = ResourcePath(name);
  if (IsPicture(path) && QFile::exists(path)) {  // a picture clicked: full size, the page stays
    showPicture(path);
    return;
  }
  const bool bundled =
      path.isEmpty() || QFile::exists(path) || PageOf(name) == HelpBrowser::kIndexPage;
  if (bundled) {
    QTextBrowser::doSetSource(name, path.endsWith(".md") ? QTextDocument::HtmlResource : type);
    return;
  }
  // A link to something that is not a page of the documentation (a source file, a folder):
  // say so on the page instead of showing nothing.
  QTextBrowser::doSetSource(HelpBrowser::pageUrl(HelpBrowser::kIndexPage),
                            QTextDocument::HtmlResource);
  setMarkdown(tr("# Not in the bundled documentation\n\n`%1` is not a page of the documentation "
                 "that comes with FilmDyn (it is part of the source code or its folders).\n\n"
                 "[All documentation](index.md)")
                  .arg(PageOf(name)));
}

QWidget* HelpTextBrowser::showPicture(const QString& path) {
  if (!picture_window_) {
    picture_window_ = new QScrollArea(this);
    picture_window_->setWindowFlag(Qt::Window);
    picture_window_->setObjectName("help_picture");
    picture_window_->setWidget(new QLabel(picture_window_));
  }
  auto* label = static_cast<QLabel*>(picture_window_->widget());
  const QPixmap pixmap(path);
  label->setPixmap(pixmap);
  label->resize(pixmap.size());
  picture_window_->setWindowTitle(QFileInfo(path).fileName());
  // The picture's size, within the screen.
  const QSize room = screen() ? screen()->availableSize() * 0.95 : pixmap.size();
  picture_window_->resize(pixmap.size().boundedTo(room) + QSize(4, 4));
  picture_window_->show();
  picture_window_->raise();
  return picture_window_;
}

HelpBrowser::HelpBrowser(QWidget* parent) : QWidget(parent, Qt::Window) {
  setObjectName("help_browser");
  setWindowTitle(tr("FilmDyn documentation"));
  resize(980, 820);
  browser_ = new HelpTextBrowser(this);
  browser_->setObjectName("help_text");
  auto* toolbar = new QToolBar(this);
  toolbar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
  back_ = toolbar->addAction(style()->standardIcon(QStyle::SP_ArrowBack), tr("Back"), browser_,
                             &QTextBrowser::backward);
  back_->setShortcut(QKeySequence::Back);
  back_->setEnabled(false);
  forward_ = toolbar->addAction(style()->standardIcon(QStyle::SP_ArrowForward), tr("Forward"),
                                browser_, &QTextBrowser::forward);
  forward_->setShortcut(QKeySequence::Forward);
  forward_->setEnabled(false);
  toolbar->addSeparator();
  toolbar->addAction(tr("Getting started"), this, [this] { showPage("getting-started.md"); });
  toolbar->addAction(style()->standardIcon(QStyle::SP_FileDialogContentsView),
                     tr("All documentation"), this, [this] { showPage(kIndexPage); });
  connect(browser_, &QTextBrowser::backwardAvailable, back_, &QAction::setEnabled);
  connect(browser_, &QTextBrowser::forwardAvailable, forward_, &QAction::setEnabled);
  connect(browser_, &QTextBrowser::sourceChanged, this, [this](const QUrl& source) {
    setWindowTitle(tr("%1 — FilmDyn documentation").arg(pageTitle(PageOf(source))));
  });
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(0);
  layout->addWidget(toolbar);
  layout->addWidget(browser_);
}

void HelpBrowser::showPage(const QString& page) {
  browser_->setSource(pageUrl(page), QTextDocument::HtmlResource);
}

QString HelpBrowser::currentPage() const { return PageOf(browser_->source()); }

QStringList HelpBrowser::pages() {
  QStringList list;
  QDirIterator it(kRoot, {"*.md"}, QDir::Files, QDirIterator::Subdirectories);
  while (it.hasNext()) list << it.next().mid(QString(kRoot).size());
  // The pages a user reads first, then the rest of the top level alphabetically, then the
  // subfolders' pages.
  static const QStringList kFirst = {"getting-started.md", "gui.md",         "case-file.md",
                                     "outputs.md",         "conventions.md", "skirt-calculator.md",
                                     "validation.md"};
  auto rank = [](const QString& page) {
    const qsizetype first = kFirst.indexOf(page);
    return first >= 0           ? int(first)
           : page.contains('/') ? int(kFirst.size()) + 1
                                : int(kFirst.size());
  };
  std::sort(list.begin(), list.end(), [&rank](const QString& a, const QString& b) {
    return rank(a) != rank(b) ? rank(a) < rank(b) : a < b;
  });
  return list;
}

QString HelpBrowser::pageTitle(const QString& page) {
  if (page == kIndexPage && !QFile::exists(kRoot + page)) return tr("All documentation");
  QFile file(kRoot + page);
  if (file.open(QIODevice::ReadOnly | QIODevice::Text)) {
    while (!file.atEnd()) {
      const QString line = QString::fromUtf8(file.readLine()).trimmed();
      if (line.startsWith("# ")) return line.mid(2).trimmed();
    }
  }
  return QFileInfo(page).completeBaseName();
}

QUrl HelpBrowser::pageUrl(const QString& page) {
  QUrl url("qrc:/docs/" + page.section('#', 0, 0));
  if (page.contains('#')) url.setFragment(page.section('#', 1));
  return url;
}

HelpBrowser* ShowHelp(QWidget* parent, const QString& page) {
  auto* help = parent ? parent->findChild<HelpBrowser*>("help_browser", Qt::FindDirectChildrenOnly)
                      : nullptr;
  if (!help) help = new HelpBrowser(parent);
  help->showPage(page);
  help->show();
  help->raise();
  help->activateWindow();
  return help;
}

}  // namespace filmdyn::ui
