#pragma once
/// @file A VTK view that shows one surface coloured by a scalar field with a scalar bar:
/// the building block of the skirt and bearing pressure-field views.
#include <vtkSmartPointer.h>
#include <QString>

#include "ui/vtk/vtk_view_widget.hpp"

class vtkDataSet;
class vtkDataSetMapper;
class vtkActor;
class vtkScalarBarActor;
class vtkLookupTable;

namespace filmdyn::ui {

class ScalarFieldView : public VtkViewWidget {
  Q_OBJECT

 public:
  explicit ScalarFieldView(QWidget* parent = nullptr);
  ~ScalarFieldView() override;

  /// Shows `data` coloured by its point array `array_name`. The colour range is the array's
  /// range unless setScalarRange() fixed one. The camera is reset on the first field only.
  void showField(vtkDataSet* data, const QString& array_name, const QString& title);
  /// Fixes the colour range (e.g. across all crank angles of an animation).
  void setScalarRange(double minimum, double maximum);
  /// Back to the automatic range of the current field.
  void clearScalarRange();

  vtkScalarBarActor* scalarBar() const;

 private:
  void applyRange();

  vtkSmartPointer<vtkDataSetMapper> mapper_;
  vtkSmartPointer<vtkActor> actor_;
  vtkSmartPointer<vtkScalarBarActor> scalar_bar_;
  vtkSmartPointer<vtkLookupTable> lookup_table_;
  vtkSmartPointer<vtkDataSet> data_;
  QString array_name_;
  bool fixed_range_ = false;
  double range_[2] = {0.0, 1.0};
  bool camera_set_ = false;
};

}  // namespace filmdyn::ui
