#pragma once
// Private to the motion engine: the state shared by its public API (any thread), its cycle
// (engine thread) and its run logger (logger thread). Members are grouped by the thread that
// writes them; cross-thread members are atomics or lock-free rings.
#include "core/engine/cycle_clock.h"
#include "core/engine/joint_move.h"
#include "core/engine/joint_spline_source.h"
#include "core/engine/motion_engine.h"
#include "core/engine/mpsc_queue.h"
#include "core/engine/path_clock.h"
#include "core/engine/realtime_thread.h"
#include "core/engine/run_log.h"
#include "core/engine/spsc_ring.h"
#include "core/sim/tracking_stats.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdarg>
#include <mutex>
#include <thread>
#include <vector>

namespace cutcell {

struct EngineCommand {
    CommandType type = CommandType::Reset;
    int axis = 0;
    double value = 0;
    const MotionProgram* program = nullptr; // kept alive by Impl::held_ (Load)
    std::uint64_t seq = 0;                  // Load: the program's hand-over number
};

// What the set-point follows: a hold, the engine's own move (home, jog, approach; time-scaled
// by the move clock's rate) or the program's motion source (which keeps its own time).
enum class TrajectoryKind : std::uint8_t { Hold, Move, Source };
// Steps of a Running job.
enum class RunPhase : std::uint8_t { Approach, Settle, Ignite, Pierce, Cut, Finish, Close };
// Why the motion is being brought to rest: a feed hold (Paused once at rest), an abort (Ready)
// or a category-1 stop (drives disabled). One state, so no hold can be cleared while a stop
// goes on.
enum class Halt : std::uint8_t { None, FeedHold, Abort, EmergencyCat1, FaultCat1 };

// Where the run is, as its motion source last said (or, before the source runs, where it
// will start): the stop point, the telemetry's progress and the messages use it.
struct RunProgress {
    double time_s = 0;      // path time (sources in time only)
    double progress = 0;    // 0..1
    double remaining_s = 0; // at the current rate; 0 if not known
    std::uint32_t point = 0, points = 0, made = 0;
    void take(const SourceOutput& o) {
        time_s = o.program_time_s;
        progress = o.progress;
        remaining_s = o.remaining_s;
        point = o.point_index;
        points = o.point_count;
        made = o.made;
    }
};

// The figures of the last finished run, published by the cycle (double buffer + generation).
struct RunResult {
    TrackingReport report;
    std::array<char, 120> outcome{};
    std::array<char, 40> method{};
    std::uint32_t run_id = 0;
    RunStopPoint stop; // where a run that ended short stopped (summary.json "stop")
    // A cut recovery: where on the path this run started; the path before it was not cut by
    // this run (summary.json "recovered_from"). Not valid for a run from the path's start.
    RunStopPoint start;
    // Where the run ended, stopped short or completed (valid for every run): what it made, in
    // the program's terms (summary.json "made").
    RunStopPoint end;
};

struct MotionEngine::Impl {
    Impl(EngineDevices d, EngineConfig c);

    // ---- immutable after construction
    EngineDevices dev;
    EngineConfig cfg;
    double T;

    // ---- any thread -> engine thread
    MpscQueue<EngineCommand> commands{256};
    std::atomic<bool> estopPressed{false};
    std::atomic<std::int64_t> estopRequestNs{0};
    std::atomic<std::uint64_t> estopPresses{0};
    std::uint64_t latchPress = 0; // engine thread: the press that latched the stop
    CycleTimer timer;
    std::mutex heldMutex; // never taken by the cycle
    struct Held {
        std::uint64_t seq;
        std::shared_ptr<const MotionProgram> program;
    };
    std::vector<Held> held;
    std::uint64_t nextLoadSeq = 1; // under heldMutex
    std::atomic<std::uint64_t> processedLoadSeq{0}, currentProgramSeq{0}, runProgramSeq{0};

    // ---- engine thread -> consumers
    SpscRing<TelemetrySample> telemetry{8192};
    SpscRing<EngineEvent> events{1024};
    SpscRing<EngineEvent> logEvents{1024};
    std::atomic<EngineState> publicState{EngineState::Idle};
    std::atomic<std::uint64_t> cycles{0}, overruns{0}, telemetryDropped{0}, eventsDropped{0},
        logDropped{0}, estopsMeasured{0}, missedDeadlines{0};
    std::atomic<double> lastEstopLatencyUs{0}, workUsMax{0};
    JitterHistogram jitter;
    RunResult results[2];
    std::atomic<std::uint64_t> resultGeneration{0};

