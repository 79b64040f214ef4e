// Supervision of the engine cycle (engine thread only; no allocation, lock or wait): the
// emergency stop's request and its completion, the drives' enabling, and every cycle the
// drives, the source's faults, following error, frozen feedback and the process tool.
#include "core/engine/engine_impl.h"

#include <cmath>
#include <cstdio>

namespace cutcell {

void MotionEngine::Impl::checkEmergencyStop() {
    if (estopLatched || !estopPressed.load(std::memory_order_acquire)) return;
    enterEmergencyStop();
    // Read back at once so the latency covers "commanded off" and "seen off".
    readDevices();
    checkEstopComplete();
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

void MotionEngine::Impl::superviseDevices() {
    const bool drivesOn = state == EngineState::Ready || state == EngineState::Homing ||
                          state == EngineState::Jogging || state == EngineState::Running ||
                          state == EngineState::Paused || state == EngineState::Completed;
    const bool stoppingLatched =
        stopping() && (state == EngineState::EmergencyStop || state == EngineState::Fault);
    if (!drivesOn && !stoppingLatched) return;
    if (sourceRan && srcOut.status == SourceStatus::Fault) {
        // A control law without trusted feedback cannot brake: torque off at once.
        faultCat0 = program->source_kind == MotionSourceKind::ControlLaw;
        return enterFault("%s source (%s): %s", toString(program->source_kind),
                          source()->stateName(), srcOut.fault);
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
        if (!source()->resumesInTime())
            return enterFault("%s: %s (%s, %s %u of %u)", toolName(),
                              program->terms.process_lost.c_str(), source()->stateName(),
                              unitSingular(program->terms.counts), runProgress.point + 1,
                              runProgress.points);
        return enterFault("%s: %s at point %u of %zu (path time %.3f s)", toolName(),
                          program->terms.process_lost.c_str(), runProgress.point,
                          program->point_count, runProgress.time_s);
    }
    arcWasOk = torchCommand && torchFb.process_ok;
}

} // namespace cutcell
