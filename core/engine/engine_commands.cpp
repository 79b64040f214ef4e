// The motion engine's commands and state transitions (engine thread only). Every accepted
// command changes state or says what it did; every refused one says why, as an event.
#include "core/common/c_format.h"
#include "core/engine/engine_impl.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace cutcell {

namespace {
bool inMotion(EngineState s) {
    return s == EngineState::Homing || s == EngineState::Jogging || s == EngineState::Running ||
           s == EngineState::Paused;
}
bool latched(EngineState s) {
    return s == EngineState::EmergencyStop || s == EngineState::Fault;
}
const char* latchedReason(EngineState s) {
    return s == EngineState::EmergencyStop ? "emergency stop latched (release it, then Reset)"
                                           : "fault latched (Reset first)";
}
} // namespace

// ---- helpers ---------------------------------------------------------------------------

double MotionEngine::Impl::speedLimit(int i) const {
    const bool linear = program && program->axis_linear[static_cast<size_t>(i)];
    return linear ? cfg.spec.home_speed_mm_s : deg2rad(cfg.spec.home_speed_deg_s);
}
JointVector MotionEngine::Impl::homeTarget() const {
    return nearestEquivalent(program->reference);
}
JointVector MotionEngine::Impl::nearestEquivalent(JointVector target) const {
    for (int i = 0; i < axisCount(); ++i) {
        if (!program->axis_continuous[static_cast<size_t>(i)]) continue;
        // The reference's equivalent nearest to the set-point: the difference wrapped into
        // [-pi, pi).
        const double d = target[i] - setpoint[i];
        target[i] = setpoint[i] + (d - 2 * kPi * std::floor((d + kPi) / (2 * kPi)));
    }
    return target;
}
double MotionEngine::Impl::followingLimit(int i) const {
    const bool linear = program && program->axis_linear[static_cast<size_t>(i)];
    return linear ? cfg.spec.following_error_limit_mm : deg2rad(cfg.spec.following_error_limit_deg);
}
double MotionEngine::Impl::displayValue(int i, double v) const {
    const bool linear = program && program->axis_linear[static_cast<size_t>(i)];
    return linear ? v : rad2deg(v);
}
const char* MotionEngine::Impl::unit(int i) const {
    return program && program->axis_linear[static_cast<size_t>(i)] ? "mm" : "deg";
}
const char* MotionEngine::Impl::axisName(int i) const {
    // c_str() of a string that lives as long as the program: no allocation.
    if (program && !program->axis_names[static_cast<size_t>(i)].empty())
        return program->axis_names[static_cast<size_t>(i)].c_str();
    return "axis";
}

void MotionEngine::Impl::emit(EventKind kind, Severity sev, EngineState from, EngineState to,
                              const char* fmt, va_list ap) {
    EngineEvent e = newEvent(kind);
    e.severity = sev;
    e.from = from;
    e.to = to;
    vsnprintfC(e.text.data(), e.text.size(), fmt, ap);
    pushEvent(e);
}

EngineEvent MotionEngine::Impl::newEvent(EventKind kind) const {
    EngineEvent e;
    e.time_s = now;
    e.wall_ms = std::chrono::duration_cast<std::chrono::milliseconds>(
                    std::chrono::system_clock::now().time_since_epoch())
                    .count();
    e.kind = kind;
    e.run_id = runId;
    return e;
}

void MotionEngine::Impl::pushEvent(const EngineEvent& e) {
    if (!events.push(e)) eventsDropped.fetch_add(1, std::memory_order_relaxed);
    if (!logEvents.push(e)) logDropped.fetch_add(1, std::memory_order_relaxed);
}

void MotionEngine::Impl::emitf(EventKind kind, Severity sev, EngineState from, EngineState to,
                               const char* fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    emit(kind, sev, from, to, fmt, ap);
    va_end(ap);
}

void MotionEngine::Impl::note(const char* fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    emit(EventKind::Info, Severity::Info, state, state, fmt, ap);
    va_end(ap);
}

