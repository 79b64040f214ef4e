// One control cycle of the motion engine (engine thread only; no allocation, lock or wait):
//   emergency stop request -> read devices -> commands -> state machine -> set-point
//   -> supervision -> tracking figures -> write devices -> telemetry -> path time.
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
    stepPathTime();
    ++cycle;
    cycles.store(cycle, std::memory_order_relaxed);
}

void MotionEngine::Impl::checkEmergencyStop() {
    if (estopLatched || !estopPressed.load(std::memory_order_acquire)) return;
    enterEmergencyStop();
    // Read back at once so the latency covers "commanded off" and "seen off".
    readDevices();
    checkEstopComplete();
}

void MotionEngine::Impl::readDevices() {
    for (int i = 0; i < kMaxAxes; ++i)
        if (axisPresent(i))
            fb[static_cast<size_t>(i)] = dev.axes[static_cast<size_t>(i)]->read(now);
    for (size_t k = 0; k < dev.sensors.size(); ++k)
        if (dev.sensors[k]) sensorFb[k] = dev.sensors[k]->read(now);
    if (dev.torch) torchFb = dev.torch->read(now);
}

void MotionEngine::Impl::checkEstopComplete() {
    if (!estopLatencyPending) return;
    for (int i = 0; i < kMaxAxes; ++i) {
        if (!axisPresent(i)) continue;
        const DriveState d = fb[static_cast<size_t>(i)].state;
        if (d != DriveState::Disabled && d != DriveState::Fault) return;
    }
    if (dev.torch && torchFb.on) return;
    estopLatencyPending = false;
    const double us = static_cast<double>(monotonicNowNs() - estopRequestSeen) / 1000.0;
    lastEstopLatencyUs.store(us, std::memory_order_relaxed);
    estopsMeasured.fetch_add(1, std::memory_order_release);
    note("Emergency stop complete: drives disabled, %s off, %.0f us after the request", toolName(),
         us);
}

void MotionEngine::Impl::superviseEnabling() {
    if (!enabling || state != EngineState::Idle) return;
    bool all = true;
    for (int i = 0; i < kMaxAxes; ++i) {
        if (!axisPresent(i)) continue;
        const DriveFeedback& f = fb[static_cast<size_t>(i)];
        if (f.state == DriveState::Fault) {
            enabling = false;
            return enterFault("Enable failed: axis %d (%s) reports drive fault 0x%04X", i,
                              axisName(i), f.fault_code);
        }
        if (f.state != DriveState::Enabled) {
            all = false;
            if (now > enableDeadline) {
                enabling = false;
                return enterFault("Enable failed: axis %d (%s) is still %s after %.2f s", i,
                                  axisName(i), toString(f.state), cfg.enable_timeout_s);
            }
        }
    }
    if (!all) return;
    enabling = false;
    holdAt(actualPositions());
    setpoint = hold;
    for (int i = 0; i < kMaxAxes; ++i) {
        lastSensed[static_cast<size_t>(i)] = fb[static_cast<size_t>(i)].position;
        travelSinceChange[static_cast<size_t>(i)] = 0;
        lastPairedSetpoint[static_cast<size_t>(i)] = setpoint[i];
    }
    // Whole sentences, no pieces glued with %s%s: the GUI translates an event by its template
    // (tools/core_messages.py).
    if (homed)
        setState(EngineState::Ready, EventKind::Transition, "Drives enabled");
    else
        setState(EngineState::Ready, EventKind::Transition,
                 "Drives enabled (not homed: Home before Start)");
}

// State machine step at the current path time (before the set-point is computed).
void MotionEngine::Impl::advance() {
    // A controlled stop (abort, category-1 stop) ends when the path rate (or the source)
    // reaches rest.
    if (stopping != StopReason::None && restReached()) {
        const StopReason why = stopping;
        stopping = StopReason::None;
        holding = false;
        if (why == StopReason::Abort) {
            captureStop(); // at rest on the path, before the hold resets the path time
            holdAt(setpoint);
            setState(EngineState::Ready, EventKind::Transition,
                     "Aborted: stopped on the path at %.3f s", tau);
            endRun("aborted");
        } else {
            disableAll();
            note("Controlled stop complete: drives disabled");
        }
        return;
    }
    if (state == EngineState::Homing || state == EngineState::Jogging) {
        if (tau >= move.duration) {
            const EngineState from = state;
            holdAt(move.to);
            if (from == EngineState::Homing) homed = true;
            setState(EngineState::Ready, EventKind::Transition,
                     from == EngineState::Homing ? "Homed: at the reference" : "Jog done");
        }
        return;
    }
    if (state == EngineState::Running || state == EngineState::Paused) stepRunning();
}

