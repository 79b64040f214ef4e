// The motion engine's public side: commands in, telemetry and events out, the engine thread
// and the run logger thread. The cycle itself is in engine_cycle.cpp / engine_commands.cpp.
#include "core/engine/motion_engine.h"

#include "core/engine/engine_impl.h"
#include "core/engine/run_log.h"

#include <chrono>
#include <cstdio>
#include <string_view>
#include <tuple>

namespace cutcell {

MotionEngine::Impl::Impl(EngineDevices d, EngineConfig c)
    : dev(d), cfg(std::move(c)), T(cfg.period_s) {
    if (!(T > 0)) T = 0.001;
    runLog = std::make_unique<RunLog>(cfg.spec.runs_dir);
}

MotionEngine::MotionEngine(EngineDevices devices, EngineConfig config)
    : impl_(std::make_unique<Impl>(devices, std::move(config))) {}

MotionEngine::~MotionEngine() {
    stopThread();
    flushRunLog();
}

bool MotionEngine::pushCommand(CommandType t, int axis, double value) {
    EngineCommand c;
    c.type = t;
    c.axis = axis;
    c.value = value;
    return impl_->commands.push(c);
}

bool MotionEngine::load(std::shared_ptr<const MotionProgram> program) {
    Impl& m = *impl_;
    EngineCommand c;
    c.type = CommandType::Load;
    std::lock_guard<std::mutex> lock(m.heldMutex);
    // Release programs the cycle no longer uses (handled loads other than the current one and
    // the one the last run executes).
    const std::uint64_t processed = m.processedLoadSeq.load(std::memory_order_acquire);
    const std::uint64_t current = m.currentProgramSeq.load(std::memory_order_acquire);
    const std::uint64_t run = m.runProgramSeq.load(std::memory_order_acquire);
    std::erase_if(m.held, [&](const Impl::Held& h) {
        return h.seq <= processed && h.seq != current && h.seq != run;
    });
    c.program = program.get();
    c.seq = m.nextLoadSeq++;
    m.held.push_back({c.seq, std::move(program)});
    if (m.commands.push(c)) return true;
    m.held.pop_back();
    return false;
}
bool MotionEngine::enable() {
    return pushCommand(CommandType::Enable);
}
bool MotionEngine::disable() {
    return pushCommand(CommandType::Disable);
}
bool MotionEngine::home() {
    return pushCommand(CommandType::Home);
}
bool MotionEngine::jog(int axis, double delta) {
    return pushCommand(CommandType::Jog, axis, delta);
}
bool MotionEngine::start() {
    return pushCommand(CommandType::Start);
}
bool MotionEngine::startFrom(double pathTime_s) {
    return pushCommand(CommandType::Start, 0, pathTime_s);
}
bool MotionEngine::feedHold() {
    return pushCommand(CommandType::FeedHold);
}
bool MotionEngine::resume() {
    return pushCommand(CommandType::Resume);
}
bool MotionEngine::setOverride(double fraction) {
    return pushCommand(CommandType::SetOverride, 0, fraction);
}
bool MotionEngine::abort() {
    return pushCommand(CommandType::Abort);
}
bool MotionEngine::releaseEmergencyStop() {
    return pushCommand(CommandType::ReleaseEmergencyStop);
}
bool MotionEngine::reset() {
    return pushCommand(CommandType::Reset);
}

bool MotionEngine::emergencyStop() {
    Impl& m = *impl_;
    // The request is the atomic; the queued command only records it in order with the others.
    m.estopRequestNs.store(monotonicNowNs(), std::memory_order_relaxed);
    m.estopPressed.store(true, std::memory_order_release);
    const auto press = m.estopPresses.fetch_add(1, std::memory_order_acq_rel) + 1;
    m.timer.wake();
    pushCommand(CommandType::EmergencyStop, 0, static_cast<double>(press));
    return true;
}

bool MotionEngine::popTelemetry(TelemetrySample& out) {
    return impl_->telemetry.pop(out);
}
bool MotionEngine::popEvent(EngineEvent& out) {
    return impl_->events.pop(out);
}

EngineState MotionEngine::state() const {
    return impl_->publicState.load(std::memory_order_acquire);
}

CycleStats MotionEngine::cycleStats() const {
    return impl_->snapshot();
}

CycleStats MotionEngine::Impl::snapshot() const {
    const Impl& m = *this;
    CycleStats s;
    s.period_s = m.T;
    s.cycles = m.cycles.load(std::memory_order_relaxed);
    s.overruns = m.overruns.load(std::memory_order_relaxed);
    s.jitter_us_p50 = m.jitter.percentile(0.50);
    s.jitter_us_p99 = m.jitter.percentile(0.99);
    s.jitter_us_max = m.jitter.max();
    s.telemetry_dropped = m.telemetryDropped.load(std::memory_order_relaxed);
    s.events_dropped = m.eventsDropped.load(std::memory_order_relaxed);
    s.last_estop_latency_us = m.lastEstopLatencyUs.load(std::memory_order_relaxed);
    s.estops_measured = m.estopsMeasured.load(std::memory_order_acquire);
    s.log_events_dropped = m.logDropped.load(std::memory_order_relaxed);
    s.work_us_max = m.workUsMax.load(std::memory_order_relaxed);
    s.missed_deadlines = m.missedDeadlines.load(std::memory_order_relaxed);
    return s;
}

RealtimeStatus MotionEngine::realtimeStatus() const {
    // Written by the engine thread once before its first cycle, published by the flag.
    return impl_->realtimeKnown.load(std::memory_order_acquire) ? impl_->realtime
                                                                : RealtimeStatus{};
}

bool MotionEngine::lastRunReport(TrackingReport& out, std::string* outcome,
                                 RunStopPoint* stop) const {
    const Impl& m = *impl_;
    for (int attempt = 0; attempt < 100; ++attempt) {
        const std::uint64_t g = m.resultGeneration.load(std::memory_order_acquire);
        if (g == 0) return false;
        const RunResult& r = m.results[g % 2];
        TrackingReport copy = r.report;
        copy.method = r.method.data();
        std::string why = r.outcome.data();
        const RunStopPoint where = r.stop;
        // The cycle writes the other slot; a changed generation means it may have lapped us.
        if (m.resultGeneration.load(std::memory_order_acquire) != g) continue;
        out = copy;
        if (outcome) *outcome = why;
        if (stop) *stop = where;
        return true;
    }
    return false;
}

std::string MotionEngine::lastRunDirectory() const {
    std::lock_guard<std::mutex> lock(impl_->logMutex);
    return impl_->runLog ? impl_->runLog->runDirectory() : std::string();
}

void MotionEngine::flushRunLog() {
    impl_->loggerDrain();
}

void MotionEngine::setRunRecord(std::shared_ptr<RunRecordSink> record) {
    std::lock_guard<std::mutex> lock(impl_->logMutex);
    impl_->runRecord = std::move(record);
    if (impl_->runLog) impl_->runLog->setRecordSink(impl_->runRecord.get());
}

void MotionEngine::logExternalEvent(Severity severity, const std::string& text) {
    Impl& m = *impl_;
    EngineEvent e;
    e.severity = severity;
    e.kind = severity == Severity::Error ? EventKind::Fault : EventKind::Info;
    e.from = e.to = m.publicState.load(std::memory_order_acquire);
    e.time_s = static_cast<double>(m.cycles.load(std::memory_order_relaxed)) * m.T;
    e.wall_ms = std::chrono::duration_cast<std::chrono::milliseconds>(
                    std::chrono::system_clock::now().time_since_epoch())
                    .count();
    std::snprintf(e.text.data(), e.text.size(), "%s", text.c_str());
    std::lock_guard<std::mutex> lock(m.externalMutex);
    if (m.external.size() < 1000) m.external.push_back(e);
}

void MotionEngine::Impl::drainExternal() {
    std::vector<EngineEvent> pending;
    {
        std::lock_guard<std::mutex> lock(externalMutex);
        pending.swap(external);
    }
    for (const EngineEvent& e : pending)
        runLog->eventForLastRun(e);
}

// Logger side: events to files; opens a run on RunStarted, writes the summary on RunEnded.
// Events from outside the cycle go first: they happened before the cycle reacted to them.
void MotionEngine::Impl::loggerDrain() {
    // One drainer at a time (the logger thread, flushRunLog()); the ring has one consumer.
    std::lock_guard<std::mutex> logLock(logMutex);
    EngineEvent e;
    drainExternal();
    while (logEvents.pop(e)) {
        if (e.kind == EventKind::RunStarted) {
            const std::uint64_t seq = runProgramSeq.load(std::memory_order_acquire);
            std::shared_ptr<const MotionProgram> p;
            {
                std::lock_guard<std::mutex> lock(heldMutex);
                for (const Held& h : held)
                    if (h.seq == seq) p = h.program;
            }
            runLog->beginRun(e.run_id, p ? p->name : std::string(),
                             p ? p->source_text : std::string());
            if (p) {
                runLog->setAxisNames(p->axis_names);
                runLog->setTerms(p->terms);
            }
        }
        if (e.kind == EventKind::RunEnded) drainExternal(); // a device's reason, still in this run
        runLog->event(e);
        if (const std::string p = runLog->takeProblem();
            !p.empty() && !logProblemPending.load(std::memory_order_acquire)) {
            std::snprintf(logProblem.data(), logProblem.size(), "%s", p.c_str());
            logProblemPending.store(true, std::memory_order_release);
        }
        if (e.kind == EventKind::RunEnded) {
            const std::uint64_t g = resultGeneration.load(std::memory_order_acquire);
            if (g != 0) {
                const RunResult& r = results[g % 2];
                TrackingReport report = r.report;
                report.method = r.method.data();
                runLog->endRun(r.outcome.data(), report, snapshot(), r.stop, r.start, r.end);
            }
        }
    }
}

void MotionEngine::startThread() {
    Impl& m = *impl_;
    if (m.threadRunning.exchange(true)) return;
    m.stopRequested.store(false);
    m.realtimeKnown.store(false); // the new thread writes m.realtime, then sets it again
    m.engineThread = std::thread([&m] {
        // Priority, memory lock, CPU, DMA latency: each checked, the outcome an event (a
        // warning when something asked for was refused) and realtimeStatus().
        int dmaFd = -1;
        if (m.cfg.clock == ClockMode::RealTime) {
            m.realtime = applyRealtime(m.cfg.realtime, &dmaFd);
            m.realtimeKnown.store(true, std::memory_order_release);
            char text[640];
            const bool allGranted = describeRealtime(m.cfg.realtime, m.realtime, text, sizeof text);
            // An event holds 239 characters; every refusal with the OS's reasons is longer.
            // The line goes out in as many events as it needs, cut between its items ("; "),
            // so each event is whole sentences (and translates item by item).
            const Severity severity = allGranted ? Severity::Info : Severity::Warning;
            constexpr std::size_t kEventChars = std::tuple_size_v<decltype(EngineEvent::text)> - 1;
            std::string_view rest(text);
            while (!rest.empty()) {
                const std::size_t cut = realtimeLinePiece(rest, kEventChars);
                m.emitf(EventKind::Info, severity, m.state, m.state, "%.*s", static_cast<int>(cut),
                        rest.data());
                rest.remove_prefix(cut);
                if (rest.substr(0, 2) == "; ") rest.remove_prefix(2);
            }
        }
        const std::int64_t periodNs = static_cast<std::int64_t>(m.T * 1e9 + 0.5);
        std::int64_t next = monotonicNowNs() + periodNs;
        while (!m.stopRequested.load(std::memory_order_acquire)) {
            if (m.cfg.clock == ClockMode::RealTime) {
                // Woken early by an emergency stop: push it to the devices now, then sleep on.
                while (m.timer.sleepUntil(next))
                    m.checkEmergencyStop();
                const std::int64_t woke = monotonicNowNs();
                m.jitter.add(static_cast<double>(woke - next) / 1000.0);
                m.runCycle();
                const std::int64_t done = monotonicNowNs();
                const double workUs = static_cast<double>(done - woke) / 1000.0;
                if (workUs > m.workUsMax.load(std::memory_order_relaxed))
                    m.workUsMax.store(workUs, std::memory_order_relaxed);
                if (done - woke > periodNs) m.overruns.fetch_add(1, std::memory_order_relaxed);
                next += periodNs;
                // Behind by a period or more: skip the missed deadlines instead of bursting.
                if (done > next) {
                    const std::int64_t skipped = (done - next) / periodNs + 1;
                    m.missedDeadlines.fetch_add(static_cast<std::uint64_t>(skipped),
                                                std::memory_order_relaxed);
                    next += skipped * periodNs;
                }
            } else {
                m.runCycle();
            }
        }
        releaseRealtime(dmaFd);
    });
    m.loggerThread = std::thread([&m] {
        while (!m.stopRequested.load(std::memory_order_acquire)) {
            m.loggerDrain();
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        m.loggerDrain();
    });
}

void MotionEngine::stopThread() {
    Impl& m = *impl_;
    if (!m.threadRunning.load()) return;
    m.stopRequested.store(true, std::memory_order_release);
    m.timer.wake();
    if (m.engineThread.joinable()) m.engineThread.join();
    if (m.loggerThread.joinable()) m.loggerThread.join();
    m.threadRunning.store(false);
}

EngineState MotionEngine::runCycles(std::uint64_t max_cycles, EngineState until) {
    Impl& m = *impl_;
    for (std::uint64_t i = 0; i < max_cycles; ++i) {
        m.runCycle();
        if (m.state == until) break;
    }
    return m.state;
}

} // namespace cutcell
