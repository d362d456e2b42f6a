#pragma once
/// @file The pressure-field view: the skirt and the big-end bearing as 3D surfaces coloured by
/// hydrodynamic pressure, contact pressure or film thickness, each with a scalar bar; a
/// crank-angle slider and play/pause drive both and emit the angle for the plot cursor. The colour
/// range is fixed over all frames of the run so the animation is comparable frame to frame.
#include <QWidget>
#include <memory>
#include <vector>

#include "ui/fields/field_frames.hpp"

class QComboBox;
class QLabel;
class QSlider;
class QStackedLayout;
class QToolButton;
class QTimer;

namespace filmdyn::ui {

class ScalarFieldView;

class FieldView : public QWidget {
  Q_OBJECT

 public:
  explicit FieldView(QWidget* parent = nullptr);
  ~FieldView() override;

  /// Shows a run's fields (empty → the explanation of why there is nothing to show).
  /// `missing_reason`: why a run has no frames when it is not the model's (shown instead of the
  /// default explanation, which names the models that compute fields).
  void setFrames(std::shared_ptr<const FieldFrames> frames, const QString& run_label,
                 const QString& missing_reason = {});
  const FieldFrames* frames() const { return frames_.get(); }

  int frameIndex() const;
  bool isPlaying() const;
  QSlider* slider() const { return slider_; }
  QComboBox* arraySelector() const { return array_combo_; }
  /// The 3D view of joint `index` (nullptr when there is none, e.g. no GL on this platform).
  ScalarFieldView* jointView(int index) const;

 public slots:
  void setFrameIndex(int index);
  void setPlaying(bool playing);
  /// Shows the frame nearest to a crank angle [°CA] (from a click on a plot).
  void setCrankAngle(double crank_angle_deg);

 signals:
  void crankAngleChanged(double crank_angle_deg);

 private:
  void showFrame();
  void updateRanges();

  std::shared_ptr<const FieldFrames> frames_;
  QComboBox* array_combo_ = nullptr;
  QSlider* slider_ = nullptr;
  QToolButton* play_ = nullptr;
  QLabel* angle_label_ = nullptr;
  QLabel* placeholder_ = nullptr;
  QWidget* views_host_ = nullptr;
  QStackedLayout* stack_ = nullptr;
  std::vector<ScalarFieldView*> views_;
  QTimer* timer_ = nullptr;
};

}  // namespace filmdyn::ui
