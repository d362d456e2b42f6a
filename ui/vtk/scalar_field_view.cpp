#include "ui/vtk/scalar_field_view.hpp"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCoordinate.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkDataSetMapper.h>
#include <vtkDoubleArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>

#include "ui/charts/color_map.hpp"
#include "ui/charts/film_map_widget.hpp"

namespace filmdyn::ui {

namespace {

constexpr double kBackground[3] = {0.13, 0.14, 0.16};
/// Width of the scalar bar's strip [px]: the bar and numbers of up to five characters.
constexpr int kBarStripPixels = 92;

void StyleText(vtkTextProperty* text, int size, bool bold) {
  text->SetFontSize(size);
  text->SetBold(bold);
  text->SetItalic(false);
  text->SetShadow(true);
  text->SetColor(1.0, 1.0, 1.0);
  text->SetFontFamilyToArial();
}

vtkSmartPointer<vtkTextActor> WorldText(const QString& text, const std::array<double, 3>& at) {
  auto actor = vtkSmartPointer<vtkTextActor>::New();
  actor->SetInput(text.toUtf8().constData());
  actor->GetPositionCoordinate()->SetCoordinateSystemToWorld();
  actor->GetPositionCoordinate()->SetValue(at[0], at[1], at[2]);
  vtkTextProperty* p = actor->GetTextProperty();
  StyleText(p, 13, true);
  p->SetJustificationToCentered();
  p->SetVerticalJustificationToCentered();
  return actor;
}

}  // namespace

ScalarFieldView::ScalarFieldView(QWidget* parent)
    : VtkViewWidget(parent),
      mapper_(vtkSmartPointer<vtkDataSetMapper>::New()),
      actor_(vtkSmartPointer<vtkActor>::New()),
      bar_renderer_(vtkSmartPointer<vtkRenderer>::New()),
      scalar_bar_(vtkSmartPointer<vtkScalarBarActor>::New()),
      lookup_table_(vtkSmartPointer<vtkLookupTable>::New()),
      arrow_data_(vtkSmartPointer<vtkPolyData>::New()),
      arrow_(vtkSmartPointer<vtkActor>::New()),
      arrow_label_(vtkSmartPointer<vtkTextActor>::New()) {
  // Viridis, the one colour map of the application (ui/charts/color_map): lightness rises
  // steadily with the value, so the picture reads in grey and for colour-blind readers.
  lookup_table_->SetNumberOfTableValues(256);
  for (int i = 0; i < 256; ++i) {
    const QColor c = Viridis(i / 255.0);
    lookup_table_->SetTableValue(i, c.redF(), c.greenF(), c.blueF(), 1.0);
  }
  const QColor nan = Viridis(NAN);
  lookup_table_->SetNanColor(nan.redF(), nan.greenF(), nan.blueF(), 1.0);
  mapper_->SetLookupTable(lookup_table_);
  mapper_->SetScalarModeToUsePointFieldData();
  mapper_->SetColorModeToMapScalars();
  mapper_->ScalarVisibilityOn();
  mapper_->InterpolateScalarsBeforeMappingOn();  // colours between nodes from the map, not mixed
  actor_->SetMapper(mapper_);
  // Unlit: a colour means a value, wherever the surface faces.
  actor_->GetProperty()->LightingOff();
  actor_->GetProperty()->SetAmbient(1.0);
  actor_->GetProperty()->SetDiffuse(0.0);
  actor_->GetProperty()->SetSpecular(0.0);
  actor_->VisibilityOff();

  // The bar in a strip of its own at the right: it never covers the surface.
  scalar_bar_->SetLookupTable(lookup_table_);
  scalar_bar_->SetUseCustomLabels(true);
  scalar_bar_->SetLabelFormat("%g");
  scalar_bar_->UnconstrainedFontSizeOn();
  scalar_bar_->SetPosition(0.08, 0.05);
  scalar_bar_->SetWidth(0.9);
  scalar_bar_->SetHeight(0.88);
  scalar_bar_->SetBarRatio(0.28);
  scalar_bar_->SetTextPad(4);
  StyleText(scalar_bar_->GetTitleTextProperty(), 13, true);
  StyleText(scalar_bar_->GetLabelTextProperty(), 13, false);
  scalar_bar_->VisibilityOff();
  bar_renderer_->SetBackground(kBackground[0], kBackground[1], kBackground[2]);
  bar_renderer_->InteractiveOff();
  bar_renderer_->AddViewProp(scalar_bar_);
  renderWindow()->AddRenderer(bar_renderer_);
  renderer()->SetBackground(kBackground[0], kBackground[1], kBackground[2]);
  updateViewports(width());

  arrow_->SetMapper(vtkSmartPointer<vtkDataSetMapper>::New());
  static_cast<vtkDataSetMapper*>(arrow_->GetMapper())->SetInputData(arrow_data_);
  arrow_->GetMapper()->ScalarVisibilityOff();
  arrow_->GetProperty()->LightingOff();
  arrow_->GetProperty()->SetColor(1.0, 0.35, 0.25);
  arrow_->GetProperty()->SetLineWidth(3.0);
  arrow_->VisibilityOff();
  StyleText(arrow_label_->GetTextProperty(), 13, true);
  // White on a dark box: readable over any colour of the field (salmon on the fluid fraction's
  // yellow was not), and clear of the shaft drawn under it.
  arrow_label_->GetTextProperty()->SetColor(1.0, 1.0, 1.0);
  arrow_label_->GetTextProperty()->SetShadow(false);
  arrow_label_->GetTextProperty()->SetBackgroundColor(0.35, 0.08, 0.05);
  arrow_label_->GetTextProperty()->SetBackgroundOpacity(0.85);
  arrow_label_->GetTextProperty()->SetJustificationToCentered();
  arrow_label_->GetTextProperty()->SetVerticalJustificationToCentered();
  arrow_label_->GetPositionCoordinate()->SetCoordinateSystemToWorld();
  arrow_label_->VisibilityOff();

  renderer()->AddActor(actor_);
  renderer()->AddActor(arrow_);
  renderer()->AddViewProp(arrow_label_);
}

ScalarFieldView::~ScalarFieldView() = default;

vtkScalarBarActor* ScalarFieldView::scalarBar() const { return scalar_bar_; }
vtkRenderer* ScalarFieldView::scalarBarRenderer() const { return bar_renderer_; }
vtkLookupTable* ScalarFieldView::lookupTable() const { return lookup_table_; }
vtkActor* ScalarFieldView::surfaceActor() const { return actor_; }
std::vector<double> ScalarFieldView::barLabels() const { return bar_labels_; }

std::vector<QString> ScalarFieldView::labelTexts() const {
  std::vector<QString> texts;
  for (const auto& label : labels_) texts.push_back(QString::fromUtf8(label->GetInput()));
  if (arrowVisible()) texts.push_back(QString::fromUtf8(arrow_label_->GetInput()));
  return texts;
}

void ScalarFieldView::resizeGL(int width, int height) {
  VtkViewWidget::resizeGL(width, height);
  updateViewports(width);
}

void ScalarFieldView::updateViewports(int width) {
  const double strip = std::clamp(double(kBarStripPixels) / std::max(width, 1), 0.0, 0.4);
  renderer()->SetViewport(0.0, 0.0, 1.0 - strip, 1.0);
  bar_renderer_->SetViewport(1.0 - strip, 0.0, 1.0, 1.0);
}

void ScalarFieldView::setViewDirection(const std::array<double, 3>& toward_camera,
                                       const std::array<double, 3>& up) {
  toward_camera_ = toward_camera;
  up_ = up;
  custom_view_ = true;
}

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
    vtkCamera* camera = renderer()->GetActiveCamera();
    if (custom_view_) {
      // Look at the surface's centre from the chosen side; ResetCamera then fits the distance.
      // The surface and its labels in the picture.
      double bounds[6];
      data->GetBounds(bounds);
      for (const auto& label : labels_) {
        const double* p = label->GetPositionCoordinate()->GetValue();
        for (int a = 0; a < 3; ++a) {
          bounds[2 * a] = std::min(bounds[2 * a], p[a]);
          bounds[2 * a + 1] = std::max(bounds[2 * a + 1], p[a]);
        }
      }
      const double centre[3] = {(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2,
                                (bounds[4] + bounds[5]) / 2};
      camera->SetFocalPoint(centre);
      camera->SetPosition(centre[0] + toward_camera_[0], centre[1] + toward_camera_[1],
                          centre[2] + toward_camera_[2]);
      camera->SetViewUp(up_[0], up_[1], up_[2]);
      renderer()->ResetCamera(bounds);
      camera->Zoom(0.9);  // room for the labels' text around the points they name
    } else {
      // An oblique view shows curved surfaces as 3D rather than edge-on.
      renderer()->ResetCamera();
      camera->Elevation(25.0);
      camera->Azimuth(30.0);
      camera->OrthogonalizeViewUp();
      renderer()->ResetCamera();
    }
    renderer()->ResetCameraClippingRange();
    camera_set_ = true;
  }
  update();
}

