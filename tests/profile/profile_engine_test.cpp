// The profile cutter through the motion engine: its program (constant surface speed on the
// cut) and a run on simulated stepper axes with progress, feed hold and emergency stop.
#include "core/engine/motion_engine.h"
#include "core/job/job_io.h"
#include "core/machines/profile_cutter/profile_cutter_program.h"
#include "core/machines/profile_cutter/profile_cutter_spec.h"
#include "devices/machines/profile_cutter/profile_cutter_rig.h"
#include "profile_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sys/wait.h>
#include <unistd.h>

namespace cutcell {
namespace {

Job singleBranchJob() {
    Job job = test::exampleProfileJob();
    cutcell::profileCutterSpec(job).other_branches.clear(); // a smooth saddle (no column switch)
    return job;
}

// The torch moves over the pipe at the cutting speed between the ramps, on the cut.
TEST(ProfileProgram, FollowsTheCutAtTheSurfaceSpeed) {
    for (const Job& job : {singleBranchJob(), test::exampleProfileJob()}) {
        const auto p = buildProfileCutterProgram(job);
        ASSERT_EQ(p->axis_count, 2);
        EXPECT_TRUE(p->axis_linear[1]);
        EXPECT_FALSE(p->axis_linear[0]);
        const ProfileCut cut = computeProfileCut(job, 4096);
        const double R = cut.work_radius_mm, v = job.cut.speed_mm_s;
        EXPECT_NEAR(p->length_mm, cut.developedLength(), 1e-9);
        // At rest at both ends; the last knot is the start one turn later (closed cut).
        EXPECT_LT(p->spline.evaluate(0).qd.norm(), 1e-9);
        EXPECT_LT(p->spline.evaluate(p->cut_time_s).qd.norm(), 1e-9);
        EXPECT_NEAR(rad2deg(p->spline.evaluate(p->cut_time_s).q[0] - p->spline.evaluate(0).q[0]),
                    360, 1e-9);
        EXPECT_NEAR(p->spline.evaluate(p->cut_time_s).q[1], p->spline.evaluate(0).q[1], 1e-9);
        double worst = 0;
        int n = 0, off = 0;
        for (double t = p->cruise_from_s; t <= p->cruise_to_s; t += 0.01, ++n) {
            const JointSample s = p->spline.evaluate(t);
            const double speed = std::hypot(s.qd[1], R * s.qd[0]);
            worst = std::max(worst, std::fabs(speed - v) / v);
            off += std::fabs(speed - v) > 0.01 * v;
        }
        if (cutcell::profileCutterSpec(job).other_branches.empty()) {
            EXPECT_LT(worst, 0.01) << "smooth saddle: within 1 % everywhere";
        } else {
            EXPECT_LT(off, n / 50) << "with corners: within 1 % on 98 % of the cut";
        }
    }
}

TEST(ProfileProgram, TipModelMeasuresTheMissOnThePipe) {
    const ProfileCutterTipModel model(44.45);
    JointVector q = JointVector::Zero(), d = JointVector::Zero();
    q << 1.3, 520, 0, 0, 0, 0;
    d << 1e-4, 3e-3, 0, 0, 0, 0;
    const double miss = (model.tip(q + d) - model.tip(q)).norm();
    EXPECT_NEAR(miss, std::hypot(3e-3, 44.45 * 1e-4), 1e-9);
}

TEST(ProfileProgram, CutOutsideTheCarriageTravelIsRefused) {
    Job job = test::exampleProfileJob();
    cutcell::profileCutterSpec(job).x_travel_mm = 550; // the brace is 600 mm long
    try {
        buildProfileCutterProgram(job);
        FAIL() << "accepted a cut beyond the travel";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("profile_cutter.x_travel_mm = 550.000 mm"),
                  std::string::npos)
            << e.what();
    }
}

struct SteppedRun {
    explicit SteppedRun(const Job& job)
        : program(buildProfileCutterProgram(job)), rig(job, *program) {
        EngineConfig config;
        rig.configure(config);
        config.clock = ClockMode::AsFastAsPossible;
        config.spec = job.engine;
        config.spec.runs_dir = ""; // no run log in tests
        engine = std::make_unique<MotionEngine>(rig.devices(), config);
    }
    // Runs up to `cycles` cycles (stopping at `until`), draining telemetry; keeps the last sample.
    EngineState cycles(std::uint64_t count, EngineState until) {
        EngineState s = engine->state();
        for (std::uint64_t done = 0; done < count && s != until; done += 50) {
            s = engine->runCycles(std::min<std::uint64_t>(50, count - done), until);
            TelemetrySample t;
            while (engine->popTelemetry(t)) {
                last = t;
                maxProgress = std::max(maxProgress, t.progress);
            }
        }
        return s;
    }
    void toRunning() {
        ASSERT_TRUE(engine->load(program));
        ASSERT_TRUE(engine->enable());
        ASSERT_EQ(cycles(1000, EngineState::Ready), EngineState::Ready);
        ASSERT_TRUE(engine->home());
        cycles(1, EngineState::Idle); // take the command
        ASSERT_EQ(cycles(200000, EngineState::Ready), EngineState::Ready);
        ASSERT_TRUE(engine->start());
        ASSERT_EQ(cycles(5, EngineState::Running), EngineState::Running);
    }
    std::shared_ptr<const MotionProgram> program;
    ProfileCutterRig rig;
    std::unique_ptr<MotionEngine> engine;
    TelemetrySample last;
    double maxProgress = 0;
};

TEST(ProfileEngine, CompletesTheCutOnSteppers) {
    const Job job = test::exampleProfileJob();
    SteppedRun run(job);
    run.toRunning();
    const std::int64_t a0 = run.rig.a().pulsePosition(), x0 = run.rig.x().pulsePosition();
    const auto limit =
        static_cast<std::uint64_t>((run.program->cut_time_s + 30) / job.sim.period_s);
    ASSERT_EQ(run.cycles(limit, EngineState::Completed), EngineState::Completed);
    EXPECT_NEAR(run.maxProgress, 1.0, 1e-9);
    EXPECT_NEAR(run.last.progress, 1.0, 1e-9); // the Completed sample itself
    EXPECT_EQ(run.last.point_count, run.program->point_count);
    // One turn of the branch on A, X back where it started: the pulses sum to the travel.
    const std::int64_t turn =
        static_cast<std::int64_t>(cutcell::profileCutterSpec(job).steps_per_rev_a) *
        cutcell::profileCutterSpec(job).pulses_per_step_a;
    EXPECT_EQ(run.rig.a().pulsePosition() - a0, turn);
    EXPECT_EQ(run.rig.x().pulsePosition(), x0);
    EXPECT_EQ(run.rig.a().rateLimitedCycles() + run.rig.x().rateLimitedCycles(), 0u);
    TrackingReport report;
    ASSERT_TRUE(run.engine->lastRunReport(report));
    // Open-loop steppers miss by their quantisation and one cycle of motion, no more.
    const double aPulseDeg = 360.0 / static_cast<double>(turn);
    EXPECT_LT(report.joints[0].max_abs, aPulseDeg);
    EXPECT_LT(report.joints[1].max_abs, 2 * cutcell::profileCutterSpec(job).mm_per_pulse_x);
}

// The job's pierce (profile_cutter.pierce_s, the G-code's G4 after M3): once the arc is
// established at the first cut point the torch stays there that long before either axis moves.
TEST(ProfileEngine, PiercesBeforeTheTorchMoves) {
    const Job job = test::exampleProfileJob();
    ASSERT_GE(cutcell::profileCutterSpec(job).pierce_s, 1.0);
    SteppedRun run(job);
    run.toRunning();
    const double T = job.sim.period_s;
    double arcAt = -1, movedAt = -1;
    JointVector atArc = JointVector::Zero();
    for (int k = 0; k < 20000 && movedAt < 0; ++k) {
        run.engine->runCycles(1, EngineState::Completed);
        TelemetrySample t;
        while (run.engine->popTelemetry(t)) {
            if (arcAt < 0 && t.torch_on && t.process_ok) {
                arcAt = t.time_s;
                atArc = t.setpoint;
            } else if (arcAt >= 0 && movedAt < 0 && t.setpoint != atArc) {
                movedAt = t.time_s;
            }
        }
    }
    ASSERT_GE(arcAt, 0) << "the arc was never established";
    ASSERT_GE(movedAt, 0) << "the path never started";
    EXPECT_GE(movedAt - arcAt, cutcell::profileCutterSpec(job).pierce_s - 0.5 * T);
    EXPECT_LE(movedAt - arcAt, cutcell::profileCutterSpec(job).pierce_s + 3 * T);
}

TEST(ProfileEngine, FeedHoldStopsOnThePathAndResumes) {
    const Job job = test::exampleProfileJob();
    SteppedRun run(job);
    run.toRunning();
    run.cycles(static_cast<std::uint64_t>(0.3 * run.program->cut_time_s / job.sim.period_s),
               EngineState::Completed);
    ASSERT_TRUE(run.engine->feedHold());
    ASSERT_EQ(run.cycles(static_cast<std::uint64_t>(5 / job.sim.period_s), EngineState::Paused),
              EngineState::Paused);
    const double progress = run.last.progress;
    EXPECT_GT(progress, 0.2);
    EXPECT_LT(progress, 0.4);
    const std::int64_t a = run.rig.a().pulsePosition(), x = run.rig.x().pulsePosition();
    run.cycles(2000, EngineState::Completed);
    EXPECT_EQ(run.engine->state(), EngineState::Paused);
    EXPECT_EQ(run.rig.a().pulsePosition(), a) << "A moved during feed hold";
    EXPECT_EQ(run.rig.x().pulsePosition(), x) << "X moved during feed hold";
    EXPECT_EQ(run.rig.torch().isOn(), job.engine.torch_on_during_feed_hold);
    ASSERT_TRUE(run.engine->resume());
    const auto limit =
        static_cast<std::uint64_t>((run.program->cut_time_s + 30) / job.sim.period_s);
    ASSERT_EQ(run.cycles(limit, EngineState::Completed), EngineState::Completed);
    EXPECT_NEAR(run.maxProgress, 1.0, 1e-9);
}

TEST(ProfileEngine, EmergencyStopCutsTorchAndPulses) {
    const Job job = test::exampleProfileJob();
    SteppedRun run(job);
    run.toRunning();
    run.cycles(static_cast<std::uint64_t>(0.5 * run.program->cut_time_s / job.sim.period_s),
               EngineState::Completed);
    EXPECT_TRUE(run.rig.torch().isOn());
    ASSERT_TRUE(run.engine->emergencyStop());
    ASSERT_EQ(run.cycles(100, EngineState::EmergencyStop), EngineState::EmergencyStop);
    EXPECT_FALSE(run.rig.torch().isOn());
    const std::uint64_t a = run.rig.a().pulsesSent(), x = run.rig.x().pulsesSent();
    run.cycles(1000, EngineState::Completed);
    EXPECT_EQ(run.engine->state(), EngineState::EmergencyStop);
    EXPECT_EQ(run.rig.a().pulsesSent(), a) << "pulses after emergency stop";
    EXPECT_EQ(run.rig.x().pulsesSent(), x) << "pulses after emergency stop";
    EXPECT_NE(run.last.drive_states[0], DriveState::Enabled);
    EXPECT_NE(run.last.drive_states[1], DriveState::Enabled);
}

// cutcell-cli run: the profile job through the engine, the report in the machine's units.
TEST(ProfileEngine, CliRunWritesTheReportAndRunLog) {
    const auto dir =
        std::filesystem::temp_directory_path() / ("cutcell_run_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string job =
        std::string(CUTCELL_SOURCE_DIR) + "/resources/jobs/profile_cutter_job.json";
    const std::string cmd = std::string(CUTCELL_CLI) + " run " + job + " --quiet --runs " +
                            (dir / "runs").string() + " --report " +
                            (dir / "report.json").string() + " 2>&1";
    FILE* p = ::popen(cmd.c_str(), "r");
    std::string out;
    char buf[4096];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, p)) > 0)
        out.append(buf, n);
    const int status = ::pclose(p);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << out;
    const json::Value report = json::parse(readTextFile((dir / "report.json").string()));
    EXPECT_EQ(report.find("machine")->asString(), "profile_cutter_2axis");
    const Job j = test::exampleProfileJob();
    const double turn = static_cast<double>(cutcell::profileCutterSpec(j).steps_per_rev_a) *
                        cutcell::profileCutterSpec(j).pulses_per_step_a;
    EXPECT_EQ(report.find("pulses")->find("a_sent")->asNumber(), turn);
    EXPECT_LT(report.find("axes")->asArray()[1].find("max_abs_error_mm")->asNumber(),
              2 * cutcell::profileCutterSpec(j).mm_per_pulse_x);
    EXPECT_FALSE(std::filesystem::is_empty(dir / "runs"));
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace cutcell
