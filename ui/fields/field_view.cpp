#include "ui/fields/field_view.hpp"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <QCheckBox>
#include <QComboBox>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <QStackedLayout>
#include <QStyle>
#include <QTabWidget>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "ui/charts/film_map_widget.hpp"
#include "ui/fields/field_maps.hpp"
#include "ui/vtk/scalar_field_view.hpp"

namespace filmdyn::ui {

namespace {

// The frame's surface in millimetres (VTK's camera and picking behave better near unit scale),
// turned into the joint's body frame; elements without film (the pin-boss relief) left out; a
// mirrored joint (the skirt) with its mirror image about y = 0 as well.
vtkSmartPointer<vtkPolyData> ToPolyData(const JointFieldFrames& joint, size_t k,
                                        const FieldArrayInfo& info) {
  const io::SurfaceField& field = joint.mesh;
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  const vtkIdType n = vtkIdType(field.points.size());
  const int copies = joint.mirrored ? 2 : 1;
  points->SetNumberOfPoints(copies * n);
  const double turn = joint.Rotation(k), c = std::cos(turn), s = std::sin(turn);
  for (size_t i = 0; i < field.points.size(); ++i) {
    const auto& p = field.points[i];
    const double x = (c * p[0] - s * p[1]) * 1e3, y = (s * p[0] + c * p[1]) * 1e3;
    points->SetPoint(vtkIdType(i), x, y, p[2] * 1e3);
    if (joint.mirrored) points->SetPoint(n + vtkIdType(i), x, -y, p[2] * 1e3);
  }
  vtkNew<vtkCellArray> cells;
  const bool grid = joint.HasGrid() && !joint.no_film.empty();
  const size_t nx = joint.angle_lines.size();
  for (const auto& t : field.triangles) {
    if (grid) {
      // The element's middle angle (a relief element's nodes lie on or inside the relief).
      double lo = INFINITY, hi = -INFINITY;
      for (int n : t) {
        lo = std::min(lo, joint.angle_lines[size_t(n) % nx]);
        hi = std::max(hi, joint.angle_lines[size_t(n) % nx]);
      }
      if (joint.InNoFilm(0.5 * (lo + hi))) continue;
    }
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    cells->InsertNextCell(3, ids);
    if (joint.mirrored) {  // the mirror image, wound the other way
      const vtkIdType mirror[3] = {n + t[0], n + t[2], n + t[1]};
      cells->InsertNextCell(3, mirror);
    }
  }
  poly->SetPoints(points);
  poly->SetPolys(cells);
  vtkNew<vtkDoubleArray> array;
  array->SetName(info.name);
  array->SetNumberOfValues(copies * n);
  const std::vector<double>* values =
      k < joint.frames.size() ? FindFieldArray(joint.frames[k], info.name) : nullptr;
  for (vtkIdType i = 0; i < copies * n; ++i) {
    const size_t node = size_t(i % n);
    array->SetValue(i, values && node < values->size() ? (*values)[node] * info.scale : 0.0);
  }
  poly->GetPointData()->AddArray(array);
  return poly;
}

// Qt 6.4 cannot render a QOpenGLWidget on the offscreen platform (docs/design.md, "VTK inside
// Qt 6"): no 3D there, the maps still work.
bool CanRenderGl() { return QGuiApplication::platformName() != QLatin1String("offscreen"); }

}  // namespace

FieldView::FieldView(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  auto* bar = new QHBoxLayout;
  array_combo_ = new QComboBox(this);
  array_combo_->setObjectName("field_array");
  for (const FieldArrayInfo& info : FieldArrays()) {
    array_combo_->addItem(QString::fromUtf8(info.title), QString::fromUtf8(info.name));
    if (info.description != nullptr) {
      array_combo_->setItemData(array_combo_->count() - 1, QString::fromUtf8(info.description),
                                Qt::ToolTipRole);
    }
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
  angle_label_->setMinimumWidth(fontMetrics().horizontalAdvance("720.0 °CA") + 8);
  same_scale_ = new QCheckBox(tr("Same scale for all runs"), this);
  same_scale_->setObjectName("field_same_scale");
  same_scale_->setToolTip(
      tr("One colour range over every run of the session that has film fields, so that runs "
         "compare by colour; otherwise the range of the run shown (over its whole cycle)."));
  bar->addWidget(new QLabel(tr("Show:"), this));
  bar->addWidget(array_combo_);
  bar->addWidget(play_);
  bar->addWidget(slider_, 1);
  bar->addWidget(angle_label_);
  bar->addWidget(same_scale_);
  layout->addLayout(bar);
  title_ = new QLabel(this);
  title_->setObjectName("field_title");
  QFont bold = title_->font();
  bold.setBold(true);
  bold.setPointSizeF(bold.pointSizeF() * 1.15);
  title_->setFont(bold);
  title_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(title_);

  stack_ = new QStackedLayout;
  placeholder_ = new QLabel(this);
  placeholder_->setAlignment(Qt::AlignCenter);
  placeholder_->setWordWrap(true);
  views_host_ = new QWidget(this);
  auto* host_layout = new QHBoxLayout(views_host_);
  host_layout->setContentsMargins(0, 0, 0, 0);
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
    updateAvailability();
    updateRanges();
    updateCrankAngleMaps();
    showFrame();
  });
  connect(same_scale_, &QCheckBox::toggled, this, [this] {
    updateRanges();
    updateCrankAngleMaps();
    showFrame();
  });
  setFrames(nullptr, {});
}

