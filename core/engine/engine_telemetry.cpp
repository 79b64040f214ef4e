// What the engine cycle reports (engine thread only; no allocation, lock or wait): the run's
// tracking figures and the telemetry sample of each cycle.
#include "core/engine/engine_impl.h"

#include <cmath>
#include <cstdio>

namespace cutcell {

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
    if (runProgress.time_s >= program->cruise_from_s && runProgress.time_s <= program->cruise_to_s)
        cruise.add(matched, actual, tips);
    if (phase == RunPhase::Finish && samples >= minRunSteps) phase = RunPhase::Close;
    ++samples;
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
    if (program) {
        std::snprintf(t.source_state.data(), t.source_state.size(), "%s", source()->stateName());
        t.master_position = srcOut.master_position;
        if (sourceRan) t.process = srcOut.process;
    }
    t.setpoint = setpoint;
    t.actual = actualPositions();
    t.error = setpointsForFeedback() - t.actual; // as supervised and reported
    if (program && program->tip_model)
        t.cartesian_error_mm = tipsThisCycle(program->tip_model.get()).error();
    if (program && (state == EngineState::Running || state == EngineState::Paused ||
                    state == EngineState::Completed)) {
        const bool completed = state == EngineState::Completed;
        t.progress = completed ? 1 : runProgress.progress;
        t.point_index = runProgress.point;
        t.point_count = runProgress.points;
        t.made = runProgress.made;
        t.elapsed_s = runActive ? now - runStartTime : runEndTime - runStartTime; // since Start
        t.remaining_s = completed ? 0 : runProgress.remaining_s;
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

} // namespace cutcell
