// Sequencing of a run (engine thread only; no allocation, lock or wait): the state machine's
// step each cycle - a controlled stop's end, home and jog moves, and a run's phases from the
// approach through settling, ignition and piercing to the source's motion and completion.
#include "core/engine/engine_impl.h"

#include <cmath>
#include <cstdio>

namespace cutcell {

// State machine step at the current path time (before the set-point is computed).
void MotionEngine::Impl::advance() {
    // A controlled stop (abort, category-1 stop) ends when the path rate (or the source)
    // reaches rest.
    if (stopping() && restReached()) {
        const Halt why = halt;
        halt = Halt::None;
        if (why == Halt::Abort) {
            captureStop(); // at rest on the path, before the hold
            holdAt(setpoint);
            setState(EngineState::Ready, EventKind::Transition,
                     "Aborted: stopped on the path at %.3f s",
                     runActive ? runProgress.time_s : moveClock.time());
            endRun("aborted");
        } else {
            disableAll();
            note("Controlled stop complete: drives disabled");
        }
        return;
    }
    if (state == EngineState::Homing || state == EngineState::Jogging) {
        if (moveClock.time() >= move.duration) {
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
    // The program's end finishes the cut (tool off) before a feed hold that comes with it can
    // pause the run: a hold in the last part of a spline's path met the path's end still
    // braking, and paused there with the torch in the Cut phase (relit on Resume).
    if (state == EngineState::Running && phase == RunPhase::Cut && sourceRan &&
        srcOut.status == SourceStatus::Done)
        finishSource();
    if (state == EngineState::Running && halt == Halt::FeedHold && restReached()) {
        setState(EngineState::Paused, EventKind::Transition, "Paused on the path at %.3f s (%s %s)",
                 runProgress.time_s, toolName(), torchCommand ? "on" : "off");
        return;
    }
    if (state == EngineState::Paused) return;
    switch (phase) {
    case RunPhase::Approach:
        if (moveClock.time() >= move.duration) {
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
        if (dev.torch && program->uses_tool && !torchFb.process_ok) {
            if (now - phaseSince > cfg.ignition_timeout_s)
                enterFault("%s: %s not reported within %.1f s", toolName(),
                           program->terms.process_ok.c_str(), cfg.ignition_timeout_s);
        } else if (dev.torch && program->uses_tool && program->pierce_s > 0 && !sourceStarted) {
            // At the first cut point (or the recovery point) the arc must go through the
            // material before it moves.
            phase = RunPhase::Pierce;
            phaseSince = now;
            note("Arc established: piercing for %.3f s", program->pierce_s);
        } else {
            startSource(false);
        }
        break;
    case RunPhase::Pierce:
        torchCommand = true;
        if (!torchFb.process_ok) { // the torch went out on a feed hold: light it again
            phase = RunPhase::Ignite;
            phaseSince = now;
        } else if (now - phaseSince >= program->pierce_s - 0.5 * T) {
            startSource(true);
        }
        break;
    case RunPhase::Cut: // ends in finishSource() above
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
                     runProgress.made, madeNounPlural(program->terms.counts), now - cutStartTime);
        endRun("completed");
        break;
    }
}

JointVector MotionEngine::Impl::startPosition() const {
    // A spline starts at its path time (a cut recovery's too); another source starts from where
    // the axes are (it reads the set-point at its start): a continuous axis needs no whole
    // turns unwound to get there.
    return program->source ? nearestEquivalent(program->start_position)
                           : splineSource.startPosition();
}

void MotionEngine::Impl::finishSource() {
    torchCommand = false;
    phase = RunPhase::Finish;
    if (source()->resumesInTime())
        note("Cut finished at path time %.3f s: %s off", program->cut_time_s, toolName());
    else
        note("Program finished (%s, %u of %u %s): %s off", source()->stateName(), srcOut.made,
             srcOut.point_count, madeNounPlural(program->terms.counts), toolName());
}

void MotionEngine::Impl::startSource(bool pierced) {
    phase = RunPhase::Cut;
    traj = TrajectoryKind::Source;
    const bool first = !sourceStarted;
    if (first) {
        SourceInput in = sourceInput();
        in.setpoint_velocity = JointVector::Zero();
        source()->start(in);
        if (program->correction) program->correction->start(in);
        sourceStarted = true;
        sourceAtRest = false;
        cutStartTime = now;
    }
    if (pierced)
        note("Pierced: cutting");
    else if (source()->resumesInTime())
        note(first ? "Arc established: cutting" : "Arc established: resuming the cut");
    else
        note(first ? "%s: %s program running" : "%s: %s program resumed",
             program->uses_tool && dev.torch ? "Process OK" : "Start",
             toString(program->source_kind));
}

} // namespace cutcell
