#pragma once
// The motion engine: a fixed-period control cycle on its own thread
//   read devices -> state machine / trajectory -> write devices
// with a real-time clock (paced to the wall clock) or as fast as possible (same code path).
//
// Threading contract:
//  - Commands may be sent from any thread; they go through a bounded lock-free queue and
//    return at once (false if the queue is full). Refusals come back as events.
//  - emergencyStop() additionally sets an atomic checked at the top of every cycle.
//  - Telemetry and events leave through bounded single-producer/single-consumer rings: one
//    consumer thread (e.g. the GUI timer) drains them with popTelemetry()/popEvent(). Samples
//    lost because the ring was full are counted in CycleStats, never hidden.
//  - The cycle itself does not allocate, lock or block. Loading a program happens outside the
//    cycle: load() hands over a shared_ptr that the engine swaps in at the next cycle.
//  - In thread mode (startThread) a logger thread writes the run log; with runCycles() the
//    caller writes it with flushRunLog(). runCycles() must not be used while the thread runs.
//
// Behaviour (see tests/engine/state_machine_test.cpp for every command in every state):
//  - Enable (Idle, job loaded) -> Ready once every drive reads back Enabled. Ready is "not
//    homed" until Home moves every axis to the program's reference at the home speed.
//  - Start (Ready and homed) -> Running: an approach move to the first set-point at the home
//    speed (torch off), settling there (in_position_*), torch on, wait for the arc, then the
//    cut from path time 0. The torch is lit only on the path. The run lasts until the path
//    ended and at least program.min_run_s of samples were taken -> Completed; its figures
//    (lastRunReport) are simulateCut()'s for an uninterrupted run at 100 %.
//  - The path time tau advances by rate * period; the set-point is the program's spline at tau.
//    Feed hold, abort, override and a category-1 stop change the rate linearly at
//    1 / spec.feed_hold_decel_s per second (100 % to rest in feed_hold_decel_s), so neither
//    the set-point nor its velocity jumps; resume ramps back from where the path stopped.
//  - Emergency stop / fault: torch off at once; category 0 disables every drive at once,
//    category 1 stops along the path first, then disables. Both latch; Reset clears a fault,
//    and an emergency stop only after releaseEmergencyStop(). Drives are "not homed" again.
//
// Motion sources (MotionProgram::source_kind): every program runs through one, the same way
// through the cycle (runSource). Axes have a unit (rotary rad / linear mm) and a
// command mode (CSP / CSV / CST) fixed before Load; Load refuses drives in another mode. Every
// cycle writes each present axis in its mode; axes not driven get position = hold, velocity 0,
// torque 0. Home, jog and the approach are set-point moves (above) for every source.
//  (1) JointSpline (JointSplineSource, the engine's own source of such programs): everything
//      above; the only source a run can start part-way on (cut recovery from a path time).
//  (2) MasterAxis (MasterFollower: gear / cam to a line encoder, MC_GearInPos / MC_CamIn):
//      Start = approach to start_position, settle, tool on and process OK (saw at speed), then
//      the source runs each cycle until its cuts are done (Completed).
//      Feed hold: the line cannot be stopped, so the saw finishes the cut in progress, the
//      axes return to their wait positions and stop waiting: Paused once at rest (tool off
//      unless torch_on_during_feed_hold). Resume: tool on, process OK, then the next sync
//      position still ahead of the line. Override: does not apply (the line sets the speed).
//      Abort: tool off, the axes leave the line decelerating to rest in the source's decel_s,
//      then Ready. Category 1 stop / fault: the same deceleration, then drives disabled;
//      category 0: drives disabled at once. A master reading that is not valid is a fault.
//  (3) ControlLaw (a machine's law writing torques in CST): no approach; Start = tool (if any),
//      then the law runs. Outside a run (Ready, Home, Jog, Paused) the law tracks the engine's
//      set-point. Feed hold / abort / category-1 stop: the law brakes to rest (an open-loop
//      phase is finished first, as the law defines), then Paused / Ready / drives disabled.
//      Override: passed to the law (scales its speed). Category 0 and every fault of a
//      control-law program: torque 0 written and drives disabled in the same cycle (no
//      braking without trusted feedback). A sensor reading that is not valid is a fault.
//  Supervision: following error and frozen feedback are checked per axis only while the
//  source says the axis has a position reference (SourceOutput::supervised); an event names
//  the axis and the reason each time supervision of an axis goes off or on again.
#include "core/devices/device_interfaces.h"
#include "core/engine/engine_types.h"
#include "core/engine/motion_program.h"
#include "core/engine/motion_source.h"
#include "core/engine/realtime_thread.h"
#include "core/job/job.h"
#include "core/record/run_record.h"
#include "core/sim/tracking_stats.h"

#include <array>
#include <memory>
#include <string>

