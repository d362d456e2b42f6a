#pragma once
/// @file The case editor: one tab per group of scalar inputs (tables with units; a choice such as
/// a joint's cavitation model as a combo box of core's names in its row), the schema's number
/// lists below them (CaseListTable: one table per list or pair of lists, a pair with its chart;
/// the skirt profile and ovality beside the skirt's inputs) and the cylinder-pressure curves per
/// speed (table + chart, CSV import and export), with the steady skirt calculator on the skirt
/// tab. All edits go through the CaseDocument (undo, validation).
#include <QWidget>
#include <map>
#include <string>

#include "ui/case_editor/case_parameters.hpp"

class QComboBox;
class QLabel;
class QTableView;
class QTabWidget;
class QLineSeries;
QT_BEGIN_NAMESPACE
class QChart;
QT_END_NAMESPACE

namespace filmdyn::ui {

class CaseDocument;
class ArrayTableModel;
class ParameterTableModel;
class SkirtCalculatorPanel;

class CaseEditor : public QWidget {
  Q_OBJECT

 public:
  explicit CaseEditor(CaseDocument* document, QWidget* parent = nullptr);

  QTableView* parameterTable(CaseGroup group) const { return tables_.at(group); }
  ParameterTableModel* parameterModel(CaseGroup group) const { return models_.at(group); }
  /// The list table (CaseListTable) with a column at `path` ("skirt.profile_h",
  /// "big_end.supply_pressure_values"): its model, view, chart (a table of two columns; else
  /// nullptr) and the line below its buttons showing core's message about it. nullptr for a path
  /// that is no list.
  ArrayTableModel* listModel(const std::string& path) const;
  QTableView* listTable(const std::string& path) const;
  QChart* listChart(const std::string& path) const;
  QLabel* listIssue(const std::string& path) const;
  /// The list block's line saying why the table is unused now (ListUnusedReason; hidden when it
  /// is used) and the line with its columns' "assumed" notes (hidden when none).
  QLabel* listHint(const std::string& path) const;
  QLabel* listAssumed(const std::string& path) const;
  /// Whether the list block's table and buttons are enabled: a table no run reads now is greyed,
  /// unless core refuses its rows (then it stays editable, to fix them).
  bool listEnabled(const std::string& path) const;

  /// Reads a CSV file (list_csv.hpp; a file dialog when `file` is empty) into the list table with
  /// a column at `path`, replacing all its rows as one undoable edit. A bad file changes nothing:
  /// the message (file, line, value, what is allowed) goes to the status bar and, from the
  /// dialog, a message box. True when the table now holds the file's rows.
  bool importListCsv(const std::string& path, const QString& file = {});
  /// Writes the list table with a column at `path` as CSV (a dialog when `file` is empty),
  /// atomically. True when written.
  bool exportListCsv(const std::string& path, const QString& file = {});
  ArrayTableModel* profileModel() const { return listModel("skirt.profile_y"); }
  ArrayTableModel* ovalityModel() const { return listModel("skirt.ovality_alpha"); }
  ArrayTableModel* pressureModel() const { return pressure_model_; }
  QComboBox* modelSelector() const { return model_combo_; }
  QComboBox* curveSelector() const { return curve_combo_; }
  QChart* profileChart() const { return listChart("skirt.profile_y"); }
  QChart* ovalityChart() const { return listChart("skirt.ovality_alpha"); }
  QChart* pressureChart() const { return pressure_chart_; }
  /// The steady skirt calculator below the skirt's inputs.
  SkirtCalculatorPanel* skirtCalculator() const { return skirt_calculator_; }

  /// Index into engineCase().pressure_curves of the curve in the table (-1: none).
  int currentCurve() const { return current_curve_; }

 public slots:
  void importPressureCsv(const QString& path = {});
  void exportPressureCsv(const QString& path = {});
  void addPressureCurve();
  void removePressureCurve();

 signals:
  void statusMessage(const QString& message);

 private:
  struct ListBlock {
    const CaseListTable* table = nullptr;
    ArrayTableModel* model = nullptr;
    QTableView* view = nullptr;
    QChart* chart = nullptr;
    QLabel* issue = nullptr;
    QLabel* hint = nullptr;     ///< why the table is unused now
    QLabel* assumed = nullptr;  ///< its columns' "assumed" notes
    QWidget* body = nullptr;    ///< the table, its chart and buttons: disabled while unused
  };

  /// The group's scalar rows, with its list tables not placed elsewhere below them.
  QWidget* makeParameterPage(CaseGroup group);
  QWidget* makeProfilePage();
  /// A list table's block: its title and a note, its "assumed" notes and why it is unused now
  /// (each a line, when there is one), the table (and its chart beside it for two columns),
  /// Insert/Remove row and Import/Export CSV buttons (also the table's context menu) and below
  /// them core's message about it in red.
  QWidget* makeListBlock(const CaseListTable& table, QWidget* parent);
  /// The list tables of `group` that have no block yet, side by side; nullptr if none.
  QWidget* makeListRow(CaseGroup group, QWidget* parent);
  const ListBlock* listBlock(const std::string& path) const;
  QWidget* makePressurePage();
  void updateCharts();
  void updateListBlock(const ListBlock& block);
  void updateCurveSelector();

  CaseDocument* document_;
  QTabWidget* tabs_ = nullptr;
  std::map<CaseGroup, QTableView*> tables_;
  std::map<CaseGroup, ParameterTableModel*> models_;
  QComboBox* model_combo_ = nullptr;
  std::map<std::string, ListBlock> lists_;  ///< by CaseListTable::key
  QComboBox* curve_combo_ = nullptr;
  ArrayTableModel* pressure_model_ = nullptr;
  QTableView* pressure_table_ = nullptr;
  QChart* pressure_chart_ = nullptr;
  int current_curve_ = -1;
  SkirtCalculatorPanel* skirt_calculator_ = nullptr;
};

}  // namespace filmdyn::ui
