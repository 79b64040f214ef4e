#include "engine_fixture.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"
#include "devices/machines/pipe_robot/pipe_robot_shared_mechanics.h"

namespace cutcell::test {

const Job& testJob() {
    static const Job job = defaultJob();
    return job;
}
const CutPlan& testPlan() {
    static const CutPlan plan = planCut(testJob());
    return plan;
}
std::shared_ptr<const MotionProgram> testProgram() {
    static const auto program = buildPipeRobotProgram(testJob(), testPlan());
    return program;
}

std::shared_ptr<const MotionProgram> quickProgram() {
    static const auto program = [] {
        Job job = testJob();
        job.cut.speed_mm_s = 40;
        job.sim.duration_s = 0;
        return buildPipeRobotProgram(job, planCut(job));
    }();
    return program;
}

SimCell::SimCell(const CellOptions& o)
    : program_(o.program ? o.program
               : o.quick ? quickProgram()
                         : testProgram()) {
    const Job& job = o.job ? *o.job : testJob();
    EngineDevices devices;
    // The six drives share the job's mechanics, as in the simulated cell (the plant of
    // simulateCut()).
    JointVector q0 = JointVector::Zero();
    q0[0] = deg2rad(o.chuck_start_deg);
    const auto mechanics = makePipeRobotSharedMechanics(job, job.sim.period_s, q0);
    for (int i = 0; i < kAxisCount; ++i) {
        SimulatedDriveConfig dc;
        dc.gains = cutcell::pipeRobotSpec(job).controller[static_cast<size_t>(i)];
        dc.plant = cutcell::pipeRobotSpec(job).plant[static_cast<size_t>(i)];
        dc.period_s = job.sim.period_s;
        dc.initial_position = q0[i];
        dc.mechanics = mechanics;
        dc.axis = i;
        drives_.push_back(std::make_unique<SimulatedDrive>(dc));
        devices.axes[static_cast<size_t>(i)] = drives_.back().get();
    }
    devices.torch = &torch_;
    EngineConfig config;
    config.period_s = job.sim.period_s;
    config.clock = o.clock;
    config.spec = job.engine;
    config.spec.estop_category = o.category;
    config.spec.runs_dir = o.runs_dir;
    config.telemetry_every_n_cycles = o.telemetry_every;
    config.in_position_window = pipeRobotInPositionWindow(job, config.in_position_window);
    if (o.quick) config.spec.home_speed_deg_s = 90;
    engine_ = std::make_unique<MotionEngine>(devices, config);
    engine_->load(program_);
}

EngineState SimCell::run(std::uint64_t cycles, EngineState until) {
    EngineState s = engine_->state();
    for (std::uint64_t k = 0; k < cycles; ++k) {
        s = engine_->runCycles(1, until);
        EngineEvent e;
        while (engine_->popEvent(e))
            events.push_back(e);
        TelemetrySample t;
        while (engine_->popTelemetry(t))
            if (keepTelemetry) telemetry.push_back(t);
        if (s == until && cycles > 1) break;
    }
    return s;
}

void SimCell::runUntil(EngineState s, std::uint64_t max) {
    // Drain every 1000 cycles: run() per cycle would be slow for long runs.
    std::uint64_t done = 0;
    while (engine_->state() != s && done < max) {
        engine_->runCycles(1000, s);
        done += 1000;
        EngineEvent e;
        while (engine_->popEvent(e))
            events.push_back(e);
        TelemetrySample t;
        while (engine_->popTelemetry(t))
            if (keepTelemetry) telemetry.push_back(t);
    }
    ASSERT_EQ(engine_->state(), s) << "events:\n" << eventText();
}

std::string SimCell::eventText(size_t from) const {
    std::string out;
    for (size_t i = from; i < events.size(); ++i) {
        out += events[i].text.data();
        out += '\n';
    }
    return out;
}

bool SimCell::drivesAllDisabled() {
    for (auto& d : drives_) {
        const DriveState s = d->read(0).state; // no torque: disabled or faulted
        if (s != DriveState::Disabled && s != DriveState::Fault) return false;
    }
    return true;
}

void SimCell::toReady(bool homed) {
    engine_->enable();
    runUntil(EngineState::Ready);
    if (homed) {
        engine_->home();
        cycleOnce();
        runUntil(EngineState::Ready);
    }
}
void SimCell::toHoming() {
    toReady(false);
    engine_->home();
    cycleOnce();
    ASSERT_EQ(engine_->state(), EngineState::Homing);
}
void SimCell::toJogging() {
    toReady(true);
    engine_->jog(1, deg2rad(10));
    cycleOnce();
    ASSERT_EQ(engine_->state(), EngineState::Jogging);
}
void SimCell::toRunning() {
    toReady(true);
    engine_->start();
    cycleOnce();
    ASSERT_EQ(engine_->state(), EngineState::Running);
}
void SimCell::toCutting(double path_s) {
    toRunning();
    // Until the arc is established (the cut's first sample), then path_s further.
    for (int k = 0; k < 200000; ++k) {
        cycleOnce();
        if (!events.empty() &&
            std::string(events.back().text.data()).find("Arc established") != std::string::npos)
            break;
    }
    run(static_cast<std::uint64_t>(path_s / testJob().sim.period_s), EngineState::Fault);
    ASSERT_EQ(engine_->state(), EngineState::Running) << eventText();
}
void SimCell::toPaused() {
    toCutting(2.0);
    engine_->feedHold();
    runUntil(EngineState::Paused);
}
void SimCell::toCompleted() {
    toRunning();
    runUntil(EngineState::Completed);
}
void SimCell::toEmergencyStop() {
    toReady(true);
    engine_->emergencyStop();
    cycleOnce();
    ASSERT_EQ(engine_->state(), EngineState::EmergencyStop);
}
void SimCell::toFault() {
    toReady(true);
    drive(3).injectFault(0x7500);
    cycleOnce();
    ASSERT_EQ(engine_->state(), EngineState::Fault);
}

} // namespace cutcell::test
