#pragma once
/// @file A table over parallel arrays of the case, shown in display units: a list table of the
/// case schema (CaseListTable: the skirt profile, a supply-pressure curve, the supply holes, ...;
/// headers, units and tooltips from core's fields) or arrays outside it (a cylinder-pressure
/// curve's angle and pressure). Edits become undoable document edits; the table's issue (core's
/// message) tints every row and is the tooltip.
#include <QAbstractTableModel>
#include <QStringList>
#include <functional>
#include <string>
#include <vector>

#include "core/engine/engine_case.hpp"
#include "ui/case_editor/case_parameters.hpp"

namespace filmdyn::ui {

class CaseDocument;

struct ArrayColumn {
  QString header;  ///< with unit, e.g. "y [mm]"
  double to_si = 1.0;
  /// The array in the case (nullptr when the table has no rows now, e.g. no curve selected).
  std::function<std::vector<double>*(engine::EngineCase&)> array;
  /// The schema field behind the column ("skirt.profile_y"): its tooltip explains the column;
  /// empty for arrays outside the schema (the pressure curves), which use `tip`.
  std::string field_path = {};
  QString tip = {};
};

class ArrayTableModel : public QAbstractTableModel {
  Q_OBJECT

 public:
  /// issue_key(): the validation key of this table ("pressure_curves[2]").
  ArrayTableModel(CaseDocument* document, std::vector<ArrayColumn> columns,
                  std::function<std::string()> issue_key, QString edit_name,
                  QObject* parent = nullptr);
  /// The schema's lists of `table`: one column per list (CaseListColumnTitle, its display scale
  /// and tooltip), the table's key, the fields' symbol in the undo text ("Edit skirt profile").
  ArrayTableModel(CaseDocument* document, const CaseListTable& table, QObject* parent = nullptr);

  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role) const override;
  bool setData(const QModelIndex& index, const QVariant& value, int role) override;
  Qt::ItemFlags flags(const QModelIndex& index) const override;
  QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

  /// Inserts a row after `row` (interpolated between neighbours) / removes a row; undoable.
  void insertRowAfter(int row);
  void removeRowAt(int row);
  /// Replaces every column by `si` (one list per column, in SI, all of one length) as one
  /// undoable edit named `description` (an import). False, with no undo step, when the columns
  /// hold exactly these values already or have no array now.
  bool replaceColumns(const std::vector<std::vector<double>>& si, const QString& description);
  /// The table's name in undo texts ("supply-pressure curve", "skirt profile").
  QString editName() const { return edit_name_; }
  /// Re-reads everything (the array behind the columns changed, e.g. another curve selected).
  void refresh();
  /// Core's message about this table now (empty when it is fine).
  QString issue() const;

 private:
  std::vector<double>* column(engine::EngineCase& c, int col) const;
  const std::vector<double>* column(int col) const;
  /// The column's tooltip: its schema field's (FieldToolTip) or its own `tip`; `first` (a cell's
  /// exact value) leads it when given.
  QString columnToolTip(int col, const QString& first = {}) const;

  CaseDocument* document_;
  std::vector<ArrayColumn> columns_;
  std::function<std::string()> issue_key_;
  QString edit_name_;
  int rows_ = 0;
};

}  // namespace filmdyn::ui
