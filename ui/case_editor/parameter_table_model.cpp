#include "ui/case_editor/parameter_table_model.hpp"

#include <QBrush>
#include <QColor>
#include <QLocale>
#include <QStringList>
#include <cmath>
#include <limits>

#include "ui/case_editor/case_document.hpp"
#include "ui/case_editor/field_tooltip.hpp"

namespace filmdyn::ui {

double ParseUserNumber(const QString& text) {
  bool ok = false;
  const QString trimmed = text.trimmed();
  // '.' as the decimal point first, without thousands separators: the C locale would read
  // "1,125" as 1125, where a user of a decimal-comma locale means 1.125 (read next).
  QLocale point = QLocale::c();
  point.setNumberOptions(QLocale::RejectGroupSeparator);
  double v = point.toDouble(trimmed, &ok);
  if (!ok) v = QLocale().toDouble(trimmed, &ok);
  return ok ? v : std::numeric_limits<double>::quiet_NaN();
}

QString FormatDisplayNumber(double value) {
  if (std::isnan(value)) return {};
  return QLocale::c().toString(value, 'g', 6);
}

QString FormatEditNumber(double display) {
  if (std::isnan(display)) return {};
  return QLocale::c().toString(display, 'g', 15);
}

bool SameEditNumber(const QString& text, double display) {
  const double typed = ParseUserNumber(text), start = ParseUserNumber(FormatEditNumber(display));
  return typed == start || (std::isnan(typed) && std::isnan(start));
}

namespace {
// A text parameter's value. The field's accessor hands out the member for editing; it is only
// read here.
std::string TextOf(const CaseParameter& p, const engine::EngineCase& engine_case) {
  return p.field->text(const_cast<engine::EngineCase&>(engine_case));
}
}  // namespace

ParameterTableModel::ParameterTableModel(CaseDocument* document, CaseGroup group, QObject* parent)
    : QAbstractTableModel(parent), document_(document) {
  for (const CaseParameter& p : CaseParameters()) {
    if (p.group == group) rows_.push_back(&p);
  }
  connect(document_, &CaseDocument::caseChanged, this, [this] {
    if (!rows_.empty()) emit dataChanged(index(0, 0), index(rowCount() - 1, kColumnCount - 1));
  });
}

int ParameterTableModel::rowCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : int(rows_.size());
}

int ParameterTableModel::columnCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : kColumnCount;
}

int ParameterTableModel::rowOf(const std::string& path) const {
  for (size_t i = 0; i < rows_.size(); ++i) {
    if (rows_[i]->path == path) return int(i);
  }
  return -1;
}

