// One control cycle of the motion engine (engine thread only; no allocation, lock or wait):
//   emergency stop request -> read devices -> commands -> state machine -> set-point
//   -> supervision -> tracking figures -> write devices -> telemetry -> move time.
// The state machine is in engine_sequencing.cpp, the supervision in engine_supervision.cpp,
// the figures and telemetry in engine_telemetry.cpp.
#include "core/engine/engine_impl.h"

#include <cmath>
#include <cstdio>

namespace cutcell {

void MotionEngine::Impl::runCycle() {
    now = static_cast<double>(cycle) * T;
    checkEmergencyStop();
    readDevices();
    checkEstopComplete();
    processCommands();
    if (logProblemPending.load(std::memory_order_acquire)) {
        emitf(EventKind::Info, Severity::Warning, state, state, "Run log: %s", logProblem.data());
        logProblemPending.store(false, std::memory_order_release);
    }
    superviseEnabling();
    advance();
    computeSetpoint();
    superviseDevices();
    track();
    writeDevices();
    publishTelemetry();
    stepMoveTime();
    ++cycle;
    cycles.store(cycle, std::memory_order_relaxed);
}

void MotionEngine::Impl::readDevices() {
    for (int i = 0; i < kMaxAxes; ++i)
        if (axisPresent(i))
            fb[static_cast<size_t>(i)] = dev.axes[static_cast<size_t>(i)]->read(now);
    for (size_t k = 0; k < dev.sensors.size(); ++k)
        if (dev.sensors[k]) sensorFb[k] = dev.sensors[k]->read(now);
    if (dev.torch) torchFb = dev.torch->read(now);
}

JointSample MotionEngine::Impl::evaluate() const {
    JointSample s;
    switch (traj) {
    case TrajectoryKind::Hold:
        s.q = hold;
        break;
    case TrajectoryKind::Move:
        s = move.at(moveClock.time());
        s.qd *= moveClock.rate();
        s.qdd *= moveClock.rate() * moveClock.rate(); // the rate's own change ignored
        break;
    case TrajectoryKind::Source: // the source sets the set-point (runSource)
        s.q = setpoint;
        break;
    }
    return s;
}

SourceInput MotionEngine::Impl::sourceInput() const {
    SourceInput in;
    in.now_s = now;
    in.period_s = T;
    in.actuation_delay_s = actuationDelay();
    in.axis_count = axisCount();
    in.axes = &fb;
    in.sensors = &sensorFb;
    in.setpoint = setpoint;
    in.setpoint_velocity = setpointVel;
    in.request = sourceRequest();
    in.override_fraction = overrideTarget;
    in.tool_ok = torchFb.process_ok;
    in.tool_on_during_feed_hold = cfg.spec.torch_on_during_feed_hold;
    return in;
}

bool MotionEngine::Impl::restReached() const {
    return traj == TrajectoryKind::Source ? sourceAtRest : moveClock.rate() <= 0;
}

SourceRequest MotionEngine::Impl::sourceRequest() const {
    if (traj != TrajectoryKind::Source) return SourceRequest::Track;
    if (halt == Halt::Abort) return SourceRequest::Abort;
    if (stopping()) return SourceRequest::ControlledStop;
    // Paused, holding, or waiting for the tool (resume): stay at rest.
    if (halt == Halt::FeedHold || state == EngineState::Paused || phase == RunPhase::Ignite)
        return SourceRequest::FeedHold;
    return SourceRequest::Run;
}

// The program's motion source: while it runs the program (traj Source), it sets the set-point;
// a control law also runs whenever its drives have torque, tracking the engine's set-point.
void MotionEngine::Impl::runSource() {
    sourceRan = false;
    if (!program) return;
    const bool torqueOn = state == EngineState::Ready || state == EngineState::Homing ||
                          state == EngineState::Jogging || state == EngineState::Running ||
                          state == EngineState::Paused || state == EngineState::Completed ||
                          stopping();
    const bool law = program->source_kind == MotionSourceKind::ControlLaw;
    if (traj != TrajectoryKind::Source && !(law && torqueOn)) return;
    const SourceInput in = sourceInput();
    srcOut = SourceOutput{};
    source()->update(in, srcOut);
    sourceRan = true;
    if (traj == TrajectoryKind::Source && program->correction)
        program->correction->update(in, torchCommand, srcOut);
    if (traj == TrajectoryKind::Source) {
        runProgress.take(srcOut);
        setpoint = srcOut.position;
        setpointVel = srcOut.velocity;
        setpointAcc = srcOut.acceleration;
        sourceAtRest = srcOut.status == SourceStatus::AtRest || srcOut.status == SourceStatus::Done;
        // The source switches its tool; held at rest, torch_on_during_feed_hold keeps it on.
        const bool keepOn = halt == Halt::FeedHold && sourceAtRest &&
                            cfg.spec.torch_on_during_feed_hold && torchCommand;
        if (phase == RunPhase::Cut) torchCommand = program->uses_tool && (srcOut.tool_on || keepOn);
    } else if (law) {
        // Tracking a move: the law's reference is the engine's set-point.
        setpoint = srcOut.position;
    }
}

void MotionEngine::Impl::computeSetpoint() {
    const bool drivesOff =
        state == EngineState::Idle ||
        ((state == EngineState::EmergencyStop || state == EngineState::Fault) && !stopping());
    // Without torque the set-point follows the axes, so enabling holds them where they are.
    if (drivesOff) holdAt(actualPositions());
    const JointSample s = evaluate();
    setpoint = s.q;
    setpointVel = s.qd;
    setpointAcc = s.qdd;
    runSource();
    setpointHistory[static_cast<size_t>(cycle % kSetpointHistory)] = setpoint;
}

void MotionEngine::Impl::writeDevices() {
    // Torque and velocity only while the drives are meant to have torque (the law ran this
    // cycle, or a move is followed); 0 at once after an emergency stop or a fault.
    const bool torqueOn = sourceRan && (state != EngineState::EmergencyStop &&
                                        state != EngineState::Fault && state != EngineState::Idle);
    const bool moving = state != EngineState::EmergencyStop && state != EngineState::Fault &&
                        state != EngineState::Idle;
    for (int i = 0; i < kMaxAxes; ++i) {
        if (!axisPresent(i)) continue;
        AxisDrive* d = dev.axes[static_cast<size_t>(i)];
        switch (mode(i)) {
        case AxisCommandMode::Position:
            d->write(setpoint[i] + (setpointVel[i] + 0.5 * setpointAcc[i] * cfg.setpoint_lead_s) *
                                       cfg.setpoint_lead_s);
            break;
        case AxisCommandMode::Velocity:
            d->writeVelocity(moving || stopping() ? setpointVel[i] : 0.0);
            break;
        case AxisCommandMode::Torque:
            d->writeTorque(torqueOn || (sourceRan && stopping()) ? srcOut.torque[i] : 0.0);
            break;
        }
    }
    if (dev.torch && torchCommand != torchWritten) {
        dev.torch->setOn(torchCommand);
        torchWritten = torchCommand;
        toolSwitched(torchCommand);
    }
    if (runActive && torchWritten) {
        ++toolOnCycles;
        ++cutOnCycles;
    }
}

// The move's time advances by its rate; feed hold, abort and a controlled stop ramp the rate to
// rest (PathClock).
void MotionEngine::Impl::stepMoveTime() {
    if (traj != TrajectoryKind::Move) return;
    const double target = halt != Halt::None ? 0.0 : 1.0;
    moveClock.step(target, T, T / cfg.spec.feed_hold_decel_s, move.duration);
}

} // namespace cutcell
