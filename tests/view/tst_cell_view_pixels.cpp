// The rendered 3D view (needs OpenGL: run under xvfb-run): the pipe and the torch appear where
// VTK's renderer projects their world positions, in their documented colours.
#include "core/job/default_job.h"
#include "core/machines/pipe_robot/cut_planner.h"
#include "ui/machines/pipe_robot/pipe_robot_scene.h"
#include "ui/view3d/cell_scene.h"
#include "ui/view3d/cell_view.h"
#include "ui/view3d/view_style.h"
#include "ui/view3d/vtk_gl_window.h"

#include <QApplication>
#include <QMouseEvent>
#include <QOpenGLWidget>
#include <QTest>
#include <QWheelEvent>
#include <QWindow>

#include <cmath>
#include <cstdio>

#include <vtkCamera.h>
#include <vtkRenderer.h>

using namespace cutcell;
using namespace cutcell::view3d;

namespace {

constexpr int kSkipReturnCode = 77; // = SKIP_RETURN_CODE of the CTest entries

// Lighting changes brightness, not hue: classify by the channels' order and spread.
bool looksLikePipe(QColor c) {
    return c.blue() > c.red() + 20 && c.blue() > 90 && c.green() > c.red();
}
bool looksLikeTorch(QColor c) {
    return c.red() > 140 && c.red() > c.green() + 50 && c.green() > c.blue() + 10;
}
// The copper nozzle (or the orange body), told apart from the amber path by its lower green.
bool looksLikeNozzle(QColor c) {
    return c.red() > 90 && c.green() < 0.7 * c.red() && c.blue() < 0.75 * c.green();
}
bool looksLikeDone(QColor c) {
    return c.green() > 200 && c.red() < 120 && c.blue() < 150;
}
bool looksLikeBackground(QColor c) {
    return c.red() < 70 && c.green() < 80 && c.blue() < 95;
}

// How many pixels within `radius` of p satisfy `pred`.
template <class Pred> int countNear(const QImage& img, QPointF p, int radius, Pred pred) {
    int n = 0;
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            const int x = int(std::lround(p.x())) + dx, y = int(std::lround(p.y())) + dy;
            if (x >= 0 && y >= 0 && x < img.width() && y < img.height() &&
                pred(img.pixelColor(x, y)))
                ++n;
        }
    return n;
}

QString describe(const QImage& img, QPointF p) {
    const QColor c = img.pixelColor(int(p.x()), int(p.y()));
    return QString("pixel (%1, %2) = rgb(%3, %4, %5)")
        .arg(p.x())
        .arg(p.y())
        .arg(c.red())
        .arg(c.green())
        .arg(c.blue());
}

} // namespace

class TstCellViewPixels : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase();
    void pipeAndTorchAtTheirProjections_data() { surfaces(); }
    void pipeAndTorchAtTheirProjections();
    void donePartTurnsGreen_data() { surfaces(); }
    void donePartTurnsGreen();
    void mouseOrbitsAndWheelZooms();
    void nativeWindowMouseOrbits();

  private:
    // Both drawing surfaces of the view draw the same frame.
    static void surfaces() {
        QTest::addColumn<int>("surface");
        QTest::newRow("QOpenGLWidget") << int(CellView::Surface::Widget);
        QTest::newRow("native window") << int(CellView::Surface::NativeWindow);
    }
    Job job_ = defaultJob();
    CutPlan plan_;
};

void TstCellViewPixels::initTestCase() {
    plan_ = planCut(job_);
    QVERIFY(plan_.reachable);
}