FieldView::~FieldView() = default;

ScalarFieldView* FieldView::jointView(int index) const {
  return index >= 0 && index < int(panes_.size()) && panes_[size_t(index)].box->isVisibleTo(this)
             ? panes_[size_t(index)].view
             : nullptr;
}
FilmMapWidget* FieldView::unrolledMap(int index) const {
  return index >= 0 && index < int(panes_.size()) ? panes_[size_t(index)].unrolled : nullptr;
}
FilmMapWidget* FieldView::crankAngleMap(int index) const {
  return index >= 0 && index < int(panes_.size()) ? panes_[size_t(index)].crank_map : nullptr;
}
QTabWidget* FieldView::jointTabs(int index) const {
  return index >= 0 && index < int(panes_.size()) ? panes_[size_t(index)].tabs : nullptr;
}
QLabel* FieldView::missingNote(int index) const {
  return index >= 0 && index < int(panes_.size()) ? panes_[size_t(index)].missing : nullptr;
}
std::pair<double, double> FieldView::colourRange(int index) const {
  return index >= 0 && index < int(panes_.size()) ? panes_[size_t(index)].range
                                                  : std::pair<double, double>{0.0, 1.0};
}

int FieldView::frameIndex() const { return slider_->value(); }
bool FieldView::isPlaying() const { return timer_->isActive(); }
QString FieldView::title() const { return title_->text(); }

