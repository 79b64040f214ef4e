// The master-axis and control-law motion sources on simulated devices (fast clock):
// a gear / cam follower on a line whose speed changes by +-10 %, sync-in at the commanded
// master position, a cam table replaced while running, feed hold on a flying saw, and a
// torque-mode control law at 1 kHz with emergency stop, sensor fault and supervision.
#include "core/engine/master_filter.h"
#include "core/engine/motion_engine.h"
#include "devices/sim/follower_rig.h"
#include "devices/sim/slider_rig.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace cutcell::test {
namespace {

EngineConfig fastConfig() {
    EngineConfig c;
    c.clock = ClockMode::AsFastAsPossible;
    c.spec.runs_dir.clear();
    return c;
}

struct Recorder {
    std::vector<TelemetrySample> samples;
    std::vector<EngineEvent> events;
    std::string text() const {
        std::string s;
        for (const EngineEvent& e : events)
            s += std::string(e.text.data()) + "\n";
        return s;
    }
    void drain(MotionEngine& e) {
        TelemetrySample t;
        while (e.popTelemetry(t))
            samples.push_back(t);
        EngineEvent ev;
        while (e.popEvent(ev))
            events.push_back(ev);
    }
    // Runs cycles until pred() holds (checked after every cycle); false after max cycles.
    template <class Pred> bool until(MotionEngine& e, Pred pred, int max = 200000) {
        for (int i = 0; i < max; ++i) {
            e.runCycles(1, static_cast<EngineState>(255));
            if (i % 256 == 0) drain(e);
            if (pred()) {
                drain(e);
                return true;
            }
        }
        drain(e);
        return false;
    }
};

// Enable, home, start (each command once the previous one is done).
void bringUpAndStart(MotionEngine& e) {
    e.enable();
    e.runCycles(2000, EngineState::Ready);
    ASSERT_EQ(e.state(), EngineState::Ready);
    e.home();
    e.runCycles(1, EngineState::Idle);
    e.runCycles(200000, EngineState::Ready);
    ASSERT_EQ(e.state(), EngineState::Ready);
    e.start();
    e.runCycles(1, EngineState::Idle);
    ASSERT_EQ(e.state(), EngineState::Running);
}

bool inState(const TelemetrySample& t, const char* s) {
    return std::strcmp(t.source_state.data(), s) == 0;
}

// ---- master axis --------------------------------------------------------------------------

FollowerRigOptions lineOptions() {
    FollowerRigOptions o;
    o.line.speed_mm_s = 200;
    o.line.speed_amplitude = 0.10; // +-10 %
    o.line.speed_period_s = 2;
    o.line.counts_per_mm = 100;
    o.line.noise_mm = 0.005;
    o.follower.filter_alpha = 0.2;
    o.follower.first_sync = 600; // the line is at ~300 mm when the run has started
    o.follower.start_distance = 60;
    o.follower.sync_span = 1200; // 6 s in sync: three periods of the speed change
    o.follower.cut_count = 1;
    o.follower.return_s = 1;
    o.follower.wait_position = JointVector::Zero();
    o.follower.wait_position[0] = 10;
    return o;
}

struct FollowerCell {
    explicit FollowerCell(const FollowerRigOptions& o) : rig(o) {
        EngineConfig c = fastConfig();
        rig.configure(c);
        engine = std::make_unique<MotionEngine>(rig.devices(), c);
        engine->load(rig.program());
        bringUpAndStart(*engine);
    }
    FollowerRig rig;
    std::unique_ptr<MotionEngine> engine;
};

// The filter's own bound on |master - filtered| (master_filter.h), in master units.
double filterBound(const FollowerRig& rigConst, const MasterFilter& f, double T) {
    FollowerRig& rig = const_cast<FollowerRig&>(rigConst);
    return f.accelGain() * rig.line().maxAcceleration() * T * T +
           f.noiseGain() * rig.line().maxReadingError();
}

// Over a bus a reading can come late, or not at all for a while (the same reading again, its
// age one more each cycle). The filter keeps the line's course: the same reading is not fed
// again (fed again with its age its residual runs away through the velocity), a late new one is
// compared with the estimate of its own time.
TEST(MasterSource, MasterFilterCoastsOnARepeatedReadingAndDatesALateOne) {
    const double T = 0.002, v = 1000;
    MasterFilter f(0.2);
    f.reset(0, v);
    double line = 0;
    for (int k = 1; k <= 50; ++k) { // on time
        line += v * T;
        f.update(line, T, 0);
    }
    const double held = line; // the encoder's TPDOs stop: its last reading, older each cycle
    for (int age = 1; age <= 60; ++age) {
        line += v * T;
        f.update(held, T, age);
    }
    EXPECT_NEAR(f.position(), line, 1e-9);
    EXPECT_NEAR(f.velocity(), v, 1e-9);
    // A new reading 3 cycles late (of the line then): no jump, no change of course.
    line += v * T;
    f.update(line - 3 * v * T, T, 3);
    EXPECT_NEAR(f.position(), line, 1e-9);
    EXPECT_NEAR(f.velocity(), v, 1e-9);
}

TEST(MasterSource, GearFollowerStaysInSyncWhileTheLineSpeedChangesTenPercent) {
    const FollowerRigOptions o = lineOptions();
    FollowerCell cell(o);
    Recorder run;
    ASSERT_TRUE(run.until(*cell.engine, [&] { return cell.rig.follower().cutsDone() == 1; }))
        << run.text();
    const double T = 0.001;
    const double bound = filterBound(cell.rig, cell.rig.follower().filter(), T);
    const double slaveSync = o.follower.wait_position[0] + o.follower.start_distance * 0.5;
    double worst = 0, worstActual = 0, vmin = 1e9, vmax = 0;
    int inSync = 0;
    for (const TelemetrySample& t : run.samples) {
        if (!inState(t, "in sync")) continue;
        ++inSync;
        const double line = cell.rig.line().linePosition(t.time_s);
        const double target = slaveSync + (line - o.follower.first_sync);
        worst = std::max(worst, std::fabs(t.setpoint[0] - target));
        worstActual = std::max(worstActual, std::fabs(t.actual[0] - target));
        vmin = std::min(vmin, cell.rig.line().lineSpeed(t.time_s));
        vmax = std::max(vmax, cell.rig.line().lineSpeed(t.time_s));
    }
    ASSERT_GT(inSync, 5000);
    EXPECT_LT(vmin, 0.91 * o.line.speed_mm_s) << "the line slowed by 10 % while in sync";
    EXPECT_GT(vmax, 1.09 * o.line.speed_mm_s) << "the line sped up by 10 % while in sync";
    std::printf("gear in sync: %d cycles, set-point error max %.5f mm (filter bound %.5f mm), "
                "actual %.5f mm\n",
                inSync, worst, bound, worstActual);
    EXPECT_LE(worst, bound);
    EXPECT_GT(worst, 0.1 * bound) << "the bound is not 10x above the figure it guards";
}

TEST(MasterSource, SyncInHappensAtTheCommandedMasterPosition) {
    const FollowerRigOptions o = lineOptions();
    FollowerCell cell(o);
    Recorder run;
    ASSERT_TRUE(run.until(*cell.engine, [&] {
        return cell.rig.follower().state() == SyncState::InSync;
    })) << run.text();
    run.until(
        *cell.engine, [] { return false; }, 200);
    const TelemetrySample* first = nullptr;
    const TelemetrySample* before = nullptr;
    double maxStepWaiting = 0, maxStep = 0, maxStepChange = 0;
    for (size_t k = 2; k < run.samples.size(); ++k) {
        const TelemetrySample& t = run.samples[k];
        const TelemetrySample& p = run.samples[k - 1];
        if (t.state != EngineState::Running || p.state != EngineState::Running) continue;
        const double step = t.setpoint[0] - p.setpoint[0];
        if (inState(p, "waiting") && inState(t, "waiting"))
            maxStepWaiting = std::max(maxStepWaiting, std::fabs(step));
        maxStep = std::max(maxStep, std::fabs(step));
        maxStepChange = std::max(
            maxStepChange, std::fabs(step - (p.setpoint[0] - run.samples[k - 2].setpoint[0])));
        if (!first && inState(t, "in sync")) {
            first = &t;
            before = &p;
        }
    }
    ASSERT_NE(first, nullptr);
    const double S = o.follower.first_sync;
    const double T = 0.001;
    // The first in-sync cycle is the first whose filtered master reached S.
    EXPECT_GE(first->master_position, S);
    EXPECT_LT(before->master_position, S);
    EXPECT_TRUE(inState(*before, "synchronizing"));
    // There the slave is exactly on its coupling.
    const double slaveSync = o.follower.wait_position[0] + o.follower.start_distance * 0.5;
    EXPECT_NEAR(first->setpoint[0], slaveSync + (first->master_position - S), 1e-9);
    // The true line is at S within one cycle of travel plus the filter's bound.
    const double vmax = o.line.speed_mm_s * (1 + o.line.speed_amplitude);
    const double line = cell.rig.line().linePosition(first->time_s);
    EXPECT_NEAR(line, S, vmax * T + filterBound(cell.rig, cell.rig.follower().filter(), T));
    // No jump: the carriage stood still while waiting; during the sync-in it catches up D/2
    // while the line travels D, so its speed peaks at max_u [s(u) + (u - 1/2) s'(u)] = 1.17
    // times the line's (s the quintic smoothstep); its speed changes by far less than a cycle's
    // travel from one cycle to the next.
    EXPECT_EQ(maxStepWaiting, 0);
    EXPECT_LE(maxStep, 1.18 * vmax * T);
    EXPECT_LE(maxStepChange, 0.05 * vmax * T);
    std::printf("sync-in: largest step %.4f mm, largest step change %.5f mm per cycle\n", maxStep,
                maxStepChange);
}

TEST(MasterSource, ReplacedCamTableTakesEffectAtTheNextCamCycleWithoutAJump) {
    FollowerRigOptions o = lineOptions();
    o.line.speed_amplitude = 0;
    o.line.noise_mm = 0;
    o.follower.sync_span = 1000; // five cam cycles of 200 mm
    FollowerCell cell(o);
    Recorder run;
    MasterFollower& f = cell.rig.follower();
    // Into the second cam cycle (master 100 mm past its start), then publish a new table.
    ASSERT_TRUE(run.until(*cell.engine, [&] {
        return f.state() == SyncState::InSync && f.filteredMaster() > f.syncPosition() + 300;
    }));
    const size_t publishedAt = run.samples.size();
    auto* back = f.camTables().beginWrite();
    ASSERT_NE(back, nullptr);
    (*back)[0] = feedStrokeCam(45, o.cam_period_mm); // a deeper cut
    ASSERT_TRUE(camTableProblem((*back)[0]).empty());
    f.camTables().publish();
    ASSERT_TRUE(
        run.until(*cell.engine, [&] { return f.filteredMaster() > f.syncPosition() + 700; }));
    EXPECT_EQ(f.camSwaps(), 1u);
    const CamTable oldCam = feedStrokeCam(o.feed_stroke_mm, o.cam_period_mm);
    const CamTable newCam = feedStrokeCam(45, o.cam_period_mm);
    const double S = f.syncPosition();
    const double P = o.cam_period_mm;
    size_t swapAt = 0;
    double maxStepElsewhere = 0, stepAtSwap = -1;
    for (size_t k = publishedAt; k < run.samples.size(); ++k) {
        const TelemetrySample& t = run.samples[k];
        const double u = t.master_position - S;
        const double expectOld = oldCam.at(u), expectNew = newCam.at(u);
        const bool boundary =
            std::floor(u / P) != std::floor((run.samples[k - 1].master_position - S) / P);
        if (!swapAt && boundary) swapAt = k;
        if (!swapAt) {
            EXPECT_NEAR(t.setpoint[1], expectOld, 1e-9) << "before the boundary: the old table";
        } else {
            EXPECT_NEAR(t.setpoint[1], expectNew, 1e-9) << "from the boundary on: the new table";
        }
        const double step = std::fabs(t.setpoint[1] - run.samples[k - 1].setpoint[1]);
        if (k == swapAt)
            stepAtSwap = step;
        else
            maxStepElsewhere = std::max(maxStepElsewhere, step);
    }
    ASSERT_GT(swapAt, publishedAt);
    // The table starts and ends at rest: the step at the swap is no larger than any other.
    EXPECT_LE(stepAtSwap, maxStepElsewhere);
    std::printf("cam swap at sample %zu: step %.3g mm (largest elsewhere %.3g mm)\n", swapAt,
                stepAtSwap, maxStepElsewhere);
}

TEST(MasterSource, FeedHoldFinishesTheCutReturnsAndStopsWaiting) {
    FollowerRigOptions o = lineOptions();
    o.follower.sync_span = 200;
    o.follower.cut_length = 600;
    o.follower.cut_count = 3;
    o.follower.return_s = 0.5;
    FollowerCell cell(o);
    Recorder run;
    MasterFollower& f = cell.rig.follower();
    ASSERT_TRUE(run.until(*cell.engine, [&] { return f.state() == SyncState::InSync; }));
    cell.engine->feedHold();
    ASSERT_TRUE(run.until(*cell.engine, [&] {
        return cell.engine->state() == EngineState::Paused;
    })) << run.text();
    EXPECT_EQ(f.cutsDone(), 1) << "the cut in progress was finished";
    EXPECT_EQ(run.samples.back().setpoint[0], o.follower.wait_position[0]) << "returned";
    EXPECT_FALSE(cell.rig.saw().isOn()) << "the saw stops while held";
    // Held: the line passes the next sync position without the carriage moving.
    run.until(
        *cell.engine, [] { return false; }, 2000);
    const double parked = cell.rig.carriage().truePosition();
    EXPECT_NEAR(parked, o.follower.wait_position[0], 1e-3);
    run.until(
        *cell.engine, [] { return false; }, 4000);
    EXPECT_GT(cell.rig.line().linePosition(run.samples.back().time_s),
              f.syncPosition() - o.follower.start_distance);
    EXPECT_EQ(cell.engine->state(), EngineState::Paused);
    EXPECT_NEAR(cell.rig.carriage().truePosition(), parked, 1e-6);
    cell.engine->resume();
    ASSERT_TRUE(run.until(*cell.engine, [&] {
        return cell.engine->state() == EngineState::Completed;
    })) << run.text();
    EXPECT_EQ(f.cutsDone(), 3);
}

TEST(MasterSource, InvalidMasterReadingIsAFault) {
    FollowerCell cell(lineOptions());
    Recorder run;
    ASSERT_TRUE(
        run.until(*cell.engine, [&] { return cell.rig.follower().state() == SyncState::InSync; }));
    cell.rig.line().injectInvalid(true);
    cell.engine->runCycles(1, EngineState::Fault);
    run.drain(*cell.engine);
    EXPECT_EQ(cell.engine->state(), EngineState::Fault);
    EXPECT_NE(run.text().find("master encoder"), std::string::npos) << run.text();
}

// ---- control law --------------------------------------------------------------------------

struct SliderCell {
    explicit SliderCell(StopCategory cat = StopCategory::Cat0, int strokes = 2)
        : rig(options(strokes)) {
        EngineConfig c = fastConfig();
        c.spec.estop_category = cat;
        rig.configure(c);
        engine = std::make_unique<MotionEngine>(rig.devices(), c);
        engine->load(rig.program());
        bringUpAndStart(*engine);
    }
    static SliderRigOptions options(int strokes) {
        SliderRigOptions o;
        o.law.stroke_count = strokes;
        return o;
    }
    SliderRig rig;
    std::unique_ptr<MotionEngine> engine;
};

TEST(ControlLawSource, RunsAt1kHzWithSupervisionOffOnlyInTheOpenLoopReturn) {
    SliderCell cell;
    Recorder run;
    ASSERT_TRUE(run.until(*cell.engine, [&] {
        return cell.engine->state() == EngineState::Completed;
    })) << run.text();
    EXPECT_EQ(cell.rig.law().strokesDone(), 2);
    const std::string text = run.text();
    EXPECT_NE(text.find("following-error supervision off: open-loop torque return stroke"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("following-error supervision on again"), std::string::npos) << text;
    // Said once per run, not at every stroke's return (two strokes here: two returns).
    const auto count = [&text](const std::string& what) {
        int n = 0;
        for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
            ++n;
        return n;
    };
    EXPECT_EQ(count("following-error supervision off"), 1) << text;
    EXPECT_EQ(count("following-error supervision on again"), 1) << text;
    // Supervised samples of the stroke stay well inside the following-error limit, and the
    // axis is unsupervised exactly in the open-loop phases.
    int unsupervised = 0;
    double worst = 0;
    for (const TelemetrySample& t : run.samples) {
        if (t.state != EngineState::Running) continue;
        EXPECT_EQ(t.modes[0], AxisCommandMode::Torque);
        EXPECT_EQ(t.units[0], AxisUnit::Linear);
        if (!t.supervised[0]) {
            ++unsupervised;
            EXPECT_TRUE(inState(t, "open-loop return") || inState(t, "catching"))
                << t.source_state.data();
        } else {
            worst = std::max(worst, std::fabs(t.error[0]));
        }
    }
    EXPECT_GT(unsupervised, 10);
    EXPECT_LT(worst, EngineSpec{}.following_error_limit_mm);
    std::printf("control law: %d unsupervised cycles, supervised error max %.4f mm\n", unsupervised,
                worst);
}

TEST(ControlLawSource, EmergencyStopRemovesTorqueWithinOneCycle) {
    SliderCell cell;
    Recorder run;
    ASSERT_TRUE(run.until(*cell.engine, [&] {
        return cell.rig.law().phase() == SliderPhase::Stroke &&
               cell.rig.drive().truePosition() > 80;
    }));
    ASSERT_NE(cell.rig.drive().appliedTorque(), 0);
    const std::uint64_t writes = cell.rig.drive().writes();
    cell.engine->emergencyStop();
    int cycles = 0;
    while (cell.rig.drive().appliedTorque() != 0 && cycles < 100) {
        cell.engine->runCycles(1, static_cast<EngineState>(255));
        ++cycles;
    }
    EXPECT_EQ(cycles, 1) << "torque removed in the first cycle after the request";
    EXPECT_EQ(cell.rig.drive().writes(), writes + 1);
    EXPECT_EQ(cell.engine->state(), EngineState::EmergencyStop);
    EXPECT_EQ(cell.rig.drive().read(0).state, DriveState::Disabled);
}

TEST(ControlLawSource, CategoryOneStopBrakesWithTheLawThenRemovesTorque) {
    SliderCell cell(StopCategory::Cat1);
    Recorder run;
    ASSERT_TRUE(run.until(*cell.engine, [&] {
        return cell.rig.law().phase() == SliderPhase::Stroke &&
               cell.rig.drive().truePosition() > 80;
    }));
    cell.engine->emergencyStop();
    ASSERT_TRUE(run.until(
        *cell.engine, [&] { return cell.rig.drive().read(0).state == DriveState::Disabled; }, 5000))
        << run.text();
    EXPECT_LT(std::fabs(cell.rig.drive().trueVelocity()), 0.05) << "at rest before torque off";
    EXPECT_EQ(cell.rig.drive().appliedTorque(), 0);
}

TEST(ControlLawSource, InvalidSensorIsAFaultWithTorqueOffAtOnce) {
    SliderCell cell(StopCategory::Cat1); // even where stops are category 1
    Recorder run;
    ASSERT_TRUE(run.until(*cell.engine, [&] {
        return cell.rig.law().phase() == SliderPhase::Stroke &&
               cell.rig.drive().truePosition() > 80;
    }));
    cell.rig.sensor().injectInvalid(true);
    cell.engine->runCycles(1, static_cast<EngineState>(255));
    run.drain(*cell.engine);
    EXPECT_EQ(cell.engine->state(), EngineState::Fault);
    EXPECT_EQ(cell.rig.drive().appliedTorque(), 0);
    EXPECT_EQ(cell.rig.drive().read(0).state, DriveState::Disabled);
    EXPECT_NE(run.text().find("slider position sensor: reading not valid"), std::string::npos)
        << run.text();
}

TEST(ControlLawSource, LoadRefusesADriveInAnotherCommandMode) {
    FollowerRigOptions o = lineOptions();
    FollowerRig follower(o);
    SliderRig slider(SliderRigOptions{});
    EngineDevices d = follower.devices(); // position-mode drives
    EngineConfig c = fastConfig();
    MotionEngine engine(d, c);
    engine.load(slider.program()); // wants torque mode on axis 0
    engine.runCycles(1, EngineState::Idle);
    Recorder run;
    run.drain(engine);
    EXPECT_NE(
        run.text().find("the program commands torque (CST), the drive is set to position (CSP)"),
        std::string::npos)
        << run.text();
}

} // namespace
} // namespace cutcell::test
