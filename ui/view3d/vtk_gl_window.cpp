#include "ui/view3d/vtk_gl_window.h"
#include "ui/view3d/vtk_mouse_forwarding.h"

#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QTimer>
#include <QWheelEvent>

#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkNew.h>
#include <vtkOpenGLState.h>

#include <algorithm>
#include <cmath>

namespace cutcell::view3d {

namespace {
// At least this long between frames (~30 Hz), and at least kBudgetFactor frame costs: the 3D
// view then uses at most 1 / kBudgetFactor of the GUI thread.
constexpr int kMinIntervalMs = 33;
constexpr double kBudgetFactor = 4.0;
constexpr int kMaxIntervalMs = 500;

} // namespace

VtkGlWindow::VtkGlWindow() : QOpenGLWindow(QOpenGLWindow::NoPartialUpdate) {
    window_ = vtkGenericOpenGLRenderWindow::New();
    window_->SetMultiSamples(0); // 4x MSAA costs ~6x the frame time on llvmpipe (STACK.md)
    window_->SetForceMaximumHardwareLineWidth(1);
    window_->SetReadyForRendering(false);
    for (unsigned long ev : {vtkCommand::WindowMakeCurrentEvent, vtkCommand::WindowIsCurrentEvent,
                             vtkCommand::WindowFrameEvent})
        observers_.push_back(window_->AddObserver(ev, this, &VtkGlWindow::onVtkEvent));

    interactor_ = vtkGenericRenderWindowInteractor::New();
    interactor_->SetRenderWindow(window_);
    interactor_->EnableRenderOff();
    vtkNew<vtkInteractorStyleTrackballCamera> style;
    interactor_->SetInteractorStyle(style);
    interactor_->Initialize();

    deferred_ = new QTimer(this);
    deferred_->setSingleShot(true);
    connect(deferred_, &QTimer::timeout, this, [this] { update(); });
    settle_ = new QTimer(this);
    settle_->setSingleShot(true);
    settle_->setInterval(kSettleMs);
    connect(settle_, &QTimer::timeout, this, [this] {
        lowRes_ = false;
        requestFrame(); // the resting machine at full resolution
    });
    // The frame's cost includes the buffer swap (a software copy to the X server here).
    connect(this, &QOpenGLWindow::frameSwapped, this, [this] {
        if (sinceFrame_.isValid())
            lastFrameMs_ = static_cast<double>(sinceFrame_.nsecsElapsed()) / 1e6;
    });
}

VtkGlWindow::~VtkGlWindow() {
    disconnect(contextConnection_);
    releaseGl();
    for (unsigned long id : observers_)
        window_->RemoveObserver(id);
    interactor_->SetRenderWindow(nullptr);
    interactor_->Delete();
    window_->Delete();
}

int VtkGlWindow::minFrameIntervalMs() const {
    const double budget = kBudgetFactor * lastFrameMs_;
    return std::clamp(static_cast<int>(std::ceil(budget)), kMinIntervalMs, kMaxIntervalMs);
}

void VtkGlWindow::requestFrame(bool moving) {
    if (moving) {
        lowRes_ = true;
        settle_->start();
    }
    if (deferred_->isActive()) return; // a frame is already on its way
    const qint64 since = sinceFrame_.isValid() ? sinceFrame_.elapsed() : kMaxIntervalMs;
    const int wait = minFrameIntervalMs() - static_cast<int>(since);
    if (wait <= 0)
        update();
    else
        deferred_->start(wait);
}

void VtkGlWindow::setMultiSamples(int samples) {
    window_->SetMultiSamples(samples);
    requestFrame();
}

void VtkGlWindow::initializeGL() {
    disconnect(contextConnection_);
    contextConnection_ = connect(context(), &QOpenGLContext::aboutToBeDestroyed, this,
                                 &VtkGlWindow::releaseGl, Qt::DirectConnection);
    window_->SetOwnContext(0);
    window_->SetReadyForRendering(true);
    window_->OpenGLInitContext();
    window_->GetState()->Reset();
    glReady_ = true;
}

void VtkGlWindow::releaseGl() {
    if (!glReady_) return;
    makeCurrent();
    window_->Finalize();
    window_->SetReadyForRendering(false);
    glReady_ = false;
    doneCurrent();
}

void VtkGlWindow::resizeGL(int, int) {
    applyScale(scale_);
}

void VtkGlWindow::applyScale(double scale) {
    scale_ = scale;
    const qreal f = devicePixelRatio() * scale;
    const int w = std::max(1, static_cast<int>(width() * f));
    const int h = std::max(1, static_cast<int>(height() * f));
    const int* size = window_->GetSize();
    if (size[0] != w || size[1] != h) interactor_->UpdateSize(w, h);
}

void VtkGlWindow::paintGL() {
    sinceFrame_.start();
    applyScale(lowRes_ ? 0.5 : 1.0);
    draw();
}

void VtkGlWindow::draw() {
    if (!glReady_) return;
    vtkOpenGLState* state = window_->GetState();
    state->Reset();
    state->Push();
    if (beforeRender_) beforeRender_();
    inPaint_ = true;
    window_->Render();
    inPaint_ = false;
    state->Pop();

    QOpenGLExtraFunctions* f = context()->extraFunctions();
    const qreal dpr = devicePixelRatio();
    const int w = static_cast<int>(width() * dpr), h = static_cast<int>(height() * dpr);
    const int* src = window_->GetSize();
    state->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
    // The window's own framebuffer: its back buffer (GL_COLOR_ATTACHMENT0 is for FBOs).
    const GLenum drawBuffer = defaultFramebufferObject() == 0 ? GL_BACK_LEFT : GL_COLOR_ATTACHMENT0;
    f->glDrawBuffers(1, &drawBuffer);
    state->vtkglDisable(GL_SCISSOR_TEST);
    window_->BlitDisplayFramebuffer(0, 0, 0, src[0], src[1], 0, 0, w, h, GL_COLOR_BUFFER_BIT,
                                    src[0] == w && src[1] == h ? GL_NEAREST : GL_LINEAR);
    f->glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
    f->glClearColor(0, 0, 0, 1);
    f->glViewport(0, 0, w, h);
    f->glClear(GL_COLOR_BUFFER_BIT);
    f->glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    // Read-backs (grabFrame) read the buffer just drawn.
    state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, defaultFramebufferObject());
    if (defaultFramebufferObject() == 0) f->glReadBuffer(GL_BACK_LEFT);
}

