#pragma once
// Helpers the case-editor suites share: typing into a table cell like a user and finding a list
// block's buttons.
#include <QLineEdit>
#include <QPushButton>
#include <QTableView>
#include <QtTest>
#include <string>

#include "ui/case_editor/case_editor.hpp"
#include "ui/case_editor/case_parameters.hpp"
#include "ui/main_window.hpp"

namespace editor_test {

// Opens the cell's editor like a user (select the cell, start editing) and, with `text` given,
// checks it starts with `expected` (when not null), replaces its text by `text`; then presses
// Enter and waits for the commit.
inline void EditCell(QTableView* table, const QModelIndex& index, const QString* text,
                     const QString* expected) {
  QWidget* window = table->window();
  window->activateWindow();
  table->setFocus();
  table->setCurrentIndex(index);
  table->edit(index);
  // The delegate's editor is a QLineEdit child of the viewport.
  QLineEdit* editor = table->viewport()->findChild<QLineEdit*>();
  QVERIFY2(editor != nullptr, "no line editor opened on the cell");
  if (expected) QCOMPARE(editor->text(), *expected);
  if (text) {
    editor->selectAll();
    QTest::keyClicks(editor, *text);
  }
  QTest::keyClick(editor, Qt::Key_Return);
  // The delegate commits on a queued call after Return.
  QTRY_VERIFY(table->viewport()->findChild<QLineEdit*>() == nullptr ||
              !table->viewport()->findChild<QLineEdit*>()->isVisible());
}

// Types `text` into the cell like a user: select it, start editing, type, press Enter.
inline void TypeIntoCell(QTableView* table, const QModelIndex& index, const QString& text) {
  EditCell(table, index, &text, nullptr);
}

// Opens the cell's editor, checks it starts with `expected` and leaves it with Return, unchanged
// (what tabbing through a table does).
inline void OpenAndLeaveCell(QTableView* table, const QModelIndex& index, const QString& expected) {
  EditCell(table, index, nullptr, &expected);
}

// The list block's button ("insert", "remove", "import", "export") of the table with a column
// at `path`.
inline QPushButton* ListButton(filmdyn::ui::MainWindow& window, const std::string& path,
                               const char* which) {
  const filmdyn::ui::CaseListTable* list = filmdyn::ui::FindCaseListTable(path);
  if (list == nullptr) return nullptr;
  return window.caseEditor()->findChild<QPushButton*>(QString::fromStdString(list->key) + "_" +
                                                      which);
}

}  // namespace editor_test