namespace cutcell {

struct EngineDevices {
    std::array<AxisDrive*, kMaxAxes> axes{};         // null for axes the machine does not have
    std::array<SensorInput*, kMaxSensors> sensors{}; // external encoders and sensors
    ProcessTool* torch = nullptr;                    // the process tool: torch or saw
};

struct EngineConfig {
    double period_s = 0.001;
    ClockMode clock = ClockMode::RealTime;
    EngineSpec spec; // stop category, feed hold, limits, runs dir
    // Before a cut starts, every axis must be this close to the first set-point (rad or mm) and
    // this slow for settle_cycles cycles in a row. Simulated drives settle to rounding level;
    // real drives need their encoder resolution here.
    double in_position_window = 1e-12;
    double in_position_velocity = 1e-10;
    int settle_cycles = 20;
    double settle_timeout_s = 30;
    double enable_timeout_s = 1.0;
    double ignition_timeout_s = 2.0;
    // Feedback that has not changed while the set-point travelled this far is frozen (rad/mm).
    double frozen_feedback_travel = 0.002;
    std::uint32_t telemetry_every_n_cycles = 1; // 1 = every cycle
    // Transport delay of the drives (s): from write() to the feedback that shows the drive
    // acting on it (2 cycles on a CANopen bus: RPDO after SYNC k, reached at SYNC k + 2).
    // The engine writes each set-point extrapolated this far ahead along its velocity and
    // acceleration (a source's along its velocity only), so the error it measures is the
    // drive's tracking error, not the bus's delay: a linear extrapolation alone was off by
    // a lead^2 / 2 (measured on the default job at 4 ms with 100 000 counts/deg: max |e|
    // twice the in-process drives'). 0 for in-process drives.
    double setpoint_lead_s = 0;
    // The engine thread's real-time set-up (RealTime clock only): SCHED_FIFO priority, memory
    // lock, CPU pinning, /dev/cpu_dma_latency. What was granted: realtimeStatus() and an event.
    RealtimeSettings realtime;
};

class MotionEngine {
  public:
    MotionEngine(EngineDevices devices, EngineConfig config);
    ~MotionEngine();
    MotionEngine(const MotionEngine&) = delete;
    MotionEngine& operator=(const MotionEngine&) = delete;

    // Thread control. In AsFastAsPossible mode the thread runs cycles back to back.
    void startThread();
    void stopThread();
    // Runs cycles on the calling thread (tests, CLI) until the predicate state is reached or
    // max_cycles have run; no thread must be started. Returns the state reached.
    EngineState runCycles(std::uint64_t max_cycles, EngineState until);

    // Commands (any thread, non-blocking).
    bool load(std::shared_ptr<const MotionProgram> program);
    bool enable();
    bool disable();
    bool home();
    bool jog(int axis, double delta); // relative move of one axis while Ready
    bool start();
    // Cut recovery: Start from path time pathTime_s of a joint-spline program (0 = start()):
    // the approach goes to the path's set-point there (torch off), the torch is lit and the
    // pierce dwell repeated, then the path rate ramps up from rest (no set-point or velocity
    // jump) and the cut runs to its end. Refused (event) for other motion sources and for a
    // time outside [0, cut_time_s). The caller picks the point (the stop point, minus a lead-in
    // along the path, or a point the operator chose).
    bool startFrom(double pathTime_s);
    bool feedHold();
    bool resume();
    bool setOverride(double fraction); // 0.10 .. 1.50
    bool abort();
    bool emergencyStop();        // also sets the atomic request at once
    bool releaseEmergencyStop(); // the operator pulled the mushroom button back out
    bool reset();

    // Consumer side (one thread).
    bool popTelemetry(TelemetrySample& out);
    bool popEvent(EngineEvent& out);

    // Snapshot readable from any thread.
    EngineState state() const;
    CycleStats cycleStats() const;
    // What the real-time set-up of the engine thread got (applied = false before the thread
    // started or in the fast clock). Read while the thread runs or after stopThread().
    RealtimeStatus realtimeStatus() const;

    // The figures of the last run that ended (Completed, aborted, stopped or faulted), with the
    // same definitions as simulateCut(); false before the first run ended. Any thread.
    // stop: where it stopped on its path (valid only for a run that ended short).
    bool lastRunReport(TrackingReport& out, std::string* outcome = nullptr,
                       RunStopPoint* stop = nullptr) const;
    // The folder of the current or last run log ("" when EngineSpec.runs_dir is empty or no
    // run started). Any thread.
    std::string lastRunDirectory() const;
    // Writes pending run-log events now (runCycles() mode; the thread mode has a logger thread).
    void flushRunLog();
    // The production record: told of each run's start, alarms and end by the run logger (not
    // the cycle). Any thread; null removes it. The engine keeps it alive.
    void setRunRecord(std::shared_ptr<RunRecordSink> record);
    // An event from outside the cycle (a device's decoded fault, e.g. "node 3: EMCY 0x2310
    // over-current"; a shutdown) for the run log, written by the log's drainer before the
    // cycle's pending events. Any thread but the cycle's: it locks and allocates.
    void logExternalEvent(Severity severity, const std::string& text);

  private:
    bool pushCommand(CommandType type, int axis = 0, double value = 0);
    struct Impl; // defined in engine_impl.h (private to the engine's sources)
    std::unique_ptr<Impl> impl_;
};

} // namespace cutcell
