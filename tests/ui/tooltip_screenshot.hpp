#pragma once
/// @file For the suites that keep screenshots for review (FILMDYN_SCREENSHOT_DIR): a table cell
/// with its tooltip shown, cut from the screen as a user sees it.
#include <QAbstractItemView>
#include <QApplication>
#include <QGuiApplication>
#include <QRect>
#include <QScreen>
#include <QString>
#include <QTest>
#include <QToolTip>
#include <QWidget>

namespace filmdyn::test {

/// Shows `tip` over the cell at `cell_rect` (viewport coordinates) of `view`, saves the cell and
/// the tooltip together to `path` and hides the tooltip again. False when the tooltip did not
/// show or the picture could not be saved.
inline bool SaveCellToolTip(QAbstractItemView* view, const QRect& cell_rect, const QString& tip,
                            const QString& path) {
  QWidget* viewport = view->viewport();
  QRect shown(viewport->mapToGlobal(cell_rect.topLeft()), cell_rect.size());
  // A focus or activation event still queued (a page just switched) hides a tooltip shown
  // before it: the events are let through first, and the tip shown again if one hid it.
  bool tip_shown = false;
  for (int attempt = 0; attempt < 5 && !tip_shown; ++attempt) {
    QTest::qWait(200);
    QToolTip::showText(viewport->mapToGlobal(cell_rect.center()), tip, viewport, cell_rect);
    QTest::qWait(200);
    for (QWidget* top : QApplication::topLevelWidgets()) {
      if (top->inherits("QTipLabel") && top->isVisible()) {
        shown = shown.united(top->geometry());
        tip_shown = true;
      }
    }
  }
  if (!tip_shown) return false;  // a picture of the cell alone would pass for one of its tip
  shown.adjust(-10, -10, 10, 10);
  const bool saved = QGuiApplication::primaryScreen()
                         ->grabWindow(0, shown.x(), shown.y(), shown.width(), shown.height())
                         .save(path);
  QToolTip::hideText();
  return saved;
}

}  // namespace filmdyn::test
