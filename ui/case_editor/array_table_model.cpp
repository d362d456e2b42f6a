#include "ui/case_editor/array_table_model.hpp"

#include <QBrush>
#include <QColor>
#include <algorithm>
#include <cmath>

#include "core/engine/case_schema.hpp"
#include "ui/case_editor/case_document.hpp"
#include "ui/case_editor/field_tooltip.hpp"
#include "ui/case_editor/parameter_table_model.hpp"

namespace filmdyn::ui {

ArrayTableModel::ArrayTableModel(CaseDocument* document, std::vector<ArrayColumn> columns,
                                 std::function<std::string()> issue_key, QString edit_name,
                                 QObject* parent)
    : QAbstractTableModel(parent),
      document_(document),
      columns_(std::move(columns)),
      issue_key_(std::move(issue_key)),
      edit_name_(std::move(edit_name)) {
  connect(document_, &CaseDocument::caseChanged, this, &ArrayTableModel::refresh);
  refresh();
}

namespace {

std::vector<ArrayColumn> SchemaColumns(const CaseListTable& table) {
  std::vector<ArrayColumn> columns;
  for (const engine::CaseField* field : table.columns) {
    columns.push_back({CaseListColumnTitle(*field), field->display_scale,
                       [field](engine::EngineCase& c) { return &field->list(c); }, field->path});
  }
  return columns;
}

}  // namespace

ArrayTableModel::ArrayTableModel(CaseDocument* document, const CaseListTable& table,
                                 QObject* parent)
    : ArrayTableModel(
          document, SchemaColumns(table), [key = table.key] { return key; },
          table.columns.front()->symbol.empty()
              ? table.title.toLower()
              : QString::fromStdString(table.columns.front()->symbol),
          parent) {}

QString ArrayTableModel::issue() const {
  const auto& issues = document_->issues();
  const auto issue = issues.find(issue_key_());
  return issue == issues.end() ? QString() : QString::fromStdString(issue->second);
}

std::vector<double>* ArrayTableModel::column(engine::EngineCase& c, int col) const {
  return columns_[size_t(col)].array(c);
}

const std::vector<double>* ArrayTableModel::column(int col) const {
  // The accessor takes a mutable case; it only locates the array.
  auto& c = const_cast<engine::EngineCase&>(document_->engineCase());
  return columns_[size_t(col)].array(c);
}

void ArrayTableModel::refresh() {
  const std::vector<double>* first = column(0);
  const int rows = first ? int(first->size()) : 0;
  if (rows != rows_) {
    beginResetModel();
    rows_ = rows;
    endResetModel();
  } else if (rows_ > 0) {
    emit dataChanged(index(0, 0), index(rows_ - 1, columnCount() - 1));
  }
}

int ArrayTableModel::rowCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : rows_;
}

int ArrayTableModel::columnCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : int(columns_.size());
}

QVariant ArrayTableModel::data(const QModelIndex& index, int role) const {
  if (!index.isValid()) return {};
  const std::vector<double>* values = column(index.column());
  const auto& issues = document_->issues();
  const auto issue = issues.find(issue_key_());
  const bool bad = issue != issues.end();
  const bool in_table = values && index.row() < int(values->size());
  const double display = in_table ? engine::ScaleToDisplay((*values)[size_t(index.row())],
                                                           columns_[size_t(index.column())].to_si)
                                  : 0.0;
  if (role == Qt::DisplayRole || role == Qt::EditRole) {
    if (!in_table) return {};
    // The editor starts with the exact value (FormatEditNumber); the cell shows it rounded.
    return role == Qt::EditRole ? FormatEditNumber(display) : FormatDisplayNumber(display);
  }
  if (role == Qt::ToolTipRole) {
    if (bad) return QString::fromStdString(issue->second);
    if (in_table) {
      if (const QString exact = FormatEditNumber(display); exact != FormatDisplayNumber(display))
        return columnToolTip(index.column(), tr("%1 (shown rounded)").arg(exact));
    }
    return columnToolTip(index.column());
  }
  if (role == Qt::BackgroundRole && bad) return QBrush(QColor(255, 225, 225));
  if (role == Qt::TextAlignmentRole) return int(Qt::AlignRight | Qt::AlignVCenter);
  return {};
}

bool ArrayTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
  if (role != Qt::EditRole || !index.isValid()) return false;
  engine::EngineCase next = document_->engineCase();
  std::vector<double>* values = column(next, index.column());
  if (!values || index.row() >= int(values->size())) return false;
  const double to_si = columns_[size_t(index.column())].to_si;
  const double old = (*values)[size_t(index.row())];
  // Left as it was: no change (the stored value kept to the bit), no empty undo step.
  if (SameEditNumber(value.toString(), engine::ScaleToDisplay(old, to_si))) return true;
  const double si = engine::ScaleFromDisplay(ParseUserNumber(value.toString()), to_si);
  (*values)[size_t(index.row())] = si;
  document_->edit(next, tr("Edit %1").arg(edit_name_));
  return true;
}

Qt::ItemFlags ArrayTableModel::flags(const QModelIndex& index) const {
  return QAbstractTableModel::flags(index) | Qt::ItemIsEditable;
}

QString ArrayTableModel::columnToolTip(int col, const QString& first) const {
  const ArrayColumn& c = columns_[size_t(col)];
  if (const engine::CaseField* field = engine::FindCaseField(c.field_path)) {
    return FieldToolTip(*field, first);
  }
  return first.isEmpty() ? c.tip : first + "\n" + c.tip;
}

QVariant ArrayTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
  if (role == Qt::ToolTipRole && orientation == Qt::Horizontal) return columnToolTip(section);
  if (role != Qt::DisplayRole) return {};
  if (orientation == Qt::Horizontal) return columns_[size_t(section)].header;
  return section + 1;
}

void ArrayTableModel::insertRowAfter(int row) {
  engine::EngineCase next = document_->engineCase();
  for (int col = 0; col < columnCount(); ++col) {
    std::vector<double>* v = column(next, col);
    if (!v) return;
    const int n = int(v->size());
    const int at = std::clamp(row + 1, 0, n);
    double value = 0.0;
    if (n > 0 && at > 0 && at < n)
      value = 0.5 * ((*v)[size_t(at - 1)] + (*v)[size_t(at)]);
    else if (n > 0)
      value = (*v)[size_t(at > 0 ? at - 1 : 0)];
    v->insert(v->begin() + at, value);
  }
  document_->edit(next, tr("Insert %1 row").arg(edit_name_));
}

void ArrayTableModel::removeRowAt(int row) {
  engine::EngineCase next = document_->engineCase();
  for (int col = 0; col < columnCount(); ++col) {
    std::vector<double>* v = column(next, col);
    if (!v || row < 0 || row >= int(v->size())) return;
    v->erase(v->begin() + row);
  }
  document_->edit(next, tr("Remove %1 row").arg(edit_name_));
}

bool ArrayTableModel::replaceColumns(const std::vector<std::vector<double>>& si,
                                     const QString& description) {
  if (int(si.size()) != columnCount()) return false;
  engine::EngineCase next = document_->engineCase();
  bool changed = false;
  for (int col = 0; col < columnCount(); ++col) {
    std::vector<double>* v = column(next, col);
    if (!v) return false;
    changed = changed || *v != si[size_t(col)];
    *v = si[size_t(col)];
  }
  if (!changed) return false;
  document_->edit(next, description);
  return true;
}

}  // namespace filmdyn::ui