void MotionEngine::Impl::refuse(CommandType c, const char* fmt, ...) {
    char reason[200];
    va_list ap;
    va_start(ap, fmt);
    vsnprintfC(reason, sizeof reason, fmt, ap);
    va_end(ap);
    emitf(EventKind::Refusal, Severity::Warning, state, state, "%s refused: %s", toString(c),
          reason);
}

void MotionEngine::Impl::setState(EngineState s, EventKind kind, const char* fmt, ...) {
    const EngineState from = state;
    state = s;
    publicState.store(s, std::memory_order_release);
    va_list ap;
    va_start(ap, fmt);
    emit(kind, kind == EventKind::Fault ? Severity::Error : Severity::Info, from, s, fmt, ap);
    va_end(ap);
}

double MotionEngine::Impl::setpointForFeedback(int i) const {
    const std::uint64_t age =
        std::min<std::uint64_t>({fb[static_cast<size_t>(i)].age_cycles, cycle,
                                 static_cast<std::uint64_t>(kSetpointHistory - 1)});
    if (age == 0) return setpoint[i];
    return setpointHistory[static_cast<size_t>((cycle - age) % kSetpointHistory)][i];
}

JointVector MotionEngine::Impl::setpointsForFeedback() const {
    JointVector q = setpoint;
    for (int i = 0; i < kMaxAxes; ++i)
        if (axisPresent(i)) q[i] = setpointForFeedback(i);
    return q;
}

JointVector MotionEngine::Impl::actualPositions() const {
    JointVector q = setpoint;
    for (int i = 0; i < kMaxAxes; ++i)
        if (axisPresent(i)) q[i] = fb[static_cast<size_t>(i)].position;
    return q;
}

void MotionEngine::Impl::holdAt(const JointVector& q) {
    traj = TrajectoryKind::Hold;
    hold = q;
    moveClock.restart(0, 0);
}

// ---- transitions -----------------------------------------------------------------------

void MotionEngine::Impl::disableAll() {
    // Torque-mode axes also get a zero torque at this cycle's write (writeDevices).
    for (int i = 0; i < kMaxAxes; ++i)
        if (axisPresent(i)) dev.axes[static_cast<size_t>(i)]->deactivate();
    enabling = false;
    homed = false;
    halt = Halt::None;
    holdAt(actualPositions());
}

void MotionEngine::Impl::stopDevices(StopCategory category, Halt reason) {
    torchCommand = false;
    if (dev.torch) dev.torch->setOn(false); // at once, not at the cycle's write
    if (torchWritten) toolSwitched(false);
    torchWritten = false;
    const bool moving = traj == TrajectoryKind::Source
                            ? !sourceAtRest
                            : traj == TrajectoryKind::Move && moveClock.rate() > 0;
    if (category == StopCategory::Cat0 || !moving)
        disableAll();
    else
        halt = reason; // decelerate along the path, then disable (advance())
}

void MotionEngine::Impl::endRun(const char* outcome) {
    if (!runActive) return;
    runActive = false;
    runEndTime = now;
    const std::uint64_t g = resultGeneration.load(std::memory_order_relaxed);
    RunResult& r = results[(g + 1) % 2];
    r.report.reachable = true;
    r.report.axis_count = axisCount();
    for (int i = 0; i < kMaxAxes; ++i) // before fill(): it gives each axis its unit
        r.report.axis_linear[static_cast<size_t>(i)] =
            program && program->axis_linear[static_cast<size_t>(i)];
    stats.fill(r.report);
    cruise.fillCruise(r.report);
    if (program && program->correction) program->correction->fill(r.report);
    r.report.length_mm = program ? program->length_mm : 0;
    r.report.cut_time_s = program ? program->cut_time_s : 0;
    r.report.simulated_s = samples > 0 ? static_cast<double>(samples - 1) * T : 0;
    r.run_id = runId;
    r.stop = stopPoint;
    r.end = stopPoint.valid ? stopPoint : currentPoint();
    stopPoint = RunStopPoint{};
    r.start = recoveryStart();
    snprintfC(r.method.data(), r.method.size(), "%s", program ? program->method.c_str() : "");
    snprintfC(r.outcome.data(), r.outcome.size(), "%s", outcome);
    resultGeneration.store(g + 1, std::memory_order_release);
    emitf(EventKind::RunEnded, Severity::Info, state, state, "Run %u ended: %s (%ld samples)",
          runId, outcome, samples);
}