void MotionEngine::Impl::stepRunning() {
    if (state == EngineState::Running && holding && restReached() && stopping == StopReason::None) {
        setState(EngineState::Paused, EventKind::Transition, "Paused on the path at %.3f s (%s %s)",
                 tau, toolName(), torchCommand ? "on" : "off");
        return;
    }
    if (state == EngineState::Paused) return;
    switch (phase) {
    case RunPhase::Approach:
        if (tau >= move.duration) {
            holdAt(move.to);
            phase = RunPhase::Settle;
            phaseSince = now;
            settleCount = 0;
        }
        break;
    case RunPhase::Settle: {
        bool in = true;
        for (int i = 0; i < axisCount() && in; ++i) {
            const DriveFeedback& f = fb[static_cast<size_t>(i)];
            in = std::fabs(hold[i] - f.position) <= cfg.in_position_window &&
                 std::fabs(f.velocity) <= cfg.in_position_velocity;
        }
        settleCount = in ? settleCount + 1 : 0;
        if (settleCount >= cfg.settle_cycles) {
            note("At the first cut point after %.3f s of settling: %s on", now - phaseSince,
                 toolName());
            phase = RunPhase::Ignite;
            phaseSince = now;
            torchCommand = true;
        } else if (now - phaseSince > cfg.settle_timeout_s) {
            enterFault("Start failed: the axes did not settle within %.4g of the first cut point "
                       "in %.1f s",
                       cfg.in_position_window, cfg.settle_timeout_s);
        }
        break;
    }
    case RunPhase::Ignite:
        torchCommand = program->uses_tool;
        if (isSourceProgram() && (!dev.torch || !program->uses_tool || torchFb.process_ok)) {
            phase = RunPhase::Cut;
            traj = TrajectoryKind::Source;
            const bool first = !sourceStarted;
            if (first) {
                SourceInput in;
                in.now_s = now;
                in.period_s = T;
                in.actuation_delay_s = actuationDelay();
                in.axis_count = axisCount();
                in.axes = &fb;
                in.sensors = &sensorFb;
                in.setpoint = setpoint;
                in.override_fraction = overrideTarget;
                in.tool_ok = torchFb.process_ok;
                program->source->start(in);
                sourceStarted = true;
                sourceAtRest = false;
                cutStartTime = now;
            }
            note(first ? "%s: %s program running" : "%s: %s program resumed",
                 program->uses_tool && dev.torch ? "Process OK" : "Start",
                 toString(program->source_kind));
        } else if (!isSourceProgram() && dev.torch && torchFb.process_ok && !pathStarted &&
                   program->pierce_s > 0) {
            // At the first cut point (or the recovery point) the arc must go through the
            // material before it moves.
            phase = RunPhase::Pierce;
            phaseSince = now;
            note("Arc established: piercing for %.3f s", program->pierce_s);
        } else if (!isSourceProgram() && (!dev.torch || torchFb.process_ok)) {
            phase = RunPhase::Cut;
            traj = TrajectoryKind::Path;
            const bool first = !pathStarted;
            if (first) startPath();
            note(first ? "Arc established: cutting" : "Arc established: resuming the cut");
        } else if (now - phaseSince > cfg.ignition_timeout_s) {
            enterFault("%s: %s not reported within %.1f s", toolName(),
                       program->terms.process_ok.c_str(), cfg.ignition_timeout_s);
        }
        break;
    case RunPhase::Pierce:
        torchCommand = true;
        if (!torchFb.process_ok) { // the torch went out on a feed hold: light it again
            phase = RunPhase::Ignite;
            phaseSince = now;
        } else if (now - phaseSince >= program->pierce_s - 0.5 * T) {
            phase = RunPhase::Cut;
            traj = TrajectoryKind::Path;
            startPath();
            note("Pierced: cutting");
        }
        break;
    case RunPhase::Cut:
        if (isSourceProgram()) {
            if (sourceRan && srcOut.status == SourceStatus::Done) {
                pathDone = true;
                torchCommand = false;
                phase = RunPhase::Finish;
                note("Program finished (%s, %u of %u %s): %s off", program->source->stateName(),
                     srcOut.made, srcOut.point_count, madeNounPlural(program->terms.counts),
                     toolName());
            }
            break;
        }
        if (tau / T >= program->cut_time_s / T - 1e-9) {
            pathDone = true;
            torchCommand = false;
            phase = RunPhase::Finish;
            note("Cut finished at path time %.3f s: %s off", program->cut_time_s, toolName());
        }
        break;
    case RunPhase::Finish:
        break;
    case RunPhase::Close:
        // The torque of the last sample was read back this cycle: the run's figures are whole.
        for (int i = 0; i < axisCount(); ++i)
            stats.addTorqueFraction(std::fabs(fb[static_cast<size_t>(i)].torque_ratio));
        holdAt(setpoint);
        if (const RunStopPoint from = recoveryStart(); from.valid)
            setState(EngineState::Completed, EventKind::Transition,
                     "Completed: %.1f of %.1f mm in %.2f s (cut recovery from point %u of %u: "
                     "the %.1f mm before it were not cut by this run)",
                     program->length_mm - from.length_mm, program->length_mm, now - cutStartTime,
                     from.point_index + 1, from.point_count, from.length_mm);
        else if (program->terms.path_length)
            setState(EngineState::Completed, EventKind::Transition, "Completed: %.1f mm in %.2f s",
                     program->length_mm, now - cutStartTime);
        else
            setState(EngineState::Completed, EventKind::Transition, "Completed: %u %s in %.2f s",
                     sourceMade, madeNounPlural(program->terms.counts), now - cutStartTime);
        endRun("completed");
        break;
    }
}