void FieldView::ensurePanes(size_t count) {
  while (panes_.size() < count) {
    const int index = int(panes_.size());
    Pane pane;
    pane.box = new QWidget(views_host_);
    auto* box_layout = new QVBoxLayout(pane.box);
    box_layout->setContentsMargins(0, 0, 0, 0);
    box_layout->setSpacing(2);
    pane.header = new QLabel(pane.box);
    QFont bold = pane.header->font();
    bold.setBold(true);
    pane.header->setFont(bold);
    pane.tabs = new QTabWidget(pane.box);
    pane.tabs->setObjectName(QString("field_tabs_%1").arg(index));
    pane.tabs->setDocumentMode(true);
    if (CanRenderGl()) {
      pane.view = new ScalarFieldView(pane.tabs);
      pane.view->setObjectName(QString("field_view_%1").arg(index));
      pane.view->setMinimumSize(260, 200);
      pane.tabs->addTab(pane.view, tr("3D"));
    } else {
      auto* note = new QLabel(tr("3D views need an OpenGL display (not available on the '%1' "
                                 "platform); the unrolled and crank-angle maps show the same "
                                 "fields, and the exported fields (HDF5 + XDMF) open in ParaView.")
                                  .arg(QGuiApplication::platformName()),
                              pane.tabs);
      note->setWordWrap(true);
      note->setAlignment(Qt::AlignCenter);
      pane.tabs->addTab(note, tr("3D"));
    }
    pane.unrolled = new FilmMapWidget(pane.tabs);
    pane.unrolled->setObjectName(QString("unrolled_map_%1").arg(index));
    pane.unrolled->setToolTip(
        tr("The film surface cut open and laid flat at the crank angle "
           "shown: every mesh node at its place with its value."));
    pane.tabs->addTab(pane.unrolled, tr("Unrolled"));
    pane.crank_map = new FilmMapWidget(pane.tabs);
    pane.crank_map->setObjectName(QString("crank_angle_map_%1").arg(index));
    pane.crank_map->setToolTip(
        tr("Over the whole cycle: for every angle around the joint the largest value along the "
           "axis (for the film thickness and the fluid fraction the smallest) — where and when the "
           "film carries load or breaks up. The line marks the crank angle shown."));
    pane.tabs->addTab(pane.crank_map, tr("Crank-angle map"));
    if (!pane.view) pane.tabs->setCurrentIndex(kTabUnrolled);
    pane.missing = new QLabel(pane.box);
    pane.missing->setObjectName(QString("field_missing_%1").arg(index));
    pane.missing->setAlignment(Qt::AlignCenter);
    pane.missing->setWordWrap(true);
    pane.missing->setMargin(24);
    pane.missing->hide();
    box_layout->addWidget(pane.header);
    box_layout->addWidget(pane.tabs, 1);
    box_layout->addWidget(pane.missing, 1);
    views_host_->layout()->addWidget(pane.box);
    panes_.push_back(pane);
  }
}

void FieldView::setUpJoint(Pane& pane, const JointFieldFrames& joint) {
  pane.header->setText(joint.name == "big_end" ? tr("%1 — rod frame").arg(JointTitle(joint))
                                               : JointTitle(joint));
  pane.header->setToolTip(
      joint.name == "big_end"
          ? tr("Drawn in the connecting rod's frame (bearing-fixed): the rod side toward the "
               "small end, the cap side opposite; the arrow is the crank pin's force on the rod.")
      : joint.mirrored ? tr("The film is symmetric about the pin-axis plane: the 3D view shows "
                            "both halves, the maps one half, from the thrust side (0°) to the "
                            "anti-thrust side (180°).")
                       : QString());
  if (!pane.view || pane.joint == joint.name) {
    pane.joint = joint.name;
    return;
  }
  pane.joint = joint.name;
  const double r = joint.radius * 1e3;
  const double length = joint.axial_lines.empty() ? r : joint.axial_lines.back() * 1e3;
  std::vector<ScalarFieldView::SceneLabel> labels;
  if (joint.name == "skirt") {
    // From outside, bore axis up, between the thrust side (+x) and the pin axis (+y): the
    // thrust panel's film face in front, the anti-thrust panel's seen through the relief.
    pane.view->setViewDirection({1.0, 0.8, 0.5}, {0.0, 0.0, 1.0});
    labels.push_back({tr("thrust side"), {r, 0.0, -1.16 * length}});
    labels.push_back({tr("anti-thrust side"), {-r, 0.0, 0.16 * length}});
    // Above the front panel's far corner (the mirrored half), clear of the other labels.
    labels.push_back({tr("skirt top"), {r * std::cos(0.7), -r * std::sin(0.7), 0.14 * length}});
    // Under the front panel's near corner (it floated in the relief's gap, far from any edge).
    labels.push_back(
        {tr("skirt bottom (crank side)"), {r * std::cos(0.8), r * std::sin(0.8), -1.14 * length}});
    // In the relief's gap, low enough to clear the anti-thrust panel seen behind it.
    for (const auto& [a, b] : joint.no_film) {
      const double m = 0.5 * (a + b);
      labels.push_back(
          {tr("pin-boss relief: no film"), {r * std::cos(m), r * std::sin(m), -0.82 * length}});
    }
  } else {
    // Along the crank-pin axis, the small end up: rod side above, cap side below.
    pane.view->setViewDirection({0.25, -0.45, 1.0}, {0.0, 1.0, 0.0});
    labels.push_back({tr("rod side"), {0.0, 1.45 * r, length / 2}});
    labels.push_back({tr("cap side"), {0.0, -1.45 * r, length / 2}});
  }
  pane.view->setLabels(labels);
  pane.view->resetCamera();
}