QVariant ParameterTableModel::data(const QModelIndex& index, int role) const {
  if (!index.isValid()) return {};
  const CaseParameter& p = *rows_[size_t(index.row())];
  const auto& issues = document_->issues();
  const auto issue = issues.find(p.path);
  const bool bad = issue != issues.end();
  const auto assumed = document_->engineCase().assumed.find(p.path);
  switch (role) {
    case Qt::DisplayRole:
    case Qt::EditRole:
      switch (index.column()) {
        case kQuantity:
          return p.label;
        case kValue: {
          if (p.choice) return choiceText(p);
          if (p.text) return QString::fromStdString(TextOf(p, document_->engineCase()));
          const double display = engine::ScaleToDisplay(p.get(document_->engineCase()), p.to_si);
          if (role == Qt::EditRole) return FormatEditNumber(display);
          return bad && std::isnan(display) ? tr("(invalid)") : FormatDisplayNumber(display);
        }
        case kUnit:
          return p.unit;
        case kNote:
          if (bad) return QString::fromStdString(issue->second);
          // Unused first: where it was assumed matters only once the field is read.
          if (const std::string unused = engine::UnusedReason(document_->engineCase(), p.path,
                                                              engine::ChoiceWording::kTitles);
              !unused.empty()) {
            return tr("not used: %1").arg(QString::fromStdString(unused));
          }
          if (assumed != document_->engineCase().assumed.end()) {
            return tr("assumed: %1").arg(QString::fromStdString(assumed->second));
          }
          return QString::fromStdString(engine::DerivedNote(document_->engineCase(), p.path));
      }
      break;
    case Qt::ToolTipRole:
      // A bad cell: core's reason (also shown in the status bar); otherwise what the input is.
      if (bad) return QString::fromStdString(issue->second);
      // The cell's whole text first where the cell may elide it: a text value, a note (a narrow
      // table).
      if (p.text && index.column() == kValue)
        return FieldToolTip(*p.field, QString::fromStdString(TextOf(p, document_->engineCase())));
      if (index.column() == kNote)
        return FieldToolTip(*p.field, data(index, Qt::DisplayRole).toString());
      // A number the display rounds: its exact value first.
      if (index.column() == kValue && !p.choice && !p.text) {
        const double display = engine::ScaleToDisplay(p.get(document_->engineCase()), p.to_si);
        if (const QString exact = FormatEditNumber(display); exact != FormatDisplayNumber(display))
          return FieldToolTip(*p.field, tr("%1 %2 (shown rounded)").arg(exact, p.unit).trimmed());
      }
      return FieldToolTip(*p.field);
    case Qt::BackgroundRole:
      if (bad) return QBrush(QColor(255, 205, 205));
      break;
    case Qt::ForegroundRole:
      if (bad && index.column() == kNote) return QBrush(QColor(170, 0, 0));
      // A field the case's choices leave unused: greyed, the reason in the note column.
      if (!bad && !engine::UnusedReason(document_->engineCase(), p.path).empty())
        return QBrush(QColor(150, 150, 150));
      break;
    case Qt::TextAlignmentRole:
      if (index.column() == kValue && !p.choice && !p.text)
        return int(Qt::AlignRight | Qt::AlignVCenter);
      break;
    case Qt::UserRole:
      return QString::fromStdString(p.path);
    case kChoicesRole:
      if (p.choice && index.column() == kValue) {
        QStringList titles;  // as the GUI shows them (CaseField::ChoiceTitle)
        for (std::size_t k = 0; k < p.field->choices.size(); ++k)
          titles << QString::fromStdString(p.field->ChoiceTitle(k));
        return titles;
      }
      break;
  }
  return {};
}

QString ParameterTableModel::choiceText(const CaseParameter& p) const {
  const int k = p.field->choice(document_->engineCase());
  if (k < 0 || k >= int(p.field->choices.size())) return tr("(invalid)");
  return QString::fromStdString(p.field->ChoiceTitle(size_t(k)));
}

bool ParameterTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
  if (role != Qt::EditRole || index.column() != kValue) return false;
  const CaseParameter& p = *rows_[size_t(index.row())];
  if (p.choice) {
    // One of core's choices by its title (what the combo box offers) or name; anything else
    // changes nothing.
    const int k = p.field->ChoiceIndex(value.toString().toStdString());
    if (k < 0) return false;
    if (k == p.field->choice(document_->engineCase())) return true;
    return document_->setChoice(p.path, p.field->choices[size_t(k)]);
  }
  if (p.text) return document_->setText(p.path, value.toString().toStdString());
  // Left as it was: no change (the stored value kept to the bit), no empty undo step.
  if (SameEditNumber(value.toString(),
                     engine::ScaleToDisplay(p.get(document_->engineCase()), p.to_si)))
    return true;
  const double typed = ParseUserNumber(value.toString());
  if (p.integer && std::isfinite(typed) && typed != std::round(typed)) {
    // Core would round it (a mesh count of 40.6 stored as 41): the user says which.
    emit editRefused(tr("%1: %2 is not a whole number; the value stays %3")
                         .arg(p.label, value.toString().trimmed(),
                              FormatDisplayNumber(engine::ScaleToDisplay(
                                  p.get(document_->engineCase()), p.to_si))));
    return false;
  }
  document_->setParameter(p.path, engine::ScaleFromDisplay(typed, p.to_si));
  return true;
}

Qt::ItemFlags ParameterTableModel::flags(const QModelIndex& index) const {
  Qt::ItemFlags f = QAbstractTableModel::flags(index);
  if (index.column() == kValue) f |= Qt::ItemIsEditable;
  return f;
}

QVariant ParameterTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
  if (role != Qt::DisplayRole || orientation != Qt::Horizontal) return {};
  switch (section) {
    case kQuantity:
      return tr("Quantity");
    case kValue:
      return tr("Value");
    case kUnit:
      return tr("Unit");
    case kNote:
      return tr("Note");
  }
  return {};
}

}  // namespace filmdyn::ui
