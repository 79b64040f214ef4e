#pragma once
// A QOpenGLWidget that renders a vtkGenericOpenGLRenderWindow (the technique of VTK's own Qt
// widget, whose Debian build is Qt 5 only; see shared/STACK.md). VTK draws into its own
// framebuffers; paintGL blits the result into the widget's framebuffer and forces alpha to 1.
// Mouse and wheel events are forwarded to a trackball-camera interactor; rendering happens
// only in paintGL (update() coalesces requests).
//
// Never construct it where CellView::openGlAvailable() is false (offscreen platform).
// Threading: GUI thread only.
#include <QOpenGLWidget>

#include <functional>
#include <vector>

class vtkGenericOpenGLRenderWindow;
class vtkGenericRenderWindowInteractor;
class vtkObject;

namespace cutcell::view3d {

class VtkGlWidget : public QOpenGLWidget {
    Q_OBJECT
  public:
    explicit VtkGlWidget(QWidget* parent = nullptr);
    ~VtkGlWidget() override;

    vtkGenericOpenGLRenderWindow* renderWindow() const;
    // Called right before each VTK render (e.g. to fit the clipping range).
    void setBeforeRender(std::function<void()> fn) { beforeRender_ = std::move(fn); }
    // Multisampling (0 = off, the fast default; 4 = smooth edges, ~6x slower on llvmpipe).
    void setMultiSamples(int samples);
    // Renders and blits now, waits for the GPU, returns the time in ms (benchmark); -1 when
    // the GL context is not ready.
    double renderNow();

  protected:
    void initializeGL() override;
    void paintGL() override;
    void resizeGL(int w, int h) override;
    void mousePressEvent(QMouseEvent* e) override;
    void mouseReleaseEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;
    void mouseDoubleClickEvent(QMouseEvent* e) override;
    void wheelEvent(QWheelEvent* e) override;

  private:
    void onVtkEvent(vtkObject* caller, unsigned long event, void* callData);
    void releaseGl();

    vtkGenericOpenGLRenderWindow* window_ = nullptr; // owned (reference counted)
    vtkGenericRenderWindowInteractor* interactor_ = nullptr;
    std::vector<unsigned long> observers_;
    std::function<void()> beforeRender_;
    bool glReady_ = false;
    bool inPaint_ = false;
    QMetaObject::Connection contextConnection_;
};

} // namespace cutcell::view3d
