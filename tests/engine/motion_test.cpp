// The engine's motion: a fast-clock run reproduces the offline simulation; feed hold, resume
// and override time-scale the path with no jump in set-point or velocity.
#include "engine_fixture.h"

#include "core/machines/pipe_robot/cut_simulation.h"
#include "core/machines/pipe_robot/pipe_robot_mechanics.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"
#include "devices/machines/pipe_robot/pipe_robot_shared_mechanics.h"

#include <cmath>
#include <cstdio>

namespace cutcell::test {
namespace {

// The default job: the rigid-body arm with Coulomb friction. Before Start the drives' loops hunt
// around the first cut point (stick-slip inside the in-position window), so the engine starts the
// cut with its integrators holding some friction besides gravity, where simulateCut() starts
// from rest with exactly the holding torque: the figures agree in order, not to rounding (the
// same computation is checked to rounding on the linear and the frictionless plants below).
// Measured: engine / simulate 1.31 (joint 2), 1.37 (joint 4) on the max errors.
TEST(EngineMotion, FastClockRunOfTheDefaultJobTracksLikeSimulate) {
    SimCell cell;
    cell.toCompleted();
    TrackingReport engineReport;
    std::string outcome;
    ASSERT_TRUE(cell.engine().lastRunReport(engineReport, &outcome));
    EXPECT_EQ(outcome, "completed");
    const TrackingReport sim = simulateCut(testJob(), testPlan());
    EXPECT_EQ(engineReport.steps, sim.steps);
    int compared = 0;
    for (size_t i = 0; i < kAxisCount; ++i) {
        SCOPED_TRACE(i);
        const double e = engineReport.joints[i].max_abs, s = sim.joints[i].max_abs;
        std::printf("axis %zu: engine %.6f deg, simulate %.6f deg\n", i, e, s);
        if (s < 1e-3) continue; // an axis that barely moves (e.g. joint 1 on the rotating pipe)
        EXPECT_GT(e, s / 1.6);
        EXPECT_LT(e, s * 1.6);
        ++compared;
    }
    EXPECT_GE(compared, 3);
    const double e = engineReport.cartesian_max_abs_mm.maxCoeff();
    const double s = sim.cartesian_max_abs_mm.maxCoeff();
    EXPECT_GT(e, s / 1.6);
    EXPECT_LT(e, s * 1.6);
    EXPECT_LT(engineReport.max_torque_fraction, 1.0);
}

// The engine's figures of a fast-clock run of `job` (its own cell: six simulated drives on the
// job's shared mechanics) against simulateCut() of the same job, to rounding.
void expectEngineRunEqualsSimulate(const Job& job) {
    const CutPlan plan = planCut(job);
    ASSERT_TRUE(plan.reachable);
    CellOptions o;
    o.job = &job;
    o.program = buildPipeRobotProgram(job, plan);
    SimCell cell(o);
    cell.toCompleted();
    TrackingReport engineReport;
    std::string outcome;
    ASSERT_TRUE(cell.engine().lastRunReport(engineReport, &outcome));
    EXPECT_EQ(outcome, "completed");
    const TrackingReport sim = simulateCut(job, plan);
    constexpr double tol = 1e-9;
    EXPECT_EQ(engineReport.steps, sim.steps);
    EXPECT_NEAR(engineReport.max_torque_fraction, sim.max_torque_fraction, tol);
    for (size_t i = 0; i < kAxisCount; ++i) {
        SCOPED_TRACE(i);
        EXPECT_NEAR(engineReport.joints[i].max_abs, sim.joints[i].max_abs, tol);
        EXPECT_NEAR(engineReport.joints[i].rms, sim.joints[i].rms, tol);
        EXPECT_NEAR(engineReport.cruise_joints[i].max_abs, sim.cruise_joints[i].max_abs, tol);
    }
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(engineReport.cartesian_max_abs_mm[k], sim.cartesian_max_abs_mm[k], tol);
        EXPECT_NEAR(engineReport.on_pipe_max_abs_mm[k], sim.on_pipe_max_abs_mm[k], tol);
    }
    EXPECT_GT(sim.joints[1].max_abs, 0);
}

TEST(EngineMotion, FastClockRunOfALinearPlantJobGivesTheSameFiguresAsSimulate) {
    Job job = testJob();
    pipeRobotSpec(job).plant_model = PlantModel::Linear;
    expectEngineRunEqualsSimulate(job);
}

// Without Coulomb friction the rigid-body arm settles to rounding at the first cut point, as
// simulateCut() starts: the drives share its coupled mechanics and step them in its order.
TEST(EngineMotion, FastClockRunOfAFrictionlessRigidBodyJobGivesTheSameFiguresAsSimulate) {
    Job job = testJob();
    ASSERT_EQ(pipeRobotSpec(job).plant_model, PlantModel::RigidBody);
    for (auto& d : pipeRobotSpec(job).drives)
        d.coulomb_nm = 0;
    expectEngineRunEqualsSimulate(job);
}

TEST(EngineMotion, FastClockRunWithGravityFeedForwardGivesTheSameFiguresAsSimulate) {
    Job job = testJob();
    for (auto& d : pipeRobotSpec(job).drives)
        d.coulomb_nm = 0;
    pipeRobotSpec(job).gravity_feedforward = true;
    expectEngineRunEqualsSimulate(job);
}

// The simulated drives on the rigid-body mechanics: a drive without torque holds its axis on
// its brake against gravity; enabled, its loop takes over with the holding torque (no sag).
TEST(SharedMechanics, ADisabledDriveHoldsItsAxisOnItsBrakeAgainstGravity) {
    const Job& job = testJob();
    ASSERT_EQ(pipeRobotSpec(job).plant_model, PlantModel::RigidBody);
    const double T = job.sim.period_s;
    JointVector q0 = JointVector::Zero();
    q0[1] = deg2rad(30);
    q0[2] = deg2rad(-20);
    constexpr int kLoaded = 2; // gravity pulls hardest on this joint
    // Gravity would pull the axis away: the same mechanics with no brake and no torque move.
    {
        PipeRobotMechanics free(job, T);
        free.setState(q0);
        ASSERT_GT(std::fabs(free.holdingTorque(kLoaded)), 1.0);
        JointVector applied;
        for (int k = 0; k < 200; ++k)
            free.step(JointVector::Zero(), applied);
        EXPECT_GT(std::fabs(free.position(kLoaded) - q0[kLoaded]), 1e-3);
    }
    const auto hub = makePipeRobotSharedMechanics(job, T, q0);
    std::vector<std::unique_ptr<SimulatedDrive>> drives;
    for (int i = 0; i < kAxisCount; ++i) {
        SimulatedDriveConfig dc;
        dc.gains = pipeRobotSpec(job).controller[static_cast<size_t>(i)];
        dc.period_s = T;
        dc.mechanics = hub;
        dc.axis = i;
        drives.push_back(std::make_unique<SimulatedDrive>(dc));
    }
    double now = 0;
    std::array<DriveFeedback, kAxisCount> fb{};
    auto cycles = [&](int n) {
        for (int k = 0; k < n; ++k, now += T) {
            for (int i = 0; i < kAxisCount; ++i)
                fb[static_cast<size_t>(i)] = drives[static_cast<size_t>(i)]->read(now);
            for (int i = 0; i < kAxisCount; ++i)
                drives[static_cast<size_t>(i)]->write(q0[i]);
        }
    };
    // Disabled: every axis on its brake, exactly where it was.
    cycles(200);
    for (int i = 0; i < kAxisCount; ++i)
        EXPECT_EQ(fb[static_cast<size_t>(i)].position, q0[i]) << i;
    // Enabled: the loops take over with the holding torque and the arm does not sag.
    for (auto& d : drives)
        d->activate();
    cycles(200);
    for (int i = 0; i < kAxisCount; ++i) {
        EXPECT_EQ(fb[static_cast<size_t>(i)].state, DriveState::Enabled) << i;
        EXPECT_NEAR(fb[static_cast<size_t>(i)].position, q0[i], 1e-9) << i;
    }
    const double limit = hub->torqueLimit(kLoaded);
    EXPECT_NEAR(fb[kLoaded].torque_ratio, hub->mechanics().holdingTorque(kLoaded) / limit, 1e-6);
    // The loaded axis's drive disabled: its brake holds it, the other drives hold theirs.
    const double held = fb[kLoaded].position;
    drives[kLoaded]->deactivate();
    cycles(200);
    EXPECT_EQ(fb[kLoaded].state, DriveState::Disabled);
    EXPECT_EQ(fb[kLoaded].position, held);
    EXPECT_EQ(fb[kLoaded].velocity, 0);
    EXPECT_EQ(fb[kLoaded].torque_ratio, 0);
    for (int i = 0; i < kAxisCount; ++i)
        EXPECT_NEAR(fb[static_cast<size_t>(i)].position, q0[i], 1e-6) << i;
    // Enabled again: no jump when the loop takes over from the brake.
    drives[kLoaded]->activate();
    cycles(200);
    EXPECT_EQ(fb[kLoaded].state, DriveState::Enabled);
    EXPECT_NEAR(fb[kLoaded].position, held, 1e-6);
}

// Largest |q'| and |q''| of the program's spline (dense sampling).
void splineBounds(double& vmax, double& amax) {
    const auto& s = testProgram()->spline;
    vmax = amax = 0;
    for (double t = 0; t <= s.duration(); t += 1e-4) {
        const JointSample x = s.evaluate(t);
        vmax = std::max(vmax, x.qd.cwiseAbs().maxCoeff());
        amax = std::max(amax, x.qdd.cwiseAbs().maxCoeff());
    }
}

// Every per-cycle step of the set-point stays within the path's speed at the highest rate,
// and every change of that step within what the path's acceleration and the rate ramp allow.
void expectNoJumps(const std::vector<TelemetrySample>& t, double maxRate) {
    const double T = testJob().sim.period_s;
    double vmax = 0, amax = 0;
    splineBounds(vmax, amax);
    const double rateSlope = 1.0 / testJob().engine.feed_hold_decel_s;
    const double stepLimit = vmax * maxRate * T * 1.001;
    const double dStepLimit = (amax * maxRate * maxRate + vmax * rateSlope) * T * T * 1.01 + 1e-15;
    for (size_t k = 2; k < t.size(); ++k) {
        const JointVector d1 = t[k].setpoint - t[k - 1].setpoint;
        const JointVector d0 = t[k - 1].setpoint - t[k - 2].setpoint;
        ASSERT_LE(d1.cwiseAbs().maxCoeff(), stepLimit) << "set-point jump at sample " << k;
        ASSERT_LE((d1 - d0).cwiseAbs().maxCoeff(), dStepLimit) << "velocity jump at sample " << k;
    }
}

TEST(EngineMotion, FeedHoldStopsOnThePathAndResumeContinuesWithoutAJump) {
    SimCell cell;
    cell.toCutting(5.0);
    cell.keepTelemetry = true;
    cell.run(200, EngineState::Fault);
    cell.engine().feedHold();
    cell.runUntil(EngineState::Paused);
    const size_t pausedAt = cell.telemetry.size();
    cell.run(500, EngineState::Fault); // stays paused
    EXPECT_EQ(cell.engine().state(), EngineState::Paused);
    const JointVector held = cell.telemetry[pausedAt - 1].setpoint;
    for (size_t k = pausedAt; k < cell.telemetry.size(); ++k)
        ASSERT_EQ(cell.telemetry[k].setpoint, held) << "the set-point stays where the hold stopped";
    // The torch is off while paused (torch_on_during_feed_hold = false in the default job).
    EXPECT_FALSE(cell.telemetry.back().torch_on);
    const double progressAtPause = cell.telemetry.back().progress;
    EXPECT_GT(progressAtPause, 0.1);

    const size_t resumedAt = cell.telemetry.size();
    cell.engine().resume();
    cell.run(3000, EngineState::Fault);
    EXPECT_EQ(cell.engine().state(), EngineState::Running) << cell.eventText();
    EXPECT_GT(cell.telemetry.back().progress, progressAtPause);
    EXPECT_TRUE(cell.telemetry.back().torch_on) << "the torch is lit again before the path moves";
    expectNoJumps(cell.telemetry, 1.0);
    // The path restarts from the held point: the held set-point is the path's own at the path
    // time the engine paused and resumed at (printed to 1 ms) ...
    double pausedTau = -1, resumedTau = -2;
    for (const EngineEvent& e : cell.events) {
        std::sscanf(e.text.data(), "Paused on the path at %lf s", &pausedTau);
        std::sscanf(e.text.data(), "Resume at path time %lf s", &resumedTau);
    }
    EXPECT_EQ(resumedTau, pausedTau) << cell.eventText();
    double vmax = 0, amax = 0;
    splineBounds(vmax, amax);
    const double T = testJob().sim.period_s;
    const JointVector onPath = testProgram()->spline.evaluate(resumedTau).q;
    EXPECT_LE((onPath - held).cwiseAbs().maxCoeff(), vmax * 0.0005 + 1e-12);
    // ... and the first set-point that moves after the resume is within one cycle's travel of
    // the held one.
    size_t k = resumedAt;
    while (k < cell.telemetry.size() && cell.telemetry[k].setpoint == held)
        ++k;
    ASSERT_LT(k, cell.telemetry.size()) << "the set-point never moved after the resume";
    EXPECT_LE((cell.telemetry[k].setpoint - held).cwiseAbs().maxCoeff(), vmax * T);
}

// A feed hold so near the path's end that the path ends while it brakes: the cut finishes
// (torch off) before the run pauses, and Resume completes it without lighting the torch again
// (it paused at the end with the torch in the Cut phase and relit it on Resume).
TEST(EngineMotion, AFeedHoldThatMeetsThePathsEndFinishesTheCutFirst) {
    SimCell cell;
    const double brake_s = 0.5 * testJob().engine.feed_hold_decel_s; // path time to rest
    ASSERT_GT(brake_s, 0.02);
    cell.toCutting(testProgram()->cut_time_s - 0.5 * brake_s);
    const size_t from = cell.events.size();
    cell.engine().feedHold();
    cell.runUntil(EngineState::Paused);
    const std::string text = cell.eventText(from);
    const size_t finished = text.find("Cut finished at path time");
    const size_t paused = text.find("Paused on the path");
    ASSERT_NE(finished, std::string::npos) << text;
    EXPECT_LT(finished, paused) << text;
    EXPECT_FALSE(cell.torch().isOn());
    const size_t resumed = cell.events.size();
    cell.engine().resume();
    cell.runUntil(EngineState::Completed);
    EXPECT_EQ(cell.eventText(resumed).find("Arc established"), std::string::npos)
        << cell.eventText(resumed);
    std::string outcome;
    TrackingReport report;
    ASSERT_TRUE(cell.engine().lastRunReport(report, &outcome));
    EXPECT_EQ(outcome, "completed");
}

TEST(EngineMotion, OverrideChangesThePathRateSmoothly) {
    SimCell cell;
    cell.toCutting(3.0);
    cell.keepTelemetry = true;
    cell.engine().setOverride(1.5);
    cell.run(2000, EngineState::Fault);
    cell.engine().setOverride(0.1);
    cell.run(2000, EngineState::Fault);
    cell.engine().setOverride(1.0);
    cell.run(2000, EngineState::Fault);
    EXPECT_EQ(cell.engine().state(), EngineState::Running);
    expectNoJumps(cell.telemetry, 1.5);
}

TEST(EngineMotion, OverrideTimeScalesTheCut) {
    SimCell cell;
    cell.engine().setOverride(1.5);
    cell.keepTelemetry = true;
    cell.toCompleted();
    // From the first sample on the path to the path's end: cut_time / 1.5 (within a cycle).
    double first = -1, last = -1;
    for (const auto& t : cell.telemetry) {
        if (t.progress > 0 && first < 0) first = t.time_s;
        if (t.progress >= 1.0 && last < 0 && first >= 0) last = t.time_s;
    }
    ASSERT_GE(first, 0);
    ASSERT_GE(last, 0);
    const double T = testJob().sim.period_s;
    EXPECT_NEAR(last - first, testProgram()->cut_time_s / 1.5, 2 * T);
}

TEST(EngineMotion, AbortStopsAlongThePathAndReturnsToReady) {
    SimCell cell;
    cell.toCutting(4.0);
    cell.keepTelemetry = true;
    cell.engine().abort();
    cell.runUntil(EngineState::Ready);
    expectNoJumps(cell.telemetry, 1.0);
    EXPECT_FALSE(cell.torch().isOn());
    TrackingReport r;
    std::string outcome;
    ASSERT_TRUE(cell.engine().lastRunReport(r, &outcome));
    EXPECT_EQ(outcome, "aborted");
}

} // namespace
} // namespace cutcell::test

