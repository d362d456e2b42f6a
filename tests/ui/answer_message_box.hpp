#pragma once
/// @file For the suites that answer the application's questions as a user would: the next
/// message box that offers a button is answered with it from the event loop.
#include <QAbstractButton>
#include <QApplication>
#include <QMessageBox>
#include <QString>
#include <QStringList>
#include <QTimer>

namespace filmdyn::test {

/// Answers the next modal message box that has `button` (one without it is left to another
/// answer; looked for again until it shows), keeping its title in *title, its text in *text and
/// appending its title to *titles, each when given. With FILMDYN_SCREENSHOT_DIR set, a picture of
/// every question asked is kept there (dialog-<title>.png).
inline void AnswerNextMessageBox(QMessageBox::StandardButton button, QString* title = nullptr,
                                 QString* text = nullptr, QStringList* titles = nullptr) {
  QTimer::singleShot(50, [button, title, text, titles] {
    auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
    if (!box || !box->button(button)) {
      AnswerNextMessageBox(button, title, text, titles);  // not shown yet: look again
      return;
    }
    if (title) *title = box->windowTitle();
    if (text) *text = box->text();
    if (titles) titles->append(box->windowTitle());
    if (const QString dir = qEnvironmentVariable("FILMDYN_SCREENSHOT_DIR"); !dir.isEmpty()) {
      box->grab().save(dir + "/dialog-" + box->windowTitle().toLower().replace(' ', '-') + ".png");
    }
    box->button(button)->click();
  });
}

}  // namespace filmdyn::test