void ScalarFieldView::setLabels(const std::vector<SceneLabel>& labels) {
  for (const auto& actor : labels_) renderer()->RemoveViewProp(actor);
  labels_.clear();
  for (const SceneLabel& label : labels) {
    labels_.push_back(WorldText(label.text, label.position));
    renderer()->AddViewProp(labels_.back());
  }
  update();
}

void ScalarFieldView::showArrow(const std::array<double, 3>& from, const std::array<double, 3>& to,
                                const QString& label) {
  // A shaft and a flat head in the plane spanned by the arrow and the view-independent normal
  // (the head lies across the arrow, perpendicular to z, or to x when the arrow is along z).
  const double d[3] = {to[0] - from[0], to[1] - from[1], to[2] - from[2]};
  const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  if (!(length > 0)) {
    hideArrow();
    return;
  }
  const double u[3] = {d[0] / length, d[1] / length, d[2] / length};
  double side[3] = {-u[1], u[0], 0.0};  // u × z
  double s = std::hypot(side[0], side[1]);
  if (s < 1e-6) side[0] = 1, side[1] = 0, s = 1;
  side[0] /= s, side[1] /= s;
  const double head = 0.16 * length, half = 0.07 * length;
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->InsertNextPoint(from.data());
  points->InsertNextPoint(to[0] - head * u[0], to[1] - head * u[1], to[2] - head * u[2]);
  points->InsertNextPoint(to.data());
  for (double sign : {1.0, -1.0}) {
    points->InsertNextPoint(to[0] - head * u[0] + sign * half * side[0],
                            to[1] - head * u[1] + sign * half * side[1],
                            to[2] - head * u[2] + sign * half * side[2]);
  }
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  const vtkIdType shaft[2] = {0, 1};
  lines->InsertNextCell(2, shaft);
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  const vtkIdType tip[3] = {2, 3, 4};
  polys->InsertNextCell(3, tip);
  arrow_data_->Initialize();
  arrow_data_->SetPoints(points);
  arrow_data_->SetLines(lines);
  arrow_data_->SetPolys(polys);
  arrow_data_->Modified();
  arrow_->VisibilityOn();
  arrow_label_->SetInput(label.toUtf8().constData());
  // Behind the tail, on the arrow's line: clear of the shaft and the head (beside the shaft the
  // label's box, wider than the offset, covered it) and of the loaded film the head points at.
  const double back = 0.3;
  arrow_label_->GetPositionCoordinate()->SetValue(from[0] - back * d[0], from[1] - back * d[1],
                                                  from[2] - back * d[2]);
  arrow_label_->SetVisibility(!label.isEmpty());
  update();
}

