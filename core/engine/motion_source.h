#pragma once
// A motion source: how a machine's program moves its axes in the engine cycle. One update(input,
// output) per cycle (Ruckig style), called on the engine thread only; it must not allocate, lock or
// block. Three kinds:
//   - JointSplineSource (core/engine/joint_spline_source.h): the joint spline in path time.
//   - MasterFollower (core/engine/master_follower.h): axes geared or cammed to a master axis
//     that the engine does not drive (a line encoder); PLCopen MC_GearInPos / MC_CamIn.
//   - ControlLawSource (core/engine/control_law.h): a machine's control law that reads the
//     sensors and axes and writes commands (torques in CST).
// How feed hold, override, abort, emergency stop and faults act on each source is written in
// core/engine/motion_engine.h.
#include "core/common/types.h"
#include "core/devices/device_interfaces.h"

#include <array>
#include <cstdint>

namespace cutcell {

inline constexpr int kMaxSensors = 4;

// The process signals of this cycle where the program runs a process control on the torch axis
// (a torch height control: core/engine/setpoint_correction.h); telemetry and the run's figures.
struct ProcessSignals {
    bool present = false;       // a process control ran this cycle
    bool arc_ok = false;        // the arc is established and the voltage reading valid
    bool thc_enabled = false;   // the control corrects (false: it only measures)
    std::uint8_t thc_state = 0; // the control's state (its own enum, e.g. ThcState)
    double arc_voltage_v = 0;   // the (filtered) arc voltage
    double standoff_mm = 0;     // the torch height above the surface estimated from the voltage
    double height_error_mm = 0; // standoff - cut height: > 0 too high
    double correction_mm = 0;   // the control's offset along the torch axis, > 0 down
};

// What the engine asks of the source this cycle.
enum class SourceRequest : std::uint8_t {
    Track,          // follow the engine's set-point (hold, home, jog, approach): control laws only
    Run,            // run the program
    FeedHold,       // come to rest where the program allows it (a saw finishes its cut first)
    Abort,          // come to rest as soon as possible without a jump (tool off)
    ControlledStop, // emergency stop / fault of category 1: come to rest, then torque is removed
};
const char* toString(SourceRequest r);

enum class SourceStatus : std::uint8_t {
    Working, // moving
    AtRest,  // the requested hold / abort / stop is reached: the axes are at rest
    Done,    // the program is finished, axes at rest
    Fault,   // the source cannot go on (SourceOutput::fault says why)
};

struct SourceInput {
    double now_s = 0;
    double period_s = 0.001;
    // From this cycle's command to the drive acting on it (s): 0 for in-process drives; one
    // cycle over a CANopen bus (a command written after SYNC k takes effect at SYNC k + 1,
    // while the feedback is the state sampled at SYNC k). A torque law predicts that far.
    double actuation_delay_s = 0;
    int axis_count = 0;
    const std::array<DriveFeedback, kMaxAxes>* axes = nullptr;
    const std::array<SensorReading, kMaxSensors>* sensors = nullptr;
    // The engine's set-point of this cycle for Track (hold or a move), else the last output.
    JointVector setpoint = JointVector::Zero();
    JointVector setpoint_velocity = JointVector::Zero();
    SourceRequest request = SourceRequest::Run;
    double override_fraction = 1;
    bool tool_ok = false; // the process tool reports "process OK"
    // The job keeps the tool on while a feed hold holds the axes (EngineSpec).
    bool tool_on_during_feed_hold = false;
};

struct SourceOutput {
    // Position set-point of every axis (CSP command; the reference the following error is
    // measured against for the other modes) and its velocity (CSV command, set-point lead).
    JointVector position = JointVector::Zero();
    JointVector velocity = JointVector::Zero();
    JointVector torque = JointVector::Zero(); // CST command (N m or N)
    // The set-point's acceleration where the source knows it (the spline: the position command
    // leads by it); 0 otherwise.
    JointVector acceleration = JointVector::Zero();
    // Following-error supervision of each axis this cycle; a source turns it off only where
    // no position reference exists (open-loop torque), and says why.
    std::array<bool, kMaxAxes> supervised{true, true, true, true, true, true, true, true};
    const char* unsupervised_reason = ""; // static text
    bool tool_on = false;
    SourceStatus status = SourceStatus::Working;
    const char* fault = "";     // static text when status == Fault
    double progress = 0;        // 0..1 of the program
    double program_time_s = 0;  // a source in time (resumesInTime()): the path time of the sample
    double remaining_s = 0;     // ... and the time left at the current rate (0: not known)
    double master_position = 0; // MasterAxis: the filtered master (telemetry)
    std::uint32_t point_index = 0, point_count = 0;
    // Units of work finished so far (pieces cut, strokes made; MotionProgram::terms).
    std::uint32_t made = 0;
    ProcessSignals process; // written by the program's set-point correction, if it has one
};

class MotionSource {
  public:
    virtual ~MotionSource() = default;
    // Called on the engine thread when the program's motion begins (after approach and
    // ignition): the input holds the axes where they are. Must not allocate.
    virtual void start(const SourceInput& in) = 0;
    virtual void update(const SourceInput& in, SourceOutput& out) = 0;
    // A short name of the source's inner state for events and telemetry ("in sync").
    virtual const char* stateName() const = 0;
    // Whether a run can start part-way, at a path time (cut recovery): the spline only.
    virtual bool resumesInTime() const { return false; }
};

} // namespace cutcell
