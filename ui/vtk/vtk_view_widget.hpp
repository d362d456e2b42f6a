#pragma once
/// @file A QOpenGLWidget that hosts a VTK render window, for Qt 6 without VTK's Qt module
/// (Debian builds that against Qt 5; see docs/design.md, "VTK inside Qt 6"). Reusable: add props to
/// renderer() and call update().
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <QOpenGLWidget>

class vtkGenericOpenGLRenderWindow;
class vtkGenericRenderWindowInteractor;
class vtkRenderer;
class vtkObject;

namespace filmdyn::ui {

class VtkViewWidget : public QOpenGLWidget {
  Q_OBJECT

 public:
  explicit VtkViewWidget(QWidget* parent = nullptr);
  ~VtkViewWidget() override;

  /// Must be called before the QApplication is created: OpenGL 3.2 core, depth 24, stencil 8,
  /// alpha 8, no multisampling — what VTK's OpenGL2 backend needs.
  static void SetDefaultSurfaceFormat();

  vtkRenderer* renderer() const;
  vtkGenericOpenGLRenderWindow* renderWindow() const;

  /// Number of frames VTK has rendered into this widget (for tests and diagnostics).
  int renderedFrames() const { return rendered_frames_; }

 protected:
  void initializeGL() override;
  void resizeGL(int width, int height) override;
  void paintGL() override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;

 private:
  static void OnRenderWindowEvent(vtkObject* caller, unsigned long event_id, void* client_data,
                                  void* call_data);
  void ForwardMouse(QMouseEvent* event, unsigned long vtk_event);

  vtkSmartPointer<vtkGenericOpenGLRenderWindow> render_window_;
  vtkSmartPointer<vtkRenderer> renderer_;
  vtkSmartPointer<vtkGenericRenderWindowInteractor> interactor_;
  bool in_paint_ = false;
  int rendered_frames_ = 0;
};

}  // namespace filmdyn::ui
