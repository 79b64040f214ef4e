// Seed 000 Section 4: the 30 s cut simulated with both methods. The rotating-pipe method must
// track better than the static one, and both within the seed's simulated figures.
#include "core/job/default_job.h"
#include "core/machines/pipe_robot/cut_planner.h"
#include "core/machines/pipe_robot/cut_simulation.h"
#include "core/machines/pipe_robot/pipe_robot_program.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

using namespace cutcell;

namespace {

TrackingReport run(CutMethod m, PlantModel model = PlantModel::Linear) {
    Job job = defaultJob();
    cutcell::pipeRobotSpec(job).method = m;
    cutcell::pipeRobotSpec(job).plant_model = model;
    const CutPlan plan = planCut(job);
    EXPECT_TRUE(plan.reachable) << plan.problem;
    return simulateCut(job, plan);
}

double maxJoint(const TrackingReport& r, int from = 0) {
    double m = 0;
    for (int i = from; i < kAxisCount; ++i)
        m = std::max(m, r.joints[static_cast<size_t>(i)].max_abs);
    return m;
}

} // namespace

TEST(Simulation, DefaultJobIsAThirtySecondCut) {
    const Job job = defaultJob();
    const CutPlan plan = planCut(job);
    EXPECT_NEAR(plan.cut_time_s, 30.0, 0.01);
    const TrackingReport r = simulateCut(job, plan);
    EXPECT_GE(r.simulated_s, 30.0 - 1e-9);
    EXPECT_EQ(r.steps, static_cast<long>(std::llround(r.simulated_s / job.sim.period_s)) + 1);
}

// The linear plant (one J q'' + b q' = u per joint, the job's plant[] rows): its figures are
// the golden ones of the sessions before the rigid-body plant, unchanged.
TEST(Simulation, BothMethodsStayWithinTheSeedsFigures) {
    const TrackingReport stat = run(CutMethod::StaticPipe);
    const TrackingReport rot = run(CutMethod::RotatingPipe);
    // Seed 000 Section 4: static joint <= 0.04 deg, Cartesian within +-0.026 mm; rotating
    // joint <= 0.009 deg, Cartesian within +-0.021 mm. Ours are far below (README, "Results"):
    // measured static 0.000457 deg / 0.000689 mm, rotating 0.000436 deg / 0.000679 mm. The
    // bounds sit about 2.5x above those, so a controller or plant regression fails here long
    // before it would reach the seed's figures.
    std::printf("static: %.6f deg, %.6f mm; rotating: %.6f deg, %.6f mm\n", maxJoint(stat),
                stat.cartesian_max_abs_mm.maxCoeff(), maxJoint(rot),
                rot.cartesian_max_abs_mm.maxCoeff());
    EXPECT_LE(maxJoint(stat), 0.0012);
    EXPECT_LE(stat.cartesian_max_abs_mm.maxCoeff(), 0.0017);
    EXPECT_LE(maxJoint(rot), 0.0011);
    EXPECT_LE(rot.cartesian_max_abs_mm.maxCoeff(), 0.0017);
    // The actuators are not saturated: the figures are the controller's, not the torque limit's.
    EXPECT_LT(stat.max_torque_fraction, 1.0);
    EXPECT_LT(rot.max_torque_fraction, 1.0);
}

TEST(Simulation, LinearPlantRotatingPipeTracksBetterThanStaticPipe) {
    const TrackingReport stat = run(CutMethod::StaticPipe);
    const TrackingReport rot = run(CutMethod::RotatingPipe);
    EXPECT_LT(maxJoint(rot), maxJoint(stat));
    EXPECT_LT(maxJoint(rot, 1), maxJoint(stat, 1)); // the arm's own joints
    EXPECT_LT(rot.cartesian_max_abs_mm.maxCoeff(), stat.cartesian_max_abs_mm.maxCoeff());
    EXPECT_LT(rot.on_pipe_max_abs_mm.maxCoeff(), stat.on_pipe_max_abs_mm.maxCoeff());
    // And it holds the torch where the process wants it: no tilt into the joint-1 plane.
    EXPECT_LT(rot.max_direction_deviation_deg, 1e-6);
    EXPECT_GT(stat.max_direction_deviation_deg, 1.0);
    // Seed: with the static pipe the chuck does not move; with the rotating pipe joint 1 stays
    // still.
    EXPECT_EQ(stat.joints[0].max_abs, 0);
    EXPECT_LT(rot.joints[1].max_abs, 1e-9);
}

TEST(Simulation, ReportJsonHasTheDocumentedKeys) {
    const json::Value v = reportToJson(run(CutMethod::RotatingPipe));
    ASSERT_TRUE(v.find("joints") && v.find("joints")->asArray().size() == kAxisCount);
    for (const auto& j : v.find("joints")->asArray()) {
        EXPECT_TRUE(j.find("max_abs_error_deg")->isNumber());
        EXPECT_TRUE(j.find("rms_error_deg")->isNumber());
    }
    const json::Value* cart = v.find("cartesian")->find("max_abs_error_mm");
    for (const char* axis : {"x", "y", "z"})
        EXPECT_TRUE(cart->find(axis)->isNumber());
    EXPECT_EQ(v.find("method")->asString(), "rotating_pipe");
    EXPECT_TRUE(v.find("reachable")->asBool());
}

// The robot's tip model seen through TipModel's own tipPair (two tip() calls).
class OneTipAtATime : public TipModel {
  public:
    explicit OneTipAtATime(const TipModel& m) : m_(m) {}
    Vec3 tip(const JointVector& q) const override { return m_.tip(q); }
    Vec3 tipOnWork(const JointVector& q, const Vec3& tipBase) const override {
        return m_.tipOnWork(q, tipBase);
    }

  private:
    const TipModel& m_;
};

// The tips computed once and shared (overall, cruise, telemetry) give the same figures as
// computing them per add(), and the robot's two-sample tipPair (the simulation's and the
// engine's path) the same as one tip() per sample.
TEST(Simulation, SharedTipsGiveTheSameFigures) {
    const Job job = defaultJob();
    const PipeRobotTipModel model(cutcell::pipeRobotSpec(job).dh);
    const OneTipAtATime single(model);
    TrackingStats perAdd(&model), shared(&model), viaModel(&single);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> angle(-kPi, kPi), small(-0.01, 0.01);
    for (int k = 0; k < 2000; ++k) {
        JointVector c, a;
        for (int i = 0; i < kAxisCount; ++i) {
            c[i] = angle(rng);
            a[i] = c[i] + small(rng);
        }
        perAdd.add(c, a);
        const TipSample tips = shared.tips(c, a);
        ASSERT_TRUE(tips.valid);
        shared.add(c, a, tips);
        viaModel.add(c, a);
    }
    TrackingReport r1, r2, r3;
    r1.axis_count = r2.axis_count = r3.axis_count = kAxisCount;
    perAdd.fill(r1);
    shared.fill(r2);
    viaModel.fill(r3);
    EXPECT_EQ(json::write(reportToJson(r1)), json::write(reportToJson(r2)));
    EXPECT_EQ(json::write(reportToJson(r1)), json::write(reportToJson(r3)));
    EXPECT_GT(r1.cartesian_max_abs_mm.norm(), 0);
    EXPECT_GT(r1.on_pipe_max_abs_mm.norm(), 0);
}
