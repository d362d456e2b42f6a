#pragma once
/// @file The case editor: one tab per group of scalar inputs (tables with units; a choice such as
/// a joint's cavitation model as a combo box of core's names in its row), the skirt
/// profile and ovality (each table + chart) and the cylinder-pressure curves per speed (table +
/// chart, CSV import and export), with the steady skirt calculator on the skirt tab. All edits go
/// through the CaseDocument (undo, validation).
#include <QWidget>
#include <map>

#include "ui/case_editor/case_parameters.hpp"

class QComboBox;
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
  ArrayTableModel* profileModel() const { return profile_model_; }
  ArrayTableModel* ovalityModel() const { return ovality_model_; }
  ArrayTableModel* pressureModel() const { return pressure_model_; }
  QComboBox* modelSelector() const { return model_combo_; }
  QComboBox* curveSelector() const { return curve_combo_; }
  QChart* profileChart() const { return profile_chart_; }
  QChart* ovalityChart() const { return ovality_chart_; }
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
  QWidget* makeParameterPage(CaseGroup group);
  QWidget* makeProfilePage();
  /// A titled table + chart side by side with Insert/Remove row buttons (profile, ovality).
  QWidget* makeArrayBlock(const QString& title, ArrayTableModel* model, const QString& table_name,
                          QChart* chart, QWidget* parent);
  QWidget* makePressurePage();
  void updateCharts();
  void updateCurveSelector();

  CaseDocument* document_;
  QTabWidget* tabs_ = nullptr;
  std::map<CaseGroup, QTableView*> tables_;
  std::map<CaseGroup, ParameterTableModel*> models_;
  QComboBox* model_combo_ = nullptr;
  ArrayTableModel* profile_model_ = nullptr;
  QTableView* profile_table_ = nullptr;
  QChart* profile_chart_ = nullptr;
  ArrayTableModel* ovality_model_ = nullptr;
  QTableView* ovality_table_ = nullptr;
  QChart* ovality_chart_ = nullptr;
  QComboBox* curve_combo_ = nullptr;
  ArrayTableModel* pressure_model_ = nullptr;
  QTableView* pressure_table_ = nullptr;
  QChart* pressure_chart_ = nullptr;
  int current_curve_ = -1;
  SkirtCalculatorPanel* skirt_calculator_ = nullptr;
};

}  // namespace filmdyn::ui