void FieldView::setScaleFrames(std::vector<std::shared_ptr<const FieldFrames>> all_runs) {
  scale_frames_ = std::move(all_runs);
  if (same_scale_->isChecked()) {
    updateRanges();
    updateCrankAngleMaps();
    showFrame();
  }
}

void FieldView::setFrames(std::shared_ptr<const FieldFrames> frames, const QString& run_label,
                          const QString& missing_reason) {
  setPlaying(false);
  frames_ = std::move(frames);
  run_label_ = run_label;
  const bool have = frames_ && !frames_->empty();
  for (QWidget* w : std::initializer_list<QWidget*>{slider_, play_, array_combo_, same_scale_})
    w->setEnabled(have);
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
    {
      QSignalBlocker block(slider_);
      slider_->setRange(0, 0);
    }
    angle_label_->clear();
    title_->setText(run_label);
    return;
  }
  ensurePanes(frames_->joints.size());
  for (size_t i = 0; i < panes_.size(); ++i) {
    panes_[i].box->setVisible(i < frames_->joints.size());
    if (i < frames_->joints.size()) setUpJoint(panes_[i], frames_->joints[i]);
  }
  stack_->setCurrentWidget(views_host_);
  updateAvailability();
  {
    // The crank angle shown stays: the nearest frame of this run.
    QSignalBlocker block(slider_);
    slider_->setRange(0, int(frames_->crank_angle_deg.size()) - 1);
    slider_->setValue(shown_angle_ >= 0 ? int(nearestFrame(shown_angle_)) : 0);
  }
  updateRanges();
  updateCrankAngleMaps();
  showFrame();
}

const FieldArrayInfo& FieldView::currentArray() const {
  return FieldArrays()[size_t(std::max(0, array_combo_->currentIndex()))];
}

void FieldView::updateAvailability() {
  if (!frames_ || frames_->empty()) return;
  const FieldArrayInfo& info = currentArray();
  for (size_t j = 0; j < panes_.size() && j < frames_->joints.size(); ++j) {
    const JointFieldFrames& joint = frames_->joints[j];
    const bool has = joint.HasArray(info.name);
    panes_[j].tabs->setVisible(has);
    panes_[j].missing->setVisible(!has);
    panes_[j].missing->setText(has ? QString() : MissingArrayText(joint, info));
  }
}

void FieldView::updateRanges() {
  if (!frames_ || frames_->empty()) return;
  const FieldArrayInfo& info = currentArray();
  for (size_t j = 0; j < panes_.size() && j < frames_->joints.size(); ++j) {
    const JointFieldFrames& joint = frames_->joints[j];
    if (info.HasFixedRange()) {
      // A quantity of known range (the fluid fraction): the same colours in every run.
      panes_[j].range = {info.fixed_lo, info.fixed_hi};
      if (panes_[j].view) panes_[j].view->setScalarRange(info.fixed_lo, info.fixed_hi);
      continue;
    }
    auto [lo, hi] = ValueRange(joint, info);
    if (same_scale_->isChecked()) {
      for (const auto& run : scale_frames_) {
        if (!run) continue;
        for (const JointFieldFrames& other : run->joints) {
          if (other.name != joint.name) continue;
          const auto [a, b] = ValueRange(other, info);
          lo = std::min(lo, a), hi = std::max(hi, b);
        }
      }
    }
    // Pressures and thicknesses from zero, the ends round: the same range in all three views.
    panes_[j].range = RoundedRange(std::min(lo, 0.0), hi, 5);
    if (panes_[j].view)
      panes_[j].view->setScalarRange(panes_[j].range.first, panes_[j].range.second);
  }
}

