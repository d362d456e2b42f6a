#include "ui/fields/field_view.hpp"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <QComboBox>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <QStackedLayout>
#include <QStyle>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>
#include <cmath>

#include "ui/vtk/scalar_field_view.hpp"

namespace filmdyn::ui {

namespace {

using FrameData = std::vector<std::pair<std::string, std::vector<double>>>;

const std::vector<double>* FindArray(const FrameData& data, const std::string& name) {
  for (const auto& [array_name, values] : data) {
    if (array_name == name) return &values;
  }
  return nullptr;
}

vtkSmartPointer<vtkPolyData> ToPolyData(const io::SurfaceField& field, const FrameData& data,
                                        const FieldArrayInfo& info) {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetNumberOfPoints(vtkIdType(field.points.size()));
  // Millimetres: VTK's camera and picking behave better near unit scale.
  for (size_t i = 0; i < field.points.size(); ++i) {
    points->SetPoint(vtkIdType(i), field.points[i][0] * 1e3, field.points[i][1] * 1e3,
                     field.points[i][2] * 1e3);
  }
  vtkNew<vtkCellArray> cells;
  for (const auto& t : field.triangles) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    cells->InsertNextCell(3, ids);
  }
  poly->SetPoints(points);
  poly->SetPolys(cells);
  vtkNew<vtkDoubleArray> array;
  array->SetName(info.name);
  array->SetNumberOfValues(vtkIdType(field.points.size()));
  const std::vector<double>* values = FindArray(data, info.name);
  for (size_t i = 0; i < field.points.size(); ++i) {
    array->SetValue(vtkIdType(i), values && i < values->size() ? (*values)[i] * info.scale : 0.0);
  }
  poly->GetPointData()->AddArray(array);
  return poly;
}

// Qt 6.4 cannot render a QOpenGLWidget on the offscreen platform (docs/design.md, "VTK inside Qt 6"): no 3D there.
bool CanRenderGl() { return QGuiApplication::platformName() != QLatin1String("offscreen"); }

}  // namespace

FieldView::FieldView(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  auto* bar = new QHBoxLayout;
  array_combo_ = new QComboBox(this);
  array_combo_->setObjectName("field_array");
  for (const FieldArrayInfo& info : FieldArrays()) {
    array_combo_->addItem(QString::fromUtf8(info.title), QString::fromUtf8(info.name));
  }
  play_ = new QToolButton(this);
  play_->setObjectName("field_play");
  play_->setCheckable(true);
  play_->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
  play_->setToolTip(tr("Play / pause (Space)"));
  play_->setShortcut(Qt::Key_Space);
  slider_ = new QSlider(Qt::Horizontal, this);
  slider_->setObjectName("field_slider");
  angle_label_ = new QLabel(this);
  angle_label_->setMinimumWidth(90);
  bar->addWidget(new QLabel(tr("Show:"), this));
  bar->addWidget(array_combo_);
  bar->addWidget(play_);
  bar->addWidget(slider_, 1);
  bar->addWidget(angle_label_);
  layout->addLayout(bar);

  stack_ = new QStackedLayout;
  placeholder_ = new QLabel(this);
  placeholder_->setAlignment(Qt::AlignCenter);
  placeholder_->setWordWrap(true);
  views_host_ = new QWidget(this);
  new QHBoxLayout(views_host_);
  stack_->addWidget(placeholder_);
  stack_->addWidget(views_host_);
  layout->addLayout(stack_, 1);

  timer_ = new QTimer(this);
  timer_->setInterval(60);
  connect(timer_, &QTimer::timeout, this, [this] {
    if (slider_->maximum() > 0) setFrameIndex((slider_->value() + 1) % (slider_->maximum() + 1));
  });
  connect(play_, &QToolButton::toggled, this, &FieldView::setPlaying);
  connect(slider_, &QSlider::valueChanged, this, [this] { showFrame(); });
  connect(array_combo_, &QComboBox::currentIndexChanged, this, [this] {
    updateRanges();
    showFrame();
  });
  setFrames(nullptr, {});
}

FieldView::~FieldView() = default;

ScalarFieldView* FieldView::jointView(int index) const {
  return index >= 0 && index < int(views_.size()) ? views_[size_t(index)] : nullptr;
}

int FieldView::frameIndex() const { return slider_->value(); }
bool FieldView::isPlaying() const { return timer_->isActive(); }

