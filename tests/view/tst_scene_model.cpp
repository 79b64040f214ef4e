// SceneModel and the CellScene scene graph (no rendering): geometry properties against the
// core's kinematics, for the default job and variants.
#include "core/geometry/cut_path.h"
#include "core/job/default_job.h"
#include "core/machines/pipe_robot/cut_planner.h"
#include "core/machines/pipe_robot/pipe_robot.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"
#include "ui/machines/pipe_robot/pipe_robot_scene.h"
#include "ui/view3d/cell_scene.h"
#include "ui/view3d/scene_model.h"

#include <QTest>

#include <algorithm>
#include <cmath>

using namespace cutcell;
using namespace cutcell::view3d;

namespace {
constexpr double kTol = 1e-6;

ArmVector arm(const JointVector& q) {
    return q.segment<kArmJointCount>(1);
}

// Each job variant the scene must handle.
Job variant(int which) {
    Job job = defaultJob();
    if (which == 1) cutcell::pipeRobotSpec(job).method = CutMethod::StaticPipe;
    if (which == 2) {
        job.cut.target = CutTarget::Branch;
        job.cut.start_phi_auto = true;
    }
    return job;
}
} // namespace

class TstSceneModel : public QObject {
    Q_OBJECT
  private slots:
    void pathLiesOnTheWorkPipe_data();
    void pathLiesOnTheWorkPipe();
    void toolPoseIsForwardKinematics();
    void torchTipTouchesThePathPoint();
    void pipeTurnsAboutItsOwnAxis();
    void unreachablePointsAreFlagged();
    void doneCountAndFlameFollowTheState();
    void emptyPathIsHarmless();
    void longPathIsDecimatedForDrawing();
};

void TstSceneModel::pathLiesOnTheWorkPipe_data() {
    QTest::addColumn<int>("which");
    QTest::newRow("default (hole, rotating pipe)") << 0;
    QTest::newRow("static pipe") << 1;
    QTest::newRow("branch end") << 2;
}

void TstSceneModel::pathLiesOnTheWorkPipe() {
    QFETCH(int, which);
    const Job job = variant(which);
    const CutPlan plan = planCut(job);
    const SceneModel m = buildRobotScene(job, plan);
    QCOMPARE(m.pathWork.size(), plan.knots.size());
    QCOMPARE(m.reachable.size(), plan.knots.size());
    const double R =
        job.cut.target == CutTarget::Main ? job.main_pipe.radius_mm : job.branch_pipe.radius_mm;
    QCOMPARE(m.workPipe.radius_mm, R);
    for (size_t i = 0; i < m.pathWork.size(); ++i) {
        const Vec3& p = m.pathWork[i];
        QVERIFY2(std::fabs(std::hypot(p.x(), p.y()) - R) < kTol,
                 qPrintable(QString("point %1").arg(i)));
        // ... and within the drawn tube's length.
        QVERIFY(std::fabs(p.z() - m.workPipeCentreZ_mm) <= m.workPipe.length_mm / 2);
    }
}

void TstSceneModel::toolPoseIsForwardKinematics() {
    const Job job = defaultJob();
    const CutPlan plan = planCut(job);
    const SceneModel m = buildRobotScene(job, plan);
    const PipeRobot robot(cutcell::pipeRobotSpec(job).dh);
    CellScene scene;
    scene.setScene(m);
    for (size_t i = 0; i < plan.knots.size(); i += 7) {
        const JointVector& q = plan.knots[i].q;
        const Pose fk = robot.forward(arm(q));
        QVERIFY((m.toolPose(q).matrix() - fk.matrix()).norm() < kTol);
        QVERIFY((m.armFrames(q).back().matrix() - fk.matrix()).norm() < kTol);
        scene.setMachineState(q, 0.5, true);
        // Read back from the torch actor's matrix, not from the model.
        QVERIFY((scene.torchTipWorld() - fk.translation()).norm() < kTol);
        QVERIFY((scene.torchAxisWorld() - fk.linear().col(2)).norm() < kTol);
    }
}

void TstSceneModel::torchTipTouchesThePathPoint() {
    for (int which = 0; which < 3; ++which) {
        const Job job = variant(which);
        const CutPlan plan = planCut(job);
        const SceneModel m = buildRobotScene(job, plan);
        CellScene scene;
        scene.setScene(m);
        for (size_t i = 0; i < plan.knots.size(); i += 5) {
            if (!m.reachable[i]) continue;
            const JointVector& q = plan.knots[i].q;
            scene.setMachineState(q, 0, false);
            // The pipe (turned by the chuck) brings path point i exactly under the torch tip.
            QVERIFY2((scene.torchTipWorld() - m.pathPointWorld(i, q)).norm() < 1e-5,
                     qPrintable(QString("variant %1 point %2").arg(which).arg(i)));
            QVERIFY((m.pathPointWorld(i, q) - plan.knots[i].tip_base).norm() < 1e-6);
        }
    }
}

