#pragma once
// Value types that cross the engine's thread boundary: commands in, events and telemetry out.
// All are trivially copyable with fixed-size text so the cycle never allocates.
#include "core/common/types.h"
#include "core/devices/device_interfaces.h"
#include "core/engine/motion_source.h"

#include <array>
#include <cstdint>

namespace cutcell {

enum class EngineState : std::uint8_t {
    Idle,          // no job loaded or devices not enabled
    Ready,         // job loaded, drives enabled (homed or not: see TelemetrySample::homed)
    Homing,        // moving every axis to its reference position
    Jogging,       // one axis moving on operator request (from Ready)
    Running,       // cutting
    Paused,        // feed hold: stopped on the path, resumable
    Completed,     // the cut reached its end
    EmergencyStop, // latched until the request is released and Reset is given
    Fault,         // a device or tracking fault; reason in the event log; Reset clears
};
const char* toString(EngineState s);

enum class CommandType : std::uint8_t {
    Load,
    Enable,
    Disable,
    Home,
    Jog,
    Start,
    FeedHold,
    Resume,
    SetOverride,
    Abort,
    EmergencyStop,
    ReleaseEmergencyStop,
    Reset,
};
const char* toString(CommandType c);

enum class ClockMode : std::uint8_t { RealTime, AsFastAsPossible };

enum class Severity : std::uint8_t { Info, Warning, Error };

// What an event is about (the run log opens a run folder on RunStarted and writes the summary
// on RunEnded).
enum class EventKind : std::uint8_t {
    Info,       // a note (e.g. "override 80 %"), no state change
    Transition, // from -> to
    Refusal,    // a command refused in its state, with the reason
    Fault,      // a device or tracking fault (also a transition to Fault)
    RunStarted, // Start accepted: a new run begins
    RunEnded,   // the run ended (Completed, aborted, fault, emergency stop): report ready
    CutEnded,   // the tool went off in a run: one cut (pierce to arc off), its figures below
};
const char* toString(EventKind k);

struct EngineEvent {
    double time_s = 0;        // engine clock
    std::int64_t wall_ms = 0; // wall clock, ms since epoch
    Severity severity = Severity::Info;
    EngineState from = EngineState::Idle;
    EngineState to = EngineState::Idle;
    std::array<char, 240> text{}; // NUL-terminated, e.g. "Start refused: drives not enabled"
    EventKind kind = EventKind::Info;
    std::uint32_t run_id = 0; // the run this event belongs to (0 = before the first Start)
    // CutEnded: the cut's tool-on time and the path length it covered.
    double cut_tool_on_s = 0;
    double cut_length_mm = 0;
};

// One cycle's view of the machine. Per axis i < axis_count: set-point, actual, error in the
// axis's unit (rotary: rad, linear: mm — see units), its command mode and the command written
// (CSP: the position; CSV: the velocity; CST: the torque or force).
struct TelemetrySample {
    double time_s = 0;
    EngineState state = EngineState::Idle;
    std::uint8_t axis_count = 0;
    std::array<AxisUnit, kMaxAxes> units{};
    std::array<AxisCommandMode, kMaxAxes> modes{};
    std::array<bool, kMaxAxes> supervised{}; // following error checked this cycle
    JointVector setpoint = JointVector::Zero();
    JointVector actual = JointVector::Zero();
    JointVector error = JointVector::Zero(); // setpoint - actual
    JointVector command = JointVector::Zero();
    double master_position = 0;             // MasterAxis source: the filtered master
    std::array<char, 24> source_state{};    // the motion source's stateName(): e.g. "in sync"
    Vec3 cartesian_error_mm = Vec3::Zero(); // FK(actual) - FK(setpoint)
    double progress = 0;                    // 0..1 of the cut's length
    std::uint32_t point_index = 0;
    std::uint32_t point_count = 0;
    std::uint32_t made = 0; // units of work finished (MotionProgram::terms.counts)
    double elapsed_s = 0;
    double remaining_s = 0;
    double override_fraction = 1;
    std::array<DriveState, kMaxAxes> drive_states{};
    bool torch_on = false;   // the process tool (torch or saw) is on
    bool process_ok = false; // arc established / blade at speed
    bool homed = false;
    ProcessSignals process; // the program's process control (torch height), if it has one
};

// Where a run that ended short (emergency stop, fault, abort) stopped on its path: summary.json's
// "stop" object. Not valid for a completed run.
struct RunStopPoint {
    bool valid = false;
    double path_time_s = 0; // s of the path's time (at 100 %)
    double progress = 0;    // 0..1 of the path
    double length_mm = 0;   // cut length done
    double elapsed_s = 0;   // since Start
    std::uint32_t point_index = 0, point_count = 0;
    // Units of work this run finished up to here (pierces, pieces, strokes: the program's
    // terms.counts).
    std::uint32_t made = 0;
    // The tool in this run: how often it went on (pierces, saw cuts) and how long it was on.
    std::uint32_t tool_starts = 0;
    double tool_on_s = 0;
};

// Cycle timing measured by the engine thread itself.
struct CycleStats {
    double period_s = 0;
    std::uint64_t cycles = 0;
    std::uint64_t overruns = 0;
    double jitter_us_p50 = 0;
    double jitter_us_p99 = 0;
    double jitter_us_max = 0;
    std::uint64_t telemetry_dropped = 0;
    std::uint64_t events_dropped = 0;
    double last_estop_latency_us = 0;
    std::uint64_t estops_measured = 0;    // emergency stops whose latency was measured
    std::uint64_t log_events_dropped = 0; // events the run logger could not take
    double work_us_max = 0;               // longest cycle work (read -> write)
    std::uint64_t missed_deadlines = 0;   // periods skipped because the thread woke too late
};

} // namespace cutcell
