// The bridge (docs/design.md, "VTK inside Qt 6", explains each step): VTK renders into its own
// framebuffer inside Qt's context; paintGL blits it into the widget's FBO.
#include "ui/vtk/vtk_view_widget.hpp"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLState.h>
#include <vtkRenderer.h>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QSurfaceFormat>
#include <QWheelEvent>

// Plain GL enums; vtk_glew.h must not come after Qt's GL headers, so spell them out.
namespace {
constexpr unsigned int kGlColorBufferBit = 0x00004000;
constexpr unsigned int kGlDrawFramebuffer = 0x8CA9;
constexpr int kGlNearest = 0x2600;
}  // namespace

namespace filmdyn::ui {

void VtkViewWidget::SetDefaultSurfaceFormat() {
  QSurfaceFormat format;
  format.setRenderableType(QSurfaceFormat::OpenGL);
  format.setVersion(3, 2);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setSwapBehavior(QSurfaceFormat::DoubleBuffer);
  format.setRedBufferSize(8);
  format.setGreenBufferSize(8);
  format.setBlueBufferSize(8);
  format.setDepthBufferSize(24);
  format.setStencilBufferSize(8);
  format.setAlphaBufferSize(8);
  format.setSamples(0);
  QSurfaceFormat::setDefaultFormat(format);
}

VtkViewWidget::VtkViewWidget(QWidget* parent)
    : QOpenGLWidget(parent),
      render_window_(vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New()),
      renderer_(vtkSmartPointer<vtkRenderer>::New()),
      interactor_(vtkSmartPointer<vtkGenericRenderWindowInteractor>::New()) {
  setFocusPolicy(Qt::StrongFocus);
  setUpdateBehavior(QOpenGLWidget::NoPartialUpdate);
  setMinimumSize(200, 150);

  render_window_->SetReadyForRendering(false);
  render_window_->SetFrameBlitModeToNoBlit();
  render_window_->AddRenderer(renderer_);
  renderer_->SetBackground(0.13, 0.14, 0.16);

  interactor_->SetRenderWindow(render_window_);
  interactor_->EnableRenderOff();  // Qt decides when to paint
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  interactor_->SetInteractorStyle(style);
  interactor_->Initialize();

  vtkNew<vtkCallbackCommand> callback;
  callback->SetClientData(this);
  callback->SetCallback(&VtkViewWidget::OnRenderWindowEvent);
  render_window_->AddObserver(vtkCommand::WindowMakeCurrentEvent, callback);
  render_window_->AddObserver(vtkCommand::WindowIsCurrentEvent, callback);
  render_window_->AddObserver(vtkCommand::WindowFrameEvent, callback);
  // Renders triggered by the interactor (camera moves) become Qt updates.
  interactor_->AddObserver(vtkCommand::RenderEvent, callback);
}

VtkViewWidget::~VtkViewWidget() {
  makeCurrent();
  render_window_->Finalize();
  render_window_->RemoveAllObservers();
  interactor_->RemoveAllObservers();
  doneCurrent();
}

vtkRenderer* VtkViewWidget::renderer() const { return renderer_; }

vtkGenericOpenGLRenderWindow* VtkViewWidget::renderWindow() const { return render_window_; }

void VtkViewWidget::OnRenderWindowEvent(vtkObject* /*caller*/, unsigned long event_id,
                                        void* client_data, void* call_data) {
  auto* self = static_cast<VtkViewWidget*>(client_data);
  switch (event_id) {
    case vtkCommand::WindowMakeCurrentEvent:
      // Not QOpenGLWidget::makeCurrent(): that would rebind Qt's FBO behind VTK's back.
      if (QOpenGLContext* context = self->context()) context->makeCurrent(context->surface());
      break;
    case vtkCommand::WindowIsCurrentEvent: {
      auto* is_current = static_cast<bool*>(call_data);
      *is_current =
          self->context() != nullptr && QOpenGLContext::currentContext() == self->context();
      break;
    }
    case vtkCommand::WindowFrameEvent:
    case vtkCommand::RenderEvent:
      if (!self->in_paint_) self->update();
      break;
    default:
      break;
  }
}

void VtkViewWidget::initializeGL() {
  render_window_->SetOwnContext(false);
  render_window_->SetIsCurrent(true);
  render_window_->SetReadyForRendering(true);
  render_window_->InitializeFromCurrentContext();
  render_window_->GetState()->Reset();
}

void VtkViewWidget::resizeGL(int width, int height) {
  const double ratio = devicePixelRatioF();
  const int w = static_cast<int>(width * ratio);
  const int h = static_cast<int>(height * ratio);
  render_window_->SetSize(w, h);
  interactor_->UpdateSize(w, h);
}

void VtkViewWidget::paintGL() {
  in_paint_ = true;
  vtkOpenGLState* state = render_window_->GetState();
  state->Reset();
  state->Push();
  const int* size = render_window_->GetSize();
  render_window_->Render();
  // Blit VTK's display framebuffer into the widget's framebuffer object.
  state->vtkglBindFramebuffer(kGlDrawFramebuffer, defaultFramebufferObject());
  render_window_->BlitDisplayFramebuffer(/*right=*/0, 0, 0, size[0], size[1], 0, 0, size[0],
                                         size[1], kGlColorBufferBit, kGlNearest);
  // The widget is composited by Qt: force opaque alpha so nothing shows through.
  state->vtkglColorMask(false, false, false, true);
  state->vtkglClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  state->vtkglClear(kGlColorBufferBit);
  state->Pop();
  ++rendered_frames_;
  in_paint_ = false;
}

void VtkViewWidget::ForwardMouse(QMouseEvent* event, unsigned long vtk_event) {
  const double ratio = devicePixelRatioF();
  const QPointF position = event->position();
  interactor_->SetEventInformationFlipY(static_cast<int>(position.x() * ratio),
                                        static_cast<int>(position.y() * ratio),
                                        (event->modifiers() & Qt::ControlModifier) ? 1 : 0,
                                        (event->modifiers() & Qt::ShiftModifier) ? 1 : 0);
  interactor_->InvokeEvent(vtk_event, event);
  update();
}

void VtkViewWidget::mousePressEvent(QMouseEvent* event) {
  switch (event->button()) {
    case Qt::LeftButton:
      ForwardMouse(event, vtkCommand::LeftButtonPressEvent);
      break;
    case Qt::MiddleButton:
      ForwardMouse(event, vtkCommand::MiddleButtonPressEvent);
      break;
    case Qt::RightButton:
      ForwardMouse(event, vtkCommand::RightButtonPressEvent);
      break;
    default:
      break;
  }
}

void VtkViewWidget::mouseReleaseEvent(QMouseEvent* event) {
  switch (event->button()) {
    case Qt::LeftButton:
      ForwardMouse(event, vtkCommand::LeftButtonReleaseEvent);
      break;
    case Qt::MiddleButton:
      ForwardMouse(event, vtkCommand::MiddleButtonReleaseEvent);
      break;
    case Qt::RightButton:
      ForwardMouse(event, vtkCommand::RightButtonReleaseEvent);
      break;
    default:
      break;
  }
}

void VtkViewWidget::mouseMoveEvent(QMouseEvent* event) {
  ForwardMouse(event, vtkCommand::MouseMoveEvent);
}

void VtkViewWidget::wheelEvent(QWheelEvent* event) {
  const double ratio = devicePixelRatioF();
  interactor_->SetEventInformationFlipY(static_cast<int>(event->position().x() * ratio),
                                        static_cast<int>(event->position().y() * ratio));
  interactor_->InvokeEvent(event->angleDelta().y() > 0 ? vtkCommand::MouseWheelForwardEvent
                                                       : vtkCommand::MouseWheelBackwardEvent,
                           event);
  update();
}

}  // namespace filmdyn::ui