void TstCellViewPixels::pipeAndTorchAtTheirProjections() {
    QFETCH(int, surface);
    CellView view(nullptr, CellView::Surface(surface));
    QCOMPARE(int(view.surface()), surface);
    view.resize(900, 700);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    QVERIFY(view.rendering());
    view.setScene(buildRobotScene(job_, plan_));
    const size_t k = plan_.knots.size() / 4;
    view.setMachineState(plan_.knots[k].q, 0.25, false);
    const QImage img = view.grabFrame();
    QVERIFY(!img.isNull());
    img.save(QDir::temp().filePath("cutcell_view_pixels.png")); // for a look when it fails

    // Background far from everything, e.g. the top-right corner.
    QVERIFY2(looksLikeBackground(img.pixelColor(img.width() - 5, 5)),
             qPrintable(describe(img, {double(img.width() - 5), 5})));

    // The pipe: its top surface between the cut and the chuck, and its centre line.
    const SceneModel& m = view.scene().model();
    const double zFar = m.workPipeCentreZ_mm - 0.30 * m.workPipe.length_mm; // toward the chuck
    const Vec3 axisPoint = m.baseFromWorkAtZero * Vec3(0, 0, zFar);
    const Vec3 u = m.baseFromWorkAtZero.linear().col(2);
    const Vec3 up = (Vec3::UnitZ() - Vec3::UnitZ().dot(u) * u).normalized();
    const Vec3 front = (-Vec3::UnitY() - (-Vec3::UnitY()).dot(u) * u).normalized();
    const double R = m.workPipe.radius_mm;
    const std::vector<Vec3> onPipe{axisPoint + R * up, axisPoint + R * (up + front).normalized()};
    for (const Vec3& p : onPipe) {
        QPointF px;
        QVERIFY(view.projectToImage(p, &px));
        QVERIFY(px.x() >= 0 && px.y() >= 0 && px.x() < img.width() && px.y() < img.height());
        QVERIFY2(countNear(img, px, 2, looksLikePipe) >= 20,
                 qPrintable("pipe expected at " + describe(img, px)));
    }

    // The torch: its body's centre, and orange or copper right next to its tip.
    QPointF body;
    QVERIFY(view.projectToImage(view.torchBodyCentreWorld(), &body));
    QVERIFY2(countNear(img, body, 2, looksLikeTorch) >= 20,
             qPrintable("torch expected at " + describe(img, body)));
    QPointF tip;
    QVERIFY(view.projectToImage(view.torchTipWorld(), &tip));
    QVERIFY2(countNear(img, tip, 8, looksLikeNozzle) >= 5,
             qPrintable("nozzle expected near " + describe(img, tip)));
    // A point in the air beside the torch (away from arm, pipe and floor) is background.
    QPointF air;
    QVERIFY(view.projectToImage(view.torchBodyCentreWorld() + Vec3(0, 0, 400), &air));
    if (air.y() > 0)
        QVERIFY2(countNear(img, air, 1, looksLikeTorch) == 0, qPrintable(describe(img, air)));
}

void TstCellViewPixels::donePartTurnsGreen() {
    QFETCH(int, surface);
    CellView view(nullptr, CellView::Surface(surface));
    QCOMPARE(int(view.surface()), surface);
    view.resize(900, 700);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.setScene(buildRobotScene(job_, plan_));
    view.setPreset(ViewPreset::FollowTorch); // close enough to see the path
    const size_t k = plan_.knots.size() * 3 / 4;
    view.setMachineState(plan_.knots[k].q, double(k) / double(plan_.knots.size() - 1), false);
    const QImage img = view.grabFrame();
    img.save(QDir::temp().filePath("cutcell_view_done.png"));
    // A point cut long ago (half-way) is drawn green where it projects.
    const SceneModel& m = view.scene().model();
    const size_t j = plan_.knots.size() / 2;
    QPointF px;
    QVERIFY(view.projectToImage(m.pathPointWorld(j, plan_.knots[k].q), &px));
    QVERIFY2(countNear(img, px, 3, looksLikeDone) >= 2,
             qPrintable("green expected at " + describe(img, px)));
}