JointSample MotionEngine::Impl::evaluate(double t) const {
    switch (traj) {
    case TrajectoryKind::Hold: {
        JointSample s;
        s.q = hold;
        return s;
    }
    case TrajectoryKind::Move:
        return move.at(t);
    case TrajectoryKind::Path:
        return program->spline.evaluate(t);
    case TrajectoryKind::Source: { // the source sets the set-point (runSource)
        JointSample s;
        s.q = setpoint;
        return s;
    }
    }
    return {};
}

JointVector MotionEngine::Impl::startPosition() const {
    // A source starts from where the axes are (it reads the set-point at its reset): a
    // continuous axis needs no whole turns unwound to get there.
    return isSourceProgram() ? nearestEquivalent(program->start_position)
                             : program->spline.evaluate(startTau).q;
}

void MotionEngine::Impl::startPath() {
    pathStarted = true;
    anchorTau = tau = startTau;
    anchorCycles = 0;
    cutStartTime = now;
    // At path time 0 the spline is at rest: full rate at once (sample 0 is this cycle, as in the
    // offline simulation). A recovered cut starts where the path moves: the rate ramps up from
    // rest (stepPathTime), so neither the set-point nor its velocity jumps.
    rate = startTau > 0 ? 0.0 : overrideTarget;
}

bool MotionEngine::Impl::restReached() const {
    return traj == TrajectoryKind::Source ? sourceAtRest : rate <= 0;
}

SourceRequest MotionEngine::Impl::sourceRequest() const {
    if (traj != TrajectoryKind::Source) return SourceRequest::Track;
    if (stopping == StopReason::Abort) return SourceRequest::Abort;
    if (stopping != StopReason::None) return SourceRequest::ControlledStop;
    // Paused, holding, or waiting for the tool (resume): stay at rest.
    if (holding || state == EngineState::Paused || phase == RunPhase::Ignite)
        return SourceRequest::FeedHold;
    return SourceRequest::Run;
}