void ScalarFieldView::hideArrow() {
  arrow_->VisibilityOff();
  arrow_label_->VisibilityOff();
  update();
}

bool ScalarFieldView::arrowVisible() const { return arrow_->GetVisibility() != 0; }

void ScalarFieldView::setScalarRange(double minimum, double maximum) {
  fixed_range_ = true;
  requested_[0] = minimum;
  requested_[1] = maximum;
  applyRange();
  update();
}

void ScalarFieldView::clearScalarRange() {
  fixed_range_ = false;
  applyRange();
  update();
}

void ScalarFieldView::applyRange() {
  double lo = requested_[0], hi = requested_[1];
  if (!fixed_range_ && data_ != nullptr) {
    vtkDataArray* array = data_->GetPointData()->GetArray(array_name_.toUtf8().constData());
    if (array != nullptr) {
      double r[2];
      array->GetRange(r);
      lo = r[0], hi = r[1];
    }
  }
  std::tie(range_[0], range_[1]) = RoundedRange(lo, hi, 5);
  lookup_table_->SetTableRange(range_);
  mapper_->SetScalarRange(range_);
  bar_labels_ = RoundTicks(range_[0], range_[1], 5);
  auto labels = vtkSmartPointer<vtkDoubleArray>::New();
  for (double t : bar_labels_) labels->InsertNextValue(t);
  scalar_bar_->SetCustomLabels(labels);
}

}  // namespace filmdyn::ui
