#pragma once
/// @file A VTK view that shows one surface coloured by a scalar field (viridis, unlit so that a
/// colour reads as a value) with a scalar bar in its own strip beside the surface (never over
/// it) whose numbers are round, text labels placed in the scene (which side is which) and an
/// optional arrow (e.g. the load line): the building block of the skirt and big-end views.
#include <vtkSmartPointer.h>
#include <QString>
#include <array>
#include <vector>

#include "ui/vtk/vtk_view_widget.hpp"

class vtkDataSet;
class vtkDataSetMapper;
class vtkActor;
class vtkPolyData;
class vtkScalarBarActor;
class vtkLookupTable;
class vtkTextActor;

namespace filmdyn::ui {

class ScalarFieldView : public VtkViewWidget {
  Q_OBJECT

 public:
  /// A text placed at a point of the scene (world coordinates, the field's units); drawn over
  /// everything, centred on the point, so that it is never hidden behind the surface.
  struct SceneLabel {
    QString text;
    std::array<double, 3> position;
  };

  explicit ScalarFieldView(QWidget* parent = nullptr);
  ~ScalarFieldView() override;

  /// Shows `data` coloured by its point array `array_name`; `title` heads the scalar bar (keep
  /// it short, e.g. the unit). The colour range is the array's range unless setScalarRange()
  /// fixed one, in either case widened to round numbers. The camera is set on the first field
  /// (and after resetCamera()).
  void showField(vtkDataSet* data, const QString& array_name, const QString& title);
  /// Fixes the colour range (e.g. across all crank angles of an animation); widened to round
  /// numbers (RoundedRange) so that the bar's end labels are whole ticks.
  void setScalarRange(double minimum, double maximum);
  /// Back to the automatic range of the current field.
  void clearScalarRange();
  /// The colour range in use (after rounding).
  std::array<double, 2> scalarRange() const { return {range_[0], range_[1]}; }

  /// The direction from the scene's centre toward the camera and the camera's up direction used
  /// the next time the camera is set (showField after construction or resetCamera()).
  void setViewDirection(const std::array<double, 3>& toward_camera,
                        const std::array<double, 3>& up);
  /// Sets the camera again at the next showField (a different surface in this view).
  void resetCamera() { camera_set_ = false; }

  /// Replaces the scene's text labels.
  void setLabels(const std::vector<SceneLabel>& labels);
  /// An arrow from `from` to `to` (world coordinates) with `label` at its tip.
  void showArrow(const std::array<double, 3>& from, const std::array<double, 3>& to,
                 const QString& label);
  void hideArrow();
  bool arrowVisible() const;

  vtkScalarBarActor* scalarBar() const;
  /// The renderer of the scalar bar's strip (its viewport lies beside the surface's).
  vtkRenderer* scalarBarRenderer() const;
  vtkLookupTable* lookupTable() const;
  vtkActor* surfaceActor() const;
  /// The texts of the scene labels and of the arrow (for tests).
  std::vector<QString> labelTexts() const;
  /// The numbers written on the scalar bar.
  std::vector<double> barLabels() const;

 protected:
  void resizeGL(int width, int height) override;

 private:
  void applyRange();
  void updateViewports(int width);

  vtkSmartPointer<vtkDataSetMapper> mapper_;
  vtkSmartPointer<vtkActor> actor_;
  vtkSmartPointer<vtkRenderer> bar_renderer_;
  vtkSmartPointer<vtkScalarBarActor> scalar_bar_;
  vtkSmartPointer<vtkLookupTable> lookup_table_;
  vtkSmartPointer<vtkDataSet> data_;
  std::vector<vtkSmartPointer<vtkTextActor>> labels_;
  vtkSmartPointer<vtkPolyData> arrow_data_;
  vtkSmartPointer<vtkActor> arrow_;
  vtkSmartPointer<vtkTextActor> arrow_label_;
  QString array_name_;
  bool fixed_range_ = false;
  double requested_[2] = {0.0, 1.0};
  double range_[2] = {0.0, 1.0};
  std::vector<double> bar_labels_;
  bool camera_set_ = false;
  std::array<double, 3> toward_camera_{0.5, -0.6, 0.6};
  std::array<double, 3> up_{0.0, 0.0, 1.0};
  bool custom_view_ = false;
};

}  // namespace filmdyn::ui
