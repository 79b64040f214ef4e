#include "core/engine/engine_types.h"

#include "core/engine/motion_program.h"
#include "core/engine/motion_source.h"

namespace cutcell {

const char* toString(EngineState s) {
    switch (s) {
    case EngineState::Idle:
        return "Idle";
    case EngineState::Ready:
        return "Ready";
    case EngineState::Homing:
        return "Homing";
    case EngineState::Jogging:
        return "Jogging";
    case EngineState::Running:
        return "Running";
    case EngineState::Paused:
        return "Paused";
    case EngineState::Completed:
        return "Completed";
    case EngineState::EmergencyStop:
        return "EmergencyStop";
    case EngineState::Fault:
        return "Fault";
    }
    return "?";
}

const char* toString(CommandType c) {
    switch (c) {
    case CommandType::Load:
        return "Load";
    case CommandType::Enable:
        return "Enable";
    case CommandType::Disable:
        return "Disable";
    case CommandType::Home:
        return "Home";
    case CommandType::Jog:
        return "Jog";
    case CommandType::Start:
        return "Start";
    case CommandType::FeedHold:
        return "Feed hold";
    case CommandType::Resume:
        return "Resume";
    case CommandType::SetOverride:
        return "Override";
    case CommandType::Abort:
        return "Abort";
    case CommandType::EmergencyStop:
        return "Emergency stop";
    case CommandType::ReleaseEmergencyStop:
        return "Release emergency stop";
    case CommandType::Reset:
        return "Reset";
    }
    return "?";
}

const char* toString(EventKind k) {
    switch (k) {
    case EventKind::Info:
        return "info";
    case EventKind::Transition:
        return "transition";
    case EventKind::Refusal:
        return "refusal";
    case EventKind::Fault:
        return "fault";
    case EventKind::RunStarted:
        return "run-started";
    case EventKind::RunEnded:
        return "run-ended";
    case EventKind::CutEnded:
        return "cut-ended";
    }
    return "?";
}

const char* toString(DriveState s) {
    switch (s) {
    case DriveState::Disabled:
        return "Disabled";
    case DriveState::Enabling:
        return "Enabling";
    case DriveState::Enabled:
        return "Enabled";
    case DriveState::QuickStop:
        return "QuickStop";
    case DriveState::Fault:
        return "Fault";
    }
    return "?";
}

const char* toString(AxisCommandMode m) {
    switch (m) {
    case AxisCommandMode::Position:
        return "position (CSP)";
    case AxisCommandMode::Velocity:
        return "velocity (CSV)";
    case AxisCommandMode::Torque:
        return "torque (CST)";
    }
    return "?";
}

const char* toString(MotionSourceKind k) {
    switch (k) {
    case MotionSourceKind::JointSpline:
        return "joint spline";
    case MotionSourceKind::MasterAxis:
        return "master axis";
    case MotionSourceKind::ControlLaw:
        return "control law";
    }
    return "?";
}

const char* toString(SourceRequest r) {
    switch (r) {
    case SourceRequest::Track:
        return "track";
    case SourceRequest::Run:
        return "run";
    case SourceRequest::FeedHold:
        return "feed hold";
    case SourceRequest::Abort:
        return "abort";
    case SourceRequest::ControlledStop:
        return "controlled stop";
    }
    return "?";
}

} // namespace cutcell