RunStopPoint MotionEngine::Impl::recoveryStart() const {
    RunStopPoint s;
    if (!program || startTau <= 0 || program->cut_time_s <= 0) return s;
    s.valid = true;
    s.path_time_s = startTau;
    s.progress = startTau / program->cut_time_s;
    s.length_mm = s.progress * program->length_mm; // the recovery's own measure (RunStarted)
    s.point_index = static_cast<std::uint32_t>(startTau / program->spline.dt());
    s.point_count = static_cast<std::uint32_t>(program->point_count);
    return s;
}

RunStopPoint MotionEngine::Impl::currentPoint() const {
    RunStopPoint p;
    if (!program) return p;
    p.valid = true;
    p.elapsed_s = (runActive ? now : runEndTime) - runStartTime;
    // A source in time has a path time to resume from; the others keep their own count
    // (pieces, strokes).
    p.path_time_s = runProgress.time_s;
    p.progress = runProgress.progress;
    p.length_mm = program->terms.path_length ? runProgress.progress * program->length_mm : 0;
    p.point_index = runProgress.point;
    p.point_count =
        runProgress.points ? runProgress.points : static_cast<std::uint32_t>(program->point_count);
    p.made = runProgress.made;
    p.tool_starts = toolStarts;
    p.tool_on_s = static_cast<double>(toolOnCycles) * T;
    return p;
}

void MotionEngine::Impl::toolSwitched(bool on) {
    if (!runActive || !program) return;
    const double length = runProgress.progress * program->length_mm;
    if (on) {
        ++toolStarts;
        cutOnCycles = 0;
        cutStartLength = length;
        return;
    }
    // One cut ended (its arc off): the consumables count it (RunRecordSink::cutEnded).
    EngineEvent e = newEvent(EventKind::CutEnded);
    e.from = e.to = state;
    e.cut_tool_on_s = static_cast<double>(cutOnCycles) * T;
    e.cut_length_mm = program->terms.path_length ? std::max(0.0, length - cutStartLength) : 0.0;
    snprintfC(e.text.data(), e.text.size(), "%s off after %.3f s, %.1f mm", toolName(),
              e.cut_tool_on_s, e.cut_length_mm);
    pushEvent(e);
}

void MotionEngine::Impl::captureStop() {
    if (!runActive || !program) return;
    stopPoint = currentPoint();
}

void MotionEngine::Impl::enterEmergencyStop() {
    captureStop();
    estopLatched = true;
    latchPress = estopPresses.load(std::memory_order_acquire);
    estopRequestSeen = estopRequestNs.load(std::memory_order_relaxed);
    estopLatencyPending = true;
    const EngineState from = state;
    stopDevices(cfg.spec.estop_category, Halt::EmergencyCat1);
    const bool cat0 = !stopping();
    setState(EngineState::EmergencyStop, EventKind::Transition,
             "Emergency stop (%s, from %s): %s off, drives %s", toString(cfg.spec.estop_category),
             toString(from), toolName(),
             cat0 ? "disabled" : "stopping along the path, then disabled");
    endRun("emergency stop");
}

