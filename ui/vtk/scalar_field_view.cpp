#include "ui/vtk/scalar_field_view.hpp"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkDataSetMapper.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextProperty.h>

namespace filmdyn::ui {

ScalarFieldView::ScalarFieldView(QWidget* parent)
    : VtkViewWidget(parent),
      mapper_(vtkSmartPointer<vtkDataSetMapper>::New()),
      actor_(vtkSmartPointer<vtkActor>::New()),
      scalar_bar_(vtkSmartPointer<vtkScalarBarActor>::New()),
      lookup_table_(vtkSmartPointer<vtkLookupTable>::New()) {
  // Blue (low) to red (high), the convention of pressure plots in the tribology literature.
  lookup_table_->SetHueRange(0.667, 0.0);
  lookup_table_->SetNumberOfTableValues(256);
  lookup_table_->Build();
  mapper_->SetLookupTable(lookup_table_);
  mapper_->SetScalarModeToUsePointFieldData();
  mapper_->SetColorModeToMapScalars();
  mapper_->ScalarVisibilityOn();
  actor_->SetMapper(mapper_);
  actor_->VisibilityOff();

  scalar_bar_->SetLookupTable(lookup_table_);
  scalar_bar_->SetNumberOfLabels(5);
  scalar_bar_->SetWidth(0.12);
  scalar_bar_->SetHeight(0.8);
  scalar_bar_->SetPosition(0.86, 0.1);
  scalar_bar_->GetTitleTextProperty()->SetFontSize(12);
  scalar_bar_->GetLabelTextProperty()->SetFontSize(10);
  scalar_bar_->VisibilityOff();

  renderer()->AddActor(actor_);
  renderer()->AddViewProp(scalar_bar_);
}

ScalarFieldView::~ScalarFieldView() = default;

vtkScalarBarActor* ScalarFieldView::scalarBar() const { return scalar_bar_; }

void ScalarFieldView::showField(vtkDataSet* data, const QString& array_name, const QString& title) {
  data_ = data;
  array_name_ = array_name;
  const QByteArray name = array_name.toUtf8();
  mapper_->SetInputData(data);
  mapper_->SelectColorArray(name.constData());
  scalar_bar_->SetTitle(title.toUtf8().constData());
  applyRange();
  actor_->VisibilityOn();
  scalar_bar_->VisibilityOn();
  if (!camera_set_) {
    // An oblique view shows curved surfaces (skirt, bearing) as 3D rather than edge-on.
    renderer()->ResetCamera();
    renderer()->GetActiveCamera()->Elevation(25.0);
    renderer()->GetActiveCamera()->Azimuth(30.0);
    renderer()->ResetCameraClippingRange();
    renderer()->ResetCamera();
    camera_set_ = true;
  }
  update();
}

void ScalarFieldView::setScalarRange(double minimum, double maximum) {
  fixed_range_ = true;
  range_[0] = minimum;
  range_[1] = maximum > minimum ? maximum : minimum + 1.0;
  applyRange();
  update();
}

void ScalarFieldView::clearScalarRange() {
  fixed_range_ = false;
  applyRange();
  update();
}

void ScalarFieldView::applyRange() {
  if (!fixed_range_ && data_ != nullptr) {
    vtkDataArray* array = data_->GetPointData()->GetArray(array_name_.toUtf8().constData());
    if (array != nullptr) {
      array->GetRange(range_);
      if (!(range_[1] > range_[0])) range_[1] = range_[0] + 1.0;  // constant field
    }
  }
  lookup_table_->SetTableRange(range_);
  mapper_->SetScalarRange(range_);
}

}  // namespace filmdyn::ui
