// The profile cutter's scene (seed 002): with the machine at (A, X) of a cut point, the torch
// tip lies on that point of the drawn cut curve and agrees with the engine's tip model (the
// torch's contact point on the pipe); the pipe turns about its own axis, the torch points into
// it radially. Offscreen, no rendering.
#include "core/job/job_io.h"
#include "core/machines/profile_cutter/profile_cutter.h"
#include "core/machines/profile_cutter/profile_cutter_program.h"
#include "core/machines/profile_cutter/profile_cutter_spec.h"
#include "ui/machines/profile_cutter/profile_scene.h"

#include <QtTest>

using namespace cutcell;

namespace {

Job loadProfileJob(const char* target) {
    Job job = loadJobFile(CUTCELL_SOURCE_DIR "/resources/jobs/profile_cutter_job.json");
    job.cut.target = std::string(target) == "main" ? CutTarget::Main : CutTarget::Branch;
    if (job.cut.target == CutTarget::Main) cutcell::profileCutterSpec(job).other_branches.clear();
    return job;
}

} // namespace

class TstProfileScene : public QObject {
    Q_OBJECT
  private slots:
    void torchTipOnTheCutCurve_data() {
        QTest::addColumn<QString>("target");
        QTest::newRow("branch end") << "branch";
        QTest::newRow("hole in the main pipe") << "main";
    }

    void torchTipOnTheCutCurve() {
        QFETCH(QString, target);
        const Job job = loadProfileJob(qPrintable(target));
        const ProfileCut cut = computeProfileCut(job);
        const view3d::SceneModel m = view3d::buildProfileCutterScene(job);
        QCOMPARE(m.mount, view3d::ToolMount::LinearCarriage);
        QCOMPARE(m.axisCount, 2);
        QCOMPARE(m.pathWork.size(), cut.points.size() + 1); // closed curve
        const ProfileCutterTipModel tipModel(cut.work_radius_mm);
        const double tol =
            1e-9 * (1 + cut.work_radius_mm + cutcell::profileCutterSpec(job).x_travel_mm);
        for (size_t i = 0; i < m.pathWork.size(); i += 7) {
            const ProfilePoint p = cut.closedAt(i);
            JointVector q = JointVector::Zero();
            q[0] = deg2rad(p.a_deg);
            q[1] = p.x_mm;
            const Pose tool = m.toolPose(q);
            const Vec3 tip = tool.translation();
            // On the drawn curve where the pipe has turned to A.
            QVERIFY2((tip - m.pathPointWorld(i, q)).norm() < tol, qPrintable(QString::number(i)));
            // The engine's tip model (work frame) is the same contact point.
            QVERIFY((m.baseFromWork(q).inverse() * tip - tipModel.tip(q)).norm() < tol);
            // On the pipe's outer surface, at X along its axis.
            const Vec3 w = m.baseFromWork(q).inverse() * tip;
            QVERIFY(std::abs(std::hypot(w.x(), w.y()) - cut.work_radius_mm) < tol);
            QVERIFY(std::abs(w.z() - p.x_mm) < tol);
            // The torch points at the pipe axis (radial).
            const Vec3 axisWorld = m.baseFromWork(q) * Vec3(0, 0, w.z());
            QVERIFY((tool.linear().col(2) - (axisWorld - tip).normalized()).norm() < 1e-9);
        }
        QCOMPARE(m.unreachableCount(), size_t(0));
    }

    void pointsOffTheCarriageAreMarked() {
        Job job = loadProfileJob("branch");
        const ProfileCut cut = computeProfileCut(job);
        double xMax = 0;
        for (const auto& p : cut.points)
            xMax = std::max(xMax, p.x_mm);
        cutcell::profileCutterSpec(job).x_travel_mm = xMax * 0.99;
        QVERIFY(!travelProblem(job, cut).empty());
        const view3d::SceneModel m = view3d::buildProfileCutterScene(job);
        QVERIFY(m.unreachableCount() > 0);
        QVERIFY(m.firstUnreachable >= 0);
        QVERIFY(m.pathWork[size_t(m.firstUnreachable)].z() >
                cutcell::profileCutterSpec(job).x_travel_mm);
    }
};

QTEST_GUILESS_MAIN(TstProfileScene)
#include "tst_profile_scene.moc"