void MotionEngine::Impl::enterFault(const char* fmt, ...) {
    char reason[200];
    va_list ap;
    va_start(ap, fmt);
    vsnprintfC(reason, sizeof reason, fmt, ap);
    va_end(ap);
    if (latched(state)) {
        // A second fault during a controlled stop: no more waiting, torque off now.
        const bool wasStopping = stopping();
        disableAll();
        if (wasStopping)
            emitf(EventKind::Fault, Severity::Error, state, state,
                  "Fault: %s (controlled stop cut short: drives disabled)", reason);
        else
            emitf(EventKind::Fault, Severity::Error, state, state, "Fault: %s", reason);
        return;
    }
    captureStop();
    const StopCategory category = faultCat0 ? StopCategory::Cat0 : cfg.spec.estop_category;
    faultCat0 = false;
    stopDevices(category, Halt::FaultCat1);
    char outcome[120];
    snprintfC(outcome, sizeof outcome, "fault: %.110s", reason);
    setState(EngineState::Fault, EventKind::Fault, "Fault: %s; %s off, %s stop", reason, toolName(),
             toString(category));
    endRun(outcome);
}

void MotionEngine::Impl::beginMove(const JointVector& target, EngineState moveState) {
    JointVector limit = JointVector::Zero();
    for (int i = 0; i < kMaxAxes; ++i)
        limit[i] = speedLimit(i);
    move = JointMove::make(setpoint, target, limit);
    traj = TrajectoryKind::Move;
    moveClock.restart(0, 1);
    halt = Halt::None;
    if (moveState == state) return;
    // The speed limits in the units of the axes the program has (deg/s rotary, mm/s linear).
    bool rotary = false, linear = false;
    for (int i = 0; i < axisCount(); ++i)
        (program->axis_linear[static_cast<size_t>(i)] ? linear : rotary) = true;
    char limits[80];
    if (rotary && linear)
        snprintfC(limits, sizeof limits, "%.1f deg/s, %.1f mm/s", cfg.spec.home_speed_deg_s,
                  cfg.spec.home_speed_mm_s);
    else if (linear)
        snprintfC(limits, sizeof limits, "%.1f mm/s", cfg.spec.home_speed_mm_s);
    else
        snprintfC(limits, sizeof limits, "%.1f deg/s", cfg.spec.home_speed_deg_s);
    setState(moveState, EventKind::Transition, "%s: %.3f s move at up to %s",
             moveState == EngineState::Homing         ? "Homing to the reference"
             : moveState == EngineState::Jogging      ? "Jogging"
             : program && !program->terms.path_length ? "Approach to the start position"
                                                      : "Approach to the first cut point",
             move.duration, limits);
}

void MotionEngine::Impl::beginCut() {
    ++runId;
    runActive = true;
    runStartTime = now;
    toolStarts = 0;
    toolOnCycles = 0;
    cutOnCycles = 0;
    runProgramSeq.store(currentProgramSeq.load(std::memory_order_relaxed),
                        std::memory_order_release);
    samples = 0;
    supervisionNotes.fill(0);
    stats = TrackingStats(program->tip_model.get());
    cruise = TrackingStats(program->tip_model.get());
    // A recovered cut covers the rest of the path: its minimum span shrinks by what it skips.
    minRunSteps =
        static_cast<long>(std::ceil(std::max(0.0, program->min_run_s - startTau) / T - 1e-9));
    if (startTau > 0)
        emitf(EventKind::RunStarted, Severity::Info, state, EngineState::Running,
              "Run %u started: %s, cut recovery from path time %.3f s (point %u of %zu, %.1f of "
              "%.1f mm)",
              runId, program->name.c_str(), startTau,
              static_cast<std::uint32_t>(startTau / program->spline.dt()), program->point_count,
              startTau / program->cut_time_s * program->length_mm, program->length_mm);
    else
        emitf(EventKind::RunStarted, Severity::Info, state, EngineState::Running,
              "Run %u started: %s, %.1f mm in %.2f s", runId, program->name.c_str(),
              program->length_mm, program->cut_time_s);
    sourceStarted = false;
    sourceAtRest = false;
    // Before its source runs, the run is where it will start.
    splineSource.setStartTime(startTau);
    runProgress = RunProgress{};
    if (program->source)
        runProgress.points = static_cast<std::uint32_t>(program->point_count);
    else
        runProgress.take(splineSource.progressAtStart(overrideTarget));
    if (program->source_kind == MotionSourceKind::ControlLaw) {
        // A control law starts from where its axes are: no approach.
        setState(EngineState::Running, EventKind::Transition, "Start: control law");
        phase = RunPhase::Ignite;
        phaseSince = now;
        return;
    }
    setState(EngineState::Running, EventKind::Transition,
             startTau > 0 ? "Start: approach to the recovery point"
                          : "Start: approach to the first cut point");
    phase = RunPhase::Approach;
    phaseSince = now;
    beginMove(startPosition(), EngineState::Running);
}

