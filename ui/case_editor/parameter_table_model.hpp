#pragma once
/// @file One group of scalar case parameters as an editable table: Quantity | Value | Unit | Note.
/// Values are shown in display units; an invalid value is kept (never lose an edit), its row is
/// tinted and the reason (core's InputError message) is the tooltip. A choice row's value is the
/// chosen name, edited with a combo box of core's choices (ChoiceDelegate, kChoicesRole).
#include <QAbstractTableModel>
#include <vector>

#include "ui/case_editor/case_parameters.hpp"

namespace filmdyn::ui {

class CaseDocument;

class ParameterTableModel : public QAbstractTableModel {
  Q_OBJECT

 public:
  enum Column { kQuantity, kValue, kUnit, kNote, kColumnCount };
  /// The value cell of a choice row: its allowed names (QStringList); empty for other rows.
  static constexpr int kChoicesRole = Qt::UserRole + 1;

  ParameterTableModel(CaseDocument* document, CaseGroup group, QObject* parent = nullptr);

  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role) const override;
  bool setData(const QModelIndex& index, const QVariant& value, int role) override;
  Qt::ItemFlags flags(const QModelIndex& index) const override;
  QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

  /// Row of a dotted path in this table, or -1.
  int rowOf(const std::string& path) const;
  const CaseParameter& parameter(int row) const { return *rows_[size_t(row)]; }

 signals:
  /// An edit left undone, and why (a whole-number field given a fraction): for the status bar.
  void editRefused(const QString& message);

 private:
  /// The chosen name of a choice row ("(invalid)" for an index outside its choices).
  QString choiceText(const CaseParameter& p) const;

  CaseDocument* document_;
  std::vector<const CaseParameter*> rows_;
};

/// Parses a number typed by the user ("1.5", "1,5" in a comma locale, "1e-3"); NaN if none.
double ParseUserNumber(const QString& text);
/// Formats a display value with 6 significant digits ("" for NaN).
QString FormatDisplayNumber(double value);
/// A display value as a cell's editor starts with it: 15 significant digits (all a decimal
/// keeps through a double; the cell shows six), so that the editor shows the value as typed or
/// read from the file, not a rounding of it.
QString FormatEditNumber(double display);
/// Whether `text`, committed from the editor of a cell showing `display`, is the number the
/// editor started with: the cell was left unchanged, and the stored value is kept to the bit.
bool SameEditNumber(const QString& text, double display);

}  // namespace filmdyn::ui
