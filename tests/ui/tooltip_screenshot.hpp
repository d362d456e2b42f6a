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
/// the tooltip together to `path` and hides the tooltip again. False when the picture could not
/// be saved.
inline bool SaveCellToolTip(QAbstractItemView* view, const QRect& cell_rect, const QString& tip,
                            const QString& path) {
  QWidget* viewport = view->viewport();
  QToolTip::showText(viewport->mapToGlobal(cell_rect.center()), tip, viewport, cell_rect);
  QTest::qWait(500);
  QRect shown(viewport->mapToGlobal(cell_rect.topLeft()), cell_rect.size());
  for (QWidget* top : QApplication::topLevelWidgets())
    if (top->inherits("QTipLabel") && top->isVisible()) shown = shown.united(top->geometry());
  shown.adjust(-10, -10, 10, 10);
  const bool saved = QGuiApplication::primaryScreen()
                         ->grabWindow(0, shown.x(), shown.y(), shown.width(), shown.height())
                         .save(path);
  QToolTip::hideText();
  return saved;
}

}  // namespace filmdyn::test
