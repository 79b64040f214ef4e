#include "core/engine/engine_types.h"

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

} // namespace cutcell
