#include "ui/view3d/cell_view.h"

#include "ui/view3d/cell_scene.h"
#include "ui/view3d/vtk_gl_widget.h"
#include "ui/view3d/vtk_gl_window.h"

#include <QAction>
#include <QActionGroup>
#include <QGuiApplication>
#include <QLabel>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QSurfaceFormat>
#include <QToolBar>
#include <QVBoxLayout>

#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkRenderer.h>

namespace cutcell::view3d {

void CellView::setDefaultSurfaceFormat() {
    QSurfaceFormat fmt;
    fmt.setRenderableType(QSurfaceFormat::OpenGL);
    fmt.setVersion(3, 2);
    fmt.setProfile(QSurfaceFormat::CoreProfile);
    fmt.setDepthBufferSize(24);
    fmt.setAlphaBufferSize(8);
    fmt.setStencilBufferSize(8);
    fmt.setSamples(0);
    QSurfaceFormat::setDefaultFormat(fmt);
}

bool CellView::openGlAvailable() {
    static const bool available = [] {
        const QString platform = QGuiApplication::platformName();
        // The offscreen platform cannot host a QOpenGLWidget even with a display (STACK.md).
        if (platform == QLatin1String("offscreen") || platform == QLatin1String("minimal"))
            return false;
        QOpenGLContext ctx;
        ctx.setFormat(QSurfaceFormat::defaultFormat());
        if (!ctx.create()) return false;
        QOffscreenSurface surface;
        surface.setFormat(ctx.format());
        surface.create();
        if (!surface.isValid() || !ctx.makeCurrent(&surface)) return false;
        const auto version = ctx.format().version();
        ctx.doneCurrent();
        return version >= qMakePair(3, 2);
    }();
    return available;
}

CellView::CellView(QWidget* parent, Surface surface)
    : QWidget(parent), scene_(std::make_unique<CellScene>()) {
    scene_->setStatusWords({tr("ON").toStdString(), tr("off").toStdString(),
                            tr("points reachable").toStdString(),
                            tr("points NOT reachable (red)").toStdString()});
    const QByteArray forced = qgetenv("CUTCELL_VIEW3D_SURFACE");
    if (forced == "widget") surface = Surface::Widget;
    if (forced == "native") surface = Surface::NativeWindow;
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);

    auto* bar = new QToolBar(this);
    bar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    presets_ = new QActionGroup(this);
    const std::pair<const char*, ViewPreset> entries[] = {
        {QT_TR_NOOP("Iso"), ViewPreset::Iso},
        {QT_TR_NOOP("Front"), ViewPreset::Front},
        {QT_TR_NOOP("Top"), ViewPreset::Top},
        {QT_TR_NOOP("Follow tool"), ViewPreset::FollowTorch}};
    for (const auto& [label, preset] : entries) {
        QAction* a = bar->addAction(tr(label));
        a->setCheckable(true);
        a->setData(static_cast<int>(preset));
        a->setChecked(preset == ViewPreset::Iso);
        presets_->addAction(a);
        connect(a, &QAction::triggered, this, [this, p = preset] { setPreset(p); });
    }
    bar->addSeparator();
    QAction* reset = bar->addAction(tr("Reset view"));
    reset->setToolTip(tr("Back to the iso view of the whole cell"));
    connect(reset, &QAction::triggered, this, &CellView::resetView);
    layout->addWidget(bar);

    if (openGlAvailable() && surface == Surface::NativeWindow) {
        glWindow_ = new VtkGlWindow;
        glWindow_->renderWindow()->AddRenderer(scene_->renderer());
        glWindow_->setBeforeRender([this] {
            // A moving machine renders at half resolution, scaled up: the texts shrink with it
            // so that they keep their size on screen (they were drawn twice as large).
            scene_->setPixelScale(glWindow_->renderScale());
            scene_->prepareRender();
        });
        container_ = QWidget::createWindowContainer(glWindow_, this); // takes ownership
        container_->setObjectName(QStringLiteral("view3dNativeWindow"));
        container_->setMinimumSize(160, 120);
        container_->setFocusPolicy(Qt::StrongFocus);
        layout->addWidget(container_, 1);
    } else if (openGlAvailable()) {
        gl_ = new VtkGlWidget(this);
        gl_->renderWindow()->AddRenderer(scene_->renderer());
        gl_->setBeforeRender([this] { scene_->prepareRender(); });
        layout->addWidget(gl_, 1);
    } else {
        placeholder_ =
            new QLabel(tr("3D view unavailable: no OpenGL on this platform (offscreen)"), this);
        placeholder_->setObjectName(QStringLiteral("view3dPlaceholder"));
        placeholder_->setAlignment(Qt::AlignCenter);
        placeholder_->setWordWrap(true);
        placeholder_->setMinimumSize(160, 120);
        placeholder_->setStyleSheet(
            QStringLiteral("QLabel { background: #1b1e24; color: #c8ccd4; }"));
        layout->addWidget(placeholder_, 1);
    }
}