    // ---- threads
    std::thread engineThread, loggerThread;
    std::atomic<bool> stopRequested{false}, threadRunning{false};
    RealtimeStatus realtime;                // written by the engine thread before its first cycle
    std::atomic<bool> realtimeKnown{false}; // ... and published by this flag
    std::mutex logMutex;                    // logger side only: one drainer at a time
    // Declared before the run log, which points to it, so it outlives the log.
    std::shared_ptr<RunRecordSink> runRecord; // under logMutex (the run log tells it)
    std::unique_ptr<class RunLog> runLog;     // under logMutex
    // Logger -> engine thread: a run-log problem the cycle reports as a Warning event (the
    // text is written before the flag is set, read after it is seen; no lock, no allocation).
    std::array<char, 200> logProblem{};
    std::atomic<bool> logProblemPending{false};
    std::mutex externalMutex;          // never taken by the cycle
    std::vector<EngineEvent> external; // logExternalEvent(), under externalMutex
    void loggerDrain();
    void drainExternal();        // under logMutex
    CycleStats snapshot() const; // any thread

    // ---- engine thread only
    const MotionProgram* program = nullptr;
    EngineState state = EngineState::Idle;
    std::uint64_t cycle = 0;
    double now = 0;
    std::array<DriveFeedback, kMaxAxes> fb{};
    std::array<SensorReading, kMaxSensors> sensorFb{};
    ProcessToolFeedback torchFb{};
    bool enabling = false;
    double enableDeadline = 0;
    bool homed = false;
    bool torchCommand = false;
    // The tool in the current run: starts, cycles on, and the cut under way (consumables).
    std::uint32_t toolStarts = 0;
    std::uint64_t toolOnCycles = 0, cutOnCycles = 0;
    double cutStartLength = 0;
    void toolSwitched(bool on); // the torch was just written on or off
    double overrideTarget = 1;
    Halt halt = Halt::None;
    // A controlled stop (abort, category 1) is bringing the motion to rest.
    bool stopping() const { return halt >= Halt::Abort; }
    bool estopLatched = false; // the request was taken (until Reset)
    bool estopLatencyPending = false;
    std::int64_t estopRequestSeen = 0;
    // trajectory
    TrajectoryKind traj = TrajectoryKind::Hold;
    JointMove move;
    PathClock moveClock; // the move's time (feed hold and abort ramp its rate too)
    JointVector hold = JointVector::Zero();
    double startTau = 0;            // path time the current run starts at (cut recovery: > 0)
    JointSplineSource splineSource; // the source of JointSpline programs (bound at Load)
    JointVector setpoint = JointVector::Zero();
    // The set-points of the last kSetpointHistory cycles (index cycle % size): a feedback that
    // came age_cycles late is compared with the set-point of its own cycle. 128 cycles cover
    // every feedback a bus drive still calls valid (no TPDO for 100 ms: stale) at any cycle of
    // 0.8 ms or more; 16 did not: 20 cycles late at 2 ms (a loaded ASan run) was paired with
    // the set-point of 15 cycles ago and showed the carriage's travel as following error.
    static constexpr int kSetpointHistory = 128;
    std::array<JointVector, kSetpointHistory> setpointHistory{};
    JointVector setpointVel = JointVector::Zero();
    JointVector setpointAcc = JointVector::Zero(); // of the move or the source
    // run
    RunPhase phase = RunPhase::Approach;
    std::uint32_t runId = 0;
    double phaseSince = 0, cutStartTime = 0, runStartTime = 0, runEndTime = 0;
    int settleCount = 0;
    long samples = 0, minRunSteps = 0;
    bool runActive = false;
    bool torchWritten = false;
    TrackingStats stats{static_cast<const TipModel*>(nullptr)};
    TrackingStats cruise{static_cast<const TipModel*>(nullptr)};
    // The tips of (set-point, actual) of the current cycle, shared by track() and telemetry.
    TipSample cycleTips{};
    std::uint64_t tipsCycle = ~std::uint64_t{0};
    const TipModel* tipsModel = nullptr;
    const TipSample& tipsThisCycle(const TipModel* model);
    // the program's motion source
    SourceOutput srcOut{};
    bool sourceRan = false;     // update() ran this cycle (srcOut is this cycle's)
    bool sourceStarted = false; // start() ran for the current run
    bool sourceAtRest = false;
    // The run's progress as the source last gave it (srcOut is cleared every cycle).
    RunProgress runProgress;
    bool faultCat0 = false; // the next fault removes torque at once (control laws)
    // supervision
    std::array<double, kMaxAxes> lastSensed{}, travelSinceChange{};
    std::array<double, kMaxAxes> lastPairedSetpoint{}; // setpointForFeedback() a cycle ago
    std::array<bool, kMaxAxes> supervisedNow{true, true, true, true, true, true, true, true};
    // Supervision changes noted in this run's log per axis: the first off and on again only
    // (the crank's open-loop return turns it off every stroke; a line each flooded the log).
    std::array<std::uint8_t, kMaxAxes> supervisionNotes{};
    bool arcWasOk = false;