void TstCellViewPixels::mouseOrbitsAndWheelZooms() {
    CellView view;
    view.resize(800, 600);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.setScene(buildRobotScene(job_, plan_));
    auto* gl = view.findChild<QOpenGLWidget*>();
    QVERIFY(gl);
    QVERIFY(!view.grabFrame().isNull());
    vtkCamera* cam = view.scene().renderer()->GetActiveCamera();
    const auto position = [cam] {
        double p[3];
        cam->GetPosition(p);
        return Vec3(p[0], p[1], p[2]);
    };
    const auto focal = [cam] {
        double p[3];
        cam->GetFocalPoint(p);
        return Vec3(p[0], p[1], p[2]);
    };
    // Left drag orbits: the camera moves, its distance to the focal point stays.
    const Vec3 p0 = position(), f0 = focal();
    const QPoint c = gl->rect().center();
    QTest::mousePress(gl, Qt::LeftButton, {}, c);
    for (int i = 1; i <= 5; ++i) {
        QMouseEvent move(QEvent::MouseMove, QPointF(c + QPoint(12 * i, 4 * i)),
                         gl->mapToGlobal(QPointF(c + QPoint(12 * i, 4 * i))), Qt::NoButton,
                         Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(gl, &move);
    }
    QTest::mouseRelease(gl, Qt::LeftButton, {}, c + QPoint(60, 20));
    const Vec3 p1 = position();
    QVERIFY((p1 - p0).norm() > 1.0);
    QVERIFY(std::fabs((p1 - f0).norm() - (p0 - f0).norm()) < 1e-6 * (p0 - f0).norm());
    // Wheel forward zooms in: closer to the focal point.
    QWheelEvent wheel(QPointF(c), gl->mapToGlobal(QPointF(c)), QPoint(), QPoint(0, 120),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(gl, &wheel);
    QVERIFY((position() - focal()).norm() < (p1 - focal()).norm() - 1.0);
    // Reset view brings the iso framing back.
    view.resetView();
    QVERIFY((position() - p0).norm() < 1e-6);
}

// The native window gets the mouse itself (no QOpenGLWidget in between).
void TstCellViewPixels::nativeWindowMouseOrbits() {
    CellView view(nullptr, CellView::Surface::NativeWindow);
    view.resize(800, 600);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.setScene(buildRobotScene(job_, plan_));
    QWindow* win = view.nativeWindow();
    QVERIFY(win);
    QVERIFY(view.findChild<QOpenGLWidget*>() == nullptr);
    QVERIFY(QTest::qWaitForWindowExposed(win));
    QVERIFY(!view.grabFrame().isNull());
    vtkCamera* cam = view.scene().renderer()->GetActiveCamera();
    double p[3];
    cam->GetPosition(p);
    const Vec3 p0(p[0], p[1], p[2]);
    const QPoint c(win->width() / 2, win->height() / 2);
    QTest::mousePress(win, Qt::LeftButton, {}, c);
    for (int i = 1; i <= 5; ++i)
        QTest::mouseMove(win, c + QPoint(12 * i, 4 * i));
    QTest::mouseRelease(win, Qt::LeftButton, {}, c + QPoint(60, 20));
    cam->GetPosition(p);
    QVERIFY((Vec3(p[0], p[1], p[2]) - p0).norm() > 1.0);
}

int main(int argc, char** argv) {
    CellView::setDefaultSurfaceFormat();
    QApplication app(argc, argv);
    // Without OpenGL nothing here can be checked: report "skipped" to CTest (SKIP_RETURN_CODE in
    // CMakeLists.txt), never "passed".
    if (!CellView::openGlAvailable()) {
        std::fprintf(stderr, "SKIP: no OpenGL on this platform: run under xvfb-run -a -s "
                             "\"-screen 0 1280x800x24\"\n");
        return kSkipReturnCode;
    }
    TstCellViewPixels t;
    return QTest::qExec(&t, argc, argv);
}
#include "tst_cell_view_pixels.moc"
