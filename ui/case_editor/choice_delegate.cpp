#include "ui/case_editor/choice_delegate.hpp"

#include <QBrush>
#include <QComboBox>
#include <QPalette>
#include <QSignalBlocker>
#include <QStringList>
#include <QWheelEvent>

#include "ui/case_editor/parameter_table_model.hpp"

namespace filmdyn::ui {

namespace {

// A combo box in a table cell: the wheel changes it only when it has the focus (clicked or
// tabbed into); otherwise the wheel scrolls the table.
class CellComboBox : public QComboBox {
 public:
  using QComboBox::QComboBox;

 protected:
  void wheelEvent(QWheelEvent* event) override {
    if (hasFocus()) {
      QComboBox::wheelEvent(event);
    } else {
      event->ignore();
    }
  }
};

}  // namespace

bool ChoiceDelegate::IsChoice(const QModelIndex& index) {
  return !index.data(ParameterTableModel::kChoicesRole).toStringList().isEmpty();
}

QWidget* ChoiceDelegate::createEditor(QWidget* parent, const QStyleOptionViewItem& option,
                                      const QModelIndex& index) const {
  const QStringList choices = index.data(ParameterTableModel::kChoicesRole).toStringList();
  if (choices.isEmpty()) return QStyledItemDelegate::createEditor(parent, option, index);
  auto* combo = new CellComboBox(parent);
  combo->setObjectName(QString("choice_%1").arg(index.data(Qt::UserRole).toString()));
  combo->setFocusPolicy(Qt::StrongFocus);
  combo->setFrame(false);
  combo->addItems(choices);
  // Picking a name is the edit: commit it at once (the editor stays open).
  connect(combo, &QComboBox::activated, this,
          [this, combo] { emit const_cast<ChoiceDelegate*>(this)->commitData(combo); });
  return combo;
}

void ChoiceDelegate::setEditorData(QWidget* editor, const QModelIndex& index) const {
  auto* combo = qobject_cast<QComboBox*>(editor);
  if (combo == nullptr || !IsChoice(index)) {
    QStyledItemDelegate::setEditorData(editor, index);
    return;
  }
  QSignalBlocker block(combo);
  combo->setCurrentIndex(combo->findText(index.data(Qt::EditRole).toString()));
  combo->setToolTip(index.data(Qt::ToolTipRole).toString());
  // The row's text colour: a choice the case leaves unused is greyed like the rest of its row
  // (it stays editable, as the row's other cells do).
  QPalette palette = combo->parentWidget() ? combo->parentWidget()->palette() : QPalette();
  if (const QVariant colour = index.data(Qt::ForegroundRole); colour.canConvert<QBrush>()) {
    const QColor text = colour.value<QBrush>().color();
    palette.setColor(QPalette::Text, text);
    palette.setColor(QPalette::ButtonText, text);
    palette.setColor(QPalette::WindowText, text);
  }
  combo->setPalette(palette);
}

void ChoiceDelegate::setModelData(QWidget* editor, QAbstractItemModel* model,
                                  const QModelIndex& index) const {
  auto* combo = qobject_cast<QComboBox*>(editor);
  if (combo == nullptr || !IsChoice(index)) {
    QStyledItemDelegate::setModelData(editor, model, index);
    return;
  }
  if (combo->currentIndex() >= 0) model->setData(index, combo->currentText(), Qt::EditRole);
}

void ChoiceDelegate::initStyleOption(QStyleOptionViewItem* option, const QModelIndex& index) const {
  QStyledItemDelegate::initStyleOption(option, index);
  option->features &= ~QStyleOptionViewItem::WrapText;
  option->textElideMode = Qt::ElideLeft;
}

}  // namespace filmdyn::ui