double VtkGlWindow::renderNow() {
    if (!glReady_ || !isValid()) return -1;
    makeCurrent();
    applyScale(1.0);
    QElapsedTimer timer;
    timer.start();
    draw();
    context()->functions()->glFinish();
    const double ms = static_cast<double>(timer.nsecsElapsed()) / 1e6;
    doneCurrent();
    return ms;
}

QImage VtkGlWindow::grabFrame() {
    if (!glReady_ || !isValid()) return {};
    makeCurrent();
    applyScale(1.0); // projections (CellView::projectToImage) match the image
    draw();
    context()->functions()->glFinish();
    QImage img = grabFramebuffer(); // reads the back buffer just drawn (no swap in between)
    doneCurrent();
    return img;
}

void VtkGlWindow::onVtkEvent(vtkObject*, unsigned long event, void* callData) {
    switch (event) {
    case vtkCommand::WindowMakeCurrentEvent:
        if (context()) context()->makeCurrent(this);
        break;
    case vtkCommand::WindowIsCurrentEvent:
        *static_cast<bool*>(callData) = context() && QOpenGLContext::currentContext() == context();
        break;
    case vtkCommand::WindowFrameEvent:
        if (!inPaint_) requestFrame();
        break;
    default:
        break;
    }
}

// Mouse: the trackball camera (orbit, pan, zoom), in the render window's pixels.
void VtkGlWindow::mousePressEvent(QMouseEvent* e) {
    if (forwardMousePress(interactor_, e, devicePixelRatio() * scale_)) requestFrame();
}

void VtkGlWindow::mouseDoubleClickEvent(QMouseEvent* e) {
    if (forwardMousePress(interactor_, e, devicePixelRatio() * scale_, true)) requestFrame();
}

void VtkGlWindow::mouseReleaseEvent(QMouseEvent* e) {
    if (forwardMouseRelease(interactor_, e, devicePixelRatio() * scale_)) requestFrame();
}

void VtkGlWindow::mouseMoveEvent(QMouseEvent* e) {
    if (forwardMouseMove(interactor_, e, devicePixelRatio() * scale_)) requestFrame();
}

void VtkGlWindow::wheelEvent(QWheelEvent* e) {
    if (forwardWheel(interactor_, e, devicePixelRatio() * scale_)) requestFrame();
}

} // namespace cutcell::view3d