CellView::~CellView() {
    delete gl_; // releases VTK's GL resources while the scene still exists
    gl_ = nullptr;
    delete container_; // and the native window with it
    container_ = nullptr;
    glWindow_ = nullptr;
}

bool CellView::rendering() const {
    return gl_ != nullptr || glWindow_ != nullptr;
}

QWidget* CellView::renderArea() const {
    return gl_ ? static_cast<QWidget*>(gl_) : container_;
}

void CellView::requestRender() {
    if (gl_) gl_->update();
    if (glWindow_) glWindow_->requestFrame();
}

void CellView::setScene(const SceneModel& model) {
    scene_->setScene(model);
    requestRender();
}

void CellView::setMachineState(const JointVector& q, double progressFraction, bool torchOn) {
    scene_->setMachineState(q, progressFraction, torchOn);
    if (glWindow_)
        glWindow_->requestFrame(true); // moving: half resolution until it rests
    else
        requestRender();
}

void CellView::setStopMark(double progressFraction) {
    scene_->setStopMark(progressFraction);
    requestRender();
}

void CellView::setPreset(ViewPreset preset) {
    scene_->setPreset(preset);
    for (QAction* a : presets_->actions())
        if (a->data().toInt() == static_cast<int>(preset)) a->setChecked(true);
    requestRender();
    emit presetChanged(preset);
}

ViewPreset CellView::preset() const {
    return scene_->preset();
}

void CellView::resetView() {
    setPreset(ViewPreset::Iso);
}

void CellView::setMultiSamples(int samples) {
    if (gl_) gl_->setMultiSamples(samples);
    if (glWindow_) glWindow_->setMultiSamples(samples);
}

QImage CellView::grabFrame() {
    if (glWindow_) return glWindow_->grabFrame();
    return gl_ ? gl_->grabFramebuffer() : QImage();
}

double CellView::renderFrameMs() {
    if (glWindow_) return glWindow_->renderNow();
    return gl_ ? gl_->renderNow() : -1.0;
}

bool CellView::projectToImage(const Vec3& world, QPointF* pixel) const {
    if (!rendering()) return false;
    vtkRenderer* r = scene_->renderer();
    r->SetWorldPoint(world.x(), world.y(), world.z(), 1.0);
    r->WorldToView();
    double v[3];
    r->GetViewPoint(v);
    if (v[2] < -1.0 || v[2] > 1.0) return false; // outside the near/far planes
    r->WorldToDisplay();
    double dpt[3];
    r->GetDisplayPoint(dpt);
    const int* size = (gl_ ? gl_->renderWindow() : glWindow_->renderWindow())->GetSize();
    *pixel = QPointF(dpt[0], size[1] - 1 - dpt[1]); // VTK's display origin is bottom-left
    return true;
}

const CellScene& CellView::scene() const {
    return *scene_;
}
Vec3 CellView::torchTipWorld() const {
    return scene_->torchTipWorld();
}
Vec3 CellView::torchBodyCentreWorld() const {
    return scene_->torchBodyCentreWorld();
}
Vec3 CellView::pipeCentreWorld() const {
    return scene_->pipeCentreWorld();
}
std::array<double, 6> CellView::machineBounds() const {
    return scene_->machineBounds();
}
void CellView::setToolName(const QString& name) {
    scene_->setToolName(name.toStdString());
    requestRender();
}

QString CellView::statusText() const {
    return QString::fromStdString(scene_->statusText());
}

int CellView::doneCount() const {
    return scene_->doneCount();
}

} // namespace cutcell::view3d
