// CellView on Qt's offscreen platform: no OpenGL, so a placeholder replaces the 3D view while
// the scene graph keeps working.
#include "core/job/default_job.h"
#include "core/machines/pipe_robot/cut_planner.h"
#include "core/machines/pipe_robot/pipe_robot.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"
#include "ui/machines/pipe_robot/pipe_robot_scene.h"
#include "ui/view3d/cell_scene.h"
#include "ui/view3d/cell_view.h"

#include <QLabel>
#include <QOpenGLWidget>
#include <QTest>

#include <vtkCamera.h>
#include <vtkRenderer.h>

using namespace cutcell;
using namespace cutcell::view3d;

class TstCellViewOffscreen : public QObject {
    Q_OBJECT
  private slots:
    void placeholderReplacesTheView();
    void sceneGraphWorksWithoutOpenGl();
    void presetsMoveTheCamera();
};

void TstCellViewOffscreen::placeholderReplacesTheView() {
    QCOMPARE(QGuiApplication::platformName(), QStringLiteral("offscreen"));
    QVERIFY(!CellView::openGlAvailable());
    CellView view;
    view.resize(640, 480);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    QVERIFY(!view.rendering());
    QVERIFY(view.findChild<QOpenGLWidget*>() == nullptr);
    auto* label = view.findChild<QLabel*>(QStringLiteral("view3dPlaceholder"));
    QVERIFY(label);
    QVERIFY(label->isVisible());
    QVERIFY(label->text().contains(QStringLiteral("unavailable")));
    QVERIFY(label->text().contains(QStringLiteral("OpenGL")));
    QVERIFY(view.grabFrame().isNull());
    QCOMPARE(view.renderFrameMs(), -1.0);
    QPointF px;
    QVERIFY(!view.projectToImage(Vec3::Zero(), &px));
}

void TstCellViewOffscreen::sceneGraphWorksWithoutOpenGl() {
    const Job job = defaultJob();
    const CutPlan plan = planCut(job);
    CellView view;
    view.setScene(buildRobotScene(job, plan));
    const PipeRobot robot(cutcell::pipeRobotSpec(job).dh);
    const size_t k = plan.knots.size() / 3;
    view.setMachineState(plan.knots[k].q, double(k) / double(plan.knots.size() - 1), true);
    const Vec3 tip = robot.forward(plan.knots[k].q.segment<kArmJointCount>(1)).translation();
    QVERIFY((view.torchTipWorld() - tip).norm() < 1e-6);
    QCOMPARE(view.doneCount(), int(k) + 1);
    // The status line names the program's tool, in a line short enough for a 500 px view.
    QVERIFY2(view.statusText().contains("torch ON"), qPrintable(view.statusText()));
    view.setToolName("saw");
    QVERIFY2(view.statusText().contains("saw ON") && !view.statusText().contains("torch"),
             qPrintable(view.statusText()));
    QVERIFY2(view.statusText().size() <= 48, qPrintable(view.statusText()));
    // The machine's bounds contain the pipe, the torch and the robot's base.
    const auto b = view.machineBounds();
    for (const Vec3& p :
         {view.pipeCentreWorld(), view.torchTipWorld(), view.torchBodyCentreWorld(), Vec3(0, 0, 0)})
        for (int a = 0; a < 3; ++a)
            QVERIFY(p[a] >= b[2 * a] - 1e-6 && p[a] <= b[2 * a + 1] + 1e-6);
}

void TstCellViewOffscreen::presetsMoveTheCamera() {
    const Job job = defaultJob();
    const CutPlan plan = planCut(job);
    CellView view;
    view.setScene(buildRobotScene(job, plan));
    vtkCamera* cam = view.scene().renderer()->GetActiveCamera();
    const auto direction = [cam] {
        double d[3];
        cam->GetDirectionOfProjection(d);
        return Vec3(d[0], d[1], d[2]);
    };
    view.setPreset(ViewPreset::Top);
    QVERIFY((direction() - Vec3(0, 0, -1)).norm() < 1e-9);
    view.setPreset(ViewPreset::Front);
    QVERIFY((direction() - Vec3(0, 1, 0)).norm() < 1e-9);
    view.setPreset(ViewPreset::FollowTorch);
    double f[3];
    cam->GetFocalPoint(f);
    QVERIFY((Vec3(f[0], f[1], f[2]) - view.torchTipWorld()).norm() < 1e-6);
    // Following: the focal point moves with the tip.
    view.setMachineState(plan.knots.back().q, 1.0, false);
    cam->GetFocalPoint(f);
    QVERIFY((Vec3(f[0], f[1], f[2]) - view.torchTipWorld()).norm() < 1e-6);
    view.resetView();
    QCOMPARE(view.preset(), ViewPreset::Iso);
    const Vec3 iso = direction();
    QVERIFY(iso.z() < -0.1 && iso.y() > 0.1); // looking down, from the front
}

QTEST_MAIN(TstCellViewOffscreen)
#include "tst_cell_view_offscreen.moc"
