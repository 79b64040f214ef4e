#pragma once
// The 3D view's drawing surface as a native OpenGL window (QOpenGLWindow), shown inside the
// widget tree through QWidget::createWindowContainer(). Why: a QOpenGLWidget makes Qt compose
// the whole top-level window through OpenGL on every update of any widget; with software
// OpenGL (llvmpipe under Xvfb) each composition of a 1600x1000 window cost 10-40 ms on the GUI
// thread. A native child window is drawn on its own (only the 3D area), and the other widgets
// go back to the cheap raster backing store.
//
// Same VTK technique as VtkGlWidget (shared/STACK.md): VTK draws into its own framebuffers,
// paintGL blits the result into the window's back buffer and forces alpha to 1.
// A frame budget: a frame requested sooner than `minFrameIntervalMs()` after the last one is
// deferred, and the interval grows with the measured frame time, so the 3D view takes at most
// about a quarter of the GUI thread however slow the renderer is. While the machine moves the
// scene is rendered at half resolution (a quarter of the pixels, scaled up); kSettleMs after
// the last move it is drawn once more at full resolution. grabFrame() always renders full.
//
// Threading: GUI thread only.
#include <QElapsedTimer>
#include <QOpenGLWindow>

#include <functional>
#include <vector>

class QTimer;
class vtkGenericOpenGLRenderWindow;
class vtkGenericRenderWindowInteractor;
class vtkObject;

namespace cutcell::view3d {

class VtkGlWindow : public QOpenGLWindow {
    Q_OBJECT
  public:
    VtkGlWindow();
    ~VtkGlWindow() override;

    vtkGenericOpenGLRenderWindow* renderWindow() const { return window_; }
    void setBeforeRender(std::function<void()> fn) { beforeRender_ = std::move(fn); }
    void setMultiSamples(int samples);
    // Asks for a frame within the frame budget (coalesced; never renders synchronously);
    // `moving`: the machine moves, half resolution until it rests.
    void requestFrame(bool moving = false);
    static constexpr int kSettleMs = 300;
    double renderScale() const { return scale_; }
    // Renders and waits for it; -1 when the GL context is not ready.
    double renderNow();
    // Renders now and reads the frame back (the window need not be exposed again).
    QImage grabFrame();
    // The measured cost of the last frame (ms) and the interval the budget allows now.
    double lastFrameMs() const { return lastFrameMs_; }
    int minFrameIntervalMs() const;

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
    void draw();

    vtkGenericOpenGLRenderWindow* window_ = nullptr;
    vtkGenericRenderWindowInteractor* interactor_ = nullptr;
    std::vector<unsigned long> observers_;
    std::function<void()> beforeRender_;
    bool glReady_ = false;
    bool inPaint_ = false;
    QMetaObject::Connection contextConnection_;
    void applyScale(double scale);
    QTimer* deferred_ = nullptr;
    QTimer* settle_ = nullptr;
    bool lowRes_ = false;
    double scale_ = 1.0;
    QElapsedTimer sinceFrame_;
    double lastFrameMs_ = 0;
};

} // namespace cutcell::view3d