void TstSceneModel::pipeTurnsAboutItsOwnAxis() {
    const Job job = defaultJob();
    const CutPlan plan = planCut(job);
    const SceneModel m = buildRobotScene(job, plan);
    CellScene scene;
    scene.setScene(m);
    const Vec3 axisPoint = m.baseFromWorkAtZero * Vec3(0, 0, m.workPipeCentreZ_mm);
    JointVector q = m.homeQ;
    for (double a : {-2.0, -0.5, 0.0, 1.0, 2.5}) {
        q[0] = a;
        scene.setMachineState(q, 0, false);
        QVERIFY((scene.pipeCentreWorld() - axisPoint).norm() < kTol);
        // A surface point turns by the chuck angle about the pipe's axis.
        const Vec3 p0 = scene.pipeSurfaceWorld(m.workPipeCentreZ_mm, 0.0) - axisPoint;
        q[0] = a + 0.3;
        scene.setMachineState(q, 0, false);
        const Vec3 p1 = scene.pipeSurfaceWorld(m.workPipeCentreZ_mm, 0.0) - axisPoint;
        const double turned =
            std::acos(std::clamp(p0.normalized().dot(p1.normalized()), -1.0, 1.0));
        QVERIFY(std::fabs(turned - 0.3) < 1e-9);
        QVERIFY(std::fabs(p0.norm() - m.workPipe.radius_mm) < kTol);
    }
}

void TstSceneModel::unreachablePointsAreFlagged() {
    Job job = defaultJob();
    CutPlan plan = planCut(job);
    QVERIFY(plan.reachable);
    QCOMPARE(buildRobotScene(job, plan).unreachableCount(), size_t(0));
    // Cut joint 3's range in the middle of what the cut needs: part of the path breaks it.
    double lo = 1e9, hi = -1e9;
    for (const auto& k : plan.knots) {
        lo = std::min(lo, k.q[3]);
        hi = std::max(hi, k.q[3]);
    }
    QVERIFY(hi - lo > 1e-3);
    cutcell::pipeRobotSpec(job).dh[3].max_deg = rad2deg((lo + hi) / 2);
    plan = planCut(job);
    QVERIFY(!plan.reachable);
    const SceneModel m = buildRobotScene(job, plan);
    QCOMPARE(m.firstUnreachable, plan.first_bad);
    QVERIFY(m.unreachableCount() > 0 && m.unreachableCount() < m.pathWork.size());
    for (size_t i = 0; i < plan.knots.size(); ++i)
        if (!plan.knots[i].ik.ok()) QCOMPARE(int(m.reachable[i]), 0);
    CellScene scene;
    scene.setScene(m);
    QCOMPARE(size_t(scene.unreachableShown()), m.unreachableCount());
}

void TstSceneModel::doneCountAndFlameFollowTheState() {
    const Job job = defaultJob();
    const CutPlan plan = planCut(job);
    CellScene scene;
    scene.setScene(buildRobotScene(job, plan));
    const int n = int(plan.knots.size());
    QCOMPARE(scene.doneCount(), 0);
    QVERIFY(!scene.flameVisible());
    scene.setMachineState(plan.knots[n / 2].q, 0.5, true);
    QVERIFY(std::abs(scene.doneCount() - (n + 1) / 2) <= 1);
    QVERIFY(scene.flameVisible());
    scene.setMachineState(plan.knots.back().q, 1.0, false);
    QCOMPARE(scene.doneCount(), n);
    QVERIFY(!scene.flameVisible());
    scene.setMachineState(plan.knots.back().q, 7.0, false); // clamped
    QCOMPARE(scene.doneCount(), n);
}

void TstSceneModel::emptyPathIsHarmless() {
    const Job job = defaultJob();
    SceneModel m = buildRobotScene(job, planCut(job));
    m.pathWork.clear();
    m.approachWork.clear();
    m.reachable.clear();
    CellScene scene;
    scene.setScene(m);
    scene.setMachineState(m.homeQ, 0.5, true);
    QCOMPARE(scene.doneCount(), 0);
    QCOMPARE(scene.unreachableShown(), 0);
    const auto b = scene.machineBounds();
    QVERIFY(b[0] < b[1] && b[2] < b[3] && b[4] < b[5]);
}

void TstSceneModel::longPathIsDecimatedForDrawing() {
    Job job = defaultJob();
    job.cut.knot_spacing_mm = CutGeometry(job).length() / 20000;
    const CutPlan plan = planCut(job);
    const int n = int(plan.knots.size());
    QVERIFY(n > 20000);
    CellScene scene;
    scene.setScene(buildRobotScene(job, plan));
    QVERIFY(scene.drawnPathPoints() <= 5001 && scene.drawnPathPoints() >= 2500);
    // Progress still counts plan points.
    scene.setMachineState(plan.knots[size_t(n / 3)].q, double(n / 3) / double(n - 1), true);
    QCOMPARE(scene.doneCount(), n / 3 + 1);
    scene.setMachineState(plan.knots.back().q, 1.0, false);
    QCOMPARE(scene.doneCount(), n);
}

QTEST_GUILESS_MAIN(TstSceneModel)
#include "tst_scene_model.moc"