// The program's motion source: while it runs the program (traj Source), it sets the set-point;
// a control law also runs whenever its drives have torque, tracking the engine's set-point.
void MotionEngine::Impl::runSource() {
    sourceRan = false;
    if (!isSourceProgram()) return;
    const bool torqueOn = state == EngineState::Ready || state == EngineState::Homing ||
                          state == EngineState::Jogging || state == EngineState::Running ||
                          state == EngineState::Paused || state == EngineState::Completed ||
                          stopping != StopReason::None;
    const bool law = program->source_kind == MotionSourceKind::ControlLaw;
    if (traj != TrajectoryKind::Source && !(law && torqueOn)) return;
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
    srcOut = SourceOutput{};
    program->source->update(in, srcOut);
    sourceRan = true;
    if (traj == TrajectoryKind::Source) {
        sourceProgress = srcOut.progress;
        sourcePoint = srcOut.point_index;
        sourcePoints = srcOut.point_count;
        sourceMade = srcOut.made;
        setpoint = srcOut.position;
        setpointVel = srcOut.velocity;
        setpointAcc = JointVector::Zero(); // a source gives no acceleration
        sourceAtRest = srcOut.status == SourceStatus::AtRest || srcOut.status == SourceStatus::Done;
        // The source switches its tool; held at rest, torch_on_during_feed_hold keeps it on.
        const bool keepOn =
            holding && sourceAtRest && cfg.spec.torch_on_during_feed_hold && torchCommand;
        if (phase == RunPhase::Cut) torchCommand = program->uses_tool && (srcOut.tool_on || keepOn);
    } else if (law) {
        // Tracking a move: the law's reference is the engine's set-point.
        setpoint = srcOut.position;
    }
}

double MotionEngine::Impl::trajectoryDuration() const {
    if (traj == TrajectoryKind::Move) return move.duration;
    if (traj == TrajectoryKind::Path) return program->cut_time_s;
    return 0;
}

void MotionEngine::Impl::computeSetpoint() {
    const bool drivesOff = state == EngineState::Idle ||
                           ((state == EngineState::EmergencyStop || state == EngineState::Fault) &&
                            stopping == StopReason::None);
    // Without torque the set-point follows the axes, so enabling holds them where they are.
    if (drivesOff) holdAt(actualPositions());
    const JointSample s = evaluate(tau);
    setpoint = s.q;
    setpointVel = s.qd * rate;
    setpointAcc = s.qdd * (rate * rate); // rate's own change ignored (it ramps over seconds)
    runSource();
    setpointHistory[static_cast<size_t>(cycle % kSetpointHistory)] = setpoint;
}

void MotionEngine::Impl::superviseDevices() {
    const bool drivesOn = state == EngineState::Ready || state == EngineState::Homing ||
                          state == EngineState::Jogging || state == EngineState::Running ||
                          state == EngineState::Paused || state == EngineState::Completed;
    const bool stoppingLatched =
        stopping != StopReason::None &&
        (state == EngineState::EmergencyStop || state == EngineState::Fault);
    if (!drivesOn && !stoppingLatched) return;
    if (sourceRan && srcOut.status == SourceStatus::Fault) {
        // A control law without trusted feedback cannot brake: torque off at once.
        faultCat0 = program->source_kind == MotionSourceKind::ControlLaw;
        return enterFault("%s source (%s): %s", toString(program->source_kind),
                          program->source->stateName(), srcOut.fault);
    }
    for (int i = 0; i < axisCount(); ++i) {
        const auto a = static_cast<size_t>(i);
        const DriveFeedback& f = fb[a];
        if (stoppingLatched && f.state != DriveState::Enabled) continue;
        if (f.state == DriveState::Fault)
            return enterFault("axis %d (%s): drive fault 0x%04X at %.3f %s (set-point %.3f %s)", i,
                              axisName(i), f.fault_code, displayValue(i, f.position), unit(i),
                              displayValue(i, setpoint[i]), unit(i));
        if (f.state != DriveState::Enabled)
            return enterFault("axis %d (%s): drive left operation (now %s)", i, axisName(i),
                              toString(f.state));
        if (!f.feedback_valid)
            return enterFault("axis %d (%s): feedback not valid (stale data) at %.3f %s", i,
                              axisName(i), displayValue(i, f.position), unit(i));
        // Against the set-point of the cycle the feedback belongs to: a TPDO late on the bus
        // says where the axis was then, not where it is (track() takes the same pair). A late
        // TPDO repeats the last position and its pair stands still too: not frozen.
        const double sp = setpointForFeedback(i);
        const double pairedTravel = std::fabs(sp - lastPairedSetpoint[a]);
        lastPairedSetpoint[a] = sp;
        const bool supervised = !sourceRan || srcOut.supervised[a];
        if (supervised != supervisedNow[a]) {
            supervisedNow[a] = supervised;
            if (supervisionNotes[a] < 2) {
                ++supervisionNotes[a];
                if (supervised)
                    note("axis %d (%s): following-error supervision on again (further changes "
                         "in this run are not logged)",
                         i, axisName(i));
                else
                    note("axis %d (%s): following-error supervision off: %s", i, axisName(i),
                         srcOut.unsupervised_reason);
            }
        }
        if (!supervised) { // no position reference (open-loop torque): nothing to compare
            travelSinceChange[a] = 0;
            lastSensed[a] = f.position;
            continue;
        }
        if (f.position == lastSensed[a]) {
            travelSinceChange[a] += pairedTravel;
            if (travelSinceChange[a] > cfg.frozen_feedback_travel)
                return enterFault(
                    "axis %d (%s): feedback frozen at %.4f %s while the set-point moved %.4f %s", i,
                    axisName(i), displayValue(i, f.position), unit(i),
                    displayValue(i, travelSinceChange[a]), unit(i));
        } else {
            travelSinceChange[a] = 0;
            lastSensed[a] = f.position;
        }
        const double e = sp - f.position;
        if (std::fabs(e) > followingLimit(i))
            return enterFault("axis %d (%s): following error %.3f %s exceeds %.3f %s (set-point "
                              "%.3f %s, actual %.3f %s, feedback %u cycle(s) late)",
                              i, axisName(i), displayValue(i, e), unit(i),
                              displayValue(i, followingLimit(i)), unit(i), displayValue(i, sp),
                              unit(i), displayValue(i, f.position), unit(i),
                              static_cast<unsigned>(f.age_cycles));
    }
    if (dev.torch && torchFb.fault_code != 0)
        return enterFault("%s: fault 0x%04X", toolName(), torchFb.fault_code);
    if (dev.torch && torchCommand && arcWasOk && !torchFb.process_ok) {
        if (isSourceProgram())
            return enterFault("%s: %s (%s, %s %u of %u)", toolName(),
                              program->terms.process_lost.c_str(), program->source->stateName(),
                              unitSingular(program->terms.counts), srcOut.point_index + 1,
                              srcOut.point_count);
        const std::uint32_t point =
            program ? static_cast<std::uint32_t>(tau / program->spline.dt()) : 0;
        return enterFault("%s: %s at point %u of %zu (path time %.3f s)", toolName(),
                          program ? program->terms.process_lost.c_str() : "process lost", point,
                          program ? program->point_count : size_t{0}, tau);
    }
    arcWasOk = torchCommand && torchFb.process_ok;
}