namespace cutcell::test {
namespace {

// Path time of a telemetry sample on the path (progress is path time / cut time).
double pathTimeOf(const TelemetrySample& s) {
    return s.progress * testProgram()->cut_time_s;
}

// Cut recovery after an emergency stop: release, reset, enable, home, then Start from the stop
// point minus a lead-in. The approach goes to the path's set-point there, the torch pierces
// again, the path ramps up from rest with no jump, and the cut runs to its end: the two runs
// together cover the whole path.
TEST(EngineCutRecovery, AfterAnEmergencyStopTheCutResumesFromTheStopPointAndCompletes) {
    SimCell cell;
    cell.keepTelemetry = true;
    cell.toCutting(6.0);
    ASSERT_FALSE(cell.telemetry.empty());
    const double stopTau = pathTimeOf(cell.telemetry.back());
    ASSERT_GT(stopTau, 5.0);
    cell.engine().emergencyStop();
    cell.cycleOnce();
    ASSERT_EQ(cell.engine().state(), EngineState::EmergencyStop);
    // The engine kept where the torch stopped (the run log's and the GUI's stop point).
    TrackingReport stopped;
    std::string how;
    RunStopPoint stop;
    ASSERT_TRUE(cell.engine().lastRunReport(stopped, &how, &stop));
    EXPECT_EQ(how, "emergency stop");
    ASSERT_TRUE(stop.valid);
    EXPECT_NEAR(stop.path_time_s, stopTau, 1.01 * testJob().sim.period_s);

    // The same path with a pierce dwell (the robot's default job has none).
    auto pierced = std::make_shared<MotionProgram>(*testProgram());
    pierced->pierce_s = 0.4;
    cell.engine().releaseEmergencyStop();
    cell.engine().reset();
    cell.run(5, EngineState::Fault);
    ASSERT_TRUE(cell.engine().load(pierced));
    cell.engine().enable();
    cell.runUntil(EngineState::Ready);
    cell.engine().home();
    cell.run(5, EngineState::Fault);
    cell.runUntil(EngineState::Ready);

    const double leadIn_s = 0.5; // along the path, before the stop point
    const double fromTau = stopTau - leadIn_s;
    const size_t eventsBefore = cell.events.size();
    cell.telemetry.clear();
    ASSERT_TRUE(cell.engine().startFrom(fromTau));
    cell.runUntil(EngineState::Completed, 400000);
    const std::string text = cell.eventText(eventsBefore);
    EXPECT_NE(text.find("cut recovery from path time"), std::string::npos) << text;
    EXPECT_NE(text.find("approach to the recovery point"), std::string::npos) << text;
    EXPECT_NE(text.find("piercing for 0.400 s"), std::string::npos) << text;

    // The torch lights with the path still at the recovery point (the first torch-on sample is
    // the path's own set-point there) ...
    size_t firstLit = 0;
    while (firstLit < cell.telemetry.size() && !cell.telemetry[firstLit].torch_on)
        ++firstLit;
    ASSERT_LT(firstLit, cell.telemetry.size());
    const JointVector atFrom = testProgram()->spline.evaluate(fromTau).q;
    EXPECT_LE((cell.telemetry[firstLit].setpoint - atFrom).cwiseAbs().maxCoeff(), 1e-3)
        << "the torch lit away from the recovery point";
    // ... it stays there for the pierce dwell ...
    size_t moved = firstLit;
    while (moved < cell.telemetry.size() &&
           cell.telemetry[moved].setpoint == cell.telemetry[firstLit].setpoint)
        ++moved;
    const double T = testJob().sim.period_s;
    EXPECT_GE(static_cast<double>(moved - firstLit) * T, 0.4 - 1.5 * T);
    // ... then the path starts from rest without a jump in set-point or velocity.
    const std::vector<TelemetrySample> cut(cell.telemetry.begin() + static_cast<long>(firstLit),
                                           cell.telemetry.end());
    expectNoJumps(cut, 1.0);
    // The recovered run reaches the end of the path and covers it from the recovery point on.
    EXPECT_NEAR(pathTimeOf(cell.telemetry.back()), testProgram()->cut_time_s, 1e-9);
    double firstTau = 1e9;
    for (size_t k = firstLit; k < cell.telemetry.size(); ++k)
        if (cell.telemetry[k].torch_on)
            firstTau = std::min(firstTau, pathTimeOf(cell.telemetry[k]));
    EXPECT_NEAR(firstTau, fromTau, 1e-6);
    EXPECT_LT(firstTau, stopTau) << "the recovered cut overlaps the first one (lead-in)";
    TrackingReport report;
    std::string outcome;
    ASSERT_TRUE(cell.engine().lastRunReport(report, &outcome));
    EXPECT_EQ(outcome, "completed");
}

TEST(EngineCutRecovery, AStartOutsideThePathIsRefusedWithTheRange) {
    SimCell cell;
    cell.toReady(true);
    const size_t before = cell.events.size();
    cell.engine().startFrom(testProgram()->cut_time_s + 1);
    cell.run(3, EngineState::Fault);
    EXPECT_EQ(cell.engine().state(), EngineState::Ready);
    EXPECT_NE(cell.eventText(before).find("outside the cut"), std::string::npos)
        << cell.eventText(before);
}

} // namespace
} // namespace cutcell::test