// ---- commands --------------------------------------------------------------------------

void MotionEngine::Impl::processCommands() {
    EngineCommand c;
    for (int n = 0; n < 16 && commands.pop(c); ++n)
        handle(c);
}

void MotionEngine::Impl::handle(const EngineCommand& c) {
    const EngineState s = state;
    switch (c.type) {
    case CommandType::Load: {
        processedLoadSeq.store(c.seq, std::memory_order_release);
        const MotionProgram* p = c.program;
        if (inMotion(s)) return refuse(c.type, "a motion is in progress (%s)", toString(s));
        // A category-1 stop still brakes along the loaded program's path.
        if (stopping()) return refuse(c.type, "the controlled stop is still in progress");
        if (!p) return refuse(c.type, "no program");
        if (p->axis_count < 1 || p->axis_count > kMaxAxes)
            return refuse(c.type, "axis_count = %d is outside 1 .. %d", p->axis_count, kMaxAxes);
        if (p->source_kind == MotionSourceKind::JointSpline &&
            (p->spline.empty() || !(p->cut_time_s > 0)))
            return refuse(c.type, "the program has no trajectory");
        if (p->source_kind != MotionSourceKind::JointSpline && !p->source)
            return refuse(c.type, "the %s program has no motion source", toString(p->source_kind));
        for (size_t k = 0; k < dev.sensors.size(); ++k)
            if ((p->sensors_used >> k & 1u) && !dev.sensors[k])
                return refuse(c.type, "sensor %zu is used by the program but not connected", k);
        for (int i = 0; i < p->axis_count; ++i) {
            if (!axisPresent(i))
                return refuse(c.type, "axis %d (%s) has no drive", i,
                              p->axis_names[static_cast<size_t>(i)].c_str());
            const AxisCommandMode want = p->axis_modes[static_cast<size_t>(i)];
            const AxisCommandMode have = dev.axes[static_cast<size_t>(i)]->commandMode();
            if (want != have)
                return refuse(c.type,
                              "axis %d (%s): the program commands %s, the drive is set to %s "
                              "(set the mode before the run)",
                              i, p->axis_names[static_cast<size_t>(i)].c_str(), toString(want),
                              toString(have));
            const double r = p->reference[i];
            if (r < p->min_position[i] || r > p->max_position[i])
                return refuse(c.type, "reference of axis %d = %.4g is outside %.4g .. %.4g", i, r,
                              p->min_position[i], p->max_position[i]);
        }
        program = p;
        splineSource.bind(p->source ? nullptr : p, cfg.spec.feed_hold_decel_s);
        currentProgramSeq.store(c.seq, std::memory_order_release);
        // In the run's own terms (whole phrases, so that the GUI translates them): a torch
        // path's points and length, the pieces and the length they add up to, the strokes.
        char what[96];
        switch (p->terms.counts) {
        case WorkCount::PathPoints:
            if (p->terms.path_length)
                snprintfC(what, sizeof what, "%zu points, %.1f mm", p->point_count, p->length_mm);
            else
                snprintfC(what, sizeof what, "%zu points", p->point_count);
            break;
        case WorkCount::Pieces:
            snprintfC(what, sizeof what, "%zu pieces, %.1f mm in all", p->point_count,
                      p->length_mm);
            break;
        case WorkCount::Strokes:
            snprintfC(what, sizeof what, "%zu strokes", p->point_count);
            break;
        }
        if (s == EngineState::Completed)
            return setState(EngineState::Ready, EventKind::Transition,
                            "Job loaded: %s (%s, %.2f s)", p->name.c_str(), what, p->cut_time_s);
        return note("Job loaded: %s (%s, %.2f s)", p->name.c_str(), what, p->cut_time_s);
    }
    case CommandType::Enable:
        if (latched(s)) return refuse(c.type, "%s", latchedReason(s));
        if (s != EngineState::Idle)
            return refuse(c.type, "drives already enabled (%s)", toString(s));
        if (!program) return refuse(c.type, "no job loaded");
        if (enabling) return refuse(c.type, "drives are already enabling");
        for (int i = 0; i < kMaxAxes; ++i)
            if (axisPresent(i)) dev.axes[static_cast<size_t>(i)]->activate();
        enabling = true;
        enableDeadline = now + cfg.enable_timeout_s;
        return note("Enabling drives");
    case CommandType::Disable:
        if (latched(s)) return refuse(c.type, "drives already disabled (%s)", toString(s));
        if (inMotion(s)) return refuse(c.type, "motion in progress (%s): Abort first", toString(s));
        if (s == EngineState::Idle && !enabling) return refuse(c.type, "drives are not enabled");
        disableAll();
        if (s == EngineState::Idle) return note("Enable cancelled: drives disabled");
        return setState(EngineState::Idle, EventKind::Transition, "Drives disabled");
    case CommandType::Home:
        if (latched(s)) return refuse(c.type, "%s", latchedReason(s));
        if (s == EngineState::Idle) return refuse(c.type, "drives not enabled");
        if (s == EngineState::Homing) return refuse(c.type, "already homing");
        if (inMotion(s)) return refuse(c.type, "motion in progress (%s)", toString(s));
        return beginMove(homeTarget(), EngineState::Homing);
    case CommandType::Jog: {
        if (s != EngineState::Ready)
            return refuse(c.type, "only while Ready (state %s)", toString(s));
        const int a = c.axis;
        if (a < 0 || a >= axisCount())
            return refuse(c.type, "axis %d does not exist (0 .. %d)", a, axisCount() - 1);
        if (!std::isfinite(c.value)) return refuse(c.type, "the jog distance is not a number");
        const double target = setpoint[a] + c.value;
        if (target < program->min_position[a] || target > program->max_position[a])
            return refuse(c.type,
                          "axis %d (%s) target %.3f %s is outside its range %.3f .. %.3f %s", a,
                          axisName(a), displayValue(a, target), unit(a),
                          displayValue(a, program->min_position[a]),
                          displayValue(a, program->max_position[a]), unit(a));
        JointVector q = setpoint;
        q[a] = target;
        return beginMove(q, EngineState::Jogging);
    }
    case CommandType::Start:
        if (latched(s)) return refuse(c.type, "%s", latchedReason(s));
        if (s == EngineState::Idle)
            return refuse(c.type, program ? "drives not enabled" : "no job loaded");
        if (s == EngineState::Running) return refuse(c.type, "already running");
        if (s == EngineState::Paused) return refuse(c.type, "paused (use Resume)");
        if (s == EngineState::Completed)
            return refuse(c.type, "the cut is complete (Home, then Start)");
        if (inMotion(s)) return refuse(c.type, "motion in progress (%s)", toString(s));
        if (!homed) return refuse(c.type, "not homed (Home first)");
        if (c.value != 0) {
            if (!source()->resumesInTime())
                return refuse(c.type,
                              "cut recovery needs a path in time; this machine's motion "
                              "follows a %s source",
                              toString(program->source_kind));
            if (!(c.value > 0 && c.value < program->cut_time_s))
                return refuse(c.type,
                              "recovery from path time %.3f s is outside the cut (0 .. %.3f s)",
                              c.value, program->cut_time_s);
        }
        startTau = c.value;
        return beginCut();
    case CommandType::FeedHold:
        if (s != EngineState::Running) return refuse(c.type, "not running (state %s)", toString(s));
        if (stopping()) return refuse(c.type, "a stop is in progress");
        if (halt == Halt::FeedHold) return refuse(c.type, "already holding");
        halt = Halt::FeedHold;
        if (program->source)
            return note("Feed hold: %s (%s)",
                        program->source_kind == MotionSourceKind::MasterAxis
                            ? "finishing the cut, returning, then no more waiting for the line"
                            : "the control law brings the axes to rest",
                        program->source->stateName());
        if (!cfg.spec.torch_on_during_feed_hold) torchCommand = false;
        return note("Feed hold: decelerating along the path (%s %s)", toolName(),
                    torchCommand ? "stays on" : "off");
    case CommandType::Resume:
        if (s == EngineState::Paused) {
            if (stopping()) return refuse(c.type, "a stop is in progress");
            halt = Halt::None;
            // The torch went out on hold: it is lit again before the path moves (RunPhase::Ignite).
            if (phase == RunPhase::Cut && !torchCommand) {
                phase = RunPhase::Ignite;
                phaseSince = now;
            }
            return setState(EngineState::Running, EventKind::Transition,
                            "Resume at path time %.3f s", runProgress.time_s);
        }
        if (s == EngineState::Running && halt == Halt::FeedHold) {
            halt = Halt::None;
            // A torch that went out on hold is lit again (and its arc awaited) before speed-up.
            if (phase == RunPhase::Cut && !torchCommand) {
                phase = RunPhase::Ignite;
                phaseSince = now;
            }
            return note("Resume while decelerating: back to speed");
        }
        return refuse(c.type, "not paused (state %s)", toString(s));
    case CommandType::SetOverride:
        if (!(c.value >= 0.10 - 1e-12 && c.value <= 1.50 + 1e-12))
            return refuse(c.type, "%.0f %% is outside 10 .. 150 %%", c.value * 100);
        overrideTarget = c.value;
        return note("Override %.0f %%", c.value * 100);
    case CommandType::Abort:
        if (latched(s)) return refuse(c.type, "%s", latchedReason(s));
        if (!inMotion(s)) return refuse(c.type, "nothing to abort (state %s)", toString(s));
        if (halt == Halt::Abort) return refuse(c.type, "already aborting");
        halt = Halt::Abort;
        torchCommand = false;
        return note("Abort: %s off, stopping along the path", toolName());
    case CommandType::EmergencyStop:
        // Taken from the atomic at the top of the cycle; a press after the latch is noted.
        if (static_cast<std::uint64_t>(c.value) > latchPress)
            return note("Emergency stop pressed again: already latched");
        return;
    case CommandType::ReleaseEmergencyStop:
        if (!estopPressed.load(std::memory_order_acquire))
            return refuse(c.type, "the emergency stop is not pressed");
        estopPressed.store(false, std::memory_order_release);
        return note("Emergency stop released (Reset to clear)");
    case CommandType::Reset:
        if (!latched(s)) return refuse(c.type, "nothing to reset (state %s)", toString(s));
        if (estopPressed.load(std::memory_order_acquire))
            return refuse(c.type, "the emergency stop is still pressed (release it first)");
        if (stopping()) return refuse(c.type, "the controlled stop is still in progress");
        for (int i = 0; i < kMaxAxes; ++i)
            if (axisPresent(i)) dev.axes[static_cast<size_t>(i)]->faultReset();
        estopLatched = false;
        return setState(EngineState::Idle, EventKind::Transition,
                        "Reset: %s cleared, drives disabled",
                        s == EngineState::Fault ? "fault" : "emergency stop");
    }
}

} // namespace cutcell