void MotionEngine::Impl::track() {
    if (!runActive || (phase != RunPhase::Cut && phase != RunPhase::Finish)) return;
    if (state != EngineState::Running && state != EngineState::Paused) return;
    const JointVector actual = actualPositions();
    // The torque read now was applied after the previous sample (simulateCut's order).
    if (samples > 0)
        for (int i = 0; i < axisCount(); ++i)
            stats.addTorqueFraction(std::fabs(fb[static_cast<size_t>(i)].torque_ratio));
    // One tip computation per cycle for the overall figures, the cruise figures and telemetry.
    const TipSample& tips = tipsThisCycle(program->tip_model.get());
    // The supervision's pairs: each feedback with the set-point of its own cycle.
    const JointVector matched = setpointsForFeedback();
    stats.add(matched, actual, tips);
    if (tau >= program->cruise_from_s && tau <= program->cruise_to_s)
        cruise.add(matched, actual, tips);
    if (pathDone && samples >= minRunSteps) phase = RunPhase::Close;
    ++samples;
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
            d->writeVelocity(moving || stopping != StopReason::None ? setpointVel[i] : 0.0);
            break;
        case AxisCommandMode::Torque:
            d->writeTorque(
                torqueOn || (sourceRan && stopping != StopReason::None) ? srcOut.torque[i] : 0.0);
            break;
        }
    }
    if (dev.torch && torchCommand != torchWritten) {
        dev.torch->setOn(torchCommand);
        torchWritten = torchCommand;
    }
}

