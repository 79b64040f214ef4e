// Cut planning: the rotating method keeps the torch on its straight line over the pipe, the
// cut point moves at the cutting speed, and unreachable paths are reported with the point.
#include "core/job/default_job.h"
#include "core/machines/pipe_robot/cut_planner.h"
#include "core/machines/pipe_robot/pipe_robot.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace cutcell;

namespace {
Job jobWith(CutMethod m, CutTarget t = CutTarget::Main) {
    Job job = defaultJob();
    cutcell::pipeRobotSpec(job).method = m;
    job.cut.target = t;
    return job;
}
} // namespace

TEST(Planner, RotatingMethodKeepsTheTorchOnItsLine) {
    for (CutTarget target : {CutTarget::Main, CutTarget::Branch}) {
        const Job job = jobWith(CutMethod::RotatingPipe, target);
        const CutPlan plan = planCut(job);
        ASSERT_TRUE(plan.reachable) << plan.problem;
        const PipeRobot robot(cutcell::pipeRobotSpec(job).dh);
        const double workR =
            target == CutTarget::Main ? job.main_pipe.radius_mm : job.branch_pipe.radius_mm;
        for (const PlannedPoint& p : plan.knots) {
            // The chuck angle brings the cut point to the top of the pipe ...
            const Vec3 onPipe = robot.baseFromWork(p.chuck_rad) * p.cut.p_work;
            ASSERT_NEAR(onPipe.y(), 0, 1e-9);
            ASSERT_NEAR(onPipe.z(), workR, 1e-9);
            // ... where the torch tip is, on the line Y0 = 0, Z0 = R.
            const Pose tool = robot.forward(p.q.segment<kArmJointCount>(1));
            ASSERT_LE((tool.translation() - onPipe).norm(), 1e-6);
            ASSERT_NEAR(p.deviation_deg, 0, 1e-6);
        }
        // Between knots the spline keeps the tip on the line too (joint 1 and the roll stay still).
        for (double t = 0; t <= plan.cut_time_s; t += 0.0137) {
            const JointVector q = plan.spline.evaluate(t).q;
            const Vec3 tip = robot.forward(q.segment<kArmJointCount>(1)).translation();
            ASSERT_NEAR(tip.y(), 0, 1e-9);
            ASSERT_NEAR(tip.z(), workR, 0.01) << "t = " << t;
        }
    }
}

TEST(Planner, CutPointMovesAtTheCuttingSpeedOnThePipe) {
    const Job job = jobWith(CutMethod::RotatingPipe);
    const CutPlan plan = planCut(job);
    const SpeedProfile profile(plan.length_mm, job.cut.speed_mm_s, job.cut.ramp_s);
    ASSERT_NEAR(plan.cut_time_s, plan.length_mm / job.cut.speed_mm_s + job.cut.ramp_s, 1e-9);
    int cruising = 0;
    for (size_t k = 1; k < plan.knots.size(); ++k) {
        const PlannedPoint& a = plan.knots[k - 1];
        const PlannedPoint& b = plan.knots[k];
        if (a.t_s < job.cut.ramp_s || b.t_s > plan.cut_time_s - job.cut.ramp_s) continue;
        // Chord on the pipe surface over one knot step, against speed x time.
        const double chord = (b.cut.p_main - a.cut.p_main).norm();
        EXPECT_NEAR(chord / plan.knot_dt_s, job.cut.speed_mm_s, 1e-3 * job.cut.speed_mm_s)
            << "knot " << k;
        ++cruising;
    }
    EXPECT_GT(cruising, 100);
    // The closed cut ends where it started.
    EXPECT_LE((plan.knots.back().cut.p_main - plan.knots.front().cut.p_main).norm(), 1e-6);
    EXPECT_NEAR(profile.distance(plan.cut_time_s), plan.length_mm, 1e-9);
}

TEST(Planner, StaticMethodHoldsTheChuckAndTiltsTheTorchIntoThePlane) {
    const Job job = jobWith(CutMethod::StaticPipe);
    const CutPlan plan = planCut(job);
    ASSERT_TRUE(plan.reachable) << plan.problem;
    const PipeRobot robot(cutcell::pipeRobotSpec(job).dh);
    for (const PlannedPoint& p : plan.knots) {
        ASSERT_EQ(p.q[0], deg2rad(job.cut.static_chuck_deg));
        const Pose tool = robot.forward(p.q.segment<kArmJointCount>(1));
        ASSERT_LE((tool.translation() - robot.baseFromWork(p.q[0]) * p.cut.p_work).norm(), 1e-6);
        ASSERT_LE((tool.linear().col(2) - p.approach_base).norm(), 1e-9);
    }
    // A 5-DOF arm cannot hold the torch normal to the pipe on the sides of the hole.
    EXPECT_GT(plan.max_deviation_deg, 1.0);
    EXPECT_LE(plan.max_deviation_deg, job.cut.max_direction_deviation_deg);
}

TEST(Planner, UnreachablePathNamesThePointAndTheReason) {
    // The branch end wraps all around the branch: with the pipe standing still the arm would
    // have to cut from below.
    const Job job = jobWith(CutMethod::StaticPipe, CutTarget::Branch);
    const CutPlan plan = planCut(job);
    ASSERT_FALSE(plan.reachable);
    ASSERT_GE(plan.first_bad, 0);
    EXPECT_NE(plan.problem.find("point " + std::to_string(plan.first_bad)), std::string::npos)
        << plan.problem;
    EXPECT_NE(plan.problem.find("phi = "), std::string::npos);
    EXPECT_TRUE(plan.problem.find("joint") != std::string::npos ||
                plan.problem.find("torch") != std::string::npos)
        << plan.problem;

    Job far = defaultJob();
    cutcell::pipeRobotSpec(far).dh[0].d_mm = 900; // pipe moved out of reach
    const CutPlan farPlan = planCut(far);
    ASSERT_FALSE(farPlan.reachable);
    EXPECT_EQ(farPlan.first_bad, 0);
    EXPECT_NE(farPlan.problem.find("beyond the arm's reach"), std::string::npos) << farPlan.problem;
}

TEST(Planner, CancelStopsPlanning) {
    std::atomic<bool> cancel{true};
    PlanOptions o;
    o.cancel = &cancel;
    const CutPlan plan = planCut(defaultJob(), o);
    EXPECT_TRUE(plan.cancelled);
    EXPECT_FALSE(plan.reachable);
}