void FieldView::updateCrankAngleMaps() {
  if (!frames_ || frames_->empty()) return;
  const FieldArrayInfo& info = currentArray();
  for (size_t j = 0; j < panes_.size() && j < frames_->joints.size(); ++j) {
    if (!frames_->joints[j].HasArray(info.name)) continue;  // its note instead
    FilmMapData d = CrankAngleMap(*frames_, j, info);
    d.scale_lo = panes_[j].range.first;
    d.scale_hi = panes_[j].range.second;
    d.y_line = shown_angle_;
    panes_[j].crank_map->setData(std::move(d));
  }
}

void FieldView::setFrameIndex(int index) { slider_->setValue(index); }

size_t FieldView::nearestFrame(double crank_angle_deg) const {
  if (!frames_ || frames_->empty()) return 0;
  const auto& angles = frames_->crank_angle_deg;
  // Distance around the cycle: 719 °CA is next to 0 °CA.
  auto distance = [&](double a) {
    const double d = std::fmod(std::abs(a - crank_angle_deg), 720.0);
    return std::min(d, 720.0 - d);
  };
  size_t best = 0;
  for (size_t k = 1; k < angles.size(); ++k) {
    if (distance(angles[k]) < distance(angles[best])) best = k;
  }
  return best;
}

void FieldView::setCrankAngle(double crank_angle_deg) {
  if (!frames_ || frames_->empty()) return;
  slider_->setValue(int(nearestFrame(crank_angle_deg)));
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
  const size_t k = size_t(std::max(0, slider_->value()));
  const double angle = frames_->crank_angle_deg[k];
  shown_angle_ = angle;
  angle_label_->setText(tr("%1 °CA").arg(angle, 0, 'f', 1));
  const FieldArrayInfo& info = currentArray();
  QString what = tr("%1 at %2 °CA").arg(QString::fromUtf8(info.words)).arg(angle, 0, 'f', 0);
  if (int(k) == frames_->failure_frame) {
    what += frames_->crank_angle_deg.size() == 1
                ? tr(", where the run failed in its run-in (the only step kept)")
                : tr(", where the run failed");
  }
  title_->setText(run_label_.isEmpty() ? what.left(1).toUpper() + what.mid(1)
                                       : tr("%1 — %2").arg(run_label_, what));
  for (size_t j = 0; j < panes_.size() && j < frames_->joints.size(); ++j) {
    const JointFieldFrames& joint = frames_->joints[j];
    Pane& pane = panes_[j];
    if (k >= joint.frames.size() || !joint.HasArray(info.name)) continue;
    FilmMapData d = UnrolledMap(joint, k, info);
    d.scale_lo = pane.range.first;
    d.scale_hi = pane.range.second;
    pane.unrolled->setData(std::move(d));
    pane.crank_map->setYLine(angle);
    if (!pane.view) continue;
    pane.view->showField(ToPolyData(joint, k, info), info.name,
                         QString::fromUtf8(info.bar_title ? info.bar_title : info.unit));
    if (k < joint.load.size() && joint.radius > 0) {
      // The load line: the crank pin's force on the bearing, from the bearing's centre.
      const auto& f = joint.load[k];
      const double magnitude = std::hypot(f[0], f[1]);
      const double r = joint.radius * 1e3 * 0.9;  // inside the bore: never hidden
      const double z = joint.axial_lines.empty() ? 0.0 : joint.axial_lines.back() * 1e3 / 2;
      if (magnitude > 0) {
        pane.view->showArrow({0.0, 0.0, z}, {r * f[0] / magnitude, r * f[1] / magnitude, z},
                             tr("load %1 kN").arg(magnitude / 1e3, 0, 'f', 1));
      } else {
        pane.view->hideArrow();
      }
    } else {
      pane.view->hideArrow();
    }
  }
  emit crankAngleChanged(angle);
}

}  // namespace filmdyn::ui
