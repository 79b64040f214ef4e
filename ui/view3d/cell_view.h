#pragma once
// The 3D view of the cell: the pipe being cut (tube with its wall) in its chuck, the mating
// pipe ghosted, the planned path (amber; red where not reachable), the part already cut
// (green), the torch (orange body, copper nozzle, flame while on) on the arm drawn from its DH
// frames. Mouse: left drag rotates, middle drag (or shift + left) pans, right drag / wheel
// zooms. A small toolbar offers the presets (Iso, Front, Top, Follow tool) and Reset.
// Colours: ui/view3d/view_style.h.
//
// Where OpenGL is unavailable (Qt's offscreen platform) a label takes the 3D view's place;
// the scene graph (CellScene) is still built and updated, so the accessors below work.
//
// Threading: GUI thread only. setMachineState() is cheap (matrices only) and rendering is
// coalesced by update(), so it can be called at the telemetry rate.
#include "core/common/types.h"
#include "ui/view3d/scene_model.h"
#include "ui/view3d/view_style.h"

#include <QImage>
#include <QPointF>
#include <QWidget>

#include <array>
#include <memory>

class QLabel;
class QActionGroup;

namespace cutcell::view3d {

class CellScene;
class VtkGlWidget;

class VtkGlWindow;

class CellView : public QWidget {
    Q_OBJECT
  public:
    // Where the 3D frames are drawn: a QOpenGLWidget (composed with the whole window through
    // OpenGL at every update of any widget), or a native OpenGL child window with a frame budget
    // (VtkGlWindow: the rest of the window stays on the raster backing store). The operator
    // station uses NativeWindow; the environment variable CUTCELL_VIEW3D_SURFACE=widget|native
    // overrides the choice (benchmarks compare the two).
    enum class Surface { Widget, NativeWindow };

    explicit CellView(QWidget* parent = nullptr, Surface surface = Surface::Widget);
    ~CellView() override;

    // Call before constructing QApplication: OpenGL 3.2 core, depth 24, alpha 8.
    static void setDefaultSurfaceFormat();
    // Whether a QOpenGLWidget can work here (probed once: offscreen platform -> false; else a
    // context must be created and made current on an offscreen surface with GL >= 3.2).
    static bool openGlAvailable();
    // Whether this instance renders (false: the placeholder label is shown).
    bool rendering() const;
    Surface surface() const { return glWindow_ ? Surface::NativeWindow : Surface::Widget; }
    // The widget that shows the frames (the QOpenGLWidget or the native window's container);
    // null without OpenGL. Screenshots of the main window paint grabFrame() over it: a native
    // window is not part of QWidget::grab().
    QWidget* renderArea() const;
    // The native window (Surface::NativeWindow only), e.g. to send it mouse events in tests.
    VtkGlWindow* nativeWindow() const { return glWindow_; }

    void setScene(const SceneModel& model);
    void setMachineState(const JointVector& q, double progressFraction, bool torchOn);
    void setStopMark(double progressFraction); // < 0: none (CellScene::setStopMark)
    void setPreset(ViewPreset preset);
    ViewPreset preset() const;
    void resetView();
    // Multisampling off by default (speed); 4 gives smooth edges.
    void setMultiSamples(int samples);

    // The current frame (renders now); a null image without OpenGL.
    QImage grabFrame();
    // Renders once synchronously and returns the time in ms (-1 without OpenGL).
    double renderFrameMs();
    // World point -> pixel of grabFrame()'s image (origin top-left, device pixels).
    // False without OpenGL or when the point is behind the camera.
    bool projectToImage(const Vec3& world, QPointF* pixel) const;

    // Scene-graph queries for tests (world frame, mm): see CellScene.
    const CellScene& scene() const;
    Vec3 torchTipWorld() const;
    Vec3 torchBodyCentreWorld() const;
    Vec3 pipeCentreWorld() const;
    std::array<double, 6> machineBounds() const;
    void setToolName(const QString& name); // CellScene::setToolName
    QString statusText() const;
    int doneCount() const;

  signals:
    void presetChanged(cutcell::view3d::ViewPreset preset);

  private:
    void requestRender();

    std::unique_ptr<CellScene> scene_;
    VtkGlWidget* gl_ = nullptr;
    VtkGlWindow* glWindow_ = nullptr;
    QWidget* container_ = nullptr; // hosts glWindow_
    QLabel* placeholder_ = nullptr;
    QActionGroup* presets_ = nullptr;
};

} // namespace cutcell::view3d
