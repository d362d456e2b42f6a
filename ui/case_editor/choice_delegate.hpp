#pragma once
/// @file The value column of the parameter tables: a combo box of core's choices for a choice row
/// (ParameterTableModel::kChoicesRole), the usual line editor for a number. A choice takes effect
/// as soon as it is picked (one undoable edit); the combo's tooltip is the cell's (what the input
/// is, or core's reason for a bad value). Scrolling the table over a combo that does not have
/// the focus scrolls the table and never changes the choice.
#include <QStyledItemDelegate>

namespace filmdyn::ui {

class ChoiceDelegate : public QStyledItemDelegate {
  Q_OBJECT

 public:
  using QStyledItemDelegate::QStyledItemDelegate;

  /// Whether the cell is a choice (its editor is a combo box, open all the time).
  static bool IsChoice(const QModelIndex& index);

  QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem& option,
                        const QModelIndex& index) const override;
  void setEditorData(QWidget* editor, const QModelIndex& index) const override;
  void setModelData(QWidget* editor, QAbstractItemModel* model,
                    const QModelIndex& index) const override;

 protected:
  /// One line, elided on the left: a file name too long for the cell keeps its own name.
  void initStyleOption(QStyleOptionViewItem* option, const QModelIndex& index) const override;
};

}  // namespace filmdyn::ui