void MotionEngine::Impl::publishTelemetry() {
    if (cfg.telemetry_every_n_cycles > 1 && cycle % cfg.telemetry_every_n_cycles != 0) return;
    TelemetrySample t;
    t.time_s = now;
    t.state = state;
    t.axis_count = static_cast<std::uint8_t>(axisCount());
    for (int i = 0; i < kMaxAxes; ++i) {
        const auto a = static_cast<size_t>(i);
        t.units[a] = program && program->axis_linear[a] ? AxisUnit::Linear : AxisUnit::Rotary;
        t.modes[a] = mode(i);
        t.supervised[a] = supervisedNow[a];
        t.command[i] = t.modes[a] == AxisCommandMode::Torque ? (sourceRan ? srcOut.torque[i] : 0)
                       : t.modes[a] == AxisCommandMode::Velocity ? setpointVel[i]
                                                                 : setpoint[i];
    }
    if (isSourceProgram()) {
        std::snprintf(t.source_state.data(), t.source_state.size(), "%s",
                      program->source->stateName());
        t.master_position = srcOut.master_position;
    }
    t.setpoint = setpoint;
    t.actual = actualPositions();
    t.error = setpointsForFeedback() - t.actual; // as supervised and reported
    if (program && program->tip_model)
        t.cartesian_error_mm = tipsThisCycle(program->tip_model.get()).error();
    if (isSourceProgram() && (state == EngineState::Running || state == EngineState::Paused ||
                              state == EngineState::Completed)) {
        t.progress = state == EngineState::Completed ? 1 : srcOut.progress;
        t.point_index = srcOut.point_index;
        t.point_count = srcOut.point_count;
        t.made = sourceMade;
        t.elapsed_s = runActive ? now - runStartTime : runEndTime - runStartTime;
    } else if (program && (state == EngineState::Running || state == EngineState::Paused ||
                           state == EngineState::Completed)) {
        const bool onPath = traj == TrajectoryKind::Path || phase == RunPhase::Finish ||
                            phase == RunPhase::Close || state == EngineState::Completed;
        const double pathT = state == EngineState::Completed ? program->cut_time_s
                             : onPath                        ? std::min(tau, program->cut_time_s)
                                      : startTau; // before the path moves: where it will start
        t.progress = program->cut_time_s > 0 ? pathT / program->cut_time_s : 0;
        t.point_count = static_cast<std::uint32_t>(program->point_count);
        t.point_index = static_cast<std::uint32_t>(std::min<double>(
            pathT / program->spline.dt(), static_cast<double>(program->point_count)));
        t.made = piercesMade();
        t.elapsed_s = runActive ? now - runStartTime : runEndTime - runStartTime; // since Start
        const double r = rate > 0 ? rate : overrideTarget;
        t.remaining_s = (program->cut_time_s - pathT) / r;
    }
    t.override_fraction = overrideTarget;
    for (int i = 0; i < kMaxAxes; ++i)
        t.drive_states[static_cast<size_t>(i)] =
            axisPresent(i) ? fb[static_cast<size_t>(i)].state : DriveState::Disabled;
    t.torch_on = torchFb.on;
    t.process_ok = torchFb.process_ok;
    t.homed = homed;
    if (!telemetry.push(t)) telemetryDropped.fetch_add(1, std::memory_order_relaxed);
}

// The tips of (set-point, actual) for this cycle: computed on first use, then shared.
const TipSample& MotionEngine::Impl::tipsThisCycle(const TipModel* model) {
    if (tipsCycle != cycle || tipsModel != model) {
        cycleTips = tipSample(model, setpoint, actualPositions());
        tipsCycle = cycle;
        tipsModel = model;
    }
    return cycleTips;
}

// Path time: tau advances by rate * T. While the rate is steady tau is computed from an
// anchor (tau0 + rate * n * T) so no rounding accumulates; at rate 1 from 0 it is n * T,
// exactly the offline simulation's sample times.
void MotionEngine::Impl::stepPathTime() {
    if (traj == TrajectoryKind::Hold || traj == TrajectoryKind::Source) return;
    double target = traj == TrajectoryKind::Path ? overrideTarget : 1.0;
    if (holding || stopping != StopReason::None) target = 0;
    if (traj == TrajectoryKind::Path && phase == RunPhase::Ignite) target = 0; // wait for the arc
    const double step = T / cfg.spec.feed_hold_decel_s;
    const double old = rate;
    rate = rate < target ? std::min(target, rate + step) : std::max(target, rate - step);
    if (rate != old) {
        tau += 0.5 * (old + rate) * T;
        anchorTau = tau;
        anchorCycles = 0;
    } else {
        ++anchorCycles;
        tau = anchorTau + rate * (static_cast<double>(anchorCycles) * T);
    }
    const double end = trajectoryDuration();
    if (tau > end) tau = end;
}

} // namespace cutcell
