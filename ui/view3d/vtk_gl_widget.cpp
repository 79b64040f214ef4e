#include "ui/view3d/vtk_gl_widget.h"
#include "ui/view3d/vtk_mouse_forwarding.h"

// GL calls go through Qt's function resolvers; VTK's own GL state cache is reset before each
// render, so Qt's changes to the state never confuse it. (vtk_glew.h is not needed here.)
#include <QElapsedTimer>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QWheelEvent>

#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkNew.h>
#include <vtkOpenGLState.h>

namespace cutcell::view3d {

VtkGlWidget::VtkGlWidget(QWidget* parent) : QOpenGLWidget(parent) {
    window_ = vtkGenericOpenGLRenderWindow::New();
    window_->SetMultiSamples(0); // 4x MSAA costs ~6x the frame time on llvmpipe (STACK.md)
    // Qt's core profile is forward compatible: glLineWidth > 1 fails there, so VTK must draw
    // wide lines itself.
    window_->SetForceMaximumHardwareLineWidth(1);
    window_->SetReadyForRendering(false);
    for (unsigned long ev : {vtkCommand::WindowMakeCurrentEvent, vtkCommand::WindowIsCurrentEvent,
                             vtkCommand::WindowFrameEvent})
        observers_.push_back(window_->AddObserver(ev, this, &VtkGlWidget::onVtkEvent));

    interactor_ = vtkGenericRenderWindowInteractor::New();
    interactor_->SetRenderWindow(window_);
    interactor_->EnableRenderOff(); // we render in paintGL only; events call update()
    vtkNew<vtkInteractorStyleTrackballCamera> style;
    interactor_->SetInteractorStyle(style);
    interactor_->Initialize();

    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(160, 120);
}

VtkGlWidget::~VtkGlWidget() {
    // Clean up here: relying on aboutToBeDestroyed alone segfaults on exit (STACK.md).
    disconnect(contextConnection_);
    releaseGl();
    for (unsigned long id : observers_)
        window_->RemoveObserver(id);
    interactor_->SetRenderWindow(nullptr);
    interactor_->Delete();
    window_->Delete();
}

vtkGenericOpenGLRenderWindow* VtkGlWidget::renderWindow() const {
    return window_;
}

void VtkGlWidget::setMultiSamples(int samples) {
    window_->SetMultiSamples(samples);
    update();
}

void VtkGlWidget::initializeGL() {
    disconnect(contextConnection_);
    contextConnection_ = connect(context(), &QOpenGLContext::aboutToBeDestroyed, this,
                                 &VtkGlWidget::releaseGl, Qt::DirectConnection);
    window_->SetOwnContext(0);
    window_->SetReadyForRendering(true);
    window_->OpenGLInitContext();
    window_->GetState()->Reset();
    glReady_ = true;
}

void VtkGlWidget::releaseGl() {
    if (!glReady_) return;
    makeCurrent();
    window_->Finalize(); // releases every GL resource of the renderers and actors
    window_->SetReadyForRendering(false);
    glReady_ = false;
    doneCurrent();
}

void VtkGlWidget::resizeGL(int w, int h) {
    const qreal dpr = devicePixelRatioF();
    interactor_->UpdateSize(static_cast<int>(w * dpr), static_cast<int>(h * dpr));
}

void VtkGlWidget::paintGL() {
    if (!glReady_) return;
    vtkOpenGLState* state = window_->GetState();
    state->Reset(); // Qt changed the GL state since the last frame
    state->Push();
    if (beforeRender_) beforeRender_();
    inPaint_ = true;
    window_->Render();
    inPaint_ = false;
    state->Pop();

    // VTK rendered into its own framebuffers: copy the result into ours.
    QOpenGLExtraFunctions* f = context()->extraFunctions();
    const qreal dpr = devicePixelRatioF();
    const int w = static_cast<int>(width() * dpr), h = static_cast<int>(height() * dpr);
    const int* src = window_->GetSize();
    state->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
    const GLenum drawBuffer = GL_COLOR_ATTACHMENT0;
    f->glDrawBuffers(1, &drawBuffer);
    state->vtkglDisable(GL_SCISSOR_TEST);
    window_->BlitDisplayFramebuffer(0, 0, 0, src[0], src[1], 0, 0, w, h, GL_COLOR_BUFFER_BIT,
                                    GL_NEAREST);

    // VTK leaves the background's alpha at 0: force it to 1 or the view shows through.
    f->glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
    f->glClearColor(0, 0, 0, 1);
    f->glViewport(0, 0, w, h);
    f->glClear(GL_COLOR_BUFFER_BIT);
    f->glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

double VtkGlWidget::renderNow() {
    if (!glReady_ || !isValid()) return -1;
    makeCurrent();
    QElapsedTimer timer;
    timer.start();
    paintGL();
    context()->functions()->glFinish();
    const double ms = static_cast<double>(timer.nsecsElapsed()) / 1e6;
    doneCurrent();
    return ms;
}

void VtkGlWidget::onVtkEvent(vtkObject*, unsigned long event, void* callData) {
    switch (event) {
    case vtkCommand::WindowMakeCurrentEvent:
        // The widget's context on its own surface; QOpenGLWidget::makeCurrent() gave black frames.
        if (context()) context()->makeCurrent(context()->surface());
        break;
    case vtkCommand::WindowIsCurrentEvent:
        *static_cast<bool*>(callData) = context() && QOpenGLContext::currentContext() == context();
        break;
    case vtkCommand::WindowFrameEvent:
        if (!inPaint_) update(); // VTK rendered from outside paintGL: show it
        break;
    default:
        break;
    }
}

// Mouse: the trackball camera (orbit, pan, zoom), in the render window's pixels.
void VtkGlWidget::mousePressEvent(QMouseEvent* e) {
    if (forwardMousePress(interactor_, e, devicePixelRatioF())) update();
}

void VtkGlWidget::mouseDoubleClickEvent(QMouseEvent* e) {
    if (forwardMousePress(interactor_, e, devicePixelRatioF(), true)) update();
}

void VtkGlWidget::mouseReleaseEvent(QMouseEvent* e) {
    if (forwardMouseRelease(interactor_, e, devicePixelRatioF())) update();
}

void VtkGlWidget::mouseMoveEvent(QMouseEvent* e) {
    if (forwardMouseMove(interactor_, e, devicePixelRatioF())) update();
}

void VtkGlWidget::wheelEvent(QWheelEvent* e) {
    if (forwardWheel(interactor_, e, devicePixelRatioF())) update();
}

} // namespace cutcell::view3d