    // engine_cycle.cpp: the cycle's order, the devices, the set-point and the source
    void runCycle();
    void readDevices();
    void computeSetpoint();
    void runSource();
    SourceInput sourceInput() const;
    SourceRequest sourceRequest() const;
    void writeDevices();
    void stepMoveTime();
    // engine_sequencing.cpp: the state machine's step
    void advance();
    void stepRunning();
    void startSource(bool pierced); // the program's motion begins (or resumes) in RunPhase::Cut
    void finishSource();            // ... and has ended (RunPhase::Finish, tool off)
    bool restReached() const;       // the move's rate or the source is at rest
    // engine_supervision.cpp
    void checkEmergencyStop();
    void checkEstopComplete();
    void superviseEnabling();
    void superviseDevices();
    // engine_telemetry.cpp
    void track();
    void publishTelemetry();

    // engine_commands.cpp: commands and transitions
    void processCommands();
    void handle(const EngineCommand& c);
    void refuse(CommandType c, const char* fmt, ...) __attribute__((format(printf, 3, 4)));
    void enterEmergencyStop();
    void enterFault(const char* fmt, ...) __attribute__((format(printf, 2, 3)));
    void stopDevices(StopCategory category, Halt reason);
    void disableAll();
    void endRun(const char* outcome);
    // Notes where the current run is on its path, before a stop resets the trajectory.
    void captureStop();
    // Where the current run is now (path time or the source's count) and what it has made.
    RunStopPoint currentPoint() const;
    RunStopPoint stopPoint;
    void beginMove(const JointVector& target, EngineState moveState);
    void beginCut();

    // helpers
    int axisCount() const { return program ? program->axis_count : 0; }
    // The drives act on a command one cycle before its effect shows in the feedback: the
    // set-point lead less that cycle (EngineConfig::setpoint_lead_s).
    double actuationDelay() const { return std::max(0.0, cfg.setpoint_lead_s - T); }
    bool axisPresent(int i) const { return dev.axes[static_cast<size_t>(i)] != nullptr; }
    double speedLimit(int i) const;
    // `target` with every continuous axis at its equivalent nearest to the set-point (whole
    // turns dropped: at most half a turn away).
    JointVector nearestEquivalent(JointVector target) const;
    // The reference, so.
    JointVector homeTarget() const;
    // Where this run started on the path if it is a cut recovery (not valid otherwise).
    RunStopPoint recoveryStart() const;
    double followingLimit(int i) const;
    double displayValue(int i, double v) const; // deg or mm
    const char* unit(int i) const;
    const char* axisName(int i) const;
    // The process tool as the program's terms name it ("torch", "saw"); "tool" with no program.
    const char* toolName() const { return program ? program->terms.tool.c_str() : "tool"; }
    void setState(EngineState s, EventKind kind, const char* fmt, ...)
        __attribute__((format(printf, 4, 5)));
    void emit(EventKind kind, Severity sev, EngineState from, EngineState to, const char* fmt,
              va_list ap);
    // An event of this cycle (time, wall clock, run) and its way to the GUI's and the logger's
    // rings (a full ring counts a drop).
    EngineEvent newEvent(EventKind kind) const;
    void pushEvent(const EngineEvent& e);
    void emitf(EventKind kind, Severity sev, EngineState from, EngineState to, const char* fmt, ...)
        __attribute__((format(printf, 6, 7)));
    void note(const char* fmt, ...) __attribute__((format(printf, 2, 3)));
    JointSample evaluate() const;
    JointVector startPosition() const; // where the approach goes
    AxisCommandMode mode(int i) const {
        return program && i < program->axis_count ? program->axis_modes[static_cast<size_t>(i)]
                                                  : AxisCommandMode::Position;
    }
    // The program's motion source: its own (MasterAxis, ControlLaw) or the spline's.
    MotionSource* source() {
        return program && program->source ? program->source.get() : &splineSource;
    }
    const MotionSource* source() const {
        return program && program->source ? program->source.get() : &splineSource;
    }

    void holdAt(const JointVector& q);
    JointVector actualPositions() const;
    // Axis i's set-point of the cycle its feedback was sampled in (this cycle's when the
    // feedback is on time; the oldest kept when later than that: the larger error, not less).
    double setpointForFeedback(int i) const;
    JointVector setpointsForFeedback() const; // every axis (absent ones: this cycle's)
};

} // namespace cutcell
