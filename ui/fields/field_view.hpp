#pragma once
/// @file The pressure-field view: per joint (piston skirt, big-end bearing) three views of the
/// film — the 3D surface, the unrolled map of the frame shown (circumferential angle × axial
/// position) and the crank-angle map of the cycle (circumferential angle × crank angle, the
/// largest value along each axial line) — coloured by film pressure, asperity contact pressure,
/// film thickness or the fluid fraction θ of mass-conserving cavitation on one viridis scale with
/// round numbers. A crank-angle slider and play/pause drive every view and emit the angle for the
/// plot cursor; the title names the run, the quantity and the crank angle. The colour range is
/// fixed over the run's cycle (or over every run with fields: "Same scale for all runs"), so that
/// frames and runs compare; the fluid fraction's is always 0 to 1. A joint whose frames lack the
/// quantity (the fluid fraction with Reynolds cavitation) says why in place of its views.
#include <QString>
#include <QWidget>
#include <memory>
#include <string>
#include <vector>

#include "ui/fields/field_frames.hpp"

class QCheckBox;
class QComboBox;
class QLabel;
class QSlider;
class QStackedLayout;
class QTabWidget;
class QToolButton;
class QTimer;

namespace filmdyn::ui {

class FilmMapWidget;
class ScalarFieldView;

class FieldView : public QWidget {
  Q_OBJECT

 public:
  /// The tabs of each joint's pane.
  enum Tab { kTab3d = 0, kTabUnrolled = 1, kTabCrankAngle = 2 };

  explicit FieldView(QWidget* parent = nullptr);
  ~FieldView() override;

  /// Shows a run's fields (empty → the explanation of why there is nothing to show).
  /// `missing_reason`: why a run has no frames when it is not the model's (shown instead of the
  /// default explanation, which names the models that compute fields). The crank angle shown is
  /// kept (the nearest frame of the new run).
  void setFrames(std::shared_ptr<const FieldFrames> frames, const QString& run_label,
                 const QString& missing_reason = {});
  const FieldFrames* frames() const { return frames_.get(); }
  /// The fields of every run of the session, for "Same scale for all runs" (runs without fields
  /// may be nullptr).
  void setScaleFrames(std::vector<std::shared_ptr<const FieldFrames>> all_runs);

  int frameIndex() const;
  bool isPlaying() const;
  QSlider* slider() const { return slider_; }
  QComboBox* arraySelector() const { return array_combo_; }
  QToolButton* playButton() const { return play_; }
  QCheckBox* sameScaleBox() const { return same_scale_; }
  /// "Skirt-LBRBE 6000 rpm — film pressure at 380 °CA".
  QString title() const;
  /// The 3D view of joint `index` (nullptr when there is none, e.g. no GL on this platform).
  ScalarFieldView* jointView(int index) const;
  FilmMapWidget* unrolledMap(int index) const;
  FilmMapWidget* crankAngleMap(int index) const;
  QTabWidget* jointTabs(int index) const;
  /// The note shown in place of joint `index`'s views when its frames lack the quantity chosen
  /// (hidden otherwise).
  QLabel* missingNote(int index) const;
  /// The colour range of joint `index` in display units (rounded; the same in all its views).
  std::pair<double, double> colourRange(int index) const;

 public slots:
  void setFrameIndex(int index);
  void setPlaying(bool playing);
  /// Shows the frame nearest to a crank angle [°CA] (from a click on a plot).
  void setCrankAngle(double crank_angle_deg);

 signals:
  void crankAngleChanged(double crank_angle_deg);

 private:
  struct Pane {
    QWidget* box = nullptr;
    QLabel* header = nullptr;
    QTabWidget* tabs = nullptr;
    ScalarFieldView* view = nullptr;  ///< nullptr without GL
    FilmMapWidget* unrolled = nullptr;
    FilmMapWidget* crank_map = nullptr;
    QLabel* missing = nullptr;  ///< in place of the tabs when the joint lacks the quantity
    std::string joint;  ///< the joint shown (a new one resets the camera and labels)
    std::pair<double, double> range{0.0, 1.0};
  };
  void ensurePanes(size_t count);
  void setUpJoint(Pane& pane, const JointFieldFrames& joint);
  void showFrame();
  void updateRanges();
  /// Shows each joint's views, or the note saying why it lacks the quantity chosen.
  void updateAvailability();
  const FieldArrayInfo& currentArray() const;
  void updateCrankAngleMaps();
  size_t nearestFrame(double crank_angle_deg) const;

  std::shared_ptr<const FieldFrames> frames_;
  std::vector<std::shared_ptr<const FieldFrames>> scale_frames_;
  QString run_label_;
  double shown_angle_ = -1.0;  ///< crank angle of the frame shown [°CA]; < 0: none yet
  QComboBox* array_combo_ = nullptr;
  QSlider* slider_ = nullptr;
  QToolButton* play_ = nullptr;
  QCheckBox* same_scale_ = nullptr;
  QLabel* angle_label_ = nullptr;
  QLabel* title_ = nullptr;
  QLabel* placeholder_ = nullptr;
  QWidget* views_host_ = nullptr;
  QStackedLayout* stack_ = nullptr;
  std::vector<Pane> panes_;
  QTimer* timer_ = nullptr;
};

}  // namespace filmdyn::ui