void FieldView::setFrames(std::shared_ptr<const FieldFrames> frames, const QString& run_label,
                          const QString& missing_reason) {
  setPlaying(false);
  frames_ = std::move(frames);
  const bool have = frames_ && !frames_->empty();
  slider_->setEnabled(have);
  play_->setEnabled(have);
  if (!have) {
    placeholder_->setText(
        run_label.isEmpty()
            ? tr("Oil-film pressure fields appear here after a run with a lubricated joint.")
        : !missing_reason.isEmpty()
            ? tr("%1 has no film fields: %2.").arg(run_label, missing_reason)
            : tr("%1 has no film fields: only runs with a lubricated joint (Only-Skirt, "
                 "Only-LBRBE, Skirt-LBRBE) compute them.")
                  .arg(run_label));
    stack_->setCurrentWidget(placeholder_);
    slider_->setRange(0, 0);
    angle_label_->clear();
    return;
  }
  if (!CanRenderGl()) {
    placeholder_->setText(tr("3D views need an OpenGL display (not available on the '%1' "
                             "platform); export the fields (HDF5 + XDMF) for ParaView instead.")
                              .arg(QGuiApplication::platformName()));
    stack_->setCurrentWidget(placeholder_);
  } else {
    while (views_.size() < frames_->joints.size()) {
      auto* view = new ScalarFieldView(views_host_);
      view->setObjectName(QString("field_view_%1").arg(views_.size()));
      view->setMinimumSize(300, 260);
      views_host_->layout()->addWidget(view);
      views_.push_back(view);
    }
    for (size_t i = 0; i < views_.size(); ++i) views_[i]->setVisible(i < frames_->joints.size());
    stack_->setCurrentWidget(views_host_);
  }
  {
    QSignalBlocker block(slider_);
    slider_->setRange(0, int(frames_->crank_angle_deg.size()) - 1);
    slider_->setValue(0);
  }
  updateRanges();
  showFrame();
}

void FieldView::updateRanges() {
  if (!frames_ || frames_->empty()) return;
  const FieldArrayInfo& info = FieldArrays()[size_t(std::max(0, array_combo_->currentIndex()))];
  for (size_t j = 0; j < views_.size() && j < frames_->joints.size(); ++j) {
    double lo = INFINITY, hi = -INFINITY;
    for (const FrameData& f : frames_->joints[j].frames) {
      if (const auto* values = FindArray(f, info.name)) {
        for (double v : *values) {
          if (std::isfinite(v))
            lo = std::min(lo, v * info.scale), hi = std::max(hi, v * info.scale);
        }
      }
    }
    if (std::isfinite(lo)) views_[j]->setScalarRange(lo, hi);
  }
}

void FieldView::setFrameIndex(int index) { slider_->setValue(index); }

void FieldView::setCrankAngle(double crank_angle_deg) {
  if (!frames_ || frames_->empty()) return;
  const auto& angles = frames_->crank_angle_deg;
  size_t best = 0;
  for (size_t k = 1; k < angles.size(); ++k) {
    if (std::abs(angles[k] - crank_angle_deg) < std::abs(angles[best] - crank_angle_deg)) best = k;
  }
  slider_->setValue(int(best));
}

void FieldView::setPlaying(bool playing) {
  if (playing && frames_ && !frames_->empty()) {
    timer_->start();
  } else {
    timer_->stop();
  }
  QSignalBlocker block(play_);
  play_->setChecked(timer_->isActive());
  play_->setIcon(
      style()->standardIcon(timer_->isActive() ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
}

void FieldView::showFrame() {
  if (!frames_ || frames_->empty()) return;
  const int k = slider_->value();
  const double angle = frames_->crank_angle_deg[size_t(k)];
  angle_label_->setText(tr("%1 °CA").arg(angle, 0, 'f', 1));
  const FieldArrayInfo& info = FieldArrays()[size_t(std::max(0, array_combo_->currentIndex()))];
  for (size_t j = 0; j < views_.size() && j < frames_->joints.size(); ++j) {
    const auto& joint = frames_->joints[j];
    if (size_t(k) >= joint.frames.size()) continue;
    const QString title = QString::fromStdString(joint.name == "big_end" ? "big end" : joint.name) +
                          "\n" + QString::fromUtf8(info.title);
    views_[j]->showField(ToPolyData(joint.mesh, joint.frames[size_t(k)], info), info.name, title);
  }
  emit crankAngleChanged(angle);
}

}  // namespace filmdyn::ui
